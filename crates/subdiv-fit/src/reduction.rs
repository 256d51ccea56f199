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
use crate::assess::{Measured, assess_segment, subsample_exceeds};
use crate::chord::ChordLengths;
use crate::corner_angles::{CornerTangents, cone_rays, corner_turns_kept, span_sides_kept};
use crate::fit::{FitMode, FitOptions, Reduction, solve_curve};
use crate::insertion::segment_range;
use crate::refit::{ABANDON_AT, Abandon, ITERATIONS, refit};
use crate::vertex::VertexKind;

/// `options` with interpolation (eq. (4)) as the mode: the start of [`Reduction::Refit`]'s
/// least-squares refits.
fn interpolating(options: &FitOptions) -> FitOptions {
    FitOptions {
        mode: FitMode::Interpolate,
        ..*options
    }
}

/// Segments on either side of a removed point that are measured again.
const WINDOW: usize = 3;

/// Polygons with more control points are not reduced (a pass is O(k²)).
pub const MAX_REDUCED: usize = 4096;

/// Control points on either side of the merged segment that a removal trial of
/// [`Reduction::Refit`] refits (the others are fixed).
const REFIT_REACH: usize = 2;

/// Passes over the fitting points. With [`Reduction::Refit`] a point is tried only while the errors
/// of its two segments sum to at most the tolerance: merging two segments that together already
/// use more than the tolerance rarely keeps it (on the glyph set at 10⁻³ em the count stays 1,794
/// with 6 % fewer instructions in all; at 10⁻² em 1,178 instead of 1,173).
const PASSES: usize = 2;

/// Removes regular fitting points while every segment's error (`errors`, one per segment,
/// updated) stays within the tolerance; returns the number removed.
pub(crate) fn reduce<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
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
    // With [`Reduction::Refit`] a trial depends only on the spans between sharp vertices that its
    // window reaches: a point is tried again in a later pass only when a point of its span or of
    // a neighbouring one was removed in the pass before (the sharp vertices, never removed, name
    // the spans by their data indices).
    let spans = SpanIndex::new(fitting, curve.kinds());
    let mut changed: Option<Vec<usize>> = None;
    for _ in 0..PASSES {
        let before = removed;
        let mut now = Vec::new();
        let k = fitting.len();
        let segs = errors.len();
        // Regular points, those with the smallest error on their two segments first.
        let mut order: Vec<(f64, usize)> = (0..k)
            .filter(|&j| !curve.is_sharp(j))
            .map(|j| {
                let left = errors[(j + segs - 1) % segs];
                let right = errors.get(j).copied().unwrap_or(0.0);
                (left + right, fitting[j].0)
            })
            .collect();
        order.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        for (sum, index) in order {
            // In increasing order: with `Reduction::Refit` the rest is not tried.
            if options.reduction == Reduction::Refit && sum > options.tolerance {
                break;
            }
            if fitting.len() <= min_points {
                return removed;
            }
            let Ok(j) = fitting.binary_search_by_key(&index, |f| f.0) else {
                continue;
            };
            let span = spans.of(index);
            let unchanged = changed.as_ref().is_some_and(|c| !spans.near(c, span));
            if options.reduction == Reduction::Refit && unchanged {
                continue;
            }
            if let Some(new_errors) = try_removal(data, corners, fitting, curve, errors, options, j)
            {
                fitting.remove(j);
                (*curve, *errors) = new_errors;
                removed += 1;
                now.push(span);
            }
        }
        if removed == before {
            break;
        }
        changed = Some(now);
    }
    removed
}

/// The spans between consecutive sharp fitting points, numbered in polygon order from the first
/// sharp point (a closed polygon without one is a single span); the sharp points are never
/// removed, so their data indices find a point's span throughout the removal.
struct SpanIndex {
    /// Data indices of the sharp points, increasing.
    starts: Vec<usize>,
}

impl SpanIndex {
    fn new(fitting: &[(usize, bool)], kinds: &[VertexKind]) -> Self {
        let starts = fitting
            .iter()
            .zip(kinds)
            .filter(|(_, k)| k.is_sharp())
            .map(|(f, _)| f.0)
            .collect();
        Self { starts }
    }

