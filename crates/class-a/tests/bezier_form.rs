//! `ClassACurve` through the `BezierForm` trait against the closed forms of typical curves.

use bez_core::proptest_support::check_bezier_form;
use bez_core::{BezierForm, Vector2, Vector3};
use class_a::Matrix3;
use class_a::{ClassACurve, TypicalPlanar, cases};
use nalgebra::Complex;

/// A planar typical curve in complex notation, with w(t) = 1 + t(z − 1), z = s e^{iθ}:
/// x'(t) = n L μ w(t)ⁿ⁻¹ and x(t) = b₀ + L μ (w(t)ⁿ − 1)/(z − 1), from the parameters alone.
fn planar_oracle(t: &TypicalPlanar) -> (impl Fn(f64) -> Vector2, impl Fn(f64) -> Vector2) {
    let z = Complex::from_polar(t.s(), t.theta());
    let lmu = Complex::new(t.mu().x(), t.mu().y()) * t.length();
    let (b0, n) = (t.b0(), t.degree());
    let w = move |u: f64| Complex::new(1.0, 0.0) + (z - 1.0) * u;
    let position = move |u: f64| {
        let x = lmu * (w(u).powu(n as u32) - 1.0) / (z - 1.0);
        b0 + Vector2::new(x.re, x.im)
    };
    let velocity = move |u: f64| {
        let v = lmu * (n as f64) * w(u).powu(n as u32 - 1);
        Vector2::new(v.re, v.im)
    };
    (position, velocity)
}

#[test]
fn planar_class_a_curves_match_the_closed_form_through_the_trait() {
    let example = [
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 0.0),
        Vector2::new(1.6, 1.0),
    ];
    // The crate example, Fig. 6's points (also at the paper's degree 49) and Fig. 7's.
    for (a, degree, tolerance) in [
        (example, 7, 1e-12),
        (cases::fig6_points(), 5, 1e-12),
        (cases::fig6_points(), 49, 1e-10),
        (cases::fig7_points(), 6, 1e-12),
    ] {
        let typical = TypicalPlanar::from_points(&a[0], &a[1], &a[2], degree).unwrap();
        let curve = ClassACurve::try_from(&typical).unwrap();
        assert_eq!(curve.as_bezier(), &typical.curve().unwrap());
        assert_eq!(curve.matrix(), typical.matrix());
        let (position, velocity) = planar_oracle(&typical);
        let r = check_bezier_form(&curve, position, velocity, tolerance);
        assert_eq!(r, Ok(()), "points {a:?}, n = {degree}");
        // Signed curvature through the trait against the closed form of TypicalPlanar.
        for k in 0..=10 {
            let u = f64::from(k) / 10.0;
            let kappa = curve.signed_curvature(u).unwrap();
            let exact = typical.curvature(u);
            assert!(
                (kappa - exact).abs() <= 1e-10 * exact.abs().max(1.0),
                "{kappa} {exact}"
            );
        }
    }
}

#[test]
fn spatial_class_a_curves_match_their_legs_through_the_trait() {
    // x(t) = Σ bᵢ B_{i,n}(t) with bᵢ = b₀ + Σ_{j<i} Mʲ Δb₀ summed here from M directly, and the
    // derivative x'(t) = n Σ Mʲ Δb₀ B_{j,n−1}(t): Bernstein sums, not de Casteljau.
    let typical = cases::fig8_typical().unwrap();
    let curve = ClassACurve::try_from(&typical).unwrap();
    let m: Matrix3 = curve.matrix();
    // nalgebra's product as the independent oracle of the legs.
    let na = nalgebra::Matrix3::from_fn(|i, j| m[(i, j)]);
    let n = typical.degree;
    let mut legs = vec![typical.v0 * typical.length];
    for j in 1..n {
        legs.push(Vector3::from(na * nalgebra::Vector3::from(legs[j - 1])));
    }
    let points: Vec<Vector3> = (0..=n)
        .map(|i| typical.b0 + legs[..i].iter().sum::<Vector3>())
        .collect();
    let bernstein = |deg: usize, i: usize, u: f64| bez_core::bernstein(deg, i, u);
    let position = |u: f64| -> Vector3 { (0..=n).map(|i| points[i] * bernstein(n, i, u)).sum() };
    let velocity = |u: f64| -> Vector3 {
        (0..n)
            .map(|j| legs[j] * (n as f64 * bernstein(n - 1, j, u)))
            .sum()
    };
    assert_eq!(check_bezier_form(&curve, position, velocity, 1e-12), Ok(()));
    let direct = ClassACurve::new(&typical.b0, &(typical.v0 * typical.length), &m, n).unwrap();
    assert_eq!(direct, curve);
    assert!(ClassACurve::new(&typical.b0, &typical.v0, &m, 0).is_err());
}
