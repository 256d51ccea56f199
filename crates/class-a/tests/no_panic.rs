//! Random (including NaN, infinite, huge and out-of-contract) inputs to class-a's public
//! functions and methods give `Result`s, never panics, and an `Ok` never holds a NaN or an
//! infinity.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, BezierForm, Vector2, Vector3};
use class_a::{
    Certificate, ClassACurve, ClassAError, ClassAReport, ClassASpline, Condition, EditFrame,
    FRAME_SAMPLES, INTERPOLATION_TOLERANCE, Interpolation, Knot, LogGraph, MAX_KNOTS, MAX_PIECES,
    MAX_SUBDIVISION_DEPTH, Matrix, Matrix2, Matrix3, Monotonicity, PlanarFeasibility,
    PlanarGeometry, Proof, SUBCURVE_SAMPLES, ScaledBernstein, SpatialClassASpline, SpatialKnot,
    SpatialRequirement, TypicalPlanar, TypicalSpatial, UndecidedCause, apollonius_pole,
    class_a_curve, curvature_certificate, curvature_numerator, curvature_samples,
    curvature_with_derivative, end_curvatures, end_curvatures_torsions, end_preserving_curve,
    hermite_planar, hermite_spatial, log_graph, log_graph_from_points, log_spiral_pole, perturb2,
    perturb3, planar_feasibility, rotation, solve_scale, spiral_deviation, torsion_certificate,
    torsion_numerator, torsion_samples, torsion_with_derivative, typical_matrix2,
    typical_planar_margin,
};
use proptest::prelude::*;

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -3.0..3.0f64,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(-1e300),
        1 => Just(1e-300),
        1 => Just(0.0),
        1 => Just(1.0),
    ]
}

fn degree() -> impl Strategy<Value = usize> {
    prop_oneof![
        8 => 0usize..12,
        1 => Just(class_a::MAX_DEGREE + 1),
        1 => Just(1usize << 40),
        1 => Just(usize::MAX),
    ]
}

fn v2() -> impl Strategy<Value = Vector2> {
    (wild(), wild()).prop_map(|(x, y)| Vector2::new(x, y))
}

fn v3() -> impl Strategy<Value = Vector3> {
    (wild(), wild(), wild()).prop_map(|(x, y, z)| Vector3::new(x, y, z))
}

