//! Spatial end curvatures in closed form, the spatial G2 Hermite solve and spatial splines,
//! against independent oracles: control-point differences, bez-core's derivative evaluation
//! (curvature, torsion, tangent and binormal at the ends) and the certificates run again.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, BezierForm, Vector3};
use class_a::{
    ClassAError, INTERPOLATION_TOLERANCE, SpatialClassASpline, SpatialKnot, TypicalSpatial,
    curvature_certificate, end_curvatures_torsions, hermite_spatial, rotation, torsion_certificate,
};
use proptest::prelude::*;

#[path = "common/spatial_g2.rs"]
mod spatial_g2;
use spatial_g2::spiral_knots;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// A unit vector from spherical angles.
fn unit(polar: f64, azimuth: f64) -> Vector3 {
    Vector3::new(
        polar.sin() * azimuth.cos(),
        polar.sin() * azimuth.sin(),
        polar.cos(),
    )
}

/// A typical spatial curve with the given parameters (b₀ = 0).
fn typical(
    n: usize,
    s: f64,
    theta: f64,
    axis: Vector3,
    v0: Vector3,
    length: f64,
) -> TypicalSpatial {
    TypicalSpatial {
        b0: Vector3::zeros(),
        v0,
        length,
        s,
        phi: 0.0,
        axis,
        theta,
        degree: n,
    }
}

/// Unit tangent, curvature, unit binormal and torsion at t by bez-core's derivatives.
fn frame_at(c: &BezierCurve<3>, t: f64) -> (Vector3, f64, Vector3, f64) {
    let d = c.eval_derivatives(t, 2).unwrap();
    let b = d[1].cross(&d[2]);
    (
        d[1] / d[1].norm(),
        c.curvature(t).unwrap(),
        b / b.norm(),
        c.torsion(t).unwrap(),
    )
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1e-300)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// The closed forms agree with the control-point differences of the generated curve and
    /// with bez-core's evaluation of κ and τ at t = 0 and 1.
    #[test]
    fn closed_form_end_curvatures_match_the_control_points(
        n in 3usize..25,
        log_s in -0.08f64..0.08,
        theta in 0.02f64..1.4,
        negative in any::<bool>(),
        (ap, aa) in (0.0f64..PI, 0.0f64..TAU),
        (vp, va) in (0.0f64..PI, 0.0f64..TAU),
        length in 0.1f64..10.0,
    ) {
        let (axis, v0) = (unit(ap, aa), unit(vp, va));
        // Control-point differences lose about ε/θ³ of τ: |θ| ≥ 0.02 keeps the oracle accurate.
        let theta = if negative { -theta } else { theta };
        let s = log_s.exp();
        let t = typical(n, s, theta, axis, v0, length);
        let closed = t.end_curvatures_torsions().unwrap();
        let curve = t.curve().unwrap();
        let points = end_curvatures_torsions(&curve);
        prop_assume!(points.is_ok());
        let points = points.unwrap();
        for (end, (c, p)) in closed.iter().zip(&points).enumerate() {
            prop_assert!(close(c.0, p.0, 1e-9), "κ({end}): {} vs {}", c.0, p.0);
            // Torsion: relative to the curvature's scale (τ → 0 as the axis turns normal to v₀).
            prop_assert!((c.1 - p.1).abs() <= 1e-8 * (p.1.abs() + p.0), "τ({end}): {} vs {}", c.1, p.1);
            let (_, k, _, tau) = frame_at(&curve, end as f64);
            prop_assert!(close(c.0, k, 1e-7), "κ({end}) bez-core: {} vs {k}", c.0);
            prop_assert!((c.1 - tau).abs() <= 1e-6 * (tau.abs() + k), "τ({end}) bez-core: {} vs {tau}", c.1);
        }
        // τ/κ is the same at both ends.
        if closed[0].0 > 0.0 && closed[1].0 > 0.0 {
            let (r0, r1) = (closed[0].1 / closed[0].0, closed[1].1 / closed[1].0);
            prop_assert!((r0 - r1).abs() <= 1e-12 * (r0.abs() + 1.0));
        }
    }
}

