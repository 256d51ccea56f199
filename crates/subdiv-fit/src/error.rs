//! The crate's error type.

use bez_core::{CoreError, Vector};

use crate::{Closure, SubdivCurve, VertexKind};

/// Everything that can go wrong when building, evaluating or fitting a subdivision curve.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SubdivFitError {
    /// An error of the Bézier kernel.
    #[error(transparent)]
    Core(#[from] CoreError),
    /// Fewer points than the curve or the fit needs.
    #[error("{got} points given, at least {needed} are needed")]
    TooFewPoints {
        /// Number of points given.
        got: usize,
        /// Minimum number of points.
        needed: usize,
    },
    /// A point has a NaN or infinite coordinate.
    #[error("point {index} has a non-finite coordinate")]
    NonFinite {
        /// Index of the offending point.
        index: usize,
    },
    /// Two consecutive points coincide (for closed data, the last and the first count as consecutive).
    #[error("points {index} and {next} coincide")]
    DuplicatePoint {
        /// Index of the first point of the pair.
        index: usize,
        /// Index of the second point of the pair.
        next: usize,
    },
    /// The vertex kinds are not one per vertex.
    #[error("{flags} vertex kinds given for {points} vertices")]
    FlagCount {
        /// Number of vertex kinds.
        flags: usize,
        /// Number of vertices.
        points: usize,
    },
    /// A segment index outside the curve.
    #[error("segment {index} does not exist; the curve has {count} segments")]
    SegmentOutOfRange {
        /// Requested segment.
        index: usize,
        /// Number of segments.
        count: usize,
    },
    /// A parameter outside its range.
    #[error("parameter {name} = {value} is outside [{min}, {max}]")]
    ParameterOutOfRange {
        /// Name of the parameter.
        name: &'static str,
        /// The value given.
        value: f64,
        /// Lower bound.
        min: f64,
        /// Upper bound.
        max: f64,
    },
    /// The fitting tolerance is not a positive finite number.
    #[error("tolerance {value} is not a positive finite number")]
    InvalidTolerance {
        /// The value given.
        value: f64,
    },
    /// The tolerance is below what the data's coordinates resolve (16 units in the last place of
    /// the largest coordinate): the loop would insert points until rounding decides.
    #[error("tolerance {tolerance} is below {floor}, 16 ulps of the largest coordinate")]
    ToleranceBelowPrecision {
        /// The tolerance given.
        tolerance: f64,
        /// The smallest tolerance accepted for these data.
        floor: f64,
    },
    /// An option of the fit is out of its range.
    #[error("option {name} = {value} is invalid: {reason}")]
    InvalidOption {
        /// Name of the option.
        name: &'static str,
        /// The value given.
        value: f64,
        /// What the option must satisfy.
        reason: &'static str,
    },
    /// The linear system for the control points (eq. 4 or its least-squares form) is singular.
    #[error("the {size}x{size} control-point system is singular")]
    SingularSystem {
        /// Number of unknown control points.
        size: usize,
    },
    /// The fitting loop hit its round cap before every error was within tolerance.
    #[error("no convergence after {rounds} rounds: max error {max_error} > tolerance {tolerance}")]
    NoConvergence {
        /// Rounds performed.
        rounds: usize,
        /// Largest remaining error (of the last round).
        max_error: f64,
        /// The tolerance asked for.
        tolerance: f64,
        /// The curve of the round with the smallest error, and that error.
        best: Box<BestCurve>,
    },
    /// The fit turns at a smooth joint ([`Corner::smooth`](crate::Corner::smooth), or a tangent
    /// joint with [`Reduction::Refit`](crate::Reduction::Refit)) by more than
    /// [`SMOOTH_JOINT_TURN`](crate::SMOOTH_JOINT_TURN): its refits could not hold the joint's two
    /// sides on one tangent within the tolerance.
    #[error(
        "the fit turns by {turn:e} rad at the smooth joint at data index {index}, at most {max:e} accepted"
    )]
    SmoothJointNotKept {
        /// The joint's data index.
        index: usize,
        /// The fit's turn there (radians; infinite where a side has no tangent).
        turn: f64,
        /// The largest turn accepted.
        max: f64,
    },
    /// A size the caller chose is above its limit.
    #[error("{name}: {requested} requested, at most {max} accepted")]
    TooLarge {
        /// What was too large.
        name: &'static str,
        /// The size requested.
        requested: usize,
        /// The largest size accepted.
        max: usize,
    },
    /// SVG path data that do not parse.
    #[error("invalid SVG path data: {reason}")]
    InvalidPathData {
        /// The parser's message.
        reason: String,
    },
    /// A tangent vertex without room for its double knot (see [`SubdivCurve::new`]).
    #[error("vertex {index} cannot be a tangent vertex: {reason}")]
    InvalidTangent {
        /// The vertex.
        index: usize,
        /// What it lacks.
        reason: &'static str,
    },
    /// A given tangent joint ([`crate::Joints::with_tangents`]) the fit cannot make.
    #[error("tangent joint at data index {index}: {reason}")]
    InvalidTangentJoint {
        /// The data index given.
        index: usize,
        /// Why it cannot be one.
        reason: &'static str,
    },
    /// [`FitOptions::corner_kind`](crate::FitOptions::corner_kind) is not a sharp kind, or is
    /// [`VertexKind::SharpCurved`] where the fit makes tangent vertices.
    #[error("corner kind {kind:?} is invalid: {reason}")]
    InvalidCornerKind {
        /// The kind given.
        kind: VertexKind,
        /// Why it cannot be the fit's corner kind.
        reason: &'static str,
    },
    /// A given corner index is not a data index.
    #[error("corner index {index} is outside the {points} data points")]
    CornerOutOfRange {
        /// The index given.
        index: usize,
        /// Number of data points.
        points: usize,
    },
    /// A known corner's tangent direction that cannot be used.
    #[error("corner at data index {index}: {reason}")]
    InvalidCornerTangent {
        /// The corner's data index.
        index: usize,
        /// What is wrong with it.
        reason: &'static str,
    },
}

/// The best curve of a fit that did not converge ([`SubdivFitError::NoConvergence`]), with its
/// error. Stored without its dimension in the type, so the error type stays one for all
/// dimensions; [`BestCurve::curve`] gives it back as a [`SubdivCurve`].
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct BestCurve {
    coordinates: Vec<f64>,
    dimension: usize,
    kinds: Vec<VertexKind>,
    closure: Closure,
    max_error: f64,
}

impl BestCurve {
    pub(crate) fn new<const D: usize>(curve: &SubdivCurve<D>, max_error: f64) -> Self {
        Self {
            coordinates: curve
                .points()
                .iter()
                .flat_map(|p| p.iter().copied())
                .collect(),
            dimension: D,
            kinds: curve.kinds().to_vec(),
            closure: curve.closure(),
            max_error,
        }
    }

    /// The curve, if its points have `D` coordinates (the dimension of the data fitted).
    #[must_use]
    pub fn curve<const D: usize>(&self) -> Option<SubdivCurve<D>> {
        if D != self.dimension || D == 0 {
            return None;
        }
        let points = self
            .coordinates
            .chunks_exact(D)
            .map(|c| {
                let mut p = [0.0; D];
                p.copy_from_slice(c);
                Vector::<D>::from(p)
            })
            .collect();
        SubdivCurve::new(points, self.kinds.clone(), self.closure).ok()
    }

    /// Its largest error (of the measure the fit drives below the tolerance).
    #[must_use]
    pub fn max_error(&self) -> f64 {
        self.max_error
    }
}
