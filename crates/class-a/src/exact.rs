//! Exact integer polynomials in the scaled Bernstein basis tᵏ(1 − t)ᴺ⁻ᵏ.
//!
//! A polynomial of degree N with Bernstein coefficients bₖ is Σ aₖ tᵏ(1 − t)ᴺ⁻ᵏ with
//! aₖ = C(N, k)·bₖ. In this basis a product is a plain convolution of coefficient vectors and
//! the derivative is aₖ' = (k + 1)aₖ₊₁ − (N − k)aₖ, so integer inputs give integer results, and
//! the sign of aₖ is the sign of bₖ.

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero, float::FloatCore};

/// An exact polynomial Σ aₖ tᵏ(1 − t)ᴺ⁻ᵏ with integer coefficients aₖ = C(N, k)·bₖ.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ScaledBernstein {
    coeffs: Vec<BigInt>,
}

/// Binomial coefficients C(n, 0..=n) as exact integers.
pub(crate) fn binomial_row(n: usize) -> Vec<BigInt> {
    let mut row = Vec::with_capacity(n + 1);
    let mut c = BigInt::one();
    row.push(c.clone());
    for k in 0..n {
        c = c * BigInt::from(n - k) / BigInt::from(k + 1);
        row.push(c.clone());
    }
    row
}

impl ScaledBernstein {
    /// The polynomial with scaled coefficients `coeffs` (degree `coeffs.len() − 1`); an empty
    /// vector is the zero polynomial of degree 0.
    #[must_use]
    pub(crate) fn new(coeffs: Vec<BigInt>) -> Self {
        if coeffs.is_empty() {
            Self {
                coeffs: vec![BigInt::zero()],
            }
        } else {
            Self { coeffs }
        }
    }

    /// The polynomial with Bernstein coefficients `b` (aₖ = C(N, k)·bₖ).
    #[must_use]
    pub(crate) fn from_bernstein(b: Vec<BigInt>) -> Self {
        let row = binomial_row(b.len().saturating_sub(1));
        Self::new(b.into_iter().zip(row).map(|(x, c)| x * c).collect())
    }

    /// The degree N.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.coeffs.len() - 1
    }

    /// The scaled coefficients a₀..a_N.
    #[must_use]
    pub fn coefficients(&self) -> &[BigInt] {
        &self.coeffs
    }

    /// Whether every coefficient is zero (the zero polynomial).
    #[must_use]
    pub fn is_zero(&self) -> bool {
        self.coeffs.iter().all(Zero::is_zero)
    }

    /// The product: tⁱ(1 − t)ᴺ⁻ⁱ · tʲ(1 − t)ᴹ⁻ʲ = tⁱ⁺ʲ(1 − t)ᴺ⁺ᴹ⁻ⁱ⁻ʲ, a convolution.
    #[must_use]
    pub(crate) fn mul(&self, other: &Self) -> Self {
        let mut out = vec![BigInt::zero(); self.coeffs.len() + other.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for (j, b) in other.coeffs.iter().enumerate() {
                out[i + j] += a * b;
            }
        }
        Self { coeffs: out }
    }

    /// Degree elevation by r: multiplication by ((1 − t) + t)ʳ.
    #[must_use]
    pub(crate) fn elevate(&self, r: usize) -> Self {
        if r == 0 {
            return self.clone();
        }
        self.mul(&Self::new(binomial_row(r)))
    }

    /// self + k·other, elevating the lower degree first.
    #[must_use]
    pub(crate) fn add_scaled(&self, other: &Self, k: i64) -> Self {
        let n = self.degree().max(other.degree());
        let a = self.elevate(n - self.degree());
        let b = other.elevate(n - other.degree());
        let k = BigInt::from(k);
        Self::new(
            a.coeffs
                .into_iter()
                .zip(b.coeffs)
                .map(|(x, y)| x + &k * y)
                .collect(),
        )
    }

    /// The derivative, aₖ' = (k + 1)aₖ₊₁ − (N − k)aₖ (degree N − 1; a constant gives zero).
    #[must_use]
    pub(crate) fn derivative(&self) -> Self {
        let n = self.degree();
        Self::new(
            (0..n)
                .map(|k| {
                    BigInt::from(k + 1) * &self.coeffs[k + 1]
                        - BigInt::from(n - k) * &self.coeffs[k]
                })
                .collect(),
        )
    }

    /// Bernstein coefficients times N!: bₖ·N! = aₖ·k!(N − k)! (exact integers, same signs).
    #[must_use]
    pub(crate) fn bernstein_times_factorial(&self) -> Vec<BigInt> {
        let n = self.degree();
        let mut fact = vec![BigInt::one(); n + 1];
        for k in 1..=n {
            fact[k] = &fact[k - 1] * BigInt::from(k);
        }
        self.coeffs
            .iter()
            .enumerate()
            .map(|(k, a)| a * &fact[k] * &fact[n - k])
            .collect()
    }

    /// The sign (−1, 0, 1) of the polynomial at the dyadic point t = m / 2ʲ ∈ [0, 1], exactly:
    /// 2ʲᴺ f(t) = Σ aₖ mᵏ (2ʲ − m)ᴺ⁻ᵏ.
    #[must_use]
    pub(crate) fn sign_at(&self, m: &BigInt, j: u32) -> i8 {
        let n = self.degree();
        let q = (BigInt::one() << j) - m;
        // Horner-like: Σ aₖ mᵏ qᴺ⁻ᵏ, accumulating powers of q from the top.
        let mut acc = BigInt::zero();
        let mut mk = BigInt::one();
        let mut qpow = vec![BigInt::one(); n + 1];
        for k in 1..=n {
            qpow[k] = &qpow[k - 1] * &q;
        }
        for (k, a) in self.coeffs.iter().enumerate() {
            if !a.is_zero() {
                acc += a * &mk * &qpow[n - k];
            }
            mk *= m;
        }
        sign(&acc)
    }
}

