//! Conversions with kurbo (feature `kurbo`): points and vectors, the segment types and paths.
//!
//! - [`Vector2`] ↔ `kurbo::Point` and `kurbo::Vec2` (`From`, coordinates unchanged).
//! - `kurbo::Line`, `QuadBez`, `CubicBez` and `PathSeg` → [`BezierCurve<2>`] by `TryFrom`:
//!   a curve's control points must be finite, so NaN or infinite input is a
//!   [`CoreError::NonFinite`], never a panic.
//! - [`BezierCurve<2>`] (owned or borrowed) → `Line` / `QuadBez` / `CubicBez` by `TryFrom`, a
//!   [`CoreError::DegreeMismatch`] when the degree is not 1 / 2 / 3.
//! - `BezPath` ↔ curves: [`bez_path_to_curves`] and [`curves_to_bez_path`].

use kurbo::{BezPath, CubicBez, Line, PathEl, PathSeg, Point, QuadBez, Vec2};

use crate::curve::BezierCurve;
use crate::error::CoreError;
use crate::vector::Vector2;

impl From<Point> for Vector2 {
    #[inline]
    fn from(p: Point) -> Self {
        Self::new(p.x, p.y)
    }
}

impl From<Vector2> for Point {
    #[inline]
    fn from(v: Vector2) -> Self {
        Self::new(v.x(), v.y())
    }
}

impl From<Vec2> for Vector2 {
    #[inline]
    fn from(v: Vec2) -> Self {
        Self::new(v.x, v.y)
    }
}

impl From<Vector2> for Vec2 {
    #[inline]
    fn from(v: Vector2) -> Self {
        Self::new(v.x(), v.y())
    }
}

impl TryFrom<Line> for BezierCurve<2> {
    type Error = CoreError;

    /// The degree-1 curve from `p0` to `p1`.
    fn try_from(l: Line) -> Result<Self, CoreError> {
        Self::new(vec![l.p0.into(), l.p1.into()])
    }
}

impl TryFrom<QuadBez> for BezierCurve<2> {
    type Error = CoreError;

    /// The degree-2 curve with control points `p0, p1, p2`.
    fn try_from(q: QuadBez) -> Result<Self, CoreError> {
        Self::new(vec![q.p0.into(), q.p1.into(), q.p2.into()])
    }
}

impl TryFrom<CubicBez> for BezierCurve<2> {
    type Error = CoreError;

    /// The degree-3 curve with control points `p0, p1, p2, p3`.
    fn try_from(c: CubicBez) -> Result<Self, CoreError> {
        Self::new(vec![c.p0.into(), c.p1.into(), c.p2.into(), c.p3.into()])
    }
}

impl TryFrom<PathSeg> for BezierCurve<2> {
    type Error = CoreError;

    /// The curve of degree 1, 2 or 3 of a line, quadratic or cubic segment.
    fn try_from(seg: PathSeg) -> Result<Self, CoreError> {
        match seg {
            PathSeg::Line(l) => l.try_into(),
            PathSeg::Quad(q) => q.try_into(),
            PathSeg::Cubic(c) => c.try_into(),
        }
    }
}

/// The control points of `curve` as kurbo points, if its degree is `N − 1`.
fn points_of_degree<const N: usize>(curve: &BezierCurve<2>) -> Result<[Point; N], CoreError> {
    let pts = curve.points();
    if pts.len() == N {
        Ok(core::array::from_fn(|i| pts[i].into()))
    } else {
        Err(CoreError::DegreeMismatch {
            found: curve.degree(),
            wanted: N - 1,
        })
    }
}

impl TryFrom<&BezierCurve<2>> for Line {
    type Error = CoreError;

    /// The line of a degree-1 curve; [`CoreError::DegreeMismatch`] for any other degree.
    fn try_from(c: &BezierCurve<2>) -> Result<Self, CoreError> {
        let [p0, p1] = points_of_degree(c)?;
        Ok(Self::new(p0, p1))
    }
}

