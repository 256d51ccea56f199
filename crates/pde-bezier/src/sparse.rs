//! Sparse linear solves with a condition estimate: Cholesky LLᵀ (approximate minimum degree
//! ordering) for symmetric definite systems, LU for other square systems, Householder QR for
//! least squares (no normal equations), on faer's supernodal factorizations; a dense path
//! for tiny systems, where it is faster.
//!
//! A symmetric definite system ±A is scaled symmetrically to unit diagonal, D A D with
//! D = diag(|a_ii|^(−1/2)); other systems have their columns scaled to unit 2-norm (a square
//! system's rows too). Neither changes the solution. The condition estimate is the
//! Frobenius condition number κ_F = ‖A‖_F ‖A⁺‖_F ≥ κ₂ of the scaled matrix, with
//! ‖A⁺‖_F² = E‖A⁺ g‖² estimated from
//! [`PROBES`] random ±1 vectors g (Hutchinson's estimator), solved with the same
//! factorization as the right-hand sides.

use crate::error::PdeError;
use crate::limits::MAX_DENSE_ENTRIES;
use faer::linalg::solvers::{Solve, SolveLstsq};
use faer::sparse::{SparseColMat, Triplet};
use faer::{Mat, Side};

/// Square systems (collocation, Galerkin with a free side) with at most this many unknowns
/// are solved by dense LU under [`Storage::Auto`].
///
/// Measured by `cargo xtask tables` (docs/results/pde-bezier-crossover.md: Laplace's
/// operator, collocation, solve time sparse/dense): dense is faster on single patches up to
/// 144 unknowns (1.1–1.7) and on grids of bi-quintic C¹ patches up to 256 (1.3–1.5), even
/// at 400 (1.04), sparse from 576 unknowns (0.78; 0.37 at 1,024).
pub const DENSE_SQUARE_UNKNOWNS: usize = 320;

/// Symmetric definite systems (Galerkin with every side fixed or periodic) with at most this
/// many unknowns are solved by dense Cholesky under [`Storage::Auto`].
///
/// Measured as [`DENSE_SQUARE_UNKNOWNS`] with Galerkin: dense is faster on single patches
/// up to 144 unknowns (1.04–1.13) and on grids up to 192 (1.1–1.2), sparse from 256 (0.94;
/// 0.79 at 400, 0.37 at 1,024).
pub const DENSE_SYMMETRIC_UNKNOWNS: usize = 224;

/// Least-squares systems (the two residual objectives) with at most this many unknowns are
/// solved by dense QR under [`Storage::Auto`].
///
/// Measured as [`DENSE_SQUARE_UNKNOWNS`] with both objectives: dense QR is faster on grids
/// up to 64 unknowns (1.1–1.4) and sparse from 96 on (0.91; 0.3 at 400, 0.1 at 1,024); on
/// single patches of degree 5–13 (16–144 unknowns) the two are within about 35 % either way.
pub const DENSE_LEAST_SQUARES_UNKNOWNS: usize = 80;

/// The dense-to-sparse switch of [`Storage::Auto`] for a kind of system.
fn dense_threshold(kind: Kind) -> usize {
    match kind {
        Kind::Square => DENSE_SQUARE_UNKNOWNS,
        Kind::Symmetric => DENSE_SYMMETRIC_UNKNOWNS,
        Kind::LeastSquares => DENSE_LEAST_SQUARES_UNKNOWNS,
    }
}

