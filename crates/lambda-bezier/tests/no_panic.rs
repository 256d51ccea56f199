//! Random (including NaN, infinite, huge and out-of-contract) inputs to the public functions
//! and methods of lambda-bezier give `Result`s, never panics, and an `Ok` never holds a NaN or
//! an infinity.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierForm, Vector2};
use lambda_bezier::{
    Continuity, LambdaBasis, LambdaBezierCurve, LambdaBezierSurface, LambdaError, LambdaRange,
    PatchJoin, continuity, corner_cut_ratio, hermite_segment, join_c1, join_g1, join_g2,
    join_patches, lambda_range, shape_preserving_curves, shape_preserving_polygons,
};
use proptest::prelude::*;

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -3.0..3.0f64,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(-1e300),
        1 => Just(bez_core::MAX_COORDINATE),
        1 => Just(0.0),
        1 => Just(1.0),
        1 => Just(1e-300),
    ]
}

fn size() -> impl Strategy<Value = usize> {
    prop_oneof![
        6 => 0usize..8,
        1 => Just(4095usize),
        1 => Just(4096usize),
        1 => Just(1usize << 30),
        1 => Just(usize::MAX),
    ]
}

fn points() -> impl Strategy<Value = Vec<Vector2>> {
    proptest::collection::vec((wild(), wild()).prop_map(|(x, y)| Vector2::new(x, y)), 0..7)
}

fn finite(v: &Vector2) -> bool {
    v.is_finite()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn basis_and_range(n in size(), k in size(), lambda in wild(), t in wild(), order in 0usize..5) {
        let _ = corner_cut_ratio(n, k, lambda);
        if let Ok(r) = LambdaRange::new(n) {
            prop_assert!(r.min().is_finite() && r.max().is_finite());
            let (num, den) = r.min_fraction();
            prop_assert!(den > 0);
            prop_assert_eq!(-(num as f64) / (den as f64), r.min());
            prop_assert!(r.binding_index() <= n);
            let _ = r.check(lambda);
            prop_assert_eq!(lambda_range(n).unwrap(), r);
        }
        for b in [LambdaBasis::new(n, lambda), LambdaBasis::new_unrestricted(n, lambda)] {
            let Ok(b) = b else { continue };
            prop_assert!(b.degree() <= bez_core::MAX_DEGREE);
            if let Ok(v) = b.eval(k, t) { prop_assert!(v.is_finite()); }
            if let Ok(v) = b.derivative(k, t, order) { prop_assert!(v.is_finite()); }
            if let Ok(c) = b.bernstein_coefficients(k) { prop_assert!(c.iter().all(|x| x.is_finite())); }
            if b.n() < 10_000 { prop_assert!(b.ratios().iter().all(|x| x.is_finite())); }
            let mut row = vec![0.0; b.n() + 1];
            if b.row(t, &mut row).is_ok() { prop_assert!(row.iter().all(|x| x.is_finite())); }
            if b.n() < 200 && let Ok(r) = b.eval_by_recurrence(t) {
                prop_assert!(r.iter().all(|x| x.is_finite()));
            }
        }
    }

    #[test]
    fn curves_joins_and_interpolation(p in points(), q in points(), la in wild(), lb in wild(), t in wild()) {
        let a = LambdaBezierCurve::new(p.clone(), la);
        let b = LambdaBezierCurve::new(q.clone(), lb);
        if let Ok(a) = &a {
            if let Ok(x) = a.eval(t) { prop_assert!(finite(&x)); }
            if let Ok(d) = a.eval_derivatives(t, 3) { prop_assert!(d.iter().all(finite)); }
            prop_assert!(finite(&a.start_tangent()) && finite(&a.end_tangent()));
            if let Ok(s) = a.sample_uniform(9) { prop_assert!(s.iter().all(finite)); }
            if let Ok(k) = a.curvature(t) { prop_assert!(k.is_finite()); }
            if let Ok(l) = a.arc_length(1e-6) { prop_assert!(l.is_finite()); }
            let _ = a.reverse();
            let _ = a.with_lambda(lb);
            let mut edited = a.clone();
            if edited.set_lambda(lb).is_ok() {
                prop_assert_eq!(edited.lambda(), lb);
            }
            if let Ok(moved) = a.map_points(|x| *x * 2.0) {
                prop_assert!(moved.points().iter().all(finite));
            }
            prop_assert_eq!(&LambdaBezierCurve::from_slice(&p, la).unwrap(), a);
            prop_assert!(a.clone().into_bezier().points().iter().all(finite));
        }
        if let (Ok(a), Ok(b)) = (&a, &b) {
            let c: Continuity = continuity(a, b, 1e-9);
            prop_assert!(c <= Continuity::C1);
            for j in [join_g1(a, b), join_c1(a, b), join_g2(a, b)].into_iter().flatten() {
                prop_assert!(j.points().iter().all(finite));
            }
        }
        if p.len() >= 2
            && q.len() >= 2
            && let Ok(h) = hermite_segment(p[0], p[1], &q, q[0], q[1], la)
        {
            prop_assert!(h.points().iter().all(finite));
        }
        if let Ok(polys) = shape_preserving_polygons(&p) {
            prop_assert!(polys.iter().flatten().all(finite));
        }
        let _ = shape_preserving_curves(&p, &[la, lb]);
    }

    #[test]
    fn surfaces(raw in proptest::collection::vec(wild(), 0..60), cols in 1usize..6, lu in wild(), lv in wild(), u in wild(), v in wild()) {
        let pts: Vec<bez_core::Vector3> = raw.chunks_exact(3).map(|c| bez_core::Vector3::new(c[0], c[1], c[2])).collect();
        let rows: Vec<Vec<bez_core::Vector3>> = pts.chunks(cols).map(<[_]>::to_vec).collect();
        if let Ok(s) = LambdaBezierSurface::new(rows, lu, lv) {
            if let Ok(x) = s.eval(u, v) { prop_assert!(x.is_finite()); }
            prop_assert_eq!((s.n_u() + 1, s.n_v() + 1), (s.rows().len(), s.rows()[0].len()));
            prop_assert_eq!((s.lambda_u(), s.lambda_v()), (lu, lv));
            prop_assert!(s.as_bezier().points().iter().all(bez_core::Vector3::is_finite));
            let mut edited = s.clone();
            if edited.set_lambdas(lv, lu).is_ok() {
                prop_assert_eq!((edited.lambda_u(), edited.lambda_v()), (lv, lu));
            }
            if let Ok(x) = s.eval_partial(u, v, 1, 2) { prop_assert!(x.is_finite()); }
            if let Ok(d) = s.partial(2, 1) { prop_assert!(d.points().iter().all(bez_core::Vector3::is_finite)); }
            for join in [PatchJoin::C1, PatchJoin::G1] {
                if let Ok(j) = join_patches(&s, &s, join) {
                    prop_assert!(j.rows().iter().flatten().all(bez_core::Vector3::is_finite));
                }
            }
        }
    }
}

