//! Spatial generation, log-spiral pole, logarithmic graphs.

use bez_core::{Vector2, Vector3};
use class_a::*;

#[test]
fn rotation_maps_v0_to_v1() {
    let a = cases::fig8_points();
    let c = TypicalSpatial::from_points(&a, 7).unwrap();
    let r = rotation(&c.axis, c.theta);
    let v1 = (a[3] - a[2]).normalize();
    let r = nalgebra::Matrix3::from_fn(|i, j| r[(i, j)]);
    assert!((Vector3::from(r.pow(6) * nalgebra::Vector3::from(c.v0)) - v1).norm() < 1e-12);
    assert!((c.axis.dot(&c.v0) - c.axis.dot(&v1)).abs() < 1e-12);
}

#[allow(
    clippy::unwrap_used,
    reason = "shared test check: a failure is a test failure"
)]
fn check(a: &[Vector3; 4], c: &TypicalSpatial) {
    let curve = c.curve().unwrap();
    let p = curve.points();
    let n = p.len() - 1;
    let scale = (a[3] - a[0]).norm();
    assert!((p[0] - a[0]).norm() <= 1e-9 * scale);
    assert!(
        (p[n] - a[3]).norm() <= 1e-9 * scale,
        "{}",
        (p[n] - a[3]).norm() / scale
    );
    assert!(((p[1] - p[0]).normalize() - (a[1] - a[0]).normalize()).norm() <= 1e-9);
    assert!(((p[n] - p[n - 1]).normalize() - (a[3] - a[2]).normalize()).norm() <= 1e-9);
}

#[test]
fn random_spatial_inputs_interpolate() {
    for (a, n) in cases::random_spatial_inputs(40, 11) {
        let c = TypicalSpatial::from_points(&a, n).unwrap();
        check(&a, &c);
        assert!(c.class_a_margin() >= 0.0, "{}", c.class_a_margin());
    }
}

#[test]
fn spatial_nelder_mead_runs() {
    let a = cases::fig8_points();
    let (c, cost) = TypicalSpatial::nelder_mead(&a, 7, 500).unwrap();
    assert!(cost < 1e-8, "{cost}");
    assert!(c.s > 0.0);
}

#[test]
fn spatial_bad_inputs() {
    let z = Vector3::zeros();
    let x = Vector3::new(1.0, 0.0, 0.0);
    assert!(matches!(
        TypicalSpatial::from_points(&[z, x, x * 2.0, x * 3.0], 5),
        Err(ClassAError::ParallelTangents { .. })
    ));
    assert!(matches!(
        TypicalSpatial::from_points(&[z, z, x, x * 3.0], 5),
        Err(ClassAError::CoincidentPoints { .. })
    ));
    assert!(matches!(
        TypicalSpatial::from_points(&cases::fig8_points(), 1),
        Err(ClassAError::DegreeTooLow { .. })
    ));
    let mut bad = cases::fig8_points();
    bad[2][1] = f64::NAN;
    assert!(matches!(
        TypicalSpatial::from_points(&bad, 5),
        Err(ClassAError::NonFinite { .. })
    ));
}

#[test]
fn pole_makes_similar_triangles_and_eq19_is_misprinted() {
    for (a, n) in cases::random_planar_inputs(50, 3) {
        let c = TypicalPlanar::from_points(&a[0], &a[1], &a[2], n).unwrap();
        let curve = c.curve().unwrap();
        let rho = log_spiral_pole(&c.b0(), &(c.mu() * c.length()), c.s(), c.theta()).unwrap();
        assert!(spiral_deviation(curve.points(), &rho, c.s(), c.theta()) < 1e-10);
        // Ratios and angles of triangles ρ bᵢ bᵢ₊₁ directly.
        let p = curve.points();
        for w in p.windows(2) {
            let (u, v) = (w[0] - rho, w[1] - rho);
            assert!((v.norm() / u.norm() - c.s()).abs() < 1e-10 * c.s());
            let ang = (u.x() * v.y() - u.y() * v.x()).atan2(u.dot(&v));
            assert!((ang - c.theta()).abs() < 1e-10);
        }
    }
    // Printed eq. (19): correct ρ_x, wrong ρ_y (with |Δb₀| = 1).
    let (b0, mu, s, th) = (Vector2::new(0.3, -0.2), Vector2::new(0.6, 0.8), 1.2, 0.3);
    let good = log_spiral_pole(&b0, &mu, s, th).unwrap();
    let printed = printed_pole_eq19(&b0, &mu, s, th);
    assert!((good.x() - printed.x()).abs() < 1e-12);
    assert!((good.y() - printed.y()).abs() > 0.1);
    assert!(matches!(
        log_spiral_pole(&b0, &mu, 1.0, 0.0),
        Err(ClassAError::NoPole { .. })
    ));
}

