//! Sparse linear solves with a condition estimate: LU for square systems, Householder QR
//! for least squares (no normal equations), on faer's supernodal factorizations; a dense
//! path for tiny systems, where it is faster.
//!
//! Columns are scaled to unit 2-norm first (a square system's rows too), which leaves the
//! solution unchanged. The condition estimate is the Frobenius condition number
//! κ_F = ‖A‖_F ‖A⁺‖_F ≥ κ₂ of the scaled matrix, with ‖A⁺‖_F² = E‖A⁺ g‖² estimated from
//! [`PROBES`] random ±1 vectors g (Hutchinson's estimator), solved with the same
//! factorization as the right-hand sides.

use crate::error::PdeError;
use faer::Mat;
use faer::linalg::solvers::{Solve, SolveLstsq};
use faer::sparse::{SparseColMat, Triplet};

/// Systems with at most this many unknowns are solved densely: single patches up to about
/// bidegree (11, 11), whose matrices are nearly full. The threshold is not tuned by a
/// measurement yet.
pub(crate) const DENSE_UNKNOWNS: usize = 96;

/// Random probes of the condition estimate.
pub(crate) const PROBES: usize = 4;

/// Condition estimates above this are refused as ill-conditioned: the answer may have
/// fewer than about three correct digits.
pub const CONDITION_LIMIT: f64 = 1e13;

/// Condition estimates above this (≈ 1/ε) mean the system is numerically rank deficient.
const RANK_LIMIT: f64 = 1.0 / f64::EPSILON;

/// What kind of solve a system needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    /// A square system A x = b (LU).
    Square,
    /// min ‖A x − b‖₂ (QR).
    LeastSquares,
}

/// A sparse system with three right-hand sides (x, y, z), assembled by triplets
/// (duplicates are summed).
#[derive(Debug, Clone)]
pub(crate) struct System {
    pub(crate) nrows: usize,
    pub(crate) ncols: usize,
    pub(crate) entries: Vec<Triplet<usize, usize, f64>>,
    pub(crate) rhs: Vec<[f64; 3]>,
}

/// The solution and its condition estimate.
#[derive(Debug, Clone)]
pub(crate) struct Solved {
    pub(crate) x: Vec<[f64; 3]>,
    pub(crate) condition: f64,
}

impl System {
    /// Adds a(row, col) += val.
    pub(crate) fn push(&mut self, row: usize, col: usize, val: f64) {
        self.entries.push(Triplet { row, col, val });
    }

    pub(crate) fn new(nrows: usize, ncols: usize) -> Self {
        Self {
            nrows,
            ncols,
            entries: Vec::new(),
            rhs: vec![[0.0; 3]; nrows],
        }
    }

