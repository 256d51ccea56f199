//! Beyond the paper: the fastest guaranteed flattening, Wang's uniform count with the points
//! streamed to a sink.

use bez_core::{BezierForm, HornerBernstein, Vector2};

use crate::bound::wang_count;
use crate::error::SubdivError;
use crate::guaranteed::FlatPoint;
use crate::stack_horner::{STACK_POINTS, StackHorner};

/// The most segments one call of [`Method::Fast`](crate::Method::Fast) produces: 2²⁴. A tolerance that needs more
/// (below the rounding of the coordinates, in practice) is refused before any point is made.
pub const MAX_WANG_SEGMENTS: usize = 1 << 24;

/// Streams the points B(k/N), k = 0..=N, of Wang's uniform flattening to `sink` and returns
/// N, the number of segments: the polyline is within `tolerance` (absolute) of the curve in
/// Hausdorff distance.
///
/// N = max(1, ⌈√(n(n − 1) M / (8 tol))⌉) with M the largest second difference of the control
/// points ([`wang_segment_count`](crate::wang_segment_count)): the chord of a parameter step h interpolates B within
/// h²/8 · max|B''| and |B''| ≤ n(n − 1) M. The same count as lyon_geom's
/// `for_each_flattened` for quadratics and cubics (about twice the optimal count on curved
/// pieces; `Method::Optimal` places about half as many);
/// no subdivision, no allocation. Points: up to degree 3 by Horner's rule on the power form
/// relative to P₀ (a few multiply-adds per point, and a translation of the curve changes
/// nothing but the added P₀); above, by [`HornerBernstein`], O(n) per point. The first and
/// last points are P₀ and Pₙ exactly.
///
/// # Errors
/// [`SubdivError::TooFewPoints`] for a degree-0 curve, [`SubdivError::InvalidTolerance`],
/// [`SubdivError::TooManySegments`] above [`MAX_WANG_SEGMENTS`].
///
pub(crate) fn flatten_wang<C: BezierForm<2> + ?Sized>(
    curve: &C,
    tolerance: f64,
    sink: impl FnMut(FlatPoint),
) -> Result<usize, SubdivError> {
    let bezier = curve.as_bezier();
    let p = bezier.points();
    if p.len() < 2 {
        return Err(SubdivError::TooFewPoints { got: p.len() });
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(SubdivError::InvalidTolerance { value: tolerance });
    }
    // Wang's count, checked before the first point. Up to degree 3 it is taken on a
    // fixed-size copy of the control points, so that the second differences unroll.
    let count = |q: &[Vector2]| match wang_count(q, tolerance) {
        Some(n) if n <= MAX_WANG_SEGMENTS => Ok(n),
        _ => Err(SubdivError::TooManySegments {
            tolerance,
            limit: MAX_WANG_SEGMENTS,
        }),
    };
    match *p {
        [p0, p1] => {
            let a = p1 - p0;
            Ok(uniform(count(&[p0, p1])?, p0, p1, |t| p0 + a * t, sink))
        }
        [p0, p1, p2] => {
            // B(t) = P₀ + t (a + t b), a = 2(P₁ − P₀), b = P₂ − 2P₁ + P₀.
            let (a, b) = ((p1 - p0) * 2.0, p2 - p1 * 2.0 + p0);
            let n = count(&[p0, p1, p2])?;
            Ok(uniform(n, p0, p2, |t| p0 + (a + b * t) * t, sink))
        }
        [p0, p1, p2, p3] => {
            // B(t) = P₀ + t (a + t (b + t c)), a = 3(P₁ − P₀), b = 3(P₂ − 2P₁ + P₀),
            // c = P₃ − 3P₂ + 3P₁ − P₀.
            let a = (p1 - p0) * 3.0;
            let b = (p2 - p1 * 2.0 + p0) * 3.0;
            let c = p3 - p2 * 3.0 + p1 * 3.0 - p0;
            let n = count(&[p0, p1, p2, p3])?;
            Ok(uniform(n, p0, p3, |t| p0 + (a + (b + c * t) * t) * t, sink))
        }
        _ => {
            let n = count(p)?;
            let (first, last) = (p[0], p[p.len() - 1]);
            // Up to `MAX_STACK_DEGREE` the scaled control points sit in the stack frame.
            let mut buffer = [Vector2::zeros(); STACK_POINTS];
            if let Some(horner) = StackHorner::new(p, &mut buffer) {
                return Ok(uniform(n, first, last, |t| horner.eval(t), sink));
            }
            let horner = HornerBernstein::new(p);
            // `None` only for an empty polygon, excluded above.
            let eval = |t: f64| horner.eval(t).unwrap_or(first);
            Ok(uniform(n, first, last, eval, sink))
        }
    }
}

