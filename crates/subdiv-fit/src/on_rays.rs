//! Least squares with some control points constrained to rays (the project's addition, for the
//! neighbours of kept corners in [`Reduction::Refit`](crate::Reduction::Refit)).
//!
//! A corner's turn is its control polygon's turn, so its neighbour `p₁` must lie on the corner's
//! tangent ray: `p₁ = p₀ + λ t` (corner `p₀`, unit tangent `t`), one unknown `λ` instead of `D`.
//! The normal equations `N X = B` of the free control points (`N` the band of the refit, the
//! same for every coordinate) then hold in every free row but the constrained ones, where only
//! the component along `t` of the gradient vanishes:
//!
//! `N X − B = Σ_c e_c μ_cᵀ`, `μ_c ⊥ t_c`, `X_c = p₀_c + λ_c t_c`,
//!
//! so `X = X⁰ + Σ_c g_c μ_cᵀ` with `X⁰ = N⁻¹ B` (the unconstrained solution) and `g_c = N⁻¹ e_c`,
//! and the `μ_c` and `λ_c` solve a dense system of `(D + 1)` equations per constrained point:
//! `Σ_l (g_l)_c μ_l − λ_c t_c = p₀_c − X⁰_c` and `t_cᵀ μ_c = 0`. One band solve per constrained
//! point more than the unconstrained solve, O(u) each; the constrained points are optimal along
//! their rays together with all the others.
//!
//! At a curved corner (module `curved_corner`) the side's tangent follows a combination
//! `X_c − κ X_w` of the neighbour and the free point beyond it; the constraint row `e_c` is then
//! `a_c = e_c − κ e_w` throughout: `g_c = N⁻¹ a_c` and `a_cᵀ X` in place of `X_c`.

use crate::banded::BandFactor;

/// A constraint of [`solve_on_rays`]: unknown `column`, less `partner.1` times unknown
/// `partner.0` if given, is `anchor + λ direction` (`direction` a unit vector).
#[derive(Debug, Clone, Copy)]
pub(crate) struct RayColumn<const D: usize> {
    pub(crate) column: usize,
    pub(crate) partner: Option<(usize, f64)>,
    pub(crate) anchor: [f64; D],
    pub(crate) direction: [f64; D],
}

/// The minimizer of `Σ_d (½ X_dᵀ N X_d − B_dᵀ X_d)` over the unknowns `X` (one row per column of
/// `n`, `D` coordinates) with the `rays` constraints, and their `λ`. `None` when a system is
/// singular or the result not finite.
pub(crate) fn solve_on_rays<const D: usize>(
    n: &BandFactor,
    b: &[[f64; D]],
    rays: &[RayColumn<D>],
) -> Option<(Vec<[f64; D]>, Vec<f64>)> {
    let mut x = n.solve(b)?;
    if rays.is_empty() {
        return Some((x, Vec::new()));
    }
    let u = b.len();
    // g_c = N⁻¹ a_c.
    let g: Vec<Vec<[f64; 1]>> = rays
        .iter()
        .map(|r| {
            let mut e = vec![[0.0]; u];
            e[r.column][0] = 1.0;
            if let Some((w, k)) = r.partner {
                e[w][0] -= k;
            }
            n.solve(&e)
        })
        .collect::<Option<_>>()?;
    // a_cᵀ v for a column vector v given by its rows.
    let along = |ray: &RayColumn<D>, v: &dyn Fn(usize) -> f64| {
        v(ray.column) - ray.partner.map_or(0.0, |(w, k)| k * v(w))
    };
    // Unknowns: μ_l (D each) then λ_l; equations: D per ray, then one per ray.
    let r = rays.len();
    let size = r * (D + 1);
    let mut m = vec![vec![0.0; size + 1]; size];
    for (c, ray) in rays.iter().enumerate() {
        for d in 0..D {
            let row = c * D + d;
            for (l, gl) in g.iter().enumerate() {
                m[row][l * D + d] = along(ray, &|i| gl[i][0]);
            }
            m[row][r * D + c] = -ray.direction[d];
            m[row][size] = ray.anchor[d] - along(ray, &|i| x[i][d]);
            m[r * D + c][c * D + d] = ray.direction[d];
        }
    }
    let z = gauss(m)?;
    for (l, gl) in g.iter().enumerate() {
        for (row, gv) in x.iter_mut().zip(gl) {
            for d in 0..D {
                row[d] += gv[0] * z[l * D + d];
            }
        }
    }
    let lambdas: Vec<f64> = (0..r).map(|c| z[r * D + c]).collect();
    // On the rays to the last bit where the point is alone (a combination holds to rounding).
    for (ray, &lambda) in rays
        .iter()
        .zip(&lambdas)
        .filter(|(r, _)| r.partner.is_none())
    {
        for ((xd, a), t) in x[ray.column].iter_mut().zip(ray.anchor).zip(ray.direction) {
            *xd = a + lambda * t;
        }
    }
    x.iter()
        .flatten()
        .chain(&lambdas)
        .all(|v| v.is_finite())
        .then_some((x, lambdas))
}

