//! What a flattening accepts before it starts: a depth cap and a tolerance above the rounding
//! level of the coordinates, so that no call enumerates pieces at rounding level.

use bez_core::{BezierCurve, Vector2};

use crate::bound::wang_steps;
use crate::error::SubdivError;

/// The largest Wang count (√(n(n − 1) M / (8 tol)), before rounding up) a subdividing
/// flattening accepts: 2²⁰. Halving at ½ divides the second differences by 4 per level, so a
/// piece is flat once its level reaches log₄ of n² M / (8 tol): the pieces number at most about
/// twice Wang's count, each costing O(n²). Above the limit (a tolerance near the rounding floor
/// of a high-degree curve), the work would run to minutes or hours.
pub(crate) const MAX_SUBDIVISION_STEPS: f64 = (1u64 << 20) as f64;

/// The largest `max_depth` a subdividing flattening accepts: 48. A piece at level 48 spans
/// 2⁻⁴⁸ of the parameter range; its control points differ by a few ulps, where the flatness
/// tests decide on rounding noise.
pub const MAX_FLATTEN_DEPTH: usize = 48;

/// The smallest absolute tolerance for a curve, 16 ulps of its largest coordinate
/// (16 · 2⁻⁵² · maxᵢ |Pᵢ|∞): below it no polyline of rounded points can be told apart from the
/// curve.
#[must_use]
pub(crate) fn rounding_floor(curve: &BezierCurve<2>) -> f64 {
    16.0 * f64::EPSILON * curve.points().iter().map(Vector2::amax).fold(0.0, f64::max)
}

/// What [`check_work`] computed on its way, for the caller to reuse.
pub(crate) struct Work {
    /// [`rounding_floor`] of the curve.
    pub(crate) floor: f64,
    /// Wang's count before rounding up ([`wang_steps`]).
    pub(crate) wang_steps: f64,
}

/// [`SubdivError::DepthTooLarge`] above [`MAX_FLATTEN_DEPTH`];
/// [`SubdivError::ToleranceBelowRounding`] for an absolute tolerance below
/// [`rounding_floor`] (a curve collapsed to the origin has floor 0 and passes);
/// [`SubdivError::TooManySegments`] when Wang's count is above [`MAX_SUBDIVISION_STEPS`].
#[inline]
pub(crate) fn check_work(
    curve: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
) -> Result<Work, SubdivError> {
    if max_depth > MAX_FLATTEN_DEPTH {
        return Err(SubdivError::DepthTooLarge {
            value: max_depth,
            max: MAX_FLATTEN_DEPTH,
        });
    }
    let min = rounding_floor(curve);
    if tolerance < min {
        return Err(SubdivError::ToleranceBelowRounding { tolerance, min });
    }
    let steps = wang_steps(curve.points(), tolerance);
    if steps.is_nan() || steps > MAX_SUBDIVISION_STEPS {
        return Err(SubdivError::TooManySegments {
            tolerance,
            limit: MAX_SUBDIVISION_STEPS as usize,
        });
    }
    Ok(Work {
        floor: min,
        wang_steps: steps,
    })
}