    /// The span of the point at data index `index`: the last sharp point at or before it, or the
    /// last of all (the span that wraps round a closed polygon).
    fn of(&self, index: usize) -> usize {
        self.starts
            .partition_point(|&s| s <= index)
            .checked_sub(1)
            .unwrap_or(self.starts.len().saturating_sub(1))
    }

    /// Whether a span in `changed` is `span` or a neighbour of it.
    fn near(&self, changed: &[usize], span: usize) -> bool {
        let m = self.starts.len().max(1);
        changed
            .iter()
            .any(|&c| c == span || (c + 1) % m == span || (span + 1) % m == c)
    }
}

/// The curve without fitting point `j` and an upper bound of each of its segment errors, or
/// `None` when the system cannot be solved or a segment's error exceeds the tolerance.
///
/// The cheap certified bounds of the segments outside the window are checked first, then the
/// merged segment (the one most likely to fail), then the rest of the window; each measurement
/// stops as soon as the error exceeds the tolerance.
fn try_removal<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    errors: &[f64],
    options: &FitOptions,
    j: usize,
) -> Option<(SubdivCurve<D>, Vec<f64>)> {
    let closed = curve.is_closed();
    let tol = options.tolerance;
    let k = fitting.len();
    let mut trial = fitting.to_vec();
    trial.remove(j);
    let k2 = trial.len();
    let next = if options.reduction == Reduction::Refit {
        // The points around the merged segment, from the interpolating solution, refitted by
        // least squares with every other point where it was.
        let interp = solve_curve(data, corners, &trial, closed, &interpolating(options)).ok()?;
        let mut points: Vec<Vector<D>> = curve.points().to_vec();
        points.remove(j);
        let mut free = Vec::new();
        for o in 0..2 * REFIT_REACH {
            // Trial vertices j − REACH ..= j + REACH − 1 (the merged segment is j − 1 → j).
            let t = (j + k2 + o).checked_sub(REFIT_REACH)?;
            let t = if closed {
                t % k2
            } else if t >= k2 && t - k2 < k2 {
                t - k2
            } else {
                continue;
            };
            if !interp.is_sharp(t) && !free.contains(&t) {
                points[t] = interp.points()[t];
                free.push(t);
            }
        }
        let guess = SubdivCurve::new(points, interp.kinds().to_vec(), curve.closure()).ok()?;
        // Given up after the first solve when the merged segment is far off.
        let merged = (j + k2 - 1) % k2;
        let abandon =
            |c: &SubdivCurve<D>| subsample_exceeds(data, &trial, c, merged, ABANDON_AT * tol);
        refit_near_corners(
            data,
            corners,
            &trial,
            guess,
            &free,
            options,
            &|_, _| true,
            Some(&abandon),
        )?
    } else {
        solve_curve(data, corners, &trial, closed, options).ok()?
    };
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
    if !corner_turns_kept(corners, &trial, &next, fitting, curve) {
        return None;
    }
    let mut window: Vec<usize> = (0..segs2).filter(|&s| measured(s)).collect();
    window.sort_by_key(|&s| distance(s));
    // With `Reduction::Refit`, a subsample of the window's segments first (as in `fit_spans`).
    if options.reduction == Reduction::Refit
        && window
            .iter()
            .any(|&s| subsample_exceeds(data, &trial, &next, s, tol))
    {
        return None;
    }
    for s in window {
        out[s] =
            assess_segment(data, &trial, &next, closed, options, s, tol).driven(options.measure);
        if out[s] > tol {
            return None;
        }
    }
    Some((next, out))
}

/// Where the regular points of a re-spaced span go.
#[derive(Clone, Copy)]
enum Spacing {
    /// At equal chord-length steps, what the uniform parameters of eq. (4) suit.
    Even,
    /// At the chord-length fractions `(1 − cos(π m / p)) / 2`, denser next to the span's ends:
    /// a sharp vertex has zero curvature on both sides (its phantom point), so a span that leaves
    /// a corner curved has to gain its curvature within the first segments.
    Graded,
    /// At equal steps of `∫ (κ + 1/ℓ)^(5/6) ds` ([`curvature_trial`]), for a span where the
    /// chord-length spacings fail.
    Curvature,
}