fn finite_curve<const D: usize>(c: &BezierCurve<D>) -> bool {
    c.points().iter().all(|p| p.is_finite())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn planar(a0 in v2(), a1 in v2(), a2 in v2(), n in degree(), s in wild(), th in wild(), t in wild()) {
        let _ = solve_scale(th, s, n.min(64));
        if let Ok(f) = planar_feasibility(&a0, &a1, &a2, n) {
            let _ = f.is_feasible();
        }
        if let Ok(tp) = TypicalPlanar::from_points(&a0, &a1, &a2, n) {
            prop_assert!(tp.s().is_finite() && tp.theta().is_finite() && tp.length().is_finite());
            if let Ok(c) = tp.curve() { prop_assert!(finite_curve(&c)); }
            let _ = tp.margin();
            let _ = tp.log_curvature_point(t);
        }
        let frame: Result<EditFrame<TypicalPlanar, 2>, ClassAError> = TypicalPlanar::edit(&a0, &a1, &a2, n);
        if let Ok(f) = frame {
            prop_assert!(finite_curve(&f.curve) && f.solution.s().is_finite());
            prop_assert!(f.slope.is_none_or(f64::is_finite));
            if let Ok(cert) = f.certificate { let _ = cert.is_monotone(); }
        }
        if let Ok((_, c, _)) = TypicalPlanar::generate(&a0, &a1, &a2, n, 1e-9) {
            prop_assert!(finite_curve(&c));
        }
        if let Ok(tp) = TypicalPlanar::new(a0, a1, s, s, th, n)
            && let Ok(c) = tp.curve()
        {
            prop_assert!(finite_curve(&c));
        }
        let m = Matrix2::new(s, -th, th, s);
        if let Ok(c) = class_a_curve(&a0, &a1, &m, n) {
            prop_assert!(finite_curve(&c));
            if let Ok(cert) = curvature_certificate(&c) { let _ = cert.is_monotone(); }
            if let Ok(samples) = curvature_samples(&c, 17) {
                prop_assert!(samples.iter().all(|(k, d)| k.is_finite() && d.is_finite()));
                if let Ok(g) = log_graph(&samples) { prop_assert!(g.slope.is_finite()); }
            }
        }
        if let Ok(r) = ClassAReport::of_2x2(&perturb2(&m, [t, 0.0, 0.0, t])) {
            for c in [r.farin3, r.singular_values, r.farin4, r.subcurve_farin4] {
                prop_assert!(c.margin.is_finite(), "{r:?}");
            }
        }
        if let Ok(p) = log_spiral_pole(&a0, &a1, s, th) {
            prop_assert!(p.is_finite());
            let _ = spiral_deviation(&[a0, a1, a2], &p, s, th);
        }
        if let Ok(p) = apollonius_pole(&[a0, a1, a2, a0 + a1]) { prop_assert!(p.is_finite()); }
    }

    #[test]
    fn spatial(a in [v3(), v3(), v3(), v3()], n in degree(), s in wild(), th in wild()) {
        if let Ok(ts) = TypicalSpatial::from_points(&a, n)
            && let Ok(c) = ts.curve()
        {
            prop_assert!(finite_curve(&c));
            if let Ok(cert) = torsion_certificate(&c) { let _ = cert.is_monotone(); }
            if let Ok(samples) = torsion_samples(&c, 9) {
                prop_assert!(samples.iter().all(|(k, d)| k.is_finite() && d.is_finite()));
            }
        }
        let _ = TypicalSpatial::candidates(&a, n);
        for requirement in [SpatialRequirement::ClassA, SpatialRequirement::MonotoneTorsion] {
            if let Ok(ts) = TypicalSpatial::solve(&a, n.min(12), requirement) {
                prop_assert!(ts.s.is_finite() && ts.theta.is_finite() && ts.length.is_finite());
                let _ = ts.torsion_condition();
                if let Ok(f) = ts.edit(&a) {
                    prop_assert!(finite_curve(&f.curve) && f.solution.s.is_finite());
                    prop_assert!(f.solution.theta.is_finite());
                    prop_assert!(f.slope.is_none_or(f64::is_finite));
                }
            }
        }
        let m = rotation(&a[0], th) * s;
        if let Ok(c) = class_a_curve(&a[1], &a[2], &m, n) {
            prop_assert!(finite_curve(&c));
        }
        let _ = ClassAReport::of_3x3(&m);
        let _ = Matrix3::identity().singular_values();
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    /// The remaining entry points: numerators, derivatives of κ and τ, log graphs from points,
    /// typical matrices and margins, interpolation measures and the Class A curve type.
    #[test]
    fn numerators_graphs_and_measures(a0 in v2(), a1 in v2(), a2 in v2(), b in v3(), n in degree(), s in wild(), th in wild(), t in wild()) {
        let _ = typical_planar_margin(s, th);
        let m: Matrix<2> = typical_matrix2(s, th);
        if let Ok(c) = ClassACurve::new(&a0, &a1, &m, n) {
            prop_assert!(c.as_bezier().points().iter().all(|p| p.is_finite()));
            let c = c.into_bezier();
            if let Ok((num, den)) = curvature_numerator(&c) {
                let nums: [&ScaledBernstein; 2] = [&num, &den];
                for x in nums { let _ = (x.degree(), x.coefficients().len(), x.is_zero()); }
            }
            if let Ok((k, dk)) = curvature_with_derivative(&c, t) {
                prop_assert!(k.is_finite() && dk.is_finite());
            }
            let i = Interpolation::measure(c.points(), &a0, &a1, &(a2 - a1), &a2);
            let _ = i.worst();
            let _ = i.within(INTERPOLATION_TOLERANCE);
        }
        let g: Result<LogGraph, ClassAError> = log_graph_from_points(vec![(s, th), (t, s), (th, t)]);
        if let Ok(g) = g { prop_assert!(g.slope.is_finite()); }
        if let Ok(geo) = PlanarGeometry::new(&a0, &a1, &a2) {
            prop_assert!(geo.turn.is_finite() && geo.chord_length.is_finite());
        }
        let f: Result<PlanarFeasibility, ClassAError> = planar_feasibility(&a0, &a1, &a2, n);
        let _ = f.map(|f| f.is_feasible());
        let m3 = perturb3(&(rotation(&b, th) * s), [t, 0.0, 0.0, t]);
        if let Ok(c) = class_a_curve(&b, &Vector3::new(1.0, t, 0.0), &m3, n) {
            if let Ok((num, _)) = torsion_numerator(&c) { let _ = num.degree(); }
            if let Ok([(k0, t0), (k1, t1)]) = end_curvatures_torsions(&c) {
                prop_assert!([k0, t0, k1, t1].iter().all(|v| v.is_finite()));
            }
            if let Ok((tau, dtau)) = torsion_with_derivative(&c, t) {
                prop_assert!(tau.is_finite() && dtau.is_finite());
            }
            if let Ok(cert) = torsion_certificate(&c) {
                let _: Proof = cert.proof;
                let verdict: Monotonicity = cert.verdict;
                if let Monotonicity::Undecided { cause, .. } = verdict {
                    prop_assert!(matches!(cause, UndecidedCause::Regularity | UndecidedCause::Sign));
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    /// Accessors of the solved curves and the small matrices: finite values from finite
    /// solutions, IEEE arithmetic (no panic) on wild matrices, and the exact identities
    /// (transpose twice, rows and columns, inverse times matrix).
    #[test]
    fn accessors_and_matrices(a0 in v2(), a1 in v2(), a2 in v2(), b in v3(), n in degree(), s in wild(), th in wild(), t in wild()) {
        if let Ok(tp) = TypicalPlanar::from_points(&a0, &a1, &a2, n.min(64)) {
            prop_assert!(tp.b0().is_finite() && tp.mu().is_finite());
            prop_assert!(tp.matrix().iter().all(|x| x.is_finite()));
            let mut out = Vec::new();
            tp.control_points_into(&mut out);
            prop_assert!(out.iter().all(Vector2::is_finite));
            if (0.0..=1.0).contains(&t) {
                prop_assert!(!tp.curvature(t).is_nan());
            }
        }
        let a = [Vector3::new(a0.x(), a0.y(), s), Vector3::new(a1.x(), a1.y(), th), Vector3::new(a2.x(), a2.y(), t), b];
        if let Ok(ts) = TypicalSpatial::solve(&a, n.min(12), SpatialRequirement::ClassA) {
            prop_assert!(ts.matrix().iter().all(|x| x.is_finite()));
            prop_assert!(!ts.class_a_margin().is_nan());
        }
        let m2 = typical_matrix2(s, th);
        if let Ok(c) = ClassACurve::new(&a0, &a1, &m2, n) {
            prop_assert_eq!(c.matrix(), m2);
        }
        let m3 = Matrix3::from_fn(|i, j| [s, th, t][(i + j) % 3]);
        if [s, th, t].iter().all(|x| x.is_finite()) && b.is_finite() {
            prop_assert_eq!(m3.transpose().transpose(), m3);
            prop_assert_eq!(Matrix3::from_rows(m3.to_rows()), m3);
            let cols = [b, Vector3::new(s, th, t), b.cross(&Vector3::new(1.0, 0.0, 0.0))];
            prop_assert_eq!(Matrix3::from_columns(&cols).transpose().to_rows()[0], cols[0].to_array());
        }
        let _ = (m3.scale(t), m3.symmetric_eigenvalues(), m3.singular_value_range(), m3.determinant());
        let _ = Matrix3::cross_matrix(&b) * b;
        if let Some(inv) = m2.try_inverse() {
            let id = inv * m2;
            if id.iter().all(|x| x.is_finite()) && m2.iter().all(|x| x.abs() < 1e6) && m2.determinant().abs() > 1e-6 {
                prop_assert!((id - Matrix2::identity()).iter().all(|x| x.abs() < 1e-6), "{id:?}");
            }
        }
        if let Ok(r) = ClassAReport::of_matrix(&m3) {
            let _ = r.is_class_a();
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    /// End curvatures, the G2 Hermite solve, end-preserving perturbations and splines: typed
    /// errors on wild knots, finite values in every `Ok`.
    #[test]
    fn g2_and_splines(a in [v2(), v2(), v2(), v2()], n in degree(), k in [wild(), wild()], t in wild()) {
        let knots: Vec<Knot> = [(a[0], a[1], k[0]), (a[2], a[3], k[1])]
            .into_iter()
            .map(|(p, d, c)| {
                let knot = Knot::new(p, d);
                if c > 0.5 { knot.with_curvature(c * t) } else { knot }
            })
            .collect();
        let small = n.min(12);
        if let Ok(c) = hermite_planar(&knots[0], &knots[1], small) {
            prop_assert!(finite_curve(c.as_bezier()));
            if let Ok((k0, k1)) = end_curvatures(c.as_bezier()) {
                prop_assert!(k0.is_finite() && k1.is_finite());
            }
        }
        let _ = hermite_planar(&knots[0], &knots[1], n);
        if let Ok(tp) = TypicalPlanar::from_points(&a[0], &a[1], &a[2], small) {
            let (k0, k1) = tp.end_curvatures();
            prop_assert!(!k0.is_nan() && !k1.is_nan());
        }
        if let Ok(c) = end_preserving_curve(&a[0], &a[1], &Matrix2::new(k[0], t, -t, k[1]), n) {
            prop_assert!(finite_curve(c.as_bezier()));
        }
        let mut more = knots.clone();
        more.push(Knot::new(a[1] + a[3], a[2]));
        if let Ok(s) = ClassASpline::new(more, small) {
            prop_assert!(s.knots().len() == 3 && s.degree() == small);
            prop_assert!(s.segments().iter().all(|c| finite_curve(c.as_bezier())));
            prop_assert!(s.to_bezier_segments().iter().all(finite_curve));
            if let Ok(p) = s.eval(t) { prop_assert!(p.is_finite()); }
        }
        let mut four = knots.clone();
        four.push(Knot::new(a[1] - a[3], a[0]));
        if let Ok(s) = ClassASpline::with_g2_joints(four, small) {
            prop_assert!(s.knots().iter().all(|k| k.curvature.is_some_and(f64::is_finite)));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    /// Spatial end curvatures in closed form, the spatial G2 Hermite solve and spatial splines:
    /// typed errors on wild input, finite values in every `Ok`.
    #[test]
    fn spatial_g2_and_splines(a in [v3(), v3(), v3(), v3()], b in [v3(), v3()], n in degree(), k in [wild(), wild()], t in wild()) {
        let knots: Vec<SpatialKnot> = [(a[0], a[1], k[0], b[0]), (a[2], a[3], k[1], b[1])]
            .into_iter()
            .map(|(p, d, c, binormal)| {
                let knot = SpatialKnot::new(p, d);
                if c > 0.5 { knot.with_curvature(c * t.abs()).with_binormal(binormal) } else if c > -0.5 { knot.with_curvature(c) } else { knot }
            })
            .collect();
        let small = n.min(9);
        if let Ok(c) = hermite_spatial(&knots[0], &knots[1], small) {
            prop_assert!(finite_curve(c.as_bezier()));
            if let Ok(e) = end_curvatures_torsions(c.as_bezier()) {
                prop_assert!(e.iter().all(|(k, tau)| k.is_finite() && tau.is_finite()));
            }
        }
        let _ = hermite_spatial(&knots[0], &knots[1], n);
        let typical = TypicalSpatial { b0: a[0], v0: a[1], length: k[0], s: k[1], phi: t, axis: b[0], theta: t, degree: n.min(64) };
        if let Ok(e) = typical.end_curvatures_torsions() {
            prop_assert!(e.iter().all(|(k, tau)| !k.is_nan() && !tau.is_nan()));
        }
        let mut more = knots.clone();
        more.push(SpatialKnot::new(a[1] + a[3], b[1]));
        if let Ok(s) = SpatialClassASpline::new(more, small) {
            prop_assert!(s.knots().len() == 3 && s.degree() == small);
            prop_assert!(s.segments().iter().all(|c| finite_curve(c.as_bezier())));
            prop_assert!(s.to_bezier_segments().iter().all(finite_curve));
            if let Ok(p) = s.eval(t) { prop_assert!(p.is_finite()); }
        }
        let three: Vec<SpatialKnot> = vec![
            SpatialKnot::new(a[0], a[1]),
            SpatialKnot::new(a[2], a[3]),
            SpatialKnot::new(b[0], b[1]),
        ];
        if let Ok(s) = SpatialClassASpline::with_g2_joints(three, small) {
            prop_assert!(s.knots().iter().all(|k| k.curvature.is_some_and(f64::is_finite)));
        }
    }
}

#[test]
fn spatial_spline_knot_count_is_bounded() {
    let knot = SpatialKnot::new(Vector3::new(0.0, 0.0, 0.0), Vector3::new(1.0, 0.0, 0.0));
    assert!(matches!(
        SpatialClassASpline::new(vec![knot; MAX_KNOTS + 1], 5),
        Err(ClassAError::InvalidParameter { .. })
    ));
}

#[test]
fn spline_knot_count_is_bounded() {
    let knot = Knot::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
    assert!(matches!(
        ClassASpline::new(vec![knot; MAX_KNOTS + 1], 5),
        Err(ClassAError::InvalidParameter { .. })
    ));
}

#[test]
fn limits_are_stated() {
    const { assert!(MAX_PIECES > 0 && MAX_SUBDIVISION_DEPTH > 0 && SUBCURVE_SAMPLES > 0) };
    const { assert!(FRAME_SAMPLES >= 2) };
    let r = ClassAReport::of_2x2(&Matrix2::identity()).unwrap();
    let c: Condition = r.farin3;
    assert!(c.holds);
    let cert: Certificate = curvature_certificate(
        &class_a_curve(
            &Vector2::new(0.0, 0.0),
            &Vector2::new(1.0, 0.0),
            &typical_matrix2(1.2, 0.2),
            5,
        )
        .unwrap(),
    )
    .unwrap();
    assert!(cert.is_monotone());
}

#[test]
fn sample_counts_above_the_limit_are_errors() {
    let c = class_a_curve(
        &Vector2::new(0.0, 0.0),
        &Vector2::new(1.0, 0.0),
        &Matrix2::new(1.1, -0.1, 0.1, 1.1),
        4,
    )
    .unwrap();
    assert!(curvature_samples(&c, usize::MAX).is_err());
    assert_eq!(curvature_samples(&c, 0).unwrap().len(), 2);
}

bez_core::suite_completeness_tests!();
