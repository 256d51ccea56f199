//! Known corners of the data, optionally with their exact one-sided tangents, and smooth joints
//! held tangent-continuous (the project's addition: the paper finds corners only by the angle at
//! a data point).

use bez_core::Vector;

use crate::SubdivFitError;

/// A known corner of the data for [`fit_with_known_corners`](crate::fit_with_known_corners): the
/// data index of a point that becomes a sharp vertex and, when the source knows them (a
/// `BezPath`, SVG path data or a glyph outline states the tangents of the segments that meet
/// there), the one-sided unit tangent directions of the outline there.
///
/// With tangents, [`FitOptions::corner_tolerance`](crate::FitOptions::corner_tolerance) bounds
/// the fit's turn at the corner against these exact directions instead of the data's estimate
/// (one-sided quadratics of the samples), and the control points next to the corner are placed
/// on the tangent rays.
///
/// A smooth joint ([`Corner::smooth`]) is a sharp vertex whose two sides are held on one tangent:
/// the curve is tangent-continuous there (G1) while each side keeps its own curvature.
///
/// ```
/// use subdiv_fit::{Corner, Vector2};
///
/// let c = Corner::with_tangents(7, Vector2::new(2.0, 0.0), Vector2::new(0.0, -3.0))?;
/// assert_eq!(c.index(), 7);
/// assert_eq!(c.tangents(), Some((Vector2::new(1.0, 0.0), Vector2::new(0.0, -1.0))));
/// assert!(Corner::with_tangents(7, Vector2::new(0.0, 0.0), Vector2::new(0.0, 1.0)).is_err());
/// # Ok::<(), subdiv_fit::SubdivFitError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "CornerRepr<D>", into = "CornerRepr<D>")
)]
pub struct Corner<const D: usize> {
    index: usize,
    /// Unit incoming and outgoing tangents.
    tangents: Option<(Vector<D>, Vector<D>)>,
    /// Whether the turn is held at zero (a smooth joint) rather than bounded by the options.
    smooth: bool,
}

impl<const D: usize> Corner<D> {
    /// A corner at data index `index` without tangents (the fit estimates them from the data).
    #[must_use]
    pub fn new(index: usize) -> Self {
        Self {
            index,
            tangents: None,
            smooth: false,
        }
    }

    /// A corner at data index `index` where the outline arrives along `incoming` and leaves along
    /// `outgoing` (directions of travel; any non-zero length, stored as unit vectors).
    ///
    /// # Errors
    /// [`SubdivFitError::InvalidCornerTangent`] when a direction has a non-finite coordinate or
    /// is zero.
    pub fn with_tangents(
        index: usize,
        incoming: Vector<D>,
        outgoing: Vector<D>,
    ) -> Result<Self, SubdivFitError> {
        Ok(Self {
            index,
            tangents: Some((unit(index, incoming)?, unit(index, outgoing)?)),
            smooth: false,
        })
    }

    /// A smooth joint at data index `index` where the outline passes along `tangent` (direction
    /// of travel, any non-zero length) and its curvature may jump, as where a straight side meets
    /// an arc: a sharp vertex whose two sides are held on the tangent, so that the fit is
    /// tangent-continuous there (its turn at most [`SMOOTH_JOINT_TURN`](crate::SMOOTH_JOINT_TURN))
    /// while each side bends on its own (with
    /// [`VertexKind::SharpCurved`](crate::VertexKind::SharpCurved) each side's curvature is free
    /// at the joint; with [`VertexKind::Sharp`](crate::VertexKind::Sharp) it is zero on both).
    /// Smooth joints need [`Reduction::Refit`](crate::Reduction::Refit), whose least squares
    /// hold the neighbouring control points on the tangent; they are kept with or without
    /// [`FitOptions::corner_tolerance`](crate::FitOptions::corner_tolerance).
    ///
    /// ```
    /// use subdiv_fit::{Corner, Vector2};
    ///
    /// let joint = Corner::smooth(40, Vector2::new(3.0, 4.0))?;
    /// assert!(joint.is_smooth());
    /// let t = Vector2::new(0.6, 0.8);
    /// assert_eq!(joint.tangents(), Some((t, t)));
    /// # Ok::<(), subdiv_fit::SubdivFitError>(())
    /// ```
    ///
    /// # Errors
    /// [`SubdivFitError::InvalidCornerTangent`] when the direction has a non-finite coordinate or
    /// is zero.
    pub fn smooth(index: usize, tangent: Vector<D>) -> Result<Self, SubdivFitError> {
        let t = unit(index, tangent)?;
        Ok(Self {
            index,
            tangents: Some((t, t)),
            smooth: true,
        })
    }

    /// The data index of the corner.
    #[must_use]
    pub fn index(&self) -> usize {
        self.index
    }

    /// The unit incoming and outgoing tangents, if given (equal for a smooth joint).
    #[must_use]
    pub fn tangents(&self) -> Option<(Vector<D>, Vector<D>)> {
        self.tangents
    }

    /// Whether this is a smooth joint ([`Corner::smooth`]).
    #[must_use]
    pub fn is_smooth(&self) -> bool {
        self.smooth
    }
}

/// `v` as a unit vector.
///
/// # Errors
/// [`SubdivFitError::InvalidCornerTangent`] (naming the corner `index`) when `v` has a non-finite
/// coordinate or is zero.
fn unit<const D: usize>(index: usize, v: Vector<D>) -> Result<Vector<D>, SubdivFitError> {
    let c = <[f64; D]>::from(v);
    if c.iter().any(|x| !x.is_finite()) {
        return Err(SubdivFitError::InvalidCornerTangent {
            index,
            reason: "a tangent has a non-finite coordinate",
        });
    }
    // Scaled first, so that neither huge nor tiny directions overflow or underflow.
    let scale = c.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if scale == 0.0 {
        return Err(SubdivFitError::InvalidCornerTangent {
            index,
            reason: "a tangent is zero",
        });
    }
    let scaled = v / scale;
    Ok(scaled / scaled.norm())
}

/// Serialized form of [`Corner`]: validated again by [`Corner::with_tangents`] on
/// deserialization.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct CornerRepr<const D: usize> {
    index: usize,
    #[serde(default)]
    tangents: Option<(Vector<D>, Vector<D>)>,
    #[serde(default)]
    smooth: bool,
}

#[cfg(feature = "serde")]
impl<const D: usize> TryFrom<CornerRepr<D>> for Corner<D> {
    type Error = SubdivFitError;
    fn try_from(r: CornerRepr<D>) -> Result<Self, SubdivFitError> {
        match (r.tangents, r.smooth) {
            (Some((a, b)), true) if a == b => Self::smooth(r.index, a),
            (_, true) => Err(SubdivFitError::InvalidCornerTangent {
                index: r.index,
                reason: "a smooth joint has one tangent on both sides",
            }),
            (Some((a, b)), false) => Self::with_tangents(r.index, a, b),
            (None, false) => Ok(Self::new(r.index)),
        }
    }
}

#[cfg(feature = "serde")]
impl<const D: usize> From<Corner<D>> for CornerRepr<D> {
    fn from(c: Corner<D>) -> Self {
        Self {
            index: c.index,
            tangents: c.tangents,
            smooth: c.smooth,
        }
    }
}
