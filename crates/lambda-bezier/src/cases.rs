//! The paper's examples (section 4) as data, shared by the tests and by `cargo xtask`.
//!
//! Where the paper gives no data (Figs. 5, 7, 8) the constructions here are ours; each says so.

use bez_core::{
    BezierCurve, BezierForm, Vector2, bernstein_derivative_coeffs, bernstein_product,
    eval_bernstein_poly, roots_in_unit_interval,
};

use crate::curve::LambdaBezierCurve;
use crate::error::LambdaError;
use crate::join::hermite_segment;

/// Akima's (1970) standard test data: 11 points, flat, then a steep rise (Fig. 5).
#[must_use]
pub fn akima_data() -> Vec<Vector2> {
    const X: [f64; 11] = [0.0, 2.0, 3.0, 5.0, 6.0, 8.0, 9.0, 11.0, 12.0, 14.0, 15.0];
    const Y: [f64; 11] = [
        10.0, 10.0, 10.0, 10.0, 10.0, 10.0, 10.5, 15.0, 50.0, 60.0, 85.0,
    ];
    X.iter()
        .zip(&Y)
        .map(|(&x, &y)| Vector2::new(x, y))
        .collect()
}

/// The λ values the paper uses for its five curved pieces of Fig. 5 (a) and (b).
pub const AKIMA_LAMBDAS: [[f64; 5]; 2] =
    [[-1.0, -1.0, -1.0, 1.0, -1.0], [0.0, 1.0, -1.0, 0.0, 1.0]];

/// The circle example (section 4.2): P₀..P₆ of the two quartic λ-curves (n = 3),
/// P₀(−1, 0), P₁(−1, 1.2), P₂(1, 1.2), P₃(1, 0), P₄(1, −1.2), P₅(−1, −1.2), P₆(−1, 0).
#[must_use]
pub fn circle_points() -> [Vector2; 7] {
    [
        Vector2::new(-1.0, 0.0),
        Vector2::new(-1.0, 1.2),
        Vector2::new(1.0, 1.2),
        Vector2::new(1.0, 0.0),
        Vector2::new(1.0, -1.2),
        Vector2::new(-1.0, -1.2),
        Vector2::new(-1.0, 0.0),
    ]
}

/// The paper's λ for the circle (Fig. 6).
pub const CIRCLE_LAMBDA: f64 = 0.56;

/// The two halves of the circle example at λ.
///
/// # Errors
/// λ outside [−3, 1].
pub fn circle_halves(lambda: f64) -> Result<[LambdaBezierCurve<2>; 2], LambdaError> {
    let p = circle_points();
    Ok([
        LambdaBezierCurve::from_slice(&p[..4], lambda)?,
        LambdaBezierCurve::from_slice(&p[3..], lambda)?,
    ])
}

/// The largest radial deviation max_t | |B(t)| − 1 | of a planar Bézier curve from the unit
/// circle, and where it occurs.
///
/// Exact up to rounding: |B(t)|² is a polynomial in Bernstein form (degree 2n); its critical
/// points are the roots of its derivative in [0, 1] (bez-core's robust isolation), and the
/// ends are checked too.
#[must_use]
pub fn max_radial_error(curve: &BezierCurve<2>) -> (f64, f64) {
    let x: Vec<f64> = curve.points().iter().map(|p| p.x()).collect();
    let y: Vec<f64> = curve.points().iter().map(|p| p.y()).collect();
    let r2: Vec<f64> = bernstein_product(&x, &x)
        .iter()
        .zip(bernstein_product(&y, &y))
        .map(|(a, b)| a + b)
        .collect();
    let mut candidates = roots_in_unit_interval(&bernstein_derivative_coeffs(&r2));
    candidates.extend([0.0, 1.0]);
    candidates
        .into_iter()
        .map(|t| ((eval_bernstein_poly(&r2, t).max(0.0).sqrt() - 1.0).abs(), t))
        .fold((0.0, 0.0), |best, c| if c.0 > best.0 { c } else { best })
}

/// The max radial error of the circle example at λ (both halves are mirror images, so one is
/// enough).
///
/// # Errors
/// λ outside [−3, 1].
pub fn circle_error(lambda: f64) -> Result<f64, LambdaError> {
    let [upper, _] = circle_halves(lambda)?;
    Ok(max_radial_error(upper.as_bezier()).0)
}

