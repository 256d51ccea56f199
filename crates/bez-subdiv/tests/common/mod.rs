//! Helpers shared by the integration tests: a measured Hausdorff distance.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::distance_to_segment;

/// max over dense curve samples of the distance to the polyline, and max over dense polyline
/// samples of the distance to the curve (exact nearest point).
pub(crate) fn hausdorff(c: &BezierCurve<2>, poly: &[Vector2<f64>]) -> f64 {
    let mut h = 0.0_f64;
    for k in 0..=3000 {
        let p = c.eval(f64::from(k) / 3000.0).unwrap();
        let d = poly
            .windows(2)
            .map(|w| distance_to_segment(&p, &w[0], &w[1]))
            .fold(f64::INFINITY, f64::min);
        h = h.max(d);
    }
    for w in poly.windows(2) {
        for k in 0..=8 {
            let s = f64::from(k) / 8.0;
            let q = w[0] * (1.0 - s) + w[1] * s;
            h = h.max(c.nearest(&q).unwrap().distance);
        }
    }
    h
}
