//! The λ-B basis of degree n + 1 (Definition 1, eqs. (1)–(2)) and its Bernstein form.

use bez_core::{CoreError, bernstein_derivative, bernstein_row};

use crate::error::LambdaError;
use crate::range::LambdaRange;

/// The corner-cutting ratio αⱼ(n, λ), j = 0..=n+1: the closed form of the λ-B basis.
///
/// αⱼ = (n+1−j)/(n+1) · [1 + λ j (n+1−2j) / (n(n−1))],   α₀ = 1, α_{n+1} = 0.
///
/// The λ-B basis function b_{k,n+1} has exactly two non-zero Bernstein coefficients of degree
/// n + 1, both linear in λ:
///
/// b_{k,n+1}(t) = αₖ B_{k,n+1}(t) + (1 − α_{k+1}) B_{k+1,n+1}(t),
///
/// so a λ-Bézier curve Σ Pₖ b_{k,n+1} is the degree n + 1 Bézier curve with control points
/// Qⱼ = (1 − αⱼ) Pⱼ₋₁ + αⱼ Pⱼ. At λ = 0 this is degree elevation, αⱼ = (n+1−j)/(n+1)
/// (Property 6). Derived from the recurrence (2) written as
/// b_{k,n+1} = Σ_{i=0}^{2} B_{k−i,n−2} b_{i,3} (see `docs/papers/lambda-bezier.md`).
///
/// Returns NaN for n < 2 or j > n + 1 (callers validate first).
#[must_use]
pub fn corner_cut_ratio(n: usize, j: usize, lambda: f64) -> f64 {
    if n < 2 || j > n.saturating_add(1) {
        return f64::NAN;
    }
    let (nf, jf) = (n as f64, j as f64);
    // j(n+1−2j) is an exact integer in f64 for any realistic n; compute it signed.
    let shape = jf * (nf + 1.0 - 2.0 * jf) / (nf * (nf - 1.0));
    (nf + 1.0 - jf) / (nf + 1.0) * (1.0 + lambda * shape)
}

/// `CoreError::DegreeTooHigh` unless the basis degree n + 1 is within bez-core's limit (the
/// basis functions are Bézier polynomials of that degree; all work is then bounded).
fn check_basis_degree(n: usize) -> Result<(), LambdaError> {
    let degree = n.saturating_add(1);
    if degree > bez_core::MAX_DEGREE {
        return Err(CoreError::DegreeTooHigh {
            max: bez_core::MAX_DEGREE,
            degree,
        }
        .into());
    }
    Ok(())
}

/// The λ-B basis {b_{0,n+1}, …, b_{n,n+1}} for n ≥ 2 and a validated λ.
///
/// Degree 3 (n = 2, Han & Liu, eq. (1)):
/// b_{0,3} = (1 − λt)(1 − t)², b_{1,3} = (2 + λ)(1 − t)t, b_{2,3} = (1 − λ + λt)t²;
/// higher degrees by the recurrence (2): b_{k,n+1} = (1 − t) b_{k,n} + t b_{k−1,n},
/// b_{−1,n} = b_{n,n} = 0. Evaluation uses the closed Bernstein form ([`corner_cut_ratio`]);
/// [`LambdaBasis::eval_by_recurrence`] runs the paper's recurrence as an independent check.
///
/// Errata: eq. (5) (values unimodal in k at fixed t) holds for λ ∈ [−2/3, 1] but not on the whole
/// valid interval; the functions are linearly dependent at the lower end of [`LambdaRange`].
///
/// ```
/// use lambda_bezier::LambdaBasis;
/// let b = LambdaBasis::new(3, -1.0)?;
/// let t = 0.25_f64;
/// // The paper's b_{1,4} = (3 + λ − λt)(1 − t)² t.
/// let paper = (3.0 - 1.0 + 0.25) * (1.0 - t).powi(2) * t;
/// assert!((b.eval(1, t)? - paper).abs() < 1e-15);
/// # Ok::<(), lambda_bezier::LambdaError>(())
/// ```
///
/// Deserialization checks what [`LambdaBasis::new_unrestricted`] checks (n ≥ 2, n within
/// [`LambdaRange`]'s limit, finite λ).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "BasisRepr", into = "BasisRepr")
)]
pub struct LambdaBasis {
    n: usize,
    lambda: f64,
}

/// The serialized form of a [`LambdaBasis`].
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct BasisRepr {
    n: usize,
    lambda: f64,
}