/// The upper half circle as a quartic λ-curve on (−1, 0), (−1, h), (1, h), (1, 0); the paper's
/// example is h = 1.2. Returns its max radial error.
///
/// # Errors
/// λ outside [−3, 1], non-finite h.
pub fn lambda_half_circle_error(h: f64, lambda: f64) -> Result<f64, LambdaError> {
    let c = LambdaBezierCurve::new(
        vec![
            Vector2::new(-1.0, 0.0),
            Vector2::new(-1.0, h),
            Vector2::new(1.0, h),
            Vector2::new(1.0, 0.0),
        ],
        lambda,
    )?;
    Ok(max_radial_error(c.as_bezier()).0)
}

/// The classical cubic Bézier half circle (−1, 0), (−1, h), (1, h), (1, 0); h = 4/3 puts the
/// midpoint on the circle. (The circle example at λ = 0 is this curve with h = 1.2.)
///
/// # Errors
/// Non-finite h.
pub fn cubic_half_circle(h: f64) -> Result<BezierCurve<2>, LambdaError> {
    Ok(BezierCurve::new(vec![
        Vector2::new(-1.0, 0.0),
        Vector2::new(-1.0, h),
        Vector2::new(1.0, h),
        Vector2::new(1.0, 0.0),
    ])?)
}

/// The classical cubic quarter circle (1, 0), (1, k), (k, 1), (0, 1); k = 4(√2 − 1)/3 puts the
/// midpoint on the circle, k ≈ 0.5519 minimizes the radial error.
///
/// # Errors
/// Non-finite k.
pub fn cubic_quarter_circle(k: f64) -> Result<BezierCurve<2>, LambdaError> {
    Ok(BezierCurve::new(vec![
        Vector2::new(1.0, 0.0),
        Vector2::new(1.0, k),
        Vector2::new(k, 1.0),
        Vector2::new(0.0, 1.0),
    ])?)
}

/// The λ values of the paper's Fig. 3 (quartic) and Fig. 7 (leaf).
pub const QUARTIC_LAMBDAS: [f64; 5] = [1.0, 0.0, -1.0, -2.0, -3.0];
/// The λ values of the paper's Fig. 4 (quintic).
pub const QUINTIC_LAMBDAS: [f64; 6] = [1.0, 0.0, -1.0, -2.0, -3.0, -4.0];

/// Control polygons for Figs. 3 and 4 (ours: the paper prints no coordinates): an arch of
/// 4 points (quartic λ-curves) and of 5 points (quintic).
#[must_use]
pub fn arch_points(n: usize) -> Vec<Vector2> {
    match n {
        3 => vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 3.0),
            Vector2::new(4.0, 3.0),
            Vector2::new(5.0, 0.0),
        ],
        _ => vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(0.5, 2.5),
            Vector2::new(2.5, 3.5),
            Vector2::new(4.5, 2.5),
            Vector2::new(5.0, 0.0),
        ],
    }
}

/// A closed leaf (Fig. 7, ours): P₀ = P₃ = (0, 0), P₁ = (−1.5, 2), P₂ = (1.5, 2), rotated by
/// `angle` radians about the origin.
#[must_use]
pub fn leaf_points(angle: f64) -> Vec<Vector2> {
    let (s, c) = angle.sin_cos();
    [(0.0, 0.0), (-1.5, 2.0), (1.5, 2.0), (0.0, 0.0)]
        .iter()
        .map(|&(x, y)| Vector2::new(c * x - s * y, s * x + c * y))
        .collect()
}

/// The vase profile of Fig. 8 (ours): radius x against height y at 7 joints, with the
/// derivative (dx, dy) of the profile at each joint. Six λ-Hermite segments
/// ([`hermite_segment`]) through them join with C1 continuity for every choice of λ.
pub const VASE_JOINTS: [([f64; 2], [f64; 2]); 7] = [
    ([0.9, 0.0], [2.0, 0.6]),
    ([1.7, 1.0], [0.8, 1.6]),
    ([1.9, 2.4], [-0.3, 1.6]),
    ([1.3, 3.9], [-1.0, 1.2]),
    ([0.6, 5.0], [-0.2, 1.2]),
    ([0.7, 6.0], [0.5, 1.0]),
    ([1.2, 6.7], [1.2, 0.4]),
];

