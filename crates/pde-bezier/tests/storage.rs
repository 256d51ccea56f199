//! Dense and sparse factorizations of the same system give the same surface, for every
//! method (Cholesky for Galerkin with fixed sides, LU for collocation, QR for least squares).

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

mod common;

use common::random_surface;
use pde_bezier::{Assembly, Discretization, Method, Operator, Problem, Storage};

/// Both storages reproduce the polynomial X (an independent oracle) and agree with each
/// other in every control point.
fn assert_storages_agree(op: Operator, disc: &Discretization, tol: f64) {
    let x = random_surface(4, 3, 7);
    let problem = Problem::manufactured(op, &x).unwrap();
    let assembly = Assembly::new(&problem, disc).unwrap();
    for method in Method::ALL {
        let dense = assembly.solve_with(method, Storage::Dense).unwrap();
        let sparse = assembly.solve_with(method, Storage::Sparse).unwrap();
        for sol in [&dense, &sparse] {
            let err = sol
                .surface
                .error_norms(|u, v| x.eval(u, v).unwrap(), 20)
                .unwrap();
            assert!(err.max < tol, "{method:?}: max error {}", err.max);
        }
        for (p, q) in dense.spline.points.iter().zip(&sparse.spline.points) {
            assert!((*p - *q).norm() < tol, "{method:?}: {p:?} vs {q:?}");
        }
        // The condition estimate is of the same scaled system on both paths.
        let ratio = dense.condition / sparse.condition;
        assert!((0.999..1.001).contains(&ratio), "{method:?}: {ratio}");
    }
}

#[test]
fn second_order_dirichlet_grid() {
    let disc = Discretization {
        patches_u: 3,
        patches_v: 2,
        smoothness_u: 2,
        smoothness_v: 1,
        ..Discretization::single(5, 5)
    };
    assert_storages_agree(Operator::second_order(1.0, 2.5).unwrap(), &disc, 1e-10);
}

#[test]
fn fourth_order_dirichlet_grid() {
    let disc = Discretization {
        patches_u: 2,
        patches_v: 3,
        smoothness_u: 3,
        smoothness_v: 3,
        ..Discretization::single(6, 6)
    };
    assert_storages_agree(Operator::bloor_wilson(0.8).unwrap(), &disc, 1e-9);
}
