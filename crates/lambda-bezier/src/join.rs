//! Joining consecutive λ-Bézier curves with G1 or C1 continuity.
//!
//! At the joint of A (n_a, λ_a, P) and B (n_b, λ_b, Q) with Q₀ = P_{n_a}, the one-sided
//! derivatives are (n_a + λ_a)(P_{n_a} − P_{n_a−1}) and (n_b + λ_b)(Q₁ − Q₀) (Property 1), so
//! - G1 ⇔ Q₁ − Q₀ = s (P_{n_a} − P_{n_a−1}) for some s > 0,
//! - C1 ⇔ s = (n_a + λ_a) / (n_b + λ_b).
//!
//! The λ values and degrees of the two curves are free: a joint fixes only Q₀ and Q₁.
//! n + λ = 0 (possible at the lower end of the range for n ≤ 5) makes the tangent vanish.

use bez_core::{BezierForm, Vector};

use crate::curve::LambdaBezierCurve;
use crate::error::LambdaError;

/// The order of continuity at the joint of two curves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Continuity {
    /// The end of the first curve is not the start of the second.
    None,
    /// Positional continuity only.
    C0,
    /// Common tangent direction.
    G1,
    /// Equal first derivatives.
    C1,
}

/// The continuity at the joint A(1) → B(0), with relative tolerance `tol` (scaled by the sizes of
/// the points and tangents involved).
#[must_use]
pub fn continuity<const D: usize>(
    a: &LambdaBezierCurve<D>,
    b: &LambdaBezierCurve<D>,
    tol: f64,
) -> Continuity {
    let (pa, pb) = (
        *a.points().last().unwrap_or(&Vector::zeros()),
        b.points()[0],
    );
    let scale = 1.0 + pa.norm().max(pb.norm());
    if (pa - pb).norm() > tol * scale {
        return Continuity::None;
    }
    let (ta, tb) = (a.end_tangent(), b.start_tangent());
    let tscale = ta.norm().max(tb.norm());
    if tscale == 0.0 {
        return Continuity::C0;
    }
    if (ta - tb).norm() <= tol * tscale {
        return Continuity::C1;
    }
    let (na, nb) = (ta.norm(), tb.norm());
    if na > 0.0 && nb > 0.0 && (ta / na - tb / nb).norm() <= tol {
        return Continuity::G1;
    }
    Continuity::C0
}

/// B moved to join A with G1 continuity: Q₀ := A(1), Q₁ := Q₀ + |Q₁ − Q₀| · u where u is the
/// unit end tangent of A; the other points and λ of B stay.
///
/// # Errors
/// [`LambdaError::DegenerateJoint`] if A's end tangent or B's first leg vanishes.
pub fn join_g1<const D: usize>(
    a: &LambdaBezierCurve<D>,
    b: &LambdaBezierCurve<D>,
) -> Result<LambdaBezierCurve<D>, LambdaError> {
    let dir = unit_end_tangent(a)?;
    let leg = (b.points()[1] - b.points()[0]).norm();
    if leg == 0.0 || !leg.is_finite() {
        return Err(LambdaError::DegenerateJoint { which: "outgoing" });
    }
    let mut q = b.points().to_vec();
    q[0] = a.eval(1.0)?;
    q[1] = q[0] + dir * leg;
    LambdaBezierCurve::new(q, b.lambda())
}

/// B moved to join A with C1 continuity:
/// Q₀ := A(1), Q₁ := Q₀ + (n_a + λ_a)/(n_b + λ_b) (P_{n_a} − P_{n_a−1}).
///
/// # Errors
/// [`LambdaError::DegenerateJoint`] if A's end tangent vanishes or n_b + λ_b = 0.
pub fn join_c1<const D: usize>(
    a: &LambdaBezierCurve<D>,
    b: &LambdaBezierCurve<D>,
) -> Result<LambdaBezierCurve<D>, LambdaError> {
    unit_end_tangent(a)?;
    let kb = b.n() as f64 + b.lambda();
    if kb <= 0.0 {
        return Err(LambdaError::DegenerateJoint { which: "outgoing" });
    }
    let mut q = b.points().to_vec();
    q[0] = a.eval(1.0)?;
    q[1] = q[0] + a.end_tangent() / kb;
    LambdaBezierCurve::new(q, b.lambda())
}

/// The λ-curve with prescribed end points and end derivatives (a λ-Hermite segment):
/// P₀ = `start`, P₁ = P₀ + `start_derivative`/(n + λ), `inner` points, Pₙ₋₁ = Pₙ − `end_derivative`/(n + λ),
/// Pₙ = `end`, with n = `inner.len()` + 3. Consecutive segments built from shared points and
/// derivatives join with C1 continuity whatever their λ, so λ can be tuned per segment.
///
/// # Errors
/// [`LambdaError::DegenerateJoint`] if n + λ ≤ 0, λ out of range, non-finite points.
pub fn hermite_segment<const D: usize>(
    start: Vector<D>,
    start_derivative: Vector<D>,
    inner: &[Vector<D>],
    end: Vector<D>,
    end_derivative: Vector<D>,
    lambda: f64,
) -> Result<LambdaBezierCurve<D>, LambdaError> {
    let n = inner.len() + 3;
    let range = crate::range::LambdaRange::new(n)?;
    let lambda = range.check(lambda)?;
    let k = n as f64 + lambda;
    if k <= 0.0 {
        return Err(LambdaError::DegenerateJoint { which: "outgoing" });
    }
    let mut p = Vec::with_capacity(n + 1);
    p.push(start);
    p.push(start + start_derivative / k);
    p.extend_from_slice(inner);
    p.push(end - end_derivative / k);
    p.push(end);
    LambdaBezierCurve::new(p, lambda)
}

