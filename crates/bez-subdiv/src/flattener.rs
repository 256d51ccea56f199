//! `Flattener`: one entry point for every flattening method, with an absolute tolerance, the
//! points streamed to a sink, and paths of several curves in one call.

use bez_core::{BezierCurve, BezierForm, Vector2};

use crate::error::SubdivError;
use crate::flatten::{DEFAULT_MAX_DEPTH, FlattenOptions, curve_size, subdivide};
use crate::guaranteed::{FlatPoint, stream_guaranteed};
use crate::local_wang::stream_local_wang;
use crate::optimal::flatten_optimal;
use crate::split_rule::SplitRule;
use crate::wang::{flatten_wang, flatten_wang_small};

/// How a [`Flattener`] places its points. Every method but [`Method::PaperRule`] guarantees
/// that the polyline is within the tolerance of the curve in Hausdorff distance.
///
/// | method | segments / N* (random cubics, tol = 1e-3 × size) | cost | use it for |
/// |---|---|---|---|
/// | [`Fast`](Method::Fast) | about 2 | fastest: no subdivision, a few flops per point (about 0.1 × kurbo's `flatten`) | rendering, hit testing, anything per frame |
/// | [`Optimal`](Method::Optimal) | median 1.05, 90th percentile 1.10 | below kurbo's `flatten` on cubics (0.84–0.88 × its time on random cubics on a quiet machine, 0.78 × on adversarial ones); about 0.08 µs per point at degree 25 | output that is stored or sent (fewest points) |
/// | [`LocalWang`](Method::LocalWang) | 1.6–2.0 | one halving per up to 16 points | high degrees |
/// | [`Halving`](Method::Halving) | about 1.7 | one de Casteljau halving per segment | — |
/// | [`PaperRule`](Method::PaperRule) | — | — | reproducing Ma, Lin & Shen's Table 1 only: **no guarantee** |
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub enum Method {
    /// Wang's uniform count: the points B(k/N), k = 0..=N, with
    /// N = max(1, ⌈√(n(n − 1) M / (8 tol))⌉) and M the largest second difference of the control
    /// points ([`wang_segment_count`](crate::wang_segment_count)): the chord of a parameter step h
    /// interpolates B within h²/8 · max|B″| and |B″| ≤ n(n − 1) M. lyon_geom's count for
    /// quadratics and cubics; no subdivision, no allocation; O(1) per point up to degree 3
    /// (forward differences, two or three vector additions per point, where their rounding
    /// error, at most 2⁻⁵⁰ s (N + 64) for the sum s of the absolute coordinates, fits in the
    /// tolerance beside the chord error and below tol / 1024, which up to 64 segments is
    /// checked as tol ≥ 2⁻²¹ s; otherwise the power form), O(n) above. At most [`MAX_WANG_SEGMENTS`](crate::MAX_WANG_SEGMENTS)
    /// segments, checked before the first point. On quadratics and cubics needing at most 64
    /// segments, N is read from a table of fourth powers (no square root), above from two
    /// square roots of its fourth power; it rounds up, so it is one more than the formula where
    /// the formula's value is within a relative 2⁻⁴⁵ or so of a whole number.
    #[default]
    Fast,
    /// Wang's bound piece by piece: the curve is halved (de Casteljau at ½) until a piece needs
    /// at most [`LOCAL_WANG_STEPS`](crate::LOCAL_WANG_STEPS) of Wang's steps, then those steps
    /// are evaluated by Horner's rule, O(n) each. The bound follows the curve's actual bending,
    /// unlike `Fast`'s single count; one O(n²) halving per up to 16 points.
    LocalWang,
    /// Halving until every control point of a piece is within the tolerance of the piece's
    /// chord *segment*: the piece then lies in their convex hull, within tol of the segment,
    /// and its projection covers the segment. The points are exact de Casteljau end points.
    Halving,
    /// Points placed by the curvature density of the lower bound N*
    /// ([`optimal_segment_count`](crate::optimal_segment_count)), each chord verified by a
    /// closed-form bound and shortened where it fails: close to N* segments (within 1.15 N* up
    /// to degree 3, 1.25 N* above), O(1) per point up to degree 3; above, each chord is
    /// measured on quintic models of the curve with rigorous remainders, and the points are the
    /// models' points: within tol / 32 of B(t) (the first and last exact), the polyline still
    /// within tol of the curve; O(n) per model. No allocation up to degree
    /// [`MAX_STACK_DEGREE`](crate::MAX_STACK_DEGREE).
    Optimal,
    /// The paper's rule: split with `SplitRule` until eq. (3) holds with ε = tolerance / size
    /// (the reproduction of Table 1), then the chords through the pieces' end points.
    /// Eq. (3) bounds the control points' distance to the chord *line*, not the curve's to the
    /// chord segment: collinear control points pass it at once, and on the cubic (0, 0),
    /// (10, 0), (−9, 0), (1, 0) the chord it returns is about 2,000 × the tolerance away from
    /// the curve.
    PaperRule(SplitRule),
}