impl Spacing {
    /// The chord-length fraction of point `m` of `pieces − 1` inside a span.
    fn fraction(self, m: usize, pieces: usize) -> f64 {
        let x = m as f64 / pieces as f64;
        match self {
            Spacing::Even | Spacing::Curvature => x,
            Spacing::Graded => 0.5 - 0.5 * (std::f64::consts::PI * x).cos(),
        }
    }
}

/// Re-spaces the regular fitting points of each span between two consecutive sharp vertices
/// (for a closed curve without one, of the whole curve from its first fitting point): the fewest
/// points, evenly spaced or else graded towards the ends ([`Spacing`]), that keep every segment
/// within the tolerance, when that is fewer than the span has. Returns the number removed.
///
/// Eq. (4) interpolates at uniform parameters, so evenly spaced points suit it best; the insertion
/// loop leaves them uneven where it bisected, and removing single points then makes the curve
/// ring.
pub(crate) fn respace_spans<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    chords: &ChordLengths,
    fitting: &mut Vec<(usize, bool)>,
    curve: &mut SubdivCurve<D>,
    errors: &mut Vec<f64>,
    options: &FitOptions,
) -> usize {
    let closed = curve.is_closed();
    let n = data.len();
    if fitting.len() > MAX_REDUCED {
        return 0;
    }
    let mut removed = 0;
    // The span ends are the sharp vertices, which re-spacing keeps.
    let sharp: Vec<(usize, bool)> = fitting
        .iter()
        .zip(curve.kinds())
        .map(|(f, s)| (f.0, s.is_sharp()))
        .collect();
    for span in spans(&sharp, n, closed) {
        let inside = |i: usize| strictly_inside(i, span, n);
        let r = fitting.iter().filter(|f| inside(f.0)).count();
        let spacings = (0..r).flat_map(|fewer| [(fewer, Spacing::Even), (fewer, Spacing::Graded)]);
        for (fewer, spacing) in spacings {
            let trial = span_trial(fitting, chords, span, fewer, spacing, inside);
            // As few points as the removal leaves, at least (a closed polygon needs 3).
            if trial.len() < if closed { 3 } else { 2 } {
                continue;
            }
            if let Some((c, e)) = try_trial(
                data, corners, &trial, fitting, curve, errors, options, inside,
            ) {
                removed += fitting.len() - trial.len();
                *fitting = trial;
                *curve = c;
                *errors = e;
                break;
            }
        }
    }
    removed
}

/// `fitting` with the points `inside` span `span` (unwrapped data indices of its ends) replaced by
/// `count` regular points at the chord-length fractions of `spacing`.
fn span_trial(
    fitting: &[(usize, bool)],
    chords: &ChordLengths,
    span: (usize, usize),
    count: usize,
    spacing: Spacing,
    inside: impl Fn(usize) -> bool,
) -> Vec<(usize, bool)> {
    let (a, b) = span;
    let n = chords.len();
    let (start, length) = (chords.at(a), chords.at(b) - chords.at(a));
    let mut trial: Vec<(usize, bool)> = fitting.iter().copied().filter(|f| !inside(f.0)).collect();
    let mut last = a;
    for m in 1..=count {
        let target = start + length * spacing.fraction(m, count + 1);
        // `nearest_interior` wraps its result; compare unwrapped.
        if let Some(i) = chords.nearest_interior(a, b, target) {
            let u = if i < a { i + n } else { i };
            if u > last {
                trial.push((i, false));
                last = u;
            }
        }
    }
    trial.sort_unstable_by_key(|f| f.0);
    trial
}

