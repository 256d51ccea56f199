//! Random (including NaN, infinite, huge and out-of-contract) inputs to every public
//! constructor and method give `Result`s or values, never panics, and an `Ok` (or a plain
//! value) of a curve inside the contract never holds a NaN or an infinity.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{
    Aabb, BezierCurve, BezierForm, BezierSurface, ControlPoint, CoreError, DEFAULT_ACCURACY,
    EXACT_BINOMIAL_DEGREE, HORNER_MAX_DEGREE, HornerBernstein, MAX_COORDINATE, MAX_DEGREE,
    MAX_SAMPLES, Nearest, Reduced, Vector, Vector2, Vector3, bernstein, bernstein_derivative,
    bernstein_derivative_coeffs, bernstein_elevate, bernstein_product, bernstein_row, binomial,
    compensated_de_casteljau, de_casteljau, de_casteljau_halve, de_casteljau_halve_array,
    de_casteljau_halve_in_place, de_casteljau_in_place, de_casteljau_split,
    de_casteljau_split_array, elevate_slice, eval_bernstein_poly, hodograph_slice, lerp,
    roots_in_unit_interval,
};
use proptest::prelude::*;

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -10.0..10.0f64,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(1e300),
        1 => Just(-1e300),
        1 => Just(MAX_COORDINATE),
        1 => Just(-MAX_COORDINATE),
        1 => Just(1e-300),
        1 => Just(0.0),
        1 => Just(1.0),
    ]
}