/// λ fitting on wild points and targets: a λ inside the valid interval with a finite residual,
/// or an error.
#[cfg(feature = "fit")]
mod fit {
    use super::*;
    use lambda_bezier::{LambdaFit, LambdaTarget, fit_lambda, minimize_over_range};

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn fitting_never_panics(p in points(), x in wild(), y in wild(), t in wild(), kappa in wild()) {
            for target in [
                LambdaTarget::Point(Vector2::new(x, y)),
                LambdaTarget::Curvature { t, kappa },
            ] {
                let r: Result<LambdaFit, LambdaError> = fit_lambda(&p, &target);
                if let Ok(fit) = r {
                    prop_assert!(fit.lambda.is_finite() && fit.residual.is_finite());
                }
            }
            if let Ok(range) = LambdaRange::new(p.len().max(2))
                && let Ok(l) = minimize_over_range(&range, |l| (l - x).abs())
            {
                prop_assert!(range.contains(l));
            }
        }
    }
}

/// Sizes the caller chooses are refused before any work.
#[test]
fn basis_degrees_above_the_kernel_limit_are_errors() {
    for n in [bez_core::MAX_DEGREE, 1 << 26, usize::MAX] {
        let refused: LambdaError = LambdaBasis::new(n, 0.0).unwrap_err();
        let limit = bez_core::MAX_DEGREE.to_string();
        assert!(refused.to_string().contains(&limit), "{refused}");
        assert!(LambdaBasis::new_unrestricted(n, 0.0).is_err());
    }
    assert!(LambdaBasis::new(bez_core::MAX_DEGREE - 1, 0.0).is_ok());
}

bez_core::suite_completeness_tests!();
