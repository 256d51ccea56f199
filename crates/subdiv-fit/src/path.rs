//! Paths in and out (feature `kurbo`): kurbo `BezPath`s and SVG path data sampled to points with
//! their corners, fitted contour by contour, and fitted curves written as `BezPath`s of exact
//! cubic Bézier segments.

use bez_core::{BezierCurve, Vector2, bez_path_to_curves};
use kurbo::{BezPath, Point};

use crate::curvature::angle_between;
use crate::line_samples::{LineSampling, line_parameters, line_sample_count};
use crate::{
    Closure, Corner, Fit, FitOptions, Joints, MAX_FIT_POINTS, Reduction, SubdivCurve,
    SubdivFitError, fit_with_joints, fit_with_known_corners,
};

/// A joint of a path where the tangent turns by more than this (radians, 1°) is a corner.
pub const PATH_CORNER_ANGLE: f64 = std::f64::consts::PI / 180.0;

/// One subpath sampled to points: its closure and the sample indices of its corners (joints
/// between path segments where the tangent turns by more than [`PATH_CORNER_ANGLE`]; the ends of
/// an open subpath are not listed, a fit makes them sharp anyway).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct SampledContour {
    /// The samples, no two consecutive ones equal (nor the last and the first of a closed one).
    pub points: Vec<Vector2>,
    /// Closed when the subpath ends where it starts.
    pub closure: Closure,
    /// Sample indices of the corners, increasing.
    pub corners: Vec<usize>,
    /// The path's incoming and outgoing tangent directions at each corner (one per entry of
    /// `corners`; the tangents of the segments that meet there, not normalized).
    pub corner_tangents: Vec<(Vector2, Vector2)>,
    /// The smooth joints (the tangent turns by at most [`PATH_CORNER_ANGLE`]) with the signed
    /// curvatures of the two segments that meet there: (sample index, incoming, outgoing),
    /// increasing. Where they differ the joint is tangent-continuous with a curvature jump
    /// ([`SampledContour::tangent_joints`]).
    pub smooth_joints: Vec<(usize, f64, f64)>,
    /// The path's unit tangent at each smooth joint (one per entry of `smooth_joints`: the mean
    /// direction of the two segments that meet there).
    pub smooth_tangents: Vec<Vector2>,
    /// A bound on the distance between the subpath and the polyline of its samples (each chord
    /// against its arc): `n(n − 1) max|Δ²P| / (8 m²)` for a segment of degree n with control
    /// points P sampled at m equal parameter steps, the largest over the segments.
    pub chord_error: f64,
}

impl SampledContour {
    /// The corners with their tangents, for [`fit_with_known_corners`] (a corner whose tangents
    /// cannot be normalized, which needs coordinates near the largest `f64`, is given without
    /// them).
    #[must_use]
    pub fn known_corners(&self) -> Vec<Corner<2>> {
        self.corners
            .iter()
            .zip(&self.corner_tangents)
            .map(|(&i, &(a, b))| Corner::with_tangents(i, a, b).unwrap_or(Corner::new(i)))
            .collect()
    }

    /// The corners with their tangents ([`SampledContour::known_corners`]) and the tangent joints
    /// of [`SampledContour::tangent_joints`] as smooth joints with the path's tangent there
    /// ([`Corner::smooth`]), for [`fit_with_known_corners`] with
    /// [`Reduction::Refit`](crate::Reduction::Refit), by increasing index.
    #[must_use]
    pub fn known_joints(&self, threshold: f64) -> Vec<Corner<2>> {
        let mut known = self.known_corners();
        for i in self.tangent_joints(threshold) {
            let tangent = self
                .smooth_joints
                .iter()
                .position(|j| j.0 == i)
                .map(|at| self.smooth_tangents[at]);
            if let Some(Ok(joint)) = tangent.map(|t| Corner::smooth(i, t)) {
                known.push(joint);
            }
        }
        known.sort_by_key(Corner::index);
        known
    }