    /// Solves the system; `method` names it in errors.
    pub(crate) fn solve(self, kind: Kind, method: &'static str) -> Result<Solved, PdeError> {
        let (m, n) = (self.nrows, self.ncols);
        if n == 0 {
            return Ok(Solved {
                x: Vec::new(),
                condition: 1.0,
            });
        }
        let undetermined = |condition: f64| PdeError::Undetermined {
            method,
            unknowns: n,
            condition,
        };
        if m < n || (kind == Kind::Square && m != n) {
            return Err(undetermined(f64::INFINITY));
        }
        for &Triplet { val: v, .. } in &self.entries {
            if !v.is_finite() {
                return Err(PdeError::NonFinite {
                    what: "system matrix entry",
                    value: v,
                });
            }
        }
        for r in &self.rhs {
            if let Some(&v) = r.iter().find(|v| !v.is_finite()) {
                return Err(PdeError::NonFinite {
                    what: "right-hand side",
                    value: v,
                });
            }
        }
        let mut a = SparseColMat::<usize, f64>::try_new_from_triplets(m, n, &self.entries)
            .map_err(|_| undetermined(f64::INFINITY))?;
        drop(self.entries);
        // Row scaling (square systems only: it would reweight a least-squares objective).
        let mut row_scale = vec![1.0; m];
        if kind == Kind::Square {
            let mut norms = vec![0.0f64; m];
            for j in 0..n {
                let range = a.col_range(j);
                for (&i, &v) in a.row_idx()[range.clone()].iter().zip(&a.val()[range]) {
                    norms[i] = norms[i].hypot(v);
                }
            }
            for (s, &norm) in row_scale.iter_mut().zip(&norms) {
                if norm == 0.0 || !norm.is_finite() {
                    return Err(undetermined(f64::INFINITY));
                }
                *s = 1.0 / norm;
            }
        }
        let mut col_scale = vec![1.0; n];
        for (j, s) in col_scale.iter_mut().enumerate() {
            let range = a.col_range(j);
            let rows: Vec<usize> = a.row_idx()[range].to_vec();
            let vals = a.val_of_col_mut(j);
            let mut norm = 0.0f64;
            for (v, &i) in vals.iter_mut().zip(&rows) {
                *v *= row_scale[i];
                norm = norm.hypot(*v);
            }
            if norm == 0.0 || !norm.is_finite() {
                return Err(undetermined(f64::INFINITY));
            }
            *s = 1.0 / norm;
            for v in vals.iter_mut() {
                *v *= *s;
            }
        }
        // Right-hand sides: three data columns, then the probes.
        let mut seed = 0x9E37_79B9_7F4A_7C15_u64;
        let mut b = Mat::<f64>::zeros(m, 3 + PROBES);
        for i in 0..m {
            for c in 0..3 {
                b[(i, c)] = self.rhs[i][c] * row_scale[i];
            }
            for c in 0..PROBES {
                b[(i, 3 + c)] = gaussian(&mut seed);
            }
        }
        let solved_ok = if n <= DENSE_UNKNOWNS {
            let mut dense = Mat::<f64>::zeros(m, n);
            for j in 0..n {
                let range = a.col_range(j);
                for (&i, &v) in a.row_idx()[range.clone()].iter().zip(&a.val()[range]) {
                    dense[(i, j)] += v;
                }
            }
            match kind {
                Kind::Square => dense.partial_piv_lu().solve_in_place(&mut b),
                Kind::LeastSquares => dense.qr().solve_lstsq_in_place(&mut b),
            }
            true
        } else {
            match kind {
                Kind::Square => match a.sp_lu() {
                    Ok(lu) => {
                        lu.solve_in_place(&mut b);
                        true
                    }
                    Err(_) => false,
                },
                Kind::LeastSquares => sparse_qr_solve(&a, &mut b),
            }
        };
        if !solved_ok {
            return Err(undetermined(f64::INFINITY));
        }
        let mut probe = 0.0;
        for c in 0..PROBES {
            for i in 0..n {
                probe += b[(i, 3 + c)] * b[(i, 3 + c)];
            }
        }
        // ‖A‖_F = √n after the column scaling.
        let condition = (n as f64).sqrt() * (probe / PROBES as f64).sqrt();
        let x: Vec<[f64; 3]> = (0..n)
            .map(|i| std::array::from_fn(|c| b[(i, c)] * col_scale[i]))
            .collect();
        if !condition.is_finite()
            || condition > RANK_LIMIT
            || x.iter().flatten().any(|v| !v.is_finite())
        {
            return Err(undetermined(condition));
        }
        if condition > CONDITION_LIMIT {
            return Err(PdeError::IllConditioned {
                method,
                unknowns: n,
                condition,
                limit: CONDITION_LIMIT,
            });
        }
        Ok(Solved { x, condition })
    }
}

/// Sparse Householder QR (supernodal, COLAMD column order) and the least-squares solve of
/// every column of `b` in place (the solutions in its first ncols rows); false when the
/// factorization cannot be set up.
///
/// The supernodal variant is forced: faer's automatic choice picks the simplicial one on
/// long strips of patches, where it is two orders of magnitude slower.
fn sparse_qr_solve(a: &SparseColMat<usize, f64>, b: &mut Mat<f64>) -> bool {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::sparse::linalg::SupernodalThreshold;
    use faer::sparse::linalg::qr::{QrSymbolicParams, factorize_symbolic_qr};
    let params = QrSymbolicParams {
        supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
        ..Default::default()
    };
    let Ok(symbolic) = factorize_symbolic_qr(a.symbolic(), params) else {
        return false;
    };
    let par = faer::Par::Seq;
    let req = symbolic
        .factorize_numeric_qr_scratch::<f64>(par, Default::default())
        .or(symbolic.solve_in_place_scratch::<f64>(b.ncols(), par));
    let Ok(mut mem) = MemBuffer::try_new(req) else {
        return false;
    };
    let stack = MemStack::new(&mut mem);
    let mut indices = vec![0usize; symbolic.len_idx()];
    let mut values = vec![0.0; symbolic.len_val()];
    let qr = symbolic.factorize_numeric_qr(
        &mut indices,
        &mut values,
        a.as_ref(),
        par,
        stack,
        Default::default(),
    );
    qr.solve_in_place_with_conj(faer::Conj::No, b.as_mut(), par, stack);
    true
}

