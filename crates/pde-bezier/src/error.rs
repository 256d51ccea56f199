//! The crate's error type.

/// Everything that can go wrong when describing or solving a PDE-surface problem.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PdeError {
    /// An error of the Bézier kernel (invalid control points, parameters out of range).
    #[error(transparent)]
    Core(#[from] bez_core::CoreError),
    /// The operator has no terms.
    #[error("the operator has no terms: give at least one c·∂^(p+q)/∂u^p∂v^q")]
    EmptyOperator,
    /// A term has an odd total order, an order above 6 or a zero order.
    #[error("term ∂^{du}u∂^{dv}v has order {order}: only even orders 2, 4 or 6 are supported")]
    UnsupportedOrder {
        /// Derivative order in u.
        du: usize,
        /// Derivative order in v.
        dv: usize,
        /// Total order du + dv.
        order: usize,
    },
    /// A coefficient or datum is NaN or infinite.
    #[error("{what} is not finite: {value}")]
    NonFinite {
        /// What the value is.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A side has the wrong number of boundary curves.
    #[error(
        "side {side} has {given} boundary curves but an operator of order {order} needs {expected} (positions and cross derivatives up to order {expected} - 1)"
    )]
    SideDataCount {
        /// The side's name (u=0, u=1, v=0, v=1).
        side: &'static str,
        /// Curves given.
        given: usize,
        /// Curves needed, k/2.
        expected: usize,
        /// PDE order k.
        order: usize,
    },
    /// Only one side of an opposite pair is periodic.
    #[error("side {side} is periodic but its opposite side is not: mark both or neither")]
    PeriodicMismatch {
        /// The periodic side.
        side: &'static str,
    },
    /// The degree is too low for the boundary conditions or the continuity.
    #[error("degree {degree} in {direction} is too low: at least {needed} is needed ({why})")]
    DegreeTooLow {
        /// "u" or "v".
        direction: &'static str,
        /// The degree given.
        degree: usize,
        /// The smallest admissible degree.
        needed: usize,
        /// The constraint that fails.
        why: &'static str,
    },
    /// The continuity order between patches is not admissible.
    #[error(
        "continuity C^{smoothness} in {direction} is not admissible: {why} (allowed {min}..={max})"
    )]
    Smoothness {
        /// "u" or "v".
        direction: &'static str,
        /// The continuity given.
        smoothness: usize,
        /// Smallest admissible value.
        min: usize,
        /// Largest admissible value.
        max: usize,
        /// The reason.
        why: &'static str,
    },
    /// A grid needs at least one patch in each direction.
    #[error(
        "the patch grid must have at least one patch in each direction, got {patches_u} x {patches_v}"
    )]
    NoPatches {
        /// Patches in u.
        patches_u: usize,
        /// Patches in v.
        patches_v: usize,
    },
    /// Piecewise boundary data must have one piece per patch along its side.
    #[error("boundary data on side {side} has {given} pieces but the side has {expected} patches")]
    PieceCount {
        /// The side's name.
        side: &'static str,
        /// Pieces given.
        given: usize,
        /// Patches along the side.
        expected: usize,
    },
    /// Sampled boundary data has too few samples or end derivatives.
    #[error("boundary data on side {side} has {given} {what} but at least {needed} are needed")]
    TooFewSamples {
        /// The side's name.
        side: &'static str,
        /// What is counted (samples, end derivatives).
        what: &'static str,
        /// Count given.
        given: usize,
        /// Count needed.
        needed: usize,
    },
    /// Boundary data of two adjacent sides disagree at a shared control point.
    #[error(
        "boundary data of sides {first} and {second} disagree at control point ({i}, {j}) by {gap:e}: make positions, cross derivatives and twists meet at the corner"
    )]
    CornerMismatch {
        /// One side.
        first: &'static str,
        /// The other side.
        second: &'static str,
        /// Control point row (u index).
        i: usize,
        /// Control point column (v index).
        j: usize,
        /// The distance between the two prescribed values.
        gap: f64,
    },
    /// The boundary data leaves the solution undetermined: the system is rank deficient
    /// (its estimated condition number is infinite or beyond 1/ε).
    #[error(
        "the {method} system with {unknowns} unknowns is rank deficient (condition estimate {condition:e}): the boundary data leaves the solution undetermined; fix more sides or raise the continuity"
    )]
    Undetermined {
        /// The method's name.
        method: &'static str,
        /// Number of unknowns.
        unknowns: usize,
        /// The condition estimate (infinite for an exactly singular system).
        condition: f64,
    },
    /// The system has full rank but is too ill-conditioned for the answer to be trusted.
    #[error(
        "the {method} system with {unknowns} unknowns is ill-conditioned (condition estimate {condition:e} above {limit:e}): lower the degree, use fewer, larger patches, or rescale the problem"
    )]
    IllConditioned {
        /// The method's name.
        method: &'static str,
        /// Number of unknowns.
        unknowns: usize,
        /// The condition estimate.
        condition: f64,
        /// The largest accepted condition estimate.
        limit: f64,
    },
    /// The principal symbol of the operator vanishes in some direction (ξ, η) ≠ 0.
    #[error(
        "the operator is not elliptic: its principal symbol (order {order}) vanishes at (ξ, η) = ({xi:.6}, {eta:.6}); the boundary-value problem is not well posed"
    )]
    NotElliptic {
        /// The operator's order k.
        order: usize,
        /// The direction where the symbol vanishes (unit vector).
        xi: f64,
        /// Second component of the direction.
        eta: f64,
    },
    /// A size the caller chose is beyond the crate's limit (checked before any allocation).
    #[error("{what} is {value}, above the limit {limit}")]
    TooLarge {
        /// What is counted.
        what: &'static str,
        /// The value asked for.
        value: usize,
        /// The largest accepted value.
        limit: usize,
    },
    /// A knot vector decreases somewhere.
    #[error("knot vector in {direction} decreases at index {index}: knots must be non-decreasing")]
    DecreasingKnots {
        /// "u" or "v".
        direction: &'static str,
        /// Index of the first knot smaller than its predecessor.
        index: usize,
    },
    /// A STEP file could not be read.
    #[error("step file: {what}")]
    Step {
        /// What went wrong.
        what: String,
    },
    /// An IGES file could not be read.
    #[error("iges file: {what}")]
    Iges {
        /// What went wrong.
        what: String,
    },
    /// Writing a file failed.
    #[error("write failed: {message}")]
    Io {
        /// The I/O error's message.
        message: String,
    },
    /// A B-spline surface's degree is outside 1..=`bez_core::MAX_DEGREE`, or its knots leave
    /// an empty parameter range.
    #[error("B-spline surface: {what}")]
    InvalidSpline {
        /// What is wrong.
        what: String,
    },
    /// A deserialized solution holds a measure that no solve gives.
    #[error("solution: the {what} is {value}; it must be finite and non-negative")]
    InvalidSolution {
        /// Which measure.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// An evaluation parameter is outside [0, 1].
    #[error("grid parameter {value} is outside [0, 1]")]
    ParameterOutOfRange {
        /// The parameter.
        value: f64,
    },
}

impl PdeError {
    /// An I/O error, by its message (so that the error stays `Clone` and `PartialEq`).
    pub(crate) fn io(e: std::io::Error) -> Self {
        Self::Io {
            message: e.to_string(),
        }
    }
}