/// `fitting` with the points `inside` span `span` (unwrapped data indices of its ends) replaced by
/// `count` regular points at equal steps of `∫ (κ + 1/ℓ)^(5/6) ds` over the span's data (`κ` the
/// discrete curvature, turn over mean edge length; `ℓ` the span's length, so a straight span is
/// spaced evenly). A cubic that follows an arc of curvature κ over a length L is off by about
/// `L⁶ κ⁵`, so equal errors need a density of `κ^(5/6)`: the points gather where the outline bends
/// tightly, as next to the joint of a 'Q''s tail.
fn curvature_trial<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    span: (usize, usize),
    count: usize,
    inside: impl Fn(usize) -> bool,
) -> Vec<(usize, bool)> {
    let (a, b) = span;
    let n = data.len();
    let at = |i: usize| data[i % n];
    let mut trial: Vec<(usize, bool)> = fitting.iter().copied().filter(|f| !inside(f.0)).collect();
    if b < a + 2 {
        return trial;
    }
    let length: f64 = (a..b).map(|i| (at(i + 1) - at(i)).norm()).sum();
    let floor = 1.0 / length.max(1e-300);
    let mut cum = vec![0.0; b - a + 1];
    for i in a + 1..=b {
        let h = (at(i) - at(i - 1)).norm();
        let kappa = if i < b {
            let (u, v) = (at(i) - at(i - 1), at(i + 1) - at(i));
            let hh = 0.5 * (h + v.norm());
            let c = u.norm() * v.norm();
            let turn = if c > 0.0 {
                (u.dot(&v) / c).clamp(-1.0, 1.0).acos()
            } else {
                0.0
            };
            turn / hh.max(1e-300)
        } else {
            0.0
        };
        cum[i - a] = cum[i - 1 - a] + h * (kappa + floor).powf(5.0 / 6.0);
    }
    let total = cum[b - a];
    let mut last = a;
    for m in 1..=count {
        let target = total * m as f64 / (count + 1) as f64;
        // The data point whose measure is nearest the target.
        let mut k = cum.partition_point(|&c| c < target);
        if k > 0 && (k == cum.len() || target - cum[k - 1] < cum[k] - target) {
            k -= 1;
        }
        let u = a + k.clamp(1, b - a - 1);
        if u > last && u < b {
            trial.push((u % n, false));
            last = u;
        }
    }
    trial.sort_unstable_by_key(|f| f.0);
    trial
}

/// The spans between consecutive sharp fitting points as unwrapped data indices of their ends
/// (a closed polygon without one is one span from its first fitting point round to it).
fn spans(fitting: &[(usize, bool)], n: usize, closed: bool) -> Vec<(usize, usize)> {
    let mut ends: Vec<usize> = fitting.iter().filter(|f| f.1).map(|f| f.0).collect();
    if closed {
        match ends.first() {
            Some(&first) => ends.push(first + n),
            None => ends = vec![fitting[0].0, fitting[0].0 + n],
        }
    }
    ends.windows(2).map(|w| (w[0], w[1])).collect()
}

/// Whether data index `i` lies strictly inside the span `(a, b)` (unwrapped, `b` may exceed `n`).
fn strictly_inside(i: usize, (a, b): (usize, usize), n: usize) -> bool {
    let u = if i < a { i + n } else { i };
    u > a && u < b
}