#[test]
fn closed_form_special_cases() {
    // A planar curve (axis normal to v₀): the planar formula, zero torsion.
    let t = typical(
        7,
        1.2,
        0.3,
        Vector3::new(0.0, 0.0, 1.0),
        Vector3::new(1.0, 0.0, 0.0),
        2.0,
    );
    let [(k0, t0), (k1, t1)] = t.end_curvatures_torsions().unwrap();
    let want0 = 6.0 * 1.2 * 0.3f64.sin() / (7.0 * 2.0);
    assert!(close(k0, want0, 1e-14) && close(k1, want0 / 1.2f64.powi(8), 1e-13));
    assert!(t0 == 0.0 && t1 == 0.0);
    // A right-handed rotation about an axis along +v₀ component winds right-handed: τ > 0.
    let t = typical(
        5,
        1.0,
        0.4,
        unit(0.5, 0.0),
        Vector3::new(0.0, 0.0, 1.0),
        1.0,
    );
    let [(_, tau0), _] = t.end_curvatures_torsions().unwrap();
    let [(_, p0), _] = end_curvatures_torsions(&t.curve().unwrap()).unwrap();
    assert!(tau0 > 0.0 && close(tau0, p0, 1e-9));
    // Invalid fields are errors, not NaN.
    let mut bad = t;
    bad.s = -1.0;
    assert!(matches!(
        bad.end_curvatures_torsions(),
        Err(ClassAError::InvalidParameter { name: "s", .. })
    ));
    bad = t;
    bad.axis = Vector3::new(0.0, 0.0, 2.0);
    assert!(matches!(
        bad.end_curvatures_torsions(),
        Err(ClassAError::InvalidParameter { .. })
    ));
    bad = t;
    bad.theta = f64::NAN;
    assert!(matches!(
        bad.end_curvatures_torsions(),
        Err(ClassAError::NonFinite { .. })
    ));
}

/// G1 data (the knots) of a Class A typical spatial curve with monotone torsion.
fn g1_knots(n: usize, s: f64, theta: f64, axis: Vector3) -> (SpatialKnot, SpatialKnot) {
    let v0 = Vector3::new(1.0, 0.0, 0.0);
    let t = typical(n, s, theta, axis, v0, 1.0);
    let c = t.curve().unwrap();
    let p = c.points();
    (
        SpatialKnot::new(p[0], p[1] - p[0]),
        SpatialKnot::new(p[n], p[n] - p[n - 1]),
    )
}

/// Every condition of an `Ok` of [`hermite_spatial`], checked by bez-core's evaluation and the
/// certificates run again.
fn assert_meets(c: &BezierCurve<3>, start: &SpatialKnot, end: &SpatialKnot) {
    let chord = (end.point - start.point).norm();
    assert!((c.start() - start.point).norm() <= 1e-12 * chord);
    assert!((c.end() - end.point).norm() <= INTERPOLATION_TOLERANCE * chord);
    for (knot, t) in [(start, 0.0), (end, 1.0)] {
        let (tangent, k, b, _) = frame_at(c, t);
        let want = knot.tangent / knot.tangent.norm();
        assert!((tangent - want).norm() <= 2e-9, "tangent at {t}");
        if let Some(kappa) = knot.curvature {
            assert!(close(k, kappa, 1e-8), "curvature at {t}: {k} vs {kappa}");
        }
        if let Some(binormal) = knot.binormal {
            let want = binormal - want * binormal.dot(&want);
            assert!((b - want / want.norm()).norm() <= 2e-9, "binormal at {t}");
        }
    }
    assert!(curvature_certificate(c).unwrap().is_monotone());
    assert!(torsion_certificate(c).unwrap().is_monotone());
}

#[test]
fn g1_is_the_typical_curve_and_proven() {
    let (start, end) = g1_knots(7, 1.15, 0.35, unit(0.6, 0.3));
    let c = hermite_spatial(&start, &end, 7).unwrap();
    assert_meets(c.as_bezier(), &start, &end);
}

#[test]
fn g2_reaches_targets_near_the_typical_pair() {
    let mut tried = 0;
    let mut reached = 0;
    for n in [4usize, 6, 9] {
        for (s, theta) in [(1.12, 0.3), (0.85, -0.35), (1.3, 0.5)] {
            for axis in [unit(0.4, 0.2), unit(1.0, 2.0)] {
                let (start, end) = g1_knots(n, s, theta, axis);
                let g1 = hermite_spatial(&start, &end, n);
                let Ok(g1) = g1 else { continue };
                let [(k0, _), (k1, _)] = end_curvatures_torsions(g1.as_bezier()).unwrap();
                for (f0, f1) in [(1.05, 1.0), (1.0, 1.05), (0.95, 1.05), (1.05, 0.95)] {
                    tried += 1;
                    let (a, b) = (start.with_curvature(k0 * f0), end.with_curvature(k1 * f1));
                    if let Ok(c) = hermite_spatial(&a, &b, n) {
                        reached += 1;
                        assert_meets(c.as_bezier(), &a, &b);
                    }
                }
            }
        }
    }
    assert!(tried >= 48, "{tried}");
    assert!(reached * 10 >= tried * 7, "reached {reached} of {tried}");
}

