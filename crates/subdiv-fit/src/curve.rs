//! Cubic B-spline subdivision curves with sharp vertices (Sec. 2.1) and their exact
//! evaluation (Sec. 2.2).

use bez_core::{BezierCurve, MAX_COORDINATE, Vector};

use crate::SubdivFitError;
use crate::bspline::{
    bezier_to_bspline, bspline_basis, bspline_basis_d1, bspline_basis_d2, bspline_to_bezier,
};
use crate::curved_corner::{self, neighbour_control, span_end};

use crate::tangent;
use crate::vertex::VertexKind;

/// A control polygon, open or closed, with one [`VertexKind`] per vertex.
///
/// Its limit curve under the rules of Sec. 2.1 has one segment per polygon edge:
/// segment `i` runs from the limit position of `p_i` to that of `p_{i+1}`
/// (indices modulo `n` for a closed polygon), except that the edge after a
/// [`VertexKind::Tangent`] vertex has no segment (its knot is double; segments are then numbered
/// along the curve, skipping those edges).
/// Both end vertices of an open polygon are sharp, whatever kind is given.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "CurveRepr<D>", into = "CurveRepr<D>")
)]
pub struct SubdivCurve<const D: usize> {
    points: Vec<Vector<D>>,
    kinds: Vec<VertexKind>,
    closure: Closure,
    /// The tangent vertices, increasing (derived from `kinds`).
    tangents: Vec<usize>,
    /// Whether a vertex is [`VertexKind::SharpCurved`] (derived from `kinds`).
    curved: bool,
}

/// Whether a control polygon (and its limit curve) is open or closed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Closure {
    /// An open polygon: its limit curve starts at the first vertex and ends at the last, both
    /// sharp.
    Open,
    /// A closed polygon: the last vertex connects back to the first.
    Closed,
}

impl Closure {
    /// `true` for [`Closure::Closed`].
    #[must_use]
    pub fn is_closed(self) -> bool {
        self == Self::Closed
    }

    /// [`Closure::Closed`] when `closed`, else [`Closure::Open`]: for a flag read from data.
    #[must_use]
    pub fn from_closed(closed: bool) -> Self {
        if closed { Self::Closed } else { Self::Open }
    }
}

/// Serialized form of [`SubdivCurve`]: validated again by [`SubdivCurve::new`] on
/// deserialization.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct CurveRepr<const D: usize> {
    points: Vec<Vector<D>>,
    kinds: Vec<VertexKind>,
    closed: bool,
}

#[cfg(feature = "serde")]
impl<const D: usize> TryFrom<CurveRepr<D>> for SubdivCurve<D> {
    type Error = SubdivFitError;
    fn try_from(r: CurveRepr<D>) -> Result<Self, SubdivFitError> {
        Self::new(r.points, r.kinds, Closure::from_closed(r.closed))
    }
}

#[cfg(feature = "serde")]
impl<const D: usize> From<SubdivCurve<D>> for CurveRepr<D> {
    fn from(c: SubdivCurve<D>) -> Self {
        Self {
            points: c.points,
            kinds: c.kinds,
            closed: c.closure.is_closed(),
        }
    }
}

/// Position and derivatives of the limit curve at one parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct CurvePoint<const D: usize> {
    /// Position C.
    pub position: Vector<D>,
    /// First derivative C' with respect to the parameter.
    pub first: Vector<D>,
    /// Second derivative C'' with respect to the parameter.
    pub second: Vector<D>,
}

