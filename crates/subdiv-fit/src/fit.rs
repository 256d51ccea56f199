//! Adaptive fitting (Secs. 3–5): initial fitting points, the interpolation system `M P = Q`
//! (eq. 4), per-segment errors (eqs. 5–6), and insertion of fitting points until the error is
//! within tolerance.

use bez_core::Vector;

use crate::assess::{assess, assess_reusing, chord_params};
use crate::banded::CyclicBand;
use crate::bspline::bspline_basis;
use crate::chord::ChordLengths;
use crate::corner::Corner;
use crate::corner_angles::{
    CornerTangents, SMOOTH_JOINT_TURN, SMOOTH_SIDE, corner_insertions, neighbours_on_tangents,
};
use crate::corners::detect_corners;
use crate::curvature::{angle_between, feature_points};
use crate::curve::Closure;
use crate::curved_corner::{Weights, neighbour_control, span_end};
use crate::distance::PowerCubic;
use crate::error::BestCurve;
use crate::insertion::{insert_points, segment_range};
use crate::joints::{Joints, balance, make_room};
use crate::reduction::{MAX_REDUCED, fit_spans, reduce, respace_spans};
use crate::seeding::seed;
use crate::tangent_joints::detect_tangent_joints;
use crate::tangent_rows::{joint_tangents, smooth_joint_tangents, solve_with_tangents};
use crate::tridiagonal::solve_tridiagonal;
use crate::vertex::VertexKind;
use crate::{SubdivCurve, SubdivFitError};

/// Which error the loop drives below the tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum ErrorMeasure {
    /// The paper's measure (Sec. 5): each data point to its own segment.
    DataToCurve,
    /// Both the paper's measure and the curve-to-data distance (dense samples of every segment to
    /// the data polyline of that segment).
    TwoSided,
}

/// How the control polygon is solved each round.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum FitMode {
    /// The paper's interpolation of the fitting points, eq. (4) (with
    /// [`FitOptions::corner_tolerance`] set, a corner's neighbouring control points, which set its
    /// tangents, are then moved onto the data's tangents there when that moves them by at most a
    /// quarter of the tolerance: the fitting points next to a corner are then no longer
    /// interpolated exactly, and the error measures check the moved curve).
    Interpolate,
    /// Interpolation first, then the regular control points re-solved by least squares over all
    /// data points at their foot-point parameters (sharp control points stay on their data points;
    /// with [`FitOptions::corner_tolerance`] set, the neighbours of a corner, which set its
    /// tangents, are then moved onto the data's tangents there and the others solved again).
    LeastSquares,
}

/// Where a failing segment gets its new fitting point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Insertion {
    /// The data point of largest error in the segment (for a curve-to-data excess, the data point
    /// nearest the worst curve sample). Literal reading of Sec. 4.3; on unevenly spaced fitting
    /// points it can make the uniform-parameter interpolation ring and stall.
    MaxError,
    /// The interior data point nearest the segment's chord-length middle: the two halves are equal,
    /// so the fitting points stay more evenly spaced than with [`Insertion::MaxError`] (eq. (4)
    /// interpolates at uniform parameters, and uneven spacing makes it ring), and a failing segment
    /// of `m` data edges is down to single edges within `log2(m)` rounds.
    Bisect,
}

/// Where the initial fitting points come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum Seeding {
    /// The paper's (Sec. 4.2): every local maximum of the discrete curvature and every point whose
    /// edge angle is below [`FitOptions::sharp_angle`] ([`crate::feature_points`]). On dense,
    /// quantized or noisy data these are maxima of the noise.
    CurvatureMaxima,
    /// Corners found at the feature scale ([`crate::scaled_corners`]), and between them regular
    /// points at equal chord-length steps, as many as an interpolation error estimate asks for at
    /// the tolerance (a circle at relative tolerance 10⁻³ gets 12). Independent of the sampling
    /// density, insensitive to noise below a quarter of the tolerance.
    Scaled,
}

/// What happens after the loop has met the tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum Reduction {
    /// Nothing: the curve of the last round (the paper).
    Off,
    /// Regular fitting points are removed, those in the segments of smallest error first, while
    /// the error stays within the tolerance (re-solving the polygon each time; polygons above
    /// [`MAX_REDUCED`](crate::MAX_REDUCED) points are left as they are).
    RemovePoints,
    /// First the regular fitting points of each span between two sharp vertices are re-spaced:
    /// the fewest that keep the tolerance, at equal chord-length steps (eq. (4) interpolates at
    /// uniform parameters, so evenly spaced points suit it, while the insertion loop leaves them
    /// uneven) or else graded towards the span's ends (a sharp vertex has zero curvature, so the
    /// curve gains it in the first segments), then [`Reduction::RemovePoints`]. On the printable
    /// ASCII glyphs of DejaVu Sans at 10⁻³ em: 1,923 control points instead of 2,667 with
    /// interpolation, in about 1.6 times the time; 1,784 instead of 2,596 in least-squares mode
    /// (TrueType stores 1,797). A step that would move a kept corner's turn beyond
    /// [`FitOptions::corner_tolerance`] is refused (without that bound, the longer segments next to
    /// the corners turned them by up to 2.6° more or less than the data on the crate's test
    /// outline).
    RespaceAndRemove,
    /// Fewest points by least squares, span by span, in place of the insertion loop: the spans
    /// between consecutive sharp initial points are independent (a sharp vertex's phantom point
    /// decouples the two sides), so each gets the fewest regular points (counting up from half the
    /// segments of its initial count, and down while that start passes), evenly spaced or else
    /// graded as in [`Reduction::RespaceAndRemove`], whose control points,
    /// refitted by least squares on the span's data with every other control point fixed, keep
    /// the span's segments within the tolerance; then [`Reduction::RemovePoints`], each trial
    /// refitting the four control points around the merged segment. Every trial costs the data of
    /// its span or window, not of the contour; the refit uses two foot-point iterations on at most
    /// 8 and then 16 data points per segment, the measurement all data (a subsample first). The
    /// removal tries only points whose two segments' errors sum to at most the tolerance. A span that needs more than six
    /// points beyond its initial count sends the contour through the insertion loop (in
    /// [`FitOptions::mode`]) and then the same re-spacing and removal. Otherwise round 0 of the
    /// reports is the span fit. On the printable ASCII glyphs of DejaVu Sans at 10⁻³ em: 1,793
    /// control points (TrueType stores 1,797) in about 0.7 ms per glyph (with `fit_bez_path`, which
    /// samples the outline's straight lines sparser between their corners for it,
    /// `LineSampling::for_fit`; a trial whose first solve is far off is given up before its later
    /// iterations). With
    /// [`FitOptions::corner_tolerance`] a free neighbour of a corner whose polygon edge leaves the
    /// corner's tangent by more than half the bound after a trial's refit is constrained to a ray
    /// at half the bound from the tangent (one unknown along it in the least-squares system) and
    /// the points are refitted once more, and a span is accepted only when its side of each end
    /// corner is within half the bound; on the same glyphs with the outline's exact tangents
    /// (`fit_bez_path` (feature `kurbo`)) and
    /// [`EXACT_CORNER_TOLERANCE`](crate::EXACT_CORNER_TOLERANCE): 1,884 control points in about
    /// 1.4 ms per glyph, every kept corner within 0.90° of the outline's turn (9.29° without the
    /// bound).
    Refit,
}

/// The largest number of data points [`fit`] accepts: 2²⁴ (bez-core's `MAX_SAMPLES`).
pub const MAX_FIT_POINTS: usize = bez_core::MAX_SAMPLES;

/// The largest absolute data coordinate [`fit`] accepts: bez-core's `MAX_COORDINATE` / 8
/// (10¹⁵² / 8), leaving room for control points that overshoot the data and for their Bézier
/// form.
pub const MAX_DATA_COORDINATE: f64 = bez_core::MAX_COORDINATE / 8.0;

