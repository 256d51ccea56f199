//! The error type of lambda-bezier.

use bez_core::CoreError;

/// Everything that can go wrong in lambda-bezier.
///
/// Messages name the offending value; a rejected λ comes with the valid interval of its degree.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LambdaError {
    /// An error of the Bézier kernel (empty or non-finite control points, t outside [0, 1], …).
    #[error(transparent)]
    Core(#[from] CoreError),
    /// λ-B bases exist for n ≥ 2 only (n + 1 control points, degree n + 1 ≥ 3).
    #[error("λ-Bézier curves need n ≥ 2 (at least 3 control points), got n = {n}")]
    DegreeTooLow {
        /// The n given (number of control points − 1).
        n: usize,
    },
    /// λ is NaN or infinite.
    #[error("shape parameter λ = {lambda} is not finite")]
    NonFiniteLambda {
        /// The value given.
        lambda: f64,
    },
    /// λ lies outside the interval where every basis function is non-negative.
    #[error(
        "shape parameter λ = {lambda} is outside the valid interval [{min}, {max}] for n = {n}"
    )]
    LambdaOutOfRange {
        /// The value given.
        lambda: f64,
        /// The n of the basis (degree n + 1).
        n: usize,
        /// Lower end of the valid interval, [`crate::LambdaRange::min`].
        min: f64,
        /// Upper end of the valid interval (always 1).
        max: f64,
    },
    /// A basis index k outside 0..=n.
    #[error("basis index k = {k} is outside 0..={n}")]
    IndexOutOfRange {
        /// The index given.
        k: usize,
        /// The largest valid index.
        n: usize,
    },
    /// A joint is impossible because a tangent vanishes (e.g. n + λ = 0 or Pₙ = Pₙ₋₁).
    #[error("the {which} tangent of the joint vanishes: no G1 joint is defined")]
    DegenerateJoint {
        /// `"incoming"` or `"outgoing"`.
        which: &'static str,
    },
    /// Too few data points for an interpolation.
    #[error("interpolation needs at least {needed} data points, got {got}")]
    TooFewPoints {
        /// The minimum.
        needed: usize,
        /// The number given.
        got: usize,
    },
    /// Interpolation data whose abscissae do not increase strictly.
    #[error("data abscissae must increase strictly: x[{index}] = {value} does not")]
    NotIncreasing {
        /// Index of the first offending abscissa.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A list of λ values whose length does not match the number of segments.
    #[error("expected {expected} λ values (one per segment), got {got}")]
    LambdaCount {
        /// The number of segments.
        expected: usize,
        /// The number of λ values given.
        got: usize,
    },
    /// A joint needs more control points in the second curve than it has: a G2 joint sets
    /// Q₀, Q₁ and Q₂ and must leave the end point Qₙ alone (n ≥ 3).
    #[error("a G2 joint sets the first three control points and needs n ≥ {needed}, got n = {n}")]
    JoinNeedsDegree {
        /// The smallest n accepted.
        needed: usize,
        /// The n of the second curve.
        n: usize,
    },
    /// Two surface patches cannot share the boundary: their grids or λ across it differ.
    #[error("the patches cannot share a boundary: {what} differ")]
    PatchMismatch {
        /// What differs (the v sizes of the grids, or λ_v).
        what: &'static str,
    },
    /// No λ in the valid interval gives a finite cost (or the minimizer failed).
    #[error("no λ in the valid interval gives a finite cost")]
    NoMinimum,
}
