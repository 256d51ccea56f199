//! The few `f64` functions that `core` lacks: `std`'s when the `std` feature is on, `libm`'s
//! otherwise (the same IEEE operations: `sqrt` and `fma` are correctly rounded in both).

/// √x.
#[inline(always)]
pub(crate) fn sqrt(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrt(x)
    }
}

/// eˣ.
#[inline]
pub(crate) fn exp(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.exp()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::exp(x)
    }
}

/// ln x.
#[inline]
pub(crate) fn ln(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.ln()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::log(x)
    }
}

/// ln(1 + x), accurate for small x.
#[inline]
pub(crate) fn ln_1p(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.ln_1p()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::log1p(x)
    }
}

/// √(a² + b²) without undue overflow or underflow.
#[inline]
pub(crate) fn hypot(a: f64, b: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        a.hypot(b)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::hypot(a, b)
    }
}

/// a·b + c with one rounding.
#[inline]
pub(crate) fn fma(a: f64, b: f64, c: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        a.mul_add(b, c)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::fma(a, b, c)
    }
}

/// The power of two 2ᵉ with 2ᵉ ≤ x < 2ᵉ⁺¹ for a positive normal x, else 1: dividing by it
/// brings x into [1, 2) exactly (no rounding), so a computation on scaled values and scaled
/// back gives the same bits as the unscaled one wherever that one does not overflow.
#[inline]
pub(crate) fn pow2_scale(x: f64) -> f64 {
    if x.is_normal() && x > 0.0 {
        f64::from_bits(x.to_bits() & 0x7ff0_0000_0000_0000)
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agree_with_exact_values() {
        assert_eq!(sqrt(2.25), 1.5);
        assert_eq!(exp(0.0), 1.0);
        assert_eq!(ln(1.0), 0.0);
        assert!((ln(exp(3.5)) - 3.5).abs() < 1e-15);
        assert_eq!(ln_1p(0.0), 0.0);
        assert!((ln_1p(1e-20) - 1e-20).abs() < 1e-35);
        assert_eq!(hypot(3e300, 4e300), 5e300);
        // 0.1 * 10 - 1 is 0 in two roundings; the fused product keeps the representation error.
        assert_eq!(fma(0.1, 10.0, -1.0), 5.551115123125783e-17);
    }

    #[test]
    fn pow2_scale_is_the_leading_power_of_two() {
        assert_eq!(pow2_scale(1.0), 1.0);
        assert_eq!(pow2_scale(1.999), 1.0);
        assert_eq!(pow2_scale(2.0), 2.0);
        assert_eq!(pow2_scale(0.3), 0.25);
        assert_eq!(pow2_scale(1e300), 2f64.powi(996));
        for x in [0.0, -1.0, f64::INFINITY, f64::NAN, f64::MIN_POSITIVE / 4.0] {
            assert_eq!(pow2_scale(x), 1.0);
        }
    }
}
