//! Beyond the paper: a-priori bounds on the subdivision depth and on the segment count (after
//! Wang Guo-Zhao, 1984).

use bez_core::{BezierCurve, Vector2};

use crate::error::SubdivError;
#[cfg(feature = "paper")]
use crate::flatten::curve_size;

/// The largest second difference M = maxᵢ |Pᵢ − 2Pᵢ₊₁ + Pᵢ₊₂| (0 below degree 2).
#[cfg(feature = "paper")]
#[must_use]
pub fn max_second_difference(curve: &BezierCurve<2>) -> f64 {
    second_difference_max(curve.points())
}

/// maxᵢ |Pᵢ − 2Pᵢ₊₁ + Pᵢ₊₂| of a control polygon (0 below three points): one square root of
/// the largest square (the same number as the largest norm: the square root is monotone and
/// correctly rounded).
#[inline]
fn second_difference_max(points: &[Vector2]) -> f64 {
    points
        .windows(3)
        .map(|w| (w[0] - w[1] * 2.0 + w[2]).norm_squared())
        .fold(0.0, f64::max)
        .sqrt()
}

/// A depth r that uniform halving never needs to exceed for eq. (3) with tolerance ε:
/// r = ⌈log₄(n² M / (8 ε s))⌉ (0 if that is ≤ 0), s the size of eq. (3).
///
/// Why: a control polygon whose second differences are bounded by M deviates from the line
/// through its end points by at most M i(n − i)/2 ≤ M n²/8 at control point i, and each de
/// Casteljau halving divides the bound on the second differences by 4. This is Wang's formula
/// adapted to eq. (3)'s relative tolerance. The fixed rule's depth never exceeds it (tested).
#[cfg(feature = "paper")]
#[must_use]
pub fn wang_depth(curve: &BezierCurve<2>, tolerance: f64) -> usize {
    let n = curve.degree() as f64;
    let m = max_second_difference(curve);
    let s = curve_size(curve);
    if m == 0.0 || s == 0.0 || tolerance.is_nan() || tolerance <= 0.0 {
        return 0;
    }
    let ratio = n * n * m / (8.0 * tolerance * s);
    if ratio <= 1.0 {
        0
    } else {
        // log₄ of a finite positive ratio; the cast saturates for absurd inputs.
        ratio.log(4.0).ceil() as usize
    }
}

/// Wang's formula: a number N = max(1, ⌈√(n(n − 1) M / (8 tol))⌉) of equal parameter steps
/// after which the polyline through B(i/N) is within `tolerance` (absolute) of the curve in
/// Hausdorff distance.
///
/// Why: |B''| ≤ n(n − 1) M, and the chord of a parameter interval of length h interpolates B
/// with error ≤ h²/8 · max|B''| (linear interpolation error, in norm). Each curve point is
/// within that of its chord's point at the same parameter, and each chord point too.
///
/// # Errors
/// [`SubdivError::InvalidTolerance`] unless `tolerance` is positive and finite;
/// [`SubdivError::TooManySegments`] when N is not below 2⁵² (a count no one can use, or an
/// overflow of the second differences).
pub fn wang_segment_count(curve: &BezierCurve<2>, tolerance: f64) -> Result<usize, SubdivError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(SubdivError::InvalidTolerance { value: tolerance });
    }
    wang_count(curve.points(), tolerance).ok_or(SubdivError::TooManySegments {
        tolerance,
        limit: WANG_COUNT_LIMIT as usize,
    })
}

/// 2⁵²: every count below it is exact in f64.
const WANG_COUNT_LIMIT: f64 = 4_503_599_627_370_496.0;

/// [`wang_segment_count`] of a control polygon for a positive `tolerance`: `None` when the
/// count is not below 2⁵² or not a number. The ceiling is taken on the integer part (exact
/// below 2⁵²), not by a call of `ceil`: this runs once per call of `Method::Fast`, whose
/// whole work on a short curve is a few dozen points.
#[inline]
pub(crate) fn wang_count(points: &[Vector2], tolerance: f64) -> Option<usize> {
    let steps = wang_steps(points, tolerance);
    if steps.is_nan() || steps >= WANG_COUNT_LIMIT {
        return None;
    }
    // 0 ≤ steps < 2⁵²: the truncation is exact, and so is its conversion back.
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "0 ≤ steps < 2^52"
    )]
    let whole = steps as usize;
    let count = if (whole as f64) < steps {
        whole + 1
    } else {
        whole
    };
    Some(count.max(1))
}

/// √(n(n − 1) M / (8 tol)) for the control polygon `points` of degree n, unrounded: Wang's
/// count before the ceiling (0 below degree 2). `tolerance` must be positive.
#[inline]
pub(crate) fn wang_steps(points: &[Vector2], tolerance: f64) -> f64 {
    let n = points.len().saturating_sub(1) as f64;
    let m = second_difference_max(points);
    (n * (n - 1.0) * m / (8.0 * tolerance)).sqrt()
}

#[cfg(test)]
mod tests {
    use bez_core::Vector2;

    use super::*;
    use crate::chord::chord_deviation;

    #[test]
    fn wang_count_is_tight_on_a_parabola() -> Result<(), SubdivError> {
        // y = 8t(1 − t): M = 8, n(n − 1) M / 8 = 2; one chord deviates by the apex height 2.
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 4.0),
            Vector2::new(2.0, 0.0),
        ])?;
        assert_eq!(wang_segment_count(&c, 2.0), Ok(1));
        assert!((chord_deviation(&c, 0.0, 1.0)? - 2.0).abs() < 1e-12);
        assert_eq!(wang_segment_count(&c, 1.99), Ok(2));
        assert!(matches!(
            wang_segment_count(&c, 0.0),
            Err(SubdivError::InvalidTolerance { .. })
        ));
        assert!(matches!(
            wang_segment_count(&c, f64::NAN),
            Err(SubdivError::InvalidTolerance { .. })
        ));
        assert!(matches!(
            wang_segment_count(&c, 1e-300),
            Err(SubdivError::TooManySegments { .. })
        ));
        Ok(())
    }

    /// The ceiling by truncation against `f64::ceil`, on whole and fractional step counts.
    #[test]
    fn wang_count_is_the_ceiling_of_wang_steps() {
        let q = [
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 4.0),
            Vector2::new(2.0, 0.0),
        ];
        // Wang's steps are √(2 / tol) here: whole for tol = 2 / k².
        for k in 1..200_u32 {
            let k = f64::from(k);
            for tol in [
                2.0 / (k * k),
                2.0 / (k * k) * 0.999,
                2.0 / (k * k) * 1.001,
                1.0 / k,
            ] {
                let expected = wang_steps(&q, tol).ceil().max(1.0);
                assert_eq!(wang_count(&q, tol), Some(expected as usize), "{tol}");
            }
        }
        assert_eq!(wang_count(&q, 1e-300), None);
        assert_eq!(wang_count(&q[..2], 1.0), Some(1));
    }

    #[cfg(feature = "paper")]
    #[test]
    fn uniform_steps_of_wang_count_are_within_tolerance() -> Result<(), SubdivError> {
        for degree in [3, 7, 12, 25] {
            for c in crate::cases::random_curves(degree, 3, 40 + degree as u64) {
                for tol in [1e-2, 1e-3] {
                    let count = wang_segment_count(&c, tol).unwrap();
                    for i in 0..count {
                        let (a, b) = (i as f64 / count as f64, (i + 1) as f64 / count as f64);
                        assert!(chord_deviation(&c, a, b)? <= tol, "degree {degree}");
                    }
                }
            }
        }
        Ok(())
    }
}
