//! The input contract: the sizes and coordinates within which every operation is finite and
//! bounded.
//!
//! * **Coordinates.** Every control point of a [`BezierCurve`](crate::BezierCurve) or
//!   [`BezierSurface`](crate::BezierSurface) is finite with |x| ≤ [`MAX_COORDINATE`]. The
//!   constructors and deserialization check it ([`CoreError::CoordinateOutOfRange`]). Inside
//!   that range, sums of squares of differences of up to 4,097 points in 3-D stay below
//!   `f64::MAX`, so evaluation, splitting, bounding boxes, nearest points and arc lengths are
//!   finite; curvature and torsion are computed in a power-of-two scaled form. A result that
//!   leaves the range (a derivative curve of a large curve, say) is an error
//!   ([`CoreError::CoordinateOutOfRange`] or [`CoreError::Overflow`]), never a curve holding
//!   huge or infinite values.
//! * **Degree.** At most [`MAX_DEGREE`] in every direction, for constructed curves and for
//!   the results of elevation ([`CoreError::DegreeTooHigh`]); the O(n²) operations then take
//!   milliseconds.
//! * **Counts** the caller chooses (samples, derivative orders) are checked against
//!   [`MAX_SAMPLES`] and [`MAX_DEGREE`] before anything is allocated ([`CoreError::TooLarge`]).
//!
//! [`CoreError::CoordinateOutOfRange`]: crate::CoreError::CoordinateOutOfRange
//! [`CoreError::Overflow`]: crate::CoreError::Overflow
//! [`CoreError::DegreeTooHigh`]: crate::CoreError::DegreeTooHigh
//! [`CoreError::TooLarge`]: crate::CoreError::TooLarge

/// The largest absolute coordinate a control point may have: 10¹⁵².
///
/// Leaves room for curves scaled by 10¹⁵⁰ and their first derivatives, and for
/// squared distances (≤ 3 · (2 · 10¹⁵²)² ≈ 10³⁰⁵).
pub const MAX_COORDINATE: f64 = 1e152;

/// The largest degree of a curve, and of a surface in each direction: 4,096.
pub const MAX_DEGREE: usize = 4096;

/// The largest number of samples one call produces (`sample_uniform`): 2²⁴.
pub const MAX_SAMPLES: usize = 1 << 24;
