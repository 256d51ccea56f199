//! Proven certificates of monotone curvature and torsion, in exact integer arithmetic.
//!
//! Every f64 control point is a dyadic rational, so after scaling all coordinates by one power
//! of two they are integers. The hodographs, the numerators of d(κ²)/dt and dτ/dt, and their
//! Bernstein coefficients are then exact integers ([`ScaledBernstein`]); their signs are decided
//! by exact subdivision (module `sign`). Nothing is rounded before the verdict.

use bez_core::BezierCurve;

use crate::ClassAError;
use crate::dd::Dd;
use crate::exact::{ScaledBernstein, to_common_integers};
use crate::filter::Filtered;
use crate::sign::{Positivity, SignProfile, locate_sign_change, positivity, sign_profile};

/// Why a certificate could not decide within the subdivision caps
/// ([`crate::MAX_SUBDIVISION_DEPTH`], [`crate::MAX_PIECES`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum UndecidedCause {
    /// Regularity (x' ≠ 0 for curvature, x' × x'' ≠ 0 for torsion) was neither proven nor refuted
    /// (e.g. a zero at a non-dyadic parameter).
    Regularity,
    /// The sign of the derivative's numerator: a root too close to a double root or to an end.
    Sign,
}

/// The verdict of a monotonicity certificate.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Monotonicity {
    /// Non-decreasing on [0, 1] (proven).
    Increasing,
    /// Non-increasing on [0, 1] (proven).
    Decreasing,
    /// Constant (the numerator is identically zero, proven).
    Constant,
    /// The derivative is > 0 at one end of `bracket` and < 0 at the other (exact values at
    /// dyadic points): an interior extremum lies strictly inside (proven).
    NotMonotone {
        /// Midpoint of the bracket.
        extremum: f64,
        /// The bracket (its dyadic end points rounded to f64), usually of width ≤ 2⁻⁴⁰.
        bracket: (f64, f64),
    },
    /// Not decided within the subdivision caps: no claim is made.
    Undecided {
        /// What was not decided.
        cause: UndecidedCause,
        /// The first unresolved parameter interval.
        interval: (f64, f64),
    },
}

/// Which arithmetic proved a certificate's verdict (both are proofs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum Proof {
    /// The floating-point filter: f64 coefficients whose signs exceed a rigorous rounding-error
    /// bound (the common case, no big integers formed).
    Filter,
    /// The filter's second stage: the same bound in double-double arithmetic (about 106
    /// significant bits), for numerators that cancel below f64 resolution.
    DoubleDouble,
    /// Exact integer arithmetic (the filter could not decide).
    Exact,
}

/// A monotonicity certificate.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Certificate {
    /// The verdict.
    pub verdict: Monotonicity,
    /// The numerator's Bernstein coefficients all have one sign (convex-hull property), so no
    /// subdivision was needed.
    pub by_coefficient_signs: bool,
    /// Which arithmetic decided.
    pub proof: Proof,
}

impl Certificate {
    /// The quantity is proven monotone (increasing, decreasing or constant).
    #[must_use]
    pub fn is_monotone(&self) -> bool {
        matches!(
            self.verdict,
            Monotonicity::Increasing | Monotonicity::Decreasing | Monotonicity::Constant
        )
    }
}

/// Exact hodographs of order 1..=k, in integers (coordinates scaled by a common power of two,
/// which multiplies every numerator by a positive constant).
fn hodographs<const D: usize>(
    curve: &BezierCurve<D>,
    k: usize,
) -> Result<Vec<Vec<ScaledBernstein>>, ClassAError> {
    let pts = curve.points();
    let flat: Vec<f64> = (0..D).flat_map(|d| pts.iter().map(move |p| p[d])).collect();
    let ints = to_common_integers(&flat).ok_or(ClassAError::NonFinite {
        name: "control point",
    })?;
    let mut cur: Vec<ScaledBernstein> = ints
        .chunks(pts.len())
        .map(|c| ScaledBernstein::from_bernstein(c.to_vec()))
        .collect();
    let mut out = Vec::with_capacity(k);
    for _ in 0..k {
        cur = cur.iter().map(ScaledBernstein::derivative).collect();
        out.push(cur.clone());
    }
    Ok(out)
}

