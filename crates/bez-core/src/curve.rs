//! `BezierCurve`: a polynomial curve in D dimensions in Bernstein form.

use crate::vector::Vector;
use alloc::vec;
use alloc::vec::Vec;
use smallvec::SmallVec;

use crate::casteljau::{
    HornerBernstein, compensated_de_casteljau, de_casteljau, de_casteljau_in_place,
    de_casteljau_split, elevate_unchecked, hodograph_slice,
};
use crate::error::{CoreError, check_unit};
use crate::halve::de_casteljau_halve;
use crate::limits::{MAX_COORDINATE, MAX_DEGREE, MAX_SAMPLES};

/// A Bézier curve B(t) = Σ_{i=0}^{n} Pᵢ B_{i,n}(t), t ∈ [0, 1], in D dimensions.
///
/// The curve owns its control points; construction validates them (at least one, all finite),
/// so every method can rely on that.
///
/// ### Interpolation
/// B(0) = P₀ and B(1) = Pₙ exactly (bit for bit).
///
/// ### Tangency
/// B'(0) = n (P₁ − P₀), B'(1) = n (Pₙ − Pₙ₋₁).
///
/// ### Usage
/// ```
/// use bez_core::{BezierCurve, Vector2};
/// let c = BezierCurve::new(vec![
///     Vector2::new(0.0, 0.0),
///     Vector2::new(1.0, 2.0),
///     Vector2::new(3.0, 2.0),
///     Vector2::new(4.0, 0.0),
/// ])?;
/// assert_eq!(c.degree(), 3);
/// assert_eq!(c.eval(0.5)?, Vector2::new(2.0, 1.5));
/// let (left, right) = c.split(0.5)?;
/// assert_eq!(left.end(), right.start());
/// # Ok::<(), bez_core::CoreError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "CurveRepr<D>", into = "CurveRepr<D>")
)]
pub struct BezierCurve<const D: usize> {
    points: Points<D>,
}

/// Control points, stored inline up to a cubic so that splitting low-degree curves (the
/// common case in flattening) does not allocate.
type Points<const D: usize> = SmallVec<[Vector<D>; 4]>;

/// Serialized form of a curve: its control points.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct CurveRepr<const D: usize> {
    points: Vec<Vector<D>>,
}

#[cfg(feature = "serde")]
impl<const D: usize> TryFrom<CurveRepr<D>> for BezierCurve<D> {
    type Error = CoreError;
    fn try_from(r: CurveRepr<D>) -> Result<Self, CoreError> {
        Self::new(r.points)
    }
}

#[cfg(feature = "serde")]
impl<const D: usize> From<BezierCurve<D>> for CurveRepr<D> {
    fn from(c: BezierCurve<D>) -> Self {
        Self {
            points: c.points.into_vec(),
        }
    }
}

/// `n` zero points, inline (no allocation, no element-wise fill loop) when they fit.
#[inline]
fn zeroed_points<const D: usize>(n: usize) -> Points<D> {
    if n <= 4 {
        SmallVec::from_buf_and_len([Vector::zeros(); 4], n)
    } else {
        SmallVec::from_elem(Vector::zeros(), n)
    }
}

/// de Casteljau for degree ≥ 4, kept out of line so the low-degree fast path inlines.
#[inline(never)]
fn eval_general<const D: usize>(points: &[Vector<D>], t: f64) -> Vector<D> {
    de_casteljau(points, t).unwrap_or_else(Vector::zeros)
}

/// Checks a list of control points: non-empty, degree ≤ [`MAX_DEGREE`], finite and within
/// ±[`MAX_COORDINATE`].
pub(crate) fn validate_points<const D: usize>(points: &[Vector<D>]) -> Result<(), CoreError> {
    if points.is_empty() {
        return Err(CoreError::Empty);
    }
    if points.len() - 1 > MAX_DEGREE {
        return Err(CoreError::DegreeTooHigh {
            max: MAX_DEGREE,
            degree: points.len() - 1,
        });
    }
    validate_coordinates(points)
}

/// Checks that every coordinate is finite and within ±[`MAX_COORDINATE`].
pub(crate) fn validate_coordinates<const D: usize>(points: &[Vector<D>]) -> Result<(), CoreError> {
    for (index, p) in points.iter().enumerate() {
        for &value in p.iter() {
            if !value.is_finite() {
                return Err(CoreError::NonFinite { index });
            }
            if value.abs() > MAX_COORDINATE {
                return Err(CoreError::CoordinateOutOfRange {
                    index,
                    value,
                    max: MAX_COORDINATE,
                });
            }
        }
    }
    Ok(())
}

