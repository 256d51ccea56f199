//! Allocation-free de Casteljau kernels on slices, generic over scalars and points.
//!
//! These are the hot loops every crate of the workspace runs; the curve and surface types call
//! them. They work for any [`ControlPoint`]: `f64` (scalar polynomials in Bernstein form) and
//! [`Vector<D>`](crate::Vector) (points in D dimensions).

use crate::math;
use alloc::vec;
use alloc::vec::Vec;
use core::ops::{Add, Mul, Sub};

use crate::CoreError;
use crate::bernstein::{binomial_row, powi};

/// What a control point must support: affine combinations with `f64` weights, and a zero.
///
/// Implemented for `f64` and for every [`Vector<D>`](crate::Vector).
pub trait ControlPoint:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<f64, Output = Self>
{
    /// The additive identity.
    fn zero() -> Self;
}

impl ControlPoint for f64 {
    #[inline]
    fn zero() -> Self {
        0.0
    }
}

impl<const D: usize> ControlPoint for crate::Vector<D> {
    #[inline]
    fn zero() -> Self {
        Self::zeros()
    }
}

/// Linear interpolation (1 − t) a + t b, exact at t = 0 and t = 1.
#[inline]
pub fn lerp<T: ControlPoint>(a: T, b: T, t: f64) -> T {
    a * (1.0 - t) + b * t
}

/// Runs de Casteljau's algorithm in place and returns B(t) = Σ Pᵢ B_{i,n}(t); `None` if empty.
///
/// Recurrence (Ma et al. 2016, eq. (1), index corrected): Pᵢʳ = (1 − t) Pᵢʳ⁻¹ + t Pᵢ₊₁ʳ⁻¹.
/// The slice is overwritten with intermediate values. Cost O(n²), numerically the most stable
/// way to evaluate a polynomial in Bernstein form.
#[inline]
pub fn de_casteljau_in_place<T: ControlPoint>(work: &mut [T], t: f64) -> Option<T> {
    let n = work.len().checked_sub(1)?;
    let s = 1.0 - t;
    for r in 1..=n {
        for i in 0..=n - r {
            work[i] = work[i] * s + work[i + 1] * t;
        }
    }
    Some(work[0])
}

/// Evaluates Σ Pᵢ B_{i,n}(t) by de Casteljau without allocating for n < 32; `None` if empty.
#[must_use]
#[inline]
pub fn de_casteljau<T: ControlPoint>(points: &[T], t: f64) -> Option<T> {
    match points.len() {
        0..=4 => on_stack::<T, 4>(points, t),
        5..=8 => on_stack::<T, 8>(points, t),
        9..=32 => on_stack::<T, 32>(points, t),
        _ => de_casteljau_in_place(&mut points.to_vec(), t),
    }
}

/// de Casteljau in a stack buffer of capacity `N` (the caller guarantees `points.len() <= N`).
#[inline]
fn on_stack<T: ControlPoint, const N: usize>(points: &[T], t: f64) -> Option<T> {
    let mut buf = [T::zero(); N];
    let work = buf.get_mut(..points.len())?;
    work.copy_from_slice(points);
    de_casteljau_in_place(work, t)
}

/// Splits a Bézier control polygon at `t` into the control polygons of B on [0, t] and [t, 1].
///
/// `left` receives P₀⁰, P₀¹, …, P₀ⁿ and `right` receives P₀ⁿ, P₁ⁿ⁻¹, …, Pₙ⁰ (NOTES, eq. (1)).
/// Both pieces share the point B(t) exactly. Cost O(n²).
///
/// # Errors
/// [`CoreError::BufferLength`] when `left` or `right` does not have the length of `points`.
pub fn de_casteljau_split<T: ControlPoint>(
    points: &[T],
    t: f64,
    left: &mut [T],
    right: &mut [T],
) -> Result<(), CoreError> {
    let len = points.len();
    check_buffer_lengths(len, &[left.len(), right.len()])?;
    if len == 0 {
        return Ok(());
    }
    let n = len - 1;
    right.copy_from_slice(points);
    let s = 1.0 - t;
    left[0] = right[0];
    for (r, l) in left.iter_mut().enumerate().skip(1) {
        // Row r: Pᵢʳ for i = 0..=n − r from the n − r + 2 points of row r − 1 (a half-open range
        // over a slice of known length, so the loop has no bounds checks).
        let row = &mut right[..n + 2 - r];
        for i in 0..row.len() - 1 {
            row[i] = row[i] * s + row[i + 1] * t;
        }
        *l = row[0];
    }
    // `right[i]` now holds Pᵢⁿ⁻ⁱ, which is exactly the right piece in order.
    Ok(())
}