/// Σ_d a_d b_d.
fn dot(a: &[ScaledBernstein], b: &[ScaledBernstein]) -> ScaledBernstein {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.mul(y))
        .reduce(|acc, p| acc.add_scaled(&p, 1))
        .unwrap_or_else(|| ScaledBernstein::new(Vec::new()))
}

/// G = |x'|²|x''|² − (x'·x'')² = Σ_{i<j} (x'ᵢx''ⱼ − x'ⱼx''ᵢ)² (Lagrange's identity; |x' × x''|²
/// in 3-D, (x' × x'')² in 2-D).
fn gram(d1: &[ScaledBernstein], d2: &[ScaledBernstein]) -> ScaledBernstein {
    let mut terms = Vec::new();
    for i in 0..d1.len() {
        for j in i + 1..d1.len() {
            terms.push(d1[i].mul(&d2[j]).add_scaled(&d1[j].mul(&d2[i]), -1));
        }
    }
    dot(&terms, &terms)
}

/// The exact numerator of d(κ²)/dt, N = G'P − 3GP' with P = |x'|², G = |x' × x''|²
/// (κ² = G/P³, d(κ²)/dt = N/P⁴), degree 6n − 9, times a positive constant; and P.
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 2; [`ClassAError::NonFinite`] for a non-finite point.
pub fn curvature_numerator<const D: usize>(
    curve: &BezierCurve<D>,
) -> Result<(ScaledBernstein, ScaledBernstein), ClassAError> {
    let n = curve.degree();
    crate::error::check_degree(n, 2)?;
    let d = hodographs(curve, 2)?;
    let p = dot(&d[0], &d[0]);
    let g = gram(&d[0], &d[1]);
    let num = g
        .derivative()
        .mul(&p)
        .add_scaled(&g.mul(&p.derivative()), -3);
    Ok((num, p))
}

/// The exact numerator of dτ/dt, N = Δ'G − ΔG' with Δ = det(x', x'', x''') and G = |x' × x''|²
/// (τ = Δ/G, dτ/dt = N/G²), degree 7n − 13, times a positive constant; and G.
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 3; [`ClassAError::NonFinite`] for a non-finite point.
pub fn torsion_numerator(
    curve: &BezierCurve<3>,
) -> Result<(ScaledBernstein, ScaledBernstein), ClassAError> {
    let n = curve.degree();
    crate::error::check_degree(n, 3)?;
    let d = hodographs(curve, 3)?;
    let (d1, d2, d3) = (&d[0], &d[1], &d[2]);
    let cross: Vec<ScaledBernstein> = (0..3)
        .map(|k| {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            d1[i].mul(&d2[j]).add_scaled(&d1[j].mul(&d2[i]), -1)
        })
        .collect();
    let g = dot(&cross, &cross);
    let delta = dot(&cross, d3);
    let num = delta
        .derivative()
        .mul(&g)
        .add_scaled(&delta.mul(&g.derivative()), -1);
    Ok((num, g))
}

/// Checks the regularity polynomial, then decides the sign of the numerator.
fn decide(
    num: &ScaledBernstein,
    regular: &ScaledBernstein,
    quantity: &'static str,
) -> Result<Certificate, ClassAError> {
    match positivity(regular) {
        Positivity::Positive => {}
        Positivity::FailsAt(t) => {
            return Err(ClassAError::Singular {
                quantity,
                parameter: t.to_f64(),
            });
        }
        Positivity::Undecided { lo, hi } => {
            return Ok(Certificate {
                verdict: Monotonicity::Undecided {
                    cause: UndecidedCause::Regularity,
                    interval: (lo, hi),
                },
                by_coefficient_signs: false,
                proof: Proof::Exact,
            });
        }
    }
    let c = num.coefficients();
    let by_coefficient_signs = c.iter().all(|x| x.sign() != num_bigint::Sign::Minus)
        || c.iter().all(|x| x.sign() != num_bigint::Sign::Plus);
    let verdict = match sign_profile(num) {
        SignProfile::Zero => Monotonicity::Constant,
        SignProfile::NonNegative => Monotonicity::Increasing,
        SignProfile::NonPositive => Monotonicity::Decreasing,
        SignProfile::Changes { positive, negative } => {
            let (lo, hi) = locate_sign_change(num, &positive, &negative);
            Monotonicity::NotMonotone {
                extremum: 0.5 * (lo + hi),
                bracket: (lo, hi),
            }
        }
        SignProfile::Undecided { lo, hi } => double_roots(num).unwrap_or(Monotonicity::Undecided {
            cause: UndecidedCause::Sign,
            interval: (lo, hi),
        }),
    };
    Ok(Certificate {
        verdict,
        by_coefficient_signs,
        proof: Proof::Exact,
    })
}

