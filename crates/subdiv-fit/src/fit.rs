//! Adaptive fitting (Secs. 3–5): initial fitting points, the interpolation system `M P = Q`
//! (eq. 4), per-segment errors (eqs. 5–6), and insertion of fitting points until the error is
//! within tolerance.

use bez_core::Vector;

use crate::banded::CyclicBand;
use crate::bspline::bspline_basis;
use crate::curvature::feature_points;
use crate::curve::{Closure, combine};
use crate::distance::{foot_point_ctrl, point_polyline_distance};
use crate::insertion::{ChordLengths, Verdict, insert_points, segment_range};
use crate::tridiagonal::solve_tridiagonal;
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
    /// The paper's interpolation of the fitting points, eq. (4).
    Interpolate,
    /// Interpolation first, then the regular control points re-solved by least squares over all
    /// data points at their foot-point parameters (sharp control points stay on their data points).
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

/// Options of [`fit`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct FitOptions {
    /// Maximum allowed error δ (Sec. 5), in data units.
    pub tolerance: f64,
    /// A data point is sharp when the angle between its two edges is below this (radians).
    /// Default 140° (a turn of more than 40°): a smooth curve sampled at spacing h with radius of
    /// curvature r turns by about h / r per point, so only features with r < 1.4 h, not resolved by
    /// the sampling, are taken for corners.
    pub sharp_angle: f64,
    /// Curvature floor relative to the bounding-box diagonal L: maxima with `K · L` at or below it
    /// are ignored. Default 1e-6 (a radius of curvature above a million diagonals counts as straight).
    pub curvature_floor: f64,
    /// Relative prominence a curvature maximum needs over its predecessor. Default 1e-9.
    pub prominence: f64,
    /// Maximum number of insertion rounds. Default 100.
    pub max_rounds: usize,
    /// Error measure. Default [`ErrorMeasure::TwoSided`].
    pub measure: ErrorMeasure,
    /// Solver. Default [`FitMode::Interpolate`].
    pub mode: FitMode,
    /// Samples per segment for the curve-to-data distance. Default 32.
    pub samples_per_segment: usize,
    /// Insertion rule. Default [`Insertion::Bisect`].
    pub insertion: Insertion,
}

