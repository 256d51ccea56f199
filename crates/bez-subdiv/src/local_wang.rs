//! Beyond the paper: guaranteed flattening from local a-priori bounds, O(n) per point.

use bez_core::{BezierCurve, HornerBernstein};

use crate::bound::wang_steps;
use crate::error::SubdivError;
use crate::guaranteed::{FlatPoint, halve_to_points};

/// Largest number of equal steps `Method::LocalWang` places on one piece; pieces that need
/// more are halved first.
pub const LOCAL_WANG_STEPS: usize = 16;

/// `Method::LocalWang`: points B(tᵢ), 0 = t₀ < … < t_k = 1, whose polyline is within `tolerance` (absolute) of the
/// curve in Hausdorff distance, placed by Wang's bound applied piece by piece.
///
/// For a piece Q of degree n on [t₀, t₁], Wang's formula bounds the deviation of the chords of
/// k equal parameter steps by n(n − 1)/8 · maxᵢ |Δ²Qᵢ| / k² (the linear interpolation error
/// h²/8 · max|Q''|, with |Q''| bounded by the convex hull of its control points; see
/// [`wang_segment_count`](crate::wang_segment_count)). The curve is halved at t = ½ (de
/// Casteljau, as [`stream_guaranteed`](crate::guaranteed::stream_guaranteed)) until a piece needs at
/// most [`LOCAL_WANG_STEPS`] steps, k = ⌈√(n(n − 1) M / (8 tol))⌉; the piece's k − 1 interior
/// points are then evaluated by Horner's rule on the whole curve, O(n) each, and its end point
/// is the halving's. Since halving divides the second differences by about 4, local bounds
/// follow the curve's actual bending, unlike the single global count of
/// `wang_segment_count`.
///
/// Against [`stream_guaranteed`](crate::guaranteed::stream_guaranteed): the same bound in both
/// directions (each chord point is within the bound of the curve point at the same parameter
/// and vice versa), up to the rounding of the evaluated points (about n · 2⁻⁵³ of the
/// coordinates); far fewer O(n²) halvings at high degree (one per up to
/// [`LOCAL_WANG_STEPS`] points), at the price of a few more points where the parametrization
/// is uneven (the bound follows |B''|, not the curvature). Cost: O(n²) per halving plus O(n)
/// per point.
///
/// # Errors
/// [`SubdivError::TooFewPoints`] for a degree-0 curve, [`SubdivError::InvalidTolerance`],
/// [`SubdivError::DepthLimit`] when a piece still needs more than [`LOCAL_WANG_STEPS`] steps
/// after `max_depth` halvings (e.g. a tolerance below the rounding level of the coordinates);/// [`SubdivError::DepthTooLarge`] for `max_depth` above [`MAX_FLATTEN_DEPTH`](crate::MAX_FLATTEN_DEPTH),
/// [`SubdivError::ToleranceBelowRounding`] below 16 ulps of the largest coordinate (checked
/// before any work).
///
/// Streamed to `sink`; returns the number of segments.
pub(crate) fn stream_local_wang(
    curve: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
    sink: impl FnMut(FlatPoint),
) -> Result<usize, SubdivError> {
    let horner = HornerBernstein::new(curve.points());
    let max_steps = LOCAL_WANG_STEPS as f64;
    halve_to_points(
        curve,
        tolerance,
        max_depth,
        |piece| wang_steps(piece, tolerance) <= max_steps,
        |piece, t0, span, out: &mut dyn FnMut(FlatPoint)| {
            // At most LOCAL_WANG_STEPS here, so the cast is exact.
            let k = wang_steps(piece, tolerance).ceil().max(1.0) as usize;
            for j in 1..k {
                let t = t0 + span * (j as f64 / k as f64);
                // `None` only for an empty polygon, which halve_to_points rejects.
                if let Some(point) = horner.eval(t) {
                    out(FlatPoint { t, point });
                }
            }
        },
        sink,
    )
}

#[cfg(all(test, feature = "paper"))]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]

    use bez_core::Vector2;

    use super::*;
    use crate::cases::{cusp, looped, random_curves};
    use crate::hausdorff::{HausdorffSampling, measured_hausdorff};
    use crate::test_support::assert_typed_errors;
    use crate::wang_segment_count;

    /// The points of [`stream_local_wang`], collected.
    fn flatten_local_wang(
        c: &BezierCurve<2>,
        tol: f64,
        depth: usize,
    ) -> Result<Vec<FlatPoint>, SubdivError> {
        let mut out = Vec::new();
        stream_local_wang(c, tol, depth, |p| out.push(p))?;
        Ok(out)
    }

    #[test]
    fn within_tolerance_and_ordered_on_random_cusp_and_loop_curves() {
        let mut curves: Vec<_> = (2..=30)
            .flat_map(|n| random_curves(n, 2, 40 + n as u64))
            .collect();
        curves.extend([cusp().unwrap(), looped().unwrap()]);
        let sampling = HausdorffSampling {
            curve_samples: 2001,
            segment_samples: 3,
        };
        for c in &curves {
            // Tolerances relative to the [0, 1]² control boxes; tighter ones only cost time.
            for tol in [3e-2, 3e-3] {
                let flat = flatten_local_wang(c, tol, 40).unwrap();
                assert_eq!((flat[0].t, flat[flat.len() - 1].t), (0.0, 1.0));
                for w in flat.windows(2) {
                    assert!(w[0].t < w[1].t);
                }
                for p in &flat {
                    assert!((c.eval(p.t).unwrap() - p.point).norm() < 1e-12);
                }
                let poly: Vec<_> = flat.iter().map(|p| p.point).collect();
                let h = measured_hausdorff(c, &poly, sampling).unwrap();
                assert!(
                    h <= tol * (1.0 + 1e-9),
                    "degree {} tol {tol}: {h}",
                    c.degree()
                );
            }
        }
    }

    #[test]
    fn one_piece_gives_wangs_count() {
        // A parabola whose global count is at most LOCAL_WANG_STEPS is not halved: its
        // segments are exactly Wang's count at equal steps.
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(0.5, 1.0),
            Vector2::new(1.0, 0.0),
        ])
        .unwrap();
        let tol = 0.01;
        let count = wang_segment_count(&c, tol).unwrap();
        assert!(count > 1 && count <= LOCAL_WANG_STEPS);
        let flat = flatten_local_wang(&c, tol, 40).unwrap();
        assert_eq!(flat.len(), count + 1);
        for (j, p) in flat.iter().enumerate() {
            assert!((p.t - j as f64 / count as f64).abs() < 1e-15);
        }
    }

    #[test]
    fn lines_and_points_need_one_segment() {
        let line = BezierCurve::new(vec![Vector2::new(0.0, 0.0), Vector2::new(2.0, 1.0)]).unwrap();
        assert_eq!(flatten_local_wang(&line, 1e-9, 0).unwrap().len(), 2);
        let collapsed = BezierCurve::new(vec![Vector2::new(1.0, 1.0); 6]).unwrap();
        assert_eq!(flatten_local_wang(&collapsed, 1e-9, 0).unwrap().len(), 2);
    }

    #[test]
    fn errors_are_typed() {
        assert_typed_errors(flatten_local_wang);
    }
}
