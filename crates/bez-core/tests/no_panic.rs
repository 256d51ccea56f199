//! Random (including NaN, infinite, huge and out-of-contract) inputs to every public
//! constructor and method give `Result`s or values, never panics, and an `Ok` (or a plain
//! value) of a curve inside the contract never holds a NaN or an infinity.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{
    BezierCurve, BezierSurface, CoreError, MAX_COORDINATE, MAX_DEGREE, Vector, Vector2, bernstein,
    bernstein_derivative, bernstein_product, bernstein_row, binomial, compensated_de_casteljau,
    de_casteljau, eval_bernstein_poly, roots_in_unit_interval,
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
