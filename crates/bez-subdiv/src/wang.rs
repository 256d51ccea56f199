//! Beyond the paper: the fastest guaranteed flattening, Wang's uniform count with the points
//! streamed to a sink.

use bez_core::{BezierForm, HornerBernstein, Vector2};

use crate::bound::wang_count;
use crate::error::SubdivError;
use crate::forward_difference::{self, Step, rounding_allowance};
use crate::guaranteed::FlatPoint;
use crate::stack_horner::{STACK_POINTS, StackHorner};

/// The most segments one call of [`Method::Fast`](crate::Method::Fast) produces: 2²⁴. A tolerance that needs more
/// (below the rounding of the coordinates, in practice) is refused before any point is made.
pub const MAX_WANG_SEGMENTS: usize = 1 << 24;

/// The largest count that [`flatten_wang_small`] reads from [`FOURTH_POWERS`]; larger counts
/// take two square roots (amortized over more than 64 points), see [`UniformCount::new`].
const TABLE_COUNTS: usize = 64;

/// i⁴ for i = 0..=[`TABLE_COUNTS`] + 2, exact in f64, except entry 0, −1 (every q ≥ 0 is
/// above it: the count is at least 1).
const FOURTH_POWERS: [f64; TABLE_COUNTS + 3] = {
    let mut table = [-1.0; TABLE_COUNTS + 3];
    let mut i = 1;
    while i < TABLE_COUNTS + 3 {
        let k = i as f64;
        table[i] = k * k * k * k;
        i += 1;
    }
    table
};

/// The step h = 1/i with its powers ([`Step`]) for i = 0..=[`TABLE_COUNTS`] (entry 0 unused),
/// each the correctly rounded value, as `Step::new(1.0 / i as f64)` at run time: the parameters
/// k/N come out bit for bit as on the general path, and the powers of the step are ready
/// together with it (no multiplication between the count and the first point).
const STEPS: [Step; TABLE_COUNTS + 1] = {
    let mut table = [Step::new(0.0); TABLE_COUNTS + 1];
    let mut i = 1;
    while i <= TABLE_COUNTS {
        table[i] = Step::new(1.0 / i as f64);
        i += 1;
    }
    table
};

/// 1 + 2⁻⁴⁶: the factor by which the square-root path of [`UniformCount::new`] and its test
/// for forward differences enlarge the computed fourth power of Wang's count.
const ROUND_UP: f64 = 1.0 + 1.0 / (1_u64 << 46) as f64;

/// fl(i⁴ − i⁴ 2⁻⁴⁵) for i = 0..=[`TABLE_COUNTS`] + 2 (entry 0, −1: every q ≥ 0 is above it):
/// the largest computed fourth power q that [`table_count`] gives the count i, each below i⁴ by
/// a relative 2⁻⁴⁵ up to one rounding (see there). Comparing q with these instead of
/// enlarging q first takes one multiplication off the way to the first point.
const COUNT_BOUNDS: [f64; TABLE_COUNTS + 3] = {
    let mut table = [-1.0; TABLE_COUNTS + 3];
    let mut i = 1;
    while i < TABLE_COUNTS + 3 {
        table[i] = FOURTH_POWERS[i] - FOURTH_POWERS[i] / (1_u64 << 45) as f64;
        i += 1;
    }
    table
};

/// Wang's count N = max(1, ⌈q^¼⌉) from `q`, its fourth power as computed, without a square
/// root: [`count_from_fourth_power`] of q, the smallest i ≥ 1 with q ≤ [`COUNT_BOUNDS`]`[i]`.
/// `None` when that is above [`TABLE_COUNTS`] or `q` is not a number.
///
/// Conservative, so the guarantee of Wang's count holds: let Q = (c |d| / tol)² be the exact
/// fourth power for the second difference d as computed (c = n(n − 1)/8). The caller computes
/// q = fl(‖fl(d · fl(c / tol))‖²) in six rounding steps at most (the quotient, one product per
/// coordinate, one square each and their sum; for a cubic the larger of two such sums), each
/// within a relative 2⁻⁵³ while no step underflows, so q ≥ Q (1 − 2⁻⁵⁰). The bound of count i
/// is i⁴ (1 − 2⁻⁴⁵) rounded once (i⁴ 2⁻⁴⁵ is exact), so at most i⁴ (1 − 2⁻⁴⁵)(1 + 2⁻⁵³), and
/// q ≤ that gives Q ≤ i⁴ (1 − 2⁻⁴⁵)(1 + 2⁻⁵³) / (1 − 2⁻⁵⁰) < i⁴: the count i found has
/// i ≥ ⌈Q^¼⌉. Underflow only adds an absolute error below 2⁻⁹⁰⁰ to a Q itself below 1, where
/// every count i ≥ 1 is enough. The count therefore never rounds down; it is one above the
/// square-root formula ([`wang_count`], ⌈√(c |d| / tol)⌉) only when that formula's unrounded
/// value lies within about 2⁻⁴⁶ of a whole number (tested, with exact integer arithmetic as the
/// oracle).
#[inline(always)]
pub(crate) fn table_count(q: f64) -> Option<usize> {
    // q ≥ 0 (a sum of squares) or NaN.
    if q.is_nan() || q > COUNT_BOUNDS[TABLE_COUNTS] {
        return None;
    }
    Some(count_from_fourth_power(q))
}

