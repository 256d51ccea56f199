//! Beyond the paper: near-optimal flattening by the curvature density √(|κ| / (8 tol)).

use bez_core::{BezierCurve, BezierForm, Vector2};

use crate::chord::chord_deviation;
use crate::error::SubdivError;
use crate::guaranteed::FlatPoint;

/// Quadrature nodes per unit of degree for the density integral.
const NODES_PER_DEGREE: usize = 64;

/// The asymptotic lower bound N* = ∫ √(|κ| / (8 tol)) ds on the number of segments of any
/// polyline through curve points within `tolerance` (a segment of a curve arc of curvature κ
/// and length h deviates by about κh²/8), by the trapezoidal rule on a fine grid.
///
/// # Errors
/// [`SubdivError::InvalidTolerance`], [`SubdivError::TooFewPoints`].
pub fn optimal_segment_count(curve: &BezierCurve<2>, tolerance: f64) -> Result<f64, SubdivError> {
    let (_, cumulative) = density_integral(curve, tolerance)?;
    Ok(cumulative.last().copied().unwrap_or(0.0))
}

/// Grid parameters and the cumulative integral of √(|κ|/(8 tol)) |B'| dt on them.
fn density_integral(
    curve: &BezierCurve<2>,
    tolerance: f64,
) -> Result<(Vec<f64>, Vec<f64>), SubdivError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(SubdivError::InvalidTolerance { value: tolerance });
    }
    if curve.points().len() < 2 {
        return Err(SubdivError::TooFewPoints {
            got: curve.points().len(),
        });
    }
    let m = NODES_PER_DEGREE * curve.degree().max(1);
    let ts: Vec<f64> = (0..=m).map(|k| k as f64 / m as f64).collect();
    let g: Vec<f64> = ts
        .iter()
        .map(|&t| {
            let d = curve
                .eval_derivatives(t, 2)
                .unwrap_or_else(|_| vec![Vector2::zeros(); 3]);
            let speed = d[1].norm();
            // √|κ| · speed = √(|x'×x''| / speed), finite even where the speed vanishes.
            let cross = (d[1].x() * d[2].y() - d[1].y() * d[2].x()).abs();
            if speed > 0.0 {
                (cross / speed).sqrt() / (8.0 * tolerance).sqrt()
            } else {
                0.0
            }
        })
        .collect();
    let mut cumulative = vec![0.0; ts.len()];
    for k in 1..ts.len() {
        cumulative[k] = cumulative[k - 1] + 0.5 * (g[k] + g[k - 1]) * (ts[k] - ts[k - 1]);
    }
    Ok((ts, cumulative))
}

/// A step is accepted once its exact deviation reaches this fraction of the tolerance.
const ACCEPT_FRACTION: f64 = 0.98;
/// Step searches stop refining after this many deviation evaluations (once a step passed).
const MAX_STEP_EVALUATIONS: usize = 12;

/// The cumulative density integral on its grid, and its inversion.
struct Density {
    ts: Vec<f64>,
    cumulative: Vec<f64>,
}

impl Density {
    /// ∫₀ᵗ of the density (linear between grid nodes).
    fn at(&self, t: f64) -> f64 {
        let k = self
            .ts
            .partition_point(|&x| x < t)
            .clamp(1, self.ts.len() - 1);
        let (t0, t1) = (self.ts[k - 1], self.ts[k]);
        let w = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0);
        self.cumulative[k - 1] + w * (self.cumulative[k] - self.cumulative[k - 1])
    }

    /// The parameter where the integral reaches `target` (1 beyond the total).
    fn inverse(&self, target: f64) -> f64 {
        let k = self.cumulative.partition_point(|&c| c < target);
        if k == 0 {
            return 0.0;
        }
        if k >= self.ts.len() {
            return 1.0;
        }
        let (c0, c1) = (self.cumulative[k - 1], self.cumulative[k]);
        let w = if c1 > c0 {
            (target - c0) / (c1 - c0)
        } else {
            0.0
        };
        self.ts[k - 1] + w * (self.ts[k] - self.ts[k - 1])
    }
}