/// Fits every span between two consecutive sharp points of the initial fitting points `seed`
/// directly by least squares ([`Reduction::Refit`] in place of the insertion loop): for each span
/// the fewest regular points, evenly spaced or else graded, whose refitted segments are all within
/// the tolerance. The search counts up from [`lowest_count`] of the span's initial count to
/// [`EXTRA_POINTS`] more than it, and down from there while the count at the start passes. The
/// spans are independent (a sharp vertex's phantom point decouples the two sides), so each trial
/// refits and measures only its span. `None` when a span needs more points than that; the
/// insertion loop takes over then.
///
/// Also returns the errors of the accepted segments, sorted by their first data index: each was
/// measured within the tolerance, so no measurement stopped early and they are exact, and the
/// segments of a span stay bit for bit what they were while the other spans are fitted.
pub(crate) fn fit_spans<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    chords: &ChordLengths,
    seed: &[(usize, bool)],
    closed: bool,
    options: &FitOptions,
) -> Option<SpanFit<D>> {
    let n = data.len();
    let tol = options.tolerance;
    let mut fitting = seed.to_vec();
    if !closed {
        let last = fitting.len() - 1;
        fitting[0].1 = true;
        fitting[last].1 = true;
    }
    let mut curve = solve_curve(data, corners, &fitting, closed, &interpolating(options)).ok()?;
    let mut measured = Vec::new();
    // The corner sides (data index, after the corner) of the spans fitted so far: their tangents
    // are final, so the next span's side at that corner may take what they leave of the bound.
    let mut fitted_sides: Vec<(usize, bool)> = Vec::new();
    for span in spans(&fitting, n, closed) {
        let settled = |index: usize, forwards: bool| fitted_sides.contains(&(index, forwards));
        let inside = |i: usize| strictly_inside(i, span, n);
        let seeded = fitting.iter().filter(|f| inside(f.0)).count();
        // Whether the search has failed with the chord-length spacings and tries curvature.
        let rescue = std::cell::Cell::new(false);
        // The first spacing with `count` points whose refit keeps the span within the tolerance:
        // its fitting points, curve and the errors of the span's segments.
        let attempt = |count: usize| {
            let spacings: &[Spacing] = if rescue.get() {
                &[Spacing::Curvature]
            } else {
                &[Spacing::Even, Spacing::Graded]
            };
            spacings.iter().find_map(|&spacing| {
                let trial = match spacing {
                    Spacing::Curvature => curvature_trial(data, &fitting, span, count, inside),
                    _ => span_trial(&fitting, chords, span, count, spacing, inside),
                };
                if trial.len() < if closed { 3 } else { 2 } {
                    return None;
                }
                // The span's segments, given up after the first solve when one is far off.
                let in_span = |s: usize| {
                    let start = trial[s].0;
                    start == span.0 % n || inside(start)
                };
                let abandon = |c: &SubdivCurve<D>| {
                    (0..c.segment_count()).any(|s| {
                        in_span(s) && subsample_exceeds(data, &trial, c, s, ABANDON_AT * tol)
                    })
                };
                let next = respaced_refit(
                    data,
                    corners,
                    &trial,
                    &fitting,
                    &curve,
                    options,
                    inside,
                    &settled,
                    Some(&abandon),
                )?;
                if !span_sides_kept(corners, &trial, &next, n, span, settled) {
                    return None;
                }
                let span_segments: Vec<usize> =
                    (0..next.segment_count()).filter(|&s| in_span(s)).collect();
                // A subsample of every segment first: most failing trials fail there.
                if span_segments
                    .iter()
                    .any(|&s| subsample_exceeds(data, &trial, &next, s, tol))
                {
                    return None;
                }
                let mut errors = Vec::new();
                for s in span_segments {
                    let e = assess_segment(data, &trial, &next, closed, options, s, tol);
                    if e.driven(options.measure) > tol {
                        return None;
                    }
                    let range = segment_range(&trial, s, n);
                    errors.push(Measured::new(range, next.segment_controls(s).ok()?, e));
                }
                Some((trial, next, errors))
            })
        };
        let lowest = lowest_count(seeded);
        let mut count = lowest;
        let mut accepted = loop {
            if count > seeded + EXTRA_POINTS {
                // Once more from the start with the points placed by curvature, before the
                // insertion loop takes the whole curve over.
                if rescue.replace(true) {
                    return None;
                }
                count = lowest;
            }
            if let Some(found) = attempt(count) {
                break found;
            }
            count += 1;
        };
        if count == lowest {
            while let Some(found) = count.checked_sub(1).and_then(attempt) {
                accepted = found;
                count -= 1;
            }
        }
        let errors;
        (fitting, curve, errors) = accepted;
        measured.extend(errors);
        fitted_sides.extend([(span.0 % n, true), (span.1 % n, false)]);
    }
    measured.sort_unstable_by_key(Measured::first);
    Some((fitting, curve, measured))
}

/// What [`fit_spans`] returns: the fitting points, the curve and the errors of its segments.
pub(crate) type SpanFit<const D: usize> = (Vec<(usize, bool)>, SubdivCurve<D>, Vec<Measured<D>>);

/// The count of regular points at which [`fit_spans`] starts a span's search, from the span's
/// initial count `seeded`: half as many segments. The initial count passes the interpolation error
/// estimate `(5/384) ℓ Θ³ ≤ tol / 2` of the seeding, whose left side falls as the fourth power of
/// the segment count (the length ℓ and the turn Θ of a segment both fall as its inverse): half
/// the segments would need an error 8 times below the estimate's at the full tolerance.
fn lowest_count(seeded: usize) -> usize {
    seeded.div_ceil(2).saturating_sub(1)
}