/// The buckets of [`first_guess`]: q in [1, 2²⁵) split by its binary exponent and the three
/// leading bits of its mantissa (192 buckets up to [`TABLE_COUNTS`]⁴ = 2²⁴, one more for 2²⁴).
const BUCKETS: usize = 193;

/// For each bucket m of [`first_guess`], the count of its smallest q,
/// L = 2^⌊m/8⌋ (1 + (m mod 8)/8), L = 0 for bucket 0 (which holds every q below 1 too): the
/// smallest i ≥ 1 with L ≤ [`COUNT_BOUNDS`]`[i]`.
const FIRST_COUNTS: [u8; BUCKETS] = {
    let mut table = [0; BUCKETS];
    let mut m = 0;
    while m < BUCKETS {
        // Bucket 0 also holds every q below 1.
        let low = if m == 0 {
            0.0
        } else {
            (1_u64 << (m / 8)) as f64 * (1.0 + (m % 8) as f64 / 8.0)
        };
        let mut i = 1;
        while COUNT_BOUNDS[i] < low {
            i += 1;
        }
        table[m] = i as u8;
        m += 1;
    }
    table
};

/// For each bucket m of [`first_guess`], the bounds ([`COUNT_BOUNDS`]) of the counts b and
/// b + 1, b = [`FIRST_COUNTS`]`[m]`: what [`count_from_fourth_power`] compares q with, read in
/// the same step as b.
const BUCKET_POWERS: [[f64; 2]; BUCKETS] = {
    let mut table = [[0.0; 2]; BUCKETS];
    let mut m = 0;
    while m < BUCKETS {
        let b = FIRST_COUNTS[m] as usize;
        table[m] = [COUNT_BOUNDS[b], COUNT_BOUNDS[b + 1]];
        m += 1;
    }
    table
};

/// The smallest i ≥ 1 with q ≤ Cᵢ ([`COUNT_BOUNDS`]), for 0 ≤ q ≤ C₆₄, without a search or a
/// data-dependent branch: a first guess b from the bits of q ([`first_guess`]), then b plus
/// the number of C_b and C_b+1 that q exceeds (both read from [`BUCKET_POWERS`] beside b,
/// not after it), which is the count whenever b ≤ count ≤ b + 2. That holds on all of
/// [0, C₆₄]: b is a non-decreasing function of q (the bits of a non-negative f64 grow with it,
/// and the table grows), so on each interval (Cᵢ₋₁, Cᵢ] of count i it is enough that b ≤ i at
/// its top and b ≥ i − 2 just above its bottom, which a test checks for every i.
#[inline(always)]
fn count_from_fourth_power(q: f64) -> usize {
    let m = bucket(q);
    let [low, high] = BUCKET_POWERS[m];
    usize::from(FIRST_COUNTS[m]) + usize::from(q > low) + usize::from(q > high)
}

/// The bucket of q: its biased binary exponent times eight plus the three leading bits of its
/// mantissa, counted from q = 1 (q below 1, the first bucket), at most the last. One
/// comparison and integer operations.
#[inline(always)]
fn bucket(q: f64) -> usize {
    // The bits of an f64 of at least 1 shifted right by 49: 8 × biased exponent + three bits,
    // at least 8 × 1023.
    #[allow(
        clippy::cast_possible_truncation,
        reason = "a 15-bit value after the shift"
    )]
    let bits = (q.max(1.0).to_bits() >> 49) as usize;
    bits.wrapping_sub(8 * 1023).min(BUCKETS - 1)
}

/// The count of the smallest q of q's bucket ([`FIRST_COUNTS`]; below 1, count 1).
#[cfg(test)]
fn first_guess(q: f64) -> usize {
    usize::from(FIRST_COUNTS[bucket(q)])
}

/// 2^±128: [`flatten_wang_small`] runs where the largest coordinate is surely within the range
/// inside which `Flattener` does not rescale the curve (the same bounds).
const UNIT_LOW: f64 = 1.0 / UNIT_HIGH;
const UNIT_HIGH: f64 = 340_282_366_920_938_463_463_374_607_431_768_211_456.0;

/// The sum s of the absolute coordinates of `points` when it lies in [2k · 2⁻¹²⁸, 2¹²⁸]
/// (k points): then the largest coordinate m, with s / 2k ≤ m ≤ s, lies within 2^±128, the
/// range in which `Flattener` flattens a curve as it is. One sum and one range test instead of
/// a maximum (a NaN or infinite coordinate fails it too). s is also the size in the rounding
/// bound of the forward differences ([`rounding_allowance`]).
#[inline(always)]
fn unit_size_sum<const K: usize>(points: &[Vector2; K]) -> Option<f64> {
    let sum = points.iter().fold(Vector2::zeros(), |acc, p| acc + p.abs());
    let sum = sum.x() + sum.y();
    (2.0 * K as f64 * UNIT_LOW..=UNIT_HIGH)
        .contains(&sum)
        .then_some(sum)
}

/// (2²⁴)⁴ = 2⁹⁶: the fourth power of [`MAX_WANG_SEGMENTS`]; above it [`flatten_wang`] decides
/// (and refuses the count).
const MAX_FOURTH_POWER: f64 = 79_228_162_514_264_337_593_543_950_336.0;