fn wild_points() -> impl Strategy<Value = Vec<Vector2>> {
    proptest::collection::vec((wild(), wild()).prop_map(|(x, y)| Vector2::new(x, y)), 0..8)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn curves_never_panic(pts in wild_points(), t in wild(), a in wild(), b in wild(), r in 0usize..4) {
        let c = match BezierCurve::new(pts.clone()) {
            Ok(c) => c,
            Err(CoreError::Empty) => { prop_assert!(pts.is_empty()); return Ok(()); }
            Err(CoreError::NonFinite { index }) => { prop_assert!(!pts[index].is_finite()); return Ok(()); }
            Err(CoreError::CoordinateOutOfRange { index, .. }) => {
                prop_assert!(pts[index].amax() > MAX_COORDINATE);
                return Ok(());
            }
            Err(e) => { prop_assert!(false, "unexpected {e}"); return Ok(()); }
        };
        let finite = |v: &Vector2| v.is_finite();
        let curve_ok = |c: &BezierCurve<2>| c.points().iter().all(finite);
        if let Ok(p) = c.eval(t) { prop_assert!(finite(&p)); }
        if let Ok(p) = c.eval_compensated(t) { prop_assert!(finite(&p)); }
        let mut many = Vec::new();
        let _ = c.eval_many(&[t, a, b], &mut many);
        prop_assert!(many.iter().all(finite));
        if let Ok((l, r)) = c.split(t) { prop_assert!(curve_ok(&l) && curve_ok(&r)); }
        if let Ok(s) = c.subsegment(a, b) { prop_assert!(curve_ok(&s)); }
        prop_assert!(curve_ok(&c.reverse()));
        if let Ok(d) = c.derivative_n(r) { prop_assert!(curve_ok(&d)); }
        if let Ok(d) = c.eval_derivatives(t, r) { prop_assert!(d.iter().all(finite)); }
        if let Ok(e) = c.elevate(r) { prop_assert!(curve_ok(&e)); }
        if let Ok(red) = c.reduce_degree() { prop_assert!(curve_ok(&red.curve)); }
        if let Ok(k) = c.curvature(t) { prop_assert!(k.is_finite()); }
        if let Ok(k) = c.signed_curvature(t) { prop_assert!(k.is_finite()); }
        if let Ok(l) = c.arc_length(a) { prop_assert!(l.is_finite()); }
        if let Ok(n) = c.nearest(&Vector2::new(a, b)) { prop_assert!(n.distance.is_finite() && finite(&n.point)); }
        let bb = c.bounding_box();
        prop_assert!(finite(&bb.min) && finite(&bb.max));
        let _ = c.control_bounding_box();
        if let Ok(s) = c.sample_uniform(r) { prop_assert!(s.iter().all(finite)); }
    }

    #[test]
    fn surfaces_and_torsion_never_panic(
        raw in proptest::collection::vec(wild(), 0..40),
        du in 0usize..4, dv in 0usize..4, u in wild(), v in wild(),
    ) {
        let pts: Vec<Vector<3>> = raw.chunks_exact(3).map(|c| Vector::<3>::new(c[0], c[1], c[2])).collect();
        if let Ok(c) = BezierCurve::new(pts.clone()) {
            let _ = c.torsion(u);
        }
        if let Ok(s) = BezierSurface::from_flat(du, dv, pts) {
            let _ = s.eval(u, v);
            let _ = s.normal(u, v);
            let _ = s.partial(du, dv + 1).unwrap();
            let _ = s.split_u(u);
            let _ = s.split_v(v);
            let _ = s.curve_at_u(u);
            let _ = s.curve_at_v(v);
            let _ = s.elevate_u(1).unwrap().elevate_v(2).unwrap();
            let _ = (s.degree_v(), s.control_point(du, dv), s.control_point(usize::MAX, 0));
            if let Ok(p) = s.eval_partial(u, v, du, dv) {
                prop_assert!(p.is_finite());
            }
            let _ = s.eval_partial(0.5, 0.5, usize::MAX, usize::MAX);
        }
        let _ = BezierSurface::<3>::new(vec![vec![]]);
        let _ = BezierSurface::<3>::from_flat(usize::MAX, 2, vec![]);
    }

    #[test]
    fn scalar_kernels_never_panic(c in proptest::collection::vec(wild(), 0..10), t in wild(), n in 0usize..200, i in 0usize..210) {
        let _ = de_casteljau(&c, t);
        let _ = compensated_de_casteljau(&c, t);
        let _ = eval_bernstein_poly(&c, t);
        let _ = roots_in_unit_interval(&c);
        let _ = bernstein_product(&c, &c);
        let _ = binomial(n, i);
        let _ = bernstein(n, i, t);
        let _ = bernstein_derivative(n, i, t, i % 5);
        let mut row = vec![0.0; n % 20];
        bernstein_row(t, &mut row);
        let _ = bernstein_derivative_coeffs(&c);
        let _ = bernstein_elevate(&c, n % 4);
        assert!(bernstein_elevate(&c, usize::MAX).is_err() || c.is_empty());
    }

    /// The slice kernels, generic over `ControlPoint`, with buffers of wrong lengths too.
    #[test]
    fn slice_kernels_never_panic(pts in wild_points(), t in wild(), extra in 0usize..3, r in 0usize..4) {
        let _ = lerp(Vector2::new(t, 0.0), Vector2::new(1.0, t), t);
        let mut work = pts.clone();
        let _ = de_casteljau_in_place(&mut work, t);
        let mut left = vec![Vector2::zeros(); pts.len() + extra];
        let mut right = vec![Vector2::zeros(); pts.len()];
        let _ = de_casteljau_split(&pts, t, &mut left, &mut right);
        let _ = de_casteljau_halve(&pts, &mut left, &mut right);
        let mut piece = pts.clone();
        let _ = de_casteljau_halve_in_place(&mut piece, &mut left);
        if let Ok(four) = <[Vector2; 4]>::try_from(&pts[..pts.len().min(4)]) {
            let _ = de_casteljau_split_array(four, t);
            let _ = de_casteljau_halve_array(four);
        }
        let _ = de_casteljau_split_array([0.0_f64; 0], t);
        let _ = elevate_slice(&pts, r);
        prop_assert!(elevate_slice(&pts, MAX_DEGREE + 1).is_err() || pts.is_empty());
        let _ = hodograph_slice(&pts);
        let h = HornerBernstein::new(&pts);
        let _ = h.eval(t);
        let b: Option<Aabb<2>> = Aabb::from_points(&pts);
        if let Some(mut b) = b {
            b.include(&Vector2::new(t, t));
            let _ = b.size();
            let _ = b.contains(&Vector2::new(t, 0.0), 0.0);
        }
    }
}

/// The kernel's slice functions accept any `ControlPoint`; curves are used through the
/// `BezierForm` trait exactly as through their inherent methods.
fn generic_midpoint<T: ControlPoint>(p: &[T]) -> Option<T> {
    de_casteljau(p, 0.5)
}