/// Solves A X = B (or min ‖A X − B‖) in place by a dense factorization: LLᵀ when `definite`
/// and it succeeds, then one step of refinement; else LU or QR. `None` never happens here
/// (dense factorizations always complete; singularity shows in the condition estimate).
fn dense_solve(
    a: &SparseColMat<usize, f64>,
    kind: Kind,
    definite: bool,
    b: &mut Mat<f64>,
) -> Option<Factorization> {
    let mut dense = Mat::<f64>::zeros(a.nrows(), a.ncols());
    for j in 0..a.ncols() {
        let range = a.col_range(j);
        for (&i, &v) in a.row_idx()[range.clone()].iter().zip(&a.val()[range]) {
            dense[(i, j)] += v;
        }
    }
    if kind == Kind::LeastSquares {
        dense.qr().solve_lstsq_in_place(b);
        return Some(Factorization::DenseQr);
    }
    if definite && let Ok(llt) = dense.llt(Side::Lower) {
        refine(a, b, |x| llt.solve_in_place(x));
        return Some(Factorization::DenseLlt);
    }
    dense.partial_piv_lu().solve_in_place(b);
    Some(Factorization::DenseLu)
}

/// Solves A X = B (or min ‖A X − B‖) in place by a sparse factorization: supernodal LLᵀ with
/// an approximate minimum degree ordering when `definite` and it succeeds, then one step of
/// refinement; else LU (COLAMD ordering) or QR. `None` when the factorization fails.
fn sparse_solve(
    a: &SparseColMat<usize, f64>,
    kind: Kind,
    definite: bool,
    b: &mut Mat<f64>,
) -> Option<Factorization> {
    if kind == Kind::LeastSquares {
        return sparse_qr_solve(a, b).then_some(Factorization::SparseQr);
    }
    if definite && sparse_llt_solve(a, b) {
        return Some(Factorization::SparseLlt);
    }
    let lu = a.sp_lu().ok()?;
    lu.solve_in_place(b);
    Some(Factorization::SparseLu)
}

/// Supernodal sparse LLᵀ of the lower triangle (approximate minimum degree ordering) and
/// the solve of every column of `b` in place with one step of [`refine`]; false when the
/// factorization fails (not definite) or cannot be set up.
///
/// The supernodal variant is forced: faer's automatic choice picks the simplicial one on
/// long strips of patches, where it is slower.
fn sparse_llt_solve(a: &SparseColMat<usize, f64>, b: &mut Mat<f64>) -> bool {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::sparse::linalg::SupernodalThreshold;
    use faer::sparse::linalg::cholesky::{
        CholeskySymbolicParams, LltRef, SymmetricOrdering, factorize_symbolic_cholesky,
    };
    let params = CholeskySymbolicParams {
        supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
        ..Default::default()
    };
    let Ok(symbolic) =
        factorize_symbolic_cholesky(a.symbolic(), Side::Lower, SymmetricOrdering::Amd, params)
    else {
        return false;
    };
    let par = faer::Par::Seq;
    let req = symbolic
        .factorize_numeric_llt_scratch::<f64>(par, Default::default())
        .or(symbolic.solve_in_place_scratch::<f64>(b.ncols(), par));
    let Ok(mut mem) = MemBuffer::try_new(req) else {
        return false;
    };
    let stack = MemStack::new(&mut mem);
    let mut values = vec![0.0; symbolic.len_val()];
    if symbolic
        .factorize_numeric_llt(
            &mut values,
            a.as_ref(),
            Side::Lower,
            Default::default(),
            par,
            stack,
            Default::default(),
        )
        .is_err()
    {
        return false;
    }
    let llt = LltRef::new(&symbolic, &values);
    refine(a, b, |x| {
        llt.solve_in_place_with_conj(faer::Conj::No, x.as_mut(), par, stack);
    });
    true
}

