//! Symmetric positive definite systems whose matrix is a band of half-width [`HALF_WIDTH`] plus,
//! for closed curves, the wrap-around corners: the least-squares normal equations of the fit.
//!
//! With the unknowns in polygon order, a data point on segment j touches the control points
//! j − 1..=j + 2, so the normal matrix couples unknowns at most 3 apart, or (closed curves) the
//! first three with the last three. Ordering the last three unknowns last makes it a band plus a
//! border: M = [[A, B], [Bᵀ, C]], A banded, C of size 3. Cholesky of the band (no fill-in outside
//! it), W = L⁻¹B, and the 3 × 3 Schur complement S = C − WᵀW give the solve in O(u) time and
//! memory, where the dense normal equations took O(u²) memory and O(u³) time.
#![allow(
    clippy::needless_range_loop,
    reason = "factorizations read clearest with the matrix indices of their formulas"
)]

/// Half-width of the band: a data point couples unknowns at most this far apart.
pub(crate) const HALF_WIDTH: usize = 3;

/// The lower triangle of the normal matrix, accumulated entry by entry.
#[derive(Debug, Clone)]
pub(crate) struct CyclicBand {
    u: usize,
    /// `band[i][d]` = M[i][i − d], d = 0..=HALF_WIDTH (entries left of column 0 unused).
    band: Vec<[f64; HALF_WIDTH + 1]>,
    /// `wrap[j][r]` = M[u − HALF_WIDTH + r][j] for j < HALF_WIDTH: the corner entries more than
    /// HALF_WIDTH apart (closed curves only).
    wrap: [[f64; HALF_WIDTH]; HALF_WIDTH],
    /// Small systems (u ≤ 2·HALF_WIDTH + 2), where band and corners overlap: dense, row-major.
    dense: Option<Vec<f64>>,
}

impl CyclicBand {
    /// A zero matrix of size u × u.
    pub(crate) fn zeros(u: usize) -> Self {
        let dense = (u <= 2 * HALF_WIDTH + 2).then(|| vec![0.0; u * u]);
        Self {
            u,
            band: vec![[0.0; HALF_WIDTH + 1]; u],
            wrap: [[0.0; HALF_WIDTH]; HALF_WIDTH],
            dense,
        }
    }

    /// M[i][j] += v for i ≥ j. Returns `false` (and adds nothing) for an entry outside the
    /// structure, which the fit never produces.
    pub(crate) fn add_lower(&mut self, i: usize, j: usize, v: f64) -> bool {
        let u = self.u;
        if j > i || i >= u {
            return false;
        }
        if let Some(d) = self.dense.as_mut() {
            d[i * u + j] += v;
            if i != j {
                d[j * u + i] += v;
            }
            return true;
        }
        if i - j <= HALF_WIDTH {
            self.band[i][i - j] += v;
            true
        } else if j < HALF_WIDTH && i >= u - HALF_WIDTH {
            self.wrap[j][i - (u - HALF_WIDTH)] += v;
            true
        } else {
            false
        }
    }

    /// M[i][j] for any i, j (zero outside the structure).
    fn get(&self, i: usize, j: usize) -> f64 {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        if let Some(d) = self.dense.as_ref() {
            return d[i * self.u + j];
        }
        if i - j <= HALF_WIDTH {
            self.band[i][i - j]
        } else if j < HALF_WIDTH && i >= self.u - HALF_WIDTH {
            self.wrap[j][i - (self.u - HALF_WIDTH)]
        } else {
            0.0
        }
    }

    /// Solves M x = b for `D` right-hand sides. `None` when M is not (numerically) positive
    /// definite or the solution is not finite.
    pub(crate) fn solve<const D: usize>(&self, rhs: &[[f64; D]]) -> Option<Vec<[f64; D]>> {
        self.factor()?.solve(rhs)
    }

    /// The Cholesky factorization of M, for solves with several right-hand sides. `None` for
    /// an empty matrix or one that is not (numerically) positive definite.
    pub(crate) fn factor(&self) -> Option<BandFactor> {
        let u = self.u;
        if u == 0 {
            return None;
        }
        if self.dense.is_some() {
            let m: Vec<Vec<f64>> = (0..u)
                .map(|i| (0..u).map(|j| self.get(i, j)).collect())
                .collect();
            return Some(BandFactor::Dense(dense_cholesky(m)?));
        }
        self.bordered_factor()
    }

