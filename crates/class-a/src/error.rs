//! The error type of class-a.

/// Everything that can go wrong when building or analysing Class A curves.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ClassAError {
    /// An error of the Bézier kernel.
    #[error(transparent)]
    Core(#[from] bez_core::CoreError),
    /// An input number (point coordinate, matrix entry, scale, angle) is NaN or infinite.
    #[error("input {name} is not finite")]
    NonFinite {
        /// Which input.
        name: &'static str,
    },
    /// A parameter of a curve is out of its range (e.g. a non-positive scale or length, a
    /// start direction that is not a unit vector).
    #[error("{name} = {value} is out of range: {expected}")]
    InvalidParameter {
        /// Which parameter.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The range it must be in.
        expected: &'static str,
    },
    /// The degree is too low for the construction.
    #[error("degree {degree} is too low: at least {needed} is needed")]
    DegreeTooLow {
        /// The degree given.
        degree: usize,
        /// The smallest degree accepted.
        needed: usize,
    },
    /// The degree is above [`MAX_DEGREE`](crate::MAX_DEGREE).
    #[error("degree {degree} is above the limit {max}")]
    DegreeTooHigh {
        /// The degree given.
        degree: usize,
        /// The largest degree accepted.
        max: usize,
    },
    /// The curve is singular at an exact parameter: x' = 0 (curvature undefined) or
    /// x' × x'' = 0 (torsion undefined).
    #[error("{quantity} vanishes at t = {parameter}: the quantity is undefined there")]
    Singular {
        /// What vanishes.
        quantity: &'static str,
        /// The parameter (an exact dyadic, rounded to f64).
        parameter: f64,
    },
    /// Two interactive control points coincide, so a tangent direction is undefined.
    #[error("interactive points {first} and {second} coincide")]
    CoincidentPoints {
        /// Index of the first point.
        first: usize,
        /// Index of the second point.
        second: usize,
    },
    /// The end tangents do not turn (collinear points) or turn by π: no unique curve.
    #[error("the end tangents turn by {turn} rad: a typical curve needs 0 < |turn| < π")]
    DegenerateTurn {
        /// The signed turn ψ of the tangent, in radians.
        turn: f64,
    },
    /// The chord α₂ − α₀ does not lie strictly between the two end tangents (impossible for a
    /// non-degenerate triangle, where δ = ψ − angle at α₂; guards rounding at near-collinear input).
    #[error(
        "the chord direction {chord_angle} rad is not strictly between 0 and the tangent turn {turn} rad"
    )]
    ChordOutsideTangents {
        /// Angle δ of the chord measured from the start tangent.
        chord_angle: f64,
        /// The signed turn ψ of the tangent.
        turn: f64,
    },
    /// The solved typical matrix s·R(θ) violates condition (4): cos θ < s < 1/cos θ.
    #[error(
        "no Class A curve: the solved scale s = {s} lies in the forbidden band ({lower}, {upper}) for θ = {theta} (an isosceles triangle gives s = 1)"
    )]
    NotClassA {
        /// The solved scale.
        s: f64,
        /// The rotation angle per leg.
        theta: f64,
        /// cos θ.
        lower: f64,
        /// 1 / cos θ.
        upper: f64,
    },
    /// The two end tangents of a spatial curve are parallel or opposite: the rotation axis of
    /// eq. (14) is undefined.
    #[error("the spatial end tangents are parallel or opposite (cos angle = {cos_angle})")]
    ParallelTangents {
        /// Cosine of the angle between the tangents.
        cos_angle: f64,
    },
    /// The solver found no parameters meeting the end conditions.
    #[error("{method} did not converge: residual {residual}")]
    NoConvergence {
        /// The solver.
        method: &'static str,
        /// The best residual reached.
        residual: f64,
    },
    /// No typical spatial curve reaches the chord direction α₃ − α₀ (searched over the whole
    /// (φ, s) grid and refined by Newton).
    #[error(
        "no typical spatial curve of this degree reaches the chord direction: smallest direction error {residual}"
    )]
    ChordUnreachable {
        /// The smallest |unit(Σ) − unit(chord)| found.
        residual: f64,
    },
    /// The spatial solve converged, but no solution found is Class A: Farin's condition (3)
    /// fails for M and for M⁻¹ in every one.
    #[error(
        "no Class A spatial curve found: {converged} converged solution(s) of the end conditions, the best has Class A margin {best_margin} < 0 (s = {s}, θ = {theta})"
    )]
    NoClassASolution {
        /// Distinct converged solutions.
        converged: usize,
        /// The largest Class A margin among them (negative).
        best_margin: f64,
        /// The scale s of the best candidate.
        s: f64,
        /// The rotation angle θ of the best candidate.
        theta: f64,
    },
    /// [`crate::SpatialRequirement::MonotoneTorsion`]: none of the Class A spatial solutions
    /// found has proven monotone torsion.
    #[error(
        "no spatial curve with proven monotone torsion among {class_a} Class A solution(s) found"
    )]
    NoMonotoneTorsion {
        /// The Class A solutions found.
        class_a: usize,
    },
    /// The rounded control points do not meet an end condition to the tolerance (e.g. the last
    /// leg L·sⁿ⁻¹ is below the rounding of the end point, so its direction is not representable).
    #[error(
        "the control points meet the {condition} condition only to {achieved:e} (tolerance {tolerance:e})"
    )]
    ToleranceNotMet {
        /// The worst condition ("end tangent", "end point", ...).
        condition: &'static str,
        /// Its achieved error (relative for points, radians for tangents).
        achieved: f64,
        /// The tolerance asked for.
        tolerance: f64,
    },
    /// An optimizer from argmin failed.
    #[error("optimizer failed: {message}")]
    Optimizer {
        /// The optimizer's message.
        message: String,
    },
    /// The spiral similarity is the identity (s e^{iθ} = 1): no pole.
    #[error("no log-spiral pole: s = {s}, θ = {theta} give the identity similarity")]
    NoPole {
        /// The scale.
        s: f64,
        /// The angle.
        theta: f64,
    },
    /// Too few usable samples for a logarithmic graph (κ or dκ/ds vanish or are not finite).
    #[error("only {count} usable samples for the logarithmic graph, need at least 2")]
    TooFewSamples {
        /// The usable samples.
        count: usize,
    },
    /// A prescribed end curvature is outside the range that a curve of monotone curvature with
    /// the given end points and tangents can have (`reason` says which bound; see
    /// [`crate::hermite_planar`]).
    #[error(
        "the {end} curvature {curvature} cannot be met: reachable range [{lower}, {upper}] ({reason})"
    )]
    CurvatureUnreachable {
        /// Which end ("start" or "end").
        end: &'static str,
        /// The curvature asked for (signed).
        curvature: f64,
        /// The smallest reachable value (signed like the turn).
        lower: f64,
        /// The largest reachable value (signed like the turn).
        upper: f64,
        /// Why the values outside are unreachable.
        reason: &'static str,
    },
    /// A solved curve meets its end conditions but its curvature is not proven monotone, so it
    /// is not returned as a Class A curve.
    #[error("the solved curve's curvature is not proven monotone: {verdict:?}")]
    CurvatureNotMonotone {
        /// The certificate's verdict.
        verdict: crate::Monotonicity,
    },
    /// A solved spatial curve meets its end conditions but its torsion is not proven monotone,
    /// so it is not returned as a Class A curve.
    #[error("the solved curve's torsion is not proven monotone: {verdict:?}")]
    TorsionNotMonotone {
        /// The certificate's verdict.
        verdict: crate::Monotonicity,
    },
    /// A segment of a curve of several segments could not be built.
    #[error("segment {index}: {source}")]
    Segment {
        /// Index of the segment (from knot `index` to knot `index + 1`).
        index: usize,
        /// Why.
        source: Box<ClassAError>,
    },
}