#[test]
fn trait_and_generic_entry_points_and_limits() {
    assert_eq!(generic_midpoint(&[0.0, 2.0]), Some(1.0));
    let c = BezierCurve::new(vec![
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(1.0, 2.0, 3.0),
    ])
    .unwrap();
    assert_eq!(BezierForm::eval(&c, 0.5).unwrap(), c.eval(0.5).unwrap());
    let n: Nearest<3> = c.nearest(&Vector3::new(1.0, 0.0, 0.0)).unwrap();
    assert!(n.distance.is_finite());
    let quad = c.elevate(1).unwrap();
    let r: Reduced<3> = quad.reduce_degree().unwrap();
    assert!(r.error_bound < 1e-14);
    const { assert!(DEFAULT_ACCURACY > 0.0 && EXACT_BINOMIAL_DEGREE >= 60) };
    const { assert!(HORNER_MAX_DEGREE < MAX_DEGREE && MAX_SAMPLES >= 1 << 20) };
}

/// kurbo paths with wild coordinates: curves or an error, never a panic.
#[cfg(feature = "kurbo")]
#[test]
fn kurbo_paths_never_panic() {
    use bez_core::{bez_path_to_curves, curves_to_bez_path};
    use kurbo::{BezPath, Point};
    for x in [f64::NAN, f64::INFINITY, 1e300, MAX_COORDINATE, 0.5] {
        let mut path = BezPath::new();
        path.move_to(Point::new(0.0, 0.0));
        path.quad_to(Point::new(x, 1.0), Point::new(2.0, x));
        path.close_path();
        if let Ok(subpaths) = bez_path_to_curves(&path) {
            for curves in &subpaths {
                assert!(
                    curves
                        .iter()
                        .flat_map(|c| c.points())
                        .all(Vector2::is_finite)
                );
                let _ = curves_to_bez_path(curves);
            }
        }
    }
}

#[test]
fn sizes_above_the_limits_are_errors_before_any_work() {
    let c = BezierCurve::new(vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 1.0)]).unwrap();
    for r in [MAX_DEGREE, usize::MAX] {
        assert!(matches!(
            c.elevate(r),
            Err(CoreError::DegreeTooHigh {
                max: MAX_DEGREE,
                ..
            })
        ));
    }
    assert!(c.elevate(MAX_DEGREE - 1).is_ok());
    assert!(matches!(
        c.sample_uniform(usize::MAX),
        Err(CoreError::TooLarge { .. })
    ));
    assert!(matches!(
        c.eval_derivatives(0.5, 1 << 40),
        Err(CoreError::TooLarge { .. })
    ));
    assert_eq!(
        c.derivative_n(usize::MAX).unwrap().points(),
        &[Vector2::new(0.0, 0.0)]
    );
    let too_many = vec![Vector2::new(0.0, 0.0); MAX_DEGREE + 2];
    assert!(matches!(
        BezierCurve::new(too_many),
        Err(CoreError::DegreeTooHigh { .. })
    ));
    let s = BezierSurface::<3>::from_flat(1, 1, vec![Vector::<3>::zeros(); 4]).unwrap();
    assert!(matches!(
        s.elevate_u(usize::MAX),
        Err(CoreError::DegreeTooHigh { .. })
    ));
    assert!(matches!(
        s.elevate_v(1 << 40),
        Err(CoreError::DegreeTooHigh { .. })
    ));
    assert_eq!(s.partial(usize::MAX, usize::MAX).unwrap().degree_u(), 0);
    assert!(matches!(
        BezierSurface::<3>::from_flat(usize::MAX, 2, vec![]),
        Err(CoreError::DegreeTooHigh { .. })
    ));
}

/// A curve at the coordinate limit: every measure finite; derivatives that leave the range
/// are errors, not curves holding huge values.
#[test]
fn curves_at_the_coordinate_limit_stay_finite() {
    let m = MAX_COORDINATE;
    let c = BezierCurve::new(vec![
        Vector2::new(m, -m),
        Vector2::new(-m, m),
        Vector2::new(m, m),
    ])
    .unwrap();
    assert!(matches!(c.derivative(), Err(CoreError::Overflow { .. })));
    assert!(c.curvature(0.3).unwrap().is_finite());
    assert!(c.arc_length(1e-3).unwrap().is_finite());
    let n = c.nearest(&Vector2::new(0.0, 0.0)).unwrap();
    assert!(n.distance.is_finite() && n.distance < m);
    assert!(matches!(
        c.nearest(&Vector2::new(1e200, 0.0)),
        Err(CoreError::QueryOutOfRange { .. })
    ));
    assert!(
        c.eval_derivatives(0.5, 2)
            .unwrap()
            .iter()
            .all(Vector2::is_finite)
    );
}

