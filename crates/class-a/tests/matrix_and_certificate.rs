//! Matrix conditions and monotonicity certificates.

use bez_core::{BezierCurve, Vector2, Vector3};
use class_a::*;
use proptest::prelude::*;

#[test]
fn report_of_known_matrices() {
    // Identity: every condition holds with margin 0.
    let r = ClassAReport::of_2x2(&Matrix2::identity()).unwrap();
    assert!(r.is_class_a());
    assert!(r.farin3.margin.abs() < 1e-15 && r.farin4.margin.abs() < 1e-15);
    // 2I: λ_min(4I − 2I) = 2; σ = 2: σ−1 = 1; σ² − σ = 2.
    let r = ClassAReport::of_3x3(&(Matrix3::identity() * 2.0)).unwrap();
    assert!((r.farin3.margin - 2.0).abs() < 1e-12);
    assert!((r.singular_values.margin - 1.0).abs() < 1e-12);
    assert!((r.farin4.margin - 2.0).abs() < 1e-12);
    // Scaled rotation: M + Mᵀ − 2I = (2s cos θ − 2)I.
    let (s, th) = (1.3, 0.4);
    let r = ClassAReport::of_2x2(&typical_matrix2(s, th)).unwrap();
    assert!((r.farin3.margin - (2.0 * s * th.cos() - 2.0)).abs() < 1e-12);
    // A shear that meets σ ≥ 1 but not Farin (3).
    let r = ClassAReport::of_2x2(&Matrix2::new(1.0, 3.0, 0.0, 1.0)).unwrap();
    assert!(!r.farin3.holds);
    assert!(ClassAReport::of_2x2(&Matrix2::new(f64::NAN, 0.0, 0.0, 1.0)).is_err());
    assert!(ClassAReport::of_3x3(&(Matrix3::identity() * f64::INFINITY)).is_err());
}

#[test]
fn fig5_matrix_is_class_a() {
    let r = ClassAReport::of_3x3(&cases::fig5_matrix()).unwrap();
    assert!(
        r.farin3.holds && r.singular_values.holds && r.farin4.holds,
        "{r:?}"
    );
}

#[test]
fn condition4_is_exact() {
    // Boundary s cos θ = 1 holds, slightly inside the band fails.
    let th: f64 = 0.3;
    assert!(typical_planar_margin(1.0 / th.cos(), th).abs() < 1e-15);
    assert!(typical_planar_margin(th.cos(), th).abs() < 1e-15);
    assert!(typical_planar_margin(1.0, th) < 0.0);
}

#[test]
fn certificate_matches_condition4_both_sides() {
    let th = 0.25;
    for (s, monotone) in [(1.2, true), (0.9, true), (1.0, false), (1.02, false)] {
        let c = class_a_curve(
            &Vector2::zeros(),
            &Vector2::new(1.0, 0.0),
            &typical_matrix2(s, th),
            6,
        )
        .unwrap();
        let cert = curvature_certificate(&c).unwrap();
        assert_eq!(cert.is_monotone(), monotone, "s = {s}: {cert:?}");
        assert_eq!(typical_planar_margin(s, th) >= 0.0, monotone);
    }
}

#[test]
fn certificate_finds_interior_extremum() {
    // A symmetric arch: curvature peaks at t = 1/2.
    let c = BezierCurve::new(vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 1.0),
        Vector2::new(2.0, 0.0),
    ])
    .unwrap();
    match curvature_certificate(&c).unwrap().verdict {
        Monotonicity::NotMonotone { extremum, .. } => assert!((extremum - 0.5).abs() < 1e-9),
        v => panic!("{v:?}"),
    }
    let line = BezierCurve::new(vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 0.0),
        Vector2::new(2.0, 0.0),
    ])
    .unwrap();
    assert_eq!(
        curvature_certificate(&line).unwrap().verdict,
        Monotonicity::Constant
    );
}

#[test]
fn certificate_errors() {
    let c = BezierCurve::new(vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0)]).unwrap();
    assert!(matches!(
        curvature_certificate(&c),
        Err(ClassAError::DegreeTooLow { .. })
    ));
    // A cusp at the dyadic parameter 1/2: x' = 0 there, proven exactly.
    let cusp = BezierCurve::new(vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 1.0),
        Vector2::new(0.0, 1.0),
        Vector2::new(1.0, 0.0),
    ])
    .unwrap();
    match curvature_certificate(&cusp) {
        Err(ClassAError::Singular { parameter, .. }) => assert_eq!(parameter, 0.5),
        r => panic!("{r:?}"),
    }
    let q = BezierCurve::new(vec![
        Vector3::zeros(),
        Vector3::new(1.0, 0.0, 0.0),
        Vector3::new(0.0, 1.0, 0.0),
    ])
    .unwrap();
    assert!(matches!(
        torsion_certificate(&q),
        Err(ClassAError::DegreeTooLow { .. })
    ));
}

