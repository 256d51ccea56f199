//! The error type of bez-core.

/// Everything that can go wrong in bez-core.
///
/// Every public function that can receive bad input returns `Result<_, CoreError>`;
/// messages name the offending value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CoreError {
    /// A curve or surface was given no control points.
    #[error("a Bézier curve or surface needs at least one control point, got none")]
    Empty,
    /// A control point has a NaN or infinite coordinate.
    #[error("control point {index} has a non-finite coordinate")]
    NonFinite {
        /// Index of the offending control point (row-major for surfaces).
        index: usize,
    },
    /// A parameter is outside [0, 1] or not finite.
    #[error("parameter {name} = {value} is outside [0, 1]")]
    ParameterOutOfRange {
        /// The parameter's name (`t`, `u`, `v`, ...).
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A parameter interval [a, b] is empty or reversed.
    #[error("parameter interval [{a}, {b}] is not a sub-interval of [0, 1] with a < b")]
    InvalidInterval {
        /// Start of the interval.
        a: f64,
        /// End of the interval.
        b: f64,
    },
    /// Rows of a surface control grid have different lengths.
    #[error("control grid row {row} has {len} points, expected {expected}")]
    RaggedGrid {
        /// Index of the first row whose length differs.
        row: usize,
        /// Its length.
        len: usize,
        /// The length of row 0.
        expected: usize,
    },
    /// The flat point list does not match the declared grid shape.
    #[error("a {rows} x {cols} control grid needs {expected} points, got {len}")]
    GridShape {
        /// Number of rows (degree in u + 1).
        rows: usize,
        /// Number of columns (degree in v + 1).
        cols: usize,
        /// rows * cols.
        expected: usize,
        /// The number of points given.
        len: usize,
    },
    /// The first derivative vanishes where a tangent-based quantity was asked.
    #[error("the tangent vanishes at t = {t}: curvature and torsion are undefined there")]
    ZeroTangent {
        /// The parameter where it vanishes.
        t: f64,
    },
    /// The first and second derivatives are parallel where a torsion was asked.
    #[error("the curvature vanishes at t = {t}: torsion is undefined there")]
    ZeroCurvature {
        /// The parameter where it vanishes.
        t: f64,
    },
    /// A tolerance or accuracy is not a positive finite number.
    #[error("tolerance {value} must be positive and finite")]
    InvalidTolerance {
        /// The value given.
        value: f64,
    },
    /// An operation needs a higher degree than the curve has.
    #[error("operation needs degree at least {needed}, the curve has degree {degree}")]
    DegreeTooLow {
        /// The minimal degree the operation needs.
        needed: usize,
        /// The degree the curve has.
        degree: usize,
    },
    /// A conversion needs a curve of one exact degree (e.g. a kurbo `CubicBez` needs 3).
    #[error("the curve has degree {found}, the conversion needs degree {wanted}")]
    DegreeMismatch {
        /// The degree of the curve given.
        found: usize,
        /// The degree the conversion needs.
        wanted: usize,
    },
    /// An operation supports curves up to some degree only (e.g. a kurbo path segment is at
    /// most cubic).
    #[error("the curve has degree {degree}, the operation supports degree at most {max}")]
    DegreeTooHigh {
        /// The largest degree the operation supports.
        max: usize,
        /// The degree the curve has.
        degree: usize,
    },
    /// A path draws a segment (or closes) before any starting point was set.
    #[error("path element {index} draws from no current point: the path must begin with MoveTo")]
    PathWithoutStart {
        /// Index of the offending path element.
        index: usize,
    },
    /// A path element has a NaN or infinite coordinate, or one outside
    /// ±[`MAX_COORDINATE`](crate::MAX_COORDINATE).
    #[error("path element {index} has a non-finite or out-of-range coordinate")]
    NonFinitePathElement {
        /// Index of the offending path element.
        index: usize,
    },
    /// A query point is not finite.
    #[error("query point has a non-finite coordinate")]
    NonFiniteQuery,
    /// A query point has a coordinate outside ±[`MAX_COORDINATE`](crate::MAX_COORDINATE).
    #[error("query point has coordinate {value}, outside ±{max}")]
    QueryOutOfRange {
        /// The coordinate.
        value: f64,
        /// The limit.
        max: f64,
    },
    /// An output buffer has the wrong length.
    #[error("buffer has length {len}, expected {expected}")]
    BufferLength {
        /// The length given.
        len: usize,
        /// The length needed.
        expected: usize,
    },
    /// A size the caller chose (a sample count, a derivative order, a grid shape) is above
    /// its documented limit.
    #[error("requested size {requested} is above the limit {max}")]
    TooLarge {
        /// The size requested.
        requested: usize,
        /// The largest size accepted.
        max: usize,
    },
    /// A control point coordinate is finite but outside ±[`MAX_COORDINATE`](crate::MAX_COORDINATE).
    #[error("control point {index} has coordinate {value}, outside ±{max}")]
    CoordinateOutOfRange {
        /// Index of the offending control point (row-major for surfaces).
        index: usize,
        /// The coordinate.
        value: f64,
        /// The limit, [`MAX_COORDINATE`](crate::MAX_COORDINATE).
        max: f64,
    },
    /// A result would leave the range of finite, representable values (e.g. a high-order
    /// derivative of a large curve).
    #[error("{operation}: the result is too large to represent")]
    Overflow {
        /// The operation that overflowed.
        operation: &'static str,
    },
}

/// Checks that `value` lies in [0, 1] (and is finite).
#[inline]
pub(crate) fn check_unit(name: &'static str, value: f64) -> Result<(), CoreError> {
    if (0.0..=1.0).contains(&value) {
        Ok(())
    } else {
        Err(CoreError::ParameterOutOfRange { name, value })
    }
}

/// Checks that a tolerance is positive and finite.
pub(crate) fn check_tolerance(value: f64) -> Result<(), CoreError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(CoreError::InvalidTolerance { value })
    }
}