/// A point of a flattened path: the index of its curve, its parameter there, and the point.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PathPoint {
    /// Index of the curve in the path.
    pub curve: usize,
    /// Parameter on that curve.
    pub t: f64,
    /// The point.
    pub point: Vector2,
}

/// Flattens curves of any degree and type (anything with a Bézier form) to polylines within
/// an **absolute** `tolerance` of the curve.
///
/// ```
/// use bez_core::{BezierCurve, Vector2};
/// use bez_subdiv::{Flattener, Method};
///
/// let curve = BezierCurve::new(vec![
///     Vector2::new(0.0, 0.0), Vector2::new(1.0, 2.0),
///     Vector2::new(3.0, -1.0), Vector2::new(4.0, 1.0),
/// ])?;
/// let mut polyline = Vec::new();
/// let segments = Flattener::new(1e-3).flatten(&curve, |p| polyline.push(p.point))?;
/// assert_eq!(polyline.len(), segments + 1);
/// let fewer = Flattener::new(1e-3).with_method(Method::Optimal).flatten(&curve, |_| {})?;
/// assert!(fewer < segments);
/// # Ok::<(), bez_subdiv::SubdivError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Flattener {
    /// The largest distance allowed between the curve and the polyline (absolute).
    pub tolerance: f64,
    /// How points are placed.
    pub method: Method,
    /// Subdivision depth cap of the subdividing methods ([`SubdivError::DepthLimit`] beyond).
    pub max_depth: usize,
}