    /// The smooth joints whose one-sided curvatures differ by at least `threshold` times the
    /// larger one (the rule of [`FitOptions::tangent_jump`], here on the path's exact curvatures),
    /// with at least [`JOINT_ROOM`] samples to the nearest corner, end of an open subpath or other
    /// such joint (a joint closer to one already taken, in the path's order, is left out): the tangent joints
    /// [`fit_bez_path`] gives [`fit_with_joints`].
    #[must_use]
    pub fn tangent_joints(&self, threshold: f64) -> Vec<usize> {
        let n = self.points.len();
        let closed = self.closure.is_closed();
        let gap = |a: usize, b: usize| {
            let d = a.abs_diff(b);
            if closed { d.min(n - d) } else { d }
        };
        let mut taken: Vec<usize> = Vec::new();
        for &(i, k_in, k_out) in &self.smooth_joints {
            let jump = (k_in - k_out).abs();
            let larger = k_in.abs().max(k_out.abs());
            let ends = !closed && (i < JOINT_ROOM || i + JOINT_ROOM >= n);
            if jump.is_finite()
                && larger > 0.0
                && jump >= threshold * larger
                && !ends
                && self.corners.iter().all(|&c| gap(c, i) >= JOINT_ROOM)
                && taken.last().is_none_or(|&t| gap(t, i) >= JOINT_ROOM)
                && taken.first().is_none_or(|&t| gap(t, i) >= JOINT_ROOM)
            {
                taken.push(i);
            }
        }
        taken
    }
}

/// Samples that a tangent joint of a path needs to its nearest corner, end or other joint: room
/// for the two regular fitting points on each side that a tangent vertex's double knot reaches.
pub const JOINT_ROOM: usize = 6;

/// Samples every subpath of `path` about every `spacing` (each segment at equal parameter steps,
/// as many as its control polygon is long in spacings, and at least as many as keep its polyline
/// within `spacing / 8` of it, see [`SampledContour::chord_error`]), keeping every segment's end
/// points (so the corners are samples): [`sample_bez_path_with`] and [`LineSampling::Even`].
///
/// ```
/// use subdiv_fit::{Closure, sample_bez_path};
///
/// let path = kurbo::BezPath::from_svg("M0 0 L10 0 Q10 10 0 10 Z").unwrap();
/// let contours = sample_bez_path(&path, 0.5)?;
/// assert_eq!(contours.len(), 1);
/// assert_eq!(contours[0].closure, Closure::Closed);
/// // Corners at the three joints: the line (20 samples) meets the quadratic, the quadratic
/// // (polygon length 20, 40 samples) meets the closing line, which meets the first line.
/// assert_eq!(contours[0].corners, [0, 20, 60]);
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
///
/// # Errors
/// [`SubdivFitError::InvalidOption`] (`spacing`) unless `spacing` is positive and finite;
/// [`SubdivFitError::Core`] for a non-finite path element; [`SubdivFitError::TooLarge`] when the
/// samples would exceed [`MAX_FIT_POINTS`] (checked before sampling).
pub fn sample_bez_path(
    path: &BezPath,
    spacing: f64,
) -> Result<Vec<SampledContour>, SubdivFitError> {
    sample_bez_path_with(path, spacing, LineSampling::Even)
}