/// Gaussian elimination with partial pivoting on the augmented matrix `m` (one extra column).
#[allow(
    clippy::needless_range_loop,
    reason = "elimination reads clearest with the matrix indices"
)]
fn gauss(mut m: Vec<Vec<f64>>) -> Option<Vec<f64>> {
    let size = m.len();
    let scale = m
        .iter()
        .flat_map(|row| &row[..size])
        .fold(0.0_f64, |a, v| a.max(v.abs()));
    for col in 0..size {
        let pivot = (col..size).max_by(|&a, &b| m[a][col].abs().total_cmp(&m[b][col].abs()))?;
        let usable = m[pivot][col].abs() > 1e-14 * scale;
        if !usable {
            return None;
        }
        m.swap(col, pivot);
        for row in col + 1..size {
            let f = m[row][col] / m[col][col];
            if f != 0.0 {
                for c in col..=size {
                    m[row][c] -= f * m[col][c];
                }
            }
        }
    }
    let mut z = vec![0.0; size];
    for row in (0..size).rev() {
        let s: f64 = (row + 1..size).map(|c| m[row][c] * z[c]).sum();
        z[row] = (m[row][size] - s) / m[row][row];
    }
    Some(z)
}

#[cfg(test)]
mod tests {
    use super::{RayColumn, solve_on_rays};
    use crate::banded::CyclicBand;
    use nalgebra::{DMatrix, DVector};
    use proptest::prelude::*;