/// X = S(B), then one step of iterative refinement X += S(B − A X) against the whole of A:
/// a Cholesky factorization reads only the lower triangle, and A is symmetric only up to the
/// rounding of its assembly.
fn refine(a: &SparseColMat<usize, f64>, b: &mut Mat<f64>, mut solve: impl FnMut(&mut Mat<f64>)) {
    let mut r = b.clone();
    solve(b);
    for j in 0..a.ncols() {
        let range = a.col_range(j);
        for (&i, &v) in a.row_idx()[range.clone()].iter().zip(&a.val()[range]) {
            for c in 0..r.ncols() {
                r[(i, c)] -= v * b[(j, c)];
            }
        }
    }
    solve(&mut r);
    *b += &r;
}

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
    /// A square system whose matrix is symmetric in exact arithmetic: LLᵀ of ±A when it is
    /// numerically symmetric with a one-signed diagonal and the factorization succeeds
    /// (definite), LU otherwise.
    Symmetric,
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
    /// The factorization that solved it (observed by the tests).
    #[cfg_attr(not(test), allow(dead_code, reason = "read by the unit tests only"))]
    pub(crate) factorization: Factorization,
}

/// The factorizations [`System::solve`] chooses from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Factorization {
    /// Nothing to solve.
    None,
    DenseLlt,
    DenseLu,
    DenseQr,
    SparseLlt,
    SparseLu,
    SparseQr,
}

/// How the linear system of a solve is stored and factorized ([`crate::Assembly::solve_with`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Storage {
    /// Dense below a measured size ([`DENSE_SQUARE_UNKNOWNS`], [`DENSE_SYMMETRIC_UNKNOWNS`],
    /// [`DENSE_LEAST_SQUARES_UNKNOWNS`], by the kind of system), sparse above: the faster
    /// of the two.
    #[default]
    Auto,
    /// Always a dense factorization (O(N³) time, O(N²) memory in the N unknowns); refused
    /// with [`crate::PdeError::TooLarge`] above [`crate::MAX_DENSE_ENTRIES`] matrix entries.
    Dense,
    /// Always a sparse factorization.
    Sparse,
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
    pub(crate) fn solve(
        self,
        kind: Kind,
        storage: Storage,
        method: &'static str,
    ) -> Result<Solved, PdeError> {
        let (m, n) = (self.nrows, self.ncols);
        if n == 0 {
            return Ok(Solved {
                x: Vec::new(),
                condition: 1.0,
                factorization: Factorization::None,
            });
        }
        let undetermined = |condition: f64| PdeError::Undetermined {
            method,
            unknowns: n,
            condition,
        };
        if m < n || (kind != Kind::LeastSquares && m != n) {
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
        let definite_sign = if kind == Kind::Symmetric {
            definite_candidate(&a)
        } else {
            None
        };
        let (row_scale, col_scale) = match definite_sign {
            Some(sign) => {
                let d = unit_diagonal_scale(&mut a, sign);
                (d.iter().map(|&d| sign * d).collect(), d)
            }
            None => match unit_norm_scale(&mut a, kind) {
                Some(scales) => scales,
                None => return Err(undetermined(f64::INFINITY)),
            },
        };
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
        let norm_a = a.val().iter().map(|v| v * v).sum::<f64>().sqrt();
        let entries = m.saturating_mul(n);
        let dense = match storage {
            Storage::Auto => n <= dense_threshold(kind) && entries <= MAX_DENSE_ENTRIES,
            Storage::Dense if entries > MAX_DENSE_ENTRIES => {
                return Err(PdeError::TooLarge {
                    what: "the number of dense matrix entries",
                    value: entries,
                    limit: MAX_DENSE_ENTRIES,
                });
            }
            Storage::Dense => true,
            Storage::Sparse => false,
        };
        let factorization = if dense {
            dense_solve(&a, kind, definite_sign.is_some(), &mut b)
        } else {
            sparse_solve(&a, kind, definite_sign.is_some(), &mut b)
        }
        .ok_or_else(|| undetermined(f64::INFINITY))?;
        let mut probe = 0.0;
        for c in 0..PROBES {
            for i in 0..n {
                probe += b[(i, 3 + c)] * b[(i, 3 + c)];
            }
        }
        let condition = norm_a * (probe / PROBES as f64).sqrt();
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
        Ok(Solved {
            x,
            condition,
            factorization,
        })
    }
}