/// The largest [`FitOptions::samples_per_segment`]: 1,024.
pub const MAX_SAMPLES_PER_SEGMENT: usize = 1024;

/// The largest [`FitOptions::max_rounds`]: 1,000 (bisection needs about log2 of the longest
/// failing segment, at most 24 for [`MAX_FIT_POINTS`] points).
pub const MAX_ROUNDS: usize = 1000;

/// The largest [`FitOptions::feature_scale`]: 10⁶ tolerances.
pub const MAX_FEATURE_SCALE: f64 = 1e6;

/// Options of [`fit`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct FitOptions {
    /// Maximum allowed error δ (Sec. 5), in data units.
    pub tolerance: f64,
    /// A corner is a point where the angle between the incoming and the outgoing direction is
    /// below this (radians), i.e. where the curve turns by more than `π − sharp_angle`.
    /// With [`Seeding::Scaled`] the directions are chords at the feature scale and the turn must
    /// also be scale-invariant ([`crate::scaled_corners`]); default 160° (a turn of more than 20°).
    /// With [`Seeding::CurvatureMaxima`] they are the two data edges (the paper's rule); the
    /// paper's configuration uses 140° (a smooth curve sampled at spacing h with radius of
    /// curvature r turns by about h / r per point, so only features with r < 1.4 h, not resolved
    /// by the sampling, are taken for corners). 0 finds no corner.
    pub sharp_angle: f64,
    /// The feature scale σ as a multiple of the tolerance (σ = `feature_scale · tolerance`, in
    /// data units): the arc length over which corners are measured and the shortest step at which
    /// turning is counted. Default 6. Noise up to about σ / 24 does not create corners.
    pub feature_scale: f64,
    /// Initial fitting points. Default [`Seeding::Scaled`].
    pub seeding: Seeding,
    /// Curvature floor relative to the bounding-box diagonal L: maxima with `K · L` at or below it
    /// are ignored. Default 1e-6 (a radius of curvature above a million diagonals counts as straight).
    pub curvature_floor: f64,
    /// Relative prominence a curvature maximum needs over its predecessor. Default 1e-9.
    pub prominence: f64,
    /// Maximum number of insertion rounds. Default 100, at most [`MAX_ROUNDS`].
    pub max_rounds: usize,
    /// Error measure. Default [`ErrorMeasure::TwoSided`].
    pub measure: ErrorMeasure,
    /// Solver. Default [`FitMode::Interpolate`].
    pub mode: FitMode,
    /// Samples per segment for the curve-to-data distance. Default 32, at most
    /// [`MAX_SAMPLES_PER_SEGMENT`].
    pub samples_per_segment: usize,
    /// Insertion rule. Default [`Insertion::Bisect`].
    pub insertion: Insertion,
    /// After convergence. Default [`Reduction::RemovePoints`] ([`Reduction::Off`] in the paper's
    /// configuration).
    pub reduction: Reduction,
    /// How far (radians) the turn of the curve at a kept corner may be from the data's turn there
    /// (the exact tangents of a known corner that has them, [`Corner::with_tangents`](crate::Corner),
    /// else estimated from one-sided quadratic fits of the samples next to the corner). With a bound,
    /// the control points next to a corner are moved onto the data's tangents after each solve
    /// (see [`FitMode`]); once the distance tolerance is met, a corner still off by more (its
    /// neighbour is sharp or shared with another corner) gets fitting points inserted next to it;
    /// and the reduction refuses a step that moves a corner beyond the bound. Only sharp vertices
    /// where the data turn by at least 20° (or the corner angle) count, and every known corner with
    /// tangents. Default `None` (unchecked,
    /// as in the paper); [`CORNER_TOLERANCE`](crate::CORNER_TOLERANCE) (0.5°) keeps the corners of
    /// the crate's test outline within 0.001° of the data's, and costs control points and time:
    /// on the printable ASCII glyphs of DejaVu Sans at 10⁻³ em 2,858 control points instead of
    /// 2,667 with interpolation, 1.66 ms per glyph instead of 0.88.
    #[cfg_attr(feature = "serde", serde(default))]
    pub corner_tolerance: Option<f64>,
    /// Detection of tangent joints (opt-in, with [`Seeding::Scaled`]): a data point becomes a
    /// tangent joint, as if given to [`fit_with_joints`], where the one-sided quadratic estimates
    /// of the data (reach 16 feature scales) agree in direction within 5° but their curvatures
    /// differ by at least this fraction of the larger one, `|κ⁺ − κ⁻| / max(|κ⁺|, |κ⁻|)` (1
    /// where a line meets an arc, `1 − ρ₁/ρ₂` where arcs of radii ρ₁ < ρ₂ meet), by a jump above
    /// the estimates' noise (`|κ⁺ − κ⁻| · reach ≥ 0.005`), by as much at half the reach (a smooth
    /// curve's estimates differ half as much there), and no point within the reach differs more.
    /// [`TANGENT_JUMP`] (0.5) suits outlines of lines and arcs. Default `None` (no detection);
    /// a value must lie in (0, 1]. With [`Reduction::Refit`] the joints are smooth joints (see
    /// [`fit_with_joints`]).
    #[cfg_attr(feature = "serde", serde(default))]
    pub tangent_jump: Option<f64>,
    /// The kind of the fit's sharp vertices: [`VertexKind::Sharp`] (the default, the paper's:
    /// zero curvature on both sides of a corner) or [`VertexKind::SharpCurved`] (each side's first
    /// segment a parabola, so a curved side leaves the corner with its curvature, at no extra
    /// control point). Not with tangent joints ([`fit_with_joints`], [`FitOptions::tangent_jump`])
    /// but with [`Reduction::Refit`], which makes them smooth joints.
    #[cfg_attr(feature = "serde", serde(default = "sharp_kind"))]
    pub corner_kind: VertexKind,
}

/// The default of [`FitOptions::corner_kind`] (for serde).
#[cfg(feature = "serde")]
fn sharp_kind() -> VertexKind {
    VertexKind::Sharp
}

/// A threshold for [`FitOptions::tangent_jump`]: curvatures that differ by half the larger one.
pub const TANGENT_JUMP: f64 = 0.5;

