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
}