/// The longest step [a, b] found whose exact chord deviation is ≤ `tol`, starting from the
/// guess `b`: the deviation of a short arc grows like (b − a)², so the next guess scales the
/// step by √(tol / deviation); failed and passed steps bracket the answer, and a guess outside
/// the bracket is replaced by its midpoint. Stops at a deviation in [0.98 tol, tol] or after
/// [`MAX_STEP_EVALUATIONS`]. Returns `None` when no step longer than `min_step` passes.
fn longest_step(
    curve: &BezierCurve<2>,
    a: f64,
    guess: f64,
    tol: f64,
    min_step: f64,
) -> Result<Option<f64>, SubdivError> {
    let mut lo = a;
    let mut hi = 1.0_f64;
    let mut hi_failed = false;
    let mut b = guess.max(a + min_step).min(1.0);
    for evaluation in 1.. {
        let e = chord_deviation(curve, a, b)?;
        let h = b - a;
        let next = if e <= tol {
            lo = b;
            if e >= ACCEPT_FRACTION * tol || b == 1.0 || evaluation >= MAX_STEP_EVALUATIONS {
                break;
            }
            // Aim just below the tolerance; a straight arc (e = 0) doubles the step.
            let scale = if e > 0.0 {
                (0.99 * tol / e).sqrt()
            } else {
                2.0
            };
            a + h * scale.max(1.01)
        } else {
            hi = b;
            hi_failed = true;
            // A failed step shrinks by at least 10 %, so the search ends (see `min_step`).
            let scale = if e.is_finite() {
                (0.99 * tol / e).sqrt()
            } else {
                0.5
            };
            a + h * scale.min(0.9)
        };
        if lo > a && evaluation >= MAX_STEP_EVALUATIONS {
            break;
        }
        b = if next > lo && next < hi {
            next
        } else if hi_failed {
            0.5 * (lo + hi)
        } else {
            1.0
        };
        if lo == a && (b <= a || b - a < min_step) {
            return Ok(None);
        }
        if lo > a && (hi - lo) <= 1e-12 * (hi - a) {
            break;
        }
    }
    Ok(Some(lo))
}

/// Points B(tᵢ) with close to the fewest segments whose polyline is within `tolerance` of the
/// curve in Hausdorff distance.
///
/// A greedy march from t = 0: each segment is the longest step [a, b] found whose exact chord
/// deviation ([`chord_deviation`]) is ≤ `tolerance`, so the result has the same Hausdorff
/// guarantee as [`crate::flatten_guaranteed`]. The first guess of each step comes from the
/// density √(|κ| / (8 tol)) |B'(t)| of the lower bound N* ([`optimal_segment_count`]): the
/// step advances the density integral by as much as the previous accepted step did (1 at the
/// start), which tracks how far the true deviation departs from the asymptotic model κh²/8
/// (near inflections and where κ varies fast within a step). Taking the longest admissible
/// step each time uses the fewest segments whenever a sub-arc of an admissible arc is
/// admissible (the greedy rule "stays ahead" of any other placement).
///
/// Cost: O(n² m) for the density (m = 64 n nodes) plus a few O(n²) deviation evaluations per
/// segment (each a sub-curve and two root isolations of degree n − 1).
///
/// # Errors
/// [`SubdivError::InvalidTolerance`], [`SubdivError::TooFewPoints`], [`SubdivError::DepthLimit`]
/// when no step longer than 2^−`max_depth` in parameter passes (a tolerance below the rounding
/// level of the coordinates); [`SubdivError::TooManySegments`] above 2²⁰ segments;/// [`SubdivError::DepthTooLarge`] for `max_depth` above [`MAX_FLATTEN_DEPTH`](crate::MAX_FLATTEN_DEPTH),
/// [`SubdivError::ToleranceBelowRounding`] below 16 ulps of the largest coordinate (checked
/// before any work).
pub fn flatten_near_optimal<C: BezierForm<2> + ?Sized>(
    curve: &C,
    tolerance: f64,
    max_depth: usize,
) -> Result<Vec<FlatPoint>, SubdivError> {
    near_optimal_bezier(curve.as_bezier(), tolerance, max_depth)
}