/// The sign s for which s·A may be symmetric positive definite: A is numerically symmetric
/// (|a_ij − a_ji| ≤ 1e-12 √(|a_ii a_jj|), a missing entry counting as 0) and its diagonal is
/// nonzero and of one sign s. Row indices must be sorted (as built from triplets).
fn definite_candidate(a: &SparseColMat<usize, f64>) -> Option<f64> {
    let n = a.ncols();
    let diag: Vec<f64> = (0..n)
        .map(|j| a.get(j, j).copied().unwrap_or(0.0))
        .collect();
    let sign = diag.first()?.signum();
    if diag
        .iter()
        .any(|&d| d == 0.0 || d.signum() != sign || !d.is_finite())
    {
        return None;
    }
    for j in 0..n {
        let range = a.col_range(j);
        for (&i, &v) in a.row_idx()[range.clone()].iter().zip(&a.val()[range]) {
            let mirror = a.get(j, i).copied().unwrap_or(0.0);
            if (v - mirror).abs() > 1e-12 * (diag[i] * diag[j]).abs().sqrt() {
                return None;
            }
        }
    }
    Some(sign)
}

/// Scales s·A to s·D A D with unit diagonal, D = diag(|a_ii|^(−1/2)), in place (the values
/// of A become those of s·D A D); returns D.
fn unit_diagonal_scale(a: &mut SparseColMat<usize, f64>, sign: f64) -> Vec<f64> {
    let n = a.ncols();
    let d: Vec<f64> = (0..n)
        .map(|j| 1.0 / a.get(j, j).copied().unwrap_or(1.0).abs().sqrt())
        .collect();
    for (j, &dj) in d.iter().enumerate() {
        let range = a.col_range(j);
        let rows: Vec<usize> = a.row_idx()[range].to_vec();
        for (v, &i) in a.val_of_col_mut(j).iter_mut().zip(&rows) {
            *v *= sign * d[i] * dj;
        }
    }
    d
}

