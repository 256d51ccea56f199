//! Bernstein-basis matrices: derivative, degree elevation and Gram (inner-product) matrices.
//!
//! All matrices act on coefficient column vectors of the unit interval's Bernstein basis.

use bez_core::binomial;
use nalgebra::DMatrix;

/// The p-th derivative as a map from degree-n to degree-(n−p) Bernstein coefficients.
///
/// (d/dt) Σ b_i B_i^n = n Σ (b_{i+1} − b_i) B_i^{n−1}, applied p times; (n−p+1) × (n+1).
/// For p > n the derivative vanishes: the 1 × (n+1) zero map (a degree-0 zero).
pub(crate) fn derivative_matrix(n: usize, p: usize) -> DMatrix<f64> {
    if p > n {
        return DMatrix::zeros(1, n + 1);
    }
    let mut m = DMatrix::<f64>::identity(n + 1, n + 1);
    for step in 0..p {
        let deg = n - step;
        let mut d = DMatrix::<f64>::zeros(deg, deg + 1);
        for i in 0..deg {
            d[(i, i)] = -(deg as f64);
            d[(i, i + 1)] = deg as f64;
        }
        m = d * m;
    }
    m
}

/// Degree elevation from degree a to degree b ≥ a.
///
/// E[j][i] = C(a,i) C(b−a, j−i) / C(b, j).
pub(crate) fn elevation_matrix(a: usize, b: usize) -> DMatrix<f64> {
    let r = b.saturating_sub(a);
    DMatrix::from_fn(b + 1, a + 1, |j, i| {
        if j < i || j - i > r {
            0.0
        } else {
            binomial(a, i) * binomial(r, j - i) / binomial(b, j)
        }
    })
}

/// Mixed Gram matrix G[i][j] = ∫₀¹ B_i^a B_j^b dt = C(a,i) C(b,j) / ((a+b+1) C(a+b, i+j)).
pub(crate) fn gram_matrix(a: usize, b: usize) -> DMatrix<f64> {
    DMatrix::from_fn(a + 1, b + 1, |i, j| {
        binomial(a, i) * binomial(b, j) / ((a + b + 1) as f64 * binomial(a + b, i + j))
    })
}

/// The Bernstein basis of degree n at t as a row vector.
pub(crate) fn bernstein_values(n: usize, t: f64) -> Vec<f64> {
    let mut out = vec![0.0; n + 1];
    bez_core::bernstein_row(t, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use bez_core::{bernstein, bernstein_derivative, bernstein_elevate};

    #[test]
    fn derivative_matrix_matches_bernstein_derivative() {
        let n = 5;
        for p in 0..=3 {
            let d = derivative_matrix(n, p);
            let t = 0.37;
            for i in 0..=n {
                let coeffs = d.column(i);
                let value: f64 = (0..=n - p)
                    .map(|j| coeffs[j] * bernstein(n - p, j, t))
                    .sum();
                let expected = bernstein_derivative(n, i, t, p);
                assert!((value - expected).abs() < 1e-10, "p={p} i={i}");
            }
        }
    }

    #[test]
    fn elevation_matrix_matches_core_elevation() {
        let c = [1.0, -2.0, 0.5, 3.0];
        let e = elevation_matrix(3, 6);
        let mine = e * nalgebra::DVector::from_row_slice(&c);
        let core = bernstein_elevate(&c, 3).unwrap();
        for (a, b) in mine.iter().zip(&core) {
            assert!((a - b).abs() < 1e-14);
        }
    }

    #[test]
    fn gram_matrix_matches_quadrature() {
        let g = gram_matrix(3, 4);
        // Gauss-Legendre would do; a fine midpoint rule is enough for degree 7 to 1e-9.
        let steps = 20_000;
        for i in 0..=3 {
            for j in 0..=4 {
                let mut s = 0.0;
                for k in 0..steps {
                    let t = (k as f64 + 0.5) / steps as f64;
                    s += bernstein(3, i, t) * bernstein(4, j, t);
                }
                s /= steps as f64;
                assert!((s - g[(i, j)]).abs() < 1e-8);
            }
        }
        // Rows of the Gram matrix sum to ∫ B_i^a = 1/(a+1).
        for i in 0..=3 {
            assert!((g.row(i).sum() - 0.25).abs() < 1e-15);
        }
    }
}