#[test]
fn lcg_of_log_spiral_and_clothoid() {
    // Log spiral: ρ = a·s (s arc length from the pole) ⇒ κ = 1/(a s), κ_s = −1/(a s²).
    let a = 0.3;
    let ls: Vec<(f64, f64)> = (1..50)
        .map(|i| {
            let s = 0.1 * i as f64;
            (1.0 / (a * s), -1.0 / (a * s * s))
        })
        .collect();
    let g = log_graph(&ls).unwrap();
    assert!((g.slope - 1.0).abs() < 1e-12 && g.straightness < 1e-12);
    // Clothoid: κ = c·s, κ_s = c.
    let cl: Vec<(f64, f64)> = (1..50).map(|i| (2.0 * 0.1 * i as f64, 2.0)).collect();
    let g = log_graph(&cl).unwrap();
    assert!((g.slope + 1.0).abs() < 1e-12 && g.straightness < 1e-12);
    assert!(matches!(
        log_graph(&[(1.0, 0.0)]),
        Err(ClassAError::TooFewSamples { .. })
    ));
}

#[test]
fn lcg_of_high_degree_typical_tends_to_slope_one() {
    // Typical planar curves tend to log spirals as n grows: the LCG slope tends to 1 and the
    // graph straightens (at n = 49 the slope is still about 0.74).
    let a = cases::fig6_points();
    let mut last = f64::INFINITY;
    for n in [49, 200, 1000] {
        let c = TypicalPlanar::from_points(&a[0], &a[1], &a[2], n).unwrap();
        let pts: Vec<(f64, f64)> = (0..=100)
            .filter_map(|i| c.log_curvature_point(i as f64 / 100.0))
            .collect();
        let g = log_graph_from_points(pts).unwrap();
        assert!((g.slope - 1.0).abs() < last, "{}", g.slope);
        last = (g.slope - 1.0).abs();
    }
    assert!(last < 0.02);
    // Closed form agrees with the generic formula at moderate degree.
    let c7 = TypicalPlanar::from_points(&a[0], &a[1], &a[2], 7).unwrap();
    let curve = c7.curve().unwrap();
    for t in [0.1, 0.5, 0.9] {
        let (k, ks) = curvature_with_derivative(&curve, t).unwrap();
        let (x, y) = c7.log_curvature_point(t).unwrap();
        assert!((x + k.ln()).abs() < 1e-9 && (y - (k / ks.abs()).ln()).abs() < 1e-8);
    }
}

#[test]
fn derivatives_match_finite_differences() {
    let c = class_a_curve(
        &Vector3::zeros(),
        &Vector3::new(1.0, 0.2, 0.3),
        &cases::fig5_matrix(),
        6,
    )
    .unwrap();
    let t = 0.4;
    let h = 1e-6;
    let (k, ks) = curvature_with_derivative(&c, t).unwrap();
    let (tau, taus) = torsion_with_derivative(&c, t).unwrap();
    assert!((k - c.curvature(t).unwrap()).abs() < 1e-12 * k.max(1.0));
    assert!((tau - c.torsion(t).unwrap()).abs() < 1e-9 * tau.abs().max(1e-9));
    let speed = c.derivative().unwrap().eval(t).unwrap().norm();
    let kd = (c.curvature(t + h).unwrap() - c.curvature(t - h).unwrap()) / (2.0 * h) / speed;
    let td = (c.torsion(t + h).unwrap() - c.torsion(t - h).unwrap()) / (2.0 * h) / speed;
    assert!((ks - kd).abs() < 1e-5 * ks.abs().max(1e-9), "{ks} {kd}");
    assert!(
        (taus - td).abs() < 1e-5 * taus.abs().max(1e-9),
        "{taus} {td}"
    );
}

#[test]
fn perturbed_matrices_are_checked() {
    let m = perturb2(&typical_matrix2(1.2, 0.2), [0.1; 4]);
    assert_eq!(m[(0, 1)], typical_matrix2(1.2, 0.2)[(0, 1)] + 0.1);
    let r = ClassAReport::of_2x2(&m).unwrap();
    assert!(r.farin3.margin.is_finite());
    let m3 = perturb3(&cases::fig5_matrix(), [0.0, 0.15, 0.0, 0.5]);
    assert_eq!(m3[(1, 1)], 2.63);
    assert_eq!(m3[(2, 2)], 2.21);
}

