//! Joining consecutive λ-Bézier curves with G1, C1 or G2 continuity.
//!
//! At the joint of A (n_a, λ_a, P) and B (n_b, λ_b, Q) with Q₀ = P_{n_a}, the one-sided
//! derivatives are (n_a + λ_a)(P_{n_a} − P_{n_a−1}) and (n_b + λ_b)(Q₁ − Q₀) (Property 1), so
//! - G1 ⇔ Q₁ − Q₀ = s (P_{n_a} − P_{n_a−1}) for some s > 0,
//! - C1 ⇔ s = (n_a + λ_a) / (n_b + λ_b).
//!
//! The λ values and degrees of the two curves are free: a G1 or C1 joint fixes only Q₀ and Q₁,
//! a G2 joint also Q₂ (see [`join_g2`]).
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

/// B moved to join A with G2 continuity (common tangent direction and curvature vector):
/// Q₀ and Q₁ as in [`join_g1`], and Q₂ solved from the second derivative.
///
/// With the Bézier form Rⱼ = (1 − aⱼ) Qⱼ₋₁ + aⱼ Qⱼ of B (degree N = n_b + 1, aⱼ the
/// [`corner_cut_ratio`](crate::corner_cut_ratio)s), B'(0) = N (R₁ − R₀) = s A'(1) with
/// s = (n_b + λ_b)|Q₁ − Q₀| / |A'(1)| > 0, and G2 asks B''(0) = s² A''(1) + μ A'(1) for some μ
/// (the curvature depends only on the part of B'' normal to B'). This takes μ = 0, so
/// R₂ = s² A''(1) / (N (N − 1)) + 2 R₁ − R₀ and
/// Q₂ = (R₂ − (1 − a₂) Q₁) / a₂. The other points and λ of B stay.
///
/// # Errors
/// [`LambdaError::JoinNeedsDegree`] for n_b < 3 (Q₂ would be B's end point);
/// [`LambdaError::DegenerateJoint`] if A's end tangent or B's first leg vanishes, or a₂ = 0
/// (λ_b at the lower end of its range for some n); a result outside the coordinate range.
pub fn join_g2<const D: usize>(
    a: &LambdaBezierCurve<D>,
    b: &LambdaBezierCurve<D>,
) -> Result<LambdaBezierCurve<D>, LambdaError> {
    let n = b.n();
    if n < 3 {
        return Err(LambdaError::JoinNeedsDegree { needed: 3, n });
    }
    let g1 = join_g1(a, b)?;
    let d = a.as_bezier().eval_derivatives(1.0, 2)?;
    let (lambda, big_n) = (b.lambda(), (n + 1) as f64);
    let (a1, a2) = (
        crate::corner_cut_ratio(n, 1, lambda),
        crate::corner_cut_ratio(n, 2, lambda),
    );
    if a2.abs() <= f64::EPSILON {
        return Err(LambdaError::DegenerateJoint { which: "outgoing" });
    }
    let mut q = g1.points().to_vec();
    let s = (n as f64 + lambda) * (q[1] - q[0]).norm() / d[1].norm();
    let r0 = q[0];
    let r1 = q[0] * (1.0 - a1) + q[1] * a1;
    let r2 = d[2] * (s * s / (big_n * (big_n - 1.0))) + r1 * 2.0 - r0;
    q[2] = (r2 - q[1] * (1.0 - a2)) / a2;
    LambdaBezierCurve::new(q, lambda)
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
    use bez_core::{Vector2, Vector3};

    use super::*;

    /// G2 checked by bez-core's curvature formulas, independent of the construction: common
    /// point, common unit tangent, equal signed curvature (2-D), equal curvature and osculating
    /// plane (3-D), for several degrees and λ on both sides.
    #[test]
    fn g2_join_matches_position_tangent_and_curvature() {
        let mut checked = 0;
        for (na, nb) in [(2, 3), (3, 4), (5, 3), (4, 7)] {
            for (la, lb) in [(0.0, 0.0), (0.5, -0.5), (-0.9, 0.9), (0.3, 0.6)] {
                let pa: Vec<Vector2> = (0..=na)
                    .map(|i| Vector2::new(i as f64, ((i * 3) % 4) as f64 * 0.7))
                    .collect();
                let pb: Vec<Vector2> = (0..=nb)
                    .map(|i| Vector2::new(10.0 + i as f64, ((i * 5) % 3) as f64 - 1.0))
                    .collect();
                let (Ok(a), Ok(b)) = (
                    LambdaBezierCurve::new(pa, la),
                    LambdaBezierCurve::new(pb, lb),
                ) else {
                    continue;
                };
                let j = join_g2(&a, &b).unwrap();
                let (ab, jb) = (a.as_bezier(), j.as_bezier());
                assert!((ab.end() - jb.start()).norm() < 1e-12);
                let (ta, tj) = (a.end_tangent(), j.start_tangent());
                assert!((ta / ta.norm() - tj / tj.norm()).norm() < 1e-12);
                let (ka, kj) = (
                    ab.signed_curvature(1.0).unwrap(),
                    jb.signed_curvature(0.0).unwrap(),
                );
                assert!(
                    (ka - kj).abs() <= 1e-9 * (1.0 + ka.abs()),
                    "n {na}/{nb} λ {la}/{lb}: {ka} vs {kj}"
                );
                // Only Q₀, Q₁, Q₂ move.
                assert_eq!(j.points()[3..], b.points()[3..]);
                checked += 1;
            }
        }
        assert!(checked >= 12, "only {checked} combinations were in range");
        let lift = |p: &[Vector2], z: f64| -> Vec<Vector3> {
            p.iter()
                .enumerate()
                .map(|(i, q)| Vector3::new(q.x(), q.y(), z * (i * i) as f64))
                .collect()
        };
        let a = LambdaBezierCurve::new(lift(a().points(), 0.3), 0.4).unwrap();
        let b = LambdaBezierCurve::new(
            lift(
                &[
                    Vector2::new(5.0, 0.0),
                    Vector2::new(6.0, 2.0),
                    Vector2::new(7.0, 0.0),
                    Vector2::new(8.0, 1.0),
                ],
                -0.2,
            ),
            -0.7,
        )
        .unwrap();
        let j = join_g2(&a, &b).unwrap();
        let (da, dj) = (
            a.as_bezier().eval_derivatives(1.0, 2).unwrap(),
            j.as_bezier().eval_derivatives(0.0, 2).unwrap(),
        );
        let (ca, cj) = (da[1].cross(&da[2]), dj[1].cross(&dj[2]));
        assert!(
            (ca / ca.norm() - cj / cj.norm()).norm() < 1e-12,
            "osculating planes differ"
        );
        let (ka, kj) = (
            a.as_bezier().curvature(1.0).unwrap(),
            j.as_bezier().curvature(0.0).unwrap(),
        );
        assert!((ka - kj).abs() <= 1e-9 * ka, "{ka} vs {kj}");
    }

    #[test]
    fn g2_join_needs_four_control_points() {
        let short = LambdaBezierCurve::new(a().points()[..3].to_vec(), 0.0).unwrap();
        assert_eq!(
            join_g2(&b(), &short),
            Err(LambdaError::JoinNeedsDegree { needed: 3, n: 2 })
        );
    }

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
