//! The exact monotonicity certificates: hand-computed numerators, agreement with the exact
//! condition (4), with the derivative of κ² and with dense sampling, at low and high degree.

use bez_core::{BezierCurve, Vector2, Vector3};
use class_a::*;
use num_bigint::BigInt;
use num_traits::ToPrimitive;
use proptest::prelude::*;

#[allow(
    clippy::unwrap_used,
    clippy::panic,
    reason = "shared test helper: a failure is a test failure"
)]
/// f64 value of Σ aₖ tᵏ(1 − t)ᴺ⁻ᵏ (test helper; coefficients must fit in f64).
fn eval(p: &ScaledBernstein, t: f64) -> f64 {
    let n = p.degree() as i32;
    p.coefficients()
        .iter()
        .enumerate()
        .map(|(k, a)| a.to_f64().unwrap() * t.powi(k as i32) * (1.0 - t).powi(n - k as i32))
        .sum()
}

#[test]
fn arch_numerator_by_hand() {
    // x = (2t, 2t − 2t²): x' = (2, 2 − 4t), x'' = (0, −4), P = 4 + (2 − 4t)², G = 64,
    // N = G'P − 3GP' = −192·(−16 + 32t) = 3072(1 − 2t) = 3072[(1−t)³ + t(1−t)² − t²(1−t) − t³].
    let c = BezierCurve::new(vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 1.0),
        Vector2::new(2.0, 0.0),
    ])
    .unwrap();
    let (num, p) = curvature_numerator(&c).unwrap();
    let want: Vec<BigInt> = [3072, 3072, -3072, -3072].map(BigInt::from).to_vec();
    assert_eq!(num.coefficients(), want.as_slice());
    assert_eq!(p.coefficients(), [8, 0, 8].map(BigInt::from).as_slice());
    let cert = curvature_certificate(&c).unwrap();
    assert!(!cert.by_coefficient_signs);
    match cert.verdict {
        Monotonicity::NotMonotone { extremum, bracket } => {
            assert!(bracket.0 < 0.5 && 0.5 < bracket.1 && bracket.1 - bracket.0 < 1e-11);
            assert!((extremum - 0.5).abs() < 1e-11);
        }
        v => panic!("{v:?}"),
    }
}

#[test]
fn helix_cubic_torsion_numerator_by_hand() {
    // x = (t, t², t³)·(3 legs of the cubic with points 0, (1/3,0,0), (2/3,1/3,0), (1,1,1)):
    // x' = (1, 2t, 3t²), x'' = (0, 2, 6t), x''' = (0, 0, 6): Δ = 12, G = 4(9t⁴ + 9t² + 1),
    // N = Δ'G − ΔG' = −12·4(36t³ + 18t) < 0 on (0, 1], zero at t = 0: torsion decreases.
    let c = BezierCurve::new(vec![
        Vector3::zeros(),
        Vector3::new(1.0 / 3.0, 0.0, 0.0),
        Vector3::new(2.0 / 3.0, 1.0 / 3.0, 0.0),
        Vector3::new(1.0, 1.0, 1.0),
    ])
    .unwrap();
    let (num, g) = torsion_numerator(&c).unwrap();
    assert_eq!(num.degree(), 8);
    // Ratios to the hand formulas are one positive constant (coordinates scaled exactly).
    let r_num = eval(&num, 0.5) / (-48.0 * (36.0 * 0.125 + 18.0 * 0.5));
    let r_g = eval(&g, 0.5) / (4.0 * (9.0 / 16.0 + 9.0 / 4.0 + 1.0));
    assert!(r_num > 0.0 && r_g > 0.0);
    for t in [0.1f64, 0.3, 0.7, 1.0] {
        let n_hand = -48.0 * (36.0 * t * t * t + 18.0 * t);
        let g_hand = 4.0 * (9.0 * t.powi(4) + 9.0 * t * t + 1.0);
        assert!((eval(&num, t) - r_num * n_hand).abs() <= 1e-12 * (r_num * n_hand).abs());
        assert!((eval(&g, t) - r_g * g_hand).abs() <= 1e-12 * (r_g * g_hand).abs());
    }
    assert_eq!(
        torsion_certificate(&c).unwrap().verdict,
        Monotonicity::Decreasing
    );
}

#[allow(
    clippy::unwrap_used,
    clippy::panic,
    reason = "shared test helper: a failure is a test failure"
)]
fn typical(s: f64, th: f64, n: usize) -> BezierCurve<2> {
    class_a_curve(
        &Vector2::new(0.3, -0.2),
        &Vector2::new(0.7, 0.2),
        &typical_matrix2(s, th),
        n,
    )
    .unwrap()
}

