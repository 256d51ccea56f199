//! Beyond the paper: [`Method::Optimal`](crate::Method::Optimal) on a quadratic, whose chords'
//! distance to the arc is known in closed form, so that the longest chord from each point is
//! found directly (the greedy march, which places the fewest segments).
//!
//! A quadratic B(t) = P₀ + t a + t² b (a = 2(P₁ − P₀), b = P₂ − 2P₁ + P₀) has B′(t) = a + 2bt
//! and B″ = 2b. Over [t₀, t₁] (h = t₁ − t₀, t_m = t₀ + h/2) its chord is
//! B(t₁) − B(t₀) = h (a + b(t₀ + t₁)) = h B′(t_m): parallel to the tangent at the middle
//! parameter. With u = B′(t_m) / |B′(t_m)|, the offset f(t) = u × (B(t) − B(t₀)) vanishes at
//! both ends and has the constant f″ = u × 2b, so
//!
//! max |f| = h² |u × 2b| / 8 = h² |a × b| / (4 |B′(t_m)|)
//!
//! (B′(t_m) × b = a × b). When the projection u · B′(t) (linear in t) is ≥ 0 at both ends, the
//! arc projects monotonically onto the chord and this offset is their Hausdorff distance. So
//! the chord is within `accept` exactly when h⁴ ≤ K |B′(t₀) + b h|² with K = 16 accept² /
//! |a × b|², and the longest such chord is the fixed point h = (K |B′(t₀) + b h|²)^¼, reached
//! by iteration from the previous chord's length (the map's slope, h |b| / (2 |B′(t_m)|), is
//! below 0.71 while the tolerance is below the parabola's radius at its vertex).
//!
//! The segments are the chords of N* itself: the longest chord's density 1/h =
//! √(|a × b| / (4 accept |B′|)) is N*'s density √(|κ| / (8 tol)) |B′| for κ = 2|a × b| / |B′|³.

use bez_core::Vector2;

/// The largest tolerance, as a fraction f of the radius R = |a × b|² / (2 |b|³) at the
/// parabola's vertex, for which the closed-form march is taken. The iteration's slope
/// h |b| / (2 |B′(t_m)|) is largest at the vertex, √(f / 2) ≤ 0.71 there, so it converges from
/// the previous chord; a chord whose projection would fold back (possible near the vertex when
/// the tolerance is close to R) fails `holds` and takes the general march. Sharper parabolas
/// (spikes, collinear control points) take the general march throughout: on the random
/// quadratics of the standing table, f = 1/16 sent more of them there for the same count
/// (2,842 against 2,841 segments) and 28 % more instructions.
const VERTEX_FRACTION: f64 = 1.0;

/// The closed-form chords of a quadratic (t ↦ P₀ + t a + t² b) at one tolerance.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ParabolaChords {
    b: Vector2,
    /// K = 16 accept² / |a × b|².
    k: f64,
}

impl ParabolaChords {
    /// The chords of the quadratic with power coefficients `a`, `b` within `accept`; `None`
    /// (left to the general march) when `accept` is above [`VERTEX_FRACTION`] of the radius of
    /// curvature at the parabola's vertex, |a × b|² / (2 |b|³) (this includes collinear control
    /// points, a × b = 0: a segment or a fold), or K is not finite.
    pub(crate) fn new(a: Vector2, b: Vector2, accept: f64) -> Option<Self> {
        let cross2 = a.perp(&b) * a.perp(&b);
        let b2 = b.dot(&b);
        // Also false for NaN.
        let gentle = 2.0 * accept * b2 * b2.sqrt() <= VERTEX_FRACTION * cross2;
        if !gentle {
            return None;
        }
        let k = 16.0 * accept * accept / cross2;
        (k.is_finite() && k > 0.0).then_some(Self { b, k })
    }

    /// The longest chord's length from a point with tangent `d1` = B′(t₀), one step of the
    /// fixed-point iteration from the length `h`: (K |B′(t₀) + b h|²)^¼ (not finite where the
    /// tangent vanishes under rounding).
    #[inline(always)]
    pub(crate) fn longest(&self, d1: Vector2, h: f64) -> f64 {
        let middle = d1 + self.b * h;
        (self.k * middle.dot(&middle)).sqrt().sqrt()
    }