/// The sign of an integer as −1, 0, 1.
pub(crate) fn sign(x: &BigInt) -> i8 {
    if x.is_positive() {
        1
    } else if x.is_negative() {
        -1
    } else {
        0
    }
}

/// Exact integers X = x·2⁻ᵉ for every coordinate x, with e the smallest binary exponent over
/// the non-zero coordinates (every finite f64 is a dyadic rational m·2ᵉ). `None` if a coordinate
/// is not finite.
pub(crate) fn to_common_integers(values: &[f64]) -> Option<Vec<BigInt>> {
    if !values.iter().all(|x| x.is_finite()) {
        return None;
    }
    // Odd mantissas (trailing zero bits moved into the exponent) keep the integers small.
    let decoded: Vec<(u64, i16, i8)> = values
        .iter()
        .map(|x| {
            let (m, e, s) = x.integer_decode();
            let tz = if m == 0 { 0 } else { m.trailing_zeros() };
            (m >> tz, e + tz as i16, s)
        })
        .collect();
    let emin = decoded
        .iter()
        .filter(|d| d.0 != 0)
        .map(|d| d.1)
        .min()
        .unwrap_or(0);
    Some(
        decoded
            .iter()
            .map(|&(m, e, s)| {
                if m == 0 {
                    return BigInt::zero();
                }
                let v =
                    BigInt::from(m) << u32::try_from(i32::from(e) - i32::from(emin)).unwrap_or(0);
                if s < 0 { -v } else { v }
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(v: &[i64]) -> ScaledBernstein {
        ScaledBernstein::new(v.iter().map(|&x| BigInt::from(x)).collect())
    }

    #[test]
    fn product_derivative_and_evaluation_agree_with_power_form() {
        // f = 1 − 2t = (1 − t) − t; g = t² = t²(1 − t)⁰.
        let f = poly(&[1, -1]);
        let g = poly(&[0, 0, 1]);
        let h = f.mul(&g); // t² − 2t³ = t²(1 − t) − t³
        assert_eq!(h, poly(&[0, 0, 1, -1]));
        // h' = 2t − 6t² = 2t(1−t)² + 2t²(1−t)·... check by evaluation at dyadic points.
        let d = h.derivative();
        for (m, j, want) in [
            (1, 1, 2.0 * 0.5 - 6.0 * 0.25),
            (1, 2, 0.5 - 6.0 / 16.0),
            (3, 2, 1.5 - 6.0 * 9.0 / 16.0),
        ] {
            let s = d.sign_at(&BigInt::from(m), j);
            assert_eq!(
                f64::from(s),
                want.signum() * f64::from(u8::from(want != 0.0))
            );
        }
        // (2t − 6t²) vanishes at t = 1/3 (not dyadic) and at 0.
        assert_eq!(d.sign_at(&BigInt::from(0), 0), 0);
        assert_eq!(poly(&[1, -1]).sign_at(&BigInt::from(1), 1), 0);
        // Elevation does not change values: (1 − 2t) elevated twice.
        assert_eq!(f.elevate(2), poly(&[1, 1, -1, -1]));
        // Bernstein coefficients × N!: [1, 1, −1, −1] / C(3,k) × 3! = [6, 2, −2, −6].
        let want: Vec<BigInt> = [6, 2, -2, -6].iter().map(|&x| BigInt::from(x)).collect();
        assert_eq!(f.elevate(2).bernstein_times_factorial(), want);
    }

    #[test]
    fn common_integers_are_exact() {
        let v = to_common_integers(&[0.5, -0.75, 0.0, 3.0]).unwrap();
        let want: Vec<BigInt> = [2, -3, 0, 12].iter().map(|&x| BigInt::from(x)).collect();
        assert_eq!(v, want);
        assert!(to_common_integers(&[f64::NAN]).is_none());
        // 2⁻¹⁰²⁵ is subnormal: the ratio to 1 is still exact.
        let tiny = to_common_integers(&[1.0, f64::MIN_POSITIVE / 4.0]).unwrap();
        assert_eq!(tiny[0], &tiny[1] << 1024u32);
    }
}
