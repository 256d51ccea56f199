//! Invariants: boundary interpolation, affine invariance, serde round trip.

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

use bez_core::{BezierSurface, Vector3};
use pde_bezier::{Discretization, Method, Operator, Problem, Side, SideCurve, side_of, solve};
use proptest::prelude::*;

fn surface(n: usize, m: usize, coords: &[f64]) -> BezierSurface<3> {
    let pts = coords
        .chunks(3)
        .take((n + 1) * (m + 1))
        .map(|c| Vector3::new(c[0], c[1], c[2]))
        .collect();
    BezierSurface::from_flat(n, m, pts).unwrap()
}

fn dirichlet(x: &BezierSurface<3>, op: Operator) -> Problem {
    Problem {
        operator: op,
        rhs: None,
        u0: side_of(x, 0, 1).unwrap(),
        u1: side_of(x, 1, 1).unwrap(),
        v0: side_of(x, 2, 1).unwrap(),
        v1: side_of(x, 3, 1).unwrap(),
    }
}

fn translate(side: &Side, t: Vector3) -> Side {
    match side {
        Side::Fixed(curves) => Side::Fixed(
            curves
                .iter()
                .map(|c| match c {
                    SideCurve::Bezier(b) => SideCurve::Bezier(
                        bez_core::BezierCurve::new(b.points().iter().map(|p| p + t).collect())
                            .unwrap(),
                    ),
                    other => other.clone(),
                })
                .collect(),
        ),
        other => other.clone(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn solution_interpolates_dirichlet_data_and_is_translation_invariant(
        coords in prop::collection::vec(-2.0..2.0f64, 3 * 16),
        t in prop::array::uniform3(-5.0..5.0f64),
        a in 0.3..3.0f64,
    ) {
        let x = surface(3, 3, &coords);
        let p = dirichlet(&x, Operator::second_order(1.0, a).unwrap());
        let disc = Discretization::single(5, 4);
        let t = Vector3::from(t);
        let mut q = p.clone();
        q.u0 = translate(&p.u0, t);
        q.u1 = translate(&p.u1, t);
        q.v0 = translate(&p.v0, t);
        q.v1 = translate(&p.v1, t);
        for method in Method::ALL {
            let s = solve(&p, &disc, method).unwrap();
            let s2 = solve(&q, &disc, method).unwrap();
            for k in 0..=10 {
                let w = k as f64 / 10.0;
                for (u, v) in [(0.0, w), (1.0, w), (w, 0.0), (w, 1.0)] {
                    let e = (s.surface.eval(u, v).unwrap() - x.eval(u, v).unwrap()).norm();
                    prop_assert!(e < 1e-10, "{method:?} boundary error {e}");
                }
                let d = s2.surface.eval(w, 0.5).unwrap() - s.surface.eval(w, 0.5).unwrap() - t;
                prop_assert!(d.norm() < 1e-9, "{method:?} translation error {}", d.norm());
            }
        }
    }
}

#[cfg(feature = "serde")]
#[test]
fn problem_round_trips_through_json() {
    let case = pde_bezier::cases::enneper(2, 2, 2).unwrap();
    let json = serde_json::to_string(&case.problem).unwrap();
    let back: Problem = serde_json::from_str(&json).unwrap();
    // serde_json's default float parsing may differ in the last bit: compare the solutions.
    let a = solve(&case.problem, &case.disc, Method::Galerkin).unwrap();
    let b = solve(&back, &case.disc, Method::Galerkin).unwrap();
    let e = (a.surface.eval(0.3, 0.6).unwrap() - b.surface.eval(0.3, 0.6).unwrap()).norm();
    assert!(e < 1e-12);
    let disc: Discretization =
        serde_json::from_str(&serde_json::to_string(&case.disc).unwrap()).unwrap();
    assert_eq!(disc, case.disc);
}
