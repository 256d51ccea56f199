//! The kind of a control-polygon vertex: how the limit curve behaves there.

/// How the limit curve behaves at a vertex of the control polygon (Sec. 2.1 and beyond).
///
/// ```
/// use subdiv_fit::{Closure, SubdivCurve, Vector2, VertexKind};
///
/// let points = vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 1.0), Vector2::new(2.0, 0.0)];
/// let curve = SubdivCurve::with_sharp(points, &[1], Closure::Closed)?;
/// assert_eq!(curve.kinds(), [VertexKind::Regular, VertexKind::Sharp, VertexKind::Regular]);
/// assert!(curve.is_sharp(1));
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum VertexKind {
    /// A regular vertex: the curve is C2 there, its refinement rule is
    /// `(p_{i-1} + 6 p_i + p_{i+1}) / 8` and its limit `(p_{i-1} + 4 p_i + p_{i+1}) / 6`.
    #[default]
    Regular,
    /// A sharp vertex (a corner): kept by refinement and interpolated by the limit curve, whose
    /// one-sided tangents there are the polygon edges.
    Sharp,
    /// A tangent vertex: its knot is doubled with the next vertex's (the cubic B-spline with a
    /// double knot), so the curve is C1 there in its parameter, with its tangent along the edge
    /// `p_{i+1} − p_i`, and its curvature is free on each side (it may jump, as where a line
    /// meets an arc tangentially). The curve passes through the edge's midpoint
    /// `(p_i + p_{i+1}) / 2`, not through `p_i`, and that edge has no segment of its own.
    /// Refinement next to it inserts knots (Boehm); evaluation is exact (de Boor), and so is the
    /// Bézier form. Sharp vertices must stay three vertices away (see [`crate::SubdivCurve::new`]).
    Tangent,
    /// A sharp vertex whose sides keep their curvature: interpolated like [`VertexKind::Sharp`],
    /// with the one-sided tangents free of the polygon edges, and the first segment on each side
    /// that has a regular vertex a parabola (the parabolic end condition instead of the phantom
    /// point's zero curvature; see the crate docs). Where a side has no regular vertex before the
    /// next sharp vertex, that edge is the straight segment, as for [`VertexKind::Sharp`]. Not
    /// allowed in a polygon with [`VertexKind::Tangent`] vertices.
    SharpCurved,
}

impl VertexKind {
    /// `true` for the corners, [`VertexKind::Sharp`] and [`VertexKind::SharpCurved`].
    #[must_use]
    pub fn is_sharp(self) -> bool {
        matches!(self, Self::Sharp | Self::SharpCurved)
    }
}
