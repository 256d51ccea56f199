//! Random (including NaN, infinite and huge) inputs to every public constructor and method
//! give `Result`s or values, never panics.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{
    BezierCurve, BezierSurface, Vector, Vector2, bernstein, bernstein_derivative,
    bernstein_product, bernstein_row, binomial, compensated_de_casteljau, de_casteljau,
    eval_bernstein_poly, roots_in_unit_interval,
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
        let Ok(c) = BezierCurve::new(pts.clone()) else {
            prop_assert!(pts.is_empty() || pts.iter().any(|p| !p.iter().all(|x| x.is_finite())));
            return Ok(());
        };
        let _ = c.eval(t);
        let _ = c.eval_compensated(t);
        let _ = c.eval_many(&[t, a, b], &mut Vec::new());
        let _ = c.split(t);
        let _ = c.subsegment(a, b);
        let _ = c.reverse();
        let _ = c.derivative_n(r);
        let _ = c.eval_derivatives(t, r);
        let _ = c.elevate(r);
        let _ = c.reduce_degree();
        let _ = c.curvature(t);
        let _ = c.signed_curvature(t);
        let _ = c.arc_length(a);
        let _ = c.nearest(&Vector2::new(a, b));
        let _ = c.bounding_box();
        let _ = c.control_bounding_box();
        let _ = c.sample_uniform(r);
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
            let _ = s.partial(du, dv + 1);
            let _ = s.split_u(u);
            let _ = s.split_v(v);
            let _ = s.curve_at_u(u);
            let _ = s.curve_at_v(v);
            let _ = s.elevate_u(1).elevate_v(2);
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
fn huge_elevation_is_an_error() {
    let c = BezierCurve::new(vec![Vector2::new(0.0, 0.0)]).unwrap();
    assert!(c.elevate(usize::MAX).is_err());
}