/// Sends `first`, the points `eval`(k/n) for k = 1..n and `last` to `sink`; returns n.
#[inline(always)]
fn uniform(
    n: usize,
    first: Vector2,
    last: Vector2,
    eval: impl Fn(f64) -> Vector2,
    mut sink: impl FnMut(FlatPoint),
) -> usize {
    let step = 1.0 / n as f64;
    sink(FlatPoint {
        t: 0.0,
        point: first,
    });
    for k in 1..n {
        let t = k as f64 * step;
        sink(FlatPoint { t, point: eval(t) });
    }
    sink(FlatPoint {
        t: 1.0,
        point: last,
    });
    n
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use crate::{HausdorffSampling, measured_hausdorff};
    use bez_core::BezierCurve;
    use bez_core::proptest_support::curve;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The measured two-sided Hausdorff distance stays within the tolerance, the count is
        /// Wang's, and the points come in parameter order with exact end points.
        #[test]
        fn within_tolerance_with_wangs_count(c in curve::<2>(1..=8, 10.0), rel in 1e-4f64..1e-1) {
            let tol = rel * crate::curve_size(&c).max(1e-3);
            let mut pts = Vec::new();
            let n = flatten_wang(&c, tol, |p| pts.push(p)).unwrap();
            prop_assert_eq!(n, crate::wang_segment_count(&c, tol).unwrap());
            prop_assert_eq!(pts.len(), n + 1);
            prop_assert_eq!(pts[0].point, c.start());
            prop_assert_eq!(pts[n].point, c.end());
            prop_assert!(pts.windows(2).all(|w| w[0].t < w[1].t));
            let poly: Vec<Vector2> = pts.iter().map(|p| p.point).collect();
            let sampling = HausdorffSampling { curve_samples: 2001, segment_samples: 3 };
            let h = measured_hausdorff(&c, &poly, sampling).unwrap();
            prop_assert!(h <= tol * (1.0 + 1e-9), "{h} > {tol}");
            // The points are on the curve (power form vs de Casteljau).
            for p in &pts {
                prop_assert!((p.point - c.eval(p.t).unwrap()).norm() <= 1e-12 * (1.0 + crate::curve_size(&c)));
            }
        }
    }

    #[test]
    fn bad_input_and_limits() {
        let dot = BezierCurve::new(vec![Vector2::new(1.0, 1.0)]).unwrap();
        assert_eq!(
            flatten_wang(&dot, 1e-3, |_| {}),
            Err(SubdivError::TooFewPoints { got: 1 })
        );
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 1.0),
            Vector2::new(2.0, 0.0),
        ])
        .unwrap();
        assert!(matches!(
            flatten_wang(&c, f64::NAN, |_| {}),
            Err(SubdivError::InvalidTolerance { .. })
        ));
        let mut calls = 0;
        assert!(matches!(
            flatten_wang(&c, 1e-20, |_| calls += 1),
            Err(SubdivError::TooManySegments { .. })
        ));
        assert_eq!(calls, 0, "refused before any point");
    }
}
