//! A measured Hausdorff distance between a curve and a polyline, for checking flattenings.

use bez_core::{BezierCurve, BezierForm, Vector2};

use crate::error::SubdivError;
use crate::guaranteed::distance_to_segment;

/// The most work [`measured_hausdorff`] accepts: 2³², counted as curve samples × segments plus
/// segment samples × segments × control points (a nearest-point search costs about that
/// many operations per control point).
pub const MAX_HAUSDORFF_WORK: f64 = 4_294_967_296.0;

/// How densely [`measured_hausdorff`] samples both sides.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct HausdorffSampling {
    /// Curve points B(k / (m − 1)), k = 0..m − 1, measured to the polyline.
    pub curve_samples: usize,
    /// Points per polyline segment (both ends included), measured to the curve.
    pub segment_samples: usize,
}

impl Default for HausdorffSampling {
    /// 20,001 curve samples, 5 points per segment.
    fn default() -> Self {
        Self {
            curve_samples: 20_001,
            segment_samples: 5,
        }
    }
}

/// The Hausdorff distance between `curve` and `polyline`, measured both ways: the largest
/// distance from a curve sample to the polyline (point-to-segment distances), and the largest
/// distance from a polyline sample to the curve (exact nearest curve points, by
/// [`BezierCurve::nearest`]).
///
/// Both halves are exact at their samples, so the result is a lower bound of the true
/// distance that converges as the samples get denser. Cost O(m · s) for m curve samples and
/// s segments, plus s · k nearest-point searches for k samples per segment.
///
/// # Errors
/// [`SubdivError::TooFewPoints`] when `polyline` is empty; [`SubdivError::Core`] when a
/// polyline point is not finite or the curve samples are above bez-core's limit;
/// [`SubdivError::SamplingTooLarge`] above [`MAX_HAUSDORFF_WORK`] (checked first).
///
/// ```
/// use bez_core::{BezierCurve, Vector2};
/// use bez_subdiv::{HausdorffSampling, measured_hausdorff};
///
/// // y = 2t(1 − t) peaks at ½ over its chord from (0, 0) to (1, 0).
/// let curve = BezierCurve::new(vec![
///     Vector2::new(0.0, 0.0), Vector2::new(0.5, 1.0), Vector2::new(1.0, 0.0),
/// ])?;
/// let chord = [curve.start(), curve.end()];
/// let h = measured_hausdorff(&curve, &chord, HausdorffSampling::default())?;
/// assert!((h - 0.5).abs() < 1e-9);
/// # Ok::<(), bez_subdiv::SubdivError>(())
/// ```
pub fn measured_hausdorff<C: BezierForm<2> + ?Sized>(
    curve: &C,
    polyline: &[Vector2],
    sampling: HausdorffSampling,
) -> Result<f64, SubdivError> {
    hausdorff_bezier(curve.as_bezier(), polyline, sampling)
}

/// [`measured_hausdorff`] on the Bézier form (one instance for every curve type).
fn hausdorff_bezier(
    curve: &BezierCurve<2>,
    polyline: &[Vector2],
    sampling: HausdorffSampling,
) -> Result<f64, SubdivError> {
    let Some(&first) = polyline.first() else {
        return Err(SubdivError::TooFewPoints { got: 0 });
    };
    // The work: every curve sample against every segment, and a nearest-point search per
    // segment sample. Refused before it starts above MAX_HAUSDORFF_WORK.
    let segments = polyline.len().max(2) - 1;
    let work = (sampling.curve_samples as f64) * (segments as f64)
        + (sampling.segment_samples as f64) * (segments as f64) * (curve.points().len() as f64);
    if work > MAX_HAUSDORFF_WORK {
        return Err(SubdivError::SamplingTooLarge {
            work,
            limit: MAX_HAUSDORFF_WORK,
        });
    }
    let to_polyline = |p: &Vector2| {
        if polyline.len() == 1 {
            return (p - first).norm();
        }
        polyline
            .windows(2)
            .map(|w| distance_to_segment(p, &w[0], &w[1]))
            .fold(f64::INFINITY, f64::min)
    };
    let mut h = curve
        .sample_uniform(sampling.curve_samples)?
        .iter()
        .map(to_polyline)
        .fold(0.0_f64, f64::max);
    if polyline.len() == 1 {
        return Ok(h.max(curve.nearest(&first)?.distance));
    }
    let k = sampling.segment_samples.max(2) - 1;
    for w in polyline.windows(2) {
        for j in 0..=k {
            let s = j as f64 / k as f64;
            h = h.max(curve.nearest(&(w[0] * (1.0 - s) + w[1] * s))?.distance);
        }
    }
    Ok(h)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]

    use super::*;

    fn parabola() -> BezierCurve<2> {
        BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(0.5, 1.0),
            Vector2::new(1.0, 0.0),
        ])
        .unwrap()
    }

    #[test]
    fn curve_side_finds_the_bulge() {
        // The chord misses the apex (½, ½) by ½; the chord's own points are within ½.
        let c = parabola();
        let h = measured_hausdorff(&c, &[c.start(), c.end()], HausdorffSampling::default());
        assert!((h.unwrap() - 0.5).abs() < 1e-9);
    }

    #[test]
    fn polyline_side_finds_an_overshoot() {
        // A polyline that runs on to (3, 0) is 2 beyond the curve's end point (1, 0) there,
        // although every curve point is close to the polyline.
        let c = parabola();
        let mut poly: Vec<_> = c.sample_uniform(2001).unwrap();
        poly.push(Vector2::new(3.0, 0.0));
        let h = measured_hausdorff(&c, &poly, HausdorffSampling::default()).unwrap();
        assert!((h - 2.0).abs() < 1e-9, "{h}");
    }

    #[test]
    fn single_point_and_empty_polylines() {
        let c = parabola();
        let h = measured_hausdorff(&c, &[Vector2::new(0.5, 0.5)], HausdorffSampling::default());
        // Farthest curve points from (½, ½) are the ends, at √2 / 2.
        assert!((h.unwrap() - 0.5_f64.sqrt()).abs() < 1e-9);
        assert_eq!(
            measured_hausdorff(&c, &[], HausdorffSampling::default()),
            Err(SubdivError::TooFewPoints { got: 0 })
        );
        let bad = [Vector2::new(f64::NAN, 0.0), Vector2::new(1.0, 0.0)];
        assert!(measured_hausdorff(&c, &bad, HausdorffSampling::default()).is_err());
    }
}