/// The verdict for a numerator whose subdivision did not settle (a double root, or a root
/// within 2⁻⁹⁶ of a piece boundary), from the odd part O of its square-free decomposition
/// (module `squarefree`): O of one sign gives N's sign (read at a dyadic point where N ≠ 0);
/// a proven sign change of O, bracketed and confirmed by exact values of N of opposite signs
/// at the bracket's dyadic ends, is an interior extremum. `None` when neither is proven.
fn double_roots(num: &ScaledBernstein) -> Option<Monotonicity> {
    let odd = crate::squarefree::odd_part(num)?;
    match sign_profile(&odd) {
        SignProfile::NonNegative | SignProfile::NonPositive => match nonzero_sign(num)? {
            1 => Some(Monotonicity::Increasing),
            _ => Some(Monotonicity::Decreasing),
        },
        SignProfile::Changes { positive, negative } => {
            let (lo, hi) = locate_sign_change(&odd, &positive, &negative);
            // The bracket's ends are dyadic of level ≤ 48, exact in f64.
            let level = 48;
            let at = |x: f64| {
                let m = x * 2f64.powi(level);
                (m.fract() == 0.0 && (0.0..=2f64.powi(level)).contains(&m))
                    .then(|| num.sign_at(&num_bigint::BigInt::from(m as u64), level as u32))
            };
            (at(lo)? * at(hi)? == -1).then_some(Monotonicity::NotMonotone {
                extremum: 0.5 * (lo + hi),
                bracket: (lo, hi),
            })
        }
        SignProfile::Zero | SignProfile::Undecided { .. } => None,
    }
}

/// The sign of N at some dyadic point where N ≠ 0 (N has at most deg N zeros, so one of
/// 2ᵏ + 1 > deg N + 1 points of level k is not a zero); `None` for N ≡ 0.
fn nonzero_sign(num: &ScaledBernstein) -> Option<i8> {
    let k = usize::BITS - (num.degree() + 1).leading_zeros() + 1;
    (0..=(1u64 << k))
        .map(|m| num.sign_at(&num_bigint::BigInt::from(m), k))
        .find(|&s| s != 0)
}

/// A filter stage's verdict as a certificate, if it decided.
fn filtered(f: Filtered, proof: Proof) -> Option<Certificate> {
    let verdict = match f {
        Filtered::Increasing => Monotonicity::Increasing,
        Filtered::Decreasing => Monotonicity::Decreasing,
        Filtered::Constant => Monotonicity::Constant,
        Filtered::Declined => return None,
    };
    Some(Certificate {
        verdict,
        by_coefficient_signs: true,
        proof,
    })
}

/// [`curvature_certificate`] by exact arithmetic only (the filter skipped).
pub(crate) fn curvature_certificate_exact<const D: usize>(
    curve: &BezierCurve<D>,
) -> Result<Certificate, ClassAError> {
    let (num, p) = curvature_numerator(curve)?;
    decide(&num, &p, "x' (speed)")
}

/// [`torsion_certificate`] by exact arithmetic only (the filter skipped).
pub(crate) fn torsion_certificate_exact(
    curve: &BezierCurve<3>,
) -> Result<Certificate, ClassAError> {
    let (num, g) = torsion_numerator(curve)?;
    decide(&num, &g, "x' × x'' (curvature)")
}

