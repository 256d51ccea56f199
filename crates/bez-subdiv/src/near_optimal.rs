//! Beyond the paper: near-optimal flattening by the curvature density √(|κ| / (8 tol)).

use bez_core::{BezierCurve, HornerBernstein, Vector2, hodograph_slice};

use crate::error::SubdivError;

/// Quadrature nodes per unit of degree for the density integral.
const NODES_PER_DEGREE: usize = 64;
/// Most quadrature nodes (reached above degree 64).
const MAX_NODES: usize = 4096;

/// The asymptotic lower bound N* = ∫ √(|κ| / (8 tol)) ds on the number of segments of any
/// polyline through curve points within `tolerance` (a segment of a curve arc of curvature κ
/// and length h deviates by about κh²/8), by the trapezoidal rule on 64 n nodes (at most 4096),
/// with B′ and B″ by Horner's rule, O(n) per node.
///
/// # Errors
/// [`SubdivError::InvalidTolerance`], [`SubdivError::TooFewPoints`];
/// [`SubdivError::TooManySegments`] when the integral overflows.
pub fn optimal_segment_count(curve: &BezierCurve<2>, tolerance: f64) -> Result<f64, SubdivError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(SubdivError::InvalidTolerance { value: tolerance });
    }
    let p = curve.points();
    if p.len() < 2 {
        return Err(SubdivError::TooFewPoints { got: p.len() });
    }
    let d1 = hodograph_slice(p);
    let (first, second) = (
        HornerBernstein::new(&d1),
        HornerBernstein::new(&hodograph_slice(&d1)),
    );
    let m = (NODES_PER_DEGREE * curve.degree()).min(MAX_NODES);
    let density = |k: usize| {
        let t = k as f64 / m as f64;
        let zero = Vector2::zeros();
        let (v, a) = (
            first.eval(t).unwrap_or(zero),
            second.eval(t).unwrap_or(zero),
        );
        let speed = v.norm();
        // √|κ| · speed = √(|x′ × x″| / speed), finite even where the speed vanishes.
        if speed > 0.0 {
            (v.perp(&a).abs() / speed).sqrt()
        } else {
            0.0
        }
    };
    let inner: f64 = (1..m).map(density).sum();
    let total = (inner + 0.5 * (density(0) + density(m))) / m as f64 / (8.0 * tolerance).sqrt();
    if total.is_finite() {
        Ok(total)
    } else {
        Err(SubdivError::TooManySegments {
            tolerance,
            limit: usize::MAX,
        })
    }
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