/// [`sample_bez_path`] with the path's lines sampled as `lines` says ([`LineSampling::Graded`]:
/// at `spacing` next to their ends, sparser in between; the curved segments as before).
///
/// ```
/// use subdiv_fit::{LineSampling, sample_bez_path_with};
///
/// // A line 1,000 spacings long and back.
/// let path = kurbo::BezPath::from_svg("M0 0 L1000 0 Z").unwrap();
/// let even = sample_bez_path_with(&path, 1.0, LineSampling::Even)?;
/// let graded = sample_bez_path_with(&path, 1.0, LineSampling::Graded)?;
/// assert_eq!(even[0].points.len(), 2000);
/// assert_eq!(even[0].corners, [0, 1000]);
/// // Each way the start and 27 samples from each end: 16 a spacing apart, 6 steps doubling to
/// // 64 spacings, 5 steps of 64.
/// assert_eq!(graded[0].points.len(), 2 * (1 + 2 * 27));
/// assert_eq!(graded[0].corners, [0, 55]);
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
///
/// # Errors
/// As [`sample_bez_path`].
pub fn sample_bez_path_with(
    path: &BezPath,
    spacing: f64,
    lines: LineSampling,
) -> Result<Vec<SampledContour>, SubdivFitError> {
    if !(spacing.is_finite() && spacing > 0.0) {
        return Err(SubdivFitError::InvalidOption {
            name: "spacing",
            value: spacing,
            reason: "must be positive and finite",
        });
    }
    let subpaths = bez_path_to_curves(path)?;
    // Samples per segment, and their total, before any sample is made.
    let mut total = 0.0_f64;
    let counts: Vec<Vec<(usize, bool)>> = subpaths
        .iter()
        .map(|sub| {
            sub.iter()
                .enumerate()
                .map(|(j, c)| {
                    let graded = lines == LineSampling::Graded && line_between_corners(sub, j);
                    let len: f64 = c.points().windows(2).map(|w| (w[1] - w[0]).norm()).sum();
                    // The chord error n(n − 1) max|Δ²P| / (8 m²) at most spacing / 8.
                    let bend = second_difference_bound(c);
                    let m = (len / spacing)
                        .ceil()
                        .max((bend / spacing).sqrt().ceil())
                        .max(1.0);
                    // The segment's start and its samples inside.
                    total += 1.0
                        + if graded {
                            line_sample_count(m)
                        } else {
                            m - 1.0
                        };
                    let m = if m.is_finite() {
                        m as usize
                    } else {
                        usize::MAX
                    };
                    (m, graded)
                })
                .collect()
        })
        .collect();
    if total.is_nan() || total > MAX_FIT_POINTS as f64 {
        return Err(SubdivFitError::TooLarge {
            name: "path samples",
            requested: if total.is_finite() {
                total as usize
            } else {
                usize::MAX
            },
            max: MAX_FIT_POINTS,
        });
    }
    Ok(subpaths
        .iter()
        .zip(&counts)
        .map(|(sub, counts)| sample_subpath(sub, counts))
        .collect())
}

/// [`sample_bez_path`] on SVG path data (`M`, `L`, `H`, `V`, `Q`, `T`, `C`, `S`, `A`, `Z`, as kurbo
/// reads it).
///
/// # Errors
/// [`SubdivFitError::InvalidPathData`] when the data do not parse; otherwise as
/// [`sample_bez_path`].
pub fn sample_svg_path(data: &str, spacing: f64) -> Result<Vec<SampledContour>, SubdivFitError> {
    let path = BezPath::from_svg(data).map_err(|e| SubdivFitError::InvalidPathData {
        reason: e.to_string(),
    })?;
    sample_bez_path(&path, spacing)
}

/// `n(n − 1) max|Δ²P|` of a Bézier segment of degree n: a bound on the norm of its second
/// derivative.
fn second_difference_bound(c: &BezierCurve<2>) -> f64 {
    let n = c.points().len().saturating_sub(1) as f64;
    let d2 = c
        .points()
        .windows(3)
        .map(|w| (w[2] - 2.0 * w[1] + w[0]).norm())
        .fold(0.0, f64::max);
    n * (n - 1.0) * d2
}

/// Whether segment `j` of `sub` is a line with a corner (or an open end) at both ends: a line
/// that meets a curve tangentially is sampled evenly, since a fit of the joint weighs the line's
/// samples as the curve's.
fn line_between_corners(sub: &[BezierCurve<2>], j: usize) -> bool {
    let closed = sub.len() > 1 && sub.first().map(|c| c.start()) == sub.last().map(|c| c.end());
    let corner = |a: &BezierCurve<2>, b: &BezierCurve<2>| {
        matches!((end_tangent(a), start_tangent(b)),
            (Some(u), Some(v)) if angle_between(&u, &v) > PATH_CORNER_ANGLE)
    };
    let before = match j.checked_sub(1) {
        Some(i) => Some(&sub[i]),
        None if closed => sub.last(),
        None => None,
    };
    let after = match sub.get(j + 1) {
        Some(next) => Some(next),
        None if closed => sub.first(),
        None => None,
    };
    let c = &sub[j];
    c.degree() == 1 && before.is_none_or(|b| corner(b, c)) && after.is_none_or(|a| corner(c, a))
}