impl Flattener {
    /// [`Method::Fast`] with `tolerance` and the default depth cap.
    #[must_use]
    pub fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            method: Method::default(),
            max_depth: DEFAULT_MAX_DEPTH,
        }
    }

    /// The same with `method`.
    #[must_use]
    pub fn with_method(mut self, method: Method) -> Self {
        self.method = method;
        self
    }

    /// The same with the depth cap `max_depth`.
    #[must_use]
    pub fn with_max_depth(mut self, max_depth: usize) -> Self {
        self.max_depth = max_depth;
        self
    }

    /// Streams the polyline of `curve` to `sink`, first point B(0) to last point B(1), and
    /// returns the number of segments.
    ///
    /// # Errors
    /// [`SubdivError::InvalidTolerance`] unless the tolerance is positive and finite,
    /// [`SubdivError::TooFewPoints`] for a degree-0 curve, [`SubdivError::DepthTooLarge`] for a
    /// depth cap above [`MAX_FLATTEN_DEPTH`](crate::MAX_FLATTEN_DEPTH),
    /// [`SubdivError::ToleranceBelowRounding`] for a tolerance below 16 ulps of the largest
    /// coordinate (the subdividing methods), [`SubdivError::TooManySegments`] when the count
    /// estimated before the first point is above the method's limit, all checked before any
    /// point is sent; [`SubdivError::DepthLimit`] when a piece still fails at the depth cap
    /// (the points before it have been sent).
    #[inline]
    pub fn flatten<C: BezierForm<2> + ?Sized>(
        &self,
        curve: &C,
        mut sink: impl FnMut(FlatPoint),
    ) -> Result<usize, SubdivError> {
        let bezier = curve.as_bezier();
        // `Fast` on a quadratic or a cubic of usual size: no dynamic dispatch and, up to 64
        // segments, no square root before the points (`None`, nothing sent, when the general path decides).
        if let Method::Fast = self.method
            && let Some(n) = flatten_wang_small(bezier.points(), self.tolerance, &mut sink)
        {
            return Ok(n);
        }
        if let Some(exponent) = unit_exponent(bezier) {
            // Far from unit size, flatten the curve scaled by 2^−exponent (exact) with the
            // tolerance scaled alike, and scale the points back: the result is the scaled
            // result, and no intermediate (|B′|³, squared lengths) leaves the f64 range.
            let down = 2f64.powi(-exponent);
            let up = 2f64.powi(exponent);
            let scaled = BezierCurve::new(bezier.points().iter().map(|&p| p * down).collect())?;
            let tolerance = (self.tolerance * down).min(f64::MAX);
            return Self { tolerance, ..*self }.flatten_unit(&scaled, |mut p| {
                p.point *= up;
                sink(p);
            });
        }
        self.flatten_unit(bezier, sink)
    }

    /// [`Self::flatten`] of a curve whose size is within 2^±[`UNIT_EXPONENT_RANGE`].
    fn flatten_unit(
        &self,
        bezier: &BezierCurve<2>,
        sink: impl FnMut(FlatPoint),
    ) -> Result<usize, SubdivError> {
        let (tol, depth) = (self.tolerance, self.max_depth);
        match self.method {
            Method::Fast => flatten_wang(bezier, tol, sink),
            Method::LocalWang => stream_local_wang(bezier, tol, depth, sink),
            Method::Halving => stream_guaranteed(bezier, tol, depth, sink),
            Method::Optimal => flatten_optimal(bezier, tol, depth, sink),
            Method::PaperRule(rule) => stream_paper_rule(bezier, tol, rule, depth, sink),
        }
    }

    /// The polyline of `curve` as a vector (see [`Self::flatten`]).
    ///
    /// # Errors
    /// As [`Self::flatten`].
    pub fn flatten_to_vec<C: BezierForm<2> + ?Sized>(
        &self,
        curve: &C,
    ) -> Result<Vec<FlatPoint>, SubdivError> {
        let mut out = Vec::new();
        self.flatten(curve, |p| out.push(p))?;
        Ok(out)
    }

    /// Flattens every curve of `curves` on its own, results in input order: with the `rayon`
    /// feature on rayon's thread pool, otherwise one after the other on the calling thread
    /// (`Sync` is asked in both cases, so that enabling the feature never breaks a caller).
    #[must_use]
    pub fn flatten_batch<C: BezierForm<2> + Sync>(
        &self,
        curves: &[C],
    ) -> Vec<Result<Vec<FlatPoint>, SubdivError>> {
        #[cfg(feature = "rayon")]
        {
            use rayon::prelude::*;
            curves.par_iter().map(|c| self.flatten_to_vec(c)).collect()
        }
        #[cfg(not(feature = "rayon"))]
        {
            curves.iter().map(|c| self.flatten_to_vec(c)).collect()
        }
    }

    /// Streams one polyline through `curves` in order (a chain: each curve should start where
    /// the previous one ends); the joint of two curves is sent once, as the end of the first.
    /// Returns the number of segments.
    ///
    /// # Errors
    /// As [`Self::flatten`], for the first curve that fails (the points of the curves before
    /// it have been sent).
    pub fn flatten_path<C: BezierForm<2>>(
        &self,
        curves: &[C],
        mut sink: impl FnMut(PathPoint),
    ) -> Result<usize, SubdivError> {
        let mut segments = 0;
        for (index, c) in curves.iter().enumerate() {
            let mut first = index > 0;
            segments += self.flatten(c, |p| {
                if first {
                    first = false;
                } else {
                    sink(PathPoint {
                        curve: index,
                        t: p.t,
                        point: p.point,
                    });
                }
            })?;
        }
        Ok(segments)
    }

    /// Flattens a kurbo path: one polyline per subpath, each point sent with its subpath's
    /// index (closing segments included). Returns the number of segments.
    ///
    /// # Errors
    /// The conversion's errors (a path without `MoveTo`, non-finite or out-of-range
    /// coordinates, as `SubdivError::Core`) and those of [`Self::flatten_path`].
    #[cfg(feature = "kurbo")]
    pub fn flatten_bez_path(
        &self,
        path: &kurbo::BezPath,
        mut sink: impl FnMut(usize, PathPoint),
    ) -> Result<usize, SubdivError> {
        let mut segments = 0;
        for (subpath, curves) in bez_core::bez_path_to_curves(path)?.iter().enumerate() {
            segments += self.flatten_path(curves, |p| sink(subpath, p))?;
        }
        Ok(segments)
    }
}