impl FitOptions {
    /// The defaults with the given tolerance.
    #[must_use]
    pub fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            sharp_angle: 140f64.to_radians(),
            curvature_floor: 1e-6,
            prominence: 1e-9,
            max_rounds: 100,
            measure: ErrorMeasure::TwoSided,
            mode: FitMode::Interpolate,
            samples_per_segment: 32,
            insertion: Insertion::Bisect,
        }
    }

    /// The paper's configuration: one-sided error, interpolation.
    #[must_use]
    pub fn paper(tolerance: f64) -> Self {
        Self {
            measure: ErrorMeasure::DataToCurve,
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
    /// The fitted curve: one control point per fitting point.
    pub curve: SubdivCurve<D>,
    /// Data indices of the fitting points, increasing; segment j covers data
    /// `fitting[j]..=fitting[j+1]` (wrapping for closed data).
    pub fitting: Vec<usize>,
    /// Data indices of the initial fitting points (round 0).
    pub initial: Vec<usize>,
    /// One report per round, round 0 first.
    pub reports: Vec<RoundReport>,
}

impl<const D: usize> Fit<D> {
    /// Number of insertion rounds performed (the paper's "loops").
    #[must_use]
    pub fn rounds(&self) -> usize {
        self.reports.len().saturating_sub(1)
    }

    /// The last round's report.
    #[must_use]
    pub fn last(&self) -> Option<&RoundReport> {
        self.reports.last()
    }
}

/// Validates data: finite, no coinciding consecutive points, enough points.
fn validate<const D: usize>(data: &[Vector<D>], closed: bool) -> Result<(), SubdivFitError> {
    let needed = 3;
    if data.len() < needed {
        return Err(SubdivFitError::TooFewPoints {
            got: data.len(),
            needed,
        });
    }
    if let Some(index) = data.iter().position(|p| !p.iter().all(|c| c.is_finite())) {
        return Err(SubdivFitError::NonFinite { index });
    }
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
    let checks: [(&'static str, f64, bool, &'static str); 4] = [
        (
            "sharp_angle",
            o.sharp_angle,
            (0.0..=std::f64::consts::PI).contains(&o.sharp_angle),
            "must lie in [0, π]",
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

/// Fits a subdivision curve with sharp vertices to ordered data (Secs. 3–5).
///
/// 1. Initial fitting points: curvature maxima and sharp points ([`crate::feature_points`]); for closed
///    data with fewer than 3, the largest gaps are split at their middle index.
/// 2. Control points from `M P = Q` (eq. 4): a sharp fitting point gives `p_i = q_i`, a regular one
///    `(p_{i−1} + 4 p_i + p_{i+1}) / 6 = q_i`, a (cyclic) tridiagonal system solved in O(k) by
///    Thomas's algorithm with a Sherman–Morrison corner correction (the matrix is strictly diagonally
///    dominant in its regular rows, so it is never singular in exact arithmetic).
/// 3. Errors per segment: each data point between two fitting points against that segment only, by
///    Newton on eq. (6) from the chord-length parameter; with [`ErrorMeasure::TwoSided`] also the
///    distance of dense curve samples to the segment's data polyline.
/// 4. Every segment whose error exceeds the tolerance gets a new regular fitting point, chosen by
///    [`FitOptions::insertion`] (by default the chord-length middle); repeat.
///
/// # Errors
/// Invalid data or options (typed), [`SubdivFitError::SingularSystem`],
/// [`SubdivFitError::NoConvergence`] when the round cap is hit or no segment can take another point.
pub fn fit<const D: usize>(
    data: &[Vector<D>],
    closure: Closure,
    options: &FitOptions,
) -> Result<Fit<D>, SubdivFitError> {
    let closed = closure.is_closed();
    validate(data, closed)?;
    validate_options(options)?;
    let n = data.len();
    let features = feature_points(
        data,
        closed,
        options.sharp_angle,
        options.curvature_floor,
        options.prominence,
    );
    let mut fitting: Vec<(usize, bool)> = features.iter().map(|f| (f.index, f.sharp)).collect();
    if closed {
        while fitting.len() < 3 {
            split_largest_gap(&mut fitting, n);
        }
    }
    let initial: Vec<usize> = fitting.iter().map(|f| f.0).collect();
    let chords = ChordLengths::new(data, closed);
    let mut reports = Vec::new();
    for round in 0..=options.max_rounds {
        let curve = solve_curve(data, &fitting, closed, options.mode)?;
        let assessment = assess(data, &fitting, &curve, closed, options);
        reports.push(RoundReport {
            round,
            control_points: fitting.len(),
            max_data_to_curve: assessment.max_d2c,
            rms_data_to_curve: assessment.rms_d2c,
            max_curve_to_data: assessment.max_c2d,
        });
        let worst = match options.measure {
            ErrorMeasure::DataToCurve => assessment.max_d2c,
            ErrorMeasure::TwoSided => assessment.max_d2c.max(assessment.max_c2d),
        };
        if worst <= options.tolerance {
            return Ok(Fit {
                curve,
                fitting: fitting.iter().map(|f| f.0).collect(),
                initial,
                reports,
            });
        }
        if round == options.max_rounds
            || insert_points(
                &mut fitting,
                &assessment.verdicts,
                options.insertion,
                &chords,
                closed,
            ) == 0
        {
            return Err(SubdivFitError::NoConvergence {
                rounds: round,
                max_error: worst,
                tolerance: options.tolerance,
            });
        }
    }
    Err(SubdivFitError::NoConvergence {
        rounds: options.max_rounds,
        max_error: f64::INFINITY,
        tolerance: options.tolerance,
    })
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

/// Solves eq. (4) (and, in least-squares mode, the least-squares refinement).
fn solve_curve<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    closed: bool,
    mode: FitMode,
) -> Result<SubdivCurve<D>, SubdivFitError> {
    let k = fitting.len();
    let mut sharp: Vec<bool> = fitting.iter().map(|f| f.1).collect();
    if !closed {
        sharp[0] = true;
        sharp[k - 1] = true;
    }
    // Eq. (4) row by row: sharp p_i = q_i; regular (p_{i−1} + 4 p_i + p_{i+1}) / 6 = q_i.
    let (mut lower, mut diag, mut upper) = (vec![0.0; k], vec![0.0; k], vec![0.0; k]);
    let mut q = Vec::with_capacity(k);
    for (i, f) in fitting.iter().enumerate() {
        if sharp[i] {
            diag[i] = 1.0;
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
    let curve = SubdivCurve::new(points, sharp, Closure::from_closed(closed))?;
    match mode {
        FitMode::Interpolate => Ok(curve),
        FitMode::LeastSquares => {
            let mut c = curve;
            for _ in 0..2 {
                c = least_squares(data, fitting, &c)?;
            }
            Ok(c)
        }
    }
}

/// Coefficients of segment j's four B-spline control points on the polygon's vertices.
fn segment_weights(sharp: &[bool], j: usize, w: [f64; 4]) -> [(usize, f64); 6] {
    let k = sharp.len();
    let i1 = (j + 1) % k;
    let prev = (j + k - 1) % k;
    let next = (i1 + 1) % k;
    let a: [(usize, f64); 2] = if sharp[j] {
        [(j, 2.0 * w[0]), (i1, -w[0])]
    } else {
        [(prev, w[0]), (j, 0.0)]
    };
    let d: [(usize, f64); 2] = if sharp[i1] {
        [(i1, 2.0 * w[3]), (j, -w[3])]
    } else {
        [(next, w[3]), (i1, 0.0)]
    };
    [a[0], a[1], (j, w[1]), (i1, w[2]), d[0], d[1]]
}

/// One least-squares solve: foot-point parameters from `curve`, then the regular control points
/// minimizing Σ |C(t_i) − v_i|² with the sharp ones fixed.
fn least_squares<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
) -> Result<SubdivCurve<D>, SubdivFitError> {
    let n = data.len();
    let sharp = curve.sharp();
    let unknown: Vec<Option<usize>> = {
        let mut next = 0;
        sharp
            .iter()
            .map(|&s| {
                if s {
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
        for (off, t0) in chord.iter().enumerate() {
            let v = data[(a + off) % n];
            let (t, _) = foot_point_ctrl(&ctrl, &v, *t0);
            let row = segment_weights(sharp, j, bspline_basis(t));
            let mut rhs = v;
            let mut coeffs: Vec<(usize, f64)> = Vec::with_capacity(6);
            for (idx, w) in row {
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
    SubdivCurve::new(points, sharp.to_vec(), curve.closure())
}

/// Chord-length parameters of data a..=b (indices mod n), the paper's Newton start (Sec. 5).
fn chord_params<const D: usize>(data: &[Vector<D>], a: usize, b: usize) -> Vec<f64> {
    let n = data.len();
    let mut acc = Vec::with_capacity(b - a + 1);
    let mut s = 0.0;
    acc.push(0.0);
    for i in a..b {
        s += (data[(i + 1) % n] - data[i % n]).norm();
        acc.push(s);
    }
    if s > 0.0 {
        for x in &mut acc {
            *x = (*x / s).clamp(0.0, 1.0);
        }
    }
    acc
}

struct Assessment {
    max_d2c: f64,
    rms_d2c: f64,
    max_c2d: f64,
    verdicts: Vec<Verdict>,
}

fn assess<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    closed: bool,
    options: &FitOptions,
) -> Assessment {
    let n = data.len();
    let tol = options.tolerance;
    let (mut max_d2c, mut sum2, mut count, mut max_c2d) = (0.0_f64, 0.0, 0usize, 0.0_f64);
    let mut verdicts = Vec::new();
    let segs = curve.segment_count();
    let mut poly: Vec<Vector<D>> = Vec::new();
    for j in 0..segs {
        let (a, b) = segment_range(fitting, j, n);
        let Ok(ctrl) = curve.segment_controls(j) else {
            verdicts.push(Verdict {
                fails: false,
                worst_point: None,
            });
            continue;
        };
        let chord = chord_params(data, a, b);
        let (mut seg_max, mut seg_arg) = (0.0_f64, None);
        for (off, t0) in chord.iter().enumerate() {
            // The segment's end data points are counted once, by the segment that starts there
            // (for open data the last point also by the last segment).
            let last_of_open = !closed && j + 1 == segs && off + 1 == chord.len();
            if off + 1 == chord.len() && !last_of_open {
                continue;
            }
            let v = data[(a + off) % n];
            let (_, d) = foot_point_ctrl(&ctrl, &v, *t0);
            sum2 += d * d;
            count += 1;
            if d > seg_max {
                seg_max = d;
                if off > 0 && a + off < b {
                    seg_arg = Some((a + off) % n);
                }
            }
        }
        max_d2c = max_d2c.max(seg_max);
        let mut verdict = Verdict {
            fails: seg_max > tol,
            worst_point: seg_arg.filter(|_| seg_max > tol),
        };
        if options.measure == ErrorMeasure::TwoSided || !verdict.fails {
            poly.clear();
            poly.extend((a..=b).map(|i| data[i % n]));
            let s = options.samples_per_segment;
            let (mut worst, mut worst_u) = (0.0_f64, 0.0);
            for m in 0..=s {
                let u = m as f64 / s as f64;
                let d = point_polyline_distance(&combine(&ctrl, bspline_basis(u)), &poly);
                if d > worst {
                    worst = d;
                    worst_u = u;
                }
            }
            max_c2d = max_c2d.max(worst);
            if options.measure == ErrorMeasure::TwoSided && !verdict.fails && worst > tol {
                let p = combine(&ctrl, bspline_basis(worst_u));
                verdict = Verdict {
                    fails: true,
                    worst_point: (a + 1..b)
                        .map(|i| (i % n, (data[i % n] - p).norm()))
                        .min_by(|x, y| x.1.total_cmp(&y.1))
                        .map(|x| x.0),
                };
            }
        }
        verdicts.push(verdict);
    }
    Assessment {
        max_d2c,
        rms_d2c: if count > 0 {
            (sum2 / count as f64).sqrt()
        } else {
            0.0
        },
        max_c2d,
        verdicts,
    }
}