/// Samples one subpath, each segment with its `(steps, graded)` of `counts`.
fn sample_subpath(sub: &[BezierCurve<2>], counts: &[(usize, bool)]) -> SampledContour {
    let (Some(first), Some(last)) = (sub.first(), sub.last()) else {
        return SampledContour {
            points: Vec::new(),
            closure: Closure::Open,
            corners: Vec::new(),
            corner_tangents: Vec::new(),
            smooth_joints: Vec::new(),
            smooth_tangents: Vec::new(),
            chord_error: 0.0,
        };
    };
    let closed = first.start() == last.end() && sub.len() > 1;
    let mut points: Vec<Vector2> = Vec::new();
    let mut corners: Vec<usize> = Vec::new();
    let mut corner_tangents: Vec<(Vector2, Vector2)> = Vec::new();
    let mut smooth_joints: Vec<(usize, f64, f64)> = Vec::new();
    let mut smooth_tangents: Vec<Vector2> = Vec::new();
    let mut chord_error = 0.0_f64;
    for (j, (c, &(m, graded))) in sub.iter().zip(counts).enumerate() {
        let steps = m as f64;
        chord_error = chord_error.max(second_difference_bound(c) / (8.0 * steps * steps));
        let joint = if j > 0 {
            Some(&sub[j - 1])
        } else if closed {
            Some(last)
        } else {
            None
        };
        if points.last() != Some(&c.start()) {
            points.push(c.start());
        }
        if let Some(prev) = joint
            && let (Some(a), Some(b)) = (end_tangent(prev), start_tangent(c))
            && angle_between(&a, &b) <= PATH_CORNER_ANGLE
            && let (Ok(k_in), Ok(k_out)) = (prev.signed_curvature(1.0), c.signed_curvature(0.0))
            && (k_in.is_finite() && k_out.is_finite())
            && smooth_joints.last().is_none_or(|l| l.0 < points.len() - 1)
            && let Some(tangent) = mean_direction(a, b)
        {
            smooth_joints.push((points.len() - 1, k_in, k_out));
            smooth_tangents.push(tangent);
        }
        if let Some(prev) = joint
            && let (Some(a), Some(b)) = (end_tangent(prev), start_tangent(c))
            && angle_between(&a, &b) > PATH_CORNER_ANGLE
        {
            let index = points.len() - 1;
            // Two joints on one sample (a segment that adds none): arriving as the first, leaving
            // as the last.
            match (corners.last(), corner_tangents.last_mut()) {
                (Some(&i), Some(t)) if i == index => t.1 = b,
                _ => {
                    corners.push(index);
                    corner_tangents.push((a, b));
                }
            }
        }
        let mut push = |t: f64| {
            if let Ok(p) = c.eval(t)
                && points.last() != Some(&p)
            {
                points.push(p);
            }
        };
        if graded {
            line_parameters(m).for_each(&mut push);
        } else {
            (1..m).for_each(|k| push(k as f64 / m as f64));
        }
    }
    if closed {
        if points.len() > 1 && points.first() == points.last() {
            points.pop();
        }
    } else if points.last() != Some(&last.end()) {
        points.push(last.end());
    }
    SampledContour {
        points,
        closure: Closure::from_closed(closed),
        corners,
        corner_tangents,
        smooth_joints,
        smooth_tangents,
        chord_error,
    }
}

/// The unit mean of the directions `a` and `b` (which turn by at most [`PATH_CORNER_ANGLE`]);
/// `None` where it cannot be normalized.
fn mean_direction(a: Vector2, b: Vector2) -> Option<Vector2> {
    let (na, nb) = (a.norm(), b.norm());
    let mean = a / na + b / nb;
    let norm = mean.norm();
    (norm > 0.0 && norm.is_finite()).then(|| mean / norm)
}

fn start_tangent(c: &BezierCurve<2>) -> Option<Vector2> {
    let p = c.points();
    p.iter().skip(1).find(|q| **q != p[0]).map(|q| q - p[0])
}

fn end_tangent(c: &BezierCurve<2>) -> Option<Vector2> {
    let p = c.points();
    let end = p[p.len() - 1];
    p.iter().rev().skip(1).find(|q| **q != end).map(|q| end - q)
}

