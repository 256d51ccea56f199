//! Beyond the paper: flattening with a guaranteed Hausdorff bound.

use bez_core::{BezierCurve, Vector2};

use crate::error::SubdivError;
use crate::fixed::halve_until;

/// A point of a flattening: a point of the curve and its parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct FlatPoint {
    /// Parameter on the curve.
    pub t: f64,
    /// B(t); for [`Method::Optimal`](crate::Method::Optimal) above degree 3 a point of the
    /// quintic models it flattens, within tol / 32 of B(t) (tol / 4 at tolerances near the rounding
    /// floor; B(0) and B(1) exact).
    pub point: Vector2,
}

/// Distance of `p` to the segment [a, b].
#[must_use]
pub fn distance_to_segment(p: &Vector2, a: &Vector2, b: &Vector2) -> f64 {
    let d = b - a;
    let len2 = d.norm_squared();
    if len2 == 0.0 {
        return (p - a).norm();
    }
    let s = ((p - a).dot(&d) / len2).clamp(0.0, 1.0);
    (p - (a + d * s)).norm()
}

/// Whether every interior control point of `piece` lies within `tolerance` of the chord segment
/// [P₀, Pₙ]: the acceptance test of [`stream_guaranteed`].
///
/// Compared in squared distances, with one division per piece (the projection parameter
/// s = (Pᵢ − P₀)·d / |d|², d = Pₙ − P₀, clamped to [0, 1]); [`distance_to_segment`] decides when
/// tolerance² or |d|² is not a normal number.
fn within_chord_segment(piece: &[Vector2], tolerance: f64) -> bool {
    let [a, interior @ .., b] = piece else {
        return true;
    };
    let d = b - a;
    let len2 = d.norm_squared();
    let tol2 = tolerance * tolerance;
    let normal = f64::MIN_POSITIVE..=f64::MAX;
    if !(normal.contains(&len2) && normal.contains(&tol2)) {
        return interior
            .iter()
            .all(|p| distance_to_segment(p, a, b) <= tolerance);
    }
    let inv_len2 = 1.0 / len2;
    interior.iter().all(|p| {
        let w = p - a;
        let s = (w.dot(&d) * inv_len2).clamp(0.0, 1.0);
        (w - d * s).norm_squared() <= tol2
    })
}

/// `Method::Halving`: points B(tᵢ), 0 = t₀ < … < t_k = 1, whose polyline is within `tolerance` of the curve in
/// Hausdorff distance (an absolute distance, in the curve's units).
///
/// Pieces are halved until every control point lies within `tolerance` of the chord
/// *segment* (not its line, as eq. (3) tests). Then the piece lies in the convex hull of its
/// control points, hence within `tolerance` of the segment; and since the piece joins the
/// segment's end points continuously, its projection covers the segment, so every segment point
/// is within `tolerance` of the piece too. Both directions of the Hausdorff distance are bounded,
/// at cusps and loops as well. The points are exact curve points (de Casteljau end points).
/// Halving runs without per-piece allocation.
///
/// # Errors
/// [`SubdivError::TooFewPoints`] for a degree-0 curve, [`SubdivError::InvalidTolerance`],
/// [`SubdivError::DepthLimit`] when a piece is not within tolerance after `max_depth` halvings
/// (e.g. a tolerance below the rounding level of the coordinates);/// [`SubdivError::DepthTooLarge`] for `max_depth` above [`MAX_FLATTEN_DEPTH`](crate::MAX_FLATTEN_DEPTH),
/// [`SubdivError::ToleranceBelowRounding`] below 16 ulps of the largest coordinate (checked
/// before any work).
/// Streamed to `sink`; returns the number of segments.
pub(crate) fn stream_guaranteed(
    curve: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
    sink: impl FnMut(FlatPoint),
) -> Result<usize, SubdivError> {
    halve_to_points(
        curve,
        tolerance,
        max_depth,
        |piece| within_chord_segment(piece, tolerance),
        |_, _, _, _: &mut dyn FnMut(FlatPoint)| {},
        sink,
    )
}

