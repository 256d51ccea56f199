//! The crate's error type.

use bez_core::CoreError;

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
    /// The sharp-flag vector does not have one flag per vertex.
    #[error("{flags} sharp flags given for {points} vertices")]
    FlagCount {
        /// Number of flags.
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
        /// Largest remaining error.
        max_error: f64,
        /// The tolerance asked for.
        tolerance: f64,
    },
}
