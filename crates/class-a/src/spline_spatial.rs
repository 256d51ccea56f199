//! Spatial Class A curves of several segments through knots with tangents (and curvatures and
//! osculating planes).

use bez_core::{BezierCurve, BezierForm, Vector3};

use crate::spline::{eval_segments, segment_ends, solve_segments, with_joint_rules};
use crate::{ClassACurve, ClassAError, SpatialKnot, hermite_spatial};

/// A spatial curve of several Class A segments: segment i runs from knot i to knot i + 1 with
/// the knots' tangent directions (G1 at every joint), and with their curvatures (and binormals,
/// where given) when both knots of the segment prescribe a curvature, each segment built by
/// [`hermite_spatial`] at one degree, so each has proven monotone curvature and torsion.
///
/// A joint is G2 (the curvature vectors of the two segments agree) where its knot prescribes
/// the curvature and the binormal: both segments then meet the same curvature and osculating
/// plane. A knot with a curvature but no binormal gives equal curvatures on both sides, with
/// osculating planes free.
///
/// The knots and the degree are the value; the segments are solved once, at construction, and
/// kept (private). Deserialization goes through [`SpatialClassASpline::new`], so a deserialized
/// spline is solved and checked like a constructed one.
///
/// ```
/// use bez_core::Vector3;
/// use class_a::{SpatialClassASpline, SpatialKnot};
/// // Knots on the conical spiral e^{0.4t}(cos t, sin t, 0.8) every 1.1 rad, with its tangents.
/// let knots: Vec<SpatialKnot> = (0..3)
///     .map(|i| {
///         let t = 1.1 * f64::from(i);
///         let (sn, cs, e) = (t.sin(), t.cos(), (0.4 * t).exp());
///         SpatialKnot::new(
///             Vector3::new(cs, sn, 0.8) * e,
///             Vector3::new(0.4 * cs - sn, 0.4 * sn + cs, 0.32) * e,
///         )
///     })
///     .collect();
/// let spline = SpatialClassASpline::new(knots.clone(), 6)?;
/// assert_eq!(spline.segments().len(), 2);
/// assert!((spline.eval(1.0)? - knots[1].point).norm() < 1e-12);
/// // G2 joints, curvatures and osculating planes chosen from the G1 spline.
/// let g2 = SpatialClassASpline::with_g2_joints(knots, 6)?;
/// assert!(g2.knots().iter().all(|k| k.curvature.is_some() && k.binormal.is_some()));
/// # Ok::<(), class_a::ClassAError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "SpatialSplineRepr", into = "SpatialSplineRepr")
)]
pub struct SpatialClassASpline {
    knots: Vec<SpatialKnot>,
    degree: usize,
    segments: Vec<ClassACurve<3>>,
}

/// Serialized form of [`SpatialClassASpline`]: knots and degree, solved again when read.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct SpatialSplineRepr {
    knots: Vec<SpatialKnot>,
    degree: usize,
}

#[cfg(feature = "serde")]
impl TryFrom<SpatialSplineRepr> for SpatialClassASpline {
    type Error = ClassAError;
    fn try_from(r: SpatialSplineRepr) -> Result<Self, ClassAError> {
        Self::new(r.knots, r.degree)
    }
}

#[cfg(feature = "serde")]
impl From<SpatialClassASpline> for SpatialSplineRepr {
    fn from(s: SpatialClassASpline) -> Self {
        Self {
            knots: s.knots,
            degree: s.degree,
        }
    }
}

impl SpatialClassASpline {
    /// Solves the segments between consecutive knots at the given degree ([`hermite_spatial`]).
    ///
    /// # Errors
    /// [`ClassAError::InvalidParameter`] for fewer than 2 or more than [`MAX_KNOTS`](crate::MAX_KNOTS) knots;
    /// [`ClassAError::DegreeTooLow`] (below 3) / [`ClassAError::DegreeTooHigh`]; the first
    /// segment that fails as [`ClassAError::Segment`] with its index and the error of
    /// [`hermite_spatial`].
    pub fn new(knots: Vec<SpatialKnot>, degree: usize) -> Result<Self, ClassAError> {
        let segments = solve_segments(&knots, degree, 3, hermite_spatial)?;
        Ok(Self {
            knots,
            degree,
            segments,
        })
    }

