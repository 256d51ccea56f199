//! The Bernstein basis B_{i,n}(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ and scalar polynomials in Bernstein form.

use crate::casteljau::{de_casteljau_in_place, elevate_slice};

/// Largest degree for which [`binomial`] and [`bernstein_row`] use exact integer binomials.
///
/// Up to this degree C(n, k) is computed exactly in 128-bit integers and then correctly
/// rounded to `f64` (exact as long as it is below 2⁵³, i.e. for every k when n ≤ 56).
/// Above it the multiplicative formula in floating point is used (relative error ≈ n ulps).
pub const EXACT_BINOMIAL_DEGREE: usize = 120;

/// The binomial coefficient C(n, k) as `f64`; zero when k > n.
///
/// Exact integer arithmetic for n ≤ [`EXACT_BINOMIAL_DEGREE`], then one rounding to `f64`.
///
/// # Examples
/// ```
/// assert_eq!(bez_core::binomial(60, 30), 118_264_581_564_861_424.0);
/// assert_eq!(bez_core::binomial(3, 5), 0.0);
/// ```
#[must_use]
pub fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    let k = k.min(n - k);
    if n <= EXACT_BINOMIAL_DEGREE {
        let mut c: u128 = 1;
        for i in 1..=k {
            // C(n, i) = C(n, i-1) (n - k + i) / i is exact at every step.
            match c.checked_mul((n - k + i) as u128) {
                Some(p) => c = p / i as u128,
                None => return binomial_float(n, k),
            }
        }
        c as f64
    } else {
        binomial_float(n, k)
    }
}

fn binomial_float(n: usize, k: usize) -> f64 {
    let mut c = 1.0_f64;
    for i in 1..=k {
        c = c * (n - k + i) as f64 / i as f64;
    }
    c
}

/// One Bernstein basis polynomial B_{i,n}(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ; zero when i > n.
///
/// Defined for every real t (the polynomial), not only [0, 1].
///
/// # Examples
/// ```
/// assert!((bez_core::bernstein(3, 1, 0.5) - 0.375).abs() < 1e-15);
/// ```
#[must_use]
pub fn bernstein(n: usize, i: usize, t: f64) -> f64 {
    if i > n {
        return 0.0;
    }
    binomial(n, i) * powi(t, i) * powi(1.0 - t, n - i)
}

/// xᵏ by repeated squaring (no i32 conversion as in `f64::powi`).
#[inline]
pub(crate) fn powi(x: f64, k: usize) -> f64 {
    let (mut base, mut e, mut acc) = (x, k, 1.0);
    while e > 0 {
        if e & 1 == 1 {
            acc *= base;
        }
        base *= base;
        e >>= 1;
    }
    acc
}

/// All Bernstein polynomials of degree `out.len() − 1` at `t`, written into `out` without allocating.
///
/// out\[i\] = B_{i,n}(t), n = out.len() − 1. Cost O(n). The values sum to 1 up to rounding
/// (partition of unity). An empty `out` is left alone.
///
/// # Examples
/// ```
/// let mut row = [0.0; 4];
/// bez_core::bernstein_row(0.5, &mut row);
/// assert_eq!(row, [0.125, 0.375, 0.375, 0.125]);
/// ```
pub fn bernstein_row(t: f64, out: &mut [f64]) {
    let Some(n) = out.len().checked_sub(1) else {
        return;
    };
    let s = 1.0 - t;
    // Powers tⁱ left to right, then multiply (1 − t)ⁿ⁻ⁱ right to left.
    let mut tp = 1.0;
    for (i, o) in out.iter_mut().enumerate() {
        *o = binomial(n, i) * tp;
        tp *= t;
    }
    let mut sp = 1.0;
    for o in out.iter_mut().rev() {
        *o *= sp;
        sp *= s;
    }
}

/// The `order`-th derivative of B_{i,n} at t.
///
/// dʳ/dtʳ B_{i,n}(t) = n!/(n−r)! Σ_{j=0}^{r} (−1)ʲ C(r, j) B_{i−r+j, n−r}(t), zero for r > n.
///
/// # Examples
/// ```
/// // d/dt B_{0,2} = d/dt (1 − t)² = −2(1 − t).
/// assert!((bez_core::bernstein_derivative(2, 0, 0.25, 1) + 1.5).abs() < 1e-15);
/// ```
#[must_use]
pub fn bernstein_derivative(n: usize, i: usize, t: f64, order: usize) -> f64 {
    if order > n || i > n {
        return 0.0;
    }
    let m = n - order;
    let mut falling = 1.0;
    for k in 0..order {
        falling *= (n - k) as f64;
    }
    let mut sum = 0.0;
    for j in 0..=order {
        // Index i − r + j of the lower-degree basis; out of range terms vanish.
        let Some(idx) = (i + j).checked_sub(order) else {
            continue;
        };
        if idx > m {
            continue;
        }
        let sign = if j.is_multiple_of(2) { 1.0 } else { -1.0 };
        sum += sign * binomial(order, j) * bernstein(m, idx, t);
    }
    falling * sum
}

