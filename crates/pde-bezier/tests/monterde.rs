//! Galerkin for Laplace's operator on one patch equals Monterde's Dirichlet-extremal harmonic
//! Bézier surface: the interior control points minimize ∫∫ |P_u|² + |P_v|² with the boundary
//! rows fixed (Monterde & Ugail 2004). Computed here from the Gram matrices of the Bernstein
//! basis and its derivatives, independently of the crate's residual map.

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

mod common;

use bez_core::{BezierSurface, Vector3, binomial};
use common::random_surface;
use nalgebra::DMatrix;
use pde_bezier::{Discretization, Method, Operator, Problem, side_of, solve};

/// ∫ B_i^n B_k^n.
fn gram(n: usize) -> DMatrix<f64> {
    DMatrix::from_fn(n + 1, n + 1, |i, k| {
        binomial(n, i) * binomial(n, k) / ((2 * n + 1) as f64 * binomial(2 * n, i + k))
    })
}

/// ∫ (B_i^n)' (B_k^n)' = n² Σ (δ-differences of degree n−1 Gram entries).
fn stiffness(n: usize) -> DMatrix<f64> {
    let g = gram(n - 1);
    let at = |i: isize, k: isize| -> f64 {
        if i < 0 || k < 0 || i > (n - 1) as isize || k > (n - 1) as isize {
            0.0
        } else {
            g[(i as usize, k as usize)]
        }
    };
    DMatrix::from_fn(n + 1, n + 1, |i, k| {
        let (i, k) = (i as isize, k as isize);
        let nn = (n * n) as f64;
        nn * (at(i - 1, k - 1) - at(i - 1, k) - at(i, k - 1) + at(i, k))
    })
}

/// Minimizes a quadratic energy over the control points at least `fixed` rows away from every
/// side, the others held at `boundary`'s: solves Σ_kl w(i, j, k, l) a_kl = 0 for every free
/// (i, j), where w is the energy's Hessian entry.
fn extremal(
    boundary: &BezierSurface<3>,
    fixed: usize,
    w: impl Fn(usize, usize, usize, usize) -> f64,
) -> BezierSurface<3> {
    let (n, m) = (boundary.degree_u(), boundary.degree_v());
    let idx = |i: usize, j: usize| i * (m + 1) + j;
    let interior: Vec<(usize, usize)> = (fixed..=n - fixed)
        .flat_map(|i| (fixed..=m - fixed).map(move |j| (i, j)))
        .collect();
    let pos = |i: usize, j: usize| interior.iter().position(|&p| p == (i, j));
    let size = interior.len();
    let mut a = DMatrix::<f64>::zeros(size, size);
    let mut b = DMatrix::<f64>::zeros(size, 3);
    for (r, &(i, j)) in interior.iter().enumerate() {
        for k in 0..=n {
            for l in 0..=m {
                let wt = w(i, j, k, l);
                match pos(k, l) {
                    Some(c) => a[(r, c)] += wt,
                    None => {
                        let p = boundary.points()[idx(k, l)];
                        for d in 0..3 {
                            b[(r, d)] -= wt * p[d];
                        }
                    }
                }
            }
        }
    }
    let x = a.lu().solve(&b).unwrap();
    let mut pts = boundary.points().to_vec();
    for (r, &(i, j)) in interior.iter().enumerate() {
        pts[idx(i, j)] = Vector3::new(x[(r, 0)], x[(r, 1)], x[(r, 2)]);
    }
    BezierSurface::from_flat(n, m, pts).unwrap()
}

/// Minimizes ∫∫ |P_u|² + |P_v|² with the outer row of control points on every side fixed.
fn dirichlet_extremal(boundary: &BezierSurface<3>) -> BezierSurface<3> {
    let (n, m) = (boundary.degree_u(), boundary.degree_v());
    let (an, cn, am, cm) = (gram(n), stiffness(n), gram(m), stiffness(m));
    extremal(boundary, 1, |i, j, k, l| {
        cn[(i, k)] * am[(j, l)] + an[(i, k)] * cm[(j, l)]
    })
}