/// The share of the tolerance that the rounding of the forward differences may take at most
/// (2⁻¹⁰): above it, that is where the tolerance is below about 2⁻⁴⁰ s / (N + 64), the points
/// are evaluated one by one.
const MAX_ROUNDING_SHARE: f64 = 1.0 / 1024.0;

/// 2⁻²⁶: the relative enlargement of the chord bound by the rounding of the count and of the
/// step (see [`UniformCount::new`]).
const CHORD_ROUNDING: f64 = 1.0 / (1_u64 << 26) as f64;

/// Wang's count of [`flatten_wang_small`], its step, and whether the points may be computed by
/// forward differences.
struct UniformCount {
    /// N.
    segments: usize,
    /// fl(1/N) and its powers.
    step: Step,
    /// Whether the rounding allowance of the forward differences fits beside the chord error.
    forward: bool,
}

/// i⁴ (1 − 2⁻²⁰) for i = 0..=[`TABLE_COUNTS`] (exact in f64: at most 24 significant bits
/// times 20): on the table path, forward differences need q (1 + 2⁻⁴⁶) at most this (see
/// [`UniformCount::new`]).
const ROOMY_FOURTH_POWERS: [f64; TABLE_COUNTS + 1] = {
    let mut table = [0.0; TABLE_COUNTS + 1];
    let mut i = 1;
    while i <= TABLE_COUNTS {
        table[i] = FOURTH_POWERS[i] * (1.0 - 1.0 / (1 << 20) as f64);
        i += 1;
    }
    table
};

/// 2²¹: on the table path, forward differences need s ≤ 2²¹ tol (see [`UniformCount::new`]).
const TABLE_SIZE_OVER_TOLERANCE: f64 = (1 << 21) as f64;

impl UniformCount {
    /// From q, the fourth power of Wang's unrounded count as computed (see [`table_count`]),
    /// `size` the sum s of the absolute coordinates and the tolerance; `None` when q is not a
    /// number or the count is above [`MAX_WANG_SEGMENTS`].
    ///
    /// N: up to [`TABLE_COUNTS`] by [`table_count`] (no square root); above, ⌈q'^¼⌉ by two
    /// square roots of q' = q (1 + 2⁻⁴⁶), which is above the exact fourth power Q by a relative
    /// 2⁻⁴⁷ at least and so stays above it through the two roundings: N ≥ ⌈Q^¼⌉ on both paths.
    ///
    /// Forward differences are allowed when their rounding allowance E
    /// ([`rounding_allowance`]) is at most [`MAX_ROUNDING_SHARE`] × tol and fits beside the
    /// chord error: the chord of a parameter step 1/N deviates by at most √Q / N² × tol, and
    /// the steps taken, fl(1/N) and the last one 1 − (N − 1) fl(1/N), are longer than 1/N by a
    /// relative N u ≤ 2⁻²⁹ at most, which makes the chord bound at most (√Q / N² + 2⁻²⁶) tol
    /// ([`CHORD_ROUNDING`]). So forward differences keep the guarantee when
    /// E + 2⁻²⁶ tol ≤ (1 − √Q / N²) tol, tested without a square root:
    ///
    /// - Up to [`TABLE_COUNTS`] segments, with two comparisons: q' ≤ N⁴ (1 − 2⁻²⁰)
    ///   ([`ROOMY_FOURTH_POWERS`]) gives √Q / N² ≤ √(q' / N⁴) ≤ (1 + q' / N⁴) / 2 ≤ 1 − 2⁻²¹,
    ///   and s ≤ 2²¹ tol ([`TABLE_SIZE_OVER_TOLERANCE`]) gives E ≤ 2⁻⁵⁰ s (64 + 64) = 2⁻⁴³ s
    ///   ≤ 2⁻²² tol, and 2⁻²² + 2⁻²⁶ < 2⁻²¹ (the rounding of s, a few units of 2⁻⁵³, is
    ///   inside that margin). It fails where the chord bound is within about 2⁻²¹ of the
    ///   tolerance (a relative 2⁻²² of N), or for a tolerance below 2⁻²¹ s.
    /// - Above, √Q / N² ≤ (1 + 2u) r / N² with r = fl(√q'). With the slack (N² − r) / N², the
    ///   test 2 (E + 2⁻²⁶ tol) N² ≤ tol (N² − r), evaluated in floating point (the factor 2
    ///   covers its own rounding), and E ≤ tol / 1024. It fails only where the chord bound is
    ///   within about 2⁻²⁵ tol of the tolerance, or for a tolerance below about
    ///   2⁻⁴⁰ s (N + 64).
    ///
    /// Where it fails, the points are evaluated.
    #[inline(always)]
    fn new(q: f64, size: f64, tolerance: f64) -> Option<Self> {
        if let Some(n) = table_count(q) {
            let forward = q.abs() * ROUND_UP <= ROOMY_FOURTH_POWERS[n]
                && size <= TABLE_SIZE_OVER_TOLERANCE * tolerance;
            return Some(Self {
                segments: n,
                step: STEPS[n],
                forward,
            });
        }
        let q = q.abs() * ROUND_UP;
        if q.is_nan() || q > MAX_FOURTH_POWER {
            return None;
        }
        let r = q.sqrt();
        let steps = r.sqrt();
        // 0 < steps ≤ 2²⁴: the truncation is exact, and so is its conversion back.
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "0 < steps <= 2^24"
        )]
        let whole = steps as usize;
        let segments = if (whole as f64) < steps {
            whole + 1
        } else {
            whole
        };
        let n2 = (segments * segments) as f64;
        let allowance = rounding_allowance(size, segments as f64);
        let forward = allowance <= MAX_ROUNDING_SHARE * tolerance
            && 2.0 * (allowance + CHORD_ROUNDING * tolerance) * n2 <= tolerance * (n2 - r);
        Some(Self {
            segments,
            step: Step::new(1.0 / segments as f64),
            forward,
        })
    }
}