impl FitOptions {
    /// The defaults with the given tolerance.
    #[must_use]
    pub fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            sharp_angle: 160f64.to_radians(),
            feature_scale: 6.0,
            seeding: Seeding::Scaled,
            curvature_floor: 1e-6,
            prominence: 1e-9,
            max_rounds: 100,
            measure: ErrorMeasure::TwoSided,
            mode: FitMode::Interpolate,
            samples_per_segment: 32,
            insertion: Insertion::Bisect,
            reduction: Reduction::RemovePoints,
            corner_tolerance: None,
            tangent_jump: None,
            corner_kind: VertexKind::Sharp,
        }
    }

    /// The paper's configuration: initial points at the curvature maxima and at edge angles
    /// below 140°, one-sided error, interpolation.
    #[must_use]
    pub fn paper(tolerance: f64) -> Self {
        Self {
            measure: ErrorMeasure::DataToCurve,
            seeding: Seeding::CurvatureMaxima,
            sharp_angle: 140f64.to_radians(),
            reduction: Reduction::Off,
            ..Self::new(tolerance)
        }
    }

    /// With `tolerance` set to `value` (the fitting tolerance).
    #[must_use]
    pub fn with_tolerance(mut self, value: f64) -> Self {
        self.tolerance = value;
        self
    }

    /// With `sharp_angle` set to `value` (the corner threshold in radians).
    #[must_use]
    pub fn with_sharp_angle(mut self, value: f64) -> Self {
        self.sharp_angle = value;
        self
    }

    /// With `feature_scale` set to `value` (the feature scale in tolerances).
    #[must_use]
    pub fn with_feature_scale(mut self, value: f64) -> Self {
        self.feature_scale = value;
        self
    }

    /// With `seeding` set to `value` (where the initial fitting points come from).
    #[must_use]
    pub fn with_seeding(mut self, value: Seeding) -> Self {
        self.seeding = value;
        self
    }

    /// With `curvature_floor` set to `value` (the smallest curvature maximum kept).
    #[must_use]
    pub fn with_curvature_floor(mut self, value: f64) -> Self {
        self.curvature_floor = value;
        self
    }

    /// With `prominence` set to `value` (the prominence of curvature maxima).
    #[must_use]
    pub fn with_prominence(mut self, value: f64) -> Self {
        self.prominence = value;
        self
    }

    /// With `max_rounds` set to `value` (the round cap).
    #[must_use]
    pub fn with_max_rounds(mut self, value: usize) -> Self {
        self.max_rounds = value;
        self
    }

    /// With `measure` set to `value` (the error measure).
    #[must_use]
    pub fn with_measure(mut self, value: ErrorMeasure) -> Self {
        self.measure = value;
        self
    }

    /// With `mode` set to `value` (interpolation or least squares).
    #[must_use]
    pub fn with_mode(mut self, value: FitMode) -> Self {
        self.mode = value;
        self
    }

    /// With `samples_per_segment` set to `value` (the samples of the curve-to-data error).
    #[must_use]
    pub fn with_samples_per_segment(mut self, value: usize) -> Self {
        self.samples_per_segment = value;
        self
    }

    /// With `reduction` set to `value` (what happens after convergence).
    #[must_use]
    pub fn with_reduction(mut self, value: Reduction) -> Self {
        self.reduction = value;
        self
    }

    /// With `corner_tolerance` set to `value` (the bound on a kept corner's turn, radians, or
    /// `None` for no bound).
    #[must_use]
    pub fn with_corner_tolerance(mut self, value: Option<f64>) -> Self {
        self.corner_tolerance = value;
        self
    }

    /// With `tangent_jump` set to `value` (the threshold of tangent-joint detection, or `None`
    /// for none).
    #[must_use]
    pub fn with_tangent_jump(mut self, value: Option<f64>) -> Self {
        self.tangent_jump = value;
        self
    }

    /// With `corner_kind` set to `value` (the kind of the fit's sharp vertices).
    #[must_use]
    pub fn with_corner_kind(mut self, value: VertexKind) -> Self {
        self.corner_kind = value;
        self
    }

    /// With `insertion` set to `value` (the insertion rule).
    #[must_use]
    pub fn with_insertion(mut self, value: Insertion) -> Self {
        self.insertion = value;
        self
    }
}

/// Errors of one round.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct RoundReport {
    /// Round number: 0 is the initial fit from the curvature maxima.
    pub round: usize,
    /// Number of control points (= fitting points).
    pub control_points: usize,
    /// Max distance of a data point to its segment (the paper's measure).
    pub max_data_to_curve: f64,
    /// RMS of the same distances.
    pub rms_data_to_curve: f64,
    /// Max distance of a curve sample to the data polyline of its segment.
    pub max_curve_to_data: f64,
}

/// The result of [`fit`].
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Fit<const D: usize> {
    /// The fitted curve: one control point per fitting point, two per tangent joint (the
    /// tangent vertex and its partner, which share the joint's knot) but with
    /// [`Reduction::Refit`] (a smooth joint: one sharp vertex).
    pub curve: SubdivCurve<D>,
    /// Data indices of the fitting points (the curve's knots), increasing; segment j covers data
    /// `fitting[j]..=fitting[j+1]` (wrapping for closed data).
    pub fitting: Vec<usize>,
    /// Data indices of the tangent joints, given ([`fit_with_joints`]) or detected
    /// ([`FitOptions::tangent_jump`]): fitting points whose knot is double (with
    /// [`Reduction::Refit`], smooth joints: sharp vertices with one tangent), increasing; empty
    /// without them.
    pub tangents: Vec<usize>,
    /// Data indices of the initial fitting points (round 0).
    pub initial: Vec<usize>,
    /// One report per round, round 0 first.
    pub reports: Vec<RoundReport>,
    /// The report of the curve after [`Reduction::RemovePoints`] (its `round` is that of the last
    /// round), when points were removed.
    pub reduced: Option<RoundReport>,
}

impl<const D: usize> Fit<D> {
    /// Number of insertion rounds performed (the paper's "loops").
    #[must_use]
    pub fn rounds(&self) -> usize {
        self.reports.len().saturating_sub(1)
    }

    /// The report of the returned curve: after the reduction if points were removed, else the
    /// last round's.
    #[must_use]
    pub fn last(&self) -> Option<&RoundReport> {
        self.reduced.as_ref().or(self.reports.last())
    }
}

/// Validates data: few enough and enough points, finite, within bez-core's coordinate range, no
/// coinciding consecutive points.
fn validate<const D: usize>(data: &[Vector<D>], closed: bool) -> Result<(), SubdivFitError> {
    let needed = 3;
    if data.len() < needed {
        return Err(SubdivFitError::TooFewPoints {
            got: data.len(),
            needed,
        });
    }
    if data.len() > MAX_FIT_POINTS {
        return Err(SubdivFitError::TooLarge {
            name: "data points",
            requested: data.len(),
            max: MAX_FIT_POINTS,
        });
    }
    crate::curve::check_points(data, MAX_DATA_COORDINATE)?;
    let n = data.len();
    let pairs = if closed { n } else { n - 1 };
    for i in 0..pairs {
        let j = (i + 1) % n;
        if data[i] == data[j] {
            return Err(SubdivFitError::DuplicatePoint { index: i, next: j });
        }
    }
    Ok(())
}

fn validate_options(o: &FitOptions) -> Result<(), SubdivFitError> {
    if !(o.tolerance.is_finite() && o.tolerance > 0.0) {
        return Err(SubdivFitError::InvalidTolerance { value: o.tolerance });
    }
    for (name, requested, max) in [
        ("max_rounds", o.max_rounds, MAX_ROUNDS),
        (
            "samples_per_segment",
            o.samples_per_segment,
            MAX_SAMPLES_PER_SEGMENT,
        ),
    ] {
        if requested > max {
            return Err(SubdivFitError::TooLarge {
                name,
                requested,
                max,
            });
        }
    }
    let checks: [(&'static str, f64, bool, &'static str); 5] = [
        (
            "sharp_angle",
            o.sharp_angle,
            (0.0..=std::f64::consts::PI).contains(&o.sharp_angle),
            "must lie in [0, π]",
        ),
        (
            "feature_scale",
            o.feature_scale,
            (0.0..=MAX_FEATURE_SCALE).contains(&o.feature_scale),
            "must lie in [0, MAX_FEATURE_SCALE]",
        ),
        (
            "curvature_floor",
            o.curvature_floor,
            o.curvature_floor.is_finite() && o.curvature_floor >= 0.0,
            "must be finite and non-negative",
        ),
        (
            "prominence",
            o.prominence,
            o.prominence.is_finite() && o.prominence >= 0.0,
            "must be finite and non-negative",
        ),
        (
            "samples_per_segment",
            o.samples_per_segment as f64,
            o.samples_per_segment >= 2,
            "must be at least 2",
        ),
    ];
    if let Some(value) = o.corner_tolerance
        && !(value > 0.0 && value <= std::f64::consts::PI)
    {
        return Err(SubdivFitError::InvalidOption {
            name: "corner_tolerance",
            value,
            reason: "must lie in (0, π]",
        });
    }
    if let Some(value) = o.tangent_jump
        && !(value > 0.0 && value <= 1.0)
    {
        return Err(SubdivFitError::InvalidOption {
            name: "tangent_jump",
            value,
            reason: "must lie in (0, 1]",
        });
    }
    if !o.corner_kind.is_sharp() {
        return Err(SubdivFitError::InvalidCornerKind {
            kind: o.corner_kind,
            reason: "must be VertexKind::Sharp or VertexKind::SharpCurved",
        });
    }
    if o.corner_kind == VertexKind::SharpCurved
        && o.tangent_jump.is_some()
        && o.reduction != Reduction::Refit
    {
        return Err(SubdivFitError::InvalidOption {
            name: "tangent_jump",
            value: o.tangent_jump.unwrap_or(f64::NAN),
            reason: "cannot be combined with corner_kind = VertexKind::SharpCurved (but with \
                     Reduction::Refit)",
        });
    }
    for (name, value, ok, reason) in checks {
        if !ok {
            return Err(SubdivFitError::InvalidOption {
                name,
                value,
                reason,
            });
        }
    }
    Ok(())
}