fn unit_end_tangent<const D: usize>(a: &LambdaBezierCurve<D>) -> Result<Vector<D>, LambdaError> {
    let t = a.end_tangent();
    let len = t.norm();
    if len == 0.0 || !len.is_finite() {
        return Err(LambdaError::DegenerateJoint { which: "incoming" });
    }
    Ok(t / len)
}

#[cfg(test)]
mod tests {
    use bez_core::Vector2;

    use super::*;

    fn a() -> LambdaBezierCurve<2> {
        LambdaBezierCurve::new(
            vec![
                Vector2::new(0.0, 0.0),
                Vector2::new(1.0, 1.0),
                Vector2::new(2.0, 1.0),
                Vector2::new(3.0, 0.0),
            ],
            -1.5,
        )
        .unwrap()
    }

    fn b() -> LambdaBezierCurve<2> {
        LambdaBezierCurve::new(
            vec![
                Vector2::new(3.5, 0.2),
                Vector2::new(4.0, 1.0),
                Vector2::new(5.0, -1.0),
                Vector2::new(6.0, 0.5),
                Vector2::new(7.0, 0.0),
            ],
            0.7,
        )
        .unwrap()
    }

    #[test]
    fn c1_joint_has_equal_derivatives() {
        let b1 = join_c1(&a(), &b()).unwrap();
        let da = a().derivative().unwrap().eval(1.0).unwrap();
        let db = b1.derivative().unwrap().eval(0.0).unwrap();
        assert!((da - db).norm() < 1e-12);
        assert_eq!(continuity(&a(), &b1, 1e-12), Continuity::C1);
        assert_eq!(continuity(&a(), &b(), 1e-12), Continuity::None);
    }

    #[test]
    fn g1_joint_keeps_direction_not_length() {
        let b1 = join_g1(&a(), &b()).unwrap();
        assert_eq!(continuity(&a(), &b1, 1e-12), Continuity::G1);
        let leg = |c: &LambdaBezierCurve<2>| (c.points()[1] - c.points()[0]).norm();
        assert!((leg(&b1) - leg(&b())).abs() < 1e-12);
    }

    #[test]
    fn hermite_segments_join_c1_for_any_lambda() {
        let (e0, d0) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 3.0));
        let (e1, d1) = (Vector2::new(2.0, 1.0), Vector2::new(2.0, -1.0));
        let (e2, d2) = (Vector2::new(4.0, 0.0), Vector2::new(0.5, -2.0));
        for (la, lb) in [(-2.0, 1.0), (0.0, -2.5), (0.9, 0.3)] {
            let a = hermite_segment(e0, d0, &[], e1, d1, la).unwrap();
            let b = hermite_segment(e1, d1, &[Vector2::new(3.0, 2.0)], e2, d2, lb).unwrap();
            assert_eq!(continuity(&a, &b, 1e-12), Continuity::C1);
            assert!((a.derivative().unwrap().start() - d0).norm() < 1e-12);
            assert!((b.derivative().unwrap().end() - d2).norm() < 1e-12);
        }
        assert!(matches!(
            hermite_segment(e0, d0, &[], e1, d1, -3.0),
            Err(LambdaError::DegenerateJoint { .. })
        ));
        assert!(hermite_segment(e0, d0, &[], e1, d1, -3.5).is_err());
    }

    #[test]
    fn degenerate_joints_are_errors() {
        // n = 3, λ = −3: n + λ = 0, the end tangent vanishes.
        let flat = a().with_lambda(-3.0).unwrap();
        assert!(matches!(
            join_g1(&flat, &b()),
            Err(LambdaError::DegenerateJoint { which: "incoming" })
        ));
        assert!(join_c1(&flat, &b()).is_err());
        let mut p = b().points().to_vec();
        p[1] = p[0];
        let stub = LambdaBezierCurve::new(p, 0.0).unwrap();
        assert!(join_g1(&a(), &stub).is_err());
        let b5 = LambdaBezierCurve::new(b().points().to_vec(), -4.0).unwrap();
        assert!(matches!(
            join_c1(&a(), &b5),
            Err(LambdaError::DegenerateJoint { which: "outgoing" })
        ));
        assert_eq!(
            continuity(&flat, &join_c1(&a(), &b()).unwrap(), 1e-12),
            Continuity::C0
        );
    }
}