#[test]
fn helix_like_spatial_typical_has_constant_torsion_sign() {
    // s = 1 with a rotation: control points on a helix-like polygon; the torsion certificate
    // must agree with dense sampling.
    let m = rotation(&Vector3::new(0.0, 0.0, 1.0), 0.3) * 1.15;
    let c = class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.0, 0.4), &m, 7).unwrap();
    let cert = torsion_certificate(&c).unwrap();
    let samples = torsion_samples(&c, 400).unwrap();
    let incr = samples.windows(2).all(|w| w[1].0 >= w[0].0 - 1e-12);
    let decr = samples.windows(2).all(|w| w[1].0 <= w[0].0 + 1e-12);
    assert_eq!(cert.is_monotone(), incr || decr, "{:?}", cert.verdict);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn typical_curves_pass_and_are_monotone(s in 0.5f64..2.0, th in -0.5f64..0.5, n in 3usize..10) {
        prop_assume!(typical_planar_margin(s, th) >= 1e-3 && th.abs() > 1e-3);
        let m = typical_matrix2(s, th);
        let c = class_a_curve(&Vector2::zeros(), &Vector2::new(0.7, 0.2), &m, n).unwrap();
        // Forward matrix test when s > 1, reversed (M⁻¹) when s < 1.
        let report = if s > 1.0 { ClassAReport::of_2x2(&m) } else { ClassAReport::of_2x2(&typical_matrix2(1.0 / s, -th)) }.unwrap();
        prop_assert!(report.farin3.holds);
        let cert = curvature_certificate(&c).unwrap();
        prop_assert!(cert.is_monotone());
        // Dense sampling agrees.
        let ks: Vec<f64> = (0..=200).map(|i| c.curvature(i as f64 / 200.0).unwrap()).collect();
        let incr = ks.windows(2).all(|w| w[1] >= w[0] * (1.0 - 1e-9));
        let decr = ks.windows(2).all(|w| w[1] <= w[0] * (1.0 + 1e-9));
        prop_assert!(incr || decr);
        // Closed-form curvature agrees with the kernel's.
        let tp = TypicalPlanar::new(Vector2::zeros(), Vector2::new(0.7, 0.2).normalize(), Vector2::new(0.7f64, 0.2).norm(), s, th, n).unwrap();
        for t in [0.0, 0.3, 1.0] {
            let k = c.signed_curvature(t).unwrap();
            prop_assert!((tp.curvature(t) - k).abs() <= 1e-9 * k.abs().max(1e-12));
        }
    }
}

#[test]
fn farin_conditions_do_not_imply_monotone_curvature() {
    // Cao & Wang's point: a matrix meeting Farin's (3) and (4) whose curve has an interior
    // curvature extremum. The certificate finds it; dense sampling confirms it.
    let found = cases::farin_counterexample_search(3000, 1);
    let (m, v, n, e) = found
        .first
        .expect("the seeded search finds a counterexample");
    let r = ClassAReport::of_2x2(&m).unwrap();
    assert!(r.farin3.holds && r.farin4.holds);
    let c = class_a_curve(&Vector2::zeros(), &v, &m, n).unwrap();
    let k = |t: f64| c.curvature(t).unwrap();
    let h = (e.min(1.0 - e) / 2.0).min(1e-3);
    let (a, b) = (k(e) - k(e - h), k(e + h) - k(e));
    assert!(a * b < 0.0, "extremum at {e}: {a} {b}");
}

