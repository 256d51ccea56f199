//! Corners found at the scale of the tolerance, not at the spacing of the data.
//!
//! The paper (Sec. 4.1) thresholds the angle between the two data edges at a point. On dense,
//! quantized or noisy data that angle measures the noise: a step of one grid unit between two
//! samples a grid unit apart turns by 45°. Here the turn at point `i` is measured between the
//! chords to the points of the data polyline at arc length `±s` from it, and a corner must look
//! the same at two scales:
//!
//! * `s_i = max(σ, 2 h_i)`, with `σ` the feature scale (a multiple of the tolerance) and `h_i` the
//!   longer of the two data edges at `i`, so the chords always span at least two edges each way;
//! * the turn `τ(s/2)` at half that scale is at least the corner angle, and at least
//!   [`SCALE_RATIO`] times the turn `τ(s)`: a corner turns by the same angle at every scale
//!   (ratio 1), a smooth arc by an angle proportional to the scale (ratio ½);
//! * among the points that pass, a corner is the one of largest `τ(s/2)` within arc length `s_i`
//!   on either side (one point per corner, at the apex).
//!
//! Noise of amplitude `ε` moves the chord directions by about `2ε / (s/2)`: with the default
//! `σ = 6 tol`, noise up to `tol / 4` changes a turn by less than 10°, half the default corner angle
//! of 20°. Bends of radius below about `σ / 2` are corners at this scale: a sharp vertex there
//! stays within about `0.4 σ / 2` of an arc that turns by 90°, and the fit's insertion takes care
//! of the rest.

use bez_core::Vector;

use crate::chord::ChordLengths;
use crate::curvature::angle_between;

/// A corner's turn at half its scale must be at least this fraction of its turn at the full
/// scale (a smooth arc gives ½, a corner between straight sides 1).
pub const SCALE_RATIO: f64 = 2.0 / 3.0;

/// Data indices of the corners (increasing): the `given` ones (increasing, below `n`) and those
/// found at feature scale `sigma` with smallest turn `min_turn` (radians) away from them. Open
/// data's end points are not included.
pub(crate) fn detect_corners<const D: usize>(
    data: &[Vector<D>],
    chords: &ChordLengths,
    closed: bool,
    given: &[usize],
    sigma: f64,
    min_turn: f64,
) -> Vec<usize> {
    let n = data.len();
    let total = chords.total();
    // No turn exceeds π: a smallest turn of π (`sharp_angle` = 0) finds nothing to add.
    if n < 3 || total <= 0.0 || min_turn >= std::f64::consts::PI {
        return given.to_vec();
    }
    // (index, scale, turn at half scale) of every candidate.
    let mut candidates: Vec<(usize, f64, f64)> = Vec::new();
    // Edge hints of the positions at −s/2, +s/2, −s, +s: they move little from point to point.
    let mut hints = [0; 4];
    let cos_min = min_turn.cos();
    for i in 0..n {
        let (prev, next) = if closed {
            ((i + n - 1) % n, (i + 1) % n)
        } else if i == 0 || i + 1 == n {
            continue;
        } else {
            (i - 1, i + 1)
        };
        let p = data[i];
        let h = (p - data[prev]).norm().max((data[next] - p).norm());
        // At most a quarter of a closed curve each way.
        let s = sigma.max(2.0 * h).min(0.25 * total);
        let at = chords.at(i);
        if !closed && (at < 0.5 * s || total - at < 0.5 * s) {
            continue;
        }
        let mut chords_at = |r: f64, [before, after]: [usize; 2]| {
            let a = chords.position_from(data, at - r, &mut hints[before]);
            let b = chords.position_from(data, at + r, &mut hints[after]);
            (p - a, b - p)
        };
        let (a, b) = chords_at(0.5 * s, [0, 1]);
        if turns_less(&a, &b, cos_min) {
            continue;
        }
        let half = angle_between(&a, &b);
        if half < min_turn || {
            let (a, b) = chords_at(s, [2, 3]);
            half < SCALE_RATIO * angle_between(&a, &b)
        } {
            continue;
        }
        candidates.push((i, s, half));
    }
    // Non-maximum suppression, greediest first: a candidate is kept unless a kept one (which turns
    // at least as much) lies within its scale. O(m log m) for m candidates.
    candidates.sort_by(|x, y| y.2.total_cmp(&x.2).then(x.0.cmp(&y.0)));
    let arc_gap = |a: usize, b: usize| {
        let d = (chords.at(a) - chords.at(b)).abs();
        if closed { d.min(total - d) } else { d }
    };
    let mut kept: std::collections::BTreeSet<usize> = given.iter().copied().collect();
    for &(i, s, _) in &candidates {
        let before = kept
            .range(..i)
            .next_back()
            .or_else(|| closed.then(|| kept.last()).flatten());
        let after = kept
            .range(i..)
            .next()
            .or_else(|| closed.then(|| kept.first()).flatten());
        if [before, after]
            .into_iter()
            .flatten()
            .all(|&j| arc_gap(i, j) > s)
        {
            kept.insert(i);
        }
    }
    kept.into_iter().collect()
}

/// Whether the turn from `a` to `b` is certainly below the angle `θ` with `cos θ` = `cos_limit`
/// (`θ` below 90°), without an arctangent or a square root: the turn is below `θ` when
/// `a·b > cos θ |a| |b|`, i.e. `a·b > 0` and `(a·b)² > cos² θ |a|² |b|²`; the relative margin of
/// 10⁻⁶ covers the rounding of both sides (and of [`angle_between`]), so `false` only means
/// "measure it".
fn turns_less<const D: usize>(a: &Vector<D>, b: &Vector<D>, cos_limit: f64) -> bool {
    let dot = a.dot(b);
    cos_limit > 0.0
        && dot > 0.0
        && dot * dot > cos_limit * cos_limit * a.norm_squared() * b.norm_squared() * (1.0 + 1e-6)
}

#[cfg(test)]
mod tests {
    use super::*;
    use bez_core::Vector2;
    use proptest::prelude::*;

    proptest! {
        /// The shortcut never answers "below" for a turn that `angle_between` puts at or above
        /// the limit, and answers it for turns clearly below.
        #[test]
        fn turns_less_agrees_with_the_angle(
            a in (-5.0f64..5.0, -5.0f64..5.0),
            b in (-5.0f64..5.0, -5.0f64..5.0),
            limit in 0.0f64..1.6,
        ) {
            let (a, b) = (Vector2::new(a.0, a.1), Vector2::new(b.0, b.1));
            let turn = angle_between(&a, &b);
            let below = turns_less(&a, &b, limit.cos());
            if below {
                prop_assert!(turn < limit, "{turn} vs {limit}");
            }
            if limit < 1.5 && turn < 0.99 * limit && a.norm() > 1e-3 && b.norm() > 1e-3 {
                prop_assert!(below, "{turn} vs {limit}");
            }
        }
    }
}
