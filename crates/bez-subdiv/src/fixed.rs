//! Halving at t = ½ without per-piece allocation: the engine of the subdividing methods, and
//! the fixed rule's fast path of [`flatten`].
//!
//! [`flatten`]: crate::flatten()

#[cfg(feature = "paper")]
use bez_core::{BezierCurve, BezierForm};
use bez_core::{Vector2, de_casteljau_halve_array, de_casteljau_halve_in_place};

use crate::error::SubdivError;
use crate::flatten::DEFAULT_MAX_DEPTH;
#[cfg(feature = "paper")]
use crate::flatten::{FlattenStats, curve_size, validate_with_depth};
#[cfg(any(test, feature = "paper"))]
use crate::measure::within_chord_line;

/// The polyline of [`flatten`](crate::flatten()) with [`SplitRule::Fixed`](crate::SplitRule),
/// written into `polyline` (cleared first, its capacity reused), and the run's counts.
///
/// The same algorithm as the general path, step for step: a piece stops when eq. (3) holds,
/// max_{i=1..n−1} D(P₀Pₙ, Pᵢ) ≤ ε · max(x extent, y extent) of the original control points, and
/// is otherwise halved by de Casteljau at t = ½, left piece first. The output equals
/// `flatten(curve, &FlattenOptions::default().with_rule(SplitRule::Fixed))`'s polyline and counts bit for
/// bit; what differs is the storage: pending pieces live in one flat buffer used as a stack (at
/// most `max_depth` + 1 pieces), final pieces go straight into the polyline, and nothing is
/// allocated per piece. Piece parameter ranges are not recorded.
///
/// # Errors
/// As [`flatten`](crate::flatten()): [`SubdivError::TooFewPoints`],
/// [`SubdivError::InvalidTolerance`], [`SubdivError::DepthLimit`],/// [`SubdivError::DepthTooLarge`] for `max_depth` above [`MAX_FLATTEN_DEPTH`](crate::MAX_FLATTEN_DEPTH),
/// [`SubdivError::ToleranceBelowRounding`] below 16 ulps of the largest coordinate (checked
/// before any work).
#[cfg(feature = "paper")]
pub fn flatten_fixed_into<C: BezierForm<2> + ?Sized>(
    curve: &C,
    tolerance: f64,
    max_depth: usize,
    polyline: &mut Vec<Vector2>,
) -> Result<FlattenStats, SubdivError> {
    fixed_into_bezier(curve.as_bezier(), tolerance, max_depth, polyline)
}

/// [`flatten_fixed_into`] on the Bézier form (one instance for every curve type).
#[cfg(feature = "paper")]
fn fixed_into_bezier(
    curve: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
    polyline: &mut Vec<Vector2>,
) -> Result<FlattenStats, SubdivError> {
    validate_with_depth(curve, tolerance, max_depth)?;
    polyline.clear();
    let size = curve_size(curve);
    let mut stats = FlattenStats::default();
    if size == 0.0 {
        // All control points coincide: one piece, as in the general path.
        polyline.extend_from_slice(curve.points());
        stats.pieces = 1;
        return Ok(stats);
    }
    let limit = tolerance * size;
    // Every piece starts where the previous one ended (the first at B(0) = P₀, exactly).
    polyline.push(curve.start());
    let mut depth = 0;
    stats.splits = halve_until(
        curve.points(),
        max_depth,
        |piece| within_chord_line(piece, limit),
        |piece, level| {
            depth = depth.max(level);
            polyline.extend_from_slice(piece.get(1..).unwrap_or_default());
        },
    )?;
    stats.depth = depth;
    // Each halving turns one piece into two.
    stats.pieces = stats.splits + 1;
    Ok(stats)
}

/// Depth-first halving at t = ½ of the control polygon `points`, left piece first, until
/// `accept` holds for a piece; `emit` receives each accepted piece and its level, in parameter
/// order. Returns the number of halvings.
///
/// Lines, quadratics and cubics are halved on fixed-size arrays (the loops unroll, the pieces
/// stay in registers), other degrees on one flat buffer; nothing is allocated per piece.
///
/// # Errors
/// [`SubdivError::DepthLimit`] when a piece is not accepted at level `max_depth`.
#[inline(always)]
pub(crate) fn halve_until(
    points: &[Vector2],
    max_depth: usize,
    accept: impl FnMut(&[Vector2]) -> bool,
    emit: impl FnMut(&[Vector2], usize),
) -> Result<usize, SubdivError> {
    match points {
        [a, b] => run_array([*a, *b], max_depth, accept, emit),
        [a, b, c] => run_array([*a, *b, *c], max_depth, accept, emit),
        [a, b, c, d] => run_array([*a, *b, *c, *d], max_depth, accept, emit),
        _ => run(FlatStack::new(points), max_depth, accept, emit),
    }
}