/// [`flatten_near_optimal`] on the Bézier form (one instance for every curve type).
/// The most segments [`flatten_near_optimal`] produces (2²⁰): at about 10 µs per segment a
/// tolerance that needs more is a request for seconds of work per curve.
const MAX_OPTIMAL_SEGMENTS: usize = 1 << 20;

fn near_optimal_bezier(
    curve: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
) -> Result<Vec<FlatPoint>, SubdivError> {
    let (ts, cumulative) = density_integral(curve, tolerance)?;
    crate::limits::check_work(curve, tolerance, max_depth)?;
    let density = Density { ts, cumulative };
    let min_step = 0.5_f64.powi(i32::try_from(max_depth).unwrap_or(i32::MAX));
    let mut out = vec![FlatPoint {
        t: 0.0,
        point: curve.start(),
    }];
    let mut a = 0.0_f64;
    let mut advance = 1.0_f64;
    while a < 1.0 {
        let from = density.at(a);
        let guess = density.inverse(from + advance);
        let Some(b) = longest_step(curve, a, guess, tolerance, min_step)? else {
            return Err(SubdivError::DepthLimit { limit: max_depth });
        };
        if out.len() > MAX_OPTIMAL_SEGMENTS {
            return Err(SubdivError::TooManySegments {
                tolerance,
                limit: MAX_OPTIMAL_SEGMENTS,
            });
        }
        let step_advance = density.at(b) - from;
        if step_advance > 0.0 && b < 1.0 {
            advance = step_advance;
        }
        let point = if b == 1.0 {
            curve.end()
        } else {
            curve.eval(b)?
        };
        out.push(FlatPoint { t: b, point });
        a = b;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_typed_errors, curve};

    #[test]
    fn density_inverse_undoes_the_integral() -> Result<(), SubdivError> {
        let c = curve(&[(0.0, 0.0), (1.0, 2.0), (3.0, -1.0), (4.0, 1.0)]);
        let (ts, cumulative) = density_integral(&c, 1e-3)?;
        let d = Density { ts, cumulative };
        for t in [0.0, 0.013, 0.4, 0.77, 1.0] {
            assert!((d.inverse(d.at(t)) - t).abs() < 1e-12, "t = {t}");
        }
        assert_eq!(d.inverse(-1.0), 0.0);
        assert_eq!(d.inverse(1e9), 1.0);
        Ok(())
    }

    #[test]
    fn straight_and_collapsed_curves_are_one_segment() -> Result<(), SubdivError> {
        let line = curve(&[(0.0, 0.0), (1.0, 1.0), (3.0, 3.0)]);
        let dot = curve(&[(2.0, 2.0), (2.0, 2.0), (2.0, 2.0)]);
        for c in [line, dot] {
            let pts = flatten_near_optimal(&c, 1e-6, 40)?;
            assert_eq!(pts.iter().map(|p| p.t).collect::<Vec<_>>(), [0.0, 1.0]);
        }
        Ok(())
    }

    #[test]
    fn every_step_is_exactly_within_tolerance_and_fills_it() -> Result<(), SubdivError> {
        let c = curve(&[(0.0, 0.0), (1.0, 3.0), (2.0, -2.0), (3.0, 2.0), (4.0, 0.0)]);
        let tol = 1e-3;
        let pts = flatten_near_optimal(&c, tol, 40)?;
        let steps: Vec<f64> = pts
            .windows(2)
            .map(|w| chord_deviation(&c, w[0].t, w[1].t))
            .collect::<Result<_, _>>()?;
        assert!(steps.iter().all(|&e| e <= tol));
        // All but the last step end at a deviation in [0.98 tol, tol] (or after the search's
        // evaluation cap, which this smooth curve does not reach).
        let full = steps[..steps.len() - 1]
            .iter()
            .filter(|&&e| e >= ACCEPT_FRACTION * tol)
            .count();
        assert_eq!(full, steps.len() - 1);
        Ok(())
    }

    #[test]
    fn errors_are_typed() {
        assert_typed_errors(flatten_near_optimal);
    }
}