/// The tolerance must be at least 16 ulps of the largest coordinate.
fn check_precision<const D: usize>(
    data: &[Vector<D>],
    tolerance: f64,
) -> Result<(), SubdivFitError> {
    let largest = data
        .iter()
        .flat_map(|p| p.iter().map(|c| c.abs()))
        .fold(0.0, f64::max);
    let floor = 16.0 * largest * f64::EPSILON;
    if tolerance < floor {
        return Err(SubdivFitError::ToleranceBelowPrecision { tolerance, floor });
    }
    Ok(())
}

/// The feature scale σ in data units.
fn sigma(options: &FitOptions) -> f64 {
    options.feature_scale * options.tolerance
}

/// The corners [`fit`] would make sharp with [`Seeding::Scaled`]: data indices, increasing, found
/// at the feature scale σ = `feature_scale · tolerance` with the corner angle
/// `π − sharp_angle` (see the module documentation of the detection in the crate docs). The ends
/// of open data are not listed (they are always sharp).
///
/// ```
/// use subdiv_fit::{Closure, FitOptions, Vector2, scaled_corners};
///
/// // A square sampled densely, its corners at indices 0, 100, 200, 300, with noise of 1e-4.
/// let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
/// let data: Vec<Vector2> = (0..400)
///     .map(|k| {
///         let ((x0, y0), (x1, y1)) = (corners[k / 100], corners[(k / 100 + 1) % 4]);
///         let s = (k % 100) as f64 / 100.0;
///         let wobble = 1e-4 * ((k * 7919) % 13) as f64 / 13.0;
///         Vector2::new(x0 + s * (x1 - x0) + wobble, y0 + s * (y1 - y0) - wobble)
///     })
///     .collect();
/// let found = scaled_corners(&data, Closure::Closed, &FitOptions::new(1e-3))?;
/// assert_eq!(found, [0, 100, 200, 300]);
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
///
/// # Errors
/// As [`fit`] for invalid data or options.
pub fn scaled_corners<const D: usize>(
    data: &[Vector<D>],
    closure: Closure,
    options: &FitOptions,
) -> Result<Vec<usize>, SubdivFitError> {
    let closed = closure.is_closed();
    validate(data, closed)?;
    validate_options(options)?;
    let chords = ChordLengths::robust(data, closed, anchor_spacing(options));
    Ok(scaled_corners_of(data, &chords, closed, &[], options))
}

/// The anchor spacing of the noise-robust chord length, σ / 4.
fn anchor_spacing(options: &FitOptions) -> f64 {
    0.25 * sigma(options)
}

fn scaled_corners_of<const D: usize>(
    data: &[Vector<D>],
    chords: &ChordLengths,
    closed: bool,
    given: &[usize],
    options: &FitOptions,
) -> Vec<usize> {
    detect_corners(
        data,
        chords,
        closed,
        given,
        sigma(options),
        std::f64::consts::PI - options.sharp_angle,
    )
}

/// Fits a subdivision curve with sharp vertices to ordered data (Secs. 3–5).
///
/// 1. Initial fitting points ([`FitOptions::seeding`]): by default corners at the feature scale
///    and evenly spaced regular points between them ([`Seeding::Scaled`]); in the paper's
///    configuration the curvature maxima and sharp points ([`crate::feature_points`]); for closed
///    data with fewer than 3, the largest gaps are split at their middle index.
/// 2. Control points from `M P = Q` (eq. 4): a sharp fitting point gives `p_i = q_i`, a regular one
///    `(p_{i−1} + 4 p_i + p_{i+1}) / 6 = q_i`, a (cyclic) tridiagonal system solved in O(k) by
///    Thomas's algorithm with a Sherman–Morrison corner correction (the matrix is strictly diagonally
///    dominant in its regular rows, so it is never singular in exact arithmetic). In
///    [`FitMode::LeastSquares`] the regular control points are then re-solved by least squares over
///    all data (banded normal equations, O(n + k) time and memory).
/// 3. Errors per segment: each data point between two fitting points against that segment only, by
///    Newton on eq. (6) from the chord-length parameter; with [`ErrorMeasure::TwoSided`] also the
///    distance of dense curve samples to the segment's data polyline.
/// 4. Every segment whose error exceeds the tolerance gets a new regular fitting point, chosen by
///    [`FitOptions::insertion`] (by default the chord-length middle); repeat.
///
/// Every option and the data size are checked before any work ([`MAX_FIT_POINTS`],
/// [`MAX_ROUNDS`], [`MAX_SAMPLES_PER_SEGMENT`], [`MAX_FEATURE_SCALE`]), and the tolerance against
/// the precision of the coordinates ([`SubdivFitError::ToleranceBelowPrecision`]).
///
/// # Errors
/// Invalid data or options (typed), [`SubdivFitError::SingularSystem`],
/// [`SubdivFitError::NoConvergence`] when the round cap is hit or no segment can take another
/// point (it carries the last curve and its error).
pub fn fit<const D: usize>(
    data: &[Vector<D>],
    closure: Closure,
    options: &FitOptions,
) -> Result<Fit<D>, SubdivFitError> {
    fit_with_corners(data, closure, &[], options)
}

/// [`fit`] with known corners: the data points at the indices `corners` are sharp fitting points
/// (kept sharp, interpolated exactly), in addition to the corners [`Seeding::Scaled`] detects away
/// from them (set [`FitOptions::sharp_angle`] to 0 to detect none). With
/// [`Seeding::CurvatureMaxima`] they are added to the paper's initial points.
///
/// ```
/// use subdiv_fit::{Closure, FitOptions, Vector2, fit_with_corners};
///
/// // A half disc: a semicircle closed by its diameter, corners at the diameter's ends.
/// let mut data: Vec<Vector2> = (0..=60)
///     .map(|k| {
///         let t = std::f64::consts::PI * k as f64 / 60.0;
///         Vector2::new(t.cos(), t.sin())
///     })
///     .collect();
/// data.extend((1..20).map(|k| Vector2::new(-1.0 + k as f64 / 10.0, 0.0)));
/// let opts = FitOptions::new(1e-3).with_sharp_angle(0.0); // only the corners given
/// let f = fit_with_corners(&data, Closure::Closed, &[0, 60], &opts)?;
/// let sharp: Vec<usize> = (0..f.fitting.len())
///     .filter(|&j| f.curve.is_sharp(j))
///     .map(|j| f.fitting[j])
///     .collect();
/// assert_eq!(sharp, [0, 60]);
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
///
/// With [`FitOptions::corner_tolerance`] set, a fit that ends with
/// [`SubdivFitError::NoConvergence`] is repeated without the bound (which moves the control points
/// next to corners, so the distance alone may still be met; a fit that fails costs twice).
///
/// # Errors
/// As [`fit`], and [`SubdivFitError::CornerOutOfRange`] for a corner index outside the data.
pub fn fit_with_corners<const D: usize>(
    data: &[Vector<D>],
    closure: Closure,
    corners: &[usize],
    options: &FitOptions,
) -> Result<Fit<D>, SubdivFitError> {
    let known: Vec<Corner<D>> = corners.iter().map(|&i| Corner::new(i)).collect();
    fit_with_known_corners(data, closure, &known, options)
}

