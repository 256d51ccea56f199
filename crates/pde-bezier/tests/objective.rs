//! The reported objective and convex-hull bound, and the degree selection of step 1.

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

use bez_core::{BezierCurve, BezierSurface, Vector3};
use pde_bezier::{Method, Problem, Side, SideCurve, apply_operator, cases, solve};

#[test]
fn bernstein_least_squares_minimizes_the_reported_objective() {
    for case in [
        cases::circle_sphere_blend(3.0, std::f64::consts::PI).unwrap(),
        cases::enneper(3, 2, 2).unwrap(),
    ] {
        let best = solve(&case.problem, &case.disc, Method::BernsteinLeastSquares).unwrap();
        for method in Method::ALL {
            let other = solve(&case.problem, &case.disc, method).unwrap();
            assert!(
                best.objective <= other.objective * (1.0 + 1e-10),
                "{}: {method:?} {} < {}",
                case.label,
                other.objective,
                best.objective
            );
        }
        assert!(best.objective > 0.0);
    }
}

#[test]
fn residual_bound_is_a_convex_hull_bound() {
    let case = cases::circle_sphere_blend(1.0, std::f64::consts::PI).unwrap();
    let sol = solve(&case.problem, &case.disc, Method::Galerkin).unwrap();
    let patch = sol.surface.patch(0, 0).unwrap();
    // F = 0 here, so R = L P.
    let r = apply_operator(&case.problem.operator, patch).unwrap();
    let mut max: f64 = 0.0;
    for i in 0..=40 {
        for j in 0..=40 {
            max = max.max(r.eval(i as f64 / 40.0, j as f64 / 40.0).unwrap().norm());
        }
    }
    assert!(
        max <= sol.residual_bound * (1.0 + 1e-12),
        "{max} > {}",
        sol.residual_bound
    );
    // The bound is not absurdly loose.
    assert!(sol.residual_bound < 100.0 * max);
    // The objective is the squared coefficient norm of R on the single patch.
    let m: f64 = r.points().iter().map(|p| p.norm_squared()).sum();
    assert!(
        (m - sol.objective).abs() <= 1e-9 * m.max(1e-300),
        "{m} vs {}",
        sol.objective
    );
}

#[test]
fn default_degrees_follow_step_one() {
    let curve = |deg: usize| {
        SideCurve::Bezier(
            BezierCurve::new(
                (0..=deg)
                    .map(|i| Vector3::new(i as f64, 0.0, 0.0))
                    .collect(),
            )
            .unwrap(),
        )
    };
    let mut p = Problem {
        operator: pde_bezier::Operator::second_order(1.0, 1.0).unwrap(),
        rhs: None,
        u0: Side::Fixed(vec![curve(6)]),
        u1: Side::Fixed(vec![curve(2)]),
        v0: Side::Free,
        v1: Side::Free,
    };
    // n = max{k+1, deg r0, deg s0, deg^u F} = 3; m = max{deg f0, deg g0, deg^v F} = 6.
    assert_eq!(p.default_degrees(), (3, 6));
    p.v0 = Side::Fixed(vec![curve(4)]);
    p.v1 = Side::Fixed(vec![curve(1)]);
    assert_eq!(p.default_degrees(), (4, 6));
    p.rhs = Some(BezierSurface::from_flat(7, 0, vec![Vector3::zeros(); 8]).unwrap());
    assert_eq!(p.default_degrees(), (7, 6));
    p.u0 = Side::Fixed(vec![curve(1)]);
    p.u1 = Side::Fixed(vec![curve(1)]);
    // v-sides carry conditions: m is raised to k + 1.
    assert_eq!(p.default_degrees(), (7, 3));
}