/// Fits every subpath of `path` ([`fit_with_known_corners`] on its samples about every
/// `tolerance`, the path's corners given as known corners with the path's exact tangents there, so
/// that [`FitOptions::corner_tolerance`] bounds the turns against the outline itself) and returns
/// the fitted curves as one path of cubic Bézier segments, with the fits. Subpaths with fewer than
/// 3 samples are left out. Each contour is fitted at the tolerance less its samples'
/// [`SampledContour::chord_error`] (at most an eighth of it), so that the fit's two-sided error
/// holds against the path, not only against its samples. The path's lines are sampled as
/// [`LineSampling::for_fit`] says: with [`Reduction::Refit`] those between corners at the spacing
/// next to their ends and sparser between ([`LineSampling::Graded`]).
///
/// The path states its tangent discontinuities exactly, so they are all its corners: no other
/// corner is detected on its samples ([`FitOptions::sharp_angle`] is taken as 0), and a bend that is smooth in the path stays
/// smooth in the fit, however tight. To have tight bends detected as corners as well, fit
/// [`sample_bez_path`]'s samples with [`fit_with_known_corners`]. Likewise with
/// [`FitOptions::tangent_jump`] set, the tangent joints are the path's own smooth joints where the
/// curvature jumps by the threshold ([`SampledContour::tangent_joints`], on the exact curvatures;
/// none is detected on the samples), and the fit takes them with [`fit_with_joints`] (which
/// interpolates without reduction, see there), or with [`Reduction::Refit`] as smooth joints on
/// the path's own tangents ([`SampledContour::known_joints`], [`Corner::smooth`]); the fit's
/// [`Fit::tangents`] lists them either way.
///
/// ```
/// use subdiv_fit::{FitOptions, fit_bez_path};
///
/// let circle = kurbo::Circle::new((0.0, 0.0), 1.0);
/// let path = kurbo::Shape::to_path(&circle, 1e-9);
/// let (fitted, fits) = fit_bez_path(&path, &FitOptions::new(1e-3))?;
/// assert_eq!(fits.len(), 1);
/// assert!(fits[0].curve.points().len() <= 16);
/// assert_eq!(fitted.segments().count(), fits[0].curve.segment_count());
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
///
/// # Errors
/// As [`sample_bez_path`] and [`fit_with_known_corners`].
pub fn fit_bez_path(
    path: &BezPath,
    options: &FitOptions,
) -> Result<(BezPath, Vec<Fit<2>>), SubdivFitError> {
    let mut out = BezPath::new();
    let mut fits = Vec::new();
    let only_given = options.with_sharp_angle(0.0).with_tangent_jump(None);
    let lines = LineSampling::for_fit(options);
    for contour in sample_bez_path_with(path, options.tolerance, lines)? {
        if contour.points.len() < 3 {
            continue;
        }
        // Within the tolerance of the path itself: the samples' polyline is within the chord
        // error of it (at most an eighth of the tolerance).
        let only_given = only_given.with_tolerance(options.tolerance - contour.chord_error);
        let joints = options
            .tangent_jump
            .map(|threshold| contour.tangent_joints(threshold))
            .unwrap_or_default();
        let f = if joints.is_empty() {
            let known = contour.known_corners();
            fit_with_known_corners(&contour.points, contour.closure, &known, &only_given)?
        } else if let (Some(threshold), Reduction::Refit) =
            (options.tangent_jump, options.reduction)
        {
            // The joints as smooth joints on the path's own tangents.
            let known = contour.known_joints(threshold);
            Fit {
                tangents: joints,
                ..fit_with_known_corners(&contour.points, contour.closure, &known, &only_given)?
            }
        } else {
            let given = Joints::new()
                .with_corners(&contour.corners)
                .with_tangents(&joints);
            fit_with_joints(&contour.points, contour.closure, &given, &only_given)?
        };
        for el in f.curve.to_bez_path()?.elements() {
            out.push(*el);
        }
        fits.push(f);
    }
    Ok((out, fits))
}

impl SubdivCurve<2> {
    /// The limit curve as a kurbo path of exact cubic Bézier segments (one per polygon edge;
    /// sharp vertices are where the tangent may jump), closed with `ClosePath` if the polygon is.
    ///
    /// # Errors
    /// As [`SubdivCurve::to_beziers`].
    pub fn to_bez_path(&self) -> Result<BezPath, SubdivFitError> {
        let mut path = BezPath::new();
        for (i, b) in self.to_beziers()?.iter().enumerate() {
            let p: Vec<Point> = b.points().iter().map(|&v| v.into()).collect();
            if i == 0 {
                path.move_to(p[0]);
            }
            path.curve_to(p[1], p[2], p[3]);
        }
        if self.is_closed() {
            path.close_path();
        }
        Ok(path)
    }
}
