//! Invariants of the Bernstein basis, curves and surfaces, as property tests.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::proptest_support::{control_points, curve, unit_parameter};
use bez_core::{BezierCurve, BezierSurface, Vector3, bernstein_row};
use proptest::prelude::*;

fn scale(c: &BezierCurve<2>) -> f64 {
    c.points().iter().map(|p| p.abs().max()).fold(1.0, f64::max)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn bernstein_row_is_a_partition_of_unity(n in 0usize..=60, t in unit_parameter()) {
        let mut row = vec![0.0; n + 1];
        bernstein_row(t, &mut row);
        let sum: f64 = row.iter().sum();
        prop_assert!((sum - 1.0).abs() <= 1e-13);
        prop_assert!(row.iter().all(|&b| b >= 0.0));
    }

    #[test]
    fn endpoints_interpolate_exactly(c in curve::<2>(0..=40, 1e3)) {
        prop_assert_eq!(c.eval(0.0).unwrap(), c.start());
        prop_assert_eq!(c.eval(1.0).unwrap(), c.end());
    }

    #[test]
    fn split_pieces_reproduce_the_curve(c in curve::<2>(1..=30, 10.0), t in 0.05..0.95f64, s in unit_parameter()) {
        let (l, r) = c.split(t).unwrap();
        let tol = 1e-12 * scale(&c);
        prop_assert!((l.eval(s).unwrap() - c.eval(s * t).unwrap()).norm() <= tol);
        prop_assert!((r.eval(s).unwrap() - c.eval(t + s * (1.0 - t)).unwrap()).norm() <= tol);
        prop_assert_eq!(l.end(), r.start());
    }

    #[test]
    fn elevation_preserves_the_curve(c in curve::<3>(0..=30, 10.0), r in 1usize..=6, s in unit_parameter()) {
        let e = c.elevate(r).unwrap();
        prop_assert_eq!(e.degree(), c.degree() + r);
        prop_assert!((e.eval(s).unwrap() - c.eval(s).unwrap()).norm() <= 1e-12 * 10.0);
    }

    #[test]
    fn derivative_matches_finite_difference(c in curve::<2>(1..=12, 1.0), s in 0.01..0.99f64) {
        let h = 1e-6;
        let fd = (c.eval(s + h).unwrap() - c.eval(s - h).unwrap()) / (2.0 * h);
        let d = c.derivative().unwrap().eval(s).unwrap();
        prop_assert!((d - fd).norm() <= 1e-5 * (1.0 + d.norm()) * c.degree() as f64);
    }

    #[test]
    fn subsegment_endpoints_are_curve_points(c in curve::<2>(1..=30, 10.0), a in 0.0..0.5f64, w in 0.01..0.5f64) {
        let b = a + w;
        let s = c.subsegment(a, b).unwrap();
        let tol = 1e-12 * scale(&c);
        prop_assert!((s.start() - c.eval(a).unwrap()).norm() <= tol);
        prop_assert!((s.end() - c.eval(b).unwrap()).norm() <= tol);
        prop_assert!((s.eval(0.5).unwrap() - c.eval(a + 0.5 * w).unwrap()).norm() <= tol);
    }

    #[test]
    fn reverse_runs_backwards(c in curve::<2>(0..=20, 10.0), s in unit_parameter()) {
        prop_assert!((c.reverse().eval(s).unwrap() - c.eval(1.0 - s).unwrap()).norm() <= 1e-12 * scale(&c));
    }

    #[test]
    fn fast_evaluation_agrees_with_de_casteljau(c in curve::<2>(0..=50, 1.0), s in unit_parameter()) {
        let mut out = Vec::new();
        c.eval_many(&[s], &mut out).unwrap();
        prop_assert!((out[0] - c.eval(s).unwrap()).norm() <= 1e-13);
    }

    #[test]
    fn surface_partials_commute(
        grid in control_points::<3>(11..=11, 5.0),
        u in unit_parameter(),
        v in unit_parameter(),
    ) {
        // A 4 x 3 grid (bidegree (3, 2)) from 12 random points.
        let s = BezierSurface::from_flat(3, 2, grid).unwrap();
        let uv = s.partial(1, 0).unwrap().partial(0, 1).unwrap().eval(u, v).unwrap();
        let vu = s.partial(0, 1).unwrap().partial(1, 0).unwrap().eval(u, v).unwrap();
        prop_assert!((uv - vu).norm() <= 1e-11);
        prop_assert!((s.partial(1, 1).unwrap().eval(u, v).unwrap() - uv).norm() <= 1e-11);
    }

    #[test]
    fn surface_iso_curves_agree_with_eval(grid in control_points::<3>(19..=19, 5.0), u in unit_parameter(), v in unit_parameter()) {
        let s = BezierSurface::from_flat(4, 3, grid).unwrap();
        let p = s.eval(u, v).unwrap();
        prop_assert!((s.curve_at_u(u).unwrap().eval(v).unwrap() - p).norm() <= 1e-12);
        prop_assert!((s.curve_at_v(v).unwrap().eval(u).unwrap() - p).norm() <= 1e-12);
        let _: Vector3 = p;
    }
}