#[test]
fn typical_curves_near_the_boundaries_of_condition4() {
    for th in [0.05f64, 0.3, 0.9, -0.6] {
        let c = th.cos();
        for n in [3, 8, 20] {
            for rel in [1e-6, -1e-6, 1e-3, -1e-3] {
                for s in [(1.0 + rel) / c, c * (1.0 - rel)] {
                    let m = typical_planar_margin(s, th);
                    let cert = curvature_certificate(&typical(s, th, n)).unwrap();
                    assert_eq!(cert.is_monotone(), m >= 0.0, "s {s} θ {th} n {n}: {cert:?}");
                    if m < 0.0 {
                        assert!(matches!(cert.verdict, Monotonicity::NotMonotone { .. }));
                    }
                }
            }
            // Exactly on the boundary the rounded control points may fall on either side:
            // a monotone verdict, or an extremum within rounding of an end.
            for s in [1.0 / c, c] {
                let cert = curvature_certificate(&typical(s, th, n)).unwrap();
                match cert.verdict {
                    Monotonicity::NotMonotone { extremum, .. } => {
                        assert!(extremum.min(1.0 - extremum) < 1e-9, "{cert:?}");
                    }
                    Monotonicity::Undecided { interval, .. } => {
                        assert!(interval.0.min(1.0 - interval.1) < 1e-9, "{cert:?}");
                    }
                    _ => assert!(cert.is_monotone()),
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// The certificate of a typical planar curve agrees with the exact condition (4) whenever
    /// the margin exceeds the rounding of the control points.
    #[test]
    fn typical_certificate_equals_condition4(s in 0.3f64..3.0, th in -1.3f64..1.3, n in 2usize..14) {
        prop_assume!(th.abs() > 1e-3);
        let m = typical_planar_margin(s, th);
        prop_assume!(m.abs() > 1e-9);
        let cert = curvature_certificate(&typical(s, th, n)).unwrap();
        prop_assert_eq!(cert.is_monotone(), m >= 0.0, "{:?}", cert);
    }

    /// N/P⁴ is a positive constant times d(κ²)/dt (central differences): a wrong sign or
    /// factor in G'P − 3GP' fails.
    #[test]
    fn numerator_is_derivative_of_kappa_squared(c in bez_core::proptest_support::curve::<3>(2..=6, 5.0)) {
        let speed_ok = (0..=100).all(|i| c.derivative().unwrap().eval(i as f64 / 100.0).map(|d| d.norm() > 1e-2).unwrap_or(false));
        prop_assume!(speed_ok);
        let (num, p) = curvature_numerator(&c).unwrap();
        let k2 = |t: f64| c.curvature(t).unwrap().powi(2);
        let h = 1e-5;
        let ts: Vec<f64> = (1..10).map(|i| i as f64 / 10.0).collect();
        let fd: Vec<f64> = ts.iter().map(|&t| (k2(t + h) - k2(t - h)) / (2.0 * h)).collect();
        let ex: Vec<f64> = ts.iter().map(|&t| eval(&num, t) / eval(&p, t).powi(4)).collect();
        let i = (0..ts.len()).max_by(|&a, &b| fd[a].abs().total_cmp(&fd[b].abs())).unwrap();
        prop_assume!(fd[i].abs() > 1e-6);
        let r = ex[i] / fd[i];
        prop_assert!(r > 0.0);
        let scale = fd[i].abs();
        for (e, f) in ex.iter().zip(&fd) {
            prop_assert!((e / r - f).abs() <= 1e-4 * scale, "{} vs {}", e / r, f);
        }
    }
}

#[allow(
    clippy::unwrap_used,
    clippy::panic,
    reason = "shared test helper: a failure is a test failure"
)]
/// Checks a verdict against dense sampling of κ or τ.
fn agrees_with_samples(verdict: Monotonicity, values: &[f64]) {
    let scale = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let tol = 1e-9 * scale;
    match verdict {
        Monotonicity::Increasing => assert!(values.windows(2).all(|w| w[1] >= w[0] - tol)),
        Monotonicity::Decreasing => assert!(values.windows(2).all(|w| w[1] <= w[0] + tol)),
        v => panic!("expected a monotone verdict, got {v:?}"),
    }
}

#[test]
fn degree_49_planar_typical_and_general() {
    let t = cases::fig6_typical().unwrap();
    let c = t.curve().unwrap();
    let cert = curvature_certificate(&c).unwrap();
    assert!(t.margin() > 0.0);
    // Curvature of the typical curve from its closed form (accurate at n = 49).
    let ks: Vec<f64> = (0..=2000)
        .map(|i| t.curvature(i as f64 / 2000.0).abs())
        .collect();
    agrees_with_samples(cert.verdict, &ks);
    // A general curve: the typical matrix perturbed; its verdict is checked by sampling.
    let g = class_a_curve(
        &t.b0(),
        &(t.mu() * t.length()),
        &perturb2(&t.matrix(), [2e-3, -1e-3, 0.0, 1e-3]),
        49,
    )
    .unwrap();
    assert_eq!(g.degree(), 49);
    let cert = curvature_certificate(&g).unwrap();
    let ks: Vec<f64> = (0..=2000)
        .map(|i| g.curvature(i as f64 / 2000.0).unwrap())
        .collect();
    match cert.verdict {
        Monotonicity::NotMonotone { extremum: e, .. } => {
            let k = |t: f64| g.curvature(t).unwrap();
            let h = (e.min(1.0 - e) / 2.0).min(1e-4);
            assert!((k(e) - k(e - h)) * (k(e + h) - k(e)) < 0.0);
        }
        v => agrees_with_samples(v, &ks),
    }
}

#[test]
fn degree_30_spatial_typical() {
    let t = TypicalSpatial::from_points(&cases::fig8_points(), 30).unwrap();
    let c = t.curve().unwrap();
    let kc = curvature_certificate(&c).unwrap();
    let ks: Vec<f64> = curvature_samples(&c, 1500)
        .unwrap()
        .iter()
        .map(|x| x.0)
        .collect();
    agrees_with_samples(kc.verdict, &ks);
    let tc = torsion_certificate(&c).unwrap();
    let ts: Vec<f64> = torsion_samples(&c, 1500)
        .unwrap()
        .iter()
        .map(|x| x.0)
        .collect();
    agrees_with_samples(tc.verdict, &ts);
}

#[test]
fn undecided_is_reported_not_guessed() {
    // x' = 0 at t = 1/3 (not dyadic): regularity can be neither proven nor refuted exactly.
    let f = |t: f64| Vector2::new((3.0 * t - 1.0).powi(3), (3.0 * t - 1.0).powi(2));
    // x = ((3t − 1)³, (3t − 1)²): Bézier points from the blossom of the power form.
    let c = BezierCurve::new(vec![
        Vector2::new(-1.0, 1.0),
        Vector2::new(2.0, -1.0),
        Vector2::new(-4.0, 0.0),
        Vector2::new(8.0, 4.0),
    ])
    .unwrap();
    for t in [0.0, 0.2, 0.7, 1.0] {
        assert!((c.eval(t).unwrap() - f(t)).norm() < 1e-12);
    }
    match curvature_certificate(&c).unwrap().verdict {
        Monotonicity::Undecided {
            cause: UndecidedCause::Regularity,
            interval,
        } => assert!(interval.0 <= 1.0 / 3.0 && 1.0 / 3.0 <= interval.1),
        v => panic!("{v:?}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    /// Torsion verdicts on random spatial curves agree with dense sampling; a reported extremum
    /// is a local extremum of τ.
    #[test]
    fn torsion_verdict_holds_on_samples(c in bez_core::proptest_support::curve::<3>(3..=6, 5.0)) {
        let tau = |t: f64| torsion_with_derivative(&c, t).map(|x| x.0);
        let regular = (0..=400).all(|i| {
            let t = i as f64 / 400.0;
            match (c.derivative().unwrap().eval(t), c.derivative().unwrap().derivative().unwrap().eval(t)) {
                (Ok(d1), Ok(d2)) => d1.cross(&d2).norm() > 1e-2,
                _ => false,
            }
        });
        prop_assume!(regular);
        let cert = torsion_certificate(&c).unwrap();
        let ts: Vec<f64> = (0..=400).map(|i| tau(i as f64 / 400.0).unwrap()).collect();
        let scale = ts.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let tol = 1e-9 * scale;
        match cert.verdict {
            Monotonicity::Increasing => prop_assert!(ts.windows(2).all(|w| w[1] >= w[0] - tol)),
            Monotonicity::Decreasing => prop_assert!(ts.windows(2).all(|w| w[1] <= w[0] + tol)),
            Monotonicity::Constant => prop_assert!(ts.windows(2).all(|w| (w[1] - w[0]).abs() <= tol)),
            Monotonicity::Undecided { .. } => prop_assert!(false, "undecided: {cert:?}"),
            Monotonicity::NotMonotone { extremum: e, bracket } => {
                prop_assert!(bracket.0 <= e && e <= bracket.1 && bracket.1 - bracket.0 < 1e-11);
                let h = (e.min(1.0 - e) / 2.0).min(1e-4);
                let (a, b) = (tau(e).unwrap() - tau(e - h).unwrap(), tau(e + h).unwrap() - tau(e).unwrap());
                prop_assert!(a * b <= tol * tol, "{a} {b}");
            }
        }
    }
}
