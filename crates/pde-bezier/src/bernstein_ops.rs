//! Bernstein-basis matrices: derivative, degree elevation and Gram (inner-product) matrices.
//!
//! All matrices act on coefficient column vectors of the unit interval's Bernstein basis.

use crate::dense::Dense;
use bez_core::binomial;

/// The p-th derivative as a map from degree-n to degree-(n−p) Bernstein coefficients.
///
/// (d/dt) Σ b_i B_i^n = n Σ (b_{i+1} − b_i) B_i^{n−1}, applied p times; (n−p+1) × (n+1).
/// For p > n the derivative vanishes: the 1 × (n+1) zero map (a degree-0 zero).
pub(crate) fn derivative_matrix(n: usize, p: usize) -> Dense {
    if p > n {
        return Dense::zeros(1, n + 1);
    }
    let mut m = Dense::identity(n + 1);
    for step in 0..p {
        let deg = n - step;
        let mut d = Dense::zeros(deg, deg + 1);
        for i in 0..deg {
            d[(i, i)] = -(deg as f64);
            d[(i, i + 1)] = deg as f64;
        }
        m = &d * &m;
    }
    m
}

/// Degree elevation from degree a to degree b ≥ a.
///
/// E[j][i] = C(a,i) C(b−a, j−i) / C(b, j).
pub(crate) fn elevation_matrix(a: usize, b: usize) -> Dense {
    let r = b.saturating_sub(a);
    Dense::from_fn(b + 1, a + 1, |j, i| {
        if j < i || j - i > r {
            0.0
        } else {
            binomial(a, i) * binomial(r, j - i) / binomial(b, j)
        }
    })
}

/// Mixed Gram matrix G[i][j] = ∫₀¹ B_i^a B_j^b dt = C(a,i) C(b,j) / ((a+b+1) C(a+b, i+j)).
pub(crate) fn gram_matrix(a: usize, b: usize) -> Dense {
    Dense::from_fn(a + 1, b + 1, |i, j| {
        binomial(a, i) * binomial(b, j) / ((a + b + 1) as f64 * binomial(a + b, i + j))
    })
}

/// A square root of the Gram matrix: Q = diag(√w_q) [B_i^a(x_q)] at the (a+1)-point
/// Gauss–Legendre rule, so that Qᵀ Q = G(a, a) exactly (the rule integrates degree 2a).
/// ‖Q b‖² = ∫₀¹ (Σ b_i B_i^a)² without forming G, whose condition grows like 4^a.
pub(crate) fn gram_root(a: usize) -> Dense {
    let (x, w) = crate::quadrature::gauss_legendre(a + 1);
    let mut q = Dense::zeros(a + 1, a + 1);
    for (k, (&x, &w)) in x.iter().zip(&w).enumerate() {
        let b = bernstein_values(a, x);
        for (i, v) in b.iter().enumerate() {
            q[(k, i)] = w.sqrt() * v;
        }
    }
    q
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
                let value: f64 = (0..=n - p)
                    .map(|j| d[(j, i)] * bernstein(n - p, j, t))
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
        let mine = &e * &Dense::from_fn(4, 1, |i, _| c[i]);
        let core = bernstein_elevate(&c, 3).unwrap();
        for (k, b) in core.iter().enumerate() {
            let a = mine[(k, 0)];
            assert!((a - b).abs() < 1e-14);
        }
    }

    #[test]
    fn gram_root_squares_to_the_gram_matrix() {
        for a in [0usize, 3, 10, 30] {
            let q = gram_root(a);
            let qtq = &q.transpose() * &q;
            let g = gram_matrix(a, a);
            for i in 0..=a {
                for j in 0..=a {
                    assert!((qtq[(i, j)] - g[(i, j)]).abs() < 1e-14, "a {a} ({i}, {j})");
                }
            }
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
            assert!(((0..=4).map(|j| g[(i, j)]).sum::<f64>() - 0.25).abs() < 1e-15);
        }
    }
}