/// [`fit_with_corners`] with known corners that may carry their exact one-sided tangents
/// ([`Corner::with_tangents`]): with [`FitOptions::corner_tolerance`] set, the fit's turn at such
/// a corner is bounded against these tangents instead of the data's estimate, whatever the
/// corner's turn (corners without tangents are bounded as in [`fit_with_corners`]). With exact
/// tangents [`EXACT_CORNER_TOLERANCE`](crate::EXACT_CORNER_TOLERANCE) (0.9°) keeps every kept
/// corner within 1° of the outline's turn. A corner given twice takes the tangents of its first
/// entry that has them.
///
/// ```
/// use subdiv_fit::{
///     Closure, Corner, EXACT_CORNER_TOLERANCE, FitOptions, Reduction, Vector2,
///     fit_with_known_corners,
/// };
///
/// // A half disc: the semicircle from (1, 0) to (−1, 0), then the diameter back.
/// let mut data: Vec<Vector2> = (0..=60)
///     .map(|k| {
///         let t = std::f64::consts::PI * k as f64 / 60.0;
///         Vector2::new(t.cos(), t.sin())
///     })
///     .collect();
/// data.extend((1..20).map(|k| Vector2::new(-1.0 + k as f64 / 10.0, 0.0)));
/// // At (1, 0) the diameter arrives along +x and the arc leaves along +y; at (−1, 0) the arc
/// // arrives along −y and the diameter leaves along +x: both corners turn by 90°.
/// let corners = [
///     Corner::with_tangents(0, Vector2::new(1.0, 0.0), Vector2::new(0.0, 1.0))?,
///     Corner::with_tangents(60, Vector2::new(0.0, -1.0), Vector2::new(1.0, 0.0))?,
/// ];
/// let opts = FitOptions::new(1e-3)
///     .with_reduction(Reduction::Refit)
///     .with_corner_tolerance(Some(EXACT_CORNER_TOLERANCE));
/// let f = fit_with_known_corners(&data, Closure::Closed, &corners, &opts)?;
/// let p = f.curve.points();
/// let k = p.len();
/// let j = f.fitting.iter().position(|&i| i == 60).unwrap();
/// let (a, b) = (p[j] - p[j - 1], p[(j + 1) % k] - p[j]);
/// let turn = a.perp(&b).atan2(a.dot(&b)).abs().to_degrees();
/// assert!((turn - 90.0).abs() <= 0.9);
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
///
/// # Errors
/// As [`fit_with_corners`].
pub fn fit_with_known_corners<const D: usize>(
    data: &[Vector<D>],
    closure: Closure,
    corners: &[Corner<D>],
    options: &FitOptions,
) -> Result<Fit<D>, SubdivFitError> {
    fit_given(data, closure, corners, &[], options)
}

/// [`fit_with_corners`] with tangent joints as well: the data points at [`Joints::tangents`] become
/// fitting points whose control points are a [`VertexKind::Tangent`] vertex and its partner (a
/// double knot), so the curve is tangent-continuous there while its curvature may jump, as where a
/// straight side meets an arc tangentially (a regular vertex would be C2 and a sharp one a corner
/// with zero curvature on both sides). The joints bound the spans of [`Seeding::Scaled`] as
/// corners do, and each gets two regular fitting points on each side before any corner or end of
/// the data (where there are fewer, the points between are placed again at equal chord-length
/// steps, one more).
///
/// The pair's rows of eq. (4) interpolate the joint's data point and set the curve's first
/// derivative there to the data's tangent (one-sided quadratic estimates, as for
/// [`FitOptions::corner_tolerance`]) times the shorter of the two segments next to it; these fix
/// the pair by themselves, so the two sides solve independently, as across a sharp vertex, and the
/// system is a band of half-width 2, solved in O(k). The segments next to a joint are kept within
/// a factor 2 of each other's length (the curve leaves the joint on both sides with one speed).
/// With tangent joints the fit interpolates in every [`FitMode`], applies no
/// [`FitOptions::corner_tolerance`] and no [`Reduction`] (the least-squares rows, the corner bound
/// and the point removal do not know double knots yet): the curve of the last round is returned.
///
/// With [`Reduction::Refit`] each tangent joint is instead a smooth joint ([`Corner::smooth`]): a
/// sharp vertex on the joint's data point whose two sides the least-squares refits hold on one
/// tangent (the one-sided estimate of the straighter side; a side fitted after the other follows
/// it exactly, and a straight edge between two sharp vertices may stay within 0.45° of it),
/// so the curve is tangent-continuous there (its turn at most [`SMOOTH_JOINT_TURN`], checked) and,
/// with [`VertexKind::SharpCurved`], each side keeps its own curvature. The reductions and the
/// corner bound then apply as without joints, and the joints need no room. On lines meeting arcs
/// at 10⁻² to 10⁻⁴ this takes 0.11–0.72 times the double knots' control points (the table
/// `docs/results/subdiv-fit-joints.md` in the repository).
///
/// ```
/// use subdiv_fit::{
///     Closure, FitOptions, Joints, Reduction, SMOOTH_JOINT_TURN, Vector2, VertexKind,
///     fit_with_joints,
/// };
///
/// // A straight line into a quarter circle of radius 1, tangent at data point 40.
/// let mut data: Vec<Vector2> = (0..40).map(|k| Vector2::new(-2.0 + k as f64 / 20.0, 0.0)).collect();
/// data.extend((0..=40).map(|k| {
///     let t = std::f64::consts::FRAC_PI_2 * k as f64 / 40.0;
///     Vector2::new(t.sin(), 1.0 - t.cos())
/// }));
/// let joints = Joints::new().with_tangents(&[40]);
/// let f = fit_with_joints(&data, Closure::Open, &joints, &FitOptions::new(1e-3))?;
/// assert_eq!(f.tangents, [40]);
/// assert_eq!(f.curve.kinds().iter().filter(|&&k| k == VertexKind::Tangent).count(), 1);
/// assert_eq!(f.curve.points().len(), f.fitting.len() + 1);
///
/// // With `Reduction::Refit`: a smooth joint, a sharp vertex with one tangent on both sides.
/// let refit = FitOptions::new(1e-3)
///     .with_reduction(Reduction::Refit)
///     .with_corner_kind(VertexKind::SharpCurved);
/// let g = fit_with_joints(&data, Closure::Open, &joints, &refit)?;
/// assert_eq!(g.tangents, [40]);
/// let j = g.fitting.binary_search(&40).unwrap();
/// let (Some(a), Some(b)) = g.curve.corner_tangents(j).unwrap() else { unreachable!() };
/// assert!(a.perp(&b).abs() <= SMOOTH_JOINT_TURN * a.norm() * b.norm());
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
///
/// # Errors
/// As [`fit_with_corners`], and [`SubdivFitError::InvalidTangentJoint`] for a tangent joint
/// outside the data, at an end of open data, at a given corner, or (without
/// [`Reduction::Refit`]) without data for two fitting points between it and a corner or an end;
/// [`SubdivFitError::SmoothJointNotKept`] when, with [`Reduction::Refit`], a joint's turn is
/// above [`SMOOTH_JOINT_TURN`].
pub fn fit_with_joints<const D: usize>(
    data: &[Vector<D>],
    closure: Closure,
    joints: &Joints,
    options: &FitOptions,
) -> Result<Fit<D>, SubdivFitError> {
    let corners: Vec<Corner<D>> = joints.corners().iter().map(|&i| Corner::new(i)).collect();
    fit_given(data, closure, &corners, joints.tangents(), options)
}