impl TryFrom<BezierCurve<2>> for Line {
    type Error = CoreError;

    /// As for `&BezierCurve<2>`.
    fn try_from(c: BezierCurve<2>) -> Result<Self, CoreError> {
        Self::try_from(&c)
    }
}

impl TryFrom<&BezierCurve<2>> for QuadBez {
    type Error = CoreError;

    /// The quadratic of a degree-2 curve; [`CoreError::DegreeMismatch`] for any other degree.
    fn try_from(c: &BezierCurve<2>) -> Result<Self, CoreError> {
        let [p0, p1, p2] = points_of_degree(c)?;
        Ok(Self::new(p0, p1, p2))
    }
}

impl TryFrom<BezierCurve<2>> for QuadBez {
    type Error = CoreError;

    /// As for `&BezierCurve<2>`.
    fn try_from(c: BezierCurve<2>) -> Result<Self, CoreError> {
        Self::try_from(&c)
    }
}

impl TryFrom<&BezierCurve<2>> for CubicBez {
    type Error = CoreError;

    /// The cubic of a degree-3 curve; [`CoreError::DegreeMismatch`] for any other degree.
    fn try_from(c: &BezierCurve<2>) -> Result<Self, CoreError> {
        let [p0, p1, p2, p3] = points_of_degree(c)?;
        Ok(Self::new(p0, p1, p2, p3))
    }
}

impl TryFrom<BezierCurve<2>> for CubicBez {
    type Error = CoreError;

    /// As for `&BezierCurve<2>`.
    fn try_from(c: BezierCurve<2>) -> Result<Self, CoreError> {
        Self::try_from(&c)
    }
}

/// Whether both coordinates of every point are finite.
/// Finite and within the coordinate contract ([`MAX_COORDINATE`](crate::MAX_COORDINATE)).
fn all_finite(points: &[Point]) -> bool {
    let ok = |x: f64| x.is_finite() && x.abs() <= crate::MAX_COORDINATE;
    points.iter().all(|p| ok(p.x) && ok(p.y))
}