/// [`CoreError::BufferLength`] for the first of `buffers` (lengths of output buffers) that is not
/// `expected`.
pub(crate) fn check_buffer_lengths(expected: usize, buffers: &[usize]) -> Result<(), CoreError> {
    match buffers.iter().find(|&&len| len != expected) {
        Some(&len) => Err(CoreError::BufferLength { len, expected }),
        None => Ok(()),
    }
}

/// [`de_casteljau_split`] of a control polygon of fixed size `N`, by value: `(left, right)`.
///
/// The same recurrence Pᵢʳ = (1 − t) Pᵢʳ⁻¹ + t Pᵢ₊₁ʳ⁻¹ in the same order, so the result equals
/// `de_casteljau_split`'s bit for bit; with `N` known at compile time the loops unroll and the
/// pieces can stay in registers (hot loops on cubics).
#[must_use]
#[inline]
pub fn de_casteljau_split_array<T: ControlPoint, const N: usize>(
    points: [T; N],
    t: f64,
) -> ([T; N], [T; N]) {
    let mut left = points;
    let mut right = points;
    let s = 1.0 - t;
    for (r, l) in left.iter_mut().enumerate().skip(1) {
        for i in 0..N - r {
            right[i] = right[i] * s + right[i + 1] * t;
        }
        *l = right[0];
    }
    (left, right)
}

/// Control points of the same polynomial written in degree n + r.
///
/// One step: Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ, a convex combination, repeated r times
/// (cost O(r (n + r))). An empty slice stays empty.
///
/// # Errors
/// [`CoreError::DegreeTooHigh`] when n + r exceeds [`MAX_DEGREE`](crate::MAX_DEGREE)
/// (checked before any work).
pub fn elevate_slice<T: ControlPoint>(points: &[T], r: usize) -> Result<Vec<T>, CoreError> {
    let degree = points.len().saturating_sub(1).saturating_add(r);
    if degree > crate::MAX_DEGREE {
        return Err(CoreError::DegreeTooHigh {
            max: crate::MAX_DEGREE,
            degree,
        });
    }
    Ok(elevate_unchecked(points, r))
}

/// [`elevate_slice`] for an r already checked.
pub(crate) fn elevate_unchecked<T: ControlPoint>(points: &[T], r: usize) -> Vec<T> {
    let mut cur = points.to_vec();
    if cur.is_empty() {
        return cur;
    }
    for _ in 0..r {
        let n1 = cur.len() as f64; // n + 1
        let mut next = Vec::with_capacity(cur.len() + 1);
        next.push(cur[0]);
        for i in 1..cur.len() {
            let a = i as f64 / n1;
            next.push(cur[i - 1] * a + cur[i] * (1.0 - a));
        }
        next.push(cur[cur.len() - 1]);
        cur = next;
    }
    cur
}

/// Control points of the derivative (hodograph): n (Pᵢ₊₁ − Pᵢ), i = 0..n−1.
///
/// The derivative of a constant (one point) is the single zero point.
#[must_use]
pub fn hodograph_slice<T: ControlPoint>(points: &[T]) -> Vec<T> {
    if points.len() <= 1 {
        return vec![T::zero(); 1];
    }
    let n = (points.len() - 1) as f64;
    points.windows(2).map(|w| (w[1] - w[0]) * n).collect()
}

/// Precomputed form for fast O(n) evaluation at many parameters (Horner in t/(1−t)).
///
/// B(t) = (1 − t)ⁿ Σ C(n,i) Pᵢ sⁱ with s = t/(1 − t) for t ≤ ½, and
/// B(t) = tⁿ Σ C(n,i) Pᵢ rⁿ⁻ⁱ with r = (1 − t)/t for t > ½, so |s|, |r| ≤ 1. This is the
/// Volk–Schumaker / Horner–Bernstein scheme. Above degree [`HORNER_MAX_DEGREE`] the scaled
/// coefficients C(n,i) Pᵢ could overflow (C(n, n/2) ≈ 2ⁿ), so each point is instead
/// Σ Pᵢ B_{i,n}(t) with the row of [`bernstein_row`](crate::bernstein_row), finite at every
/// degree. Cost: O(n) to build, O(n) per point.
#[derive(Debug, Clone)]
pub struct HornerBernstein<T> {
    /// C(n,i) Pᵢ up to degree [`HORNER_MAX_DEGREE`], the plain Pᵢ above it.
    coefficients: Vec<T>,
}

/// The largest degree [`HornerBernstein`] evaluates by Horner's rule: 2⁵⁰⁰ · 10¹⁵² (the
/// coordinate limit) is about 3 · 10³⁰², still finite.
pub const HORNER_MAX_DEGREE: usize = 500;

impl<T: ControlPoint> HornerBernstein<T> {
    /// Builds the scaled coefficients C(n, i) Pᵢ (or keeps Pᵢ above [`HORNER_MAX_DEGREE`]).
    #[must_use]
    pub fn new(points: &[T]) -> Self {
        let n = points.len().saturating_sub(1);
        let coefficients = if n > HORNER_MAX_DEGREE {
            points.to_vec()
        } else {
            points
                .iter()
                .zip(binomial_row(n))
                .map(|(&p, c)| p * c)
                .collect()
        };
        Self { coefficients }
    }