impl<const D: usize> SubdivCurve<D> {
    /// Builds a curve from its control polygon and the kind of every vertex.
    ///
    /// An open polygon needs at least 2 vertices, a closed one at least 3.
    /// The end vertices of an open polygon are made sharp ([`VertexKind::Sharp`] unless given as
    /// [`VertexKind::SharpCurved`]).
    /// A [`VertexKind::Tangent`] vertex needs room for its double knot: no sharp vertex from two
    /// before it to three after it, no tangent neighbour, at least 6 vertices in a closed polygon
    /// and 3 before it and 4 after it in an open one.
    ///
    /// # Errors
    /// [`SubdivFitError::TooFewPoints`], [`SubdivFitError::NonFinite`],
    /// [`SubdivFitError::FlagCount`], [`SubdivFitError::InvalidTangent`];
    /// [`SubdivFitError::Core`] with
    /// [`CoordinateOutOfRange`](bez_core::CoreError::CoordinateOutOfRange) for a coordinate beyond
    /// ±`MAX_COORDINATE`.
    pub fn new(
        points: Vec<Vector<D>>,
        mut kinds: Vec<VertexKind>,
        closure: Closure,
    ) -> Result<Self, SubdivFitError> {
        let closed = closure.is_closed();
        let needed = if closed { 3 } else { 2 };
        if points.len() < needed {
            return Err(SubdivFitError::TooFewPoints {
                got: points.len(),
                needed,
            });
        }
        if kinds.len() != points.len() {
            return Err(SubdivFitError::FlagCount {
                flags: kinds.len(),
                points: points.len(),
            });
        }
        check_points(&points, MAX_COORDINATE)?;
        if !closed {
            let last = kinds.len() - 1;
            for end in [0, last] {
                if !kinds[end].is_sharp() {
                    kinds[end] = VertexKind::Sharp;
                }
            }
        }
        let tangents = tangent::check_tangents(&kinds, closed)?;
        let curved = kinds.contains(&VertexKind::SharpCurved);
        if curved && let Some(&index) = tangents.first() {
            return Err(SubdivFitError::InvalidTangent {
                index,
                reason: "tangent vertices and curved sharp vertices cannot share a polygon",
            });
        }
        Ok(Self {
            points,
            kinds,
            closure,
            tangents,
            curved,
        })
    }

    /// A curve with every interior vertex regular (a uniform cubic B-spline, with sharp ends if open).
    ///
    /// # Errors
    /// As [`SubdivCurve::new`].
    pub fn smooth(points: Vec<Vector<D>>, closure: Closure) -> Result<Self, SubdivFitError> {
        let n = points.len();
        Self::new(points, vec![VertexKind::Regular; n], closure)
    }

    /// A curve whose vertices at the indices `sharp` are sharp and all others regular.
    ///
    /// # Errors
    /// [`SubdivFitError::SegmentOutOfRange`] for an index that is not a vertex; otherwise as
    /// [`SubdivCurve::new`].
    pub fn with_sharp(
        points: Vec<Vector<D>>,
        sharp: &[usize],
        closure: Closure,
    ) -> Result<Self, SubdivFitError> {
        let n = points.len();
        let mut kinds = vec![VertexKind::Regular; n];
        for &i in sharp {
            *kinds
                .get_mut(i)
                .ok_or(SubdivFitError::SegmentOutOfRange { index: i, count: n })? =
                VertexKind::Sharp;
        }
        Self::new(points, kinds, closure)
    }

    /// The control points.
    #[must_use]
    pub fn points(&self) -> &[Vector<D>] {
        &self.points
    }

    /// The vertex kinds, one per control point.
    #[must_use]
    pub fn kinds(&self) -> &[VertexKind] {
        &self.kinds
    }

    /// Whether vertex `i` is sharp (`false` when `i` is not a vertex).
    #[must_use]
    pub fn is_sharp(&self, i: usize) -> bool {
        self.kinds.get(i).is_some_and(|k| k.is_sharp())
    }

    /// Whether the polygon is open or closed.
    #[must_use]
    pub fn closure(&self) -> Closure {
        self.closure
    }

