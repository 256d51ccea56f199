//! Shared, seeded inputs for the criterion benchmarks in `benches/`.

use bez_core::{BezierCurve, Vector};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A random curve of the given degree with coordinates in [−1, 1], from a fixed seed.
#[must_use]
pub fn random_curve<const D: usize>(degree: usize, seed: u64) -> BezierCurve<D> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let pts = (0..=degree)
        .map(|_| Vector::<D>::from_fn(|_| rng.random_range(-1.0..=1.0)))
        .collect();
    // Finite, non-empty points: construction cannot fail.
    BezierCurve::new(pts).unwrap_or_else(|_| unreachable!("random points are finite"))
}

/// `count` parameters uniformly spaced on [0, 1].
#[must_use]
pub fn uniform_parameters(count: usize) -> Vec<f64> {
    let d = count.saturating_sub(1).max(1) as f64;
    (0..count).map(|k| k as f64 / d).collect()
}
