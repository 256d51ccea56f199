//! The exact interval of λ for which the λ-B basis of degree n + 1 is non-negative.
//!
//! Derivation (proved in `docs/papers/lambda-bezier.md`). Each basis function has only two
//! non-zero Bernstein coefficients ([`crate::corner_cut_ratio`]):
//!
//! b_{k,n+1}(t) = αₖ B_{k,n+1}(t) + (1 − α_{k+1}) B_{k+1,n+1}(t)
//!             = t^k (1 − t)^{n−k} [C(n+1,k) αₖ (1 − t) + C(n+1,k+1) (1 − α_{k+1}) t],
//!
//! so b_{k,n+1} ≥ 0 on [0, 1] exactly when the linear bracket is non-negative at t = 0 and
//! t = 1, i.e. when αₖ ≥ 0 and α_{k+1} ≤ 1. Here nonnegativity of the Bernstein coefficients
//! is necessary as well as sufficient. With
//! αⱼ = (n+1−j)/(n+1) · [1 + λ j (n+1−2j) / (n(n−1))], the conditions over all j reduce to
//!
//! −n(n−1) / M(n) ≤ λ ≤ 1,   M(n) = max_{1≤j≤n} j (n + 1 − 2j).
//!
//! The paper states [−2, 1], [−3, 1], [−4, 1] for n = 2, 3, 4 (true) and suggests [−n, 1]
//! (false from n = 6 on: n = 6 gives [−5, 1]); the lower end decreases towards −8 and
//! stays above it for every n.

use crate::error::LambdaError;

/// Largest supported n: n(n − 1) and M(n) stay exact in u64 and in f64's 53-bit mantissa.
const MAX_N: usize = 1 << 26;

/// The exact valid interval [min, 1] of λ for the λ-B basis of degree n + 1.
///
/// `min = −numerator / denominator` with `numerator = n(n−1)` and
/// `denominator = M(n) = max_{1≤j≤n} j(n+1−2j)` (not reduced).
///
/// With the `serde` feature it is stored as its n alone and rebuilt (and checked) by
/// [`LambdaRange::new`] when deserialized.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "RangeRepr", into = "RangeRepr")
)]
pub struct LambdaRange {
    n: usize,
    numerator: u64,
    denominator: u64,
    argmax: usize,
}

/// The serialized form of a [`LambdaRange`]: its n.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct RangeRepr {
    n: usize,
}

#[cfg(feature = "serde")]
impl TryFrom<RangeRepr> for LambdaRange {
    type Error = LambdaError;
    fn try_from(r: RangeRepr) -> Result<Self, LambdaError> {
        Self::new(r.n)
    }
}

#[cfg(feature = "serde")]
impl From<LambdaRange> for RangeRepr {
    fn from(r: LambdaRange) -> Self {
        Self { n: r.n }
    }
}

impl LambdaRange {
    /// The exact interval for n ≥ 2 (degree n + 1 ≥ 3).
    ///
    /// # Errors
    /// [`LambdaError::DegreeTooLow`] for n < 2; `CoreError::TooLarge` for n > 2²⁶ (the exact
    /// fraction would no longer be exact in f64).
    ///
    /// ```
    /// use lambda_bezier::LambdaRange;
    /// let r = LambdaRange::new(6)?;
    /// assert_eq!((r.min(), r.max()), (-5.0, 1.0)); // not [-6, 1]
    /// # Ok::<(), lambda_bezier::LambdaError>(())
    /// ```
    pub fn new(n: usize) -> Result<Self, LambdaError> {
        if n < 2 {
            return Err(LambdaError::DegreeTooLow { n });
        }
        if n > MAX_N {
            return Err(bez_core::CoreError::TooLarge {
                requested: n,
                max: MAX_N,
            }
            .into());
        }
        // j(n+1−2j) is a concave parabola in j with its peak at (n+1)/4: the integer maximum is at
        // floor or ceil of it (both ≥ 1 and ≤ n for n ≥ 2).
        let value = |j: usize| -> u64 {
            let j = j as u64;
            j * (n as u64 + 1 - 2 * j)
        };
        let lo = ((n + 1) / 4).max(1);
        let hi = (lo + 1).min(n.div_ceil(2));
        let argmax = if value(hi) > value(lo) { hi } else { lo };
        Ok(Self {
            n,
            numerator: (n as u64) * (n as u64 - 1),
            denominator: value(argmax),
            argmax,
        })
    }