/// The largest degree of a Class A curve: 1,024 (the paper's examples go to 49). Curve
/// construction is O(n); the exact certificates grow about as n^2.7 and take minutes near the
/// limit, so interactive use should stay well below it.
pub const MAX_DEGREE: usize = 1024;

/// [`ClassAError::DegreeTooLow`] below `needed`, [`ClassAError::DegreeTooHigh`] above
/// [`MAX_DEGREE`]: checked before any work.
pub(crate) fn check_degree(degree: usize, needed: usize) -> Result<(), ClassAError> {
    if degree < needed {
        return Err(ClassAError::DegreeTooLow { degree, needed });
    }
    if degree > MAX_DEGREE {
        return Err(ClassAError::DegreeTooHigh {
            degree,
            max: MAX_DEGREE,
        });
    }
    Ok(())
}

/// A finite point within ±`bez_core::MAX_COORDINATE` ([`ClassAError::NonFinite`] or
/// [`ClassAError::InvalidParameter`] naming it otherwise).
pub(crate) fn check_point<const D: usize>(
    p: &bez_core::Vector<D>,
    name: &'static str,
) -> Result<(), ClassAError> {
    for &value in p.iter() {
        if !value.is_finite() {
            return Err(ClassAError::NonFinite { name });
        }
        if value.abs() > bez_core::MAX_COORDINATE {
            return Err(ClassAError::InvalidParameter {
                name,
                value,
                expected: "within ±1e152 (bez_core::MAX_COORDINATE)",
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use crate::{TypicalPlanar, TypicalSpatial, class_a_curve, planar_feasibility};
    use bez_core::{Vector2, Vector3};

    #[test]
    fn degrees_above_the_limit_are_refused_before_any_work() {
        let (a0, a1, a2) = (
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 0.0),
            Vector2::new(2.0, 1.0),
        );
        for degree in [MAX_DEGREE + 1, 1_000_000_000, usize::MAX] {
            let too_high = ClassAError::DegreeTooHigh {
                degree,
                max: MAX_DEGREE,
            };
            assert_eq!(
                planar_feasibility(&a0, &a1, &a2, degree).unwrap_err(),
                too_high
            );
            assert_eq!(
                TypicalPlanar::from_points(&a0, &a1, &a2, degree).unwrap_err(),
                too_high
            );
            let a = [
                Vector3::new(0.0, 0.0, 0.0),
                Vector3::new(1.0, 0.0, 0.0),
                Vector3::new(2.0, 1.0, 0.5),
                Vector3::new(3.0, 1.0, 1.0),
            ];
            assert_eq!(
                TypicalSpatial::from_points(&a, degree).unwrap_err(),
                too_high
            );
            let m = crate::Matrix2::identity();
            assert_eq!(class_a_curve(&a0, &a1, &m, degree).unwrap_err(), too_high);
        }
        assert!(planar_feasibility(&a0, &a1, &a2, MAX_DEGREE).is_ok());
    }
}