/// Evaluates the scalar polynomial Σ cᵢ B_{i,n}(t) (n = coeffs.len() − 1) by de Casteljau.
///
/// Returns 0 for an empty coefficient list. Cost O(n²), no allocation for n < 64.
#[must_use]
pub fn eval_bernstein_poly(coeffs: &[f64], t: f64) -> f64 {
    if coeffs.len() <= 64 {
        let mut buf = [0.0_f64; 64];
        let work = &mut buf[..coeffs.len()];
        work.copy_from_slice(coeffs);
        de_casteljau_in_place(work, t).unwrap_or(0.0)
    } else {
        let mut work = coeffs.to_vec();
        de_casteljau_in_place(&mut work, t).unwrap_or(0.0)
    }
}

/// Bernstein coefficients of the product of two polynomials given in Bernstein form.
///
/// With a of degree m and b of degree n, the product has degree m + n and
/// c_k = Σ_{i+j=k} C(m, i) C(n, j) / C(m+n, k) aᵢ bⱼ. Empty input gives an empty result.
///
/// # Examples
/// ```
/// // (1 − t) · t = B_{1,2} / 2.
/// assert_eq!(bez_core::bernstein_product(&[1.0, 0.0], &[0.0, 1.0]), vec![0.0, 0.5, 0.0]);
/// ```
#[must_use]
pub fn bernstein_product(a: &[f64], b: &[f64]) -> Vec<f64> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let (m, n) = (a.len() - 1, b.len() - 1);
    // Binomial rows once (O(m + n) calls), not per term: the double loop is O(mn).
    let wa: Vec<f64> = a
        .iter()
        .enumerate()
        .map(|(i, &ai)| binomial(m, i) * ai)
        .collect();
    let wb: Vec<f64> = b
        .iter()
        .enumerate()
        .map(|(j, &bj)| binomial(n, j) * bj)
        .collect();
    let mut c = vec![0.0; m + n + 1];
    for (i, &ai) in wa.iter().enumerate() {
        for (j, &bj) in wb.iter().enumerate() {
            c[i + j] += ai * bj;
        }
    }
    for (k, ck) in c.iter_mut().enumerate() {
        *ck /= binomial(m + n, k);
    }
    c
}

/// Bernstein coefficients of the same polynomial written in degree n + r (degree elevation).
#[must_use]
pub fn bernstein_elevate(coeffs: &[f64], r: usize) -> Vec<f64> {
    elevate_slice(coeffs, r)
}

/// Bernstein coefficients (degree n − 1) of the derivative of Σ cᵢ B_{i,n}: n (c_{i+1} − cᵢ).
///
/// A constant (or empty) polynomial has the zero polynomial `[0.0]` as derivative.
#[must_use]
pub fn bernstein_derivative_coeffs(coeffs: &[f64]) -> Vec<f64> {
    if coeffs.len() <= 1 {
        return vec![0.0];
    }
    let n = (coeffs.len() - 1) as f64;
    coeffs.windows(2).map(|w| n * (w[1] - w[0])).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomial_matches_pascal_exactly() {
        let mut row = vec![1u128];
        for n in 1..=EXACT_BINOMIAL_DEGREE {
            let mut next = vec![1u128; n + 1];
            for k in 1..n {
                next[k] = row[k - 1] + row[k];
            }
            row = next;
            for (k, &c) in row.iter().enumerate() {
                assert_eq!(binomial(n, k), c as f64, "C({n},{k})");
            }
        }
    }

    #[test]
    fn bernstein_row_matches_single_values() {
        for n in 0..40 {
            let mut row = vec![0.0; n + 1];
            for &t in &[0.0, 0.1, 0.5, 0.77, 1.0] {
                bernstein_row(t, &mut row);
                for (i, r) in row.iter().enumerate() {
                    assert!((r - bernstein(n, i, t)).abs() <= 1e-14);
                }
            }
        }
    }

    #[test]
    fn bernstein_derivative_matches_finite_difference() {
        let h = 1e-5;
        for n in 1..8 {
            for i in 0..=n {
                for &t in &[0.2, 0.5, 0.9] {
                    let fd = (bernstein(n, i, t + h) - bernstein(n, i, t - h)) / (2.0 * h);
                    assert!((bernstein_derivative(n, i, t, 1) - fd).abs() < 1e-7);
                    let fd2 = (bernstein(n, i, t + h) - 2.0 * bernstein(n, i, t)
                        + bernstein(n, i, t - h))
                        / (h * h);
                    assert!((bernstein_derivative(n, i, t, 2) - fd2).abs() < 1e-3);
                }
            }
        }
    }

    #[test]
    fn bernstein_product_evaluates_to_product() {
        let a = [1.0, -2.0, 0.5, 3.0];
        let b = [0.3, 4.0, -1.0];
        let c = bernstein_product(&a, &b);
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            let lhs = eval_bernstein_poly(&c, t);
            let rhs = eval_bernstein_poly(&a, t) * eval_bernstein_poly(&b, t);
            assert!((lhs - rhs).abs() < 1e-13);
        }
    }
}