    /// The n of the basis (degree n + 1).
    #[must_use]
    pub fn n(&self) -> usize {
        self.n
    }

    /// Lower end: −n(n−1)/M(n), correctly rounded to f64 (exact for the small n in use).
    #[must_use]
    pub fn min(&self) -> f64 {
        -(self.numerator as f64) / (self.denominator as f64)
    }

    /// Upper end: always 1 (at λ = 1, α₁ = 1 and b_{0,n+1} = (1 − t)^{n+1}; beyond it b_{0,n+1} < 0 near t = 0).
    #[must_use]
    pub fn max(&self) -> f64 {
        1.0
    }

    /// The lower end as an unreduced fraction: min = −numerator/denominator.
    #[must_use]
    pub fn min_fraction(&self) -> (u64, u64) {
        (self.numerator, self.denominator)
    }

    /// The index j where the lower bound is attained: at λ = min, α_j = 0, so
    /// b_{j,n+1} loses its B_{j,n+1} coefficient (and the basis becomes linearly dependent).
    #[must_use]
    pub fn binding_index(&self) -> usize {
        self.argmax
    }

    /// Whether λ lies in [min, 1].
    #[must_use]
    pub fn contains(&self, lambda: f64) -> bool {
        lambda >= self.min() && lambda <= self.max()
    }

    /// Returns λ if it lies in the interval, else a typed error stating the interval.
    ///
    /// # Errors
    /// [`LambdaError::NonFiniteLambda`], [`LambdaError::LambdaOutOfRange`].
    pub fn check(&self, lambda: f64) -> Result<f64, LambdaError> {
        if !lambda.is_finite() {
            return Err(LambdaError::NonFiniteLambda { lambda });
        }
        if !self.contains(lambda) {
            return Err(LambdaError::LambdaOutOfRange {
                lambda,
                n: self.n,
                min: self.min(),
                max: self.max(),
            });
        }
        Ok(lambda)
    }
}

/// The valid λ interval for degree n + 1: shorthand for [`LambdaRange::new`].
///
/// # Errors
/// [`LambdaError::DegreeTooLow`] for n < 2.
pub fn lambda_range(n: usize) -> Result<LambdaRange, LambdaError> {
    LambdaRange::new(n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_cases_and_the_break_at_six() {
        let mins: Vec<f64> = (2..=10)
            .map(|n| LambdaRange::new(n).unwrap().min())
            .collect();
        assert_eq!(
            mins,
            [-2.0, -3.0, -4.0, -5.0, -5.0, -5.25, -5.6, -6.0, -6.0]
        );
    }

    #[test]
    fn argmax_matches_brute_force_and_bound_above_minus_eight() {
        for n in 2..2000usize {
            let r = LambdaRange::new(n).unwrap();
            let brute = (1..=n)
                .map(|j| j as i64 * (n as i64 + 1 - 2 * j as i64))
                .max()
                .unwrap();
            assert_eq!(r.min_fraction().1 as i64, brute, "n = {n}");
            assert!(r.min() > -8.0);
        }
        assert!(LambdaRange::new(1_000_000).unwrap().min() < -7.99);
    }

    #[test]
    fn rejects_low_degree_and_bad_lambda() {
        assert_eq!(LambdaRange::new(1), Err(LambdaError::DegreeTooLow { n: 1 }));
        assert!(LambdaRange::new(usize::MAX).is_err());
        assert!(LambdaRange::new(1 << 26).is_ok());
        let r = LambdaRange::new(3).unwrap();
        assert!(matches!(
            r.check(f64::NAN),
            Err(LambdaError::NonFiniteLambda { .. })
        ));
        let e = r.check(-3.5).unwrap_err();
        assert_eq!(
            e.to_string(),
            "shape parameter λ = -3.5 is outside the valid interval [-3, 1] for n = 3"
        );
        assert!(r.check(1.0 + 1e-15).is_err());
        assert_eq!(r.check(-3.0), Ok(-3.0));
    }
}
