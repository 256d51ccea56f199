//! Curvature and torsion of Bézier curves.

use crate::math;
use crate::vector::Vector;
use alloc::vec::Vec;

use crate::curve::BezierCurve;
use crate::error::{CoreError, check_unit};

/// Relative size below which a derivative counts as zero (times the control polygon's scale).
const DEGENERATE: f64 = 1e-12;

impl<const D: usize> BezierCurve<D> {
    /// Scale of the control polygon: the largest |Pᵢ − P₀| (1 for a single point).
    fn scale(&self) -> f64 {
        let p0 = self.start();
        let s = self
            .points()
            .iter()
            .map(|p| (p - p0).norm())
            .fold(0.0, f64::max);
        if s > 0.0 { s } else { 1.0 }
    }

    fn tangent_checked(&self, t: f64, k: usize) -> Result<Vec<Vector<D>>, CoreError> {
        check_unit("t", t)?;
        let d = self.eval_derivatives_unchecked(t, k);
        let n = self.degree().max(1) as f64;
        let s = math::pow2_scale(d[1].amax());
        if (d[1] / s).norm() * s <= DEGENERATE * n * self.scale() {
            return Err(CoreError::ZeroTangent { t });
        }
        Ok(d)
    }

    /// Unsigned curvature κ(t) = |B' ∧ B''| / |B'|³ in any dimension.
    ///
    /// |B' ∧ B''|² = |B'|² |B''|² − (B'·B'')² (Lagrange's identity).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] for t ∉ [0, 1]; [`CoreError::ZeroTangent`] where B'
    /// vanishes (relative to the control polygon's size).
    pub fn curvature(&self, t: f64) -> Result<f64, CoreError> {
        let d = self.tangent_checked(t, 2)?;
        // B' = s_a a and B'' = s_b b with powers of two s (exact), so |a|³ cannot overflow:
        // κ = (s_b / s_a²) |a ∧ b| / |a|³.
        let ([a, b], [sa, sb]) = scaled([d[1], d[2]]);
        let an = a.norm();
        let ab = a.dot(&b);
        let wedge2 = (a.norm_squared() * b.norm_squared() - ab * ab).max(0.0);
        Ok(math::sqrt(wedge2) / (an * an * an) * (sb / sa) / sa)
    }
}

impl BezierCurve<2> {
    /// Signed curvature κ(t) = (x'y'' − y'x'') / |B'|³ (positive when turning left).
    ///
    /// # Errors
    /// As [`BezierCurve::curvature`].
    pub fn signed_curvature(&self, t: f64) -> Result<f64, CoreError> {
        let d = self.tangent_checked(t, 2)?;
        let ([a, b], [sa, sb]) = scaled([d[1], d[2]]);
        let an = a.norm();
        Ok((a.x() * b.y() - a.y() * b.x()) / (an * an * an) * (sb / sa) / sa)
    }
}

