//! The error type of bez-subdiv.

use bez_core::CoreError;

/// Everything that can go wrong when measuring, splitting or flattening.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SubdivError {
    /// An error of the Bézier kernel (empty or non-finite control points, bad parameters).
    #[error(transparent)]
    Core(#[from] CoreError),
    /// Flattening needs a curve, i.e. at least two control points.
    #[error("flattening needs at least 2 control points, got {got}")]
    TooFewPoints {
        /// The number of control points given.
        got: usize,
    },
    /// The tolerance ε is not positive and finite.
    #[error("tolerance ε = {value} must be positive and finite")]
    InvalidTolerance {
        /// The value given.
        value: f64,
    },
    /// A piece still failed the flatness test at the depth cap.
    #[error(
        "a piece is still not flat after {limit} subdivision levels (raise max_depth or the tolerance)"
    )]
    DepthLimit {
        /// The depth cap that was reached.
        limit: usize,
    },
    /// A segment count that does not fit in `usize` (the tolerance is tiny against the curve's
    /// second differences, or they overflow).
    #[error("the curve needs more than {limit} segments at tolerance {tolerance}")]
    TooManySegments {
        /// The tolerance asked for.
        tolerance: f64,
        /// The largest count that can be returned.
        limit: usize,
    },
    /// A subdivision depth cap above [`MAX_FLATTEN_DEPTH`](crate::MAX_FLATTEN_DEPTH).
    #[error("max_depth {value} is above the limit {max}: deeper pieces are at rounding level")]
    DepthTooLarge {
        /// The cap given.
        value: usize,
        /// The largest cap accepted.
        max: usize,
    },
    /// A tolerance below the rounding level of the control points' coordinates: no
    /// subdivision can meet it, and trying enumerates pieces at rounding level.
    #[error("tolerance {tolerance} is below the rounding level {min} of the coordinates")]
    ToleranceBelowRounding {
        /// The (absolute) tolerance given.
        tolerance: f64,
        /// The smallest tolerance accepted for this curve.
        min: f64,
    },
    /// A measurement whose sampling asks for more work than
    /// [`MAX_HAUSDORFF_WORK`](crate::MAX_HAUSDORFF_WORK).
    #[error("the sampling needs about {work:e} operations, above the limit {limit:e}")]
    SamplingTooLarge {
        /// The work asked for.
        work: f64,
        /// The limit.
        limit: f64,
    },
    /// The 1-D optimizer failed.
    #[error("the split-parameter optimizer failed: {message}")]
    Optimizer {
        /// argmin's message.
        message: String,
    },
}