/// The fit with given corners and tangent joints; one that ends with
/// [`SubdivFitError::NoConvergence`] under [`FitOptions::corner_tolerance`] is repeated without it.
fn fit_given<const D: usize>(
    data: &[Vector<D>],
    closure: Closure,
    corners: &[Corner<D>],
    tangents: &[usize],
    options: &FitOptions,
) -> Result<Fit<D>, SubdivFitError> {
    let fit = match fit_checked(data, closure, corners, tangents, options) {
        // The corners' bound moves control points: without it the distance alone may be met.
        Err(SubdivFitError::NoConvergence { .. }) if options.corner_tolerance.is_some() => {
            fit_checked(
                data,
                closure,
                corners,
                tangents,
                &options.with_corner_tolerance(None),
            )
        }
        result => result,
    }?;
    // The smooth joints: given, and with `Reduction::Refit` the tangent joints.
    let refit = options.reduction == Reduction::Refit;
    let smooth = corners
        .iter()
        .filter(|c| c.is_smooth())
        .map(Corner::index)
        .chain(fit.tangents.iter().copied().filter(|_| refit));
    for index in smooth {
        let turn = fit
            .fitting
            .binary_search(&index)
            .ok()
            .and_then(|j| fit.curve.corner_tangents(j))
            .and_then(|(a, b)| Some(angle_between(&a?, &b?)))
            .unwrap_or(f64::INFINITY);
        if turn.is_nan() || turn > SMOOTH_JOINT_TURN {
            return Err(SubdivFitError::SmoothJointNotKept {
                index,
                turn,
                max: SMOOTH_JOINT_TURN,
            });
        }
    }
    Ok(fit)
}

/// [`fit_given`] without the retry.
fn fit_checked<const D: usize>(
    data: &[Vector<D>],
    closure: Closure,
    corners: &[Corner<D>],
    tangents: &[usize],
    options: &FitOptions,
) -> Result<Fit<D>, SubdivFitError> {
    let closed = closure.is_closed();
    validate(data, closed)?;
    validate_options(options)?;
    check_precision(data, options.tolerance)?;
    let n = data.len();
    if let Some(c) = corners.iter().find(|c| c.index() >= n) {
        return Err(SubdivFitError::CornerOutOfRange {
            index: c.index(),
            points: n,
        });
    }
    // `Reduction::Refit` places tangent joints as smooth joints (sharp vertices held on the
    // tangent), the other reductions as tangent vertices (double knots).
    let refit = options.reduction == Reduction::Refit;
    if options.corner_kind == VertexKind::SharpCurved && !tangents.is_empty() && !refit {
        return Err(SubdivFitError::InvalidCornerKind {
            kind: options.corner_kind,
            reason: "cannot be combined with tangent joints (but with Reduction::Refit)",
        });
    }
    if let Some(c) = corners.iter().find(|c| c.is_smooth())
        && !refit
    {
        return Err(SubdivFitError::InvalidTangentJoint {
            index: c.index(),
            reason: "a smooth joint needs Reduction::Refit",
        });
    }
    let indices: Vec<usize> = corners.iter().map(Corner::index).collect();
    let joints = Joints::new().with_corners(&indices).with_tangents(tangents);
    joints.check(n, closed)?;
    let given = joints.corners();
    let chords = ChordLengths::robust(data, closed, anchor_spacing(options));
    let mut tangents = joints.tangents().to_vec();
    let mut fitting: Vec<(usize, bool)> = match options.seeding {
        Seeding::CurvatureMaxima => {
            let mut f: Vec<(usize, bool)> = feature_points(
                data,
                closed,
                options.sharp_angle,
                options.curvature_floor,
                options.prominence,
            )
            .iter()
            .map(|f| (f.index, f.sharp))
            .collect();
            for &c in given {
                match f.binary_search_by_key(&c, |x| x.0) {
                    Ok(pos) => f[pos].1 = true,
                    Err(pos) => f.insert(pos, (c, true)),
                }
            }
            f
        }
        Seeding::Scaled => {
            // Detection runs away from the tangent joints too, which are no corners.
            let mut known: Vec<usize> = given.iter().chain(&tangents).copied().collect();
            known.sort_unstable();
            let mut found = scaled_corners_of(data, &chords, closed, &known, options);
            if let Some(threshold) = options.tangent_jump {
                // Away from the corners and from the given tangent joints.
                tangents.extend(detect_tangent_joints(
                    data, &chords, closed, &found, threshold, options,
                ));
                tangents.sort_unstable();
                tangents.dedup();
                found.extend(&tangents);
                found.sort_unstable();
                found.dedup();
            }
            // The tangent joints bound the spans too (each side seeded on its own); `make_room`
            // makes them regular.
            seed(
                data,
                &chords,
                closed,
                &found,
                sigma(options),
                options.tolerance,
            )
        }
    };
    // With `Reduction::Refit`, each tangent joint is a sharp fitting point with the data's tangent
    // there, a smooth joint ([`Corner::smooth`]).
    let joints_found = tangents.clone();
    let with_smooth: Vec<Corner<D>>;
    // The smooth joints' tangents are the data's estimates: a straight edge between two sharp
    // vertices may stay within `SMOOTH_SIDE` of one.
    let smooth_side = if refit && !tangents.is_empty() {
        SMOOTH_SIDE
    } else {
        0.0
    };
    let corners = if refit && !tangents.is_empty() {
        for &t in &tangents {
            match fitting.binary_search_by_key(&t, |f| f.0) {
                Ok(pos) => fitting[pos].1 = true,
                Err(pos) => fitting.insert(pos, (t, true)),
            }
        }
        let directions = smooth_joint_tangents(data, &fitting, &tangents, closed, sigma(options));
        let mut all = corners.to_vec();
        for (&t, &d) in tangents.iter().zip(&directions) {
            all.push(Corner::smooth(t, d)?);
        }
        with_smooth = all;
        tangents.clear();
        &with_smooth[..]
    } else {
        corners
    };
    let tangents = &tangents[..];
    // With tangent joints: interpolation, no corner bound, no reduction (see `fit_with_joints`).
    let options = &if tangents.is_empty() {
        *options
    } else {
        FitOptions {
            mode: FitMode::Interpolate,
            corner_tolerance: None,
            reduction: Reduction::Off,
            ..*options
        }
    };
    if closed {
        while fitting.len() < 3 {
            split_largest_gap(&mut fitting, n);
        }
    }
    make_room(&mut fitting, tangents, &chords, closed)?;
    balance(&mut fitting, tangents, &chords, closed);
    let directions = joint_tangents(data, &fitting, tangents, closed, sigma(options));
    // The sharp fitting points stay, so the tangents of the bounded corners are found once.
    let corner_tangents =
        CornerTangents::new(data, &fitting, closed, corners, smooth_side, options);
    let initial: Vec<usize> = fitting.iter().map(|f| f.0).collect();
    if options.reduction == Reduction::Refit
        && let Some(direct) = span_fit(data, &corner_tangents, &chords, &fitting, closed, options)
    {
        return Ok(Fit {
            initial,
            tangents: joints_found,
            ..direct
        });
    }
    let mut reports = Vec::new();
    let mut best: Option<(SubdivCurve<D>, f64)> = None;
    // The last round within the tolerance, while points are inserted next to corners whose turn
    // is still off: it is returned if a later round is not within the tolerance.
    let mut within: Option<Within<D>> = None;
    let mut round = 0;
    let mut measured = Vec::new();
    // The converged fit with its reductions, and the tangent joints it was given or found.
    let done = |state, reports| {
        Ok(Fit {
            tangents: joints_found.clone(),
            ..finish(
                data,
                &corner_tangents,
                &chords,
                state,
                initial,
                reports,
                options,
            )
        })
    };
    loop {
        let curve = if tangents.is_empty() {
            solve_curve(data, &corner_tangents, &fitting, closed, options)?
        } else {
            solve_with_tangents(data, &fitting, tangents, &directions, closed)?
        };
        let assessment = assess_reusing(data, &fitting, &curve, closed, options, &mut measured);
        reports.push(RoundReport {
            round,
            control_points: curve.points().len(),
            max_data_to_curve: assessment.max_d2c,
            rms_data_to_curve: assessment.rms_d2c,
            max_curve_to_data: assessment.max_c2d,
        });
        let worst = match options.measure {
            ErrorMeasure::DataToCurve => assessment.max_d2c,
            ErrorMeasure::TwoSided => assessment.max_d2c.max(assessment.max_c2d),
        };
        if worst <= options.tolerance {
            let state = Within {
                curve,
                fitting,
                errors: assessment.driven,
                round,
            };
            let mut more = state.fitting.clone();
            if round < options.max_rounds
                && corner_insertions(&corner_tangents, &chords, &mut more, &state.curve, n) > 0
            {
                within = Some(state);
                fitting = more;
                round += 1;
                continue;
            }
            return done(state, reports);
        }
        if let Some(state) = within.take() {
            reports.truncate(state.round + 1);
            return done(state, reports);
        }
        if best.as_ref().is_none_or(|b| worst < b.1) {
            best = Some((curve.clone(), worst));
        }
        if round == options.max_rounds
            || insert_points(
                &mut fitting,
                &assessment.verdicts,
                options.insertion,
                &chords,
                closed,
            ) + balance(&mut fitting, tangents, &chords, closed)
                == 0
        {
            return Err(SubdivFitError::NoConvergence {
                rounds: round,
                max_error: worst,
                tolerance: options.tolerance,
                best: Box::new(match &best {
                    Some((c, e)) => BestCurve::new(c, *e),
                    None => BestCurve::new(&curve, worst),
                }),
            });
        }
        round += 1;
    }
}