/// The segments of a kurbo path as curves, one list per subpath.
///
/// Each `MoveTo` starts a new subpath; the curves of one subpath form a chain (each starts
/// exactly where the previous one ends). `LineTo`, `QuadTo` and `CurveTo` become curves of
/// degree 1, 2 and 3. `ClosePath` adds the closing line back to the subpath's start when the
/// current point is elsewhere (as kurbo's `segments()` does), then ends the subpath; a segment
/// drawn after it without a `MoveTo` starts a new subpath at the same start point (SVG rules).
/// Subpaths without any segment (a lone `MoveTo`) are left out, so
/// `curves_to_bez_path(&bez_path_to_curves(&path)?.concat())` draws the same segments as `path`
/// (closing lines explicit, subpaths that start where the previous one ended merged).
///
/// ```
/// use bez_core::{bez_path_to_curves, curves_to_bez_path};
/// use kurbo::BezPath;
///
/// let mut path = BezPath::new();
/// path.move_to((0.0, 0.0));
/// path.quad_to((1.0, 2.0), (2.0, 0.0));
/// path.close_path();
/// path.move_to((5.0, 5.0));
/// path.line_to((6.0, 5.0));
/// let subpaths = bez_path_to_curves(&path)?;
/// assert_eq!(subpaths.len(), 2);
/// assert_eq!(subpaths[0].len(), 2); // the quadratic and the closing line
/// assert_eq!(subpaths[0][1].degree(), 1);
/// let back = curves_to_bez_path(&subpaths.concat())?;
/// assert_eq!(back.elements().len(), 5); // MoveTo QuadTo LineTo MoveTo LineTo
/// # Ok::<(), bez_core::CoreError>(())
/// ```
///
/// # Errors
/// [`CoreError::NonFinitePathElement`] (with the element's index) for a NaN or infinite
/// coordinate; [`CoreError::PathWithoutStart`] if a segment or `ClosePath` comes before any
/// `MoveTo`.
pub fn bez_path_to_curves(path: &BezPath) -> Result<Vec<Vec<BezierCurve<2>>>, CoreError> {
    let mut subpaths: Vec<Vec<BezierCurve<2>>> = Vec::new();
    let mut current: Vec<BezierCurve<2>> = Vec::new();
    // (subpath start, current point), once a MoveTo has been seen.
    let mut state: Option<(Point, Point)> = None;
    for (index, el) in path.elements().iter().enumerate() {
        let (start, last) = match (*el, state) {
            (PathEl::MoveTo(p), _) => {
                if !all_finite(&[p]) {
                    return Err(CoreError::NonFinitePathElement { index });
                }
                if !current.is_empty() {
                    subpaths.push(core::mem::take(&mut current));
                }
                state = Some((p, p));
                continue;
            }
            (_, Some(s)) => s,
            (_, None) => return Err(CoreError::PathWithoutStart { index }),
        };
        let points: Vec<Point> = match *el {
            PathEl::LineTo(p1) => vec![last, p1],
            PathEl::QuadTo(p1, p2) => vec![last, p1, p2],
            PathEl::CurveTo(p1, p2, p3) => vec![last, p1, p2, p3],
            PathEl::ClosePath | PathEl::MoveTo(_) => {
                if last != start {
                    current.push(BezierCurve::from_valid(vec![last.into(), start.into()]));
                }
                if !current.is_empty() {
                    subpaths.push(core::mem::take(&mut current));
                }
                state = Some((start, start));
                continue;
            }
        };
        if !all_finite(&points) {
            return Err(CoreError::NonFinitePathElement { index });
        }
        let end = points[points.len() - 1];
        current.push(BezierCurve::from_valid(
            points.into_iter().map(Vector2::from).collect(),
        ));
        state = Some((start, end));
    }
    if !current.is_empty() {
        subpaths.push(current);
    }
    Ok(subpaths)
}

