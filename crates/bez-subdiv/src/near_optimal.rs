//! Beyond the paper: near-optimal flattening by the curvature density √(|κ| / (8 tol)).

use bez_core::{BezierCurve, Vector2};

use crate::error::SubdivError;

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::curve;

    /// N* of a circular arc of radius r and angle θ: the density √(κ/(8 tol)) is constant, so
    /// N* = rθ √(1/(8 r tol)) = θ √(r / (8 tol)). The quadratic arc is not exactly circular, so
    /// against a quarter circle within 1 %.
    #[test]
    fn n_star_of_a_near_circular_arc() -> Result<(), SubdivError> {
        // The cubic quarter circle of radius 1 (handle 0.5523), curvature within 0.03 % of 1.
        let k: f64 = 0.552_284_749_831;
        let c = curve(&[(1.0, 0.0), (1.0, k), (k, 1.0), (0.0, 1.0)]);
        let tol = 1e-4;
        let expected = std::f64::consts::FRAC_PI_2 * (1.0_f64 / (8.0 * tol)).sqrt();
        let n_star = optimal_segment_count(&c, tol)?;
        assert!(
            (n_star / expected - 1.0).abs() < 1e-2,
            "{n_star} vs {expected}"
        );
        Ok(())
    }
}