/// [`halve_until`] on pieces of `N` control points held by value: the current piece stays in
/// registers and descends into its left half; right halves wait on a stack with their levels,
/// an array in the call's stack frame when `max_depth` ≤ [`INLINE_LEVELS`], a `Vec` otherwise.
///
/// Kept out of line: one small function per degree and caller, with the caller's closures
/// inlined into it, measured about 4 % faster on the peer cubics than inlining every degree's
/// loop into one caller.
#[inline(never)]
fn run_array<const N: usize>(
    points: [Vector2; N],
    max_depth: usize,
    accept: impl FnMut(&[Vector2]) -> bool,
    emit: impl FnMut(&[Vector2], usize),
) -> Result<usize, SubdivError> {
    if max_depth <= INLINE_LEVELS {
        let mut pending = InlineStack {
            items: [([Vector2::zeros(); N], 0); INLINE_LEVELS],
            len: 0,
        };
        descend(points, &mut pending, max_depth, accept, emit)
    } else {
        descend(points, &mut Vec::with_capacity(64), max_depth, accept, emit)
    }
}

/// Depth caps up to which [`run_array`] keeps the pending pieces in an array (the default cap
/// among them): the whole flattening of the peer cubics measured 20–25 % faster than with the
/// pieces pushed onto a `Vec` (no length, capacity and pointer traffic per node).
const INLINE_LEVELS: usize = DEFAULT_MAX_DEPTH;

/// Storage of the pending pieces of [`descend`], the next one on top.
trait Pending<T> {
    /// Pushes `item`; the caller makes sure there is room.
    fn push(&mut self, item: T);
    /// Removes and returns the top item.
    fn pop(&mut self) -> Option<T>;
}

/// Up to `C` pending items in an array, `items[..len]`.
struct InlineStack<T, const C: usize> {
    items: [T; C],
    len: usize,
}

impl<T: Copy, const C: usize> Pending<T> for InlineStack<T, C> {
    #[inline(always)]
    fn push(&mut self, item: T) {
        let slot = self.items.get_mut(self.len);
        debug_assert!(slot.is_some(), "a full inline stack takes no push");
        if let Some(slot) = slot {
            *slot = item;
            self.len += 1;
        }
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<T> {
        self.len = self.len.checked_sub(1)?;
        self.items.get(self.len).copied()
    }
}

impl<T> Pending<T> for Vec<T> {
    #[inline(always)]
    fn push(&mut self, item: T) {
        Vec::push(self, item);
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<T> {
        Vec::pop(self)
    }
}

/// The loop of [`run_array`] with `pending` holding the right halves.
///
/// Each pending piece is one level deeper than the one below it and pieces are halved above
/// `max_depth` only, so `pending` never holds more than `max_depth` pieces.
#[inline(always)]
fn descend<const N: usize>(
    points: [Vector2; N],
    pending: &mut impl Pending<([Vector2; N], usize)>,
    max_depth: usize,
    mut accept: impl FnMut(&[Vector2]) -> bool,
    mut emit: impl FnMut(&[Vector2], usize),
) -> Result<usize, SubdivError> {
    let (mut piece, mut level) = (points, 0);
    let mut splits = 0;
    loop {
        if accept(&piece) {
            emit(&piece, level);
            match pending.pop() {
                Some(next) => (piece, level) = next,
                None => return Ok(splits),
            }
            continue;
        }
        if level >= max_depth {
            return Err(SubdivError::DepthLimit { limit: max_depth });
        }
        splits += 1;
        level += 1;
        let (left, right) = de_casteljau_halve_array(piece);
        pending.push((right, level));
        piece = left;
    }
}

/// The pending pieces of a depth-first subdivision with their levels, the next piece on top.
trait PieceStack {
    /// The control polygon and level of the top piece, `None` when the stack is empty.
    fn top(&self) -> Option<(&[Vector2], usize)>;
    /// Removes the top piece.
    fn pop(&mut self);
    /// Replaces the top piece by its halves one level deeper, the left half on top.
    fn halve_top(&mut self) -> Result<(), SubdivError>;
}

/// Pieces of n control points, piece k at `buffer[k n .. (k + 1) n]` and level `depths[k]`.
struct FlatStack {
    n: usize,
    buffer: Vec<Vector2>,
    depths: Vec<usize>,
}

impl FlatStack {
    fn new(points: &[Vector2]) -> Self {
        let mut buffer = Vec::with_capacity(points.len() * 64);
        buffer.extend_from_slice(points);
        let mut depths = Vec::with_capacity(64);
        depths.push(0);
        Self {
            n: points.len(),
            buffer,
            depths,
        }
    }
}

impl PieceStack for FlatStack {
    fn top(&self) -> Option<(&[Vector2], usize)> {
        let depth = *self.depths.last()?;
        let start = self.buffer.len().saturating_sub(self.n);
        Some((&self.buffer[start..], depth))
    }

