//! `Matrix<D>`: the small square matrices of the Class A construction (D = 2 or 3), with the
//! few operations the crate needs: products, transpose, determinant, the eigenvalues of a
//! symmetric matrix and the singular values (both by Jacobi rotations, accurate to a few ulps
//! of the largest value).

use core::ops::{Add, Index, IndexMut, Mul, Sub};

use bez_core::Vector;

/// A D × D matrix of `f64`, stored by rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Matrix<const D: usize>([[f64; D]; D]);

/// A 2 × 2 matrix.
pub type Matrix2 = Matrix<2>;
/// A 3 × 3 matrix.
pub type Matrix3 = Matrix<3>;

/// Jacobi sweeps before giving up (each sweep squares the off-diagonal size; 3 × 3 needs
/// about 5).
const MAX_SWEEPS: usize = 64;

impl<const D: usize> Matrix<D> {
    /// The matrix with these rows.
    #[must_use]
    pub const fn from_rows(rows: [[f64; D]; D]) -> Self {
        Self(rows)
    }

    /// The rows.
    #[must_use]
    pub const fn to_rows(&self) -> [[f64; D]; D] {
        self.0
    }

    /// The identity.
    #[must_use]
    pub fn identity() -> Self {
        Self::from_fn(|i, j| if i == j { 1.0 } else { 0.0 })
    }

    /// The matrix with entry (i, j) = f(i, j).
    #[must_use]
    pub fn from_fn(mut f: impl FnMut(usize, usize) -> f64) -> Self {
        Self(core::array::from_fn(|i| core::array::from_fn(|j| f(i, j))))
    }

    /// The matrix whose columns are `columns`.
    #[must_use]
    pub fn from_columns(columns: &[Vector<D>; D]) -> Self {
        Self::from_fn(|i, j| columns[j][i])
    }

    /// The entries row by row.
    pub fn iter(&self) -> impl Iterator<Item = &f64> {
        self.0.iter().flatten()
    }

    /// Mᵀ.
    #[must_use]
    pub fn transpose(&self) -> Self {
        Self::from_fn(|i, j| self.0[j][i])
    }

    /// Every entry times `s`.
    #[must_use]
    pub fn scale(&self, s: f64) -> Self {
        Self::from_fn(|i, j| self.0[i][j] * s)
    }

    /// The eigenvalues of the symmetric part (M + Mᵀ)/2, in increasing order (cyclic Jacobi).
    #[must_use]
    pub fn symmetric_eigenvalues(&self) -> [f64; D] {
        let mut a = Self::from_fn(|i, j| 0.5 * (self.0[i][j] + self.0[j][i])).0;
        for _ in 0..MAX_SWEEPS {
            let off: f64 = (0..D)
                .flat_map(|i| (0..D).filter(move |&j| j != i).map(move |j| (i, j)))
                .map(|(i, j)| a[i][j] * a[i][j])
                .sum();
            let diag: f64 = (0..D).map(|i| a[i][i] * a[i][i]).sum();
            if off <= f64::EPSILON * f64::EPSILON * diag || off == 0.0 {
                break;
            }
            for p in 0..D {
                for q in p + 1..D {
                    if a[p][q] == 0.0 {
                        continue;
                    }
                    // The rotation that zeroes a[p][q]: tan 2φ = 2a_pq / (a_qq − a_pp).
                    let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                    let t = theta.signum() / (theta.abs() + theta.hypot(1.0));
                    let t = if theta == 0.0 { 1.0 } else { t };
                    let c = 1.0 / t.hypot(1.0);
                    let s = t * c;
                    // A ← Jᵀ A J: columns p and q, then rows p and q.
                    for row in &mut a {
                        let (x, y) = (row[p], row[q]);
                        row[p] = c * x - s * y;
                        row[q] = s * x + c * y;
                    }
                    (a[p], a[q]) = rotate_pair(&a[p], &a[q], c, s);
                }
            }
        }
        let mut e: [f64; D] = core::array::from_fn(|i| a[i][i]);
        e.sort_by(f64::total_cmp);
        e
    }

    /// The singular values σ₁ ≤ … ≤ σ_D, by one-sided Jacobi (Hestenes): plane rotations of
    /// column pairs until all columns are orthogonal; the σ are then the column lengths. Small
    /// singular values keep their relative accuracy (no Mᵀ M is formed).
    #[must_use]
    pub fn singular_values(&self) -> [f64; D] {
        // Columns as rows of the transpose.
        let mut u = self.transpose().0;
        let dot = |x: &[f64; D], y: &[f64; D]| -> f64 { x.iter().zip(y).map(|(a, b)| a * b).sum() };
        for _ in 0..MAX_SWEEPS {
            let mut rotated = false;
            for p in 0..D {
                for q in p + 1..D {
                    let (alpha, beta, gamma) =
                        (dot(&u[p], &u[p]), dot(&u[q], &u[q]), dot(&u[p], &u[q]));
                    if gamma == 0.0 || gamma.abs() <= f64::EPSILON * (alpha * beta).sqrt() {
                        continue;
                    }
                    rotated = true;
                    let zeta = (beta - alpha) / (2.0 * gamma);
                    let t = zeta.signum() / (zeta.abs() + zeta.hypot(1.0));
                    let t = if zeta == 0.0 { 1.0 } else { t };
                    let c = 1.0 / t.hypot(1.0);
                    let s = c * t;
                    (u[p], u[q]) = rotate_pair(&u[p], &u[q], c, s);
                }
            }
            if !rotated {
                break;
            }
        }
        let mut sv: [f64; D] = core::array::from_fn(|i| dot(&u[i], &u[i]).sqrt());
        sv.sort_by(f64::total_cmp);
        sv
    }