/// A flattening by halving at t = ½ until `accept` holds for a piece, streamed to `sink`: B(0),
/// then for each accepted piece on [t₀, t₀ + span], in parameter order, the points
/// `interior(piece, t₀, span, sink)` sends and the piece's end point (an exact de Casteljau end
/// point; the dyadic spans of at most [`MAX_FLATTEN_DEPTH`](crate::MAX_FLATTEN_DEPTH) levels
/// sum to exactly 1). Returns the number of segments. On an error, the points before it have
/// been sent.
///
/// # Errors
/// [`SubdivError::InvalidTolerance`] unless `tolerance` is positive and finite,
/// [`SubdivError::TooFewPoints`] below two control points, [`SubdivError::DepthTooLarge`],
/// [`SubdivError::ToleranceBelowRounding`] (before any point), [`SubdivError::DepthLimit`].
pub(crate) fn halve_to_points(
    curve: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
    accept: impl FnMut(&[Vector2]) -> bool,
    mut interior: impl FnMut(&[Vector2], f64, f64, &mut dyn FnMut(FlatPoint)),
    mut sink: impl FnMut(FlatPoint),
) -> Result<usize, SubdivError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(SubdivError::InvalidTolerance { value: tolerance });
    }
    let n = curve.points().len();
    if n < 2 {
        return Err(SubdivError::TooFewPoints { got: n });
    }
    crate::limits::check_work(curve, tolerance, max_depth)?;
    let mut points = 1_usize;
    let mut counted = |p: FlatPoint| {
        points += 1;
        sink(p);
    };
    counted(FlatPoint {
        t: 0.0,
        point: curve.start(),
    });
    // A piece at level d spans 2⁻ᵈ of the parameter range.
    let mut t0 = 0.0_f64;
    halve_until(curve.points(), max_depth, accept, |piece, depth| {
        let span = 0.5_f64.powi(i32::try_from(depth).unwrap_or(i32::MAX));
        interior(piece, t0, span, &mut counted);
        t0 += span;
        counted(FlatPoint {
            t: t0,
            point: piece[n - 1],
        });
    })?;
    Ok(points - 2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::assert_typed_errors;

    #[test]
    fn segment_distance_clamps_to_end_points() {
        let (a, b) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
        assert_eq!(distance_to_segment(&Vector2::new(0.5, 2.0), &a, &b), 2.0);
        assert_eq!(distance_to_segment(&Vector2::new(4.0, 4.0), &a, &b), 5.0);
        assert_eq!(distance_to_segment(&Vector2::new(3.0, 4.0), &a, &a), 5.0);
    }

    #[test]
    fn points_carry_their_parameters() {
        for pts in [
            vec![
                Vector2::new(0.0, 0.0),
                Vector2::new(1.0, 2.0),
                Vector2::new(3.0, -1.0),
            ],
            vec![
                Vector2::new(0.0, 0.0),
                Vector2::new(2.0, 2.0),
                Vector2::new(-1.0, 2.0),
                Vector2::new(1.0, 0.0),
            ],
            (0..9)
                .map(|i| Vector2::new(f64::from(i), f64::from(i * i % 5)))
                .collect(),
        ] {
            let c = BezierCurve::new(pts).unwrap();
            let mut flat = Vec::new();
            stream_guaranteed(&c, 1e-3, 40, |p| flat.push(p)).unwrap();
            assert!(flat.len() > 2);
            assert_eq!((flat[0].t, flat[flat.len() - 1].t), (0.0, 1.0));
            for w in flat.windows(2) {
                assert!(w[0].t < w[1].t);
            }
            for p in &flat {
                assert!((c.eval(p.t).unwrap() - p.point).norm() < 1e-12);
            }
        }
    }

    #[test]
    fn errors_are_typed() {
        assert_typed_errors(|c, tol, depth| stream_guaranteed(c, tol, depth, |_| {}));
    }
}
