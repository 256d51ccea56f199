//! Double-double ("double-word") numbers x = hi + lo, |lo| ≤ ulp(hi)/2, for the certificates'
//! second filter stage.
//!
//! The algorithms are the error-free transformations TwoSum (Knuth), Fast2Sum (Dekker) and
//! TwoProd by Dekker's splitting (no fused multiply-add needed, so the results are the same on
//! every target), combined as in Joldes, Muller, Popescu, *Tight and rigorous error bounds for
//! basic building blocks of double-word arithmetic*, ACM TOMS 44 (2017): addition by their
//! Algorithm 6 (AccurateDWPlusDW, relative error ≤ 3u²/(1 − 4u)) and multiplication by their
//! Algorithm 10 (DWTimesDW1, relative error ≤ 7u²), u = 2⁻⁵³, both without underflow or
//! overflow. The filter charges [`UNIT`] = 2⁻¹⁰⁰ = 64u² per operation, which covers both bounds
//! and the absolute error of an underflowing partial product (module `filter`).

/// The error charged to one double-double operation, relative to the magnitude of its operands
/// (2⁻¹⁰⁰; the published bounds are at most 7·2⁻¹⁰⁶).
pub(crate) const UNIT: f64 = 7.888_609_052_210_118e-31; // 2⁻¹⁰⁰

/// A double-double number hi + lo.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Dd {
    pub(crate) hi: f64,
    pub(crate) lo: f64,
}

/// s + e = a + b exactly (TwoSum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// s + e = a + b exactly, for |a| ≥ |b| or a = 0 (Fast2Sum).
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Dekker's splitting a = h + l, each half of at most 26 significant bits.
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2²⁷ + 1
    let h = c - (c - a);
    (h, a - h)
}