/// The paper's rule as a [`Method`]: eq. (3) with ε = `tolerance` / size, each final piece's
/// end point streamed to `sink` as soon as the piece is flat (the first piece's start first);
/// returns the number of pieces.
fn stream_paper_rule(
    curve: &BezierCurve<2>,
    tolerance: f64,
    rule: SplitRule,
    max_depth: usize,
    mut sink: impl FnMut(FlatPoint),
) -> Result<usize, SubdivError> {
    let size = curve_size(curve);
    let eps = if size > 0.0 {
        tolerance / size
    } else {
        tolerance
    };
    let options = FlattenOptions::default()
        .with_tolerance(eps)
        .with_rule(rule)
        .with_max_depth(max_depth);
    let mut first = true;
    let stats = subdivide(curve, &options, |piece| {
        if first {
            first = false;
            sink(FlatPoint {
                t: piece.t0,
                point: piece.points[0],
            });
        }
        sink(FlatPoint {
            t: piece.t1,
            point: piece.points[piece.points.len() - 1],
        });
    })?;
    Ok(stats.pieces)
}

/// Curves whose largest coordinate lies within 2^±`UNIT_EXPONENT_RANGE` are flattened as they
/// are; others are first scaled by a power of two (see [`Flattener::flatten`]).
const UNIT_EXPONENT_RANGE: i32 = 128;
/// 2^−[`UNIT_EXPONENT_RANGE`] and 2^[`UNIT_EXPONENT_RANGE`].
const UNIT_LOW: f64 = 1.0 / UNIT_HIGH;
const UNIT_HIGH: f64 = 340_282_366_920_938_463_463_374_607_431_768_211_456.0;