/// Points beyond its initial count that [`fit_spans`] tries in a span before leaving the fit to
/// the insertion loop.
const EXTRA_POINTS: usize = 6;
/// The curve of the fitting points `trial` with an upper bound of each segment error, or `None`
/// when the system cannot be solved or a segment's error exceeds the tolerance. A segment between
/// the same two data points as one of the current curve (`fitting`, `curve`, `errors`) moved by
/// at most the largest displacement of its four control points (the basis functions are
/// non-negative and sum to 1), which is added to its old error; the others are measured.
#[expect(
    clippy::too_many_arguments,
    reason = "the data with their corners, the trial, the current state (points, curve, errors) and the span"
)]
fn try_trial<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    trial: &[(usize, bool)],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    errors: &[f64],
    options: &FitOptions,
    inside: impl Fn(usize) -> bool,
) -> Option<(SubdivCurve<D>, Vec<f64>)> {
    let tol = options.tolerance;
    let closed = curve.is_closed();
    let next = if options.reduction == Reduction::Refit {
        respaced_refit(
            data,
            corners,
            trial,
            fitting,
            curve,
            options,
            inside,
            &|_, _| true,
            None,
        )?
    } else {
        solve_curve(data, corners, trial, closed, options).ok()?
    };
    if !corner_turns_kept(corners, trial, &next, fitting, curve) {
        return None;
    }
    let (k, k2) = (fitting.len(), trial.len());
    let segs = next.segment_count();
    let mut out = vec![f64::NAN; segs];
    let mut measured = Vec::new();
    for s in 0..segs {
        let (ds, de) = (trial[s].0, trial[(s + 1) % k2].0);
        let same = fitting
            .binary_search_by_key(&ds, |f| f.0)
            .ok()
            .filter(|&o| o < curve.segment_count() && fitting[(o + 1) % k].0 == de);
        let Some(old) = same else {
            measured.push(s);
            continue;
        };
        let (Ok(new_ctrl), Ok(old_ctrl)) = (next.segment_controls(s), curve.segment_controls(old))
        else {
            return None;
        };
        let moved = new_ctrl
            .iter()
            .zip(&old_ctrl)
            .map(|(p, q)| (p - q).norm())
            .fold(0.0, f64::max);
        out[s] = errors[old] + moved;
        if out[s] > tol {
            return None;
        }
    }
    for s in measured {
        out[s] =
            assess_segment(data, trial, &next, closed, options, s, tol).driven(options.measure);
        if out[s] > tol {
            return None;
        }
    }
    Some((next, out))
}

/// The curve of the fitting points `trial` for [`Reduction::Refit`]: the regular control points
/// of the data indices `inside` the re-spaced span, from the interpolating solution, refitted by
/// least squares; the others stay where `curve` (of `fitting`) has them.
#[expect(
    clippy::too_many_arguments,
    reason = "the data with their corners, the trial, the current state, the span, its settled corner sides and when to give up"
)]
fn respaced_refit<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    trial: &[(usize, bool)],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    options: &FitOptions,
    inside: impl Fn(usize) -> bool,
    settled: &impl Fn(usize, bool) -> bool,
    abandon: Option<Abandon<'_, D>>,
) -> Option<SubdivCurve<D>> {
    let closed = curve.is_closed();
    let interp = solve_curve(data, corners, trial, closed, &interpolating(options)).ok()?;
    let mut points = interp.points().to_vec();
    let mut free = Vec::new();
    for (t, f) in trial.iter().enumerate() {
        if inside(f.0) && !interp.is_sharp(t) {
            free.push(t);
        } else if let Ok(o) = fitting.binary_search_by_key(&f.0, |g| g.0) {
            points[t] = curve.points()[o];
        }
    }
    // In polygon order (a span may wrap round the first point of a closed polygon), so that the
    // columns of the band follow the polygon.
    if let Some(cut) = (1..free.len()).find(|&i| free[i] != free[i - 1] + 1) {
        free.rotate_left(cut);
    }
    let guess = SubdivCurve::new(points, interp.kinds().to_vec(), curve.closure()).ok()?;
    refit_near_corners(
        data, corners, trial, guess, &free, options, settled, abandon,
    )
}

