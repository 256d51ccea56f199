//! The interpolation system of eq. (4) with tangent vertices: a (cyclic) band of half-width
//! [`REACH`], solved in O(k) by LU factorization without pivoting.
//!
//! Next to a double knot the rows of eq. (4) have up to four entries (see module `greville`), so
//! the system is no longer tridiagonal. Its rows are B-spline collocations at increasing
//! parameters (sharp rows are rows of the identity), a totally positive matrix, for which
//! Gaussian elimination without pivoting is stable (de Boor and Pinkus, 1977), as Thomas's
//! algorithm is for the tridiagonal case. A closed polygon's matrix also has entries in its
//! corners; the last [`REACH`] unknowns are then a border, eliminated through their
//! `REACH × REACH` Schur complement.
#![allow(
    clippy::needless_range_loop,
    reason = "factorizations read clearest with the matrix indices of their formulas"
)]

/// Half-width of the band: a row couples unknowns at most this far apart (cyclically).
pub(crate) const REACH: usize = 2;

/// Width of a row of the band: offsets `−REACH ..= REACH`.
pub(crate) const WIDTH: usize = 2 * REACH + 1;

/// Systems up to this size are solved densely (with partial pivoting): there the cyclic offsets
/// of a row may name one unknown twice.
const DENSE: usize = 4 * REACH;

/// Solves `Σ_o rows[i][o + REACH] x[(i + o) mod k] = rhs[i]` for every row `i` (offsets `o` in
/// `−REACH ..= REACH`; for open systems the entries outside `0..k` must be zero and are ignored).
/// `None` on a zero pivot or a non-finite result.
pub(crate) fn solve_band<const D: usize>(
    rows: &[[f64; WIDTH]],
    rhs: &[[f64; D]],
    closed: bool,
) -> Option<Vec<[f64; D]>> {
    let k = rows.len();
    if k == 0 || rhs.len() != k {
        return None;
    }
    let x = if k <= DENSE {
        dense_solve(rows, rhs, closed)?
    } else if closed {
        bordered_solve(rows, rhs)?
    } else {
        let lu = BandLu::factor(rows.to_vec())?;
        columns_solve(&lu, rhs)
    };
    x.iter().flatten().all(|v| v.is_finite()).then_some(x)
}

/// The LU factors of an open band matrix, in place: `band[i][j − i + REACH]` holds `L[i][j]`
/// for `j < i` (unit diagonal) and `U[i][j]` for `j ≥ i`.
struct BandLu {
    band: Vec<[f64; WIDTH]>,
}

impl BandLu {
    /// Factors the band without pivoting; `None` on a zero or non-finite pivot.
    fn factor(mut band: Vec<[f64; WIDTH]>) -> Option<Self> {
        let m = band.len();
        for c in 0..m {
            let pivot = band[c][REACH];
            if pivot == 0.0 || !pivot.is_finite() {
                return None;
            }
            for r in c + 1..(c + REACH + 1).min(m) {
                let f = band[r][c + REACH - r] / pivot;
                band[r][c + REACH - r] = f;
                for j in c + 1..(c + REACH + 1).min(m) {
                    band[r][j + REACH - r] -= f * band[c][j + REACH - c];
                }
            }
        }
        Some(Self { band })
    }

    /// Solves `L U x = b` in place for one column.
    fn solve(&self, b: &mut [f64]) {
        let m = self.band.len();
        for i in 0..m {
            for j in i.saturating_sub(REACH)..i {
                b[i] -= self.band[i][j + REACH - i] * b[j];
            }
        }
        for i in (0..m).rev() {
            for j in i + 1..(i + REACH + 1).min(m) {
                b[i] -= self.band[i][j + REACH - i] * b[j];
            }
            b[i] /= self.band[i][REACH];
        }
    }
}

/// `A⁻¹ rhs` column by column.
fn columns_solve<const D: usize>(lu: &BandLu, rhs: &[[f64; D]]) -> Vec<[f64; D]> {
    let m = rhs.len();
    let mut x = vec![[0.0; D]; m];
    for c in 0..D {
        let mut col: Vec<f64> = rhs.iter().map(|r| r[c]).collect();
        lu.solve(&mut col);
        for (xi, v) in x.iter_mut().zip(col) {
            xi[c] = v;
        }
    }
    x
}

