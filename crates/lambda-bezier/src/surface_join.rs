//! Joining two λ-Bézier surface patches across a common boundary (the surface part the paper
//! leaves out).
//!
//! Patch A (rows P₀..P_{n_a} in u, λ_u = λ_a) and patch B (rows Q₀..Q_{n_b}) share the boundary
//! u = 1 of A and u = 0 of B when Q₀ = P_{n_a} row by row and both have the same v degree and λ_v
//! (then the boundary λ-curves in v coincide). By curve Property 1 applied to every v,
//! ∂S/∂u(0, v) of B = (n_b + λ_b) Σⱼ (Q₁ⱼ − Q₀ⱼ) bⱼ(v) and ∂S/∂u(1, v) of A =
//! (n_a + λ_a) Σⱼ (P_{n_a,j} − P_{n_a−1,j}) bⱼ(v), so setting
//! Q₁ = Q₀ + s (P_{n_a} − P_{n_a−1}) with one s > 0 makes the cross-boundary derivatives
//! positively proportional along the whole boundary, with ratio (n_b + λ_b) s / (n_a + λ_a):
//! a G1 join (common tangent plane), C1 when the ratio is 1.

use bez_core::Vector;

use crate::error::LambdaError;
use crate::surface::LambdaBezierSurface;

/// How the second patch's first interior row is placed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PatchJoin {
    /// Equal cross-boundary derivatives: s = (n_a + λ_a) / (n_b + λ_b).
    C1,
    /// Common tangent plane, keeping B's mean distance between its rows 0 and 1:
    /// s = Σⱼ |Q₁ⱼ − Q₀ⱼ| / Σⱼ |P_{n_a,j} − P_{n_a−1,j}|.
    G1,
}

/// B moved so that its boundary u = 0 is A's boundary u = 1 and the two patches join with the
/// continuity `join` across it: rows 0 and 1 of B change, the others and both λ stay.
///
/// # Errors
/// [`LambdaError::PatchMismatch`] when the v grid sizes or λ_v differ;
/// [`LambdaError::DegenerateJoint`] when A's last two rows coincide (no cross-boundary
/// tangent), B's first two rows coincide (for [`PatchJoin::G1`]) or n_b + λ_b = 0 (for
/// [`PatchJoin::C1`]); the constructor's errors for a result outside the coordinate range.
pub fn join_patches<const D: usize>(
    a: &LambdaBezierSurface<D>,
    b: &LambdaBezierSurface<D>,
    join: PatchJoin,
) -> Result<LambdaBezierSurface<D>, LambdaError> {
    if a.n_v() != b.n_v() {
        return Err(LambdaError::PatchMismatch {
            what: "the v sizes of the grids",
        });
    }
    if a.lambda_v() != b.lambda_v() {
        return Err(LambdaError::PatchMismatch { what: "λ_v" });
    }
    let (pa, qb) = (a.rows(), b.rows());
    let (last, before) = (&pa[pa.len() - 1], &pa[pa.len() - 2]);
    let across: Vec<Vector<D>> = last.iter().zip(before).map(|(p, q)| p - q).collect();
    let across_len: f64 = across.iter().map(Vector::norm).sum();
    if across_len == 0.0 || !across_len.is_finite() {
        return Err(LambdaError::DegenerateJoint { which: "incoming" });
    }
    let s = match join {
        PatchJoin::C1 => {
            let kb = b.n_u() as f64 + b.lambda_u();
            if kb <= 0.0 {
                return Err(LambdaError::DegenerateJoint { which: "outgoing" });
            }
            (a.n_u() as f64 + a.lambda_u()) / kb
        }
        PatchJoin::G1 => {
            let leg: f64 = qb[1].iter().zip(&qb[0]).map(|(p, q)| (p - q).norm()).sum();
            if leg == 0.0 || !leg.is_finite() {
                return Err(LambdaError::DegenerateJoint { which: "outgoing" });
            }
            leg / across_len
        }
    };
    let mut rows = qb.to_vec();
    rows[0].clone_from(last);
    rows[1] = last.iter().zip(&across).map(|(p, d)| p + d * s).collect();
    LambdaBezierSurface::new(rows, b.lambda_u(), b.lambda_v())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use bez_core::Vector3;

    fn patch(x0: f64, nu: usize, nv: usize, lu: f64, lv: f64) -> LambdaBezierSurface<3> {
        let rows = (0..=nu)
            .map(|i| {
                (0..=nv)
                    .map(|j| {
                        let (x, y) = (x0 + i as f64, j as f64);
                        Vector3::new(x, y, (0.7 * x - 0.4 * y).sin() + 0.1 * (i * j) as f64)
                    })
                    .collect()
            })
            .collect();
        LambdaBezierSurface::new(rows, lu, lv).unwrap()
    }

    /// Along the whole boundary: same points, cross-boundary derivatives positively
    /// proportional with one ratio (1 for C1), and the same unit normal.
    #[test]
    fn joined_patches_share_points_tangent_planes_and_for_c1_derivatives() {
        for (nu_a, nu_b, la, lb) in [(3, 3, 0.0, 0.0), (3, 4, 0.5, -0.5), (4, 2, -1.0, 0.8)] {
            let a = patch(0.0, nu_a, 3, la, 0.3);
            let b = patch(9.0, nu_b, 3, lb, 0.3);
            for join in [PatchJoin::C1, PatchJoin::G1] {
                let j = join_patches(&a, &b, join).unwrap();
                let mut ratios = Vec::new();
                for k in 0..=20 {
                    let v = k as f64 / 20.0;
                    assert!((a.eval(1.0, v).unwrap() - j.eval(0.0, v).unwrap()).norm() < 1e-12);
                    let (du_a, du_j) = (
                        a.eval_partial(1.0, v, 1, 0).unwrap(),
                        j.eval_partial(0.0, v, 1, 0).unwrap(),
                    );
                    let dv = a.eval_partial(1.0, v, 0, 1).unwrap();
                    let ratio = du_j.dot(&du_a) / du_a.norm_squared();
                    assert!((du_j - du_a * ratio).norm() < 1e-10 * du_a.norm());
                    assert!(ratio > 0.0);
                    ratios.push(ratio);
                    let (na, nj) = (du_a.cross(&dv), du_j.cross(&dv));
                    assert!((na / na.norm() - nj / nj.norm()).norm() < 1e-10);
                }
                let spread = ratios
                    .iter()
                    .fold(0.0_f64, |m, r| m.max((r - ratios[0]).abs()));
                assert!(spread < 1e-10, "ratio varies by {spread}");
                if join == PatchJoin::C1 {
                    assert!((ratios[0] - 1.0).abs() < 1e-12, "{}", ratios[0]);
                }
            }
        }
    }

    #[test]
    fn mismatched_patches_are_errors() {
        let a = patch(0.0, 3, 3, 0.0, 0.3);
        assert_eq!(
            join_patches(&a, &patch(9.0, 3, 4, 0.0, 0.3), PatchJoin::C1),
            Err(LambdaError::PatchMismatch {
                what: "the v sizes of the grids"
            })
        );
        assert_eq!(
            join_patches(&a, &patch(9.0, 3, 3, 0.0, 0.2), PatchJoin::G1),
            Err(LambdaError::PatchMismatch { what: "λ_v" })
        );
    }
}