/// [`Reduction::Refit`] without the insertion loop: every span fitted directly by least squares
/// from the initial points (`fit_spans`), then the point removal, measured in full. `None` when a
/// span needs more points than the search tries; the insertion loop takes over then.
fn span_fit<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    chords: &ChordLengths,
    seed: &[(usize, bool)],
    closed: bool,
    options: &FitOptions,
) -> Option<Fit<D>> {
    if seed.len() > MAX_REDUCED {
        return None;
    }
    let (mut fitting, mut curve, mut measured) =
        fit_spans(data, corners, chords, seed, closed, options)?;
    // Every segment as the span search measured it; after the removal only the changed ones.
    let a = assess_reusing(data, &fitting, &curve, closed, options, &mut measured);
    let report = |a: &crate::assess::Assessment, f: &[(usize, bool)]| RoundReport {
        round: 0,
        control_points: f.len(),
        max_data_to_curve: a.max_d2c,
        rms_data_to_curve: a.rms_d2c,
        max_curve_to_data: a.max_c2d,
    };
    if a.driven.iter().any(|&e| e > options.tolerance) {
        return None;
    }
    let reports = vec![report(&a, &fitting)];
    let mut errors = a.driven;
    let (f0, c0) = (fitting.clone(), curve.clone());
    let mut reduced = None;
    if reduce(
        data,
        corners,
        &mut fitting,
        &mut curve,
        &mut errors,
        closed,
        options,
    ) > 0
    {
        let b = assess_reusing(data, &fitting, &curve, closed, options, &mut measured);
        if b.driven.iter().any(|&e| e > options.tolerance) {
            (fitting, curve) = (f0, c0);
        } else {
            reduced = Some(report(&b, &fitting));
        }
    }
    Some(Fit {
        curve,
        fitting: fitting.iter().map(|f| f.0).collect(),
        tangents: Vec::new(),
        initial: Vec::new(),
        reports,
        reduced,
    })
}

/// A round within the tolerance: its curve, fitting points, per-segment errors and number.
struct Within<const D: usize> {
    curve: SubdivCurve<D>,
    fitting: Vec<(usize, bool)>,
    errors: Vec<f64>,
    round: usize,
}

/// The [`Fit`] of a round within the tolerance, after the reduction.
fn finish<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    chords: &ChordLengths,
    state: Within<D>,
    initial: Vec<usize>,
    reports: Vec<RoundReport>,
    options: &FitOptions,
) -> Fit<D> {
    let Within {
        curve,
        fitting,
        errors,
        round,
    } = state;
    let (curve, fitting, reduced) = match options.reduction {
        Reduction::Off => (curve, fitting, None),
        Reduction::RemovePoints | Reduction::RespaceAndRemove | Reduction::Refit => {
            let (c, f, report) =
                reduced_fit(data, corners, chords, fitting, curve, errors, options);
            (c, f, report.map(|r| RoundReport { round, ..r }))
        }
    };
    Fit {
        curve,
        fitting: fitting.iter().map(|f| f.0).collect(),
        tangents: Vec::new(),
        initial,
        reports,
        reduced,
    }
}

/// [`Reduction::RemovePoints`] or [`Reduction::RespaceAndRemove`] on a converged fit, checked once
/// more on every segment (the converged fit is kept if that check fails).
fn reduced_fit<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    chords: &ChordLengths,
    fitting: Vec<(usize, bool)>,
    curve: SubdivCurve<D>,
    mut errors: Vec<f64>,
    options: &FitOptions,
) -> (SubdivCurve<D>, Vec<(usize, bool)>, Option<RoundReport>) {
    let closed = curve.is_closed();
    let (mut f, mut c) = (fitting.clone(), curve.clone());
    let respaced = if matches!(
        options.reduction,
        Reduction::RespaceAndRemove | Reduction::Refit
    ) {
        respace_spans(data, corners, chords, &mut f, &mut c, &mut errors, options)
    } else {
        0
    };
    if reduce(data, corners, &mut f, &mut c, &mut errors, closed, options) + respaced == 0 {
        return (curve, fitting, None);
    }
    let a = assess(data, &f, &c, closed, options);
    if a.driven.iter().any(|&e| e > options.tolerance) {
        return (curve, fitting, None);
    }
    // The caller sets the round.
    let report = RoundReport {
        round: 0,
        control_points: f.len(),
        max_data_to_curve: a.max_d2c,
        rms_data_to_curve: a.rms_d2c,
        max_curve_to_data: a.max_c2d,
    };
    (c, f, Some(report))
}

fn split_largest_gap(fitting: &mut Vec<(usize, bool)>, n: usize) {
    if fitting.is_empty() {
        fitting.push((0, false));
        return;
    }
    let m = fitting.len();
    let (mut best, mut gap) = (0, 0);
    for j in 0..m {
        let a = fitting[j].0;
        let b = if j + 1 < m {
            fitting[j + 1].0
        } else {
            fitting[0].0 + n
        };
        if b - a > gap {
            gap = b - a;
            best = j;
        }
    }
    let idx = (fitting[best].0 + gap / 2) % n;
    if let Err(pos) = fitting.binary_search_by_key(&idx, |f| f.0) {
        fitting.insert(pos, (idx, false));
    }
}

