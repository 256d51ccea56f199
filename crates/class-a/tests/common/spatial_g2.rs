//! The spatial G2 data shared by the spatial G2 tests and the `spatial_spline` example.

use bez_core::Vector3;
use class_a::SpatialKnot;

/// Knots on the conical spiral e^{ct}(cos t, sin t, h) every 1.1 rad, c = 0.4, h = 0.8, with
/// its tangents, and (with `g2`) its curvature and binormal from its analytic derivatives.
pub(crate) fn spiral_knots(count: usize, g2: bool) -> Vec<SpatialKnot> {
    let (c, h) = (0.4f64, 0.8f64);
    (0..count)
        .map(|i| {
            let t = 1.1 * i as f64;
            let (sn, cs) = t.sin_cos();
            let e = (c * t).exp();
            let d1 = Vector3::new(c * cs - sn, c * sn + cs, c * h) * e;
            let d2 = Vector3::new(
                (c * c - 1.0) * cs - 2.0 * c * sn,
                (c * c - 1.0) * sn + 2.0 * c * cs,
                c * c * h,
            ) * e;
            let knot = SpatialKnot::new(Vector3::new(cs, sn, h) * e, d1);
            if g2 {
                let b = d1.cross(&d2);
                let n1 = d1.norm();
                knot.with_curvature(b.norm() / (n1 * n1 * n1))
                    .with_binormal(b)
            } else {
                knot
            }
        })
        .collect()
}