/// The right half of the vase: 6 C1-joined λ-curves with n = 3 (quartic) or n = 4 (quintic;
/// the free middle point is the midpoint of its neighbours), λ cycling through `lambdas`.
///
/// # Errors
/// n other than 3 or 4 ([`LambdaError::DegreeTooLow`] for n < 3); λ out of range or with
/// n + λ = 0; an empty `lambdas` ([`LambdaError::LambdaCount`]).
pub fn vase_profile(n: usize, lambdas: &[f64]) -> Result<Vec<LambdaBezierCurve<2>>, LambdaError> {
    if n < 3 {
        return Err(LambdaError::DegreeTooLow { n });
    }
    if lambdas.is_empty() {
        return Err(LambdaError::LambdaCount {
            expected: 6,
            got: 0,
        });
    }
    let v = |a: [f64; 2]| Vector2::new(a[0], a[1]);
    VASE_JOINTS
        .windows(2)
        .zip(lambdas.iter().cycle())
        .map(|(w, &l)| {
            let (e0, d0) = (v(w[0].0), v(w[0].1));
            let (e1, d1) = (v(w[1].0), v(w[1].1));
            let k = n as f64 + l;
            let inner: Vec<Vector2> = if n == 3 {
                Vec::new()
            } else {
                // One free point per extra degree, spread on the chord between the two legs.
                let a = e0 + d0 / k;
                let b = e1 - d1 / k;
                (1..=n - 3)
                    .map(|i| a + (b - a) * (i as f64 / (n - 2) as f64))
                    .collect()
            };
            hermite_segment(e0, d0, &inner, e1, d1, l)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::join::{Continuity, continuity};

    #[test]
    fn circle_error_is_radial_deviation() {
        // Dense sampling cannot exceed the exact maximum and comes close to it.
        let [upper, lower] = circle_halves(CIRCLE_LAMBDA).unwrap();
        let e = circle_error(CIRCLE_LAMBDA).unwrap();
        let sampled = upper
            .sample_uniform(20001)
            .unwrap()
            .iter()
            .chain(lower.sample_uniform(20001).unwrap().iter())
            .map(|p| (p.norm() - 1.0).abs())
            .fold(0.0, f64::max);
        assert!(sampled <= e + 1e-15 && sampled > e - 1e-8, "{sampled} {e}");
        // Midpoint: B(1/2) = (0, (8·1.068 + 7.2)/16) at λ = 0.56, computed by hand.
        assert!((upper.eval(0.5).unwrap().y() - 0.984).abs() < 1e-12);
        // The classical quarter circle with the midpoint on the circle: 2.7e-4.
        let k = 4.0 * (2f64.sqrt() - 1.0) / 3.0;
        let (q, _) = max_radial_error(&cubic_quarter_circle(k).unwrap());
        assert!((q - 2.7253e-4).abs() < 1e-7, "{q}");
        assert!(circle_error(1.5).is_err());
        assert_eq!(lambda_half_circle_error(1.2, CIRCLE_LAMBDA).unwrap(), e);
        // λ = 0 is the cubic half circle of the same points.
        let cubic = max_radial_error(&cubic_half_circle(1.2).unwrap()).0;
        assert!((lambda_half_circle_error(1.2, 0.0).unwrap() - cubic).abs() < 1e-14);
    }

    #[test]
    fn vase_is_c1_for_any_lambdas() {
        for n in [3, 4] {
            for lambdas in [vec![0.0], vec![1.0, -1.0, 0.5, -2.0, 0.0, 1.0]] {
                let v = vase_profile(n, &lambdas).unwrap();
                assert_eq!(v.len(), 6);
                // A vase profile: positive radius, height increasing.
                for c in &v {
                    let q = c.sample_uniform(50).unwrap();
                    assert!(q.iter().all(|p| p.x() > 0.3));
                    assert!(q.windows(2).all(|w| w[1].y() > w[0].y()));
                }
                for w in v.windows(2) {
                    assert_eq!(continuity(&w[0], &w[1], 1e-12), Continuity::C1);
                }
            }
        }
        assert!(vase_profile(2, &[0.0]).is_err());
        assert!(vase_profile(3, &[]).is_err());
        assert!(vase_profile(3, &[-3.0]).is_err());
    }

    #[test]
    fn figure_data_is_valid() {
        for (n, ls) in [(3, &QUARTIC_LAMBDAS[..]), (4, &QUINTIC_LAMBDAS[..])] {
            for &l in ls {
                assert!(LambdaBezierCurve::new(arch_points(n), l).is_ok());
            }
        }
        let leaf = leaf_points(0.3);
        assert!((leaf[0] - leaf[3]).norm() == 0.0);
        assert_eq!(akima_data().len(), 11);
        assert_eq!(AKIMA_LAMBDAS[0].len(), 5);
    }
}