/// Proven certificate of monotone curvature of a planar or spatial curve of any degree.
///
/// First a floating-point filter (module docs of `filter`: the same numerator in f64 with a
/// rigorous bound on every coefficient's rounding error) decides the common case, where the
/// regularity polynomial and the numerator have coefficients of proven sign
/// ([`Proof::Filter`]); then the same filter in double-double arithmetic, for numerators that
/// cancel below f64 resolution ([`Proof::DoubleDouble`]); otherwise the exact path below
/// decides ([`Proof::Exact`]). All give the same verdict (tested).
///
/// κ² = G/P³ with P = |x'|² and G = |x' × x''|², so d(κ²)/dt = N/P⁴ with N = G'P − 3GP'
/// ([`curvature_numerator`]), formed exactly in integers. Regularity P > 0 on [0, 1] is proven
/// first; then all Bernstein coefficients of N of one sign prove monotonicity (convex hull), and
/// otherwise exact subdivision at 1/2 either proves one sign piece by piece or finds exact values
/// of opposite signs (an interior extremum, bracketed by exact bisection).
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 2, [`ClassAError::NonFinite`], and
/// [`ClassAError::Singular`] when x' = 0 at an exact dyadic parameter.
pub fn curvature_certificate<const D: usize>(
    curve: &BezierCurve<D>,
) -> Result<Certificate, ClassAError> {
    crate::error::check_degree(curve.degree(), 2)?;
    if let Some(c) =
        filtered(crate::filter::curvature::<f64, D>(curve), Proof::Filter).or_else(|| {
            filtered(
                crate::filter::curvature::<Dd, D>(curve),
                Proof::DoubleDouble,
            )
        })
    {
        return Ok(c);
    }
    curvature_certificate_exact(curve)
}

/// Proven certificate of monotone torsion of a spatial curve of any degree.
///
/// τ = Δ/G with Δ = det(x', x'', x''') and G = |x' × x''|², so dτ/dt = (Δ'G − ΔG')/G²
/// ([`torsion_numerator`]); G > 0 on [0, 1] (torsion defined) is proven first, then the
/// numerator is decided as in [`curvature_certificate`].
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 3, [`ClassAError::NonFinite`], and
/// [`ClassAError::Singular`] when x' × x'' = 0 at an exact dyadic parameter.
pub fn torsion_certificate(curve: &BezierCurve<3>) -> Result<Certificate, ClassAError> {
    crate::error::check_degree(curve.degree(), 3)?;
    if let Some(c) = filtered(crate::filter::torsion::<f64>(curve), Proof::Filter)
        .or_else(|| filtered(crate::filter::torsion::<Dd>(curve), Proof::DoubleDouble))
    {
        return Ok(c);
    }
    torsion_certificate_exact(curve)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use num_bigint::BigInt;

    /// The scaled Bernstein form of Π (aᵢ t + bᵢ) (power basis products).
    fn product(factors: &[(i64, i64)]) -> ScaledBernstein {
        let mut c = vec![BigInt::from(1)];
        for &(a, b) in factors {
            let mut next = vec![BigInt::from(0); c.len() + 1];
            for (j, x) in c.iter().enumerate() {
                next[j] += x * b;
                next[j + 1] += x * a;
            }
            c = next;
        }
        crate::squarefree::from_power(&c)
    }

    #[test]
    fn double_roots_are_resolved_by_the_odd_part() {
        // (3t − 1)²(t + 2) ≥ 0 with a double root at the non-dyadic 1/3: subdivision alone
        // cannot settle it, the odd part (t + 2) can.
        let f = product(&[(3, -1), (3, -1), (1, 2)]);
        assert!(matches!(sign_profile(&f), SignProfile::Undecided { .. }));
        assert_eq!(double_roots(&f), Some(Monotonicity::Increasing));
        let g = product(&[(3, -1), (3, -1), (-1, -2)]);
        assert_eq!(double_roots(&g), Some(Monotonicity::Decreasing));
        // (3t − 1)²(5t − 2)(t + 2): the sign change at 2/5 is found and confirmed on N.
        let h = product(&[(3, -1), (3, -1), (5, -2), (1, 2)]);
        match double_roots(&h) {
            Some(Monotonicity::NotMonotone { bracket, .. }) => {
                assert!(bracket.0 < 0.4 && 0.4 < bracket.1 && bracket.1 - bracket.0 < 1e-11);
            }
            v => panic!("{v:?}"),
        }
        // Through `decide`: the numerator with the double root is proven, not `Undecided`.
        let regular = product(&[]);
        let cert = decide(&f, &regular, "test").unwrap();
        assert_eq!(cert.verdict, Monotonicity::Increasing);
        assert_eq!(cert.proof, Proof::Exact);
    }
}
