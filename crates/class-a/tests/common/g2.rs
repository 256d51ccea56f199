//! The G2 data shared by the G2 tests and the `spline` example.

use bez_core::Vector2;
use class_a::{Knot, Matrix2, perturb2, typical_matrix2};

/// Knots on the log spiral r = e^{bφ} (b = 0.2) at φ = 0, 1.2, 2.4, 3.6: its tangent turns
/// by 1.2 between knots and its curvature κ = e^{−bφ}/√(1 + b²) decreases along it; with that
/// curvature if asked.
pub(crate) fn spiral_knots(with_curvature: bool) -> Vec<Knot> {
    let b: f64 = 0.2;
    (0..4)
        .map(|i| {
            let phi = 1.2 * f64::from(i);
            let r = (b * phi).exp();
            let (sn, cs) = phi.sin_cos();
            let point = Vector2::new(r * cs, r * sn);
            // d/dφ (r cos φ, r sin φ) = r (b cos φ − sin φ, b sin φ + cos φ).
            let tangent = Vector2::new(b * cs - sn, b * sn + cs);
            let knot = Knot::new(point, tangent);
            if with_curvature {
                knot.with_curvature(1.0 / (r * (1.0 + b * b).sqrt()))
            } else {
                knot
            }
        })
        .collect()
}

/// A fixed-seed generator of uniform numbers in [0, 1) (64-bit LCG, top 53 bits).
fn uniform(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// The next perturbed typical matrix of the recovery data (seed the state with 12,345): degree
/// 3..12, turn 0.3..2.8, both branches of condition (4) (s = 1/cos θ + 0..0.3 or
/// cos θ − 0..0.3), entries perturbed by ±0.05 ([`perturb2`]). Returns (n, M).
pub(crate) fn perturbed_typical(state: &mut u64) -> (usize, Matrix2) {
    let n = 3 + (uniform(state) * 10.0) as usize;
    let theta = (0.3 + 2.5 * uniform(state)) / (n - 1) as f64;
    let c = theta.cos();
    let s = if uniform(state) < 0.5 {
        1.0 / c + 0.3 * uniform(state)
    } else {
        c - 0.3 * uniform(state)
    };
    let delta = [0; 4].map(|_| 0.05 * (2.0 * uniform(state) - 1.0));
    (n, perturb2(&typical_matrix2(s, theta), delta))
}