#[test]
fn g2_with_binormals_is_met() {
    // G1 data of a typical curve turning by 2 rad at degree 7 (as in the example's reach table).
    let theta = 2.0 / 6.0;
    let (start, end) = g1_knots(
        7,
        1.0 / (2.0 * f64::cos(theta) - 1.0) + 0.1,
        theta,
        unit(FRAC_PI_2 - 0.8, 0.0),
    );
    let g1 = hermite_spatial(&start, &end, 7).unwrap();
    let c = g1.as_bezier();
    let (t0, k0, b0, _) = frame_at(c, 0.0);
    let (t1, k1, b1, _) = frame_at(c, 1.0);
    // Turn both osculating planes by 0.03 rad about the tangents, curvatures kept.
    let a = start
        .with_curvature(k0)
        .with_binormal(rotation(&t0, 0.03) * b0);
    let b = end
        .with_curvature(k1)
        .with_binormal(rotation(&t1, 0.03) * b1);
    let g2 = hermite_spatial(&a, &b, 7).unwrap();
    assert_meets(g2.as_bezier(), &a, &b);
}

/// Where a solution is known (a perturbed typical curve with proven monotone curvature and
/// torsion), its full G2 data (curvatures and binormals at both ends) are met.
#[test]
fn g2_data_of_known_curves_are_met() {
    let mut known = 0;
    let mut met = 0;
    for (i, n) in [4usize, 5, 6, 7, 8].into_iter().enumerate() {
        for j in 0..6 {
            let t = typical(
                n,
                0.9 + 0.08 * j as f64,
                0.2 + 0.05 * i as f64,
                unit(0.3 + 0.2 * j as f64, 0.5 * i as f64),
                Vector3::new(1.0, 0.0, 0.0),
                1.0,
            );
            let delta = [0.02, -0.01, 0.015, 0.01, -0.02, 0.0, 0.01, 0.0, -0.01];
            let mut m = t.matrix();
            for r in 0..3 {
                for c in 0..3 {
                    m[(r, c)] += delta[3 * r + c] * if j % 2 == 0 { 1.0 } else { -1.0 };
                }
            }
            let curve =
                class_a::class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.0, 0.0), &m, n)
                    .unwrap();
            let proven = curvature_certificate(&curve).is_ok_and(|c| c.is_monotone())
                && torsion_certificate(&curve).is_ok_and(|c| c.is_monotone());
            if !proven {
                continue;
            }
            known += 1;
            let p = curve.points();
            let (_, k0, b0, _) = frame_at(&curve, 0.0);
            let (_, k1, b1, _) = frame_at(&curve, 1.0);
            let a = SpatialKnot::new(p[0], p[1] - p[0])
                .with_curvature(k0)
                .with_binormal(b0);
            let b = SpatialKnot::new(p[n], p[n] - p[n - 1])
                .with_curvature(k1)
                .with_binormal(b1);
            if let Ok(c) = hermite_spatial(&a, &b, n) {
                met += 1;
                assert_meets(c.as_bezier(), &a, &b);
            }
        }
    }
    assert!(known >= 20, "{known}");
    assert!(met * 10 >= known * 8, "met {met} of {known}");
}