mod certificate_vs_sampling {
    use super::*;
    use bez_core::proptest_support;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// A "monotone" verdict is never contradicted by dense sampling, and a reported extremum is
        /// a local extremum (regular curves only).
        #[test]
        fn monotone_verdict_holds_on_samples(c in proptest_support::curve::<2>(2..=6, 10.0)) {
            let speed_ok = (0..=400).all(|i| c.derivative().unwrap().eval(i as f64 / 400.0).map(|d| d.norm() > 1e-3).unwrap_or(false));
            prop_assume!(speed_ok);
            let cert = curvature_certificate(&c).unwrap();
            let ks: Vec<f64> = (0..=400).map(|i| c.curvature(i as f64 / 400.0).unwrap()).collect();
            let scale = ks.iter().fold(0.0f64, |m, k| m.max(*k));
            let tol = 1e-9 * scale;
            match cert.verdict {
                Monotonicity::Increasing => prop_assert!(ks.windows(2).all(|w| w[1] >= w[0] - tol)),
                Monotonicity::Decreasing => prop_assert!(ks.windows(2).all(|w| w[1] <= w[0] + tol)),
                Monotonicity::Constant => prop_assert!(ks.windows(2).all(|w| (w[1] - w[0]).abs() <= tol)),
                Monotonicity::Undecided { .. } => prop_assert!(false, "undecided: {cert:?}"),
                Monotonicity::NotMonotone { extremum: e, .. } => {
                    prop_assert!(e > 0.0 && e < 1.0);
                    // A local extremum of κ: the one-sided differences do not share a sign.
                    let h = (e.min(1.0 - e) / 2.0).min(1e-4);
                    let k = |t: f64| c.curvature(t).unwrap();
                    prop_assert!((k(e) - k(e - h)) * (k(e + h) - k(e)) <= tol * tol);
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    /// The crate's Jacobi eigenvalues and singular values against nalgebra's (an independent
    /// implementation), plus the invariants Σσ² = ‖M‖²_F and Πσ = |det M|.
    #[test]
    fn small_matrix_spectra_match_nalgebra(e in proptest::collection::vec(-3.0f64..3.0, 9)) {
        let m3 = Matrix3::from_rows([[e[0], e[1], e[2]], [e[3], e[4], e[5]], [e[6], e[7], e[8]]]);
        let n3 = nalgebra::Matrix3::from_fn(|i, j| m3[(i, j)]);
        let mut sv: Vec<f64> = n3.singular_values().iter().copied().collect();
        sv.sort_by(f64::total_cmp);
        let ours = m3.singular_values();
        for (a, b) in ours.iter().zip(&sv) {
            prop_assert!((a - b).abs() <= 1e-13 * sv[2], "{ours:?} vs {sv:?}");
        }
        let frob: f64 = m3.iter().map(|x| x * x).sum();
        prop_assert!((ours.iter().map(|s| s * s).sum::<f64>() - frob).abs() <= 1e-12 * frob);
        prop_assert!((ours.iter().product::<f64>() - m3.determinant().abs()).abs() <= 1e-12 * (1.0 + frob * frob));
        let sym = (n3 + n3.transpose()) * 0.5;
        let mut ev: Vec<f64> = sym.symmetric_eigenvalues().iter().copied().collect();
        ev.sort_by(f64::total_cmp);
        let ours = m3.symmetric_eigenvalues();
        for (a, b) in ours.iter().zip(&ev) {
            prop_assert!((a - b).abs() <= 1e-13 * (1.0 + ev[0].abs().max(ev[2].abs())), "{ours:?} vs {ev:?}");
        }
        let m2 = Matrix2::new(e[0], e[1], e[2], e[3]);
        let n2 = nalgebra::Matrix2::new(e[0], e[1], e[2], e[3]);
        let mut sv: Vec<f64> = n2.singular_values().iter().copied().collect();
        sv.sort_by(f64::total_cmp);
        let ours = m2.singular_values();
        prop_assert!((ours[0] - sv[0]).abs() <= 1e-13 * sv[1] && (ours[1] - sv[1]).abs() <= 1e-13 * sv[1]);
        prop_assert_eq!(m2.determinant(), n2.determinant());
        if let Some(inv) = m2.try_inverse() {
            let id = m2 * inv;
            let cond = sv[1] / sv[0];
            for (i, j) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                let want = if i == j { 1.0 } else { 0.0 };
                prop_assert!((id[(i, j)] - want).abs() <= 1e-14 * cond, "{id:?}");
            }
        }
    }
}

#[test]
fn scaled_rotations_have_equal_singular_values() {
    for (s, th) in [(1.0, 0.3), (2.5, -1.2), (0.1, 3.0)] {
        let sv = typical_matrix2(s, th).singular_values();
        assert!((sv[0] - s).abs() < 1e-15 * s.max(1.0) && (sv[1] - s).abs() < 1e-15 * s.max(1.0));
        let r = rotation(&Vector3::new(0.0, 0.6, 0.8), th) * s;
        for x in r.singular_values() {
            assert!((x - s).abs() < 1e-14 * s.max(1.0), "{x} vs {s}");
        }
        assert!((r.determinant() - s * s * s).abs() < 1e-13 * s.max(1.0).powi(3));
    }
}