impl BezierCurve<3> {
    /// Torsion τ(t) = (B' × B'') · B''' / |B' × B''|².
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`], [`CoreError::ZeroTangent`], and
    /// [`CoreError::ZeroCurvature`] where B' × B'' vanishes (torsion undefined).
    pub fn torsion(&self, t: f64) -> Result<f64, CoreError> {
        let d = self.tangent_checked(t, 3)?;
        // Scaled as in curvature: τ = s_c / (s_a s_b) · (a × b) · c / |a × b|².
        let ([a, b, e], [sa, sb, sc]) = scaled([d[1], d[2], d[3]]);
        let c = a.cross(&b);
        let c2 = c.norm_squared();
        let scale = a.norm() * b.norm();
        if math::sqrt(c2) <= DEGENERATE * scale || c2 == 0.0 {
            return Err(CoreError::ZeroCurvature { t });
        }
        Ok(c.dot(&e) / c2 * (sc / sa) / sb)
    }
}

/// Each vector divided by the power of two of its largest coordinate (exact), and the powers.
fn scaled<const D: usize, const K: usize>(v: [Vector<D>; K]) -> ([Vector<D>; K], [f64; K]) {
    let s = v.map(|x| math::pow2_scale(x.amax()));
    (core::array::from_fn(|i| v[i] / s[i]), s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::{Vector2, Vector3};

    #[test]
    fn parabola_curvature_matches_analytic() {
        // y = x² on x ∈ [−1, 1] as a quadratic: P = (−1,1), (0,−1), (1,1); κ = 2/(1+4x²)^{3/2}.
        let c = BezierCurve::new(vec![
            Vector2::new(-1.0, 1.0),
            Vector2::new(0.0, -1.0),
            Vector2::new(1.0, 1.0),
        ])
        .unwrap();
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            let x = 2.0 * t - 1.0;
            let exact = 2.0 / (1.0 + 4.0 * x * x).powf(1.5);
            assert!((c.signed_curvature(t).unwrap() - exact).abs() < 1e-13);
            assert!((c.curvature(t).unwrap() - exact).abs() < 1e-13);
        }
    }

    #[test]
    fn circle_cubic_curvature_matches_endpoint_formula() {
        // Quarter-circle cubic P0 = (1,0), P1 = (1,k), P2 = (k,1), P3 = (0,1). At the ends
        // κ = (n−1)/n · |Δ₀ × Δ₁| / |Δ₀|³; with k = 4(√2−1)/3 this is ≈ 1 (the unit circle),
        // and the midpoint lies on the circle exactly.
        let k = 4.0 * (2f64.sqrt() - 1.0) / 3.0;
        let c = BezierCurve::new(vec![
            Vector2::new(1.0, 0.0),
            Vector2::new(1.0, k),
            Vector2::new(k, 1.0),
            Vector2::new(0.0, 1.0),
        ])
        .unwrap();
        let (d0, d1) = (Vector2::new(0.0, k), Vector2::new(k - 1.0, 1.0 - k));
        let end = 2.0 / 3.0 * (d0.x() * d1.y() - d0.y() * d1.x()).abs() / d0.norm().powi(3);
        assert!((c.signed_curvature(0.0).unwrap() - end).abs() < 1e-14);
        assert!((c.signed_curvature(1.0).unwrap() - end).abs() < 1e-14);
        assert!((end - 1.0).abs() < 0.1);
        assert!((c.eval(0.5).unwrap().norm() - 1.0).abs() < 1e-15);
        // Curvature is symmetric about t = ½ and positive (turning left).
        for k in 0..=10 {
            let t = f64::from(k) / 10.0;
            let a = c.signed_curvature(t).unwrap();
            assert!(a > 0.0);
            assert!((a - c.signed_curvature(1.0 - t).unwrap()).abs() < 1e-12);
        }
    }

    #[test]
    fn twisted_cubic_torsion_matches_analytic() {
        // (t, t², t³): power basis → Bernstein: P0 = 0, P1 = (1/3,0,0), P2 = (2/3,1/3,0), P3 = (1,1,1).
        let c = BezierCurve::new(vec![
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(1.0 / 3.0, 0.0, 0.0),
            Vector3::new(2.0 / 3.0, 1.0 / 3.0, 0.0),
            Vector3::new(1.0, 1.0, 1.0),
        ])
        .unwrap();
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            // τ = 3 / (9t⁴ + 9t² + 1), κ = 2 sqrt(9t⁴ + 9t² + 1) / (1 + 4t² + 9t⁴)^{3/2}.
            let q = 9.0 * t.powi(4) + 9.0 * t * t + 1.0;
            let tau = 3.0 / q;
            let kappa = 2.0 * q.sqrt() / (1.0 + 4.0 * t * t + 9.0 * t.powi(4)).powf(1.5);
            assert!((c.torsion(t).unwrap() - tau).abs() < 1e-12);
            assert!((c.curvature(t).unwrap() - kappa).abs() < 1e-12);
        }
    }

    #[test]
    fn degenerate_tangent_and_curvature_are_errors() {
        let c = BezierCurve::new(vec![Vector2::new(1.0, 1.0); 3]).unwrap();
        assert_eq!(c.curvature(0.5), Err(CoreError::ZeroTangent { t: 0.5 }));
        let line = BezierCurve::new(vec![Vector3::zeros(), Vector3::new(1.0, 2.0, 3.0)]).unwrap();
        assert_eq!(line.torsion(0.2), Err(CoreError::ZeroCurvature { t: 0.2 }));
    }
}
