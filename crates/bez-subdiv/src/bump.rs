//! Beyond the paper: a root-free bound on the bump of a cubic between two of its zeros, shared
//! by the chord tests of [`optimal`](crate::optimal) and [`model_march`](crate::model_march).
//!
//! A cubic offset that vanishes at both ends of a chord is, with y ∈ [−1, 1] running along the
//! chord, ¼ (1 − y²)(m + δy) (up to sign and the chord's scale). Its largest magnitude needs the
//! roots of a quadratic (a square root and two divisions); when δ is small against m, as on
//! short arcs where the curvature barely changes, the bound below is as good and needs
//! neither.

/// Lemma: for |ε| ≤ 1 and y ∈ [−1, 1], 0 ≤ (1 − y²)(1 + εy) ≤ 1 + ε²/4.
///
/// Proof: (1 − y²)(1 + εy) = 1 + φ(y), φ = εy − y² − εy³. Where εy ≤ 0,
/// φ = εy(1 − y²) − y² ≤ 0; where εy > 0, −εy³ = −εy · y² ≤ 0, so φ ≤ εy − y² ≤ ε²/4 (the
/// parabola's top at y = ε/2).
///
/// With ε = δ/m (m ≠ 0, δ² ≤ `skew` · m², `skew` ≤ 1):
/// max over y of ¼ |(1 − y²)(m + δy)| ≤ ¼ |m| (1 + δ²/(4m²)) = (4m² + δ²) / (16 |m|),
/// returned as the fraction (4m² + δ², 16 |m|), denominator > 0. The maximum is at least its
/// value at y = 0, |m| / 4, so the bound is within a relative δ²/(4m²) ≤ `skew` / 4 of it, and
/// |m| / 4 is a lower bound on the maximum. `None` for m = 0, δ² > `skew` · m² or NaN.
#[inline(always)]
pub(crate) fn bump_bound(m: f64, delta: f64, skew: f64) -> Option<(f64, f64)> {
    let (m2, delta2) = (m * m, delta * delta);
    // Also false for NaN.
    if m2 > 0.0 && delta2 <= skew * m2 {
        Some((4.0 * m2 + delta2, 16.0 * m.abs()))
    } else {
        None
    }
}

/// max over σ ∈ [0, 1] of |ψ(σ)|, ψ = σ(1 − σ)(A + Cσ): at the roots of
/// ψ′ = A + 2(C − A)σ − 3Cσ² in [0, 1] (ψ vanishes at both ends). The roots are
/// ((C − A) ± √(A² + AC + C²)) / (3C), taken in the cancellation-free pair q / (3C), −A / q.
#[inline(always)]
pub(crate) fn cubic_offset(a: f64, c: f64) -> f64 {
    let psi = |s: f64| {
        if (0.0..=1.0).contains(&s) {
            (s * (1.0 - s) * (a + c * s)).abs()
        } else {
            0.0
        }
    };
    let d = (a * a + a * c + c * c).max(0.0).sqrt();
    let q = (c - a) + (c - a).signum() * d;
    if q == 0.0 {
        // C − A = 0 and A² + AC + C² = 0: A = C = 0.
        return 0.0;
    }
    psi(q / (3.0 * c)).max(psi(-a / q))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]

    use proptest::prelude::*;

    use super::*;

    /// max over y ∈ [−1, 1] of ¼ |(1 − y²)(m + δy)| by dense sampling.
    fn sampled(m: f64, delta: f64) -> f64 {
        (0..=20_000)
            .map(|j| {
                let y = -1.0 + f64::from(j) / 10_000.0;
                0.25 * ((1.0 - y * y) * (m + delta * y)).abs()
            })
            .fold(0.0, f64::max)
    }

    /// The lemma itself: (1 − y²)(1 + εy) ≤ 1 + ε²/4 on [−1, 1] for |ε| ≤ 1, with equality
    /// approached (to O(ε⁴)) near y = ε/2, by dense sampling.
    #[test]
    fn lemma() {
        for i in 0..=200 {
            let eps = -1.0 + f64::from(i) / 100.0;
            let top = (0..=20_000)
                .map(|j| {
                    let y = -1.0 + f64::from(j) / 10_000.0;
                    (1.0 - y * y) * (1.0 + eps * y)
                })
                .fold(f64::NEG_INFINITY, f64::max);
            assert!(
                top >= 0.0 && top <= 1.0 + eps * eps / 4.0 + 1e-15,
                "{eps}: {top}"
            );
            assert!(
                top >= 1.0 + eps * eps / 4.0 - eps.powi(4) / 4.0 - 1e-9,
                "{eps}: {top}"
            );
        }
    }

    #[test]
    fn refuses_what_it_cannot_bound() {
        assert_eq!(bump_bound(0.0, 0.0, 1.0), None);
        assert_eq!(bump_bound(1.0, 2.0, 1.0), None);
        assert_eq!(bump_bound(1.0, 0.5, 1.0 / 64.0), None);
        assert_eq!(bump_bound(f64::NAN, 0.0, 1.0), None);
        assert_eq!(bump_bound(2.0, f64::NAN, 1.0), None);
        // m = ±2, δ = 0: exactly |m| / 4.
        for m in [2.0, -2.0] {
            let (numerator, denominator) = bump_bound(m, 0.0, 1.0).unwrap();
            assert_eq!(numerator / denominator, 0.5);
        }
    }

    proptest! {
        /// Where it answers, the bound is above the sampled maximum and within a relative
        /// δ²/(4m²) of it, and |m| / 4 is below it.
        #[test]
        fn bounds_the_maximum_tightly(m in -10.0f64..10.0, ratio in -1.0f64..1.0) {
            let delta = m * ratio;
            let (numerator, denominator) = bump_bound(m, delta, 1.0).unwrap();
            prop_assert!(denominator > 0.0);
            let (bound, exact) = (numerator / denominator, sampled(m, delta));
            let slack = 1e-12 * m.abs();
            prop_assert!(bound >= exact - slack, "{} < {}", bound, exact);
            prop_assert!(bound <= exact * (1.0 + ratio * ratio / 4.0) + slack);
            prop_assert!(m.abs() / 4.0 <= exact + slack);
        }
    }

    /// `cubic_offset` against a dense sampling of |σ(1 − σ)(A + Cσ)|.
    #[test]
    fn cubic_offset_is_the_maximum() {
        for (a, c) in [
            (3.0, 0.0),
            (1.0, -2.0),
            (-4.0, 9.0),
            (0.0, 1.0),
            (2.0, -2.0),
            (0.0, 0.0),
        ] {
            let sampled = (0..=100_000)
                .map(|k| {
                    let s = f64::from(k) / 100_000.0;
                    (s * (1.0 - s) * (a + c * s)).abs()
                })
                .fold(0.0, f64::max);
            let exact = cubic_offset(a, c);
            assert!(
                exact >= sampled && exact <= sampled + 1e-9,
                "{a} {c}: {exact} vs {sampled}"
            );
        }
    }
}