    /// B(t); `None` when built from no points.
    #[inline]
    #[must_use]
    pub fn eval(&self, t: f64) -> Option<T> {
        let q = &self.coefficients;
        let n = q.len().checked_sub(1)?;
        if n > HORNER_MAX_DEGREE {
            let mut row = vec![0.0; n + 1];
            crate::bernstein::bernstein_row(t, &mut row);
            return Some(
                q.iter()
                    .zip(&row)
                    .fold(T::zero(), |acc, (&p, &b)| acc + p * b),
            );
        }
        if t <= 0.5 {
            let u = 1.0 - t;
            let s = t / u;
            let mut acc = q[n];
            for &c in q[..n].iter().rev() {
                acc = acc * s + c;
            }
            Some(acc * powi(u, n))
        } else {
            let r = (1.0 - t) / t;
            let mut acc = q[0];
            for &c in &q[1..] {
                acc = acc * r + c;
            }
            Some(acc * powi(t, n))
        }
    }
}

/// Error-free transformation a + b = s + e (Knuth's TwoSum).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let z = s - a;
    (s, (a - (s - z)) + (b - z))
}

/// Error-free transformation a · b = p + e (with a fused multiply-add).
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, math::fma(a, b, -p))
}

/// Compensated de Casteljau evaluation of a scalar polynomial in Bernstein form.
///
/// Graillat, Langlois & Louvet's CompDeCasteljau: every step's rounding error is captured by
/// error-free transformations and propagated in a second de Casteljau run, so the result is
/// as accurate as if computed in twice the working precision, then rounded: relative error
/// ≈ u + cond · u² instead of cond · u. Use it for ill-conditioned evaluations near multiple
/// roots. Cost ≈ 4x plain de Casteljau. Returns 0 for an empty slice.
#[must_use]
pub fn compensated_de_casteljau(coeffs: &[f64], t: f64) -> f64 {
    let Some(n) = coeffs.len().checked_sub(1) else {
        return 0.0;
    };
    let (s, s_err) = two_sum(1.0, -t);
    let mut b = coeffs.to_vec();
    let mut e = vec![0.0; n + 1];
    for r in 1..=n {
        for i in 0..=n - r {
            let (p1, pi1) = two_prod(s, b[i]);
            let (p2, pi2) = two_prod(t, b[i + 1]);
            let (sum, sigma) = two_sum(p1, p2);
            let w = pi1 + pi2 + sigma + s_err * b[i];
            e[i] = w + s * e[i] + t * e[i + 1];
            b[i] = sum;
        }
    }
    b[0] + e[0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_pieces_share_the_split_point() {
        let p = [0.0, 3.0, -1.0, 2.0, 5.0];
        let (mut l, mut r) = ([0.0; 5], [0.0; 5]);
        de_casteljau_split(&p, 0.3, &mut l, &mut r).unwrap();
        assert_eq!(l[4], r[0]);
        assert_eq!(l[4], de_casteljau(&p, 0.3).unwrap());
        assert_eq!(l[0], p[0]);
        assert_eq!(r[4], p[4]);
    }

    #[test]
    fn split_array_equals_split_bit_for_bit() {
        let p = [0.1, 3.7, -1.3, 2.9, 5.3, -0.7];
        for t in [0.0, 0.3, 0.5, 0.77, 1.0] {
            let (mut l, mut r) = ([0.0; 6], [0.0; 6]);
            de_casteljau_split(&p, t, &mut l, &mut r).unwrap();
            assert_eq!(de_casteljau_split_array(p, t), (l, r));
        }
        assert_eq!(de_casteljau_split_array([2.5], 0.5), ([2.5], [2.5]));
    }

    #[test]
    fn split_rejects_wrong_buffers() {
        let p = [0.0, 1.0];
        let (mut l, mut r) = ([0.0; 3], [0.0; 2]);
        assert_eq!(
            de_casteljau_split(&p, 0.5, &mut l, &mut r),
            Err(CoreError::BufferLength {
                len: 3,
                expected: 2
            })
        );
    }

    #[test]
    fn horner_matches_de_casteljau_at_degree_50() {
        let p: Vec<f64> = (0..51)
            .map(|i| ((i * 37 % 11) as f64 - 5.0) * 0.7)
            .collect();
        let h = HornerBernstein::new(&p);
        let scale = p.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        for k in 0..=200 {
            let t = k as f64 / 200.0;
            let a = h.eval(t).unwrap();
            let b = de_casteljau(&p, t).unwrap();
            assert!(
                (a - b).abs() <= 64.0 * f64::EPSILON * scale,
                "t={t}: {a} vs {b}"
            );
        }
    }
}
