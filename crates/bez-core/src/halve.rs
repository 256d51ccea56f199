//! Subdivision at t = ½ (midpoint subdivision) by pairwise sums.

use crate::CoreError;
use crate::casteljau::{ControlPoint, check_buffer_lengths};

/// Splits a control polygon at t = ½ into the control polygons of B on [0, ½] and [½, 1], by
/// pairwise sums: `left` receives 2⁻ʳ S₀ʳ (r = 0..n), `right` receives 2⁻⁽ⁿ⁻ⁱ⁾ Sᵢⁿ⁻ⁱ.
///
/// At t = ½ de Casteljau's recurrence Pᵢʳ = ½ Pᵢʳ⁻¹ + ½ Pᵢ₊₁ʳ⁻¹ (Ma et al. 2016, eq. (1), index
/// corrected) is Pᵢʳ = 2⁻ʳ Sᵢʳ with the pairwise sums Sᵢ⁰ = Pᵢ, Sᵢʳ = Sᵢʳ⁻¹ + Sᵢ₊₁ʳ⁻¹. The sums
/// and one scaling per output point take n(n + 1)/2 additions and 2n multiplications for degree
/// n, against n(n + 1)/2 times two multiplications and an addition, and the chain of dependent
/// operations per level is one addition instead of a multiplication and an addition. Cost O(n²).
///
/// Multiplying by a power of two is exact and commutes with rounding, so
/// fl(½ a + ½ b) = fl(a + b) · ½ and, by induction on r, the result equals
/// `de_casteljau_split(points, 0.5, left, right)` bit for bit as long as no sum overflows and no
/// value is subnormal. Both hold when every coordinate is zero or between 1e-250 and 1e250 in
/// magnitude, up to degree 100; outside that range the two differ by rounding only.
///
/// # Errors
/// [`CoreError::BufferLength`] when `left` or `right` does not have the length of `points`.
///
/// # Example
/// ```
/// use bez_core::de_casteljau_halve;
///
/// let (mut left, mut right) = ([0.0; 3], [0.0; 3]);
/// de_casteljau_halve(&[0.0, 4.0, 0.0], &mut left, &mut right)?;
/// assert_eq!(left, [0.0, 2.0, 2.0]);
/// assert_eq!(right, [2.0, 2.0, 0.0]);
/// # Ok::<(), bez_core::CoreError>(())
/// ```
pub fn de_casteljau_halve<T: ControlPoint>(
    points: &[T],
    left: &mut [T],
    right: &mut [T],
) -> Result<(), CoreError> {
    check_buffer_lengths(points.len(), &[left.len(), right.len()])?;
    right.copy_from_slice(points);
    pairwise_sums(right, left);
    Ok(())
}

/// [`de_casteljau_halve`] in place: `piece` is replaced by its right half and `left` receives its
/// left half (no copy of the input is made).
///
/// # Errors
/// [`CoreError::BufferLength`] when `left` does not have the length of `piece`.
///
/// # Example
/// ```
/// use bez_core::de_casteljau_halve_in_place;
///
/// let (mut piece, mut left) = ([0.0, 4.0, 0.0], [0.0; 3]);
/// de_casteljau_halve_in_place(&mut piece, &mut left)?;
/// assert_eq!((left, piece), ([0.0, 2.0, 2.0], [2.0, 2.0, 0.0]));
/// # Ok::<(), bez_core::CoreError>(())
/// ```
pub fn de_casteljau_halve_in_place<T: ControlPoint>(
    piece: &mut [T],
    left: &mut [T],
) -> Result<(), CoreError> {
    check_buffer_lengths(piece.len(), &[left.len()])?;
    pairwise_sums(piece, left);
    Ok(())
}

/// [`de_casteljau_halve`] of a control polygon of fixed size `N`, by value: `(left, right)`.
///
/// The same sums in the same order, so the result equals `de_casteljau_halve`'s (and, in the
/// range given there, `de_casteljau_split_array(points, 0.5)`'s) bit for bit; with `N` known at
/// compile time the loops unroll and the pieces can stay in registers.
#[must_use]
#[inline]
pub fn de_casteljau_halve_array<T: ControlPoint, const N: usize>(
    points: [T; N],
) -> ([T; N], [T; N]) {
    let mut left = points;
    let mut right = points;
    pairwise_sums(&mut right, &mut left);
    (left, right)
}