impl<const D: usize> BezierCurve<D> {
    /// Creates a curve from its control points P₀ … Pₙ (degree n = points.len() − 1).
    ///
    /// # Errors
    /// [`CoreError::Empty`] for no points, [`CoreError::NonFinite`] for a NaN or infinite
    /// coordinate.
    pub fn new(points: Vec<Vector<D>>) -> Result<Self, CoreError> {
        validate_points(&points)?;
        Ok(Self {
            points: SmallVec::from_vec(points),
        })
    }

    /// Creates a curve from a slice of control points (copied).
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn from_slice(points: &[Vector<D>]) -> Result<Self, CoreError> {
        Self::new(points.to_vec())
    }

    /// Builds a curve from points already known to be valid (internal results).
    ///
    /// Convex combinations of points within ±`MAX_COORDINATE` (splits, elevation) can exceed it
    /// by a rounding error, which is harmless: the limit leaves far more room than that.
    pub(crate) fn from_valid(points: Vec<Vector<D>>) -> Self {
        debug_assert!(
            !points.is_empty()
                && points.len() <= MAX_DEGREE + 1
                && points
                    .iter()
                    .all(|p| p.is_finite() && p.amax() <= 2.0 * MAX_COORDINATE)
        );
        Self {
            points: SmallVec::from_vec(points),
        }
    }

    /// The control points P₀ … Pₙ.
    #[must_use]
    pub fn points(&self) -> &[Vector<D>] {
        &self.points
    }

    /// Consumes the curve and returns its control points.
    #[must_use]
    pub fn into_points(self) -> Vec<Vector<D>> {
        self.points.into_vec()
    }

    /// The degree n (number of control points − 1).
    #[must_use]
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The first control point, B(0).
    #[must_use]
    pub fn start(&self) -> Vector<D> {
        self.points[0]
    }

    /// The last control point, B(1).
    #[must_use]
    pub fn end(&self) -> Vector<D> {
        self.points[self.points.len() - 1]
    }

    /// B(t) by de Casteljau's algorithm (O(n²), the most stable evaluation; closed-form Bernstein
    /// weights for degree ≤ 3).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when t ∉ [0, 1] or t is NaN.
    #[inline(always)]
    pub fn eval(&self, t: f64) -> Result<Vector<D>, CoreError> {
        check_unit("t", t)?;
        Ok(self.eval_unchecked(t))
    }