/// `Method::Fast` on a quadratic or a cubic without a data-dependent branch before the points
/// up to [`TABLE_COUNTS`] segments: Wang's count by [`UniformCount`] (q = (n(n − 1)/8 · |d| /
/// tol)² with d the largest second difference), then the points by forward differences
/// ([`forward_difference`](crate::forward_difference), two or three vector additions per
/// point) where their rounding fits in the tolerance (on usual input), otherwise by
/// Horner's rule on the power form relative to P₀. Returns `None` before sending any point
/// when the curve is not a quadratic or a cubic, the tolerance is not a normal positive
/// number, the curve is not surely of unit size ([`unit_size_sum`]) or the count is above
/// [`MAX_WANG_SEGMENTS`]: [`flatten_wang`] then decides (the same count, up to one more here
/// at exact boundaries, see [`table_count`]).
#[inline(always)]
pub(crate) fn flatten_wang_small(
    points: &[Vector2],
    tolerance: f64,
    sink: impl FnMut(FlatPoint),
) -> Option<usize> {
    if !(f64::MIN_POSITIVE..=f64::MAX).contains(&tolerance) {
        return None;
    }
    match *points {
        [p0, p1, p2] => {
            let size = unit_size_sum(&[p0, p1, p2])?;
            // B(t) = P₀ + t (a + t d), a = 2(P₁ − P₀), d = P₀ − 2P₁ + P₂; n(n − 1)/8 = 1/4.
            let d = p0 - p1 * 2.0 + p2;
            let count =
                UniformCount::new((d * (0.25 / tolerance)).norm_squared(), size, tolerance)?;
            let (n, step) = (count.segments, count.step);
            let a = (p1 - p0) * 2.0;
            Some(if count.forward {
                forward_difference::quadratic([p0, a, d], p2, n, step, sink)
            } else {
                uniform(n, step.h, p0, p2, |t| p0 + (a + d * t) * t, sink)
            })
        }
        [p0, p1, p2, p3] => {
            let size = unit_size_sum(&[p0, p1, p2, p3])?;
            // B(t) = P₀ + t (a + t (b + t c)), a = 3(P₁ − P₀), b = 3 d₀, c = d₁ − d₀ with the
            // second differences d₀ = P₀ − 2P₁ + P₂, d₁ = P₁ − 2P₂ + P₃; n(n − 1)/8 = 3/4.
            let (d0, d1) = (p0 - p1 * 2.0 + p2, p1 - p2 * 2.0 + p3);
            let k = 0.75 / tolerance;
            let (q0, q1) = ((d0 * k).norm_squared(), (d1 * k).norm_squared());
            let count = UniformCount::new(if q0 > q1 { q0 } else { q1 }, size, tolerance)?;
            let (n, step) = (count.segments, count.step);
            let (a, b, c) = ((p1 - p0) * 3.0, d0 * 3.0, d1 - d0);
            Some(if count.forward {
                forward_difference::cubic([p0, a, b, c], p3, n, step, sink)
            } else {
                // (P₀ + a t) + (b + c t) t²: two short chains instead of Horner's one long one.
                let eval = |t: f64| (p0 + a * t) + (b + c * t) * (t * t);
                uniform(n, step.h, p0, p3, eval, sink)
            })
        }
        _ => None,
    }
}