#[cfg(feature = "serde")]
impl TryFrom<BasisRepr> for LambdaBasis {
    type Error = LambdaError;
    fn try_from(r: BasisRepr) -> Result<Self, LambdaError> {
        Self::new_unrestricted(r.n, r.lambda)
    }
}

#[cfg(feature = "serde")]
impl From<LambdaBasis> for BasisRepr {
    fn from(b: LambdaBasis) -> Self {
        Self {
            n: b.n,
            lambda: b.lambda,
        }
    }
}

impl LambdaBasis {
    /// The basis for n ≥ 2 (n + 1 functions of degree n + 1) and λ in [`LambdaRange`].
    ///
    /// # Errors
    /// [`LambdaError::DegreeTooLow`], [`LambdaError::NonFiniteLambda`],
    /// [`LambdaError::LambdaOutOfRange`]; `CoreError::DegreeTooHigh` when the degree n + 1
    /// exceeds bez-core's [`MAX_DEGREE`](bez_core::MAX_DEGREE).
    pub fn new(n: usize, lambda: f64) -> Result<Self, LambdaError> {
        check_basis_degree(n)?;
        let lambda = LambdaRange::new(n)?.check(lambda)?;
        Ok(Self { n, lambda })
    }

    /// The basis without the range check, for exploring λ outside the valid interval
    /// (the functions then take negative values). Still needs n ≥ 2 and a finite λ.
    ///
    /// # Errors
    /// [`LambdaError::DegreeTooLow`], [`LambdaError::NonFiniteLambda`], `CoreError::DegreeTooHigh`
    /// as in [`Self::new`].
    pub fn new_unrestricted(n: usize, lambda: f64) -> Result<Self, LambdaError> {
        check_basis_degree(n)?;
        LambdaRange::new(n)?;
        if !lambda.is_finite() {
            return Err(LambdaError::NonFiniteLambda { lambda });
        }
        Ok(Self { n, lambda })
    }

    /// n: the basis has n + 1 functions.
    #[must_use]
    pub fn n(&self) -> usize {
        self.n
    }

    /// The polynomial degree n + 1.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.n + 1
    }

    /// The shape parameter λ.
    #[must_use]
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// The corner-cutting ratios α₀..α_{n+1} ([`corner_cut_ratio`]).
    #[must_use]
    pub fn ratios(&self) -> Vec<f64> {
        (0..=self.n + 1)
            .map(|j| corner_cut_ratio(self.n, j, self.lambda))
            .collect()
    }

    /// The n + 2 Bernstein coefficients (degree n + 1) of b_{k,n+1}: only entries k and k + 1
    /// are non-zero, αₖ and 1 − α_{k+1}.
    ///
    /// # Errors
    /// [`LambdaError::IndexOutOfRange`] for k > n.
    pub fn bernstein_coefficients(&self, k: usize) -> Result<Vec<f64>, LambdaError> {
        self.check_index(k)?;
        let mut c = vec![0.0; self.n + 2];
        c[k] = corner_cut_ratio(self.n, k, self.lambda);
        c[k + 1] = 1.0 - corner_cut_ratio(self.n, k + 1, self.lambda);
        Ok(c)
    }

    /// b_{k,n+1}(t).
    ///
    /// # Errors
    /// [`LambdaError::IndexOutOfRange`], t outside [0, 1] ([`CoreError::ParameterOutOfRange`]).
    pub fn eval(&self, k: usize, t: f64) -> Result<f64, LambdaError> {
        self.derivative(k, t, 0)
    }

    /// The `order`-th derivative of b_{k,n+1} at t (order 0 is the value).
    ///
    /// # Errors
    /// [`LambdaError::IndexOutOfRange`], t outside [0, 1]; `CoreError::Overflow` when the value
    /// is not representable (high orders at high degree).
    pub fn derivative(&self, k: usize, t: f64, order: usize) -> Result<f64, LambdaError> {
        self.check_index(k)?;
        check_t(t)?;
        let m = self.n + 1;
        let a = corner_cut_ratio(self.n, k, self.lambda);
        let b = 1.0 - corner_cut_ratio(self.n, k + 1, self.lambda);
        let value =
            a * bernstein_derivative(m, k, t, order) + b * bernstein_derivative(m, k + 1, t, order);
        if value.is_finite() {
            Ok(value)
        } else {
            Err(CoreError::Overflow {
                operation: "basis derivative",
            }
            .into())
        }
    }

    /// All n + 1 values b_{0,n+1}(t), …, b_{n,n+1}(t) into `out` (length n + 1), in O(n)
    /// without allocating.
    ///
    /// # Errors
    /// [`CoreError::BufferLength`] when `out.len() != n + 1`, t outside [0, 1].
    pub fn row(&self, t: f64, out: &mut [f64]) -> Result<(), LambdaError> {
        if out.len() != self.n + 1 {
            return Err(CoreError::BufferLength {
                len: out.len(),
                expected: self.n + 1,
            }
            .into());
        }
        check_t(t)?;
        // Degree-n Bernstein row in place, then B_{k,n+1} = (1−t)B_{k,n} + t B_{k−1,n} on the fly.
        bernstein_row(t, out);
        let s = 1.0 - t;
        let n = self.n;
        let mut prev = 0.0; // B_{k−1,n}
        let mut alpha = 1.0; // α_k, α_0 = 1
        for k in 0..=n {
            let cur = out[k];
            let next = if k < n { out[k + 1] } else { 0.0 };
            let b_k = s * cur + t * prev; // B_{k,n+1}
            let b_k1 = s * next + t * cur; // B_{k+1,n+1}
            let alpha_next = corner_cut_ratio(n, k + 1, self.lambda);
            out[k] = alpha * b_k + (1.0 - alpha_next) * b_k1;
            prev = cur;
            alpha = alpha_next;
        }
        Ok(())
    }

    /// All n + 1 values by the paper's recurrence (2) from the degree-3 basis (1): O(n²),
    /// kept as an independent algorithm for tests and for readers who want the definition.
    ///
    /// # Errors
    /// t outside [0, 1].
    pub fn eval_by_recurrence(&self, t: f64) -> Result<Vec<f64>, LambdaError> {
        check_t(t)?;
        let l = self.lambda;
        let s = 1.0 - t;
        let mut b = vec![
            (1.0 - l * t) * s * s,
            (2.0 + l) * s * t,
            (1.0 - l + l * t) * t * t,
        ];
        for _ in 3..=self.n {
            let mut next = Vec::with_capacity(b.len() + 1);
            for k in 0..=b.len() {
                let own = b.get(k).copied().unwrap_or(0.0);
                let left = k
                    .checked_sub(1)
                    .and_then(|i| b.get(i))
                    .copied()
                    .unwrap_or(0.0);
                next.push(s * own + t * left);
            }
            b = next;
        }
        Ok(b)
    }

    fn check_index(&self, k: usize) -> Result<(), LambdaError> {
        if k > self.n {
            Err(LambdaError::IndexOutOfRange { k, n: self.n })
        } else {
            Ok(())
        }
    }
}