/// The refit of the control points `free` of `guess` (fitting points `trial`) for
/// [`Reduction::Refit`]; with [`FitOptions::corner_tolerance`] set or smooth joints, a free
/// neighbour of a corner
/// whose side then leaves the corner's tangent by more than its share of the bound (the turn's
/// error is at most the sum of the sides'; a side takes what a settled other side leaves, else
/// half, `settled` naming the settled sides outside `free`) is constrained to the nearest edge of
/// the cone within that angle and the points are refitted once more, each constrained one
/// optimal along its ray ([`cone_rays`]). `abandon` may give the trial up after the first solve
/// ([`refit`]).
#[expect(
    clippy::too_many_arguments,
    reason = "the data with their corners, the trial with its free points, the settled corner sides and when to give up"
)]
fn refit_near_corners<const D: usize>(
    data: &[Vector<D>],
    corners: &CornerTangents<D>,
    trial: &[(usize, bool)],
    guess: SubdivCurve<D>,
    free: &[usize],
    options: &FitOptions,
    settled: &impl Fn(usize, bool) -> bool,
    abandon: Option<Abandon<'_, D>>,
) -> Option<SubdivCurve<D>> {
    if options.corner_tolerance.is_none() && corners.is_empty() {
        return refit(data, trial, guess, free, &[], ITERATIONS, None, abandon);
    }
    let cone =
        |fitted: &SubdivCurve<D>| cone_rays(corners, trial, fitted, |v| free.contains(&v), settled);
    // One iteration more than without the bound: the first solve that leaves a side's share
    // fixes its ray, and the foot points follow the constrained curve once more.
    refit(
        data,
        trial,
        guess,
        free,
        &[],
        ITERATIONS + 1,
        Some(&cone),
        abandon,
    )
}

#[cfg(test)]
mod tests {
    use super::{Spacing, SpanIndex, curvature_trial, fit_spans, lowest_count};
    use crate::assess::{assess, assess_reusing};
    use crate::chord::ChordLengths;
    use crate::corner_angles::CornerTangents;
    use crate::{FitOptions, Reduction, Vector2, VertexKind};

    /// Spans by the sharp points at data indices 10, 40, 55, 70 (a closed polygon): a point after
    /// 70 or before 10 is in the span that wraps round; neighbours wrap round too.
    #[test]
    fn span_index_finds_spans_and_neighbours() {
        let fitting = [
            (0, false),
            (10, true),
            (25, false),
            (40, true),
            (55, true),
            (70, true),
            (80, false),
        ];
        let kinds: Vec<VertexKind> = fitting
            .iter()
            .map(|f| {
                if f.1 {
                    VertexKind::Sharp
                } else {
                    VertexKind::Regular
                }
            })
            .collect();
        let spans = SpanIndex::new(&fitting, &kinds);
        let of = [0, 10, 25, 39, 40, 54, 55, 70, 80].map(|i| spans.of(i));
        assert_eq!(of, [3, 0, 0, 0, 1, 1, 2, 3, 3]);
        assert!(spans.near(&[0], 0) && spans.near(&[0], 1) && spans.near(&[0], 3));
        assert!(!spans.near(&[0], 2) && !spans.near(&[], 0));
        assert!(spans.near(&[3], 0) && spans.near(&[1, 3], 2));
        let none = SpanIndex::new(&fitting, &[VertexKind::Regular; 7]);
        assert_eq!(none.of(25), 0);
        assert!(none.near(&[0], 0));
    }

    /// The search starts at half the segments of the initial count (points = segments − 1).
    #[test]
    fn lowest_count_halves_the_segments() {
        for (seeded, lowest) in [
            (0, 0),
            (1, 0),
            (2, 0),
            (3, 1),
            (4, 1),
            (13, 6),
            (14, 6),
            (21, 10),
        ] {
            assert_eq!(lowest_count(seeded), lowest, "{seeded}");
            assert!(2 * (lowest + 1) <= seeded + 1 || lowest == 0);
            assert!(2 * (lowest + 2) > seeded + 1);
        }
    }