/// Scales the columns of A to unit 2-norm (for square systems after scaling the rows to
/// unit 2-norm; row scaling would reweight a least-squares objective), in place; returns
/// (row scales, column scales), or `None` when a row or column is zero.
fn unit_norm_scale(a: &mut SparseColMat<usize, f64>, kind: Kind) -> Option<(Vec<f64>, Vec<f64>)> {
    let (m, n) = (a.nrows(), a.ncols());
    let mut row_scale = vec![1.0; m];
    if kind != Kind::LeastSquares {
        let mut norms = vec![0.0f64; m];
        for j in 0..n {
            let range = a.col_range(j);
            for (&i, &v) in a.row_idx()[range.clone()].iter().zip(&a.val()[range]) {
                norms[i] = norms[i].hypot(v);
            }
        }
        for (s, &norm) in row_scale.iter_mut().zip(&norms) {
            if norm == 0.0 || !norm.is_finite() {
                return None;
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
            return None;
        }
        *s = 1.0 / norm;
        for v in vals.iter_mut() {
            *v *= *s;
        }
    }
    Some((row_scale, col_scale))
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
    /// both paths (dense below `DENSE_SQUARE_UNKNOWNS`, sparse above).
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
            let solved = s.solve(Kind::Square, Storage::Auto, "test").unwrap();
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
            let solved = s.solve(Kind::LeastSquares, Storage::Auto, "test").unwrap();
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
            s.solve(Kind::LeastSquares, Storage::Auto, "t"),
            Err(PdeError::Undetermined { .. })
        ));
        // Nearly equal columns and rows: full rank, condition ≈ 4e14.
        let mut s = System::new(2, 2);
        for (i, j, v) in [(0, 0, 1.0), (0, 1, 1.0), (1, 0, 1.0), (1, 1, 1.0 + 1e-14)] {
            s.push(i, j, v);
        }
        match s.solve(Kind::Square, Storage::Auto, "t") {
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
            s.solve(Kind::Square, Storage::Auto, "t"),
            Err(PdeError::Undetermined { .. })
        ));
    }

    /// The 1-D Laplacian −x_{i−1} + 2x_i − x_{i+1} times `sign`, with solution sin(0.37 i),
    /// plus `skew` added to the entry (0, 1) only.
    fn laplacian(n: usize, sign: f64, skew: f64) -> (System, Vec<f64>) {
        let mut s = System::new(n, n);
        let exact: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).sin()).collect();
        for i in 0..n {
            let mut b = 0.0;
            for (j, w) in [(i.wrapping_sub(1), -1.0), (i, 2.0), (i + 1, -1.0)] {
                if j < n {
                    let w = sign * w + if (i, j) == (0, 1) { skew } else { 0.0 };
                    s.push(i, j, w);
                    b += w * exact[j];
                }
            }
            s.rhs[i] = [b, -b, 0.5 * b];
        }
        (s, exact)
    }

    /// Symmetric definite systems (either sign) go to Cholesky on both storages and agree
    /// with the known solution; an unsymmetric or indefinite one falls back to LU.
    #[test]
    fn symmetric_systems_use_cholesky_and_others_fall_back_to_lu() {
        use Factorization::{DenseLlt, DenseLu, SparseLlt, SparseLu};
        for (storage, llt, lu) in [
            (Storage::Dense, DenseLlt, DenseLu),
            (Storage::Sparse, SparseLlt, SparseLu),
        ] {
            for (sign, skew, expected) in [
                (1.0, 0.0, llt),
                (-1.0, 0.0, llt),
                (1.0, 1e-3, lu),
                // Indefinite: diagonal entries of one sign, but a negative pivot.
                (1.0, 0.0, lu),
            ] {
                let n = 200;
                let (mut s, exact) = laplacian(n, sign, skew);
                if expected == lu && skew == 0.0 {
                    // Off-diagonal entries 1.9 times the diagonal: symmetric, not definite.
                    for t in &mut s.entries {
                        if t.row != t.col {
                            t.val *= 1.9;
                        }
                    }
                    let x: Vec<f64> = exact.clone();
                    for (i, r) in s.rhs.iter_mut().enumerate() {
                        let mut b = 0.0;
                        for t in s.entries.iter().filter(|t| t.row == i) {
                            b += t.val * x[t.col];
                        }
                        *r = [b, -b, 0.5 * b];
                    }
                }
                let solved = s.solve(Kind::Symmetric, storage, "test").unwrap();
                assert_eq!(solved.factorization, expected, "{sign} {skew}");
                for (x, e) in solved.x.iter().zip(&exact) {
                    assert!((x[0] - e).abs() < 1e-8, "{sign} {skew}: {} {e}", x[0]);
                    assert!((x[1] + e).abs() < 1e-8);
                }
            }
        }
    }

    /// `Storage::Auto` switches at the measured thresholds.
    #[test]
    fn auto_storage_switches_at_the_thresholds() {
        for (n, expected) in [
            (DENSE_SYMMETRIC_UNKNOWNS, Factorization::DenseLlt),
            (DENSE_SYMMETRIC_UNKNOWNS + 1, Factorization::SparseLlt),
        ] {
            let solved = laplacian(n, 1.0, 0.0)
                .0
                .solve(Kind::Symmetric, Storage::Auto, "test")
                .unwrap();
            assert_eq!(solved.factorization, expected);
        }
        for (n, expected) in [
            (DENSE_SQUARE_UNKNOWNS, Factorization::DenseLu),
            (DENSE_SQUARE_UNKNOWNS + 1, Factorization::SparseLu),
        ] {
            let solved = laplacian(n, 1.0, 0.0)
                .0
                .solve(Kind::Square, Storage::Auto, "test")
                .unwrap();
            assert_eq!(solved.factorization, expected);
        }
    }
}
