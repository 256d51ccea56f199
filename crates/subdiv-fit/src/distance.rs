//! Foot points on one segment (eq. 6) and distances to a polyline.

use bez_core::Vector;

use crate::bspline::{bspline_basis, bspline_basis_d1, bspline_basis_d2};
use crate::curve::combine;
use crate::{SubdivCurve, SubdivFitError};

/// The foot point of `v` on segment `segment` of `curve`: Newton's method on eq. (6),
/// `g(t) = (C(t) − v)ᵀ C'(t) = 0`, `g'(t) = |C'|² + (C − v)ᵀ C''`, from `t0` (the paper's
/// chord-length start), clamped to `[0, 1]`; the segment's end points are also tried, so the result
/// is never worse than them.
/// Returns `(t, distance)`.
///
/// # Errors
/// [`SubdivFitError::SegmentOutOfRange`], [`SubdivFitError::ParameterOutOfRange`] for `t0 ∉ [0, 1]`.
pub fn foot_point<const D: usize>(
    curve: &SubdivCurve<D>,
    segment: usize,
    v: &Vector<D>,
    t0: f64,
) -> Result<(f64, f64), SubdivFitError> {
    if !(0.0..=1.0).contains(&t0) {
        return Err(SubdivFitError::ParameterOutOfRange {
            name: "t0",
            value: t0,
            min: 0.0,
            max: 1.0,
        });
    }
    let ctrl = curve.segment_controls(segment)?;
    Ok(foot_point_ctrl(&ctrl, v, t0))
}

pub(crate) fn foot_point_ctrl<const D: usize>(
    ctrl: &[Vector<D>; 4],
    v: &Vector<D>,
    t0: f64,
) -> (f64, f64) {
    let mut t = t0;
    for _ in 0..30 {
        let c = combine(ctrl, bspline_basis(t)) - v;
        let d1 = combine(ctrl, bspline_basis_d1(t));
        let d2 = combine(ctrl, bspline_basis_d2(t));
        let g = c.dot(&d1);
        let gp = d1.norm_squared() + c.dot(&d2);
        if gp <= 0.0 || !gp.is_finite() {
            break;
        }
        let next = (t - g / gp).clamp(0.0, 1.0);
        let step = (next - t).abs();
        t = next;
        if step < 1e-13 {
            break;
        }
    }
    let mut best = (t, (combine(ctrl, bspline_basis(t)) - v).norm());
    for e in [0.0, 1.0] {
        let d = (combine(ctrl, bspline_basis(e)) - v).norm();
        if d < best.1 {
            best = (e, d);
        }
    }
    best
}

/// Distance from `p` to the polyline through `poly` (to its vertex if it has one point;
/// infinite if empty).
pub fn point_polyline_distance<const D: usize>(p: &Vector<D>, poly: &[Vector<D>]) -> f64 {
    match poly {
        [] => f64::INFINITY,
        [q] => (p - q).norm(),
        _ => poly
            .windows(2)
            .map(|w| {
                let e = w[1] - w[0];
                let len2 = e.norm_squared();
                let s = if len2 > 0.0 {
                    ((p - w[0]).dot(&e) / len2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                (p - (w[0] + e * s)).norm()
            })
            .fold(f64::INFINITY, f64::min),
    }
}
