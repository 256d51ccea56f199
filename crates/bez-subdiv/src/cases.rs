//! The seeded test curves of the Table 1 reproduction and of the N* comparison.
//!
//! The paper's curves were "drawn interactively with random points" and are not given. We draw
//! control points uniformly in the unit square with `ChaCha8Rng` seeded by
//! [`TABLE1_SEED`] + degree, [`CURVES_PER_DEGREE`] curves per degree, in the paper's degrees.

use bez_core::{BezierCurve, Vector2};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The degrees of the paper's Table 1.
pub const TABLE1_DEGREES: [usize; 10] = [12, 13, 16, 17, 18, 19, 20, 22, 24, 25];
/// Curves per degree (so a row is not one lucky draw).
pub const CURVES_PER_DEGREE: usize = 5;
/// Base seed of the generator.
pub const TABLE1_SEED: u64 = 2016;

/// `count` random curves of `degree` with control points uniform in [0, 1]².
#[must_use]
pub fn random_curves(degree: usize, count: usize, seed: u64) -> Vec<BezierCurve<2>> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..count)
        .filter_map(|_| {
            let pts = (0..=degree)
                .map(|_| Vector2::new(rng.random_range(0.0..1.0), rng.random_range(0.0..1.0)))
                .collect();
            BezierCurve::new(pts).ok()
        })
        .collect()
}

/// The Table 1 curves: for each paper degree, [`CURVES_PER_DEGREE`] seeded random curves.
#[must_use]
pub fn table1_curves() -> Vec<(usize, Vec<BezierCurve<2>>)> {
    TABLE1_DEGREES
        .iter()
        .map(|&d| {
            (
                d,
                random_curves(d, CURVES_PER_DEGREE, TABLE1_SEED + d as u64),
            )
        })
        .collect()
}

/// Seed of the random cubics of [`peer_cubics`].
pub const PEER_SEED: u64 = 2011;

/// The cubics flattened side by side with other libraries (benchmarks and the peer table):
/// three seeded random cubics (control points uniform in [0, 1]², seed [`PEER_SEED`]), the
/// [`cusp`] and the [`looped`] cubic, with their names.
#[must_use]
pub fn peer_cubics() -> Vec<(String, BezierCurve<2>)> {
    let random = random_curves(3, 3, PEER_SEED)
        .into_iter()
        .enumerate()
        .map(|(k, c)| (format!("random cubic {}", k + 1), c));
    let special = [("cusp", cusp()), ("loop", looped())]
        .into_iter()
        .filter_map(|(name, c)| c.map(|c| (name.to_owned(), c)));
    random.chain(special).collect()
}

/// A cubic with a cusp (its hodograph vanishes at t = ½).
#[must_use]
pub fn cusp() -> Option<BezierCurve<2>> {
    let v = Vector2::new;
    BezierCurve::new(vec![v(0.0, 0.0), v(1.0, 1.0), v(0.0, 1.0), v(1.0, 0.0)]).ok()
}

/// A cubic with a loop (it crosses itself).
#[must_use]
pub fn looped() -> Option<BezierCurve<2>> {
    let v = Vector2::new;
    BezierCurve::new(vec![v(0.0, 0.0), v(2.0, 2.0), v(-1.0, 2.0), v(1.0, 0.0)]).ok()
}

/// The degree-25 curve of the per-output-point speed target (the benchmark
/// `flatten_degree25_per_point` and `cargo xtask tables`): the degree-25 curve of
/// [`nstar_curves`].
#[must_use]
pub fn degree25_curve() -> Option<BezierCurve<2>> {
    random_curves(25, 1, 7 + 25).into_iter().next()
}

/// The curves of the N* comparison, named: one seeded random curve of degree 3, 12 and 25
/// (seed 7 + degree), the cusp and the loop.
#[must_use]
pub fn nstar_curves() -> Vec<(String, BezierCurve<2>)> {
    let random = [3usize, 12, 25].into_iter().flat_map(|n| {
        random_curves(n, 1, 7 + n as u64)
            .into_iter()
            .map(move |c| (format!("random, degree {n}"), c))
    });
    let special = [("cusp (cubic)", cusp()), ("loop (cubic)", looped())]
        .into_iter()
        .filter_map(|(name, c)| c.map(|c| (name.to_owned(), c)));
    random.chain(special).collect()
}
