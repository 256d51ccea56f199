//! Exact rational arithmetic shared by the oracle tests.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;

/// Exact rationals.
pub(crate) type Q = BigRational;

/// The exact rational value of a finite `f64`.
pub(crate) fn q(x: f64) -> Q {
    Q::from_float(x).expect("finite")
}

/// The binomial coefficient C(n, k) as an exact rational.
pub(crate) fn binom(n: usize, k: usize) -> Q {
    let mut c = BigInt::one();
    for i in 1..=k {
        c = c * BigInt::from(n - k + i) / BigInt::from(i);
    }
    Q::from_integer(c)
}
