//! Shared test data: seeded random Bézier surfaces.

use bez_core::{BezierSurface, Vector3};

/// A surface of bidegree (du, dv) with control points in [−1, 1]³ from a fixed-seed LCG.
pub(crate) fn random_surface(du: usize, dv: usize, seed: u64) -> BezierSurface<3> {
    let mut s = seed;
    let mut next = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((s >> 33) as f64 / (1u64 << 31) as f64) * 2.0 - 1.0
    };
    let pts = (0..(du + 1) * (dv + 1))
        .map(|_| Vector3::new(next(), next(), next()))
        .collect();
    BezierSurface::from_flat(du, dv, pts).unwrap()
}
