//! Planar Class A curves of several segments through knots with tangents (and curvatures).

use bez_core::{BezierCurve, BezierForm, Vector, Vector2};

use crate::{ClassACurve, ClassAError, Knot, hermite_planar};

/// A planar curve of several Class A segments: segment i runs from knot i to knot i + 1 with the
/// knots' tangent directions (G1 at every joint), and with their curvatures where both knots of
/// the segment prescribe one (G2 at a joint whose curvature is prescribed), each segment built
/// by [`hermite_planar`] at one degree, so each has proven monotone curvature.
///
/// The knots and the degree are the value; the segments are solved once, at construction, and
/// kept (private). Deserialization goes through [`ClassASpline::new`], so a deserialized spline
/// is solved and checked like a constructed one.
///
/// ```
/// use bez_core::Vector2;
/// use class_a::{ClassASpline, Knot};
/// let knots = vec![
///     Knot::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0)),
///     Knot::new(Vector2::new(2.0, 1.0), Vector2::new(0.2, 1.0)),
///     Knot::new(Vector2::new(1.0, 3.0), Vector2::new(-1.0, 0.3)),
/// ];
/// let spline = ClassASpline::new(knots, 6)?;
/// assert_eq!(spline.segments().len(), 2);
/// assert!((spline.eval(1.0)? - Vector2::new(2.0, 1.0)).norm() < 1e-12);
/// # Ok::<(), class_a::ClassAError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "SplineRepr", into = "SplineRepr")
)]
pub struct ClassASpline {
    knots: Vec<Knot>,
    degree: usize,
    segments: Vec<ClassACurve<2>>,
}

/// Serialized form of [`ClassASpline`]: knots and degree, solved again when read.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct SplineRepr {
    knots: Vec<Knot>,
    degree: usize,
}

#[cfg(feature = "serde")]
impl TryFrom<SplineRepr> for ClassASpline {
    type Error = ClassAError;
    fn try_from(r: SplineRepr) -> Result<Self, ClassAError> {
        Self::new(r.knots, r.degree)
    }
}

#[cfg(feature = "serde")]
impl From<ClassASpline> for SplineRepr {
    fn from(s: ClassASpline) -> Self {
        Self {
            knots: s.knots,
            degree: s.degree,
        }
    }
}

/// The most knots of a spline (checked before any segment is solved).
pub const MAX_KNOTS: usize = 4096;

impl ClassASpline {
    /// Solves the segments between consecutive knots at the given degree ([`hermite_planar`]).
    ///
    /// # Errors
    /// [`ClassAError::InvalidParameter`] for fewer than 2 or more than [`MAX_KNOTS`] knots;
    /// [`ClassAError::DegreeTooLow`] / [`ClassAError::DegreeTooHigh`]; the first segment that
    /// fails as [`ClassAError::Segment`] with its index and the error of [`hermite_planar`].
    pub fn new(knots: Vec<Knot>, degree: usize) -> Result<Self, ClassAError> {
        let segments = solve_segments(&knots, degree, 2, hermite_planar)?;
        Ok(Self {
            knots,
            degree,
            segments,
        })
    }

    /// G2 at every knot without choosing the curvatures: knots without a prescribed curvature
    /// get one from the G1 spline of the same knots, then every segment is solved with both end
    /// curvatures ([`hermite_planar`]). The chosen curvatures are kept in
    /// [`ClassASpline::knots`], so the result serializes as a spline with prescribed curvatures.
    ///
    /// At an end knot the choice is the G1 segment's own end curvature. At an interior knot the
    /// G1 segments meeting there have one-sided curvatures κ₋ (the left segment's end) and κ₊
    /// (the right one's start); three rules are tried in turn, each at every knot: the mean
    /// (κ₋ + κ₊)/2, then κ₋ (the left segment keeps its end curvature, the right one's start
    /// moves), then κ₊. The first rule under which every segment is solved, with proven monotone
    /// curvature, is returned. Which one works depends on the direction of the moves: moving a
    /// segment's end curvatures apart keeps its curvature monotone more often than moving them
    /// together (see the reach in the crate's docs).
    ///
    /// # Errors
    /// As [`ClassASpline::new`] for the G1 spline, then the error of the first rule (the mean)
    /// when no rule gives a spline; [`ClassAError::Segment`] with [`ClassAError::Singular`]
    /// inside when a G1 segment has a zero end leg.
    pub fn with_g2_joints(knots: Vec<Knot>, degree: usize) -> Result<Self, ClassAError> {
        let free: Vec<Knot> = knots
            .iter()
            .map(|k| Knot::new(k.point, k.tangent))
            .collect();
        let g1 = Self::new(free, degree)?;
        let ends = segment_ends(&g1.segments, |seg| {
            crate::end_curvatures(seg.as_bezier()).map(|(k0, k1)| [k0, k1])
        })?;
        with_joint_rules(
            &knots,
            &ends,
            |left, right, weight_left| weight_left * left + (1.0 - weight_left) * right,
            |k, estimate| {
                Knot::new(k.point, k.tangent).with_curvature(k.curvature.unwrap_or(estimate))
            },
            |chosen| Self::new(chosen, degree),
        )
    }

