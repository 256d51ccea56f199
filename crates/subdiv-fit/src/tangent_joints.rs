//! Detection of tangent joints ([`FitOptions::tangent_jump`]): data points where the outline
//! stays tangent-continuous but its curvature jumps, as where a straight side meets an arc.
//!
//! At every data point a least-squares quadratic `b x + a x²` through the point is fitted to the
//! samples within the reach `r` (16 feature scales) on each side (`x` the polyline length over `r`;
//! the samples averaged in at most [`SAMPLES`] runs of consecutive ones); its curvature vector at the point, `K = (2a)⊥ / |b|²`
//! (the part of `2a` across the tangent `b`), is the same whichever way the side runs. A joint is
//! a point where
//!
//! - the one-sided tangents agree within [`MAX_TURN`];
//! - the relative jump `|K⁺ − K⁻| / max(|K⁺|, |K⁻|)` is at least the threshold (1 where a line
//!   meets an arc, `1 − ρ₁/ρ₂` where arcs of radii ρ₁ < ρ₂ meet);
//! - the jump is above the noise: `|K⁺ − K⁻| · r ≥` [`NOISE_FLOOR`] (noise of amplitude ε moves
//!   each estimate by about `2ε / r²`, and ε ≤ tol / 4 = r / 384);
//! - the difference at half the reach is at least [`SCALE_RATIO`] of that at the full reach (a
//!   jump differs by the same at every reach, a smooth change of curvature, an ellipse's say, by
//!   about half as much at half the reach);
//! - no point within `r` jumps more (by `|K⁺ − K⁻|`), and it is at least `r` from every corner,
//!   from the given tangent joints and from the ends of open data.

use bez_core::Vector;

use crate::chord::ChordLengths;
use crate::corner_angles::{REACH_SCALES, SAMPLES};
use crate::fit::FitOptions;

/// The one-sided curvatures of a tangent joint must differ at half the reach by at least this
/// fraction of their difference at the full reach: a jump differs by the same at every reach, a
/// smooth change of curvature by about half as much at half the reach.
pub(crate) const SCALE_RATIO: f64 = 0.75;

/// The smallest `|K⁺ − K⁻| · r` taken for a jump: 0.005, about the estimates' response to noise
/// of a quarter of the tolerance.
pub(crate) const NOISE_FLOOR: f64 = 0.005;

/// The largest angle between the two one-sided tangents of a tangent joint: 5° (a larger turn
/// within the reach is a corner or a bend, not a joint).
pub(crate) const MAX_TURN: f64 = 5.0 * std::f64::consts::PI / 180.0;

/// Prefix sums of the data's arc lengths and positions over the data unrolled once more round
/// (closed data), for the means of runs of samples in O(1).
struct Sums<const D: usize> {
    /// Arc length from point 0 of unrolled point j.
    arc: Vec<f64>,
    /// Σ of `arc` and of the positions over the first j unrolled points.
    arc_sum: Vec<f64>,
    point_sum: Vec<Vector<D>>,
    n: usize,
    closed: bool,
}

impl<const D: usize> Sums<D> {
    fn new(data: &[Vector<D>], arc: &[f64], total: f64, closed: bool) -> Self {
        let n = data.len();
        let m = if closed { 2 * n } else { n };
        let unrolled: Vec<f64> = (0..m)
            .map(|j| if j < n { arc[j] } else { arc[j - n] + total })
            .collect();
        let (mut arc_sum, mut point_sum) = (vec![0.0], vec![Vector::<D>::zeros()]);
        for j in 0..m {
            arc_sum.push(arc_sum[j] + unrolled[j]);
            point_sum.push(point_sum[j] + data[j % n]);
        }
        Self {
            arc: unrolled,
            arc_sum,
            point_sum,
            n,
            closed,
        }
    }
}