/// Solves eq. (4) (and, in least-squares mode, the least-squares refinement); with
/// [`FitOptions::corner_tolerance`] set, the neighbours of corners go onto the data's tangents.
pub(crate) fn solve_curve<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    fitting: &[(usize, bool)],
    closed: bool,
    options: &FitOptions,
) -> Result<SubdivCurve<D>, SubdivFitError> {
    let k = fitting.len();
    let mut sharp: Vec<bool> = fitting.iter().map(|f| f.1).collect();
    if !closed {
        sharp[0] = true;
        sharp[k - 1] = true;
    }
    let kinds: Vec<VertexKind> = sharp
        .iter()
        .map(|&s| {
            if s {
                options.corner_kind
            } else {
                VertexKind::Regular
            }
        })
        .collect();
    let curved = options.corner_kind == VertexKind::SharpCurved;
    // Eq. (4) row by row: sharp p_i = q_i; regular (p_{i−1} + 4 p_i + p_{i+1}) / 6 = q_i, where
    // next to a curved sharp vertex p_{i±1} is its span end's derived point (still on
    // p_{i−1}, p_i, p_{i+1}).
    let (mut lower, mut diag, mut upper) = (vec![0.0; k], vec![0.0; k], vec![0.0; k]);
    let mut q = Vec::with_capacity(k);
    for (i, f) in fitting.iter().enumerate() {
        if sharp[i] {
            diag[i] = 1.0;
        } else if curved {
            let (prev, next) = ((i + k - 1) % k, (i + 1) % k);
            diag[i] = 4.0 / 6.0;
            for (m, forwards) in [(prev, true), (next, false)] {
                for (v, w) in neighbour_control(&kinds, closed, m, forwards) {
                    let slot = if v == i {
                        &mut diag[i]
                    } else if v == prev {
                        &mut lower[i]
                    } else {
                        &mut upper[i]
                    };
                    *slot += w / 6.0;
                }
            }
        } else {
            lower[i] = 1.0 / 6.0;
            diag[i] = 4.0 / 6.0;
            upper[i] = 1.0 / 6.0;
        }
        q.push(<[f64; D]>::from(data[f.0]));
    }
    let p = solve_tridiagonal(&lower, &diag, &upper, &q, closed)
        .ok_or(SubdivFitError::SingularSystem { size: k })?;
    let points: Vec<Vector<D>> = p.into_iter().map(Vector::<D>::from).collect();
    let curve = SubdivCurve::new(points, kinds, Closure::from_closed(closed))?;
    match options.mode {
        FitMode::Interpolate => Ok(if !corners.is_empty() {
            let max_move = 0.25 * options.tolerance;
            neighbours_on_tangents(corners, fitting, &curve, max_move, |_| true)
                .map_or(curve, |c| c.0)
        } else {
            curve
        }),
        FitMode::LeastSquares => {
            // A least-squares system without enough data for some control point is singular: the
            // interpolating curve is kept then.
            let mut c = curve;
            let free = vec![false; k];
            for _ in 0..2 {
                match least_squares(data, fitting, &c, &free) {
                    Ok(next) => c = next,
                    Err(_) => break,
                }
            }
            // A corner's tangents are the polygon edges to its neighbours: with the corner bound,
            // those move onto the data's tangents and the others are solved again around them.
            if !corners.is_empty()
                && let Some((on_tangents, moved)) =
                    neighbours_on_tangents(corners, fitting, &c, f64::INFINITY, |_| true)
                && let Ok(next) = least_squares(data, fitting, &on_tangents, &moved)
            {
                c = next;
            }
            Ok(c)
        }
    }
}

/// Segment j's four B-spline control points as combinations of the polygon's vertices (module
/// `curved_corner` for the derived points at a sharp vertex). The paper's rule gives
/// `a = 2 p_j − p_{j+1}` at a sharp `p_j`, else `p_{j−1}`, and likewise for `d`.
pub(crate) fn segment_controls_weights(
    kinds: &[VertexKind],
    closed: bool,
    j: usize,
) -> [Weights; 4] {
    let k = kinds.len();
    let i1 = (j + 1) % k;
    let alone = |v: usize| [(v, 1.0), (v, 0.0), (v, 0.0)];
    let (a, b) = if kinds[j].is_sharp() {
        let end = span_end(kinds, closed, j, true);
        (end.phantom, end.control)
    } else {
        (
            neighbour_control(kinds, closed, (j + k - 1) % k, true),
            alone(j),
        )
    };
    let (c, d) = if kinds[i1].is_sharp() {
        let end = span_end(kinds, closed, i1, false);
        (end.control, end.phantom)
    } else {
        (
            alone(i1),
            neighbour_control(kinds, closed, (i1 + 1) % k, false),
        )
    };
    [a, b, c, d]
}

/// The row of one data point with basis weights `w` on the vertices: `(vertex, coefficient)`
/// pairs of [`segment_controls_weights`] scaled by `w`, a vertex possibly more than once.
pub(crate) fn segment_weights(
    kinds: &[VertexKind],
    closed: bool,
    j: usize,
    w: [f64; 4],
) -> SegmentRow {
    let mut row = SegmentRow::default();
    for (control, scale) in segment_controls_weights(kinds, closed, j).iter().zip(w) {
        for &(v, c) in control {
            if c != 0.0 {
                row.push(v, c * scale);
            }
        }
    }
    row
}

/// The coefficients of one data point's row on the vertices (see [`segment_weights`]).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct SegmentRow {
    entries: [(usize, f64); 12],
    len: usize,
}

impl SegmentRow {
    fn push(&mut self, vertex: usize, coefficient: f64) {
        self.entries[self.len] = (vertex, coefficient);
        self.len += 1;
    }

    /// The `(vertex, coefficient)` pairs.
    pub(crate) fn iter(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.entries[..self.len].iter().copied()
    }
}

/// One least-squares solve: foot-point parameters from `curve`, then the regular control points
/// minimizing Σ |C(t_i) − v_i|² with the sharp ones and those marked in `keep` fixed.
fn least_squares<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    keep: &[bool],
) -> Result<SubdivCurve<D>, SubdivFitError> {
    let n = data.len();
    let kinds = curve.kinds();
    let k = kinds.len();
    let fixed = |j: usize| kinds[j].is_sharp() || keep[j];
    let unknown: Vec<Option<usize>> = {
        let mut next = 0;
        (0..k)
            .map(|j| {
                if fixed(j) {
                    None
                } else {
                    next += 1;
                    Some(next - 1)
                }
            })
            .collect()
    };
    let u = unknown.iter().flatten().count();
    if u == 0 {
        return Ok(curve.clone());
    }
    // Normal equations in band-plus-corners form (O(u) memory and time, see `banded`).
    let mut ata = CyclicBand::zeros(u);
    let mut atb = vec![[0.0; D]; u];
    for j in 0..curve.segment_count() {
        let (a, b) = segment_range(fitting, j, n);
        let ctrl = curve.segment_controls(j)?;
        let chord = chord_params(data, a, b);
        let cubic = PowerCubic::new(&ctrl);
        for (off, t0) in chord.iter().enumerate() {
            let v = data[(a + off) % n];
            let (t, _) = cubic.foot(&v, *t0);
            let row = segment_weights(kinds, curve.is_closed(), j, bspline_basis(t));
            let mut rhs = v;
            let mut coeffs: Vec<(usize, f64)> = Vec::with_capacity(6);
            for (idx, w) in row.iter() {
                match unknown[idx] {
                    Some(col) => coeffs.push((col, w)),
                    None => rhs -= curve.points()[idx] * w,
                }
            }
            for &(c1, w1) in &coeffs {
                for &(c2, w2) in &coeffs {
                    if c1 >= c2 && !ata.add_lower(c1, c2, w1 * w2) {
                        return Err(SubdivFitError::SingularSystem { size: u });
                    }
                }
                for (c, b) in atb[c1].iter_mut().enumerate() {
                    *b += w1 * rhs[c];
                }
            }
        }
    }
    let sol = ata
        .solve(&atb)
        .ok_or(SubdivFitError::SingularSystem { size: u })?;
    let mut points = curve.points().to_vec();
    for (i, slot) in unknown.iter().enumerate() {
        if let Some(col) = slot {
            points[i] = Vector::<D>::from(sol[*col]);
        }
    }
    if !points.iter().all(|p| p.iter().all(|c| c.is_finite())) {
        return Err(SubdivFitError::SingularSystem { size: u });
    }
    SubdivCurve::new(points, curve.kinds().to_vec(), curve.closure())
}
