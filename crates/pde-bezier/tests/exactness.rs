//! Polynomial exactness of every method, single patch and patch grids.

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

mod common;

use bez_core::BezierSurface;
use common::random_surface;
use pde_bezier::{Discretization, Method, Operator, Problem, solve};

fn assert_reproduces(op: Operator, x: &BezierSurface<3>, disc: Discretization, tol: f64) {
    assert_reproduces_with_residual(op, x, disc, tol, 1e3 * tol);
}

/// `residual` bounds the convex-hull bound of the residual: on a grid of width h an
/// order-k operator scales coefficient errors by about h^−k.
fn assert_reproduces_with_residual(
    op: Operator,
    x: &BezierSurface<3>,
    disc: Discretization,
    tol: f64,
    residual: f64,
) {
    let problem = Problem::manufactured(op, x).unwrap();
    for method in Method::ALL {
        let sol = solve(&problem, &disc, method).unwrap();
        let err = sol
            .surface
            .error_norms(|u, v| x.eval(u, v).unwrap(), 20)
            .unwrap();
        assert!(err.max < tol, "{method:?} {disc:?}: max error {}", err.max);
        assert!(
            sol.residual_bound < residual,
            "{method:?}: residual {}",
            sol.residual_bound
        );
    }
}

#[test]
fn single_patch_laplace_reproduces_polynomial() {
    let x = random_surface(4, 3, 1);
    let op = Operator::second_order(1.0, 2.5).unwrap();
    assert_reproduces(op, &x, Discretization::single(5, 5), 1e-10);
}

#[test]
fn single_patch_fourth_order_reproduces_polynomial() {
    let x = random_surface(5, 4, 2);
    let op = Operator::bloor_wilson(0.8).unwrap();
    assert_reproduces(op, &x, Discretization::single(6, 6), 1e-9);
}

#[test]
fn single_patch_sixth_order_reproduces_polynomial() {
    let x = random_surface(6, 6, 3);
    let op = Operator::new(vec![
        pde_bezier::Term {
            coeff: 1.0,
            du: 6,
            dv: 0,
        },
        pde_bezier::Term {
            coeff: 0.5,
            du: 2,
            dv: 4,
        },
        pde_bezier::Term {
            coeff: 1.0,
            du: 0,
            dv: 6,
        },
    ])
    .unwrap();
    assert_reproduces(op, &x, Discretization::single(7, 7), 1e-8);
}

#[test]
fn patch_grid_reproduces_polynomial() {
    let x = random_surface(4, 4, 4);
    let op = Operator::second_order(1.0, 1.0).unwrap();
    let disc = Discretization {
        degree_u: 5,
        degree_v: 4,
        patches_u: 3,
        patches_v: 2,
        smoothness_u: 2,
        smoothness_v: 1,
    };
    assert_reproduces(op, &x, disc, 1e-10);
    let op4 = Operator::bloor_wilson(1.0).unwrap();
    let disc4 = Discretization {
        degree_u: 5,
        degree_v: 5,
        patches_u: 2,
        patches_v: 3,
        smoothness_u: 3,
        smoothness_v: 4,
    };
    assert_reproduces(op4, &x, disc4, 1e-9);
}

/// A refined fourth-order grid, 16 × 16 quintic C³ patches on the biharmonic: every method
/// within 1e-9 (the 32 × 32 grid, where normal equations lost five digits, is a row of the
/// pde-bezier-scale table: too slow for the test profile).
#[test]
fn refined_biharmonic_grid_reproduces_polynomial_with_every_method() {
    let x = random_surface(5, 5, 7);
    let op = Operator::bloor_wilson(1.0).unwrap();
    let disc = Discretization {
        degree_u: 5,
        degree_v: 5,
        patches_u: 16,
        patches_v: 16,
        smoothness_u: 3,
        smoothness_v: 3,
    };
    assert_reproduces_with_residual(op, &x, disc, 1e-9, 1e-4);
}
