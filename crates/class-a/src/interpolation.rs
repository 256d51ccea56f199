//! How well the actual (f64) control points meet the interactive end conditions.
//!
//! The leg formula interpolates the end points and end tangents exactly in real arithmetic, but
//! the control points are rounded: when the last leg L·sⁿ⁻¹ is tiny next to |bₙ| (s ≪ 1 at high
//! degree, a tight turn near the end point), the end tangent bₙ − bₙ₋₁ of the representable
//! curve is off by up to about ε|bₙ| / |Δbₙ₋₁|. This module measures the achieved errors.

use bez_core::Vector;

use crate::ClassAError;

/// The interpolation tolerance of the interactive generation (relative end-point error, and
/// tangent angle in radians).
pub const INTERPOLATION_TOLERANCE: f64 = 1e-9;

/// Allowance for the f64 evaluation of an angle between two differences of f64 points
/// (subtraction, normalization and the chord formula, a few units of roundoff each).
const ANGLE_EVALUATION_ALLOWANCE: f64 = 8.0 * f64::EPSILON;

/// The achieved errors of a curve's control points b₀..bₙ against the interactive points.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Interpolation {
    /// |b₀ − α_first| / |α_last − α_first|.
    pub start_point: f64,
    /// |bₙ − α_last| / |α_last − α_first|.
    pub end_point: f64,
    /// Angle (rad) between b₁ − b₀ and the start tangent, plus the evaluation allowance 8ε.
    pub start_tangent: f64,
    /// Angle (rad) between bₙ − bₙ₋₁ and the end tangent, plus the evaluation allowance 8ε.
    pub end_tangent: f64,
}

/// Angle between two non-zero vectors, 2·asin(|û − v̂|/2), plus the evaluation allowance;
/// π + allowance if either is zero or not finite (no direction).
fn angle_bound<const D: usize>(u: &Vector<D>, v: &Vector<D>) -> f64 {
    let (nu, nv) = (u.norm(), v.norm());
    if !(nu > 0.0 && nv > 0.0 && nu.is_finite() && nv.is_finite()) {
        return std::f64::consts::PI + ANGLE_EVALUATION_ALLOWANCE;
    }
    let chord = (u / nu - v / nv).norm();
    2.0 * (0.5 * chord).min(1.0).asin() + ANGLE_EVALUATION_ALLOWANCE
}

impl Interpolation {
    /// Measures the control points `points` against α_first, the start tangent direction
    /// `start_tangent`, the end tangent direction `end_tangent` and α_last.
    #[must_use]
    pub fn measure<const D: usize>(
        points: &[Vector<D>],
        first: &Vector<D>,
        start_tangent: &Vector<D>,
        end_tangent: &Vector<D>,
        last: &Vector<D>,
    ) -> Self {
        let scale = (last - first).norm();
        let n = points.len().saturating_sub(1);
        match (
            points.first(),
            points.get(1),
            points.get(n.saturating_sub(1)),
            points.last(),
        ) {
            (Some(b0), Some(b1), Some(bp), Some(bn)) if n >= 1 => Self {
                start_point: (b0 - first).norm() / scale,
                end_point: (bn - last).norm() / scale,
                start_tangent: angle_bound(&(b1 - b0), start_tangent),
                end_tangent: angle_bound(&(bn - bp), end_tangent),
            },
            _ => Self {
                start_point: f64::INFINITY,
                end_point: f64::INFINITY,
                start_tangent: f64::INFINITY,
                end_tangent: f64::INFINITY,
            },
        }
    }

    /// The largest of the four errors, with its name.
    #[must_use]
    pub fn worst(&self) -> (&'static str, f64) {
        [
            ("start point", self.start_point),
            ("end point", self.end_point),
            ("start tangent", self.start_tangent),
            ("end tangent", self.end_tangent),
        ]
        .into_iter()
        .fold(("start point", f64::NEG_INFINITY), |a, b| {
            if b.1 > a.1 || b.1.is_nan() { b } else { a }
        })
    }

    /// `self` if every error is within `tolerance`.
    ///
    /// # Errors
    /// [`ClassAError::ToleranceNotMet`] naming the worst condition.
    pub fn within(self, tolerance: f64) -> Result<Self, ClassAError> {
        let (condition, achieved) = self.worst();
        if achieved <= tolerance {
            Ok(self)
        } else {
            Err(ClassAError::ToleranceNotMet {
                condition,
                achieved,
                tolerance,
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use bez_core::Vector2;

    #[test]
    fn measures_known_errors() {
        let pts = [
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 0.0),
            Vector2::new(2.0, 1.0),
            Vector2::new(2.0, 2.0),
        ];
        let m = Interpolation::measure(
            &pts,
            &Vector2::new(0.0, 0.0),
            &Vector2::new(1.0, 0.0),
            &Vector2::new(1.0, 1.0),
            &Vector2::new(2.0, 2.0 + 1e-3),
        );
        assert!(m.start_point == 0.0 && m.start_tangent <= 1e-14);
        assert!((m.end_point - 1e-3 / (4.0f64 + 4.004001).sqrt()).abs() < 1e-9);
        // bₙ − bₙ₋₁ = (0, 1) against (1, 1): π/4.
        assert!((m.end_tangent - std::f64::consts::FRAC_PI_4).abs() < 1e-12);
        assert_eq!(m.worst().0, "end tangent");
        assert!(matches!(
            m.within(1e-9),
            Err(ClassAError::ToleranceNotMet {
                condition: "end tangent",
                ..
            })
        ));
        assert!(m.within(1.0).is_ok());
    }
}