/// Streams the points B(k/N), k = 0..=N, of Wang's uniform flattening to `sink` and returns
/// N, the number of segments: the polyline is within `tolerance` (absolute) of the curve in
/// Hausdorff distance.
///
/// N = max(1, ⌈√(n(n − 1) M / (8 tol))⌉) with M the largest second difference of the control
/// points ([`wang_segment_count`](crate::wang_segment_count)): the chord of a parameter step h interpolates B within
/// h²/8 · max|B''| and |B''| ≤ n(n − 1) M. The same count as lyon_geom's
/// `for_each_flattened` for quadratics and cubics (about twice the optimal count on curved
/// pieces; `Method::Optimal` places about half as many);
/// no subdivision, no allocation. (`Flattener` sends quadratics and cubics of usual size to
/// [`flatten_wang_small`] first, which computes the points by forward differences.) Points
/// here: up to degree 3 by Horner's rule on the power form relative to P₀ (a few multiply-adds per point, and a translation of the curve changes
/// nothing but the added P₀); above, by [`HornerBernstein`], O(n) per point. The first and
/// last points are P₀ and Pₙ exactly.
///
/// # Errors
/// [`SubdivError::TooFewPoints`] for a degree-0 curve, [`SubdivError::InvalidTolerance`],
/// [`SubdivError::TooManySegments`] above [`MAX_WANG_SEGMENTS`].
///
pub(crate) fn flatten_wang<C: BezierForm<2> + ?Sized>(
    curve: &C,
    tolerance: f64,
    sink: impl FnMut(FlatPoint),
) -> Result<usize, SubdivError> {
    let bezier = curve.as_bezier();
    let p = bezier.points();
    if p.len() < 2 {
        return Err(SubdivError::TooFewPoints { got: p.len() });
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(SubdivError::InvalidTolerance { value: tolerance });
    }
    // Wang's count, checked before the first point. Up to degree 3 it is taken on a
    // fixed-size copy of the control points, so that the second differences unroll.
    let count = |q: &[Vector2]| match wang_count(q, tolerance) {
        Some(n) if n <= MAX_WANG_SEGMENTS => Ok(n),
        _ => Err(SubdivError::TooManySegments {
            tolerance,
            limit: MAX_WANG_SEGMENTS,
        }),
    };
    match *p {
        [p0, p1] => {
            let a = p1 - p0;
            let n = count(&[p0, p1])?;
            Ok(uniform(n, 1.0 / n as f64, p0, p1, |t| p0 + a * t, sink))
        }
        [p0, p1, p2] => {
            // B(t) = P₀ + t (a + t b), a = 2(P₁ − P₀), b = P₂ − 2P₁ + P₀.
            let (a, b) = ((p1 - p0) * 2.0, p2 - p1 * 2.0 + p0);
            let n = count(&[p0, p1, p2])?;
            Ok(uniform(
                n,
                1.0 / n as f64,
                p0,
                p2,
                |t| p0 + (a + b * t) * t,
                sink,
            ))
        }
        [p0, p1, p2, p3] => {
            // B(t) = P₀ + t (a + t (b + t c)), a = 3(P₁ − P₀), b = 3(P₂ − 2P₁ + P₀),
            // c = P₃ − 3P₂ + 3P₁ − P₀.
            let a = (p1 - p0) * 3.0;
            let b = (p2 - p1 * 2.0 + p0) * 3.0;
            let c = p3 - p2 * 3.0 + p1 * 3.0 - p0;
            let n = count(&[p0, p1, p2, p3])?;
            Ok(uniform(
                n,
                1.0 / n as f64,
                p0,
                p3,
                |t| p0 + (a + (b + c * t) * t) * t,
                sink,
            ))
        }
        _ => {
            let n = count(p)?;
            let (first, last) = (p[0], p[p.len() - 1]);
            // Up to `MAX_STACK_DEGREE` the scaled control points sit in the stack frame.
            let mut buffer = [Vector2::zeros(); STACK_POINTS];
            if let Some(horner) = StackHorner::new(p, &mut buffer) {
                return Ok(uniform(
                    n,
                    1.0 / n as f64,
                    first,
                    last,
                    |t| horner.eval(t),
                    sink,
                ));
            }
            let horner = HornerBernstein::new(p);
            // `None` only for an empty polygon, excluded above.
            let eval = |t: f64| horner.eval(t).unwrap_or(first);
            Ok(uniform(n, 1.0 / n as f64, first, last, eval, sink))
        }
    }
}