/// High degrees (binomials beyond the f64 range from degree 1030): sampling, splitting and
/// nearest points agree with de Casteljau.
#[test]
fn high_degree_curves_evaluate_split_and_project_correctly() {
    let pts: Vec<Vector2> = (0..=1500)
        .map(|i| Vector2::new(i as f64, ((i * 7919) % 13) as f64))
        .collect();
    let c = BezierCurve::new(pts).unwrap();
    let mid = c.eval(0.5).unwrap();
    let (l, r) = c.split(0.5).unwrap();
    assert_eq!(l.end(), mid);
    assert_eq!(r.start(), mid);
    let samples = c.sample_uniform(5).unwrap();
    for (k, p) in samples.iter().enumerate() {
        let exact = c.eval(k as f64 / 4.0).unwrap();
        assert!((p - exact).norm() < 1e-9 * 1500.0, "{p:?} vs {exact:?}");
    }
    let n = c.nearest(&mid).unwrap();
    assert!(n.distance < 1e-9, "{n:?}");
    let b = c.bounding_box();
    assert!(b.contains(&mid, 0.0));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Vector arithmetic follows IEEE 754 (no panic for any input); inside the coordinate
    /// contract (|x| ≤ `MAX_COORDINATE`, so squares stay below 10³⁰⁴) every product, length
    /// and normal is finite.
    #[test]
    fn vectors_never_panic(a in proptest::array::uniform3(wild()), b in proptest::array::uniform3(wild())) {
        let (u, v) = (Vector3::from_array(a), Vector3::from_fn(|i| b[i]));
        let inside = u.amax() <= MAX_COORDINATE && v.amax() <= MAX_COORDINATE
            && u.is_finite() && v.is_finite();
        let mut w = Vector3::repeat(a[0]);
        w.as_mut_array()[1] = b[1];
        for x in w.iter_mut() {
            *x = x.abs();
        }
        let _ = (w.to_array(), w.as_array(), w.as_slice(), u.abs(), u.inf(&v), u.sup(&v));
        let products = [u.dot(&v), u.norm_squared(), u.norm(), u.xy().perp(&v.xy()), u.z()];
        let vectors = [u.cross(&v), u.component_mul(&v), u.zip_map(&v, f64::max)];
        if inside {
            prop_assert!(products.iter().all(|x| x.is_finite()));
            prop_assert!(vectors.iter().all(Vector3::is_finite));
            if let Some(n) = u.try_normalize(0.0) {
                prop_assert!(n.is_finite() && (n.norm() - 1.0).abs() < 1e-12);
                prop_assert_eq!(n, u.normalize());
            }
        }
    }

    /// Slices, owned points and clamped evaluation behave like `new`, `points` and `eval`.
    #[test]
    fn slice_constructors_and_clamped_evaluation(pts in wild_points(), t in wild()) {
        let from_slice = BezierCurve::from_slice(&pts);
        prop_assert_eq!(&from_slice, &BezierCurve::new(pts.clone()));
        if let Ok(c) = from_slice {
            let p = c.eval_clamped(t);
            prop_assert!(p.is_finite());
            if let Ok(q) = c.eval(t) {
                prop_assert_eq!(p, q);
            }
            prop_assert_eq!(c.degree() + 1, pts.len());
            prop_assert_eq!((p.x(), p.y()), (p[0], p[1]));
            prop_assert_eq!(c.clone().into_points(), pts);
        }
    }
}

/// glam's vectors with wild coordinates: a curve or an error, and the curve converts back.
#[cfg(feature = "glam")]
#[test]
fn glam_points_never_panic() {
    use glam::{DVec2, DVec3};
    for x in [f64::NAN, f64::INFINITY, 1e300, MAX_COORDINATE, 0.5] {
        let flat = [DVec2::new(0.0, 0.0), DVec2::new(x, 1.0)];
        if let Ok(c) = BezierCurve::<2>::from_dvec2(&flat) {
            assert_eq!(c.to_dvec2(), flat);
        }
        let space = [DVec3::new(0.0, 0.0, 0.0), DVec3::new(x, 1.0, 2.0)];
        if let Ok(c) = BezierCurve::<3>::from_dvec3(&space) {
            assert_eq!(c.to_dvec3(), space);
        }
    }
}

bez_core::suite_completeness_tests!();
