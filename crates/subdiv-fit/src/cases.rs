//! The documented test shapes of the reproduction (the paper's data are not published).
//!
//! Both are normalized to the unit bounding box (translated to the origin, scaled uniformly so the
//! longer side is 1) so the paper's tolerance 0.01 means the same thing.
//! `density` multiplies the number of samples (1 for the paper's size; 10 and 100 for the scaling
//! table); corners stay on samples at every density.

use bez_core::Vector2;

/// Closed "four-petal" shape: `r(θ) = 1 + 0.4 |sin 2θ| + 0.1 cos(5θ + 0.3)`,
/// `θ_i = 2π i / (64 · density)`.
/// Four concave corners at `θ = kπ/2` (where `|sin 2θ|` kinks) and smooth petal tips made unequal by
/// the 5th harmonic: 64 points and 9 curvature maxima (4 of them sharp) at density 1, like the
/// paper's Fig. 2 and 4 data (64 points, 9 maxima, points 1, 4, 6, 9 sharp).
#[must_use]
pub fn closed_petals(density: usize) -> Vec<Vector2> {
    let n = 64 * density.max(1);
    let pts = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 1.0 + 0.4 * (2.0 * t).sin().abs() + 0.1 * (5.0 * t + 0.3).cos();
            Vector2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    normalize(pts)
}

/// Closed "rippled petals": `r(θ) = 1 + 0.4 |sin 2θ| + a cos(kθ + φ)`,
/// `θ_i = 2π i / (64 · density)`: the four corners of [`closed_petals`] plus `k` ripples of
/// amplitude `a`, so many close, unevenly spaced curvature maxima. `rippled_petals(d, 0.08, 9.0, 0.0)`
/// is the shape on which an earlier insertion rule stalled at 10x and 100x density.
#[must_use]
pub fn rippled_petals(density: usize, a: f64, k: f64, phase: f64) -> Vec<Vector2> {
    let n = 64 * density.max(1);
    let pts = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 1.0 + 0.4 * (2.0 * t).sin().abs() + a * (k * t + phase).cos();
            Vector2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    normalize(pts)
}

/// Open "wave with two kinks": `y = 0.2 sin(5π x) + 0.8 (|x − 22/65| + |x − 44/65|)`,
/// `x_i = i / (65 · density)`, 66 points at density 1, two corners (slope jump 1.6, turning about
/// 77° on a flat part) and the smooth crests of the sine.
#[must_use]
pub fn open_wave(density: usize) -> Vec<Vector2> {
    let m = 65 * density.max(1);
    let pts = (0..=m)
        .map(|i| {
            let x = i as f64 / m as f64;
            let y = 0.2 * (5.0 * std::f64::consts::PI * x).sin()
                + 0.8 * ((x - 22.0 / 65.0).abs() + (x - 44.0 / 65.0).abs());
            Vector2::new(x, y)
        })
        .collect();
    normalize(pts)
}

/// Translates to the origin and scales uniformly so the longer bounding-box side is 1.
#[must_use]
pub fn normalize(mut pts: Vec<Vector2>) -> Vec<Vector2> {
    let Some(first) = pts.first().copied() else {
        return pts;
    };
    let (mut lo, mut hi) = (first, first);
    for p in &pts {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    let side = (hi - lo).max();
    if side > 0.0 {
        for p in &mut pts {
            *p = (*p - lo) / side;
        }
    }
    pts
}
