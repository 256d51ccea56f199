//! Initial fitting points from the shape at the tolerance's scale (the project's replacement of
//! the paper's curvature maxima, Sec. 4.2, which on dense or noisy data are maxima of the noise).
//!
//! The corners split the data into spans (a closed curve without corners is one span round from
//! point 0). Each span gets `m − 1` regular fitting points at equal chord-length steps, with `m` the
//! smallest count whose pieces all pass the error estimate of cubic spline interpolation,
//! `(5/384) h⁴ max|f⁗|`, which for a piece of length `ℓ` turning by `Θ` (an arc of radius `ℓ / Θ`)
//! is `(5/384) ℓ Θ³`, against half the tolerance. Turning is measured on the span resampled at
//! steps of at least the feature scale (and at most 1/128 of the span), so noise below the
//! tolerance adds little and the count does not grow with the sampling density. A circle at a
//! relative tolerance of 10⁻³ gets 12 points (30° each); a straight span none.

use bez_core::Vector;

use crate::chord::ChordLengths;
use crate::curvature::angle_between;

/// Largest number of coarse steps one span is resampled at.
const MAX_COARSE_STEPS: usize = 4096;

/// Fitting points `(index, sharp)` in increasing index order: the corners (sharp), the ends of
/// open data (sharp) and the regular points of every span.
pub(crate) fn seed<const D: usize>(
    data: &[Vector<D>],
    chords: &ChordLengths,
    closed: bool,
    corners: &[usize],
    sigma: f64,
    tolerance: f64,
) -> Vec<(usize, bool)> {
    let n = data.len();
    let mut fitting: Vec<(usize, bool)> = Vec::new();
    let mut bounds: Vec<(usize, bool)> = corners.iter().map(|&c| (c, true)).collect();
    if !closed {
        if bounds.first().is_none_or(|b| b.0 != 0) {
            bounds.insert(0, (0, true));
        }
        if bounds.last().is_none_or(|b| b.0 != n - 1) {
            bounds.push((n - 1, true));
        }
    } else if bounds.is_empty() {
        bounds.push((0, false));
    }
    let spans = if closed {
        bounds.len()
    } else {
        bounds.len() - 1
    };
    for k in 0..spans {
        let a = bounds[k].0;
        let b = if k + 1 < bounds.len() {
            bounds[k + 1].0
        } else {
            bounds[0].0 + n
        };
        fitting.push(bounds[k]);
        let m = piece_count(data, chords, a, b, sigma, tolerance);
        let (start, length) = (chords.at(a), chords.at(b) - chords.at(a));
        for j in 1..m {
            let target = start + length * j as f64 / m as f64;
            if let Some(i) = chords.nearest_interior(a, b, target)
                && fitting.last().is_none_or(|f| f.0 != i)
            {
                fitting.push((i, false));
            }
        }
    }
    if !closed {
        fitting.push(bounds[bounds.len() - 1]);
    }
    fitting.sort_by_key(|f| f.0);
    fitting.dedup_by_key(|f| f.0);
    fitting
}

/// The number of equal pieces span `a..=b` (unwrapped indices) needs by the estimate
/// `(5/384) ℓ Θ³ ≤ tol / 2`.
fn piece_count<const D: usize>(
    data: &[Vector<D>],
    chords: &ChordLengths,
    a: usize,
    b: usize,
    sigma: f64,
    tolerance: f64,
) -> usize {
    let (start, length) = (chords.at(a), chords.at(b) - chords.at(a));
    if length.is_nan() || length <= 0.0 {
        return 1;
    }
    let by_scale = if sigma > 0.0 {
        (length / sigma).ceil()
    } else {
        f64::INFINITY
    };
    let steps = by_scale.clamp(2.0, 128.0).min((b - a).max(2) as f64) as usize;
    let steps = steps.clamp(2, MAX_COARSE_STEPS);
    let mut hint = a % chords.len();
    let coarse: Vec<Vector<D>> = (0..=steps)
        .map(|k| chords.position_from(data, start + length * k as f64 / steps as f64, &mut hint))
        .collect();
    // cum[k]: turning from the start up to coarse vertex k.
    let mut cum = vec![0.0; steps + 1];
    for k in 1..steps {
        let t = angle_between(&(coarse[k] - coarse[k - 1]), &(coarse[k + 1] - coarse[k]));
        cum[k] = cum[k - 1] + t;
    }
    cum[steps] = cum[steps - 1];
    let worst = |m: usize| {
        let piece = length / m as f64;
        (0..m)
            .map(|j| {
                let lo = (j * steps) / m;
                let hi = ((j + 1) * steps).div_ceil(m).min(steps);
                let theta = cum[hi] - cum[lo];
                5.0 / 384.0 * piece * theta * theta * theta
            })
            .fold(0.0, f64::max)
    };
    let target = 0.5 * tolerance;
    let cap = steps.min(b - a);
    let mut m = 1;
    while m < cap && worst(m) > target {
        m = (2 * m).min(cap);
    }
    // Smallest passing count in (m/2, m].
    let (mut lo, mut hi) = (m / 2 + 1, m);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if worst(mid) > target {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    hi.max(1)
}
