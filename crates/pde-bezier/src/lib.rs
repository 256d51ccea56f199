//! # pde-bezier
//!
//! Xu Gang, Wang Guozhao. *Bézier approximation of PDE surface.* Journal of Software
//! 18(11):2914–2920, 2007.
//!
//! Bézier surfaces that approximately solve a linear elliptic PDE L X = F (L a sum of
//! constant-coefficient derivatives of even order 2, 4 or 6, F a polynomial) under boundary
//! conditions on positions and cross-boundary derivatives. The unknown control points of
//! P(u, v) = Σ B_i^n(u) B_j^m(v) a_ij enter the Bernstein coefficients b_ij of the residual
//! R = L P − F linearly; the paper minimizes M = Σ |b_ij|² (eq. (4)) subject to the boundary
//! conditions. The improved algorithm (Sec. 3) uses a uniform grid of C^r patches with the
//! area-weighted objective.
//!
//! Here the trial space is always a tensor-product spline space (one patch, or a grid with
//! C^r joins parametrized by B-spline coefficients and Bézier extraction, optionally periodic);
//! boundary conditions fix whole rows of coefficients and are eliminated. On the same space,
//! four [`Method`]s: the paper's Bernstein least squares, the exact ∫∫R² least squares, and
//! the Bloor–Wilson baselines, collocation and Galerkin. The `cases` module (feature `paper`) holds the
//! paper's examples with exact solutions. The result exports to CAD as one B-spline surface
//! ([`Solution::spline`], [`write_step`] for STEP AP214, [`write_iges`] for IGES entity 128).
//!
//! ```
//! use bez_core::{BezierSurface, Vector3};
//! use pde_bezier::{Discretization, Method, Operator, Problem, solve};
//!
//! // A harmonic polynomial surface X = (u, v, u² − v²) is reproduced exactly.
//! let pts: Vec<_> = (0..=2)
//!     .flat_map(|i| (0..=2).map(move |j| (i as f64 / 2.0, j as f64 / 2.0)))
//!     .map(|(u, v)| Vector3::new(u, v, 0.0))
//!     .collect();
//! let mut x = BezierSurface::from_flat(2, 2, pts)?;
//! // Bernstein coefficients of u² − v²: u² → (0, 0, 1), v² likewise.
//! let z = [0.0, 0.0, -1.0, 0.0, 0.0, -1.0, 1.0, 1.0, 0.0];
//! let pts: Vec<_> = x.points().iter().zip(z).map(|(p, z)| Vector3::new(p.x(), p.y(), z)).collect();
//! x = BezierSurface::from_flat(2, 2, pts)?;
//! let problem = Problem::manufactured(Operator::second_order(1.0, 1.0)?, &x)?;
//! let sol = solve(&problem, &Discretization::single(4, 4), Method::BernsteinLeastSquares)?;
//! let p = sol.surface.eval(0.3, 0.8)?;
//! assert!((p - Vector3::new(0.3, 0.8, 0.09 - 0.64)).norm() < 1e-12);
//! assert!(sol.residual_bound < 1e-10);
//! # Ok::<(), pde_bezier::PdeError>(())
//! ```

mod bernstein_ops;
mod boundary;
#[cfg(feature = "paper")]
pub mod cases;
mod dense;
mod error;
mod grid;
mod iges;
mod limits;
mod manufactured;
mod problem;
mod quadrature;
mod solve;
mod space;
mod sparse;
mod spline_surface;
mod step;
mod symbol;

pub use crate::error::PdeError;
pub use crate::grid::{ErrorNorms, MAX_ERROR_GRID, PatchGrid};
pub use crate::iges::{read_iges, write_iges};
pub use crate::limits::{
    MAX_COEFFICIENTS, MAX_DENSE_ENTRIES, MAX_LOCAL_ENTRIES, MAX_PATCHES, MAX_SOLVE_DEGREE,
};
pub use crate::manufactured::{apply_operator, side_of};
pub use crate::problem::{Discretization, MAX_JET, Operator, Problem, Side, SideCurve, Term};
pub use crate::solve::{Assembly, Method, Solution, solve};
pub use crate::sparse::{
    CONDITION_LIMIT, DENSE_LEAST_SQUARES_UNKNOWNS, DENSE_SQUARE_UNKNOWNS, DENSE_SYMMETRIC_UNKNOWNS,
    Storage,
};
pub use crate::spline_surface::BSplineSurface;
pub use crate::step::{read_step, write_step};

/// The README's example, compiled and run with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
