//! Problems manufactured from a known polynomial surface: F = L X and the boundary data of X.
//!
//! If X has a bidegree within the trial space, every method must return X to rounding
//! (polynomial exactness), which is the basic test of every solver in this crate.

use crate::error::PdeError;
use crate::problem::{Operator, Problem, Side, SideCurve};
use bez_core::{BezierSurface, Vector3};

/// L X as a Bézier surface over [0, 1]² (each term's partial elevated to the common degree).
///
/// # Errors
/// Kernel errors only (none for a valid surface).
pub fn apply_operator(op: &Operator, x: &BezierSurface<3>) -> Result<BezierSurface<3>, PdeError> {
    let parts: Vec<(f64, BezierSurface<3>)> = op
        .terms()
        .iter()
        .map(|t| Ok((t.coeff, x.partial(t.du, t.dv)?)))
        .collect::<Result<_, PdeError>>()?;
    let du = parts.iter().map(|(_, s)| s.degree_u()).max().unwrap_or(0);
    let dv = parts.iter().map(|(_, s)| s.degree_v()).max().unwrap_or(0);
    let mut points = vec![Vector3::zeros(); (du + 1) * (dv + 1)];
    for (c, s) in parts {
        let s = s
            .elevate_u(du - s.degree_u())?
            .elevate_v(dv - s.degree_v())?;
        for (p, q) in points.iter_mut().zip(s.points()) {
            *p += q * c;
        }
    }
    Ok(BezierSurface::from_flat(du, dv, points)?)
}

/// The side data of X: ∂^i X/∂u^i at u = 0 or 1 (curves in v), ∂^i X/∂v^i at v = 0 or 1
/// (curves in u), for i = 0..count.
///
/// `side` is 0..4 for u=0, u=1, v=0, v=1.
///
/// # Errors
/// [`PdeError::TooLarge`] for more than 3 curves (operators have order at most 6) or a side
/// index above 3; kernel errors.
pub fn side_of(x: &BezierSurface<3>, side: usize, count: usize) -> Result<Side, PdeError> {
    for (what, value, limit) in [("side curve count", count, 3), ("side index", side, 3)] {
        if value > limit {
            return Err(PdeError::TooLarge { what, value, limit });
        }
    }
    let t = if side % 2 == 1 { 1.0 } else { 0.0 };
    let curves = (0..count)
        .map(|i| {
            let c = if side < 2 {
                x.partial(i, 0)?.curve_at_u(t)?
            } else {
                x.partial(0, i)?.curve_at_v(t)?
            };
            Ok(SideCurve::Bezier(c))
        })
        .collect::<Result<Vec<_>, PdeError>>()?;
    Ok(Side::Fixed(curves))
}

impl Problem {
    /// The problem whose exact solution is the polynomial surface X: F = L X and all four
    /// sides fixed with the data of X.
    ///
    /// # Errors
    /// Kernel errors only.
    pub fn manufactured(op: Operator, x: &BezierSurface<3>) -> Result<Self, PdeError> {
        let half = op.order() / 2;
        Ok(Self {
            rhs: Some(apply_operator(&op, x)?),
            u0: side_of(x, 0, half)?,
            u1: side_of(x, 1, half)?,
            v0: side_of(x, 2, half)?,
            v1: side_of(x, 3, half)?,
            operator: op,
        })
    }
}
