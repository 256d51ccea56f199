//! Adaptive subdivision ("flattening") with per-piece stopping by eq. (3).

#[cfg(feature = "paper")]
use bez_core::BezierForm;
use bez_core::{BezierCurve, Vector2, de_casteljau_halve, de_casteljau_split};

use crate::error::SubdivError;
use crate::measure::within_chord_line;
use crate::split_rule::{Branch, SplitRule};

/// The paper's tolerance ε of eq. (3).
pub const DEFAULT_TOLERANCE: f64 = 1e-5;
/// Depth cap: a piece still not flat at this depth is an error, never an endless loop.
pub const DEFAULT_MAX_DEPTH: usize = 40;

/// Options of [`flatten`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct FlattenOptions {
    /// ε of eq. (3), relative to the original curve's size (default 1e-5).
    pub tolerance: f64,
    /// Where to split each piece (default: the fixed rule t = 0.5).
    pub rule: SplitRule,
    /// The depth cap (default 40).
    pub max_depth: usize,
}

impl FlattenOptions {
    /// With `tolerance` set to `value` (the relative ε of eq. (3)).
    #[must_use]
    pub fn with_tolerance(mut self, value: f64) -> Self {
        self.tolerance = value;
        self
    }

    /// With `rule` set to `value` (the split rule).
    #[must_use]
    pub fn with_rule(mut self, value: SplitRule) -> Self {
        self.rule = value;
        self
    }

    /// With `max_depth` set to `value` (the subdivision depth cap).
    #[must_use]
    pub fn with_max_depth(mut self, value: usize) -> Self {
        self.max_depth = value;
        self
    }
}

impl Default for FlattenOptions {
    fn default() -> Self {
        Self {
            tolerance: DEFAULT_TOLERANCE,
            rule: SplitRule::Fixed,
            max_depth: DEFAULT_MAX_DEPTH,
        }
    }
}

/// One final piece: its parameter range on the original curve and its control polygon.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Piece {
    /// Start parameter on the original curve.
    pub t0: f64,
    /// End parameter on the original curve.
    pub t1: f64,
    /// Control points of the piece (the curve restricted to [t0, t1]).
    pub points: Vec<Vector2>,
}

/// Counts of one flattening run (what the running time is proportional to).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FlattenStats {
    /// Deepest subdivision level any final piece needed (Table 1's "iteration count").
    pub depth: usize,
    /// Split operations performed (= pieces − 1).
    pub splits: usize,
    /// Final pieces.
    pub pieces: usize,
    /// Objective evaluations spent choosing split parameters.
    pub evaluations: usize,
}

/// The result of [`flatten`].
#[cfg(feature = "paper")]
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Flattening {
    /// The control polygons of the final pieces in order, joints not repeated.
    pub polyline: Vec<Vector2>,
    /// The final pieces in parameter order.
    pub pieces: Vec<Piece>,
    /// Counts.
    pub stats: FlattenStats,
}

/// The denominator of eq. (3): max(x extent, y extent) of the original control points.
#[must_use]
pub fn curve_size(curve: &BezierCurve<2>) -> f64 {
    let b = curve.control_bounding_box();
    let s = b.size();
    s.x().max(s.y())
}

/// The input checks of every eq. (3) flattening: ε positive and finite, at least two points.
pub(crate) fn validate(curve: &BezierCurve<2>, eps: f64) -> Result<(), SubdivError> {
    if !(eps.is_finite() && eps > 0.0) {
        return Err(SubdivError::InvalidTolerance { value: eps });
    }
    let n = curve.points().len();
    if n < 2 {
        return Err(SubdivError::TooFewPoints { got: n });
    }
    Ok(())
}

/// [`validate`] and the work limits of [`crate::limits::check_work`] for eq. (3)'s relative ε.
pub(crate) fn validate_with_depth(
    curve: &BezierCurve<2>,
    eps: f64,
    max_depth: usize,
) -> Result<(), SubdivError> {
    validate(curve, eps)?;
    let size = curve_size(curve);
    if size > 0.0 {
        crate::limits::check_work(curve, eps * size, max_depth)?;
    } else {
        crate::limits::check_work(curve, f64::INFINITY, max_depth)?;
    }
    Ok(())
}

