//! Beyond the paper: near-optimal flattening by the curvature density √(|κ| / (8 tol)).

use bez_core::{
    BezierCurve, Vector2, bernstein_derivative_coeffs, eval_bernstein_poly, roots_in_unit_interval,
};

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
            let cross = (d[1].x * d[2].y - d[1].y * d[2].x).abs();
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

/// Whether the piece of `curve` on [a, b] lies within `tol` of the chord segment B(a)B(b),
/// exactly: the signed distance to the chord line and the projection onto it are polynomials
/// in Bernstein form (coefficients from the piece's control points), maximized at their end
/// points or at the roots of their derivatives.
fn piece_within(curve: &BezierCurve<2>, a: f64, b: f64, tol: f64) -> bool {
    let Ok(piece) = curve.subsegment(a, b) else {
        return false;
    };
    let (p0, p1) = (piece.start(), piece.end());
    let d = p1 - p0;
    let len = d.norm();
    if len == 0.0 {
        return piece.points().iter().all(|p| (p - p0).norm() <= tol);
    }
    let u = d / len;
    let dist: Vec<f64> = piece
        .points()
        .iter()
        .map(|p| u.x * (p.y - p0.y) - u.y * (p.x - p0.x))
        .collect();
    let proj: Vec<f64> = piece.points().iter().map(|p| u.dot(&(p - p0))).collect();
    // Values at the end points and at every stationary point bound the polynomial's range.
    let range = |c: &[f64]| {
        roots_in_unit_interval(&bernstein_derivative_coeffs(c))
            .into_iter()
            .chain([0.0, 1.0])
            .map(|t| eval_bernstein_poly(c, t))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    };
    let (dlo, dhi) = range(&dist);
    let (plo, phi) = range(&proj);
    // A point at perpendicular offset ≤ d whose projection overshoots the chord by ≤ o is
    // within √(d² + o²) of the segment.
    let d = dlo.abs().max(dhi.abs());
    let o = (-plo).max(phi - len).max(0.0);
    d.hypot(o) <= tol
}

/// Points B(tᵢ) placed by the density √(|κ|/(8 tol)) |B'(t)|: ⌈N*⌉ segments at equal steps of
/// the integral, then every segment is verified exactly (distance to its chord segment ≤ tol,
/// see `piece_within`) and halved until it passes, so the result has the same Hausdorff
/// guarantee as [`crate::flatten_guaranteed`] with close to the minimal number of points.
///
/// Cost: O(n² m) for the density (m = 64 n nodes) plus O(n²) per verified segment.
///
/// # Errors
/// [`SubdivError::InvalidTolerance`], [`SubdivError::TooFewPoints`], [`SubdivError::DepthLimit`]
/// when a segment fails after `max_depth` halvings.
pub fn flatten_near_optimal(
    curve: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
) -> Result<Vec<FlatPoint>, SubdivError> {
    let (ts, cumulative) = density_integral(curve, tolerance)?;
    let total = cumulative.last().copied().unwrap_or(0.0);
    let count = total.ceil().max(1.0) as usize;
    let mut params = vec![0.0];
    let mut k = 1;
    for i in 1..count {
        let target = total * i as f64 / count as f64;
        while k < ts.len() - 1 && cumulative[k] < target {
            k += 1;
        }
        let (c0, c1) = (cumulative[k - 1], cumulative[k]);
        let w = if c1 > c0 {
            (target - c0) / (c1 - c0)
        } else {
            0.0
        };
        let t = ts[k - 1] + w * (ts[k] - ts[k - 1]);
        if t > *params.last().unwrap_or(&0.0) && t < 1.0 {
            params.push(t);
        }
    }
    params.push(1.0);
    let mut out = vec![FlatPoint {
        t: 0.0,
        point: curve.start(),
    }];
    for w in params.windows(2) {
        let mut stack = vec![(w[0], w[1], 0usize)];
        while let Some((a, b, depth)) = stack.pop() {
            if piece_within(curve, a, b, tolerance) {
                let point = if b == 1.0 {
                    curve.end()
                } else {
                    curve.eval(b)?
                };
                out.push(FlatPoint { t: b, point });
            } else if depth >= max_depth {
                return Err(SubdivError::DepthLimit { limit: max_depth });
            } else {
                let m = 0.5 * (a + b);
                stack.push((m, b, depth + 1));
                stack.push((a, m, depth + 1));
            }
        }
    }
    Ok(out)
}