/// A kurbo path drawing `curves` in order.
///
/// The path starts with a `MoveTo` to the first curve's start; every curve whose start differs
/// (exactly) from the previous curve's end starts a new subpath with a `MoveTo`. Curves of
/// degree 1, 2 and 3 become `LineTo`, `QuadTo` and `CurveTo`. No `ClosePath` is emitted: a
/// closed chain simply ends at its start. An empty slice gives an empty path.
///
/// ```
/// use bez_core::{BezierCurve, Vector2, curves_to_bez_path};
/// use kurbo::PathEl;
///
/// let line = BezierCurve::new(vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0)])?;
/// let path = curves_to_bez_path(&[line])?;
/// assert_eq!(
///     path.elements(),
///     [PathEl::MoveTo((0.0, 0.0).into()), PathEl::LineTo((1.0, 0.0).into())]
/// );
/// # Ok::<(), bez_core::CoreError>(())
/// ```
///
/// # Errors
/// [`CoreError::DegreeTooLow`] for a degree-0 curve and [`CoreError::DegreeTooHigh`] for a
/// degree above 3 (kurbo paths hold lines, quadratics and cubics only).
pub fn curves_to_bez_path(curves: &[BezierCurve<2>]) -> Result<BezPath, CoreError> {
    let mut path = BezPath::new();
    let mut last: Option<Vector2> = None;
    for c in curves {
        let degree = c.degree();
        if degree == 0 {
            return Err(CoreError::DegreeTooLow { needed: 1, degree });
        }
        if degree > 3 {
            return Err(CoreError::DegreeTooHigh { max: 3, degree });
        }
        if last != Some(c.start()) {
            path.move_to(Point::from(c.start()));
        }
        let p: Vec<Point> = c.points().iter().map(|&v| v.into()).collect();
        match p[..] {
            [_, p1] => path.line_to(p1),
            [_, p1, p2] => path.quad_to(p1, p2),
            [_, p1, p2, p3] => path.curve_to(p1, p2, p3),
            _ => return Err(CoreError::DegreeTooHigh { max: 3, degree }),
        }
        last = Some(c.end());
    }
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vector2 {
        Vector2::new(x, y)
    }

    #[test]
    fn points_and_vectors_round_trip() {
        let a = v(1.5, -2.25);
        assert_eq!(Point::from(a), Point::new(1.5, -2.25));
        assert_eq!(Vec2::from(a), Vec2::new(1.5, -2.25));
        assert_eq!(Vector2::from(Point::new(1.5, -2.25)), a);
        assert_eq!(Vector2::from(Vec2::new(1.5, -2.25)), a);
    }

    #[test]
    fn segments_round_trip_and_evaluate_alike() {
        use kurbo::ParamCurve;
        let cubic = CubicBez::new((0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0));
        let curve = BezierCurve::try_from(cubic).unwrap();
        assert_eq!(curve.degree(), 3);
        assert_eq!(CubicBez::try_from(&curve).unwrap(), cubic);
        for k in 0..=8 {
            let t = k as f64 / 8.0;
            let (a, b) = (curve.eval(t).unwrap(), cubic.eval(t));
            assert!((a - Vector2::from(b)).norm() < 1e-14, "t = {t}");
        }
        let quad = QuadBez::new((0.0, 0.0), (1.0, 2.0), (2.0, 0.0));
        let qc = BezierCurve::try_from(quad).unwrap();
        assert_eq!(QuadBez::try_from(qc.clone()).unwrap(), quad);
        let line = Line::new((0.0, 1.0), (2.0, 3.0));
        let lc = BezierCurve::try_from(PathSeg::Line(line)).unwrap();
        assert_eq!(lc.points(), [v(0.0, 1.0), v(2.0, 3.0)]);
        assert_eq!(Line::try_from(lc).unwrap(), line);
        assert_eq!(BezierCurve::try_from(PathSeg::Quad(quad)).unwrap(), qc);
    }

    #[test]
    fn wrong_degree_and_non_finite_are_errors() {
        let quad = BezierCurve::new(vec![v(0.0, 0.0), v(1.0, 1.0), v(2.0, 0.0)]).unwrap();
        assert_eq!(
            CubicBez::try_from(&quad),
            Err(CoreError::DegreeMismatch {
                found: 2,
                wanted: 3
            })
        );
        assert_eq!(
            Line::try_from(&quad),
            Err(CoreError::DegreeMismatch {
                found: 2,
                wanted: 1
            })
        );
        assert!(QuadBez::try_from(quad).is_ok());
        let bad = Line::new((0.0, f64::NAN), (1.0, 1.0));
        assert_eq!(
            BezierCurve::try_from(bad),
            Err(CoreError::NonFinite { index: 0 })
        );
        let bad = CubicBez::new((0.0, 0.0), (1.0, 1.0), (f64::INFINITY, 0.0), (1.0, 1.0));
        assert_eq!(
            BezierCurve::try_from(bad),
            Err(CoreError::NonFinite { index: 2 })
        );
    }

    #[test]
    fn path_to_curves_splits_subpaths_and_closes() {
        let mut path = BezPath::new();
        path.move_to((0.0, 0.0));
        path.line_to((1.0, 0.0));
        path.curve_to((1.0, 1.0), (0.5, 1.5), (0.0, 1.0));
        path.close_path();
        path.line_to((-1.0, 0.0)); // after ClosePath: a new subpath from (0, 0)
        path.move_to((9.0, 9.0)); // lone MoveTo: no subpath
        path.move_to((5.0, 5.0));
        path.quad_to((6.0, 6.0), (7.0, 5.0));
        path.line_to((5.0, 5.0));
        path.close_path(); // already at the start: no closing line
        let subs = bez_path_to_curves(&path).unwrap();
        let degrees: Vec<Vec<usize>> = subs
            .iter()
            .map(|s| s.iter().map(BezierCurve::degree).collect())
            .collect();
        assert_eq!(degrees, [vec![1, 3, 1], vec![1], vec![2, 1]]);
        assert_eq!(subs[0][2].points(), [v(0.0, 1.0), v(0.0, 0.0)]);
        assert_eq!(subs[1][0].points(), [v(0.0, 0.0), v(-1.0, 0.0)]);
        for s in &subs {
            for w in s.windows(2) {
                assert_eq!(w[0].end(), w[1].start());
            }
        }
        // Same segments as kurbo's own iterator.
        let kurbo_segs: Vec<BezierCurve<2>> = path
            .segments()
            .map(|s| BezierCurve::try_from(s).unwrap())
            .collect();
        assert_eq!(subs.concat(), kurbo_segs);
        assert!(bez_path_to_curves(&BezPath::new()).unwrap().is_empty());
    }

    #[test]
    fn malformed_paths_are_errors() {
        let path = BezPath::from_vec(vec![
            PathEl::MoveTo((0.0, 0.0).into()),
            PathEl::LineTo((1.0, 0.0).into()),
            PathEl::QuadTo((1.0, f64::NAN).into(), (2.0, 0.0).into()),
        ]);
        assert_eq!(
            bez_path_to_curves(&path),
            Err(CoreError::NonFinitePathElement { index: 2 })
        );
        let path = BezPath::from_vec(vec![PathEl::MoveTo((f64::INFINITY, 0.0).into())]);
        assert_eq!(
            bez_path_to_curves(&path),
            Err(CoreError::NonFinitePathElement { index: 0 })
        );
        let mut path = BezPath::new();
        path.move_to((0.0, 0.0));
        let mut els = path.elements().to_vec();
        els.insert(0, PathEl::ClosePath);
        // kurbo only debug-asserts the leading MoveTo, so build the malformed path by hand.
        let mut bad = BezPath::new();
        for el in els {
            bad.extend([el]);
        }
        assert_eq!(
            bez_path_to_curves(&bad),
            Err(CoreError::PathWithoutStart { index: 0 })
        );
    }

    #[test]
    fn curves_to_path_round_trips() {
        let a = BezierCurve::new(vec![v(0.0, 0.0), v(1.0, 2.0), v(2.0, 0.0)]).unwrap();
        let b = BezierCurve::new(vec![v(2.0, 0.0), v(3.0, 0.0)]).unwrap();
        let c = BezierCurve::new(vec![v(5.0, 5.0), v(6.0, 6.0), v(7.0, 6.0), v(8.0, 5.0)]).unwrap();
        let path = curves_to_bez_path(&[a.clone(), b.clone(), c.clone()]).unwrap();
        assert_eq!(
            path.elements(),
            [
                PathEl::MoveTo((0.0, 0.0).into()),
                PathEl::QuadTo((1.0, 2.0).into(), (2.0, 0.0).into()),
                PathEl::LineTo((3.0, 0.0).into()),
                PathEl::MoveTo((5.0, 5.0).into()),
                PathEl::CurveTo((6.0, 6.0).into(), (7.0, 6.0).into(), (8.0, 5.0).into()),
            ]
        );
        let back = bez_path_to_curves(&path).unwrap();
        assert_eq!(back, [vec![a, b], vec![c]]);
        assert_eq!(curves_to_bez_path(&[]).unwrap().elements(), []);
        let point = BezierCurve::new(vec![v(0.0, 0.0)]).unwrap();
        assert_eq!(
            curves_to_bez_path(&[point]),
            Err(CoreError::DegreeTooLow {
                needed: 1,
                degree: 0
            })
        );
        let quartic = BezierCurve::new(vec![v(0.0, 0.0); 5]).unwrap();
        assert_eq!(
            curves_to_bez_path(&[quartic]),
            Err(CoreError::DegreeTooHigh { max: 3, degree: 4 })
        );
    }
}