/// The power of two to divide `bezier` by before flattening, when its largest coordinate is
/// outside 2^±[`UNIT_EXPONENT_RANGE`] (`None` inside, and for a curve at the origin).
#[inline]
fn unit_exponent(bezier: &BezierCurve<2>) -> Option<i32> {
    let size = bezier
        .points()
        .iter()
        .map(Vector2::amax)
        .fold(0.0, f64::max);
    // Within 2^±UNIT_EXPONENT_RANGE the rounded exponent below is within the range too: no
    // logarithm on the usual path.
    if size == 0.0 || !size.is_finite() || (UNIT_LOW..=UNIT_HIGH).contains(&size) {
        return None;
    }
    let exponent = size.log2().round();
    // |exponent| ≤ 1075 for every positive finite f64, so the cast is exact.
    #[allow(
        clippy::cast_possible_truncation,
        reason = "a finite f64's binary exponent"
    )]
    let exponent = exponent as i32;
    (exponent.abs() > UNIT_EXPONENT_RANGE).then_some(exponent)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use crate::{HausdorffSampling, measured_hausdorff};
    use bez_core::BezierCurve;

    fn curves() -> Vec<BezierCurve<2>> {
        vec![
            BezierCurve::new(vec![
                Vector2::new(0.0, 0.0),
                Vector2::new(1.0, 2.0),
                Vector2::new(3.0, -1.0),
                Vector2::new(4.0, 1.0),
            ])
            .unwrap(),
            // A cusp.
            BezierCurve::new(vec![
                Vector2::new(4.0, 1.0),
                Vector2::new(6.0, 3.0),
                Vector2::new(4.0, 3.0),
                Vector2::new(6.0, 1.0),
            ])
            .unwrap(),
            // Degree 6.
            BezierCurve::new(
                (0..=6)
                    .map(|i| Vector2::new(6.0 + f64::from(i), f64::from((i * 5) % 4) - 1.0))
                    .collect(),
            )
            .unwrap(),
        ]
    }

    /// Every guaranteed method is within the tolerance (measured both ways), ends at B(0) and
    /// B(1), and Optimal uses the fewest segments.
    #[test]
    fn guaranteed_methods_meet_the_tolerance() {
        let tol = 1e-3;
        for c in curves() {
            let mut counts = Vec::new();
            for method in [
                Method::Fast,
                Method::LocalWang,
                Method::Halving,
                Method::Optimal,
            ] {
                let f = Flattener::new(tol).with_method(method);
                let pts = f.flatten_to_vec(&c).unwrap();
                assert_eq!(pts[0].point, c.start());
                assert_eq!(pts[pts.len() - 1].point, c.end());
                let poly: Vec<Vector2> = pts.iter().map(|p| p.point).collect();
                let h = measured_hausdorff(&c, &poly, HausdorffSampling::default()).unwrap();
                assert!(h <= tol * (1.0 + 1e-9), "{method:?}: {h}");
                counts.push(pts.len() - 1);
            }
            assert!(counts[3] <= *counts.iter().min().unwrap(), "{counts:?}");
        }
    }

    /// The paper's rule has no guarantee: collinear control points satisfy eq. (3) at once
    /// (every distance to the chord line is 0), so the single chord P₀P₃ is returned although
    /// the curve runs far outside it. The numbers are the ones `docs/papers/bez-subdiv.md` quotes.
    #[test]
    fn paper_rule_fails_on_collinear_control_points() {
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(10.0, 0.0),
            Vector2::new(-9.0, 0.0),
            Vector2::new(1.0, 0.0),
        ])
        .unwrap();
        let tol = 1e-3;
        let paper = Flattener::new(tol).with_method(Method::PaperRule(SplitRule::Fixed));
        let poly: Vec<Vector2> = paper
            .flatten_to_vec(&c)
            .unwrap()
            .iter()
            .map(|p| p.point)
            .collect();
        assert_eq!(poly.len(), 2);
        let h = measured_hausdorff(&c, &poly, HausdorffSampling::default()).unwrap();
        // The curve leaves the chord's span [0, 1] by about 2.0: about 2,007 × tol.
        assert!(h / tol > 2_000.0 && h / tol < 2_015.0, "{}", h / tol);
        let fast = Flattener::new(tol).flatten_to_vec(&c).unwrap();
        let poly: Vec<Vector2> = fast.iter().map(|p| p.point).collect();
        assert!(measured_hausdorff(&c, &poly, HausdorffSampling::default()).unwrap() <= tol);
    }

    #[test]
    fn paper_rule_points_are_curve_points() {
        let c = &curves()[0];
        let f = Flattener::new(1e-3).with_method(Method::PaperRule(SplitRule::Fixed));
        for p in f.flatten_to_vec(c).unwrap() {
            assert!((p.point - c.eval(p.t).unwrap()).norm() < 1e-12);
        }
    }

    /// The paper's rule streams each piece's end point as the piece is found: the points are
    /// the end points of `flatten`'s pieces (computed independently, collected), and when a
    /// piece fails at the depth cap the points of the pieces before it have already been sent.
    #[cfg(feature = "paper")]
    #[test]
    fn paper_rule_streams_its_pieces() {
        use crate::flatten::flatten;
        let c = &curves()[0];
        for rule in [SplitRule::Fixed, SplitRule::flatness()] {
            let tol = 1e-3;
            let streamed = Flattener::new(tol)
                .with_method(Method::PaperRule(rule))
                .flatten_to_vec(c)
                .unwrap();
            let options = FlattenOptions::default()
                .with_tolerance(tol / curve_size(c))
                .with_rule(rule);
            let pieces = flatten(c, &options).unwrap().pieces;
            assert_eq!(streamed.len(), pieces.len() + 1);
            assert_eq!((streamed[0].t, streamed[0].point), (0.0, c.start()));
            for (p, piece) in streamed[1..].iter().zip(&pieces) {
                assert_eq!(
                    (p.t, p.point),
                    (piece.t1, piece.points[piece.points.len() - 1])
                );
            }
        }
        // Eight collinear control points, then a turn: nearly straight on [0, ½], a sharp corner
        // near t = 1. With a depth cap of 3 the left pieces are flat and sent before the corner
        // fails.
        let corner = BezierCurve::new(
            (0..8)
                .map(|i| Vector2::new(f64::from(i), 0.0))
                .chain([Vector2::new(7.0, 7.0)])
                .collect(),
        )
        .unwrap();
        let mut sent = Vec::new();
        let result = Flattener::new(1e-4)
            .with_method(Method::PaperRule(SplitRule::Fixed))
            .with_max_depth(3)
            .flatten(&corner, |p| sent.push(p.t));
        assert_eq!(result, Err(SubdivError::DepthLimit { limit: 3 }));
        assert!(sent.len() >= 2 && sent[0] == 0.0, "{sent:?}");
        assert!(sent.windows(2).all(|w| w[0] < w[1]));
    }

    /// A path's joints are sent once, with the index of the curve that ends there.
    #[test]
    fn paths_send_each_joint_once() {
        let cs = curves();
        let mut pts = Vec::new();
        let segments = Flattener::new(1e-3)
            .flatten_path(&cs, |p| pts.push(p))
            .unwrap();
        assert_eq!(pts.len(), segments + 1);
        let single: usize = cs
            .iter()
            .map(|c| Flattener::new(1e-3).flatten(c, |_| {}).unwrap())
            .sum();
        assert_eq!(segments, single);
        assert!(pts.windows(2).all(|w| w[0].point != w[1].point));
        assert_eq!(pts.last().unwrap().curve, 2);
    }

    #[test]
    fn batch_equals_one_by_one() {
        let cs = curves();
        for method in [Method::Fast, Method::Optimal] {
            let f = Flattener::new(1e-3).with_method(method);
            let batch = f.flatten_batch(&cs);
            for (c, r) in cs.iter().zip(batch) {
                assert_eq!(r, f.flatten_to_vec(c));
            }
        }
    }

    #[cfg(feature = "kurbo")]
    #[test]
    fn kurbo_paths_flatten_per_subpath() {
        let path =
            kurbo::BezPath::from_svg("M0 0 C1 2 3 -1 4 1 L 4 0 Z M 10 10 Q 11 12 12 10").unwrap();
        let mut by_subpath = [0usize; 2];
        Flattener::new(1e-3)
            .flatten_bez_path(&path, |s, _| by_subpath[s] += 1)
            .unwrap();
        assert!(by_subpath[0] > 3 && by_subpath[1] > 2, "{by_subpath:?}");
    }

    #[test]
    fn bad_input_is_an_error() {
        let c = &curves()[0];
        for tol in [0.0, -1.0, f64::NAN] {
            for method in [
                Method::Fast,
                Method::LocalWang,
                Method::Halving,
                Method::Optimal,
            ] {
                assert!(
                    Flattener::new(tol)
                        .with_method(method)
                        .flatten(c, |_| {})
                        .is_err()
                );
            }
        }
    }
}