    /// A normal matrix of least squares on `u` unknowns (data points touching four consecutive
    /// ones, as a B-spline's) and a right-hand side, from `seed`.
    fn system(u: usize, seed: u64) -> (CyclicBand, DMatrix<f64>, Vec<[f64; 2]>) {
        let mut s = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
        let mut next = move || {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut band = CyclicBand::zeros(u);
        let mut dense = DMatrix::zeros(u, u);
        let mut rhs = vec![[0.0; 2]; u];
        for start in 0..u.saturating_sub(3) {
            for _ in 0..6 {
                let w: Vec<f64> = (0..4).map(|_| 0.05 + next()).collect();
                let v = [4.0 * next() - 2.0, 4.0 * next() - 2.0];
                for a in 0..4 {
                    for c in 0..=a {
                        assert!(band.add_lower(start + a, start + c, w[a] * w[c]));
                        dense[(start + a, start + c)] += w[a] * w[c];
                        if a != c {
                            dense[(start + c, start + a)] += w[a] * w[c];
                        }
                    }
                    for d in 0..2 {
                        rhs[start + a][d] += w[a] * v[d];
                    }
                }
            }
        }
        (band, dense, rhs)
    }

    /// The objective `Σ_d ½ X_dᵀ N X_d − B_dᵀ X_d`.
    fn objective(n: &DMatrix<f64>, b: &[[f64; 2]], x: &[[f64; 2]]) -> f64 {
        (0..2)
            .map(|d| {
                let xd = DVector::from_iterator(x.len(), x.iter().map(|p| p[d]));
                let bd = DVector::from_iterator(b.len(), b.iter().map(|p| p[d]));
                0.5 * xd.dot(&(n * &xd)) - bd.dot(&xd)
            })
            .sum()
    }

    /// The best `X` with the rows `fixed` at the given points: the others by a dense solve.
    fn with_fixed(n: &DMatrix<f64>, b: &[[f64; 2]], fixed: &[(usize, [f64; 2])]) -> Vec<[f64; 2]> {
        let u = b.len();
        let free: Vec<usize> = (0..u).filter(|i| fixed.iter().all(|f| f.0 != *i)).collect();
        let nff = DMatrix::from_fn(free.len(), free.len(), |i, j| n[(free[i], free[j])]);
        let lu = nff.lu();
        let mut x = vec![[0.0; 2]; u];
        for &(i, p) in fixed {
            x[i] = p;
        }
        for d in 0..2 {
            let rhs = DVector::from_fn(free.len(), |i, _| {
                b[free[i]][d]
                    - fixed
                        .iter()
                        .map(|&(c, p)| n[(free[i], c)] * p[d])
                        .sum::<f64>()
            });
            let sol = lu.solve(&rhs).unwrap();
            for (i, &f) in free.iter().enumerate() {
                x[f][d] = sol[i];
            }
        }
        x
    }

    /// Golden-section minimum of a unimodal `f` on `[a, b]`.
    fn golden(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
        let r = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..200 {
            let (c, d) = (b - r * (b - a), a + r * (b - a));
            if f(c) < f(d) {
                b = d;
            } else {
                a = c;
            }
        }
        0.5 * (a + b)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        /// One ray at the first unknown, or one at each end: the constrained solve is the
        /// minimum of the objective found by a brute-force search over λ (golden section, the
        /// others solved densely for each λ; with two rays, coordinate descent of such searches),
        /// and the constrained rows lie on their rays.
        #[test]
        fn the_constrained_solve_is_the_minimum_along_the_rays(
            seed in 0u64..1_000_000,
            u in 5usize..14,
            angles in (0.0..std::f64::consts::TAU, 0.0..std::f64::consts::TAU),
            two in proptest::bool::ANY,
        ) {
            let (band, dense, rhs) = system(u, seed);
            let rays: Vec<RayColumn<2>> = [(0, angles.0), (u - 1, angles.1)]
                .iter()
                .take(if two { 2 } else { 1 })
                .map(|&(column, a)| RayColumn {
                    column,
                    partner: None,
                    anchor: [0.3 * a, -0.2],
                    direction: [a.cos(), a.sin()],
                })
                .collect();
            let (x, lambdas) = solve_on_rays(&band.factor().unwrap(), &rhs, &rays).unwrap();
            let at = |ray: &RayColumn<2>, l: f64| {
                (ray.column, [ray.anchor[0] + l * ray.direction[0], ray.anchor[1] + l * ray.direction[1]])
            };
            for (ray, &l) in rays.iter().zip(&lambdas) {
                prop_assert_eq!(x[ray.column], at(ray, l).1);
            }
            // Brute force: coordinate descent over the λ's, each a golden-section search.
            let mut best: Vec<f64> = vec![0.0; rays.len()];
            for _ in 0..if two { 60 } else { 1 } {
                for m in 0..rays.len() {
                    let cost = |l: f64| {
                        let fixed: Vec<(usize, [f64; 2])> = rays
                            .iter()
                            .enumerate()
                            .map(|(i, r)| at(r, if i == m { l } else { best[i] }))
                            .collect();
                        objective(&dense, &rhs, &with_fixed(&dense, &rhs, &fixed))
                    };
                    best[m] = golden(cost, -100.0, 100.0);
                }
            }
            let fixed: Vec<(usize, [f64; 2])> =
                rays.iter().zip(&best).map(|(r, &l)| at(r, l)).collect();
            let brute = objective(&dense, &rhs, &with_fixed(&dense, &rhs, &fixed));
            let ours = objective(&dense, &rhs, &x);
            prop_assert!(ours <= brute + 1e-9 * (1.0 + brute.abs()), "{ours} vs {brute}");
            for (l, b) in lambdas.iter().zip(&best) {
                prop_assert!((l - b).abs() < 1e-5 * (1.0 + b.abs()), "{l} vs {b}");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]
        /// A ray on a combination `X_c − κ X_w` (a curved corner's side): the solution meets the
        /// constraint and the optimality conditions of the convex problem (the gradient
        /// `N X − B` vanishes in every other row, is `μ ⊥ t` in row c and `−κ μ` in row w), so it
        /// is the constrained minimum.
        #[test]
        fn a_ray_on_a_combination_meets_the_optimality_conditions(
            seed in 0u64..1_000_000,
            u in 5usize..14,
            angle in 0.0..std::f64::consts::TAU,
            kappa in -0.5..0.5f64,
        ) {
            let (band, dense, rhs) = system(u, seed);
            let ray = RayColumn {
                column: 0,
                partner: Some((1, kappa)),
                anchor: [0.3, -0.2],
                direction: [angle.cos(), angle.sin()],
            };
            let (x, lambdas) = solve_on_rays(&band.factor().unwrap(), &rhs, &[ray]).unwrap();
            let scale = rhs.iter().flatten().fold(1.0_f64, |m, v| m.max(v.abs()));
            for ((&x0, &x1), (&a, &t)) in x[0].iter().zip(&x[1]).zip(ray.anchor.iter().zip(&ray.direction)) {
                let (on, want) = (x0 - kappa * x1, a + lambdas[0] * t);
                prop_assert!((on - want).abs() < 1e-9 * scale, "{on} vs {want}");
            }
            let grad: Vec<[f64; 2]> = (0..u)
                .map(|i| {
                    let mut g = [-rhs[i][0], -rhs[i][1]];
                    for (j, xj) in x.iter().enumerate() {
                        g[0] += dense[(i, j)] * xj[0];
                        g[1] += dense[(i, j)] * xj[1];
                    }
                    g
                })
                .collect();
            let tol = 1e-8 * scale;
            for g in &grad[2..] {
                prop_assert!(g[0].abs() < tol && g[1].abs() < tol, "{g:?}");
            }
            let mu = grad[0];
            prop_assert!((mu[0] * ray.direction[0] + mu[1] * ray.direction[1]).abs() < tol);
            for d in 0..2 {
                prop_assert!((grad[1][d] + kappa * mu[d]).abs() < tol, "{:?} {mu:?}", grad[1]);
            }
        }
    }
}