    fn pop(&mut self) {
        self.buffer
            .truncate(self.buffer.len().saturating_sub(self.n));
        self.depths.pop();
    }

    fn halve_top(&mut self) -> Result<(), SubdivError> {
        let Some(depth) = self.depths.last_mut() else {
            return Ok(());
        };
        *depth += 1;
        let depth = *depth;
        self.depths.push(depth);
        let start = self.buffer.len().saturating_sub(self.n);
        self.buffer.resize(start + 2 * self.n, Vector2::zeros());
        // The piece becomes its right half where it lies; the left half goes on top.
        let (piece, left) = self.buffer[start..].split_at_mut(self.n);
        de_casteljau_halve_in_place(piece, left)?;
        Ok(())
    }
}

/// The loop of [`halve_until`] on a stack holding the whole curve (degree 4 and up).
fn run<S: PieceStack>(
    mut stack: S,
    max_depth: usize,
    mut accept: impl FnMut(&[Vector2]) -> bool,
    mut emit: impl FnMut(&[Vector2], usize),
) -> Result<usize, SubdivError> {
    let mut splits = 0;
    while let Some((piece, depth)) = stack.top() {
        if accept(piece) {
            emit(piece, depth);
            stack.pop();
            continue;
        }
        if depth >= max_depth {
            return Err(SubdivError::DepthLimit { limit: max_depth });
        }
        splits += 1;
        stack.halve_top()?;
    }
    Ok(splits)
}

#[cfg(test)]
mod tests {
    use bez_core::proptest_support::curve;
    use proptest::prelude::*;

    use super::*;

    /// Accepted pieces with their levels, and the halving count.
    type Leaves = Result<(Vec<(Vec<Vector2>, usize)>, usize), SubdivError>;

    /// The array loop with pending pieces in `pending`.
    fn array_leaves(
        points: [Vector2; 4],
        pending: &mut impl Pending<([Vector2; 4], usize)>,
        limit: f64,
        depth: usize,
    ) -> Leaves {
        let mut leaves = Vec::new();
        let splits = descend(
            points,
            pending,
            depth,
            |piece| within_chord_line(piece, limit),
            |piece, level| leaves.push((piece.to_vec(), level)),
        )?;
        Ok((leaves, splits))
    }

    /// An empty array stack of `C` cubic pieces.
    fn empty<const C: usize>() -> InlineStack<([Vector2; 4], usize), C> {
        InlineStack {
            items: [([Vector2::zeros(); 4], 0); C],
            len: 0,
        }
    }

    /// The slice loop on the flat buffer.
    fn flat_leaves(points: [Vector2; 4], limit: f64, depth: usize) -> Leaves {
        let mut leaves = Vec::new();
        let splits = run(
            FlatStack::new(&points),
            depth,
            |piece| within_chord_line(piece, limit),
            |piece, level| leaves.push((piece.to_vec(), level)),
        )?;
        Ok((leaves, splits))
    }

    proptest! {
        /// An array of exactly `max_depth` pending pieces is enough (a full array would drop
        /// pieces), and the array, a `Vec` and the slice loop give the same pieces, levels,
        /// halving count and errors; tight tolerances and small caps make deep descents and
        /// failures common.
        #[test]
        fn array_of_max_depth_pieces_suffices(
            c in curve::<2>(3..=3, 10.0),
            exponent in 1.0..9.0f64,
        ) {
            let points = [c.points()[0], c.points()[1], c.points()[2], c.points()[3]];
            let limit = 10f64.powf(-exponent);
            for depth in [1, 2, 5, 12] {
                let reference = flat_leaves(points, limit, depth);
                prop_assert_eq!(&array_leaves(points, &mut Vec::new(), limit, depth), &reference);
                let result = match depth {
                    1 => array_leaves(points, &mut empty::<1>(), limit, depth),
                    2 => array_leaves(points, &mut empty::<2>(), limit, depth),
                    5 => array_leaves(points, &mut empty::<5>(), limit, depth),
                    _ => array_leaves(points, &mut empty::<12>(), limit, depth),
                };
                prop_assert_eq!(&result, &reference);
            }
        }
    }
}
