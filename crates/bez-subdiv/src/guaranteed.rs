//! Beyond the paper: flattening with a guaranteed Hausdorff bound.

use bez_core::{BezierCurve, Vector2, de_casteljau_split};

use crate::error::SubdivError;

/// A point of a flattening: a point of the curve and its parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FlatPoint {
    /// Parameter on the curve.
    pub t: f64,
    /// B(t).
    pub point: Vector2<f64>,
}

/// Distance of `p` to the segment [a, b].
#[must_use]
pub fn distance_to_segment(p: &Vector2<f64>, a: &Vector2<f64>, b: &Vector2<f64>) -> f64 {
    let d = b - a;
    let len2 = d.norm_squared();
    if len2 == 0.0 {
        return (p - a).norm();
    }
    let s = ((p - a).dot(&d) / len2).clamp(0.0, 1.0);
    (p - (a + d * s)).norm()
}

/// Points B(tᵢ), 0 = t₀ < … < t_k = 1, whose polyline is within `tolerance` of the curve in
/// Hausdorff distance (an absolute distance, in the curve's units).
///
/// Pieces are halved until every control point lies within `tolerance` of the chord
/// *segment* (not its line, as eq. (3) tests). Then the piece lies in the convex hull of its
/// control points, hence within `tolerance` of the segment; and since the piece joins the
/// segment's end points continuously, its projection covers the segment, so every segment point
/// is within `tolerance` of the piece too. Both directions of the Hausdorff distance are bounded,
/// at cusps and loops as well. The points are exact curve points (de Casteljau end points).
///
/// # Errors
/// [`SubdivError::TooFewPoints`] for a degree-0 curve, [`SubdivError::InvalidTolerance`],
/// [`SubdivError::DepthLimit`] when a piece is not within tolerance after `max_depth` halvings
/// (e.g. a tolerance below the rounding level of the coordinates).
pub fn flatten_guaranteed(
    curve: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
) -> Result<Vec<FlatPoint>, SubdivError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(SubdivError::InvalidTolerance { value: tolerance });
    }
    let n = curve.points().len();
    if n < 2 {
        return Err(SubdivError::TooFewPoints { got: n });
    }
    let mut out = vec![FlatPoint {
        t: 0.0,
        point: curve.start(),
    }];
    let mut stack = vec![(curve.points().to_vec(), 0usize, 0.0_f64, 1.0_f64)];
    while let Some((points, depth, t0, t1)) = stack.pop() {
        let (a, b) = (points[0], points[n - 1]);
        let ok = points[1..n - 1]
            .iter()
            .all(|p| distance_to_segment(p, &a, &b) <= tolerance);
        if ok {
            out.push(FlatPoint { t: t1, point: b });
            continue;
        }
        if depth >= max_depth {
            return Err(SubdivError::DepthLimit { limit: max_depth });
        }
        let mut left = vec![Vector2::zeros(); n];
        let mut right = vec![Vector2::zeros(); n];
        de_casteljau_split(&points, 0.5, &mut left, &mut right)?;
        let tm = 0.5 * (t0 + t1);
        stack.push((right, depth + 1, tm, t1));
        stack.push((left, depth + 1, t0, tm));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segment_distance_clamps_to_end_points() {
        let (a, b) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
        assert_eq!(distance_to_segment(&Vector2::new(0.5, 2.0), &a, &b), 2.0);
        assert_eq!(distance_to_segment(&Vector2::new(4.0, 4.0), &a, &b), 5.0);
        assert_eq!(distance_to_segment(&Vector2::new(3.0, 4.0), &a, &a), 5.0);
    }

    #[test]
    fn errors_are_typed() {
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 5.0),
            Vector2::new(2.0, 0.0),
        ])
        .unwrap();
        assert!(matches!(
            flatten_guaranteed(&c, 0.0, 40),
            Err(SubdivError::InvalidTolerance { .. })
        ));
        assert_eq!(
            flatten_guaranteed(&c, 1e-9, 3),
            Err(SubdivError::DepthLimit { limit: 3 })
        );
        let dot = BezierCurve::new(vec![Vector2::new(0.0, 0.0)]).unwrap();
        assert_eq!(
            flatten_guaranteed(&dot, 1.0, 3),
            Err(SubdivError::TooFewPoints { got: 1 })
        );
    }
}
