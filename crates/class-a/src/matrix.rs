//! Class A matrices (Farin 2006; the paper's eqs. (3)–(5)): each condition reported separately.

use crate::square::{Matrix, Matrix2, Matrix3};

use crate::ClassAError;

/// Number of interior sub-curve parameters t at which the sub-curve condition is evaluated.
pub const SUBCURVE_SAMPLES: usize = 256;

/// One matrix condition: whether it holds and by how much (margin ≥ 0 iff it holds).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Condition {
    /// The condition holds (margin ≥ 0).
    pub holds: bool,
    /// The signed margin (see each field of [`ClassAReport`]).
    pub margin: f64,
}

impl Condition {
    fn new(margin: f64) -> Self {
        Self {
            holds: margin >= 0.0,
            margin,
        }
    }
}

/// Each Class A condition of a square matrix M, separately, with its margin.
///
/// Farin's condition (3), |(1−t)v + tMv| ≥ |v| for unit v and t ∈ [0, 1], is equivalent to
/// M + Mᵀ − 2I ⪰ 0; it implies that every singular value is ≥ 1 (the paper's "property 2"),
/// which is reported too. Farin's condition (4) is σ_min² ≥ σ_max. The paper drops (4).
/// Neither guarantees monotone curvature (Cao & Wang 2008): use
/// [`crate::curvature_certificate`] on the actual curve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ClassAReport {
    /// Farin (3): margin = λ_min(M + Mᵀ − 2I).
    pub farin3: Condition,
    /// Singular values ≥ 1: margin = σ_min − 1.
    pub singular_values: Condition,
    /// Farin (4): margin = σ_min² − σ_max.
    pub farin4: Condition,
    /// Farin (4) for the sub-curve matrices (1−t)I + tM: margin = min over t of σ_min² − σ_max,
    /// evaluated at t = k/[`SUBCURVE_SAMPLES`], k = 1..=SUBCURVE_SAMPLES, then refined by golden
    /// section around the smallest sample (a numerical minimum, not a proof).
    /// Condition (3) for these matrices is t·(M + Mᵀ − 2I) ⪰ 0, the same as for M.
    pub subcurve_farin4: Condition,
}

impl ClassAReport {
    /// All four conditions hold.
    #[must_use]
    pub fn is_class_a(&self) -> bool {
        self.farin3.holds
            && self.singular_values.holds
            && self.farin4.holds
            && self.subcurve_farin4.holds
    }

    /// The report of a 2×2 matrix.
    ///
    /// # Errors
    /// [`ClassAError::NonFinite`] if an entry is NaN or infinite,
    /// [`ClassAError::InvalidParameter`] if one is outside ±`bez_core::MAX_COORDINATE`.
    pub fn of_2x2(m: &Matrix2) -> Result<Self, ClassAError> {
        Self::of_matrix(m)
    }

    /// The report of a 3×3 matrix.
    ///
    /// # Errors
    /// [`ClassAError::NonFinite`] if an entry is NaN or infinite,
    /// [`ClassAError::InvalidParameter`] if one is outside ±`bez_core::MAX_COORDINATE`.
    pub fn of_3x3(m: &Matrix3) -> Result<Self, ClassAError> {
        Self::of_matrix(m)
    }

    /// The report of a D × D matrix.
    ///
    /// # Errors
    /// [`ClassAError::NonFinite`] if an entry is NaN or infinite,
    /// [`ClassAError::InvalidParameter`] if one is outside ±`bez_core::MAX_COORDINATE`.
    pub fn of_matrix<const D: usize>(m: &Matrix<D>) -> Result<Self, ClassAError> {
        check_finite(m.iter())?;
        let sym_min = |a: &Matrix<D>| {
            (*a + a.transpose() - Matrix::<D>::identity() * 2.0).symmetric_eigenvalues()[0]
        };
        Ok(report(m, sym_min, Matrix::singular_value_range, |t| {
            Matrix::identity() * (1.0 - t) + *m * t
        }))
    }
}

/// Entries finite and within ±`bez_core::MAX_COORDINATE`, so that σ² and the margins stay
/// finite.
fn check_finite<'a>(mut it: impl Iterator<Item = &'a f64>) -> Result<(), ClassAError> {
    match it.find(|x| !x.is_finite() || x.abs() > bez_core::MAX_COORDINATE) {
        None => Ok(()),
        Some(x) if !x.is_finite() => Err(ClassAError::NonFinite { name: "matrix" }),
        Some(&value) => Err(ClassAError::InvalidParameter {
            name: "matrix entry",
            value,
            expected: "within ±1e152 (bez_core::MAX_COORDINATE)",
        }),
    }
}

fn report<M>(
    m: &M,
    sym_min: impl Fn(&M) -> f64,
    sv: impl Fn(&M) -> (f64, f64),
    sub: impl Fn(f64) -> M,
) -> ClassAReport {
    let (smin, smax) = sv(m);
    let margin_at = |t: f64| {
        let (a, b) = sv(&sub(t));
        a * a - b
    };
    let h = 1.0 / SUBCURVE_SAMPLES as f64;
    let (mut k_best, mut sub_margin) = (1, f64::INFINITY);
    for k in 1..=SUBCURVE_SAMPLES {
        let v = margin_at(k as f64 * h);
        if v < sub_margin {
            (k_best, sub_margin) = (k, v);
        }
    }
    // Golden-section refinement between the neighbours of the best sample.
    let (mut lo, mut hi) = (
        (k_best as f64 - 1.0) * h,
        ((k_best as f64 + 1.0) * h).min(1.0),
    );
    let g = 0.5 * (5.0_f64.sqrt() - 1.0);
    for _ in 0..60 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if margin_at(x1) < margin_at(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    let t = 0.5 * (lo + hi);
    if t > 0.0 {
        sub_margin = sub_margin.min(margin_at(t));
    }
    ClassAReport {
        farin3: Condition::new(sym_min(m)),
        singular_values: Condition::new(smin - 1.0),
        farin4: Condition::new(smin * smin - smax),
        subcurve_farin4: Condition::new(sub_margin),
    }
}

/// The typical planar matrix M = s·R(θ) of eq. (5): [[s cos θ, −s sin θ], [s sin θ, s cos θ]].
#[must_use]
pub fn typical_matrix2(s: f64, theta: f64) -> Matrix2 {
    let (sn, c) = theta.sin_cos();
    Matrix2::new(s * c, -s * sn, s * sn, s * c)
}

/// Exact condition (4) for M = s·R(θ), with "≥" allowed (NOTES): the curve's curvature is
/// monotone for every degree iff s cos θ ≥ 1 or s ≤ cos θ.
///
/// Returns the signed margin max(s cos θ − 1, cos θ − s): ≥ 0 iff the condition holds.
/// With s cos θ ≥ 1 the curvature decreases from b₀; with s ≤ cos θ it increases
/// (M⁻¹ = s⁻¹R(−θ) is then Class A: the reversed curve is).
/// Proof: κ(t) ∝ |w(t)|^{−(n+1)}, w = 1 + t(s e^{iθ} − 1), and d|w|²/dt has the sign of
/// s cos θ − 1 at t = 0 and of s − cos θ at t = 1, linear in between.
#[must_use]
pub fn typical_planar_margin(s: f64, theta: f64) -> f64 {
    let c = theta.cos();
    (s * c - 1.0).max(c - s)
}