/// A closed system (k > [`DENSE`]): the first `m = k − REACH` unknowns form an open band `A`,
/// the last `REACH` a border; `M = [[A, B], [C, E]]`, `S = E − C A⁻¹ B`.
fn bordered_solve<const D: usize>(
    rows: &[[f64; WIDTH]],
    rhs: &[[f64; D]],
) -> Option<Vec<[f64; D]>> {
    let k = rows.len();
    let m = k - REACH;
    let col = |i: usize, o: usize| (i + k + o - REACH) % k;
    let mut a = vec![[0.0; WIDTH]; m];
    let mut b = vec![[0.0; REACH]; m];
    let mut c = [[0.0; REACH]; REACH].map(|_| vec![0.0; m]);
    let mut e = [[0.0; REACH]; REACH];
    for i in 0..k {
        for o in 0..WIDTH {
            let (j, v) = (col(i, o), rows[i][o]);
            match (i < m, j < m) {
                (true, true) => a[i][j + REACH - i] += v,
                (true, false) => b[i][j - m] += v,
                (false, true) => c[i - m][j] += v,
                (false, false) => e[i - m][j - m] += v,
            }
        }
    }
    let lu = BandLu::factor(a)?;
    // A⁻¹ B and A⁻¹ b1.
    let ab: Vec<Vec<f64>> = (0..REACH)
        .map(|r| {
            let mut v: Vec<f64> = b.iter().map(|row| row[r]).collect();
            lu.solve(&mut v);
            v
        })
        .collect();
    let ax = columns_solve(&lu, &rhs[..m]);
    let dot = |row: &[f64], v: &dyn Fn(usize) -> f64| (0..m).map(|j| row[j] * v(j)).sum::<f64>();
    let mut s = e;
    for p in 0..REACH {
        for q in 0..REACH {
            s[p][q] -= dot(&c[p], &|j| ab[q][j]);
        }
    }
    let mut y = [[0.0; D]; REACH];
    for p in 0..REACH {
        for d in 0..D {
            y[p][d] = rhs[m + p][d] - dot(&c[p], &|j| ax[j][d]);
        }
    }
    let det = s[0][0] * s[1][1] - s[0][1] * s[1][0];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let mut x2 = [[0.0; D]; REACH];
    for d in 0..D {
        x2[0][d] = (s[1][1] * y[0][d] - s[0][1] * y[1][d]) / det;
        x2[1][d] = (s[0][0] * y[1][d] - s[1][0] * y[0][d]) / det;
    }
    let mut x = ax;
    for j in 0..m {
        for d in 0..D {
            x[j][d] -= ab[0][j] * x2[0][d] + ab[1][j] * x2[1][d];
        }
    }
    x.extend_from_slice(&x2);
    Some(x)
}

/// Small systems: dense Gaussian elimination with partial pivoting.
fn dense_solve<const D: usize>(
    rows: &[[f64; WIDTH]],
    rhs: &[[f64; D]],
    closed: bool,
) -> Option<Vec<[f64; D]>> {
    let k = rows.len();
    let mut a = vec![vec![0.0; k]; k];
    for (i, row) in rows.iter().enumerate() {
        for (o, &v) in row.iter().enumerate() {
            let j = i as isize + o as isize - REACH as isize;
            let j = if closed {
                j.rem_euclid(k as isize) as usize
            } else if (0..k as isize).contains(&j) {
                j as usize
            } else {
                continue;
            };
            a[i][j] += v;
        }
    }
    let mut x = rhs.to_vec();
    for c in 0..k {
        let p = (c..k).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if a[p][c] == 0.0 || !a[p][c].is_finite() {
            return None;
        }
        a.swap(c, p);
        x.swap(c, p);
        for r in c + 1..k {
            let f = a[r][c] / a[c][c];
            for j in c..k {
                a[r][j] -= f * a[c][j];
            }
            let xc = x[c];
            for (v, xc) in x[r].iter_mut().zip(xc) {
                *v -= f * xc;
            }
        }
    }
    for i in (0..k).rev() {
        for j in i + 1..k {
            let xj = x[j];
            for (v, xj) in x[i].iter_mut().zip(xj) {
                *v -= a[i][j] * xj;
            }
        }
        for v in &mut x[i] {
            *v /= a[i][i];
        }
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;
    use proptest::prelude::*;

    /// The dense matrix of `rows`.
    fn dense(rows: &[[f64; WIDTH]], closed: bool) -> DMatrix<f64> {
        let k = rows.len();
        let mut m = DMatrix::zeros(k, k);
        for (i, row) in rows.iter().enumerate() {
            for (o, &v) in row.iter().enumerate() {
                let j = i as isize + o as isize - REACH as isize;
                if closed {
                    m[(i, j.rem_euclid(k as isize) as usize)] += v;
                } else if (0..k as isize).contains(&j) {
                    m[(i, j as usize)] += v;
                }
            }
        }
        m
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]
        /// Random band rows with a dominant diagonal (as the identity rows and the collocation
        /// rows of eq. (4) have away from a double knot, and nearly so next to one) against
        /// nalgebra's dense LU.
        #[test]
        fn matches_dense_lu(
            rows in prop::collection::vec(
                (prop::array::uniform4(-1.0..1.0f64), 4.5..6.0f64, -1.0..1.0f64, -1.0..1.0f64),
                1..40,
            ),
            closed in any::<bool>(),
        ) {
            let band: Vec<[f64; WIDTH]> = rows
                .iter()
                .map(|(off, d, _, _)| [off[0], off[1], *d, off[2], off[3]])
                .collect();
            let rhs: Vec<[f64; 2]> = rows.iter().map(|r| [r.2, r.3]).collect();
            let x = solve_band(&band, &rhs, closed).unwrap();
            let m = dense(&band, closed);
            let k = band.len();
            for col in 0..2 {
                let b = nalgebra::DVector::from_iterator(k, rhs.iter().map(|r| r[col]));
                let xd = m.clone().lu().solve(&b).unwrap();
                for i in 0..k {
                    prop_assert!((x[i][col] - xd[i]).abs() < 1e-10, "{} vs {}", x[i][col], xd[i]);
                }
            }
        }
    }

    #[test]
    fn singular_systems_are_reported() {
        assert!(solve_band(&[[0.0; WIDTH]; 12], &[[1.0]; 12], true).is_none());
        assert!(solve_band(&[[0.0; WIDTH]; 12], &[[1.0]; 12], false).is_none());
        assert!(solve_band(&[[0.0; WIDTH]; 3], &[[1.0]; 3], false).is_none());
        assert!(solve_band::<1>(&[], &[], false).is_none());
    }
}