    /// Whether the chord of length `h` from the point with tangent `d1` is within the
    /// tolerance: the projection monotone (B′(t_m) · B′(t₀) ≥ 0 and B′(t_m) · B′(t₁) ≥ 0) and
    /// h⁴ ≤ K |B′(t_m)|². False for NaN.
    #[inline(always)]
    pub(crate) fn holds(&self, d1: Vector2, h: f64) -> bool {
        let step = self.b * h;
        let middle = d1 + step;
        let end = middle + step;
        let h2 = h * h;
        middle.dot(&d1) >= 0.0 && middle.dot(&end) >= 0.0 && h2 * h2 <= self.k * middle.dot(&middle)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]

    use bez_core::BezierCurve;
    use bez_core::proptest_support::curve;
    use proptest::prelude::*;

    use super::*;
    use crate::chord::chord_deviation;

    fn coefficients(c: &BezierCurve<2>) -> (Vector2, Vector2) {
        let p = c.points();
        ((p[1] - p[0]) * 2.0, p[2] - p[1] * 2.0 + p[0])
    }

    proptest! {
        /// The closed form against the exact deviation of `chord_deviation` (root isolation on
        /// the curve itself): a chord that holds is within the tolerance, and the longest
        /// chord (the iteration run to its fixed point) has a deviation of the tolerance.
        #[test]
        fn the_longest_chord_meets_the_tolerance(
            c in curve::<2>(2..=2, 10.0),
            t0 in 0.0f64..0.9,
            rel in 1e-4f64..1e-2,
        ) {
            let (a, b) = coefficients(&c);
            let size = c.points().iter().map(Vector2::amax).fold(1.0, f64::max);
            let tol = rel * size;
            let Some(chords) = ParabolaChords::new(a, b, tol) else {
                return Ok(());
            };
            let d1 = a + b * (2.0 * t0);
            let mut h = chords.longest(d1, 0.0);
            for _ in 0..200 {
                h = chords.longest(d1, h);
            }
            prop_assume!(h.is_finite() && t0 + h <= 1.0);
            prop_assume!((chords.longest(d1, h) - h).abs() <= 1e-12 * h);
            prop_assume!(chords.holds(d1, h * (1.0 - 1e-9)));
            let exact = chord_deviation(&c, t0, t0 + h).unwrap();
            prop_assert!((exact - tol).abs() <= 1e-6 * tol, "{exact} vs {tol}");
            let shorter = chord_deviation(&c, t0, t0 + 0.9 * h).unwrap();
            prop_assert!(shorter <= tol, "{shorter} > {tol}");
        }
    }

    /// A chord across the vertex of a sharp parabola whose projection folds back is refused
    /// even where h⁴ ≤ K |B′(t_m)|² holds.
    #[test]
    fn a_folding_chord_does_not_hold() {
        // B(t) = (t − ½, 100 (t − ½)²): a = (1, −100), b = (0, 100), vertex at t = ½.
        let (a, b) = (Vector2::new(1.0, -100.0), Vector2::new(0.0, 100.0));
        // Its vertex radius is 1e4 / 2e6 = 0.005: `new` leaves a tolerance of 1e3 to the
        // general march; the closed form built directly refuses the folding chord.
        assert!(ParabolaChords::new(a, b, 1e3).is_none());
        assert!(ParabolaChords::new(a, b, 0.005 * VERTEX_FRACTION * 0.99).is_some());
        let cross: f64 = a.perp(&b);
        let chords = ParabolaChords {
            b,
            k: 16.0 * 1e6 / (cross * cross),
        };
        // From t₀ = 0.1 to 0.6: t_m = 0.35, B′(t_m) = (1, −30) and B′(t₀) = (1, −80) agree,
        // B′(t₁) = (1, 20) points back.
        let d1 = a + b * 0.2;
        let h = 0.5;
        let middle = d1 + b * h;
        assert!(h.powi(4) <= chords.k * middle.dot(&middle));
        assert!(!chords.holds(d1, h));
        // A short chord on one side holds.
        assert!(chords.holds(d1, 0.01));
    }

    #[test]
    fn collinear_control_points_are_left_to_the_general_march() {
        let (a, b) = (Vector2::new(2.0, 2.0), Vector2::new(-1.0, -1.0));
        assert!(ParabolaChords::new(a, b, 1e-3).is_none());
    }
}