    /// The band-plus-border factorization (u > 2·HALF_WIDTH + 2).
    fn bordered_factor(&self) -> Option<BandFactor> {
        const W: usize = HALF_WIDTH;
        let u = self.u;
        let m = u - W;
        // Banded Cholesky of A = M[0..m, 0..m]: l[i][d] = L[i][i − d].
        let mut l = vec![[0.0; W + 1]; m];
        for i in 0..m {
            for d in (0..=W.min(i)).rev() {
                let j = i - d;
                // L[i][j] = (A[i][j] − Σ_{k<j} L[i][k] L[j][k]) / L[j][j], k within both bands.
                let mut s = self.band[i][d];
                for k in i.saturating_sub(W)..j {
                    s -= l[i][i - k] * l[j][j - k];
                }
                if d == 0 {
                    if s.is_nan() || s <= 0.0 {
                        return None;
                    }
                    l[i][0] = s.sqrt();
                } else {
                    l[i][d] = s / l[j][0];
                }
            }
        }
        // W = L⁻¹ B, B = M[0..m, m..u] (column c is unknown m + c).
        let mut wmat = vec![[0.0; W]; m];
        for c in 0..W {
            for i in 0..m {
                let mut s = self.get(i, m + c);
                for k in i.saturating_sub(W)..i {
                    s -= l[i][i - k] * wmat[k][c];
                }
                wmat[i][c] = s / l[i][0];
            }
        }
        // S = C − WᵀW and its Cholesky factor.
        let mut s = vec![vec![0.0; W]; W];
        for (a, row) in s.iter_mut().enumerate() {
            for (b, v) in row.iter_mut().enumerate() {
                *v = self.get(m + a, m + b) - wmat.iter().map(|w| w[a] * w[b]).sum::<f64>();
            }
        }
        let ls = dense_cholesky(s)?;
        Some(BandFactor::Bordered { l, wmat, ls })
    }
}

/// The Cholesky factorization of a [`CyclicBand`] ([`CyclicBand::factor`]): one factorization
/// for several solves (the refit's unconstrained solve and one per constrained point).
#[derive(Debug, Clone)]
pub(crate) enum BandFactor {
    /// Small systems: the dense lower factor.
    Dense(Vec<Vec<f64>>),
    /// The band's factor L (`l[i][d]` = L[i][i − d]), W = L⁻¹B and the Schur complement's
    /// factor.
    Bordered {
        l: Vec<[f64; HALF_WIDTH + 1]>,
        wmat: Vec<[f64; HALF_WIDTH]>,
        ls: Vec<Vec<f64>>,
    },
}

impl BandFactor {
    /// The number of unknowns.
    pub(crate) fn size(&self) -> usize {
        match self {
            Self::Dense(l) => l.len(),
            Self::Bordered { l, .. } => l.len() + HALF_WIDTH,
        }
    }

    /// Solves M x = b for `D` right-hand sides. `None` when `rhs` has another size or the
    /// solution is not finite.
    pub(crate) fn solve<const D: usize>(&self, rhs: &[[f64; D]]) -> Option<Vec<[f64; D]>> {
        if rhs.len() != self.size() {
            return None;
        }
        let x = match self {
            Self::Dense(l) => {
                let mut y = rhs.to_vec();
                forward(l, &mut y);
                backward(l, &mut y);
                y
            }
            Self::Bordered { l, wmat, ls } => bordered_solve(l, wmat, ls, rhs),
        };
        x.iter().flatten().all(|v| v.is_finite()).then_some(x)
    }
}

/// The band-plus-border solve with the factors of [`CyclicBand::bordered_factor`].
fn bordered_solve<const D: usize>(
    l: &[[f64; HALF_WIDTH + 1]],
    wmat: &[[f64; HALF_WIDTH]],
    ls: &[Vec<f64>],
    rhs: &[[f64; D]],
) -> Vec<[f64; D]> {
    const W: usize = HALF_WIDTH;
    let m = l.len();
    // Forward: y1 = L⁻¹ b1, y2 = Ls⁻¹ (b2 − Wᵀ y1).
    let mut y = rhs.to_vec();
    for i in 0..m {
        for k in i.saturating_sub(W)..i {
            let lik = l[i][i - k];
            let yk = y[k];
            for (v, yk) in y[i].iter_mut().zip(yk) {
                *v -= lik * yk;
            }
        }
        for v in &mut y[i] {
            *v /= l[i][0];
        }
    }
    for a in 0..W {
        for i in 0..m {
            let (wa, yi) = (wmat[i][a], y[i]);
            for (v, yi) in y[m + a].iter_mut().zip(yi) {
                *v -= wa * yi;
            }
        }
    }
    let mut y2: Vec<[f64; D]> = y[m..].to_vec();
    forward(ls, &mut y2);
    backward(ls, &mut y2);
    // Back: Lᵀ x1 = y1 − W x2.
    let mut x = y;
    x[m..].copy_from_slice(&y2);
    for i in 0..m {
        for (c, x2) in y2.iter().enumerate() {
            let wc = wmat[i][c];
            for (v, x2) in x[i].iter_mut().zip(x2) {
                *v -= wc * x2;
            }
        }
    }
    for i in (0..m).rev() {
        for k in i + 1..(i + W + 1).min(m) {
            let lki = l[k][k - i];
            let xk = x[k];
            for (v, xk) in x[i].iter_mut().zip(xk) {
                *v -= lki * xk;
            }
        }
        for v in &mut x[i] {
            *v /= l[i][0];
        }
    }
    x
}