/// Subdivides `curve` until every piece is flat by eq. (3) and returns the pieces' control
/// polygons as a polyline.
///
/// A piece P* stops when max_{i=1..n−1} D(P*₀P*ₙ, P*ᵢ) / max(x_max − x_min, y_max − y_min) ≤ ε,
/// the denominator taken from the original curve's control points (Ma et al., eq. (3)), so the
/// test is invariant under similarities. Pieces are split by `options.rule`; every piece stops on
/// its own (the algorithm as written). A curve whose control points all coincide is one piece.
///
/// Guarantee: every final piece lies, by the convex hull property, within ε · size of the line
/// through its end points. Eq. (3) measures distance to the chord's *line*: near cusps a piece
/// may fold back past an end point (see the paper doc).
///
/// Accepts any curve with a Bézier form ([`BezierForm`]: a `BezierCurve`, a λ-Bézier curve, a
/// Class A curve, a subdivision-curve segment) and flattens that form; the borrow is free.
///
/// Cost: O(n²) per split plus the rule's evaluations (13 or about 30 splits per optimized piece).
/// For the fixed rule, [`flatten_fixed_into`](crate::flatten_fixed_into) computes the same
/// polyline and counts without allocating per piece.
///
/// # Errors
/// [`SubdivError::TooFewPoints`] for a degree-0 curve, [`SubdivError::InvalidTolerance`],
/// [`SubdivError::DepthLimit`] when a piece is not flat at `max_depth`,
/// [`SubdivError::Optimizer`] from an exact rule;/// [`SubdivError::DepthTooLarge`] for `max_depth` above [`MAX_FLATTEN_DEPTH`](crate::MAX_FLATTEN_DEPTH),
/// [`SubdivError::ToleranceBelowRounding`] below 16 ulps of the largest coordinate (checked
/// before any work).
#[cfg(feature = "paper")]
pub fn flatten<C: BezierForm<2> + ?Sized>(
    curve: &C,
    options: &FlattenOptions,
) -> Result<Flattening, SubdivError> {
    flatten_bezier(curve.as_bezier(), options)
}

/// [`flatten`] on the Bézier form (one instance for every curve type).
#[cfg(feature = "paper")]
fn flatten_bezier(
    curve: &BezierCurve<2>,
    options: &FlattenOptions,
) -> Result<Flattening, SubdivError> {
    let mut pieces = Vec::new();
    let stats = subdivide(curve, options, |piece| pieces.push(piece))?;
    let mut polyline = Vec::with_capacity(pieces.len() * (curve.points().len() - 1) + 1);
    for (k, piece) in pieces.iter().enumerate() {
        let skip = usize::from(k > 0);
        polyline.extend_from_slice(&piece.points[skip..]);
    }
    Ok(Flattening {
        polyline,
        pieces,
        stats,
    })
}

/// The subdivision of [`flatten`]: sends each final piece to `emit` as soon as it is flat, in
/// parameter order, and returns the counts. On an error, the pieces before it have been sent.
///
/// # Errors
/// As [`flatten`].
pub(crate) fn subdivide(
    curve: &BezierCurve<2>,
    options: &FlattenOptions,
    mut emit: impl FnMut(Piece),
) -> Result<FlattenStats, SubdivError> {
    let eps = options.tolerance;
    validate_with_depth(curve, eps, options.max_depth)?;
    let n = curve.points().len();
    let size = curve_size(curve);
    let mut stats = FlattenStats::default();
    // Depth-first, left piece first, so pieces come out in parameter order.
    let mut stack = vec![(
        curve.points().to_vec(),
        0usize,
        0.0_f64,
        1.0_f64,
        Branch::Searching,
    )];
    while let Some((points, depth, t0, t1, branch)) = stack.pop() {
        let flat = size == 0.0 || within_chord_line(&points, eps * size);
        if flat {
            stats.depth = stats.depth.max(depth);
            stats.pieces += 1;
            emit(Piece { t0, t1, points });
            continue;
        }
        if depth >= options.max_depth {
            return Err(SubdivError::DepthLimit {
                limit: options.max_depth,
            });
        }
        let choice = options.rule.choose(&points, depth, branch)?;
        stats.evaluations += choice.evaluations;
        stats.splits += 1;
        let mut left = vec![Vector2::zeros(); n];
        let mut right = vec![Vector2::zeros(); n];
        if choice.t == 0.5 {
            // The same halving as the fixed rule's fast path, bit for bit.
            de_casteljau_halve(&points, &mut left, &mut right)?;
        } else {
            de_casteljau_split(&points, choice.t, &mut left, &mut right)?;
        }
        let tm = t0 + choice.t * (t1 - t0);
        // A settled branch stays settled.
        let keep = match branch {
            Branch::Searching => choice.next,
            Branch::Settled => Branch::Settled,
        };
        stack.push((right, depth + 1, tm, t1, keep));
        stack.push((left, depth + 1, t0, tm, keep));
    }
    Ok(stats)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::assert_typed_errors;

    #[test]
    fn errors_are_typed() {
        assert_typed_errors(|c, tolerance, max_depth| {
            let options = FlattenOptions::default()
                .with_tolerance(tolerance)
                .with_max_depth(max_depth);
            subdivide(c, &options, |_| {})
        });
    }

    #[test]
    fn collapsed_and_straight_curves_terminate_as_one_piece() {
        let dot = BezierCurve::new(vec![Vector2::new(3.0, 3.0); 5]).unwrap();
        let stats = subdivide(&dot, &FlattenOptions::default(), |_| {}).unwrap();
        assert_eq!((stats.pieces, stats.splits), (1, 0));
        let line = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 1.0),
            Vector2::new(3.0, 3.0),
        ])
        .unwrap();
        assert_eq!(
            subdivide(&line, &FlattenOptions::default(), |_| {})
                .unwrap()
                .pieces,
            1
        );
    }
}