/// p + e = a·b exactly (no underflow), with a and b already split.
fn two_prod_split(a: f64, (ah, al): (f64, f64), b: f64, (bh, bl): (f64, f64)) -> (f64, f64) {
    let p = a * b;
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl Dd {
    /// Zero.
    pub(crate) const ZERO: Self = Self { hi: 0.0, lo: 0.0 };

    /// The f64 x, exactly.
    pub(crate) fn from_f64(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    /// a − b exactly.
    pub(crate) fn difference(a: f64, b: f64) -> Self {
        let (hi, lo) = two_sum(a, -b);
        Self { hi, lo }
    }

    /// The integer x exactly as hi + lo (every x below 2¹⁰⁶ and some above), else `None`.
    pub(crate) fn from_u128(x: u128) -> Option<Self> {
        let hi = x as f64;
        let rest = i128::try_from(x).ok()? - (hi as i128);
        let lo = rest as f64;
        (lo as i128 == rest && hi.is_finite()).then_some(Self { hi, lo })
    }

    /// Multiplication by 2ᵏ given as the f64 `p` (exact unless it under- or overflows).
    pub(crate) fn scale(self, p: f64) -> Self {
        Self {
            hi: self.hi * p,
            lo: self.lo * p,
        }
    }

    /// Both parts finite.
    pub(crate) fn is_finite(self) -> bool {
        self.hi.is_finite() && self.lo.is_finite()
    }

    /// Sum (Algorithm 6 of Joldes, Muller, Popescu 2017).
    pub(crate) fn add(self, y: Self) -> Self {
        let (sh, sl) = two_sum(self.hi, y.hi);
        let (th, tl) = two_sum(self.lo, y.lo);
        let c = sl + th;
        let (vh, vl) = fast_two_sum(sh, c);
        let w = tl + vl;
        let (hi, lo) = fast_two_sum(vh, w);
        Self { hi, lo }
    }

    /// Product (Algorithm 10 of Joldes, Muller, Popescu 2017).
    pub(crate) fn mul(self, y: Self) -> Self {
        self.mul_split(split(self.hi), y, split(y.hi))
    }

    /// Product with both high parts already split (the same operations as [`Dd::mul`]).
    pub(crate) fn mul_split(self, xs: (f64, f64), y: Self, ys: (f64, f64)) -> Self {
        let (ch, cl1) = two_prod_split(self.hi, xs, y.hi, ys);
        let cl2 = self.hi * y.lo + self.lo * y.hi;
        let cl3 = cl1 + cl2;
        let (hi, lo) = fast_two_sum(ch, cl3);
        Self { hi, lo }
    }

    /// The split of the high part, for [`Dd::mul_split`].
    pub(crate) fn split_hi(self) -> (f64, f64) {
        split(self.hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;
    use num_traits::{Signed, float::FloatCore};

    /// SplitMix64: an f64 in [−1, 1) times 2ᵏ, k ∈ [−30, 30].
    struct Rng(u64);
    impl Rng {
        fn bits(&mut self) -> u64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        }
        fn f(&mut self) -> f64 {
            let x = (self.bits() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
            x * 2f64.powi((self.bits() % 61) as i32 - 30)
        }
        fn dd(&mut self) -> Dd {
            let (a, b) = (self.f(), self.f() * 1e-17);
            let (hi, lo) = two_sum(a, b);
            Dd { hi, lo }
        }
    }

    /// The exponent q with every value an integer multiple of 2^q.
    fn grid(v: &[f64]) -> i32 {
        v.iter()
            .filter(|x| **x != 0.0)
            .map(|x| {
                let (m, e, _) = x.integer_decode();
                i32::from(e) + m.trailing_zeros() as i32
            })
            .min()
            .unwrap_or(0)
    }

    /// x / 2^q as an exact integer (x must be a multiple of 2^q).
    fn on_grid(x: f64, q: i32) -> BigInt {
        let (m, e, s) = x.integer_decode();
        let shift = i32::from(e) - q;
        let v = if shift >= 0 {
            BigInt::from(m) << shift.unsigned_abs()
        } else {
            assert!(m.trailing_zeros() as i32 + shift >= 0 || m == 0);
            BigInt::from(m) >> shift.unsigned_abs()
        };
        if s < 0 { -v } else { v }
    }

    /// |got − exact| · 2¹⁰⁶ ≤ k · |exact|.
    fn within(got: &BigInt, exact: &BigInt, k: u32) -> bool {
        ((got - exact).abs() << 106u32) <= exact.abs() * BigInt::from(k)
    }

    #[test]
    fn sums_and_products_meet_the_published_bounds() {
        let mut rng = Rng(7);
        for _ in 0..3000 {
            let (x, y) = (rng.dd(), rng.dd());
            let q = grid(&[x.hi, x.lo, y.hi, y.lo]);
            let xi = on_grid(x.hi, q) + on_grid(x.lo, q);
            let yi = on_grid(y.hi, q) + on_grid(y.lo, q);
            // Sum: rounding keeps multiples of 2^q.
            let s = x.add(y);
            let si = on_grid(s.hi, q) + on_grid(s.lo, q);
            assert!(within(&si, &(&xi + &yi), 4), "{x:?} + {y:?}");
            assert!(s.lo.abs() <= s.hi.abs() * f64::EPSILON);
            // Product: multiples of 2^(2q).
            let p = x.mul(y);
            let pi = on_grid(p.hi, 2 * q) + on_grid(p.lo, 2 * q);
            assert!(within(&pi, &(&xi * &yi), 7), "{x:?} · {y:?}");
        }
        // Cancellation: the sum of x and −x(1 + 2⁻⁹⁰) is exact.
        let x = Dd {
            hi: 1.0,
            lo: 2f64.powi(-60),
        };
        let y = Dd {
            hi: -1.0,
            lo: -2f64.powi(-60) - 2f64.powi(-90),
        };
        assert_eq!(
            x.add(y),
            Dd {
                hi: -(2f64.powi(-90)),
                lo: 0.0
            }
        );
    }

    #[test]
    fn integers_convert_exactly_up_to_106_bits() {
        let x = (1u128 << 105) + 1;
        let d = Dd::from_u128(x).unwrap();
        assert_eq!(d.hi as i128 + d.lo as i128, x as i128);
        assert!(Dd::from_u128((1u128 << 120) + (1 << 60) + 1).is_none());
        let d = Dd::from_u128((1u128 << 120) + 1).unwrap();
        assert_eq!((d.hi, d.lo), (2f64.powi(120), 1.0));
        assert_eq!(Dd::from_u128(1 << 120).unwrap().lo, 0.0);
        let d = Dd::difference(1.0, 1e-30);
        assert_eq!((d.hi, d.lo), (1.0, -1e-30));
    }
}