#[test]
fn galerkin_laplace_is_monterde_dirichlet_extremal() {
    for (n, m, seed) in [(4usize, 4usize, 1u64), (5, 3, 2), (6, 5, 3)] {
        let x = random_surface(n, m, seed);
        let problem = Problem {
            operator: Operator::second_order(1.0, 1.0).unwrap(),
            rhs: None,
            u0: side_of(&x, 0, 1).unwrap(),
            u1: side_of(&x, 1, 1).unwrap(),
            v0: side_of(&x, 2, 1).unwrap(),
            v1: side_of(&x, 3, 1).unwrap(),
        };
        let sol = solve(&problem, &Discretization::single(n, m), Method::Galerkin).unwrap();
        let oracle = dirichlet_extremal(&x);
        let ours = sol.surface.patch(0, 0).unwrap();
        for (p, q) in ours.points().iter().zip(oracle.points()) {
            assert!((p - q).norm() < 1e-11, "({n}, {m}): {p} vs {q}");
        }
        // The other objectives give different interior points (the comparison is not vacuous).
        let ls = solve(
            &problem,
            &Discretization::single(n, m),
            Method::BernsteinLeastSquares,
        )
        .unwrap();
        let gap: f64 = ls
            .surface
            .patch(0, 0)
            .unwrap()
            .points()
            .iter()
            .zip(oracle.points())
            .map(|(p, q)| (p - q).norm())
            .fold(0.0, f64::max);
        assert!(
            gap > 1e-6,
            "least squares coincided with the Dirichlet extremal"
        );
    }
}

/// ∫ (B_i^n)^(p) (B_k^n)^(q) for p, q ≤ 2, from the Bernstein derivative expansion and the
/// closed-form mixed Gram matrix.
fn derivative_gram(n: usize, p: usize, q: usize) -> DMatrix<f64> {
    // (B_i^n)^(p) = n!/(n−p)! Σ_a (−1)^(p−a) C(p, a) B_{i−a}^{n−p}.
    let expand = |i: usize, p: usize| -> Vec<(usize, f64)> {
        let falling: f64 = (0..p).map(|s| (n - s) as f64).product();
        (0..=p)
            .filter(|&a| a <= i && i - a <= n - p)
            .map(|a| {
                let sign = if (p - a).is_multiple_of(2) { 1.0 } else { -1.0 };
                (i - a, falling * sign * binomial(p, a))
            })
            .collect()
    };
    let (dp, dq) = (n - p, n - q);
    DMatrix::from_fn(n + 1, n + 1, |i, k| {
        let mut s = 0.0;
        for (a, wa) in expand(i, p) {
            for (b, wb) in expand(k, q) {
                s += wa * wb * binomial(dp, a) * binomial(dq, b)
                    / ((dp + dq + 1) as f64 * binomial(dp + dq, a + b));
            }
        }
        s
    })
}

/// Minimizes ∫∫ (P_uu + P_vv)² with the two outer rows of control points on every side fixed
/// (the biharmonic extremal of Monterde & Ugail).
fn biharmonic_extremal(boundary: &BezierSurface<3>) -> BezierSurface<3> {
    let (n, m) = (boundary.degree_u(), boundary.degree_v());
    let (a_n, a_m) = (derivative_gram(n, 0, 0), derivative_gram(m, 0, 0));
    let (k_n, k_m) = (derivative_gram(n, 2, 2), derivative_gram(m, 2, 2));
    let (x_n, x_m) = (derivative_gram(n, 2, 0), derivative_gram(m, 2, 0));
    // ∂/∂a_ij of ∫ (Σ a_kl (B_k'' B_l + B_k B_l''))².
    extremal(boundary, 2, |i, j, k, l| {
        k_n[(i, k)] * a_m[(j, l)]
            + a_n[(i, k)] * k_m[(j, l)]
            + x_n[(i, k)] * x_m[(l, j)]
            + x_n[(k, i)] * x_m[(j, l)]
    })
}

#[test]
fn galerkin_biharmonic_is_the_biharmonic_extremal() {
    for (n, m, seed) in [(5usize, 5usize, 7u64), (6, 5, 8), (7, 6, 9)] {
        let x = random_surface(n, m, seed);
        let problem = Problem {
            operator: Operator::bloor_wilson(1.0).unwrap(),
            rhs: None,
            u0: side_of(&x, 0, 2).unwrap(),
            u1: side_of(&x, 1, 2).unwrap(),
            v0: side_of(&x, 2, 2).unwrap(),
            v1: side_of(&x, 3, 2).unwrap(),
        };
        let sol = solve(&problem, &Discretization::single(n, m), Method::Galerkin).unwrap();
        let oracle = biharmonic_extremal(&x);
        let ours = sol.surface.patch(0, 0).unwrap();
        for (p, q) in ours.points().iter().zip(oracle.points()) {
            assert!((p - q).norm() < 1e-9, "({n}, {m}): {p} vs {q}");
        }
    }
}
