//! Small dense matrices for the local maps of one patch or one piece (row-major).
//!
//! Everything global is sparse (see `sparse`); these matrices are at most
//! (n+1)(m+1) × (n+1)(m+1) for bidegree (n, m).

use std::ops::{Index, IndexMut, Mul};

/// A row-major dense matrix.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Dense {
    rows: usize,
    cols: usize,
    data: Vec<f64>,
}

impl Dense {
    pub(crate) fn zeros(rows: usize, cols: usize) -> Self {
        Self {
            rows,
            cols,
            data: vec![0.0; rows * cols],
        }
    }

    pub(crate) fn identity(n: usize) -> Self {
        Self::from_fn(n, n, |i, j| if i == j { 1.0 } else { 0.0 })
    }

    pub(crate) fn from_fn(rows: usize, cols: usize, f: impl Fn(usize, usize) -> f64) -> Self {
        let mut data = Vec::with_capacity(rows * cols);
        for i in 0..rows {
            for j in 0..cols {
                data.push(f(i, j));
            }
        }
        Self { rows, cols, data }
    }

    pub(crate) fn nrows(&self) -> usize {
        self.rows
    }

    pub(crate) fn ncols(&self) -> usize {
        self.cols
    }

    /// Rows start..start + count.
    pub(crate) fn rows_range(&self, start: usize, count: usize) -> Self {
        Self {
            rows: count,
            cols: self.cols,
            data: self.data[start * self.cols..(start + count) * self.cols].to_vec(),
        }
    }

    pub(crate) fn transpose(&self) -> Self {
        Self::from_fn(self.cols, self.rows, |i, j| self[(j, i)])
    }

    pub(crate) fn scaled(mut self, s: f64) -> Self {
        for x in &mut self.data {
            *x *= s;
        }
        self
    }

    /// self += other · s.
    pub(crate) fn add_scaled(&mut self, other: &Self, s: f64) {
        debug_assert_eq!((self.rows, self.cols), (other.rows, other.cols));
        for (a, b) in self.data.iter_mut().zip(&other.data) {
            *a += s * b;
        }
    }

    /// The Kronecker product self ⊗ other (row index i·other.rows + k).
    pub(crate) fn kron(&self, other: &Self) -> Self {
        let (r, c) = (other.rows, other.cols);
        let mut out = Self::zeros(self.rows * r, self.cols * c);
        for i in 0..self.rows {
            for j in 0..self.cols {
                let a = self[(i, j)];
                if a == 0.0 {
                    continue;
                }
                for k in 0..r {
                    for l in 0..c {
                        out[(i * r + k, j * c + l)] = a * other[(k, l)];
                    }
                }
            }
        }
        out
    }

    /// Solves self · X = rhs by Gaussian elimination with partial pivoting (square self);
    /// `None` when a pivot vanishes.
    pub(crate) fn solve(&self, rhs: &Self) -> Option<Self> {
        let n = self.rows;
        debug_assert_eq!(n, self.cols);
        debug_assert_eq!(n, rhs.rows);
        let mut a = self.clone();
        let mut b = rhs.clone();
        for col in 0..n {
            let pivot =
                (col..n).max_by(|&x, &y| a[(x, col)].abs().total_cmp(&a[(y, col)].abs()))?;
            let p = a[(pivot, col)];
            if p == 0.0 || !p.is_finite() {
                return None;
            }
            a.swap_rows(col, pivot);
            b.swap_rows(col, pivot);
            for row in col + 1..n {
                let f = a[(row, col)] / p;
                if f == 0.0 {
                    continue;
                }
                for k in col..n {
                    a[(row, k)] -= f * a[(col, k)];
                }
                for k in 0..b.cols {
                    b[(row, k)] -= f * b[(col, k)];
                }
            }
        }
        for col in (0..n).rev() {
            for k in 0..b.cols {
                let mut s = b[(col, k)];
                for j in col + 1..n {
                    s -= a[(col, j)] * b[(j, k)];
                }
                b[(col, k)] = s / a[(col, col)];
            }
        }
        b.data.iter().all(|x| x.is_finite()).then_some(b)
    }

    fn swap_rows(&mut self, a: usize, b: usize) {
        if a != b {
            for k in 0..self.cols {
                self.data.swap(a * self.cols + k, b * self.cols + k);
            }
        }
    }
}

impl Index<(usize, usize)> for Dense {
    type Output = f64;
    fn index(&self, (i, j): (usize, usize)) -> &f64 {
        &self.data[i * self.cols + j]
    }
}

impl IndexMut<(usize, usize)> for Dense {
    fn index_mut(&mut self, (i, j): (usize, usize)) -> &mut f64 {
        &mut self.data[i * self.cols + j]
    }
}

impl Mul for &Dense {
    type Output = Dense;
    fn mul(self, rhs: &Dense) -> Dense {
        debug_assert_eq!(self.cols, rhs.rows);
        let mut out = Dense::zeros(self.rows, rhs.cols);
        for i in 0..self.rows {
            for k in 0..self.cols {
                let a = self[(i, k)];
                if a == 0.0 {
                    continue;
                }
                let row = &rhs.data[k * rhs.cols..(k + 1) * rhs.cols];
                let out_row = &mut out.data[i * rhs.cols..(i + 1) * rhs.cols];
                for (o, b) in out_row.iter_mut().zip(row) {
                    *o += a * b;
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn product_kron_and_solve_agree_with_hand_values() {
        let a = Dense::from_fn(2, 2, |i, j| [[2.0, 1.0], [1.0, 3.0]][i][j]);
        let b = Dense::from_fn(2, 1, |i, _| [3.0, 5.0][i]);
        let x = a.solve(&b).unwrap();
        // 2x + y = 3, x + 3y = 5 → x = 0.8, y = 1.4.
        assert!((x[(0, 0)] - 0.8).abs() < 1e-15 && (x[(1, 0)] - 1.4).abs() < 1e-15);
        let ax = &a * &x;
        assert!((ax[(0, 0)] - 3.0).abs() < 1e-14 && (ax[(1, 0)] - 5.0).abs() < 1e-14);
        let k = a.kron(&Dense::identity(2));
        assert_eq!(k[(1, 3)], 1.0);
        assert_eq!(k[(3, 1)], 1.0);
        assert_eq!(k[(2, 2)], 3.0);
        assert!(Dense::zeros(2, 2).solve(&b).is_none());
    }
}