    /// G2 at every knot without choosing curvatures or osculating planes: knots without a
    /// prescribed curvature get one, and knots without a binormal get one, from the G1 spline
    /// of the same knots; then every segment is solved with both end curvatures and binormals
    /// ([`hermite_spatial`]). The choices are kept in [`SpatialClassASpline::knots`], so the
    /// result serializes as a spline with prescribed curvatures and binormals.
    ///
    /// At an end knot the choice is the G1 segment's own end curvature and binormal
    /// (Δb₀ × Δb₁ or Δbₙ₋₂ × Δbₙ₋₁). At an interior knot the G1 segments meeting there have
    /// one-sided values (the left segment's end, the right one's start); three rules are tried
    /// in turn, each at every knot: the mean (curvatures averaged, unit binormals summed and
    /// normalized), then the left values, then the right ones. The first rule under which every
    /// segment is solved, with proven monotone curvature and torsion, is returned.
    ///
    /// # Errors
    /// As [`SpatialClassASpline::new`] for the G1 spline, then the error of the first rule (the
    /// mean) when no rule gives a spline; [`ClassAError::Segment`] with
    /// [`ClassAError::Singular`] inside when a G1 segment has a zero end leg or straight ends.
    pub fn with_g2_joints(knots: Vec<SpatialKnot>, degree: usize) -> Result<Self, ClassAError> {
        let free: Vec<SpatialKnot> = knots
            .iter()
            .map(|k| SpatialKnot::new(k.point, k.tangent))
            .collect();
        let g1 = Self::new(free, degree)?;
        let ends = segment_ends(&g1.segments, one_sided)?;
        with_joint_rules(
            &knots,
            &ends,
            |left: (f64, Vector3), right: (f64, Vector3), weight_left| {
                (
                    weight_left * left.0 + (1.0 - weight_left) * right.0,
                    left.1 * weight_left + right.1 * (1.0 - weight_left),
                )
            },
            |k, (curvature, binormal)| {
                SpatialKnot::new(k.point, k.tangent)
                    .with_curvature(k.curvature.unwrap_or(curvature))
                    .with_binormal(k.binormal.unwrap_or(binormal))
            },
            |chosen| Self::new(chosen, degree),
        )
    }

    /// The knots.
    #[must_use]
    pub fn knots(&self) -> &[SpatialKnot] {
        &self.knots
    }

    /// The degree of every segment.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The segments, segment i from knot i to knot i + 1.
    #[must_use]
    pub fn segments(&self) -> &[ClassACurve<3>] {
        &self.segments
    }

    /// The point at u ∈ [0, m] for m segments: segment ⌊u⌋ (the last one at u = m) at its
    /// parameter u − ⌊u⌋.
    ///
    /// # Errors
    /// [`ClassAError::InvalidParameter`] for u outside [0, m] or NaN.
    pub fn eval(&self, u: f64) -> Result<Vector3, ClassAError> {
        eval_segments(&self.segments, u)
    }

    /// The segments' Bézier forms, in order (for flattening or export).
    #[must_use]
    pub fn to_bezier_segments(&self) -> Vec<BezierCurve<3>> {
        self.segments
            .iter()
            .map(|s| s.as_bezier().clone())
            .collect()
    }
}

/// A segment's (curvature, unit binormal) at its start and at its end, from its first and last
/// three control points.
fn one_sided(seg: &ClassACurve<3>) -> Result<[(f64, Vector3); 2], ClassAError> {
    let [(k0, _), (k1, _)] = crate::end_curvatures_torsions(seg.as_bezier())?;
    let p = seg.as_bezier().points();
    let n = p.len() - 1;
    let leg = |i: usize| p[i + 1] - p[i];
    let (b0, b1) = (leg(0).cross(&leg(1)), leg(n - 2).cross(&leg(n - 1)));
    Ok([(k0, b0 / b0.norm()), (k1, b1 / b1.norm())])
}