    /// The errors the span fit hands on are those of a full measurement of its curve, bit for bit.
    #[test]
    fn span_fit_errors_are_those_of_a_full_measurement() {
        // A half disc: the semicircle (data 0..=80), then the diameter back; corners at 0 and 80.
        let mut data: Vec<Vector2> = (0..=80)
            .map(|i| {
                let a = std::f64::consts::PI * f64::from(i) / 80.0;
                Vector2::new(a.cos(), a.sin())
            })
            .collect();
        data.extend((1..40).map(|i| Vector2::new(-1.0 + f64::from(i) / 20.0, 0.0)));
        let opts = FitOptions::new(1e-2).with_reduction(Reduction::Refit);
        let chords = ChordLengths::robust(&data, true, 1.5e-2);
        let mut seed: Vec<(usize, bool)> = (0..8).map(|m| (10 * m, m == 0)).collect();
        seed.push((80, true));
        let (fitting, curve, mut measured) =
            fit_spans(&data, &CornerTangents::none(), &chords, &seed, true, &opts).unwrap();
        assert_eq!(measured.len(), curve.segment_count());
        assert!(fitting.len() > 3);
        let full = assess(&data, &fitting, &curve, true, &opts);
        let reused = assess_reusing(&data, &fitting, &curve, true, &opts, &mut measured);
        assert_eq!(reused.driven, full.driven);
        assert!(full.driven.iter().all(|&e| e <= 1e-2));
        assert_eq!(
            (reused.max_d2c, reused.rms_d2c, reused.max_c2d),
            (full.max_d2c, full.rms_d2c, full.max_c2d)
        );
    }

    /// The curvature spacing puts several of its points into a bend that is 4 % of the span's
    /// length (chord-length spacing would put none of 8 there), and spaces a line evenly.
    #[test]
    fn curvature_spacing_gathers_points_in_a_tight_bend() {
        // Two straight legs of 2 joined by a half circle of radius 0.05, samples every 0.01: the
        // bend is 4 % of the length.
        let mut data = Vec::new();
        for i in 0..200 {
            data.push(Vector2::new(f64::from(i) * 0.01, 0.0));
        }
        for i in 0..16 {
            let a = std::f64::consts::PI * f64::from(i) / 16.0 - std::f64::consts::FRAC_PI_2;
            data.push(Vector2::new(2.0 + 0.05 * a.cos(), 0.05 + 0.05 * a.sin()));
        }
        for i in 0..=200 {
            data.push(Vector2::new(2.0 - f64::from(i) * 0.01, 0.1));
        }
        let n = data.len();
        let fitting = [(0, true), (n - 1, true)];
        let inside = |i: usize| i > 0 && i < n - 1;
        let trial = curvature_trial(&data, &fitting, (0, n - 1), 8, inside);
        assert_eq!(trial.len(), 10);
        let in_bend = trial.iter().filter(|f| (200..216).contains(&f.0)).count();
        assert!(in_bend >= 2, "{trial:?}");
        // A straight span is spaced evenly.
        let line: Vec<Vector2> = (0..=100).map(|i| Vector2::new(f64::from(i), 0.0)).collect();
        let fitting = [(0, true), (100, true)];
        let trial = curvature_trial(&line, &fitting, (0, 100), 4, |i| i > 0 && i < 100);
        let got: Vec<usize> = trial.iter().map(|f| f.0).collect();
        assert_eq!(got, [0, 20, 40, 60, 80, 100]);
    }

    /// Even fractions are `m / p`; graded ones are increasing, symmetric about the middle, and
    /// their steps grow from the ends to the middle (denser next to the span's ends).
    #[test]
    fn spacing_fractions() {
        for pieces in 2..12 {
            let even: Vec<f64> = (0..=pieces)
                .map(|m| Spacing::Even.fraction(m, pieces))
                .collect();
            let graded: Vec<f64> = (0..=pieces)
                .map(|m| Spacing::Graded.fraction(m, pieces))
                .collect();
            for m in 0..=pieces {
                assert!((even[m] - m as f64 / pieces as f64).abs() < 1e-15);
                assert!((graded[m] + graded[pieces - m] - 1.0).abs() < 1e-12);
            }
            assert!(graded[0].abs() < 1e-15 && (graded[pieces] - 1.0).abs() < 1e-15);
            let steps: Vec<f64> = graded.windows(2).map(|w| w[1] - w[0]).collect();
            for m in 0..pieces / 2 {
                assert!(steps[m] > 0.0);
                assert!(steps[m] < steps[m + 1] + 1e-12, "{pieces}: {steps:?}");
            }
            if pieces > 2 {
                assert!(steps[0] < 1.0 / pieces as f64);
            }
        }
    }
}
