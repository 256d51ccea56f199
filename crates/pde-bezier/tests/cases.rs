//! The paper's examples: exact solutions satisfy their PDEs, and the solvers converge.

use pde_bezier::cases::{self, Exact};
use pde_bezier::{Method, solve};

/// L X by central differences (second-order operators only).
fn laplace_like(exact: &Exact, cu: f64, cv: f64, u: f64, v: f64) -> f64 {
    let h = 1e-4;
    let f = |a: f64, b: f64| exact.eval(a, b);
    let uu = (f(u + h, v) - 2.0 * f(u, v) + f(u - h, v)) / (h * h);
    let vv = (f(u, v + h) - 2.0 * f(u, v) + f(u, v - h)) / (h * h);
    (uu * cu + vv * cv).norm()
}

#[test]
fn exact_solutions_solve_their_pdes() {
    let theta = std::f64::consts::FRAC_PI_2;
    for (exact, cu, cv) in [
        (
            Exact::CircleSphereBlend { a: 3.0, theta },
            1.0,
            3.0 / (theta * theta),
        ),
        (Exact::Vase, 5.0, 1.0),
        (Exact::Enneper { k: 3 }, 1.0, 1.0),
    ] {
        for (u, v) in [(0.3, 0.4), (0.7, 0.2), (0.5, 0.9)] {
            assert!(laplace_like(&exact, cu, cv, u, v) < 1e-3, "{exact:?}");
        }
    }
    // Problem (5)'s boundary: radius √3 at height 3, radius 3 at height 0.
    let e = Exact::CircleSphereBlend { a: 1.0, theta: 1.0 };
    let p = e.eval(0.0, 0.0);
    assert!((p.x() - 3.0_f64.sqrt()).abs() < 1e-15 && (p.z() - 3.0).abs() < 1e-15);
    // Fig. 4: plane trim circle at u = 0, cylinder at u = 1, X_u radial inward / vertical.
    let e = Exact::CylinderPlane;
    let p = e.eval(0.0, 0.25);
    assert!((p - bez_core::Vector3::new(0.0, 2.0, 0.0)).norm() < 1e-12);
    let q = e.eval(0.0, 0.0);
    assert!((q.z() - q.x() / 3.0_f64.sqrt()).abs() < 1e-12);
    let top = e.eval(1.0, 0.1);
    assert!((top.z() - 2.0).abs() < 1e-12 && (top.xy().norm() - 1.0).abs() < 1e-12);
    let du = e.eval_du(1.0, 0.3, 1);
    assert!((du - bez_core::Vector3::new(0.0, 0.0, 2.0)).norm() < 1e-12);
    // The biharmonic-type equation in the separated form: A'''' − 2A'' + A = 0 by differences.
    let h = 1e-2;
    let a = |u: f64| e.eval(u, 0.0).x();
    let u = 0.5;
    let d4 = (a(u + 2.0 * h) - 4.0 * a(u + h) + 6.0 * a(u) - 4.0 * a(u - h) + a(u - 2.0 * h))
        / h.powi(4);
    let d2 = (a(u + h) - 2.0 * a(u) + a(u - h)) / (h * h);
    assert!((d4 - 2.0 * d2 + a(u)).abs() < 1e-2);
}

#[test]
fn enneper_k1_is_reproduced_on_a_cubic_patch() {
    let mut case = cases::enneper(1, 1, 1).unwrap();
    case.disc = pde_bezier::Discretization::single(3, 3);
    for method in Method::ALL {
        let sol = solve(&case.problem, &case.disc, method).unwrap();
        let err = sol
            .surface
            .error_norms(|u, v| case.exact.eval(u, v), 20)
            .unwrap();
        assert!(err.max < 1e-10, "{method:?}: {}", err.max);
    }
}

#[test]
fn every_case_solves_with_small_error() {
    for case in cases::paper_cases().unwrap() {
        // A septic boundary on one quintic patch is a poor fit by construction.
        if case.disc.patches_u == 1 && case.figure == 5 {
            continue;
        }
        let sol = solve(&case.problem, &case.disc, Method::BernsteinLeastSquares).unwrap();
        let err = sol
            .surface
            .error_norms(|u, v| case.exact.eval(u, v), 20)
            .unwrap();
        assert!(err.max < 5e-2, "{}: {}", case.label, err.max);
    }
}
