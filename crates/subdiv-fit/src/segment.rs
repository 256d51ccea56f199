//! One segment of a subdivision curve as a value with its exact cubic Bézier form.

use bez_core::{BezierCurve, BezierForm, Vector};

use crate::SubdivFitError;
use crate::curve::SubdivCurve;

/// Segment `i` of a [`SubdivCurve`]: the piece from the limit of `p_i` to that of `p_{i+1}`
/// (after a tangent vertex, whose next edge has no segment, of the next edge along the curve),
/// on its local parameter u ∈ [0, 1].
///
/// It keeps the segment's four uniform cubic B-spline control points
/// ([`SubdivCurve::segment_controls`]) and its exact cubic Bézier form
/// ([`SubdivCurve::segment_bezier`]), computed once by [`SubdivCurve::segment`], and implements
/// [`BezierForm`]: evaluation, derivative, splitting, arc length, nearest point, bounding box
/// and curvature of the segment come from bez-core, and the segment goes to any consumer of
/// `BezierForm` (the flatteners of bez-subdiv). For the whole curve, piece by piece, use
/// [`SubdivCurve::to_beziers`] or map [`SubdivCurve::segment`] over `0..segment_count()`.
///
/// ```
/// use bez_core::BezierForm;
/// use subdiv_fit::{Closure, SubdivCurve, Vector2};
///
/// let square = vec![
///     Vector2::new(0.0, 0.0),
///     Vector2::new(1.0, 0.0),
///     Vector2::new(1.0, 1.0),
///     Vector2::new(0.0, 1.0),
/// ];
/// let curve = SubdivCurve::with_sharp(square, &[0], Closure::Closed)?;
/// let segment = curve.segment(1)?;
/// assert_eq!(segment.index(), 1);
/// assert!((segment.eval(0.3)? - curve.eval_segment(1, 0.3)?).norm() < 1e-15);
/// assert!(segment.arc_length(1e-12)? > 0.0);
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Segment<const D: usize> {
    index: usize,
    controls: [Vector<D>; 4],
    bezier: BezierCurve<D>,
}

impl<const D: usize> Segment<D> {
    /// The segment's index in its curve.
    #[must_use]
    pub fn index(&self) -> usize {
        self.index
    }

    /// The four uniform cubic B-spline control points (phantom points at sharp vertices, the
    /// derived points of the parabolic end next to a curved sharp vertex; next to a tangent
    /// vertex the uniform form of the segment's cubic).
    #[must_use]
    pub fn controls(&self) -> &[Vector<D>; 4] {
        &self.controls
    }

    /// Consumes the segment and returns its cubic Bézier form.
    #[must_use]
    pub fn into_bezier(self) -> BezierCurve<D> {
        self.bezier
    }
}

impl<const D: usize> BezierForm<D> for Segment<D> {
    /// The exact cubic Bézier form (stored, so the borrow is free).
    fn as_bezier(&self) -> &BezierCurve<D> {
        &self.bezier
    }
}

impl<const D: usize> SubdivCurve<D> {
    /// Segment `i` as a value implementing [`BezierForm`], local parameter u ∈ [0, 1].
    ///
    /// # Errors
    /// [`SubdivFitError::SegmentOutOfRange`]; [`SubdivFitError::Core`] only if the Bézier control
    /// points overflow.
    pub fn segment(&self, i: usize) -> Result<Segment<D>, SubdivFitError> {
        Ok(Segment {
            index: i,
            controls: self.segment_controls(i)?,
            bezier: self.segment_bezier(i)?,
        })
    }
}