/// Sends `first`, the points `eval`(k · `step`) for k = 1..n and `last` to `sink`; returns n.
/// `step` is 1/n, as computed by `1.0 / n as f64`.
#[inline(always)]
fn uniform(
    n: usize,
    step: f64,
    first: Vector2,
    last: Vector2,
    eval: impl Fn(f64) -> Vector2,
    mut sink: impl FnMut(FlatPoint),
) -> usize {
    sink(FlatPoint {
        t: 0.0,
        point: first,
    });
    // k counted in f64 (exact below 2⁵³): the same t = k · step as from the integer, without
    // a conversion per point.
    let mut k = 0.0;
    for _ in 1..n {
        k += 1.0;
        let t = k * step;
        sink(FlatPoint { t, point: eval(t) });
    }
    sink(FlatPoint {
        t: 1.0,
        point: last,
    });
    n
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use crate::{HausdorffSampling, measured_hausdorff};
    use bez_core::BezierCurve;
    use bez_core::proptest_support::curve;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The measured two-sided Hausdorff distance stays within the tolerance, the count is
        /// Wang's, and the points come in parameter order with exact end points.
        #[test]
        fn within_tolerance_with_wangs_count(c in curve::<2>(1..=8, 10.0), rel in 1e-4f64..1e-1) {
            let tol = rel * crate::curve_size(&c).max(1e-3);
            let mut pts = Vec::new();
            let n = flatten_wang(&c, tol, |p| pts.push(p)).unwrap();
            prop_assert_eq!(n, crate::wang_segment_count(&c, tol).unwrap());
            prop_assert_eq!(pts.len(), n + 1);
            prop_assert_eq!(pts[0].point, c.start());
            prop_assert_eq!(pts[n].point, c.end());
            prop_assert!(pts.windows(2).all(|w| w[0].t < w[1].t));
            // The public path (the table count on quadratics and cubics) gives the same count.
            prop_assert_eq!(crate::Flattener::new(tol).flatten(&c, |_| {}), Ok(n));
            let poly: Vec<Vector2> = pts.iter().map(|p| p.point).collect();
            let sampling = HausdorffSampling { curve_samples: 2001, segment_samples: 3 };
            let h = measured_hausdorff(&c, &poly, sampling).unwrap();
            prop_assert!(h <= tol * (1.0 + 1e-9), "{h} > {tol}");
            // The points are on the curve (power form vs de Casteljau).
            for p in &pts {
                prop_assert!((p.point - c.eval(p.t).unwrap()).norm() <= 1e-12 * (1.0 + crate::curve_size(&c)));
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// `Method::Fast` on quadratics and cubics (forward differences), near the origin and
        /// translated far from it: the measured two-sided Hausdorff distance stays within the
        /// tolerance, the count is Wang's (one more only at an exact boundary), and every
        /// point is within the rounding allowance of the curve point at its parameter.
        #[test]
        fn forward_differences_are_within_tolerance(
            c in curve::<2>(2..=3, 10.0),
            rel in 1e-5f64..1e-1,
            offset in prop_oneof![Just(0.0), -1e4f64..1e4],
        ) {
            let c = BezierCurve::new(
                c.points().iter().map(|&p| p + Vector2::new(offset, -offset)).collect(),
            ).unwrap();
            let tol = rel * crate::curve_size(&c).max(1e-3);
            let mut pts = Vec::new();
            let n = crate::Flattener::new(tol).flatten(&c, |p| pts.push(p)).unwrap();
            let wang = crate::wang_segment_count(&c, tol).unwrap();
            prop_assert!(n == wang || n == wang + 1, "{n} vs {wang}");
            prop_assert_eq!(pts.len(), n + 1);
            prop_assert_eq!((pts[0].point, pts[n].point), (c.start(), c.end()));
            let size: f64 = c.points().iter().map(|p| p.x().abs() + p.y().abs()).sum();
            // The allowance, and the evaluation's own rounding at fl(k h) instead of k h.
            let near = rounding_allowance(size, n as f64) + 1e-15 * size;
            for p in &pts {
                prop_assert!((p.point - c.eval(p.t).unwrap()).norm() <= near);
            }
            let poly: Vec<Vector2> = pts.iter().map(|p| p.point).collect();
            let sampling = HausdorffSampling { curve_samples: 2001, segment_samples: 3 };
            let h = measured_hausdorff(&c, &poly, sampling).unwrap();
            prop_assert!(h <= tol * (1.0 + 1e-9), "{h} > {tol}");
        }
    }

    /// The forward differences are taken on usual input, on both count paths, and declined
    /// where the rounding would take more than its share of the tolerance or where the chord
    /// bound leaves no room for it (q on an exact fourth or square power).
    #[test]
    fn forward_differences_are_taken_where_they_fit() {
        // (q, s, tol): table path, square-root path, both at 1e-3 and s = 4.
        for (q, size, tol, forward) in [
            (20.5_f64.powi(4), 4.0, 1e-3, true),
            (400.5_f64.powi(4), 4.0, 1e-3, true),
            (50.5_f64.powi(4), 4.0, 1e-3, true),
            (3_000.5_f64.powi(4), 4.0, 1e-5, true),
            // The allowance 2⁻⁵⁰ s (N + 64) above tol / 1024.
            (20.5_f64.powi(4), 1e12, 1e-3, false),
            // Just below a fourth power: the chord bound is all but the whole tolerance (on an
            // exact fourth power the count rounds up, leaving room).
            (16.0_f64.powi(4) / (1.0 + 1e-12), 4.0, 1e-3, false),
            (1_024.0_f64.powi(4) / (1.0 + 1e-12), 4.0, 1e-3, false),
            (16.0_f64.powi(4), 4.0, 1e-3, true),
            (20.0_f64.powi(4) * (1.0 - 1e-9), 4.0, 1e-3, false),
            (20.0_f64.powi(4) * (1.0 - 1e-5), 4.0, 1e-3, true),
            (50.0_f64.powi(4) * (1.0 - 1e-9), 4.0, 1e-3, false),
            (64.0_f64.powi(4) * (1.0 - 1e-5), 4.0, 1e-3, true),
            // Up to 64 segments, a tolerance below 2⁻²¹ s: evaluated.
            (20.5_f64.powi(4), 1e4, 1e-3, false),
            (400.5_f64.powi(4), 1e4, 1e-3, true),
        ] {
            let count = UniformCount::new(q, size, tol).unwrap();
            assert_eq!(count.forward, forward, "{q} {size} {tol}");
            assert_eq!(count.step, Step::new(1.0 / count.segments as f64));
        }
        assert!(UniformCount::new(f64::NAN, 4.0, 1e-3).is_none());
        assert!(UniformCount::new(MAX_FOURTH_POWER * 1.01, 4.0, 1e-3).is_none());
        let top = UniformCount::new(MAX_FOURTH_POWER / 1.01, 4.0, 1e-3).unwrap();
        assert!(top.segments <= MAX_WANG_SEGMENTS);
    }

    /// The table of steps holds what the general path computes at run time, bit for bit.
    #[test]
    fn step_table_is_the_run_time_step() {
        for (i, &step) in STEPS.iter().enumerate().skip(1) {
            let h = 1.0 / std::hint::black_box(i as f64);
            let h2 = h * h;
            assert_eq!((step.h, step.h2, step.h3), (h, h2, h2 * h), "{i}");
        }
    }

    /// Splitmix64: a seeded stream of u64 for the table tests.
    fn stream(mut state: u64) -> impl FnMut() -> u64 {
        move || {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        }
    }

    /// The count `Method::Fast` sends on the table path (`None` when it falls back).
    fn small_count(points: &[Vector2], tol: f64) -> Option<usize> {
        let mut sent = 0;
        let n = flatten_wang_small(points, tol, |_| sent += 1)?;
        assert_eq!(sent, n + 1);
        Some(n)
    }

    /// The first guess of `count_from_fourth_power` is within [i − 2, i] at both ends of the
    /// interval ((i − 1)⁴, i⁴] of every count i (so everywhere, by its monotonicity), and the
    /// count is the smallest i with q ≤ i⁴ on a dense sweep of [0, 64⁴].
    #[test]
    fn count_from_fourth_power_is_exact_on_its_range() {
        for i in 1..=TABLE_COUNTS {
            let top = COUNT_BOUNDS[i];
            let bottom = if i == 1 {
                0.0
            } else {
                COUNT_BOUNDS[i - 1].next_up()
            };
            // Below i⁴ by a relative 2⁻⁴⁵ up to one rounding.
            let exact = (i as f64).powi(4);
            assert!(
                top < exact && top >= exact * (1.0 - 2.0 * 2f64.powi(-45)),
                "{i}"
            );
            assert!(first_guess(top) <= i, "{i}");
            assert!(first_guess(bottom) + 2 >= i, "{i}");
            assert_eq!(count_from_fourth_power(top), i);
            assert_eq!(count_from_fourth_power(bottom), i);
        }
        let naive = |q: f64| (1..).find(|&i: &usize| q <= COUNT_BOUNDS[i]).unwrap_or(0);
        let limit = COUNT_BOUNDS[TABLE_COUNTS];
        for k in 0..=200_000 {
            let q = limit * (f64::from(k) / 200_000.0).powi(4);
            assert_eq!(count_from_fourth_power(q), naive(q), "{q}");
        }
        assert_eq!(count_from_fourth_power(f64::from_bits(1)), 1);
        assert_eq!(table_count(limit * 1.000_001), None);
        assert_eq!(table_count(f64::NAN), None);
    }

    /// Exact oracle: integer control points (so the second differences are exact) and
    /// tol = `num` / 2^`shift`. Wang's fourth power Q = (c |d| / tol)², c = n(n − 1)/8, is at
    /// most i⁴ iff `weight` |d|² 4^shift ≤ 16 i⁴ num² (weight 1 for quadratics, 9 for cubics),
    /// in u128. Returns the least i ≥ 1 that passes.
    fn exact_count(d2: u128, weight: u128, num: u128, shift: u32) -> usize {
        let lhs = (weight * d2) << (2 * shift);
        (1..)
            .find(|&i: &u128| lhs <= 16 * i.pow(4) * num * num)
            .map_or(0, |i| i as usize)
    }

    /// The table count never rounds down against exact integer arithmetic, and rounds up by
    /// at most one, only at exact boundaries; on quadratics and cubics with integer control
    /// points, exact boundaries (Q = i⁴) and their neighbours included.
    #[test]
    fn table_count_is_the_exact_ceiling_or_one_more_at_a_boundary() {
        let mut next = stream(15);
        let mut boundaries = 0;
        for case in 0..20_000 {
            let shift = (next() % 12) as u32;
            let num = u128::from(next() % 4096 + 1);
            let tol = num as f64 / f64::from(1_u32 << shift);
            let cubic = case % 2 == 1;
            let weight = if cubic { 9 } else { 1 };
            // Second differences: random, or on a boundary Q = i⁴ (|d|² = 16 i⁴ num² / (weight 4^shift)
            // when that is a whole square), or one off it.
            let (dx, dy, boundary) = if case % 4 < 2 {
                let r = |v: u64| (v % 2001) as i64 - 1000;
                (r(next()), r(next()), false)
            } else {
                // |d| = 4 i² num / (√weight 2^shift) along x, when whole.
                let i = (next() % TABLE_COUNTS as u64 + 1) as i64;
                let root = if cubic { 3 } else { 1 };
                let top = 4 * i * i * num as i64;
                let bottom = root << shift;
                if top % bottom != 0 {
                    continue;
                }
                let offset = (next() % 3) as i64 - 1;
                boundaries += usize::from(offset == 0);
                (top / bottom + offset, 0, offset == 0)
            };
            let d = Vector2::new(dx as f64, dy as f64);
            let d2 = (dx * dx + dy * dy) as u128;
            let o = Vector2::new(3.0, -2.0);
            // P₀ = o, P₁ = o + e, P₂ = o + 2e + d: the second difference d (exact in f64).
            let e = Vector2::new(5.0, 7.0);
            let points: Vec<Vector2> = if cubic {
                // Second differences d and 0 (P₃ = 2P₂ − P₁).
                let p2 = o + e * 2.0 + d;
                vec![o, o + e, p2, p2 * 2.0 - (o + e)]
            } else {
                vec![o, o + e, o + e * 2.0 + d]
            };
            let exact = exact_count(d2, weight, num, shift);
            match small_count(&points, tol) {
                Some(n) => {
                    assert!(
                        n == exact || n == exact + 1,
                        "{points:?} at {tol}: {n} vs {exact}"
                    );
                    // On a boundary (Q = exact⁴) the count rounds up.
                    assert!(!boundary || n == exact + 1, "{points:?} at {tol}");
                    if n == exact + 1 {
                        // Only where Q is within 2⁻⁴⁰ of exact⁴.
                        let q = (weight * d2) as f64 * 4f64.powi(shift as i32)
                            / (16.0 * (num * num) as f64);
                        assert!((q / (exact as f64).powi(4) - 1.0).abs() < 1e-12, "{q}");
                    }
                    // Against the square-root formula: never below it, at most one above.
                    let sqrt = wang_count(&points, tol).unwrap();
                    assert!(n == sqrt || n == sqrt + 1, "{n} vs {sqrt}");
                }
                None => assert!(exact >= TABLE_COUNTS, "{points:?} at {tol}: {exact}"),
            }
        }
        assert!(boundaries > 300, "{boundaries}");
    }

    /// On random quadratics and cubics at random tolerances the table count is the
    /// square-root formula's, except within 1e-12 of a whole number, where it may be one more.
    #[test]
    fn table_count_matches_the_square_root_formula() {
        let mut next = stream(2026);
        let mut unit = || (next() >> 11) as f64 / (1_u64 << 53) as f64;
        let mut table = 0;
        for case in 0..20_000 {
            let len = 3 + case % 2;
            let scale = 10f64.powf(6.0 * unit() - 3.0);
            let points: Vec<Vector2> = (0..len)
                .map(|_| Vector2::new(unit() - 0.5, unit() - 0.5) * scale)
                .collect();
            let tol = scale * 10f64.powf(-4.0 * unit());
            let sqrt = wang_count(&points, tol).unwrap();
            let Some(n) = small_count(&points, tol) else {
                assert!(sqrt >= TABLE_COUNTS, "{sqrt}");
                continue;
            };
            table += 1;
            let steps = crate::bound::wang_steps(&points, tol);
            if (steps - steps.round()).abs() > 1e-12 * steps {
                assert_eq!(n, sqrt, "{points:?} at {tol}");
            } else {
                assert!(n == sqrt || n == sqrt + 1);
            }
        }
        assert!(table > 5_000, "{table}");
    }

    /// The table path's points: those of the general path up to rounding, the same count,
    /// the same parameters bit for bit; and it declines what the general path must decide.
    #[test]
    fn table_path_agrees_with_the_general_path() {
        let mut next = stream(7);
        let mut unit = || (next() >> 11) as f64 / (1_u64 << 53) as f64;
        for case in 0..2_000 {
            let points: Vec<Vector2> = (0..3 + case % 2)
                .map(|_| Vector2::new(unit(), unit()))
                .collect();
            let tol = 10f64.powf(-1.0 - 3.0 * unit());
            let mut fast = Vec::new();
            let Some(n) = flatten_wang_small(&points, tol, |p| fast.push(p)) else {
                continue;
            };
            let curve = BezierCurve::new(points.clone()).unwrap();
            let mut general = Vec::new();
            assert_eq!(flatten_wang(&curve, tol, |p| general.push(p)), Ok(n));
            for (f, g) in fast.iter().zip(&general) {
                assert_eq!(f.t, g.t);
                // Forward differences against Horner's rule: within the rounding allowance.
                let size: f64 = points.iter().map(|p| p.x().abs() + p.y().abs()).sum();
                let allowance = 2.0 * rounding_allowance(size, n as f64);
                assert!((f.point - g.point).norm() <= allowance, "{f:?} vs {g:?}");
            }
        }
        let q = [
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 4.0),
            Vector2::new(2.0, 0.0),
        ];
        let huge = q.map(|p| p * 1e50);
        let tiny = q.map(|p| p * 1e-50);
        let zero = [Vector2::zeros(); 3];
        for (points, tol) in [
            (&q[..], 1e-16), // more than MAX_WANG_SEGMENTS
            (&q[..], 0.0),   // invalid tolerances
            (&q[..], f64::NAN),
            (&q[..], f64::INFINITY),
            (&q[..], -1.0),
            (&q[..], 1e-310),  // subnormal
            (&q[..2], 1.0),    // a line
            (&huge[..], 1e49), // not of unit size
            (&tiny[..], 1e-51),
            (&zero[..], 1.0),
        ] {
            assert_eq!(
                flatten_wang_small(points, tol, |_| panic!("sent")),
                None,
                "{points:?}"
            );
        }
    }

    #[test]
    fn bad_input_and_limits() {
        let dot = BezierCurve::new(vec![Vector2::new(1.0, 1.0)]).unwrap();
        assert_eq!(
            flatten_wang(&dot, 1e-3, |_| {}),
            Err(SubdivError::TooFewPoints { got: 1 })
        );
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 1.0),
            Vector2::new(2.0, 0.0),
        ])
        .unwrap();
        assert!(matches!(
            flatten_wang(&c, f64::NAN, |_| {}),
            Err(SubdivError::InvalidTolerance { .. })
        ));
        let mut calls = 0;
        assert!(matches!(
            flatten_wang(&c, 1e-20, |_| calls += 1),
            Err(SubdivError::TooManySegments { .. })
        ));
        assert_eq!(calls, 0, "refused before any point");
    }
}
