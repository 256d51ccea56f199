//! The Bernstein basis B_{i,n}(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ and scalar polynomials in Bernstein form.

use crate::CoreError;
use crate::casteljau::{de_casteljau_in_place, elevate_slice};
use crate::math;
use alloc::vec;
use alloc::vec::Vec;

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

/// The row C(n, 0), …, C(n, n) in O(n), by C(n, i) = C(n, i − 1)(n − i + 1)/i: exact integers
/// rounded once (equal to [`binomial`]) up to [`EXACT_BINOMIAL_DEGREE`], then in floating point
/// from both ends to the middle (within n/2 roundings of the exact values, infinite beyond
/// degree about 1,029).
pub(crate) fn binomial_row(n: usize) -> Vec<f64> {
    let mut row = vec![1.0; n + 1];
    if n <= EXACT_BINOMIAL_DEGREE {
        let mut c: u128 = 1;
        for (i, r) in row.iter_mut().enumerate().skip(1) {
            c = c * (n - i + 1) as u128 / i as u128;
            *r = c as f64;
        }
    } else {
        let mut c = 1.0;
        for i in 1..=n / 2 {
            c = c * (n - i + 1) as f64 / i as f64;
            row[i] = c;
            row[n - i] = c;
        }
    }
    row
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
/// Defined for every real t (the polynomial), not only [0, 1]. For t in [0, 1] the value is
/// finite and accurate at every degree: when C(n, i) overflows or a power of t or 1 − t leaves
/// the normal range of `f64` (degrees above about 1000, or t very close to 0 or 1), it is
/// computed as exp(ln C(n, i) + i ln t + (n − i) ln(1 − t)) instead, with a relative error of a
/// few times n ulps; a true value below the smallest `f64` is 0.
///
/// # Examples
/// ```
/// assert!((bez_core::bernstein(3, 1, 0.5) - 0.375).abs() < 1e-15);
/// // C(2000, 1000) overflows f64, B_{1000,2000}(½) ≈ 0.0178 does not.
/// assert!((bez_core::bernstein(2000, 1000, 0.5) - 0.017839).abs() < 1e-6);
/// ```
#[must_use]
pub fn bernstein(n: usize, i: usize, t: f64) -> f64 {
    if i > n {
        return 0.0;
    }
    let c = binomial(n, i);
    let (a, b) = (powi(t, i), powi(1.0 - t, n - i));
    let direct = c * a * b;
    let in_range = |x: f64, base: f64| x.abs() >= f64::MIN_POSITIVE || base == 0.0;
    if (0.0..=1.0).contains(&t) && !(direct.is_finite() && in_range(a, t) && in_range(b, 1.0 - t)) {
        return math::exp(ln_bernstein(n, i, t));
    }
    direct
}

/// ln C(n, k) as a sum of k = min(k, n − k) logarithms of exact ratios: O(min(k, n − k)).
fn ln_binomial(n: usize, k: usize) -> f64 {
    let k = k.min(n - k);
    (1..=k)
        .map(|j| math::ln((n - k + j) as f64 / j as f64))
        .sum()
}

/// ln B_{i,n}(t) for t in [0, 1] (−∞ where the value is exactly 0).
fn ln_bernstein(n: usize, i: usize, t: f64) -> f64 {
    let ln_t = if i == 0 { 0.0 } else { i as f64 * math::ln(t) };
    let ln_s = if i == n {
        0.0
    } else {
        (n - i) as f64 * math::ln_1p(-t)
    };
    ln_binomial(n, i) + ln_t + ln_s
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
/// out\[i\] = B_{i,n}(t), n = out.len() − 1. Cost O(n) at every degree. The values sum to 1 up
/// to rounding (partition of unity). An empty `out` is left alone.
///
/// Up to degree [`EXACT_BINOMIAL_DEGREE`] the row is C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ with the exact
/// binomials of [`binomial`] (the same bits as [`bernstein`]). For t in [0, 1] at higher degrees,
/// or where a power of t or 1 − t leaves the normal `f64` range, it starts from the largest term
/// i = ⌊nt⌋ in logarithmic form and walks outwards with the ratio
/// B_{i+1,n} / B_{i,n} = (n − i)/(i + 1) · t/(1 − t), so nothing overflows: every value is finite
/// and terms below the smallest `f64` are 0.
///
/// # Examples
/// ```
/// let mut row = [0.0; 4];
/// bez_core::bernstein_row(0.5, &mut row);
/// assert_eq!(row, [0.125, 0.375, 0.375, 0.125]);
///
/// let mut big = vec![0.0; 5001];
/// bez_core::bernstein_row(0.3, &mut big);
/// assert!((big.iter().sum::<f64>() - 1.0).abs() < 1e-9);
/// ```
pub fn bernstein_row(t: f64, out: &mut [f64]) {
    let Some(n) = out.len().checked_sub(1) else {
        return;
    };
    let inside = (0.0..=1.0).contains(&t);
    if n > EXACT_BINOMIAL_DEGREE && inside {
        bernstein_row_from_mode(t, out);
        return;
    }
    let s = 1.0 - t;
    // Exact binomials by C(n, i) = C(n, i − 1)(n − i + 1)/i in 128-bit integers (exact at every
    // step up to EXACT_BINOMIAL_DEGREE), with powers tⁱ left to right.
    let mut c: u128 = 1;
    let mut tp = 1.0;
    let mut underflow = false;
    for (i, o) in out.iter_mut().enumerate() {
        if i > 0 {
            c = c * (n - i + 1) as u128 / i as u128;
        }
        *o = c as f64 * tp;
        underflow |= tp.abs() < f64::MIN_POSITIVE && t != 0.0;
        tp *= t;
    }
    // Then (1 − t)ⁿ⁻ⁱ right to left.
    let mut sp = 1.0;
    for o in out.iter_mut().rev() {
        *o *= sp;
        underflow |= sp.abs() < f64::MIN_POSITIVE && s != 0.0;
        sp *= s;
    }
    if underflow && inside {
        bernstein_row_from_mode(t, out);
    }
}

/// The row for t in [0, 1] from its largest term outwards (see [`bernstein_row`]).
fn bernstein_row_from_mode(t: f64, out: &mut [f64]) {
    let n = out.len() - 1;
    if t == 0.0 || t == 1.0 {
        out.fill(0.0);
        out[if t == 0.0 { 0 } else { n }] = 1.0;
        return;
    }
    let mode = ((n as f64 * t) as usize).min(n);
    out[mode] = math::exp(ln_bernstein(n, mode, t));
    let r = t / (1.0 - t);
    for i in mode + 1..=n {
        out[i] = out[i - 1] * ((n - i + 1) as f64 / i as f64 * r);
    }
    for i in (0..mode).rev() {
        out[i] = out[i + 1] * ((i + 1) as f64 / (n - i) as f64 / r);
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
    if m + n > PRODUCT_EXACT_DEGREE {
        return bernstein_product_log(a, b);
    }
    // Binomial rows once, in O(m + n), not per term: the double loop is O(mn).
    let wa: Vec<f64> = a
        .iter()
        .zip(binomial_row(m))
        .map(|(&ai, c)| c * ai)
        .collect();
    let wb: Vec<f64> = b
        .iter()
        .zip(binomial_row(n))
        .map(|(&bj, c)| c * bj)
        .collect();
    let mut c = vec![0.0; m + n + 1];
    for (i, &ai) in wa.iter().enumerate() {
        for (j, &bj) in wb.iter().enumerate() {
            c[i + j] += ai * bj;
        }
    }
    for (ck, binom) in c.iter_mut().zip(binomial_row(m + n)) {
        *ck /= binom;
    }
    c
}

/// Above this product degree [`bernstein_product`] forms its weights in logarithms (the
/// binomials C(m + n, k) leave the `f64` range near degree 1030).
const PRODUCT_EXACT_DEGREE: usize = 500;

/// [`bernstein_product`] with each weight C(m, i) C(n, j) / C(m+n, i+j) ≤ 1 (a hypergeometric
/// probability) formed as the exponential of a sum of logarithms: finite at every degree.
fn bernstein_product_log(a: &[f64], b: &[f64]) -> Vec<f64> {
    let (m, n) = (a.len() - 1, b.len() - 1);
    let (la, lb, lc) = (
        ln_binomial_row(m),
        ln_binomial_row(n),
        ln_binomial_row(m + n),
    );
    let mut c = vec![0.0; m + n + 1];
    for (i, &ai) in a.iter().enumerate() {
        for (j, &bj) in b.iter().enumerate() {
            c[i + j] += math::exp(la[i] + lb[j] - lc[i + j]) * ai * bj;
        }
    }
    c
}

/// ln C(n, i) for i = 0..=n, by ln C(n, i) = ln C(n, i − 1) + ln((n − i + 1)/i).
fn ln_binomial_row(n: usize) -> Vec<f64> {
    let mut row = Vec::with_capacity(n + 1);
    let mut acc = 0.0;
    row.push(acc);
    for i in 1..=n {
        acc += math::ln((n - i + 1) as f64 / i as f64);
        row.push(acc);
    }
    row
}

/// Bernstein coefficients of the same polynomial written in degree n + r (degree elevation).
///
/// # Errors
/// As [`elevate_slice`](crate::elevate_slice).
pub fn bernstein_elevate(coeffs: &[f64], r: usize) -> Result<Vec<f64>, CoreError> {
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
    fn binomial_rows_match_single_binomials() {
        for n in [0, 1, 2, 7, 60, 119, 120] {
            let row = binomial_row(n);
            for (i, c) in row.iter().enumerate() {
                assert_eq!(*c, binomial(n, i), "C({n},{i})");
            }
        }
        for n in [121, 200, 500, 1000] {
            let row = binomial_row(n);
            for (i, c) in row.iter().enumerate() {
                let exact = binomial(n, i);
                assert!(
                    (c - exact).abs() <= 1e-12 * exact,
                    "C({n},{i}): {c} vs {exact}"
                );
            }
        }
    }

    #[test]
    fn product_in_logarithms_matches_the_exact_weights_and_stays_finite() {
        // Degree 60 · 70: both ways agree; degree 3000 · 3000: finite and the product of the
        // values at t = 0.3.
        let a: Vec<f64> = (0..=60).map(|i| ((i * 7) % 11) as f64 - 5.0).collect();
        let b: Vec<f64> = (0..=70).map(|i| ((i * 5) % 13) as f64 - 6.0).collect();
        let exact = bernstein_product(&a, &b);
        let logs = bernstein_product_log(&a, &b);
        for (x, y) in exact.iter().zip(&logs) {
            assert!((x - y).abs() <= 1e-12 * (1.0 + x.abs()), "{x} vs {y}");
        }
        let a: Vec<f64> = (0..=3000).map(|i| (i as f64 * 0.01).sin()).collect();
        let b: Vec<f64> = (0..=3000).map(|i| (i as f64 * 0.003).cos()).collect();
        let c = bernstein_product(&a, &b);
        assert!(c.iter().all(|x| x.is_finite()));
        let t = 0.3;
        let (pa, pb, pc) = (
            eval_bernstein_poly(&a, t),
            eval_bernstein_poly(&b, t),
            eval_bernstein_poly(&c, t),
        );
        assert!((pa * pb - pc).abs() < 1e-9);
    }

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

    /// The previous O(n²) row: `binomial` per entry times tⁱ, then times (1 − t)ⁿ⁻ⁱ, with the
    /// powers as running products.
    fn direct_row(t: f64, n: usize) -> Vec<f64> {
        let mut tp = 1.0;
        let mut row: Vec<f64> = (0..=n)
            .map(|i| {
                let v = binomial(n, i) * tp;
                tp *= t;
                v
            })
            .collect();
        let mut sp = 1.0;
        for o in row.iter_mut().rev() {
            *o *= sp;
            sp *= 1.0 - t;
        }
        row
    }

    #[test]
    fn bernstein_row_is_bit_identical_to_the_direct_formula_up_to_the_exact_degree() {
        for n in 0..=EXACT_BINOMIAL_DEGREE {
            let mut row = vec![0.0; n + 1];
            for &t in &[0.0, 0.013, 0.1, 0.25, 0.5, 0.77, 0.999, 1.0] {
                bernstein_row(t, &mut row);
                let direct = direct_row(t, n);
                // Same bits wherever the direct formula stays in the normal range (elsewhere the
                // row is recomputed from its largest term, see the high-degree tests).
                let exact_ends = t == 0.0 || t == 1.0;
                if exact_ends || direct.iter().all(|v| v.abs() >= f64::MIN_POSITIVE) {
                    assert_eq!(row, direct, "n = {n}, t = {t}");
                }
            }
        }
    }

    /// B_{i,n}(p/q) exactly in rationals, rounded to f64 once.
    fn exact_bernstein(n: usize, i: usize, p: i64, q: i64) -> f64 {
        use num_bigint::BigInt;
        use num_rational::BigRational;
        use num_traits::{One, ToPrimitive};
        let t = BigRational::new(BigInt::from(p), BigInt::from(q));
        let s = BigRational::one() - &t;
        let mut c = BigInt::one();
        for j in 1..=i {
            c = c * BigInt::from(n - i + j) / BigInt::from(j);
        }
        let v = BigRational::from_integer(c) * num_traits::pow(t, i) * num_traits::pow(s, n - i);
        v.to_f64().unwrap_or(f64::NAN)
    }

    #[test]
    fn high_degree_values_are_finite_and_match_exact_rationals() {
        for &(n, p, q) in &[
            (1500, 3, 8),
            (2000, 1, 2),
            (5000, 1, 1000),
            (1200, 999, 1000),
        ] {
            let t = p as f64 / q as f64;
            let mut row = vec![0.0; n + 1];
            bernstein_row(t, &mut row);
            assert!(row.iter().all(|v| v.is_finite() && *v >= 0.0), "n = {n}");
            assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-10, "n = {n}");
            let mode = (n as f64 * t) as usize;
            for i in [0, 1, mode / 2, mode, (mode + n) / 2, n - 1, n] {
                let exact = exact_bernstein(n, i, p, q);
                for value in [row[i], bernstein(n, i, t)] {
                    let scale = exact.abs().max(1e-300);
                    assert!(
                        (value - exact).abs() <= 1e-10 * scale,
                        "B_{{{i},{n}}}({t}) = {value}, exact {exact}"
                    );
                }
            }
        }
    }

    #[test]
    fn tiny_parameters_keep_representable_values() {
        // t¹¹⁰ underflows, B_{110,1500}(10⁻³) ≈ 1e-158 does not.
        let exact = exact_bernstein(1500, 110, 1, 1000);
        assert!(exact > 1e-200);
        let v = bernstein(1500, 110, 1e-3);
        assert!((v - exact).abs() <= 1e-10 * exact, "{v} vs {exact}");
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
