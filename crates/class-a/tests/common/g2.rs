//! The G2 data shared by the G2 tests and the `spline` example.

use bez_core::{BezierCurve, Vector2};
use class_a::{
    ClassACurve, ClassAError, Knot, Matrix2, class_a_curve, curvature_certificate, end_curvatures,
    hermite_planar, perturb2, typical_matrix2,
};

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

/// The next random general matrix (seed the state with any value): degree 3..12, M = P J P⁻¹
/// with J a rotation-scaling m R(φ) (φ up to π/(n − 1)) or, one time in three, diag(m, ρm)
/// (ρ ∈ [0.2, 1)), m = e^{±0.4}, and P with entries 1 + [−0.6, 0.6] on and [−0.6, 0.6] off the
/// diagonal (|det P| ≥ 0.2); the first leg is a random unit vector. Returns (n, first leg, M).
/// Not every such curve turns one way by less than π or has monotone curvature: callers filter.
pub(crate) fn random_general(state: &mut u64) -> (usize, Vector2, Matrix2) {
    let n = 3 + (uniform(state) * 10.0) as usize;
    let m = (0.8 * uniform(state) - 0.4).exp();
    let j = if uniform(state) < 1.0 / 3.0 {
        let rho = 0.2 + 0.8 * uniform(state);
        Matrix2::new(m, 0.0, 0.0, rho * m)
    } else {
        let phi = std::f64::consts::PI / (n - 1) as f64 * uniform(state);
        typical_matrix2(m, phi)
    };
    let p = loop {
        let e = [0; 4].map(|_| 1.2 * uniform(state) - 0.6);
        let p = Matrix2::new(1.0 + e[0], e[1], e[2], 1.0 + e[3]);
        if (p[(0, 0)] * p[(1, 1)] - p[(0, 1)] * p[(1, 0)]).abs() >= 0.2 {
            break p;
        }
    };
    let det = p[(0, 0)] * p[(1, 1)] - p[(0, 1)] * p[(1, 0)];
    let inverse = Matrix2::new(p[(1, 1)], -p[(0, 1)], -p[(1, 0)], p[(0, 0)]) * (1.0 / det);
    let angle = 2.0 * std::f64::consts::PI * uniform(state);
    (n, Vector2::new(angle.cos(), angle.sin()), p * j * inverse)
}

/// Whether the control polygon turns one way, by less than π in total (the shape the G2 solve
/// returns).
pub(crate) fn turns_one_way(points: &[Vector2]) -> bool {
    let legs: Vec<Vector2> = points.windows(2).map(|w| w[1] - w[0]).collect();
    let turns: Vec<f64> = legs
        .windows(2)
        .map(|w| w[0].perp(&w[1]).atan2(w[0].dot(&w[1])))
        .collect();
    let total: f64 = turns.iter().sum();
    turns.iter().all(|t| t * total > 0.0) && total.abs() > 1e-3 && total.abs() < 3.1
}

/// A known curve's G2 data solved back.
#[allow(
    dead_code,
    reason = "the tests check the result against the knots, the example only counts"
)]
pub(crate) struct SolvedBack {
    /// The start knot with the curve's curvature there.
    pub(crate) start: Knot,
    /// The end knot with the curve's curvature there.
    pub(crate) end: Knot,
    /// What [`hermite_planar`] returned.
    pub(crate) result: Result<ClassACurve<2>, ClassAError>,
    /// Whether the result's matrix is the generating one to 1e-6.
    pub(crate) same: bool,
}

/// The Class A curve of degree n from the origin with first leg v and matrix m, its G2 data
/// (end points, tangents and curvatures) solved back with [`hermite_planar`]; None when the
/// curve's curvature is not proven monotone (then no monotone solution need exist) or, if
/// `one_way` is asked, its polygon does not turn one way by less than π.
pub(crate) fn solve_back(n: usize, v: Vector2, m: &Matrix2, one_way: bool) -> Option<SolvedBack> {
    let curve: BezierCurve<2> = class_a_curve(&Vector2::zeros(), &v, m, n).ok()?;
    let p = curve.points();
    if (one_way && !turns_one_way(p)) || !curvature_certificate(&curve).ok()?.is_monotone() {
        return None;
    }
    let (k0, k1) = end_curvatures(&curve).ok()?;
    let start = Knot::new(p[0], p[1] - p[0]).with_curvature(k0);
    let end = Knot::new(p[n], p[n] - p[n - 1]).with_curvature(k1);
    let result = hermite_planar(&start, &end, n);
    let same = result
        .as_ref()
        .is_ok_and(|c| (c.matrix() - *m).iter().all(|v| v.abs() < 1e-6));
    Some(SolvedBack {
        start,
        end,
        result,
        same,
    })
}