    /// B(t) with t clamped to [0, 1] (NaN counts as 0): the evaluation for hot loops whose
    /// parameters are in range by construction. No `Result` to unwrap, the same value as
    /// [`BezierCurve::eval`] for every t in [0, 1], and never a point off the curve segment.
    ///
    /// ```
    /// use bez_core::{BezierCurve, Vector2};
    /// let c = BezierCurve::new(vec![Vector2::new(0.0, 0.0), Vector2::new(2.0, 2.0)])?;
    /// assert_eq!(c.eval_clamped(0.25), c.eval(0.25)?);
    /// assert_eq!(c.eval_clamped(1.5), c.end());
    /// assert_eq!(c.eval_clamped(f64::NAN), c.start());
    /// # Ok::<(), bez_core::CoreError>(())
    /// ```
    #[inline(always)]
    #[must_use]
    #[expect(
        clippy::manual_clamp,
        reason = "f64::clamp keeps NaN; max then min maps it to 0"
    )]
    pub fn eval_clamped(&self, t: f64) -> Vector<D> {
        // `max` then `min` map NaN to 0 (f64::max returns the non-NaN operand).
        self.eval_unchecked(t.max(0.0).min(1.0))
    }

    /// B(t) for a t already checked to be in [0, 1] (also valid, as a polynomial, outside).
    ///
    /// Degrees ≤ 3 use the Bernstein weights directly (non-negative, summing to 1, and exactly
    /// (1, 0, …) at t = 0 and (…, 0, 1) at t = 1, so endpoints stay exact); higher degrees run
    /// de Casteljau.
    #[inline(always)]
    pub(crate) fn eval_unchecked(&self, t: f64) -> Vector<D> {
        let p = &self.points;
        let s = 1.0 - t;
        match p.len() {
            1 => p[0],
            2 => p[0] * s + p[1] * t,
            3 => p[0] * (s * s) + p[1] * (2.0 * s * t) + p[2] * (t * t),
            4 => {
                let (s2, t2) = (s * s, t * t);
                p[0] * (s2 * s) + p[1] * (3.0 * s2 * t) + p[2] * (3.0 * s * t2) + p[3] * (t2 * t)
            }
            _ => eval_general(p, t),
        }
    }

    /// B(t) at many parameters in O(n) each (Horner in t/(1 − t), see [`HornerBernstein`]).
    ///
    /// Results are appended to `out`. The O(n) setup is shared by all parameters, so this is
    /// the fast path for sampling and plotting; at degree 50 it agrees with [`Self::eval`] to a
    /// few ulps of the control points' magnitude.
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] for the first parameter outside [0, 1]; `out` is then
    /// left with the values computed before it.
    pub fn eval_many(&self, ts: &[f64], out: &mut Vec<Vector<D>>) -> Result<(), CoreError> {
        let h = HornerBernstein::new(&self.points);
        out.reserve(ts.len());
        for &t in ts {
            check_unit("t", t)?;
            out.push(h.eval(t).unwrap_or_else(Vector::zeros));
        }
        Ok(())
    }

    /// B(t) at `count` uniformly spaced parameters 0, 1/(count−1), …, 1.
    ///
    /// `count` = 0 gives an empty vector and `count` = 1 gives [B(0)].
    ///
    /// # Errors
    /// [`CoreError::TooLarge`] when `count` > [`MAX_SAMPLES`] (checked before allocating).
    pub fn sample_uniform(&self, count: usize) -> Result<Vec<Vector<D>>, CoreError> {
        if count > MAX_SAMPLES {
            return Err(CoreError::TooLarge {
                requested: count,
                max: MAX_SAMPLES,
            });
        }
        let h = HornerBernstein::new(&self.points);
        let denom = count.saturating_sub(1).max(1) as f64;
        Ok((0..count)
            .map(|k| h.eval(k as f64 / denom).unwrap_or_else(Vector::zeros))
            .collect())
    }

    /// B(t) by compensated de Casteljau (twice the working precision, then rounded).
    ///
    /// For ill-conditioned evaluations, e.g. near a multiple root of a coordinate polynomial,
    /// where plain de Casteljau loses most digits. About 4x the cost of [`Self::eval`].
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when t ∉ [0, 1].
    pub fn eval_compensated(&self, t: f64) -> Result<Vector<D>, CoreError> {
        check_unit("t", t)?;
        let mut coords = vec![0.0; self.points.len()];
        let mut out = Vector::<D>::zeros();
        for d in 0..D {
            for (c, p) in coords.iter_mut().zip(&self.points) {
                *c = p[d];
            }
            out[d] = compensated_de_casteljau(&coords, t);
        }
        Ok(out)
    }

    /// Splits the curve at t into the pieces on [0, t] and [t, 1] (de Casteljau subdivision).
    ///
    /// The pieces share the point B(t) exactly and reproduce the curve: left(s) = B(s t),
    /// right(s) = B(t + s (1 − t)).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when t ∉ [0, 1].
    #[inline]
    pub fn split(&self, t: f64) -> Result<(Self, Self), CoreError> {
        check_unit("t", t)?;
        Ok(self.split_unchecked(t))
    }

    #[inline]
    pub(crate) fn split_unchecked(&self, t: f64) -> (Self, Self) {
        let n = self.points.len();
        if let [p0, p1, p2, p3] = self.points[..] {
            // The cubic, unrolled (the same de Casteljau arithmetic, in registers).
            let s = 1.0 - t;
            let (p01, p12, p23) = (p0 * s + p1 * t, p1 * s + p2 * t, p2 * s + p3 * t);
            let (p012, p123) = (p01 * s + p12 * t, p12 * s + p23 * t);
            let mid = p012 * s + p123 * t;
            return (
                Self {
                    points: SmallVec::from_buf([p0, p01, p012, mid]),
                },
                Self {
                    points: SmallVec::from_buf([mid, p123, p23, p3]),
                },
            );
        }
        let mut left = zeroed_points::<D>(n);
        let mut right = zeroed_points::<D>(n);
        // Buffers have the right length by construction. At t = ½ the pairwise sums give the
        // same points with about a third of the operations, as long as the sums (up to 2ⁿ times
        // the coordinates) cannot overflow: up to degree 100.
        let _ = if t == 0.5 && n <= 101 {
            de_casteljau_halve(&self.points, &mut left, &mut right)
        } else {
            de_casteljau_split(&self.points, t, &mut left, &mut right)
        };
        (Self { points: left }, Self { points: right })
    }

    /// The piece of the curve on [a, b] ⊆ [0, 1], reparametrized to [0, 1].
    ///
    /// Computed by two de Casteljau splits (at b, then at a/b on the left piece), never through
    /// the power basis, so it stays accurate at degree 100. The endpoints are B(a) and B(b).
    ///
    /// # Errors
    /// [`CoreError::InvalidInterval`] unless 0 ≤ a < b ≤ 1.
    pub fn subsegment(&self, a: f64, b: f64) -> Result<Self, CoreError> {
        if !(0.0 <= a && a < b && b <= 1.0) {
            return Err(CoreError::InvalidInterval { a, b });
        }
        let left = if b == 1.0 {
            self.clone()
        } else {
            self.split_unchecked(b).0
        };
        if a == 0.0 {
            return Ok(left);
        }
        Ok(left.split_unchecked(a / b).1)
    }

    /// The same curve traversed backwards: control points in reverse order.
    #[must_use]
    pub fn reverse(&self) -> Self {
        let mut points = self.points.clone();
        points.reverse();
        Self { points }
    }

    /// The derivative curve (hodograph) B'(t) = Σ n (Pᵢ₊₁ − Pᵢ) B_{i,n−1}(t), degree n − 1.
    ///
    /// The derivative of a degree-0 curve is the zero curve of degree 0.
    ///
    /// # Errors
    /// [`CoreError::Overflow`] when a control point of the hodograph leaves
    /// ±[`MAX_COORDINATE`] (possible only for curves within a factor 2n of the limit).
    pub fn derivative(&self) -> Result<Self, CoreError> {
        Self::checked_result(hodograph_slice(&self.points), "derivative")
    }

    /// The `order`-th derivative curve (order 0 is the curve itself; orders above the degree
    /// give the zero curve of degree 0).
    ///
    /// # Errors
    /// As [`Self::derivative`].
    pub fn derivative_n(&self, order: usize) -> Result<Self, CoreError> {
        let mut c = self.clone();
        // Beyond the degree every further derivative is the zero curve.
        for _ in 0..order.min(self.degree() + 1) {
            c = c.derivative()?;
        }
        Ok(c)
    }

    /// A curve from computed points, or [`CoreError::Overflow`] if they left the contract's
    /// range (see [`MAX_COORDINATE`]).
    pub(crate) fn checked_result(
        points: Vec<Vector<D>>,
        operation: &'static str,
    ) -> Result<Self, CoreError> {
        match validate_points(&points) {
            Ok(()) => Ok(Self::from_valid(points)),
            Err(_) => Err(CoreError::Overflow { operation }),
        }
    }

    /// B(t) and its derivatives B'(t), …, B⁽ᵏ⁾(t) at one parameter.
    ///
    /// B⁽ʲ⁾(t) = n!/(n−j)! Σᵢ Δʲ Pᵢ B_{i,n−j}(t): the forward differences of the control
    /// points are taken first and then evaluated by de Casteljau, so the result does not
    /// depend on where the curve sits (a translation changes no derivative, not even by
    /// rounding). Derivatives beyond the degree are zero. Cost O(min(k, n) · n²).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when t ∉ [0, 1]; [`CoreError::TooLarge`] when
    /// k > [`MAX_DEGREE`]; [`CoreError::Overflow`] when a derivative is not representable.
    pub fn eval_derivatives(&self, t: f64, k: usize) -> Result<Vec<Vector<D>>, CoreError> {
        check_unit("t", t)?;
        if k > MAX_DEGREE {
            return Err(CoreError::TooLarge {
                requested: k,
                max: MAX_DEGREE,
            });
        }
        let out = self.eval_derivatives_unchecked(t, k);
        if out.iter().all(Vector::is_finite) {
            Ok(out)
        } else {
            Err(CoreError::Overflow {
                operation: "eval_derivatives",
            })
        }
    }

    /// [`Self::eval_derivatives`] for t in [0, 1] and k ≤ [`MAX_DEGREE`], unchecked for
    /// overflow.
    pub(crate) fn eval_derivatives_unchecked(&self, t: f64, k: usize) -> Vec<Vector<D>> {
        let n = self.degree();
        let mut out = vec![Vector::<D>::zeros(); k + 1];
        let mut diffs: Vec<Vector<D>> = self.points.to_vec();
        let mut work: Vec<Vector<D>> = Vec::with_capacity(n + 1);
        let mut falling = 1.0;
        for (j, slot) in out.iter_mut().enumerate().take(n + 1) {
            if j > 0 {
                // Δʲ Pᵢ = Δʲ⁻¹ Pᵢ₊₁ − Δʲ⁻¹ Pᵢ, and n!/(n−j)! one factor further.
                for i in 0..=n - j {
                    diffs[i] = diffs[i + 1] - diffs[i];
                }
                diffs.truncate(n + 1 - j);
                falling *= (n + 1 - j) as f64;
            }
            work.clear();
            work.extend_from_slice(&diffs);
            *slot = de_casteljau_in_place(&mut work, t).unwrap_or_else(Vector::zeros) * falling;
        }
        out
    }

    /// The same curve written with degree n + r (exact degree elevation).
    ///
    /// Each step Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ; the curve is unchanged.
    ///
    /// # Errors
    /// [`CoreError::DegreeTooHigh`] when n + r exceeds [`MAX_DEGREE`] (checked before
    /// allocating).
    pub fn elevate(&self, r: usize) -> Result<Self, CoreError> {
        let degree = self.degree().saturating_add(r);
        if degree > MAX_DEGREE {
            return Err(CoreError::DegreeTooHigh {
                max: MAX_DEGREE,
                degree,
            });
        }
        let len = degree + 1;
        let p = elevate_unchecked(&self.points, r);
        debug_assert_eq!(p.len(), len);
        Ok(Self::from_valid(p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::Vector2;

    #[test]
    fn split_at_one_half_equals_de_casteljau_bit_for_bit() {
        let c = BezierCurve::new(
            (0..8)
                .map(|i| Vector2::new(f64::from(i) * 0.37, f64::from(i * i % 5) - 1.3))
                .collect(),
        )
        .unwrap();
        let (left, right) = c.split(0.5).unwrap();
        let (mut l, mut r) = (c.points().to_vec(), c.points().to_vec());
        de_casteljau_split(c.points(), 0.5, &mut l, &mut r).unwrap();
        assert_eq!((left.points(), right.points()), (&l[..], &r[..]));
    }

    fn cubic() -> BezierCurve<2> {
        BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 2.0),
            Vector2::new(3.0, 2.0),
            Vector2::new(4.0, 0.0),
        ])
        .unwrap()
    }

    #[test]
    fn curve_rejects_bad_points() {
        assert_eq!(BezierCurve::<2>::new(vec![]), Err(CoreError::Empty));
        assert_eq!(
            BezierCurve::new(vec![Vector2::new(0.0, 0.0), Vector2::new(f64::NAN, 1.0)]),
            Err(CoreError::NonFinite { index: 1 })
        );
    }

    #[test]
    fn curve_rejects_bad_parameters() {
        let c = cubic();
        assert!(matches!(
            c.eval(1.5),
            Err(CoreError::ParameterOutOfRange { .. })
        ));
        assert!(matches!(
            c.eval(f64::NAN),
            Err(CoreError::ParameterOutOfRange { .. })
        ));
        assert!(c.split(-0.1).is_err());
        assert!(matches!(
            c.subsegment(0.5, 0.5),
            Err(CoreError::InvalidInterval { .. })
        ));
        assert!(c.eval_many(&[0.2, 2.0], &mut Vec::new()).is_err());
    }

    #[test]
    fn eval_derivatives_matches_hodographs() {
        let c = cubic();
        for &t in &[0.0, 0.3, 1.0] {
            let d = c.eval_derivatives(t, 4).unwrap();
            assert!((d[0] - c.eval(t).unwrap()).norm() < 1e-14);
            assert!((d[1] - c.derivative().unwrap().eval(t).unwrap()).norm() < 1e-13);
            assert!((d[2] - c.derivative_n(2).unwrap().eval(t).unwrap()).norm() < 1e-12);
            assert!((d[3] - c.derivative_n(3).unwrap().eval(t).unwrap()).norm() < 1e-12);
            assert_eq!(d[4], Vector2::zeros());
        }
    }
}