    /// (smallest, largest) singular value.
    #[must_use]
    pub fn singular_value_range(&self) -> (f64, f64) {
        let s = self.singular_values();
        (s[0], s[D - 1])
    }
}

/// (c x − s y, s x + c y) for two rows x, y: a plane rotation.
fn rotate_pair<const D: usize>(x: &[f64; D], y: &[f64; D], c: f64, s: f64) -> ([f64; D], [f64; D]) {
    (
        core::array::from_fn(|k| c * x[k] - s * y[k]),
        core::array::from_fn(|k| s * x[k] + c * y[k]),
    )
}

impl<const D: usize> Matrix<D> {
    /// x with a x = b by Gaussian elimination with partial pivoting; the failing pivot if one is
    /// zero or not finite (infinity if the solution overflows).
    pub(crate) fn solve(&self, b: &Vector<D>) -> Result<Vector<D>, f64> {
        let mut a = *self;
        let mut b = b.to_array();
        for col in 0..D {
            let pivot = (col..D)
                .max_by(|&i, &j| a[(i, col)].abs().total_cmp(&a[(j, col)].abs()))
                .unwrap_or(col);
            let p = a[(pivot, col)].abs();
            if !(p > 0.0 && p.is_finite()) {
                return Err(if p.is_nan() { f64::INFINITY } else { p });
            }
            for k in 0..D {
                let t = a[(col, k)];
                a[(col, k)] = a[(pivot, k)];
                a[(pivot, k)] = t;
            }
            b.swap(col, pivot);
            for row in col + 1..D {
                let f = a[(row, col)] / a[(col, col)];
                for k in col..D {
                    let v = a[(col, k)];
                    a[(row, k)] -= f * v;
                }
                b[row] -= f * b[col];
            }
        }
        let mut x = [0.0; D];
        for row in (0..D).rev() {
            let tail: f64 = (row + 1..D).map(|k| a[(row, k)] * x[k]).sum();
            x[row] = (b[row] - tail) / a[(row, row)];
        }
        if x.iter().all(|v| v.is_finite()) {
            Ok(Vector::from_array(x))
        } else {
            Err(f64::INFINITY)
        }
    }
}

impl Matrix<2> {
    /// The matrix [[a, b], [c, d]].
    #[must_use]
    pub const fn new(a: f64, b: f64, c: f64, d: f64) -> Self {
        Self([[a, b], [c, d]])
    }

    /// ad − bc.
    #[must_use]
    pub fn determinant(&self) -> f64 {
        let [[a, b], [c, d]] = self.0;
        a * d - b * c
    }

    /// M⁻¹ = [[d, −b], [−c, a]] / det, or `None` when det = 0 or the result is not finite.
    #[must_use]
    pub fn try_inverse(&self) -> Option<Self> {
        let [[a, b], [c, d]] = self.0;
        let det = self.determinant();
        let inv = Self([[d / det, -b / det], [-c / det, a / det]]);
        (det != 0.0 && inv.iter().all(|x| x.is_finite())).then_some(inv)
    }
}

impl Matrix<3> {
    /// det by cofactors along the first row.
    #[must_use]
    pub fn determinant(&self) -> f64 {
        let m = &self.0;
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    }

    /// The cross-product matrix \[k\]ₓ of v ↦ k × v.
    #[must_use]
    pub fn cross_matrix(k: &Vector<3>) -> Self {
        let (x, y, z) = (k[0], k[1], k[2]);
        Self([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    }
}

impl<const D: usize> Index<(usize, usize)> for Matrix<D> {
    type Output = f64;
    fn index(&self, (i, j): (usize, usize)) -> &f64 {
        &self.0[i][j]
    }
}

impl<const D: usize> IndexMut<(usize, usize)> for Matrix<D> {
    fn index_mut(&mut self, (i, j): (usize, usize)) -> &mut f64 {
        &mut self.0[i][j]
    }
}

impl<const D: usize> Add for Matrix<D> {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        Self::from_fn(|i, j| self.0[i][j] + rhs.0[i][j])
    }
}

impl<const D: usize> Sub for Matrix<D> {
    type Output = Self;
    fn sub(self, rhs: Self) -> Self {
        Self::from_fn(|i, j| self.0[i][j] - rhs.0[i][j])
    }
}

impl<const D: usize> Mul for Matrix<D> {
    type Output = Self;
    fn mul(self, rhs: Self) -> Self {
        Self::from_fn(|i, j| (0..D).map(|k| self.0[i][k] * rhs.0[k][j]).sum())
    }
}

impl<const D: usize> Mul<Vector<D>> for Matrix<D> {
    type Output = Vector<D>;
    fn mul(self, v: Vector<D>) -> Vector<D> {
        Vector::from_fn(|i| (0..D).map(|k| self.0[i][k] * v[k]).sum())
    }
}

impl<const D: usize> Mul<f64> for Matrix<D> {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        self.scale(s)
    }
}

impl<const D: usize> From<[[f64; D]; D]> for Matrix<D> {
    fn from(rows: [[f64; D]; D]) -> Self {
        Self(rows)
    }
}