/// A standard normal sample (Box–Muller on two SplitMix64 draws).
fn gaussian(state: &mut u64) -> f64 {
    let unit = |x: u64| ((x >> 11) as f64 + 0.5) / (1u64 << 53) as f64;
    let (a, b) = (unit(splitmix(state)), unit(splitmix(state)));
    (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
}

/// SplitMix64: a tiny deterministic generator for the probes.
fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tridiagonal system −x_{i−1} + 2x_i − x_{i+1} with a known solution, solved on
    /// both paths (dense below `DENSE_UNKNOWNS`, sparse above).
    #[test]
    fn square_solve_recovers_known_solution_on_both_paths() {
        for n in [10usize, 500] {
            let mut s = System::new(n, n);
            let exact: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).sin()).collect();
            for i in 0..n {
                let mut b = 0.0;
                for (j, w) in [(i.wrapping_sub(1), -1.0), (i, 2.0), (i + 1, -1.0)] {
                    if j < n {
                        s.push(i, j, w);
                        b += w * exact[j];
                    }
                }
                s.rhs[i] = [b, 2.0 * b, -b];
            }
            let solved = s.solve(Kind::Square, "test").unwrap();
            for (x, e) in solved.x.iter().zip(&exact) {
                assert!((x[0] - e).abs() < 1e-9 * n as f64);
                assert!((x[1] - 2.0 * e).abs() < 2e-9 * n as f64);
            }
            // κ₂ of the 1-D Laplacian is about 4(n+1)²/π², and κ_F ≥ κ₂.
            let k2 = 4.0 * ((n + 1) as f64).powi(2) / std::f64::consts::PI.powi(2);
            assert!(
                solved.condition > 0.3 * k2 && solved.condition < 30.0 * k2 * (n as f64).sqrt(),
                "n {n}: {} vs κ₂ {k2}",
                solved.condition
            );
        }
    }

    /// Least squares against the normal-equations answer of an overdetermined fit.
    #[test]
    fn least_squares_matches_the_line_fit() {
        for count in [20usize, 400] {
            // Fit c0 + c1 t_i (plus unused columns for the sparse path) to y = 1 + 2t + noise.
            let extra = if count > 100 { 120 } else { 0 };
            let n = 2 + extra;
            let mut s = System::new(count + extra, n);
            let mut sums = [0.0; 5];
            for i in 0..count {
                let t = i as f64 / count as f64;
                let y = 1.0 + 2.0 * t + 0.01 * (i as f64 * 1.7).sin();
                s.push(i, 0, 1.0);
                s.push(i, 1, t);
                s.rhs[i] = [y, 0.0, 0.0];
                sums[0] += 1.0;
                sums[1] += t;
                sums[2] += t * t;
                sums[3] += y;
                sums[4] += t * y;
            }
            for k in 0..extra {
                s.push(count + k, 2 + k, 1.0);
                s.rhs[count + k] = [k as f64, 0.0, 0.0];
            }
            let solved = s.solve(Kind::LeastSquares, "test").unwrap();
            let det = sums[0] * sums[2] - sums[1] * sums[1];
            let c0 = (sums[3] * sums[2] - sums[1] * sums[4]) / det;
            let c1 = (sums[0] * sums[4] - sums[1] * sums[3]) / det;
            assert!((solved.x[0][0] - c0).abs() < 1e-12, "{count}");
            assert!((solved.x[1][0] - c1).abs() < 1e-12, "{count}");
            for k in 0..extra {
                assert!((solved.x[2 + k][0] - k as f64).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn singular_and_ill_conditioned_systems_are_told_apart() {
        // Two equal columns: rank deficient.
        let mut s = System::new(3, 2);
        for i in 0..3 {
            s.push(i, 0, 1.0 + i as f64);
            s.push(i, 1, 1.0 + i as f64);
        }
        assert!(matches!(
            s.solve(Kind::LeastSquares, "t"),
            Err(PdeError::Undetermined { .. })
        ));
        // Nearly equal columns and rows: full rank, condition ≈ 4e14.
        let mut s = System::new(2, 2);
        for (i, j, v) in [(0, 0, 1.0), (0, 1, 1.0), (1, 0, 1.0), (1, 1, 1.0 + 1e-14)] {
            s.push(i, j, v);
        }
        match s.solve(Kind::Square, "t") {
            Err(PdeError::IllConditioned { condition, .. }) => {
                assert!(condition > 1e13 && condition < 1e16, "{condition}");
            }
            other => panic!("{other:?}"),
        }
        // An empty column.
        let mut s = System::new(2, 2);
        s.push(0, 0, 1.0);
        s.push(1, 0, 1.0);
        assert!(matches!(
            s.solve(Kind::Square, "t"),
            Err(PdeError::Undetermined { .. })
        ));
    }
}
