//! `Flattener`: one entry point for every flattening method, with an absolute tolerance, the
//! points streamed to a sink, and paths of several curves in one call.

use bez_core::{BezierForm, Vector2};

use crate::error::SubdivError;
use crate::flatten::{DEFAULT_MAX_DEPTH, FlattenOptions, curve_size, flatten};
use crate::guaranteed::{FlatPoint, flatten_guaranteed};
use crate::local_wang::flatten_local_wang;
use crate::near_optimal::flatten_near_optimal;
use crate::split_rule::SplitRule;
use crate::wang::flatten_wang;

/// How a [`Flattener`] places its points. Every method but [`Method::PaperRule`] guarantees
/// that the polyline is within the tolerance of the curve in Hausdorff distance.
///
/// | method | segments / N* (random cubics) | cost | use it for |
/// |---|---|---|---|
/// | [`Fast`](Method::Fast) | about 2 | fastest: no subdivision, a few flops per point | rendering, hit testing, anything per frame |
/// | [`LocalWang`](Method::LocalWang) | 1.6–2.0 | one halving per up to 16 points | high degrees |
/// | [`Halving`](Method::Halving) | about 1.7 | one de Casteljau halving per segment | fewer points than `Fast` at moderate cost |
/// | [`Optimal`](Method::Optimal) | 1.01–1.17 | exact deviation per segment, slowest | output that is stored or sent (fewest points) |
/// | [`PaperRule`](Method::PaperRule) | — | — | reproducing Ma, Lin & Shen's Table 1 only: **no guarantee** |
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub enum Method {
    /// Wang's uniform count ([`flatten_wang`]).
    #[default]
    Fast,
    /// Wang's bound piece by piece after halving ([`flatten_local_wang`]).
    LocalWang,
    /// Halving until every control point is within the tolerance of its chord segment
    /// ([`flatten_guaranteed`]).
    Halving,
    /// The greedy longest admissible steps ([`flatten_near_optimal`]).
    Optimal,
    /// The paper's rule: split with `SplitRule` until eq. (3) holds with ε = tolerance / size
    /// ([`flatten`](crate::flatten)), then the chords through the pieces' end points.
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
    /// The errors of the method's function ([`flatten_wang`], [`flatten_local_wang`],
    /// [`flatten_guaranteed`], [`flatten_near_optimal`], [`flatten`](crate::flatten)):
    /// an invalid tolerance, a degree-0 curve, a depth or segment limit.
    pub fn flatten<C: BezierForm<2> + ?Sized>(
        &self,
        curve: &C,
        mut sink: impl FnMut(FlatPoint),
    ) -> Result<usize, SubdivError> {
        let (tol, depth) = (self.tolerance, self.max_depth);
        let points = match self.method {
            Method::Fast => return flatten_wang(curve, tol, sink),
            Method::LocalWang => flatten_local_wang(curve, tol, depth)?,
            Method::Halving => flatten_guaranteed(curve, tol, depth)?,
            Method::Optimal => flatten_near_optimal(curve, tol, depth)?,
            Method::PaperRule(rule) => paper_rule_points(curve, tol, rule, depth)?,
        };
        let segments = points.len().saturating_sub(1);
        points.into_iter().for_each(&mut sink);
        Ok(segments)
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

/// The paper's pieces' end points (exact curve points with their parameters).
fn paper_rule_points<C: BezierForm<2> + ?Sized>(
    curve: &C,
    tolerance: f64,
    rule: SplitRule,
    max_depth: usize,
) -> Result<Vec<FlatPoint>, SubdivError> {
    let size = curve_size(curve.as_bezier());
    let eps = if size > 0.0 {
        tolerance / size
    } else {
        tolerance
    };
    let options = FlattenOptions::default()
        .with_tolerance(eps)
        .with_rule(rule)
        .with_max_depth(max_depth);
    let result = flatten(curve, &options)?;
    let mut out = Vec::with_capacity(result.pieces.len() + 1);
    for (k, piece) in result.pieces.iter().enumerate() {
        if k == 0 {
            out.push(FlatPoint {
                t: piece.t0,
                point: piece.points[0],
            });
        }
        out.push(FlatPoint {
            t: piece.t1,
            point: piece.points[piece.points.len() - 1],
        });
    }
    Ok(out)
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