#[test]
fn g2_errors_are_typed() {
    let (start, end) = g1_knots(6, 1.15, 0.35, unit(0.6, 0.3));
    assert!(matches!(
        hermite_spatial(&start.with_curvature(-1.0), &end.with_curvature(1.0), 6),
        Err(ClassAError::CurvatureUnreachable { end: "start", .. })
    ));
    assert!(matches!(
        hermite_spatial(&start.with_curvature(1.0), &end, 6),
        Err(ClassAError::InvalidParameter {
            name: "curvature",
            ..
        })
    ));
    assert!(matches!(
        hermite_spatial(&start.with_binormal(Vector3::new(0.0, 0.0, 1.0)), &end, 6),
        Err(ClassAError::InvalidParameter {
            name: "binormal",
            ..
        })
    ));
    let parallel = start.with_curvature(1.0).with_binormal(start.tangent);
    assert!(matches!(
        hermite_spatial(&parallel, &end.with_curvature(1.0), 6),
        Err(ClassAError::InvalidParameter { .. })
    ));
    assert!(matches!(
        hermite_spatial(&start, &end, 2),
        Err(ClassAError::DegreeTooLow { needed: 3, .. })
    ));
    assert!(matches!(
        hermite_spatial(&start, &start, 6),
        Err(ClassAError::CoincidentPoints { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// Ok ⇒ the end conditions are met to the stated tolerance and both certificates prove
    /// monotonicity.
    #[test]
    fn ok_means_met_and_proven(
        n in 3usize..9,
        log_s in -0.3f64..0.3,
        theta in 0.1f64..0.6,
        (ap, aa) in (0.2f64..1.4, 0.0f64..TAU),
        f in [0.9f64..1.1, 0.9f64..1.1],
        turn in [-0.1f64..0.1, -0.1f64..0.1],
        with_binormals in any::<bool>(),
    ) {
        let (start, end) = g1_knots(n, log_s.exp(), theta, unit(ap, aa));
        if let Ok(g1) = hermite_spatial(&start, &end, n) {
            assert_meets(g1.as_bezier(), &start, &end);
            let c = g1.as_bezier();
            let (t0, k0, b0, _) = frame_at(c, 0.0);
            let (t1, k1, b1, _) = frame_at(c, 1.0);
            let (mut a, mut b) = (start.with_curvature(k0 * f[0]), end.with_curvature(k1 * f[1]));
            if with_binormals {
                a = a.with_binormal(rotation(&t0, turn[0]) * b0);
                b = b.with_binormal(rotation(&t1, turn[1]) * b1);
            }
            if let Ok(g2) = hermite_spatial(&a, &b, n) {
                assert_meets(g2.as_bezier(), &a, &b);
            }
        }
    }
}

#[test]
fn spline_through_spiral_knots_g1_and_g2() {
    let knots = spiral_knots(4, false);
    let g1 = SpatialClassASpline::new(knots.clone(), 6).unwrap();
    assert_eq!(g1.segments().len(), 3);
    assert_eq!(g1.to_bezier_segments().len(), 3);
    for (i, k) in knots.iter().enumerate() {
        assert!((g1.eval(i as f64).unwrap() - k.point).norm() < 1e-12);
    }
    for w in g1.segments().windows(2) {
        let (ta, ..) = frame_at(w[0].as_bezier(), 1.0);
        let (tb, ..) = frame_at(w[1].as_bezier(), 0.0);
        assert!((ta - tb).norm() < 2e-9);
    }
    // The spiral's own curvature and binormal at every knot: G2 with the spiral's values.
    let exact = spiral_knots(4, true);
    let g2 = SpatialClassASpline::new(exact.clone(), 6).unwrap();
    for (seg, w) in g2.segments().iter().zip(exact.windows(2)) {
        assert_meets(seg.as_bezier(), &w[0], &w[1]);
    }
    // Chosen joints: every joint G2 (equal curvature vectors on both sides).
    let chosen = SpatialClassASpline::with_g2_joints(knots, 6).unwrap();
    assert!(
        chosen
            .knots()
            .iter()
            .all(|k| k.curvature.is_some() && k.binormal.is_some())
    );
    for w in chosen.segments().windows(2) {
        let (ta, ka, ba, _) = frame_at(w[0].as_bezier(), 1.0);
        let (tb, kb, bb, _) = frame_at(w[1].as_bezier(), 0.0);
        assert!((ta - tb).norm() < 2e-9);
        assert!(close(ka, kb, 2e-8), "{ka} vs {kb}");
        assert!((ba - bb).norm() < 4e-9);
    }
}

#[test]
fn spline_errors_are_typed() {
    let knots = spiral_knots(2, false);
    assert!(matches!(
        SpatialClassASpline::new(knots[..1].to_vec(), 5),
        Err(ClassAError::InvalidParameter { .. })
    ));
    assert!(matches!(
        SpatialClassASpline::new(knots.clone(), 2),
        Err(ClassAError::DegreeTooLow { .. })
    ));
    let mut bad = knots.clone();
    bad[1].tangent = Vector3::zeros();
    assert!(matches!(
        SpatialClassASpline::new(bad, 5),
        Err(ClassAError::Segment { index: 0, .. })
    ));
    let s = SpatialClassASpline::new(knots, 5).unwrap();
    assert!(s.eval(1.5).is_err() && s.eval(f64::NAN).is_err());
    assert_eq!(s.degree(), 5);
}

#[cfg(feature = "serde")]
#[test]
fn spline_serde_round_trip_and_validation() {
    let s = SpatialClassASpline::new(spiral_knots(3, false), 5).unwrap();
    let json = serde_json::to_string(&s).unwrap();
    let back: SpatialClassASpline = serde_json::from_str(&json).unwrap();
    assert_eq!(back.degree(), s.degree());
    for (a, b) in back.to_bezier_segments().iter().zip(s.to_bezier_segments()) {
        for (p, q) in a.points().iter().zip(b.points()) {
            assert!((p - q).norm() < 1e-12);
        }
    }
    let bad = json.replace("\"degree\":5", "\"degree\":2");
    assert!(serde_json::from_str::<SpatialClassASpline>(&bad).is_err());
}