/// Lower Cholesky factor of a small dense SPD matrix; `None` if it is not positive definite.
fn dense_cholesky(mut a: Vec<Vec<f64>>) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    for j in 0..n {
        let mut d = a[j][j];
        for k in 0..j {
            d -= a[j][k] * a[j][k];
        }
        if d.is_nan() || d <= 0.0 {
            return None;
        }
        a[j][j] = d.sqrt();
        for i in j + 1..n {
            let mut s = a[i][j];
            for k in 0..j {
                s -= a[i][k] * a[j][k];
            }
            a[i][j] = s / a[j][j];
        }
        for i in 0..j {
            a[i][j] = 0.0;
        }
    }
    Some(a)
}

/// y ← L⁻¹ y.
fn forward<const D: usize>(l: &[Vec<f64>], y: &mut [[f64; D]]) {
    for i in 0..y.len() {
        for k in 0..i {
            let (lik, yk) = (l[i][k], y[k]);
            for (v, yk) in y[i].iter_mut().zip(yk) {
                *v -= lik * yk;
            }
        }
        for v in &mut y[i] {
            *v /= l[i][i];
        }
    }
}

/// y ← L⁻ᵀ y.
fn backward<const D: usize>(l: &[Vec<f64>], y: &mut [[f64; D]]) {
    for i in (0..y.len()).rev() {
        for k in i + 1..y.len() {
            let (lki, yk) = (l[k][i], y[k]);
            for (v, yk) in y[i].iter_mut().zip(yk) {
                *v -= lki * yk;
            }
        }
        for v in &mut y[i] {
            *v /= l[i][i];
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;

    /// A deterministic SPD matrix with the fit's structure: Σ rows rᵀr of 4 consecutive
    /// unknowns (cyclically when `closed`), plus a small diagonal.
    fn random_system(u: usize, closed: bool, seed: u64) -> (CyclicBand, Vec<Vec<f64>>) {
        let mut state = seed;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64) - 0.5
        };
        let mut band = CyclicBand::zeros(u);
        let mut dense = vec![vec![0.0; u]; u];
        let starts = if closed { u } else { u.saturating_sub(3) };
        for s in 0..starts {
            for _ in 0..3 {
                let cols: Vec<(usize, f64)> =
                    (0..4.min(u)).map(|o| ((s + o) % u, next())).collect();
                for &(c1, w1) in &cols {
                    for &(c2, w2) in &cols {
                        dense[c1][c2] += w1 * w2;
                        if c1 >= c2 {
                            assert!(band.add_lower(c1, c2, w1 * w2), "({c1}, {c2}) of {u}");
                        }
                    }
                }
            }
        }
        for i in 0..u {
            dense[i][i] += 1e-3;
            band.add_lower(i, i, 1e-3);
        }
        (band, dense)
    }

    #[test]
    fn matches_a_dense_solve_open_and_closed() {
        for u in [1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 17, 64, 301] {
            for closed in [false, true] {
                let (band, dense) = random_system(u, closed, u as u64 * 7 + u64::from(closed));
                let rhs: Vec<[f64; 2]> = (0..u)
                    .map(|i| [i as f64 * 0.3 - 1.0, (i % 5) as f64])
                    .collect();
                let x = band.solve(&rhs).unwrap();
                // Residual of the dense matrix: M x = b.
                for i in 0..u {
                    for c in 0..2 {
                        let mx: f64 = (0..u).map(|j| dense[i][j] * x[j][c]).sum();
                        assert!(
                            (mx - rhs[i][c]).abs() < 1e-9,
                            "u = {u}, closed = {closed}, row {i}: {mx} vs {}",
                            rhs[i][c]
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn rejects_entries_outside_the_structure_and_indefinite_matrices() {
        let mut band = CyclicBand::zeros(20);
        assert!(!band.add_lower(10, 2, 1.0));
        assert!(!band.add_lower(2, 10, 1.0));
        assert!(band.add_lower(19, 1, 1.0));
        // The zero matrix is singular.
        assert!(CyclicBand::zeros(20).solve(&[[1.0]; 20]).is_none());
        assert!(CyclicBand::zeros(5).solve(&[[1.0]; 5]).is_none());
        assert!(band.solve(&[[1.0]; 3]).is_none());
    }

    #[test]
    fn a_hundred_thousand_unknowns_solve_in_linear_memory() {
        let (band, _) = {
            let u = 100_000;
            let mut band = CyclicBand::zeros(u);
            for i in 0..u {
                band.add_lower(i, i, 4.0);
                if i > 0 {
                    band.add_lower(i, i - 1, 1.0);
                }
            }
            band.add_lower(u - 1, 0, 1.0);
            (band, ())
        };
        let x = band.solve(&vec![[6.0]; 100_000]).unwrap();
        // The cyclic matrix 4 on the diagonal, 1 beside it: constant rhs 6 gives x = 1.
        assert!(x.iter().all(|v| (v[0] - 1.0).abs() < 1e-12));
    }
}
