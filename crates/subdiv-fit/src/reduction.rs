//! Fewer control points after convergence: removal of regular fitting points while the error
//! stays within the tolerance (the project's addition; the paper only inserts).
//!
//! The insertion loop bisects failing segments, so it ends with fitting points denser than the
//! tolerance needs wherever a bisection overshot. Each regular fitting point is tried for
//! removal, those whose two segments have the smallest error first: the control polygon is solved
//! again without it (eq. 4, or the least-squares mode) and the removal is kept when every segment
//! stays within the tolerance. Only the segments within [`WINDOW`] of the removed point are
//! measured again; every other segment moved by at most three times the largest displacement of
//! its four control points (phantom points `2 p_i − p_{i+1}` at sharp vertices move by at most
//! three times as much as the polygon), so its old error plus that bound is a certified upper
//! bound, kept as the segment's error from then on. A trial costs O(k) plus the data of the
//! window; a pass over all points O(k²), so polygons above [`MAX_REDUCED`] points are left as
//! they are.

use bez_core::Vector;

use crate::SubdivCurve;
use crate::assess::assess_segment;
use crate::fit::{FitOptions, solve_curve};

/// Segments on either side of a removed point that are measured again.
const WINDOW: usize = 3;

/// Polygons with more control points are not reduced (a pass is O(k²)).
pub const MAX_REDUCED: usize = 4096;

/// Passes over the fitting points.
const PASSES: usize = 2;

/// Removes regular fitting points while every segment's error (`errors`, one per segment,
/// updated) stays within the tolerance; returns the number removed.
pub(crate) fn reduce<const D: usize>(
    data: &[Vector<D>],
    fitting: &mut Vec<(usize, bool)>,
    curve: &mut SubdivCurve<D>,
    errors: &mut Vec<f64>,
    closed: bool,
    options: &FitOptions,
) -> usize {
    let min_points = if closed { 3 } else { 2 };
    let mut removed = 0;
    if fitting.len() > MAX_REDUCED {
        return 0;
    }
    for _ in 0..PASSES {
        let before = removed;
        let k = fitting.len();
        let segs = errors.len();
        // Regular points, those with the smallest error on their two segments first.
        let mut order: Vec<(f64, usize)> = (0..k)
            .filter(|&j| !curve.sharp()[j])
            .map(|j| {
                let left = errors[(j + segs - 1) % segs];
                let right = errors.get(j).copied().unwrap_or(0.0);
                (left + right, fitting[j].0)
            })
            .collect();
        order.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        for (_, index) in order {
            if fitting.len() <= min_points {
                return removed;
            }
            let Ok(j) = fitting.binary_search_by_key(&index, |f| f.0) else {
                continue;
            };
            if let Some(new_errors) = try_removal(data, fitting, curve, errors, closed, options, j)
            {
                fitting.remove(j);
                (*curve, *errors) = new_errors;
                removed += 1;
            }
        }
        if removed == before {
            break;
        }
    }
    removed
}

/// The curve without fitting point `j` and an upper bound of each of its segment errors, or
/// `None` when the system cannot be solved or a segment's error exceeds the tolerance.
///
/// The cheap certified bounds of the segments outside the window are checked first, then the
/// merged segment (the one most likely to fail), then the rest of the window; each measurement
/// stops as soon as the error exceeds the tolerance.
fn try_removal<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    errors: &[f64],
    closed: bool,
    options: &FitOptions,
    j: usize,
) -> Option<(SubdivCurve<D>, Vec<f64>)> {
    let tol = options.tolerance;
    let k = fitting.len();
    let mut trial = fitting.to_vec();
    trial.remove(j);
    let next = solve_curve(data, &trial, closed, options.mode).ok()?;
    let k2 = trial.len();
    // Old vertex of trial vertex t.
    let old = |t: usize| if t < j { t } else { t + 1 };
    let disp: Vec<f64> = (0..k2)
        .map(|t| (next.points()[t] - curve.points()[old(t)]).norm())
        .collect();
    let segs2 = next.segment_count();
    // The merged segment: from trial vertex j − 1 to trial vertex j (old j − 1 to old j + 1).
    let merged = (j + k2 - 1) % k2;
    let distance = |s: usize| {
        if closed {
            let d = s.abs_diff(merged);
            d.min(k2 - d)
        } else {
            s.abs_diff(merged)
        }
    };
    let measured = |s: usize| (j == 0 && !closed) || distance(s) <= WINDOW;
    let mut out = vec![0.0; segs2];
    for s in (0..segs2).filter(|&s| !measured(s)) {
        // Vertices s − 1 ..= s + 2 shape segment s.
        let moved = (0..4)
            .filter_map(|o| {
                let t = s + o;
                if closed {
                    Some((t + k2 - 1) % k2)
                } else {
                    (t >= 1 && t - 1 < k2).then(|| t - 1)
                }
            })
            .map(|t| disp[t])
            .fold(0.0, f64::max);
        out[s] = errors[old(s) % k] + 3.0 * moved;
        if out[s] > tol {
            return None;
        }
    }
    let mut window: Vec<usize> = (0..segs2).filter(|&s| measured(s)).collect();
    window.sort_by_key(|&s| distance(s));
    for s in window {
        out[s] =
            assess_segment(data, &trial, &next, closed, options, s, tol).driven(options.measure);
        if out[s] > tol {
            return None;
        }
    }
    Some((next, out))
}