    /// The knots.
    #[must_use]
    pub fn knots(&self) -> &[Knot] {
        &self.knots
    }

    /// The degree of every segment.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The segments, segment i from knot i to knot i + 1.
    #[must_use]
    pub fn segments(&self) -> &[ClassACurve<2>] {
        &self.segments
    }

    /// The point at u ∈ [0, m] for m segments: segment ⌊u⌋ (the last one at u = m) at its
    /// parameter u − ⌊u⌋.
    ///
    /// # Errors
    /// [`ClassAError::InvalidParameter`] for u outside [0, m] or NaN.
    pub fn eval(&self, u: f64) -> Result<Vector2, ClassAError> {
        eval_segments(&self.segments, u)
    }

    /// The segments' Bézier forms, in order (for flattening, export or bez-core's kurbo
    /// conversion `curves_to_bez_path`).
    #[must_use]
    pub fn to_bezier_segments(&self) -> Vec<BezierCurve<2>> {
        self.segments
            .iter()
            .map(|s| s.as_bezier().clone())
            .collect()
    }
}

/// The one-sided values `at` (start, end) of every segment, a failure as
/// [`ClassAError::Segment`] with its index.
pub(crate) fn segment_ends<const D: usize, V>(
    segments: &[ClassACurve<D>],
    at: impl Fn(&ClassACurve<D>) -> Result<[V; 2], ClassAError>,
) -> Result<Vec<[V; 2]>, ClassAError> {
    segments
        .iter()
        .enumerate()
        .map(|(index, seg)| {
            at(seg).map_err(|e| ClassAError::Segment {
                index,
                source: Box::new(e),
            })
        })
        .collect()
}

/// The rules of `with_g2_joints` (planar and spatial): with `ends[i]` the one-sided values of
/// G1 segment i, each knot gets, where not prescribed (`build` keeps a prescribed value), its
/// only one-sided value at an end of the spline and `mix(left, right, weight_left)` inside;
/// the weights 1/2 (the mean), 1 (the left value) and 0 (the right one) are tried in turn, each
/// at every knot, and the first spline that `solve` accepts is returned, else the mean's error.
pub(crate) fn with_joint_rules<K: Clone, V: Copy, S>(
    knots: &[K],
    ends: &[[V; 2]],
    mix: impl Fn(V, V, f64) -> V,
    build: impl Fn(&K, V) -> K,
    solve: impl Fn(Vec<K>) -> Result<S, ClassAError>,
) -> Result<S, ClassAError> {
    let choose = |weight_left: f64| -> Vec<K> {
        knots
            .iter()
            .enumerate()
            .map(|(i, k)| {
                let left = i.checked_sub(1).map(|j| ends[j][1]);
                let right = ends.get(i).map(|e| e[0]);
                // Every knot ends or starts at least one segment (a knot with neither, which
                // `solve` refuses anyway, would be kept as given).
                left.zip(right)
                    .map(|(l, r)| mix(l, r, weight_left))
                    .or(left)
                    .or(right)
                    .map_or_else(|| k.clone(), |value| build(k, value))
            })
            .collect()
    };
    let first = solve(choose(0.5));
    if first.is_ok() {
        return first;
    }
    [1.0, 0.0]
        .into_iter()
        .find_map(|weight| solve(choose(weight)).ok())
        .map_or(first, Ok)
}

/// The segments of a spline through `knots`, segment i solved from knots i and i + 1 by
/// `solve` at `degree`, after the knot count (2..=[`MAX_KNOTS`]) and the degree (from
/// `min_degree`) are checked; the first failing segment as [`ClassAError::Segment`].
pub(crate) fn solve_segments<K, const D: usize>(
    knots: &[K],
    degree: usize,
    min_degree: usize,
    solve: impl Fn(&K, &K, usize) -> Result<ClassACurve<D>, ClassAError>,
) -> Result<Vec<ClassACurve<D>>, ClassAError> {
    if knots.len() < 2 || knots.len() > MAX_KNOTS {
        return Err(ClassAError::InvalidParameter {
            name: "number of knots",
            value: knots.len() as f64,
            expected: "2..=4096 (MAX_KNOTS)",
        });
    }
    crate::error::check_degree(degree, min_degree)?;
    knots
        .windows(2)
        .enumerate()
        .map(|(index, w)| {
            solve(&w[0], &w[1], degree).map_err(|e| ClassAError::Segment {
                index,
                source: Box::new(e),
            })
        })
        .collect()
}

/// The point at u ∈ [0, m] of a spline of m `segments`: segment ⌊u⌋ (the last one at u = m)
/// at its parameter u − ⌊u⌋.
pub(crate) fn eval_segments<const D: usize>(
    segments: &[ClassACurve<D>],
    u: f64,
) -> Result<Vector<D>, ClassAError> {
    let m = segments.len();
    if m == 0 || !(0.0..=m as f64).contains(&u) {
        return Err(ClassAError::InvalidParameter {
            name: "u",
            value: u,
            expected: "in [0, number of segments]",
        });
    }
    let index = (u.floor() as usize).min(m - 1);
    let t = (u - index as f64).clamp(0.0, 1.0);
    Ok(segments[index].as_bezier().eval(t)?)
}