#[test]
fn figure_cases_build() {
    let c5 = cases::fig5_curve().unwrap();
    assert!(
        c5.torsion(0.5).unwrap().abs() > 1e-6,
        "Fig. 5 start vector must give a spatial curve"
    );
    let t6 = cases::fig6_typical().unwrap();
    assert!(cases::endpoint_error(&cases::fig6_points(), &t6.curve().unwrap()) < 1e-9);
    let (_, c7) = cases::fig7_general().unwrap();
    assert!(curvature_certificate(&c7).is_ok());
    let t8 = cases::fig8_typical().unwrap();
    assert!(cases::endpoint_error(&cases::fig8_points(), &t8.curve().unwrap()) < 1e-9);
    let (_, c9) = cases::fig9_general().unwrap();
    assert!(torsion_certificate(&c9).is_ok());
}

#[test]
fn unreachable_chord_is_reported() {
    let z = Vector3::zeros();
    let a = [
        z,
        Vector3::new(1.0, 0.0, 0.0),
        Vector3::new(-5.0, 1.0, 0.0),
        Vector3::new(-10.0, 0.0, 0.0),
    ];
    // A quadratic's chord lies between its end tangents: unreachable at n = 2.
    let e = TypicalSpatial::from_points(&a, 2).unwrap_err();
    assert!(matches!(e, ClassAError::ChordUnreachable { residual } if residual > 0.1));
    assert!(e.to_string().contains("chord direction"));
    // At n = 5 a Class A curve reaches it by turning its tangent by more than π (branch k ≠ 0).
    let t = TypicalSpatial::from_points(&a, 5).unwrap();
    assert!(4.0 * t.theta.abs() > std::f64::consts::PI && t.class_a_margin() >= 0.0);
    check(&a, &t);
}

#[test]
fn apollonius_construction_agrees_with_closed_form_pole() {
    for (a, n) in cases::random_planar_inputs(100, 9) {
        let c = TypicalPlanar::from_points(&a[0], &a[1], &a[2], n).unwrap();
        if (c.s() - 1.0).abs() < 1e-3 {
            continue;
        }
        let p = c.curve().unwrap().into_points();
        let rho = log_spiral_pole(&c.b0(), &(c.mu() * c.length()), c.s(), c.theta()).unwrap();
        let geo = apollonius_pole(&[p[0], p[1], p[2], p[3]]).unwrap();
        let scale = (p[1] - p[0]).norm() / (1.0 - c.s()).abs().max(1e-3);
        assert!(
            (geo - rho).norm() <= 1e-8 * scale,
            "{} vs scale {scale}",
            (geo - rho).norm()
        );
    }
    // s = 1: the circles are lines.
    let sq = [
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 0.0),
        Vector2::new(1.0, 1.0),
        Vector2::new(0.0, 1.0),
    ];
    assert!(matches!(
        apollonius_pole(&sq),
        Err(ClassAError::NoPole { .. })
    ));
    let mut bad = sq;
    bad[3][0] = f64::INFINITY;
    assert!(matches!(
        apollonius_pole(&bad),
        Err(ClassAError::NonFinite { .. })
    ));
}

#[test]
fn non_class_a_spatial_input_is_a_typed_error() {
    // Points of a typical spatial curve with s = 1: inside the forbidden band for every θ ≠ 0.
    let m = rotation(&Vector3::new(0.3, 0.2, 1.0).normalize(), 0.25);
    let c = class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.0, 0.2), &m, 6).unwrap();
    let p = c.points();
    let a = [p[0], p[1], p[5], p[6]];
    let e = TypicalSpatial::from_points(&a, 6).unwrap_err();
    match e {
        ClassAError::NoClassASolution {
            converged,
            best_margin,
            ..
        } => assert!(converged >= 1 && best_margin < 0.0),
        ref e => panic!("{e:?}"),
    }
    assert!(e.to_string().contains("no Class A"));
    // The candidates are still available, and include the generating curve.
    let all = TypicalSpatial::candidates(&a, 6).unwrap();
    assert!(all.iter().any(|t| (t.s - 1.0).abs() < 1e-9), "{all:?}");
    assert!(all.iter().all(|t| t.class_a_margin() < 0.0));
    check(&a, &all[0]);
}

#[test]
fn spatial_generation_reports_achieved_interpolation() {
    for (a, n) in cases::random_spatial_inputs(20, 3) {
        let (_, _, e) = TypicalSpatial::generate(&a, n, INTERPOLATION_TOLERANCE).unwrap();
        assert!(e.worst().1 <= INTERPOLATION_TOLERANCE, "{e:?}");
    }
    // An impossible tolerance is reported, not met silently.
    let a = cases::fig8_points();
    assert!(matches!(
        TypicalSpatial::generate(&a, 7, 0.0),
        Err(ClassAError::ToleranceNotMet { .. })
    ));
}