    /// Whether the polygon is closed.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.closure.is_closed()
    }

    /// Number of limit-curve segments: `n` if closed, `n - 1` if open, less one per tangent
    /// vertex.
    #[must_use]
    pub fn segment_count(&self) -> usize {
        self.edge_count() - self.tangents.len()
    }

    /// Number of polygon edges: `n` if closed, `n - 1` if open.
    fn edge_count(&self) -> usize {
        if self.closure.is_closed() {
            self.points.len()
        } else {
            self.points.len() - 1
        }
    }

    /// One level of the refinement of Sec. 2.1:
    /// E-vertex `(p_i + p_{i+1}) / 2`, regular V-vertex `(p_{i-1} + 6 p_i + p_{i+1}) / 8`,
    /// sharp V-vertex `p_i`; next to a curved sharp vertex the derived point `e₀` of its span
    /// end takes the vertex's place in these rules.
    /// V-vertices keep their kind; E-vertices are regular.
    /// Next to a tangent vertex the rules are those of knot insertion at the middle of every
    /// segment (the double knot stays double and the edge after it gets no E-vertex).
    #[must_use]
    pub fn refine(&self) -> Self {
        if !self.tangents.is_empty() {
            let (points, kinds) = tangent::refine_with_tangents(self);
            let tangents = (0..kinds.len())
                .filter(|&i| kinds[i] == VertexKind::Tangent)
                .collect();
            return Self {
                points,
                kinds,
                closure: self.closure,
                tangents,
                curved: false,
            };
        }
        let n = self.points.len();
        let edges = self.edge_count();
        let mut points = Vec::with_capacity(n + edges);
        let mut kinds = Vec::with_capacity(n + edges);
        for i in 0..n {
            // The segment's control points as vertex i sees them: its neighbours, or at a curved
            // sharp vertex the derived point e₀ in its place (module `curved_corner`).
            let v = if self.kinds[i].is_sharp() {
                self.points[i]
            } else {
                // A regular vertex has both neighbours and the edge after it (an open polygon's
                // ends are sharp).
                let [a, b, c, _] = self.uniform_controls(i);
                (a + 6.0 * b + c) / 8.0
            };
            points.push(v);
            kinds.push(self.kinds[i]);
            if i < edges {
                let [_, b, c, _] = self.uniform_controls(i);
                points.push((b + c) * 0.5);
                kinds.push(VertexKind::Regular);
            }
        }
        Self {
            points,
            kinds,
            closure: self.closure,
            tangents: Vec::new(),
            curved: self.curved,
        }
    }

    /// `levels` levels of refinement.
    ///
    /// # Errors
    /// [`SubdivFitError::TooLarge`] when the refined polygon would have more than
    /// [`MAX_FIT_POINTS`](crate::MAX_FIT_POINTS) vertices (checked before any refinement: each
    /// level doubles the edges).
    pub fn refine_levels(&self, levels: usize) -> Result<Self, SubdivFitError> {
        let max = crate::MAX_FIT_POINTS;
        let edges = self.segment_count();
        let open_end = usize::from(!self.is_closed()) + self.tangents.len();
        let fits = u32::try_from(levels)
            .ok()
            .and_then(|l| edges.checked_mul(1usize.checked_shl(l)?))
            .and_then(|e| e.checked_add(open_end))
            .filter(|&count| count <= max);
        if fits.is_none() {
            return Err(SubdivFitError::TooLarge {
                name: "refined vertices",
                requested: edges.saturating_mul(
                    1usize
                        .checked_shl(u32::try_from(levels).unwrap_or(u32::MAX))
                        .unwrap_or(usize::MAX),
                ),
                max,
            });
        }
        let mut c = self.clone();
        for _ in 0..levels {
            c = c.refine();
        }
        Ok(c)
    }

    /// The limit position of vertex `i` (the limit mask):
    /// `(p_{i-1} + 4 p_i + p_{i+1}) / 6` for a regular vertex, `p_i` for a sharp one; next to a
    /// double knot the curve at the vertex's knot (a tangent vertex and the vertex after it share
    /// the joint, `(p_v + p_{v+1}) / 2`).
    ///
    /// # Errors
    /// [`SubdivFitError::SegmentOutOfRange`] if `i` is not a vertex.
    pub fn limit_position(&self, i: usize) -> Result<Vector<D>, SubdivFitError> {
        let n = self.points.len();
        if i >= n {
            return Err(SubdivFitError::SegmentOutOfRange { index: i, count: n });
        }
        if !self.tangents.is_empty()
            && let Some(p) = tangent::vertex_limit(self, i)
        {
            return Ok(p);
        }
        Ok(if self.kinds[i].is_sharp() {
            self.points[i]
        } else if self.curved {
            // A regular vertex has the edge after it (an open polygon's ends are sharp).
            let [a, b, c, _] = self.uniform_controls(i);
            (a + 4.0 * b + c) / 6.0
        } else {
            (self.points[(i + n - 1) % n] + 4.0 * self.points[i] + self.points[(i + 1) % n]) / 6.0
        })
    }

    /// The limit curve's one-sided derivatives at the sharp vertex `i`: `C′` of the segment that
    /// arrives there and of the one that leaves (`None` for a side beyond an open polygon's end).
    /// At a [`VertexKind::Sharp`] vertex they are the polygon edges `p_i − p_{i−1}` and
    /// `p_{i+1} − p_i`; at a [`VertexKind::SharpCurved`] one `(9 p_i + 2 p_{i∓2} − 11 p_{i∓1}) / 7`
    /// and `(11 p_{i+1} − 2 p_{i+2} − 9 p_i) / 7` where the side is parabolic (module docs of
    /// the crate). `None` when `i` is not a sharp vertex.
    ///
    /// ```
    /// use subdiv_fit::{Closure, SubdivCurve, Vector2, VertexKind};
    ///
    /// let square = vec![
    ///     Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0),
    ///     Vector2::new(1.0, 1.0), Vector2::new(0.0, 1.0),
    /// ];
    /// let curve = SubdivCurve::with_sharp(square, &[0], Closure::Closed)?;
    /// let (incoming, outgoing) = curve.corner_tangents(0).unwrap();
    /// assert_eq!(incoming, Some(Vector2::new(0.0, -1.0)));
    /// assert_eq!(outgoing, Some(Vector2::new(1.0, 0.0)));
    /// # Ok::<(), subdiv_fit::SubdivFitError>(())
    /// ```
    #[must_use]
    pub fn corner_tangents(&self, i: usize) -> Option<(Option<Vector<D>>, Option<Vector<D>>)> {
        if !self.is_sharp(i) {
            return None;
        }
        let n = self.points.len();
        let closed = self.is_closed();
        let side = |forwards| {
            let exists = closed || if forwards { i + 1 < n } else { i > 0 };
            exists.then(|| {
                curved_corner::side_tangent(&self.kinds, &self.points, closed, i, forwards)
            })
        };
        Some((side(false).map(|t| -t), side(true)))
    }

    /// The four uniform cubic B-spline control points of segment `i`.
    ///
    /// This is the collapsed closed form of Sec. 2.2 (see the crate docs for the derivation):
    /// `(a, p_i, p_{i+1}, d)` with `a = p_{i-1}` if `p_i` is regular, else the phantom point
    /// `2 p_i − p_{i+1}`; and `d = p_{i+2}` if `p_{i+1}` is regular, else `2 p_{i+1} − p_i`.
    /// Next to a [`VertexKind::SharpCurved`] vertex the corner's side takes the parabolic end
    /// condition instead: `p_i` and the phantom point are replaced by the derived points of that
    /// span end (module `curved_corner`), and so is a sharp `p_{i−1}`'s contribution.
    /// With two sharp ends the four points are equally spaced on a line and the segment is the
    /// line `(1 − u) p_i + u p_{i+1}` of eq. (2); with two regular ends it is eq. (1).
    /// A segment whose knots include the double knot of a tangent vertex is a cubic of the
    /// non-uniform B-spline; its four points are then the unique uniform B-spline form of that
    /// cubic (from its Bézier points, see [`SubdivCurve::segment_bezier`]).
    ///
    /// # Errors
    /// [`SubdivFitError::SegmentOutOfRange`].
    pub fn segment_controls(&self, i: usize) -> Result<[Vector<D>; 4], SubdivFitError> {
        let count = self.segment_count();
        if i >= count {
            return Err(SubdivFitError::SegmentOutOfRange { index: i, count });
        }
        if self.tangents.is_empty() {
            return Ok(self.uniform_controls(i));
        }
        let e = tangent::edge_of_segment(&self.tangents, i);
        Ok(if tangent::span_is_uniform(self, e) {
            self.uniform_controls(e)
        } else {
            bezier_to_bspline(&tangent::span_bezier_points(self, e))
        })
    }

    /// The closed form on edge `i` with uniform knots around it.
    fn uniform_controls(&self, i: usize) -> [Vector<D>; 4] {
        if self.curved {
            return self.curved_controls(i);
        }
        let n = self.points.len();
        let j = (i + 1) % n;
        let (b, c) = (self.points[i], self.points[j]);
        let a = if self.kinds[i].is_sharp() {
            2.0 * b - c
        } else {
            self.points[(i + n - 1) % n]
        };
        let d = if self.kinds[j].is_sharp() {
            2.0 * c - b
        } else {
            self.points[(j + 1) % n]
        };
        [a, b, c, d]
    }

    /// [`SubdivCurve::uniform_controls`] with curved sharp vertices: each sharp end replaced by
    /// its span end's derived control and phantom points, a sharp vertex one further by its
    /// derived control point.
    fn curved_controls(&self, i: usize) -> [Vector<D>; 4] {
        let n = self.points.len();
        let closed = self.is_closed();
        let j = (i + 1) % n;
        let at = |w| curved_corner::point(&w, &self.points);
        let (a, b) = if self.kinds[i].is_sharp() {
            let end = span_end(&self.kinds, closed, i, true);
            (at(end.phantom), at(end.control))
        } else {
            let prev = (i + n - 1) % n;
            (
                at(neighbour_control(&self.kinds, closed, prev, true)),
                self.points[i],
            )
        };
        let (c, d) = if self.kinds[j].is_sharp() {
            let end = span_end(&self.kinds, closed, j, false);
            (at(end.control), at(end.phantom))
        } else {
            let next = (j + 1) % n;
            (
                self.points[j],
                at(neighbour_control(&self.kinds, closed, next, false)),
            )
        };
        [a, b, c, d]
    }

    /// Position of segment `i` at its local parameter `u ∈ [0, 1]`.
    ///
    /// # Errors
    /// [`SubdivFitError::SegmentOutOfRange`], [`SubdivFitError::ParameterOutOfRange`].
    pub fn eval_segment(&self, i: usize, u: f64) -> Result<Vector<D>, SubdivFitError> {
        let ctrl = self.segment_controls(i)?;
        check_unit(u)?;
        Ok(combine(&ctrl, bspline_basis(u)))
    }

    /// Position, first and second derivative of segment `i` at `u ∈ [0, 1]`
    /// (derivatives with respect to the local parameter).
    ///
    /// # Errors
    /// As [`SubdivCurve::eval_segment`].
    pub fn eval_segment_derivatives(
        &self,
        i: usize,
        u: f64,
    ) -> Result<CurvePoint<D>, SubdivFitError> {
        let ctrl = self.segment_controls(i)?;
        check_unit(u)?;
        Ok(CurvePoint {
            position: combine(&ctrl, bspline_basis(u)),
            first: combine(&ctrl, bspline_basis_d1(u)),
            second: combine(&ctrl, bspline_basis_d2(u)),
        })
    }

    /// Maps the global parameter `s ∈ [0, segment_count]` to (segment, local parameter).
    /// Integer values of `s` other than the end belong to the segment that starts there.
    ///
    /// # Errors
    /// [`SubdivFitError::ParameterOutOfRange`].
    pub fn locate(&self, s: f64) -> Result<(usize, f64), SubdivFitError> {
        let count = self.segment_count();
        let max = count as f64;
        if !(0.0..=max).contains(&s) {
            return Err(SubdivFitError::ParameterOutOfRange {
                name: "s",
                value: s,
                min: 0.0,
                max,
            });
        }
        let i = (s.floor() as usize).min(count - 1);
        Ok((i, s - i as f64))
    }

    /// Position at the global parameter `s ∈ [0, segment_count]`: vertex `i`'s limit is at `s = i`
    /// (with tangent vertices at its knot `k_i`, which does not advance after a tangent vertex).
    ///
    /// # Errors
    /// [`SubdivFitError::ParameterOutOfRange`].
    pub fn eval(&self, s: f64) -> Result<Vector<D>, SubdivFitError> {
        let (i, u) = self.locate(s)?;
        self.eval_segment(i, u)
    }

    /// Position and derivatives at the global parameter (one unit of `s` per segment,
    /// so the derivatives equal the local ones).
    ///
    /// # Errors
    /// [`SubdivFitError::ParameterOutOfRange`].
    pub fn eval_derivatives(&self, s: f64) -> Result<CurvePoint<D>, SubdivFitError> {
        let (i, u) = self.locate(s)?;
        self.eval_segment_derivatives(i, u)
    }

    /// Evaluates at many global parameters, appending to `out` (cleared first).
    ///
    /// # Errors
    /// [`SubdivFitError::ParameterOutOfRange`] for the first bad parameter.
    pub fn eval_many(
        &self,
        params: &[f64],
        out: &mut Vec<Vector<D>>,
    ) -> Result<(), SubdivFitError> {
        out.clear();
        out.reserve(params.len());
        let mut cached: Option<(usize, [Vector<D>; 4])> = None;
        for &s in params {
            let (i, u) = self.locate(s)?;
            let ctrl = match cached {
                Some((j, c)) if j == i => c,
                _ => {
                    let c = self.segment_controls(i)?;
                    cached = Some((i, c));
                    c
                }
            };
            out.push(combine(&ctrl, bspline_basis(u)));
        }
        Ok(())
    }

    /// Segment `i` as an exact cubic Bézier curve (next to a tangent vertex: the non-uniform
    /// segment with its knots inserted to full multiplicity).
    ///
    /// # Errors
    /// [`SubdivFitError::SegmentOutOfRange`].
    pub fn segment_bezier(&self, i: usize) -> Result<BezierCurve<D>, SubdivFitError> {
        let ctrl = self.segment_controls(i)?;
        Ok(BezierCurve::new(bspline_to_bezier(&ctrl).to_vec())?)
    }

    /// Every segment as an exact cubic Bézier curve, in order.
    ///
    /// # Errors
    /// Only on non-finite intermediate values (impossible for a validated polygon of moderate size).
    pub fn to_beziers(&self) -> Result<Vec<BezierCurve<D>>, SubdivFitError> {
        (0..self.segment_count())
            .map(|i| self.segment_bezier(i))
            .collect()
    }
}

/// Every coordinate finite ([`SubdivFitError::NonFinite`]) and within ±`max`
/// (bez-core's [`CoordinateOutOfRange`](bez_core::CoreError::CoordinateOutOfRange)).
pub(crate) fn check_points<const D: usize>(
    points: &[Vector<D>],
    max: f64,
) -> Result<(), SubdivFitError> {
    for (index, p) in points.iter().enumerate() {
        for &value in p.iter() {
            if !value.is_finite() {
                return Err(SubdivFitError::NonFinite { index });
            }
            if value.abs() > max {
                return Err(bez_core::CoreError::CoordinateOutOfRange { index, value, max }.into());
            }
        }
    }
    Ok(())
}

fn check_unit(u: f64) -> Result<(), SubdivFitError> {
    if (0.0..=1.0).contains(&u) {
        Ok(())
    } else {
        Err(SubdivFitError::ParameterOutOfRange {
            name: "u",
            value: u,
            min: 0.0,
            max: 1.0,
        })
    }
}

pub(crate) fn combine<const D: usize>(ctrl: &[Vector<D>; 4], w: [f64; 4]) -> Vector<D> {
    ctrl[0] * w[0] + ctrl[1] * w[1] + ctrl[2] * w[2] + ctrl[3] * w[3]
}