/// The one-sided estimate at data point `i`: unit tangent (along the data's direction) and
/// curvature vector, from the samples within `reach` forwards or backwards, averaged in at most
/// [`SAMPLES`] runs of consecutive samples (dense noisy data are smoothed, not thinned). `None`
/// when the side is shorter than the reach (the end of open data) or degenerate.
fn side<const D: usize>(
    data: &[Vector<D>],
    sums: &Sums<D>,
    i: usize,
    forwards: bool,
    reach: f64,
) -> Option<(Vector<D>, Vector<D>)> {
    let (n, arc) = (sums.n, &sums.arc);
    let base = if forwards || !sums.closed { i } else { i + n };
    let (lo, hi) = if forwards {
        let end = arc.partition_point(|&a| a - arc[base] <= reach);
        if end >= arc.len() || end > base + n - 1 {
            return None;
        }
        (base + 1, end)
    } else {
        let start = arc.partition_point(|&a| arc[base] - a > reach);
        if start == 0 || start + n <= base + 1 {
            return None;
        }
        (start, base)
    };
    let count = hi.checked_sub(lo).filter(|&c| c >= 2)?;
    let groups = count.min(SAMPLES);
    let (s_origin, origin) = (arc[base], data[i]);
    let (mut s2, mut s3, mut s4) = (0.0, 0.0, 0.0);
    let (mut r1, mut r2) = (Vector::<D>::zeros(), Vector::<D>::zeros());
    for g in 0..groups {
        let (j0, j1) = (lo + g * count / groups, lo + (g + 1) * count / groups);
        let c = (j1 - j0) as f64;
        let t = ((sums.arc_sum[j1] - sums.arc_sum[j0]) / c - s_origin).abs();
        let v = (sums.point_sum[j1] - sums.point_sum[j0]) / c - origin;
        let x = t / reach;
        let x2 = x * x;
        (s2, s3, s4) = (s2 + x2, s3 + x2 * x, s4 + x2 * x2);
        r1 += v * x;
        r2 += v * x2;
    }
    let det = s2 * s4 - s3 * s3;
    if det.is_nan() || det <= 1e-12 * s2 * s4 {
        return None;
    }
    let b = (r1 * s4 - r2 * s3) / det;
    let a = (r2 * s2 - r1 * s3) / det;
    let speed2 = b.norm_squared();
    if !(speed2 > 0.0 && speed2.is_finite()) {
        return None;
    }
    let unit = b / speed2.sqrt();
    // With x = t / reach both derivatives carry the same powers of the reach as |b|²: the
    // curvature vector is (2a)⊥ / |b|².
    let across = (a - unit * a.dot(&unit)) * 2.0;
    let curvature = across / speed2;
    Some((if forwards { unit } else { -unit }, curvature))
}

/// The tangent joints of `data` (data indices, increasing) with relative jump at least
/// `threshold`, at the reach [`REACH_SCALES`] · σ, away from the `corners` (data indices,
/// increasing).
pub(crate) fn detect_tangent_joints<const D: usize>(
    data: &[Vector<D>],
    chords: &ChordLengths,
    closed: bool,
    corners: &[usize],
    threshold: f64,
    options: &FitOptions,
) -> Vec<usize> {
    let n = data.len();
    let reach = REACH_SCALES * options.feature_scale * options.tolerance;
    if n < 5 || reach.is_nan() || reach <= 0.0 {
        return Vec::new();
    }
    // Arc length from point 0.
    // The noise-robust chord length (anchors σ / 4 apart): on dense noisy data the polyline's
    // own length grows with the noise's zigzag.
    let arc: Vec<f64> = (0..n).map(|i| chords.at(i)).collect();
    let total = chords.total();
    let sums = Sums::new(data, &arc, total, closed);
    // Arc-length distance between two data points (round the loop when closed).
    let apart = |i: usize, j: usize| {
        let d = (arc[i] - arc[j]).abs();
        if closed { d.min(total - d) } else { d }
    };
    let jump: Vec<f64> = (0..n)
        .map(|i| {
            if corners.iter().any(|&c| apart(c, i) < reach) {
                return 0.0;
            }
            // The one-sided curvature vectors at reach r (`None` unless the tangents agree).
            let curvatures = |r: f64| match (
                side(data, &sums, i, false, r),
                side(data, &sums, i, true, r),
            ) {
                (Some((t0, k0)), Some((t1, k1))) if t0.dot(&t1) >= MAX_TURN.cos() => Some((k0, k1)),
                _ => None,
            };
            let Some((k0, k1)) = curvatures(reach) else {
                return 0.0;
            };
            let full = (k1 - k0).norm();
            let relative = full / k0.norm().max(k1.norm());
            if full * reach < NOISE_FLOOR || relative.is_nan() || relative < threshold {
                return 0.0;
            }
            // A jump is the same at half the reach, a smooth change of curvature half as large.
            match curvatures(0.5 * reach) {
                Some((h0, h1)) if (h1 - h0).norm() >= SCALE_RATIO * full => full,
                _ => 0.0,
            }
        })
        .collect();
    let mut joints = Vec::new();
    for i in 0..n {
        if jump[i].is_nan() || jump[i] <= 0.0 {
            continue;
        }
        // The largest jump within the reach (the first of equal ones).
        let mut largest = true;
        for o in 1..n {
            let (a, b) = ((i + o) % n, (i + n - o) % n);
            let within_a = (closed || i + o < n) && apart(i, a) <= reach;
            let within_b = (closed || o <= i) && apart(i, b) <= reach;
            if !within_a && !within_b {
                break;
            }
            let beats = |j: usize| jump[j] > jump[i] || (jump[j] == jump[i] && j < i);
            if (within_a && beats(a)) || (within_b && beats(b)) {
                largest = false;
                break;
            }
        }
        if largest {
            joints.push(i);
        }
    }
    joints
}