fn check_t(t: f64) -> Result<(), CoreError> {
    if (0.0..=1.0).contains(&t) {
        Ok(())
    } else {
        Err(CoreError::ParameterOutOfRange {
            name: "t",
            value: t,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degree_three_is_han_liu() {
        for &l in &[-2.0, -1.0, 0.0, 0.5, 1.0] {
            let b = LambdaBasis::new(2, l).unwrap();
            for i in 0..=10 {
                let t = f64::from(i) / 10.0;
                let s = 1.0 - t;
                let want = [
                    (1.0 - l * t) * s * s,
                    (2.0 + l) * s * t,
                    (1.0 - l + l * t) * t * t,
                ];
                let mut row = [0.0; 3];
                b.row(t, &mut row).unwrap();
                for k in 0..3 {
                    assert!((row[k] - want[k]).abs() < 1e-15);
                    assert!((b.eval(k, t).unwrap() - want[k]).abs() < 1e-15);
                }
            }
        }
    }

    #[test]
    fn bad_inputs_are_typed_errors() {
        let b = LambdaBasis::new(4, 0.5).unwrap();
        assert!(matches!(
            b.eval(5, 0.5),
            Err(LambdaError::IndexOutOfRange { k: 5, n: 4 })
        ));
        assert!(matches!(
            b.eval(1, 1.5),
            Err(LambdaError::Core(CoreError::ParameterOutOfRange { .. }))
        ));
        assert!(matches!(
            b.row(0.5, &mut [0.0; 4]),
            Err(LambdaError::Core(CoreError::BufferLength { .. }))
        ));
        assert!(b.eval_by_recurrence(-0.1).is_err());
        assert!(LambdaBasis::new(4, -4.5).is_err());
        assert!(LambdaBasis::new_unrestricted(4, -4.5).is_ok());
        assert!(LambdaBasis::new_unrestricted(4, f64::INFINITY).is_err());
        assert!(LambdaBasis::new(1, 0.0).is_err());
        assert!(corner_cut_ratio(1, 0, 0.0).is_nan());
    }
}