/// With `right` holding P₀..Pₙ on entry, leaves the right half in it and writes the left half
/// into `left` (of the same length; its entries are only written).
#[inline(always)]
#[expect(
    clippy::needless_range_loop,
    reason = "the level r bounds the inner loop and indexes the left half"
)]
fn pairwise_sums<T: ControlPoint>(right: &mut [T], left: &mut [T]) {
    let len = right.len();
    // Reslicing tells the optimizer that `left` is as long as `right` (no bounds checks).
    let (Some(left), Some(&first)) = (left.get_mut(..len), right.first()) else {
        return;
    };
    left[0] = first;
    // Level r: right[i] = Sᵢʳ for i ≤ n − r; left[r] = 2⁻ʳ S₀ʳ.
    let mut scale = 1.0;
    for r in 1..len {
        for i in 0..len - r {
            right[i] = right[i] + right[i + 1];
        }
        scale *= 0.5;
        left[r] = right[0] * scale;
    }
    // right[i] holds Sᵢⁿ⁻ⁱ: scale it by 2⁻⁽ⁿ⁻ⁱ⁾.
    let mut scale = 1.0;
    for p in right.iter_mut().rev() {
        *p = *p * scale;
        scale *= 0.5;
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::{de_casteljau_split, de_casteljau_split_array};

    #[test]
    fn halves_of_a_quartic_by_hand() {
        // Sums of 0, 16, 0, 16, 0: levels (16, 16, 16, 16), (32, 32, 32), (64, 64), (128).
        let (mut left, mut right) = ([0.0; 5], [0.0; 5]);
        de_casteljau_halve(&[0.0, 16.0, 0.0, 16.0, 0.0], &mut left, &mut right).unwrap();
        assert_eq!(left, [0.0, 8.0, 8.0, 8.0, 8.0]);
        assert_eq!(right, [8.0, 8.0, 8.0, 8.0, 0.0]);
    }

    #[test]
    fn degenerate_lengths_and_wrong_buffers() {
        let (mut l, mut r) = ([0.0; 1], [0.0; 1]);
        de_casteljau_halve(&[2.5], &mut l, &mut r).unwrap();
        assert_eq!((l, r), ([2.5], [2.5]));
        de_casteljau_halve::<f64>(&[], &mut [], &mut []).unwrap();
        assert_eq!(
            de_casteljau_halve_in_place(&mut [0.0, 1.0], &mut [0.0]),
            Err(CoreError::BufferLength {
                len: 1,
                expected: 2
            })
        );
        let (mut l, mut r) = ([0.0; 3], [0.0; 2]);
        assert_eq!(
            de_casteljau_halve(&[0.0, 1.0], &mut l, &mut r),
            Err(CoreError::BufferLength {
                len: 3,
                expected: 2
            })
        );
    }

    fn coordinate() -> impl Strategy<Value = f64> {
        prop_oneof![
            Just(0.0),
            -1e3..1e3f64,
            (-1.0..1.0f64, -250..250i32).prop_map(|(m, e)| m * 10f64.powi(e)),
        ]
    }

    proptest! {
        /// Bit for bit de Casteljau at ½, on slices of degree 0..30 of 2-D points and on
        /// fixed-size cubics, with coordinates spanning 1e-250..1e250.
        #[test]
        fn equals_de_casteljau_at_one_half(
            pts in proptest::collection::vec((coordinate(), coordinate()), 1..31),
        ) {
            let pts: Vec<crate::Vector2> =
                pts.into_iter().map(|(x, y)| crate::Vector2::new(x, y)).collect();
            let n = pts.len();
            let (mut l, mut r) = (vec![pts[0]; n], vec![pts[0]; n]);
            de_casteljau_split(&pts, 0.5, &mut l, &mut r).unwrap();
            let (mut hl, mut hr) = (vec![pts[0]; n], vec![pts[0]; n]);
            de_casteljau_halve(&pts, &mut hl, &mut hr).unwrap();
            prop_assert_eq!(&hl, &l);
            prop_assert_eq!(&hr, &r);
            let (mut piece, mut il) = (pts.clone(), vec![pts[0]; n]);
            de_casteljau_halve_in_place(&mut piece, &mut il).unwrap();
            prop_assert_eq!(&il, &l);
            prop_assert_eq!(&piece, &r);
            if let [a, b, c, d, ..] = pts[..] {
                prop_assert_eq!(
                    de_casteljau_halve_array([a, b, c, d]),
                    de_casteljau_split_array([a, b, c, d], 0.5)
                );
            }
        }
    }
}
