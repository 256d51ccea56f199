//! Foot points on one segment (eq. 6) and distances to a polyline.

use bez_core::Vector;

use crate::bspline::bspline_basis;
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
    Ok(PowerCubic::new(&ctrl).foot(v, t0))
}

/// The Newton step of [`PowerCubic::foot`] below which it stops. Newton converges quadratically
/// near a foot point, so the parameter is then off by about the square of the step (10⁻¹⁰ of the
/// segment's parameter range); the distance returned is that of a point of the segment, above the
/// distance to the exact foot point by at most that times the segment's speed, never below it.
const FOOT_STEP: f64 = 1e-5;

/// One uniform cubic B-spline segment in power form, `C(t) = c₀ + c₁ t + c₂ t² + c₃ t³`, for
/// foot points: with the B-spline control points `(a, b, c, d)` (eq. 1),
/// `c₀ = (a + 4b + c) / 6`, `c₁ = (c − a) / 2`, `c₂ = (a − 2b + c) / 2`, `c₃ = (d − a + 3(b − c)) / 6`.
pub(crate) struct PowerCubic<const D: usize> {
    c: [Vector<D>; 4],
    /// `C(0)` and `C(1)`.
    start: Vector<D>,
    end: Vector<D>,
}

impl<const D: usize> PowerCubic<D> {
    pub(crate) fn new(ctrl: &[Vector<D>; 4]) -> Self {
        let [a, b, c, d] = *ctrl;
        Self {
            c: [
                (a + 4.0 * b + c) / 6.0,
                (c - a) * 0.5,
                (a - 2.0 * b + c) * 0.5,
                (d - a + 3.0 * (b - c)) / 6.0,
            ],
            start: combine(ctrl, bspline_basis(0.0)),
            end: combine(ctrl, bspline_basis(1.0)),
        }
    }

    /// `C(t)`, by Horner's rule.
    fn at(&self, t: f64) -> Vector<D> {
        let c = &self.c;
        c[0] + (c[1] + (c[2] + c[3] * t) * t) * t
    }

    /// Newton's start for the data point `v` that follows the data point `prev` along the
    /// segment's data, `t` the foot parameter of `prev`: one Gauss–Newton step of eq. (6) from
    /// `t`, `t + (v − prev)ᵀ C'(t) / |C'(t)|²` (at the foot of `prev`, `(C(t) − prev)ᵀ C'(t) = 0`),
    /// clamped to `[0, 1]`. Its error is of the second order in the step between the two points,
    /// so Newton converges in fewer steps than from the chord-length parameter.
    pub(crate) fn start_after(&self, t: f64, prev: &Vector<D>, v: &Vector<D>) -> f64 {
        let c = &self.c;
        let d1 = c[1] + (2.0 * c[2] + 3.0 * t * c[3]) * t;
        let speed2 = d1.norm_squared();
        if speed2 > 0.0 {
            (t + (v - prev).dot(&d1) / speed2).clamp(0.0, 1.0)
        } else {
            t
        }
    }

    /// The foot point of `v`: Newton's method on eq. (6), `g(t) = (C(t) − v)ᵀ C'(t) = 0`,
    /// `g'(t) = |C'|² + (C − v)ᵀ C''`, from `t0`, clamped to `[0, 1]`, until a step is below
    /// [`FOOT_STEP`]; the segment's end points are also tried, so the result is never worse than
    /// them. Returns `(t, distance)`; the distance is that of a point of the segment, so it is
    /// never below the distance to the segment.
    pub(crate) fn foot(&self, v: &Vector<D>, t0: f64) -> (f64, f64) {
        let c = &self.c;
        let mut t = t0;
        for _ in 0..30 {
            let r = self.at(t) - v;
            let d1 = c[1] + (2.0 * c[2] + 3.0 * t * c[3]) * t;
            let d2 = 2.0 * c[2] + 6.0 * t * c[3];
            let g = r.dot(&d1);
            let gp = d1.norm_squared() + r.dot(&d2);
            if gp <= 0.0 || !gp.is_finite() {
                break;
            }
            let next = (t - g / gp).clamp(0.0, 1.0);
            let step = (next - t).abs();
            t = next;
            if step < FOOT_STEP {
                break;
            }
        }
        // Compared squared: the square root is monotone.
        let mut best = (t, (self.at(t) - v).norm_squared());
        for (e, end) in [(0.0, &self.start), (1.0, &self.end)] {
            let d = (end - v).norm_squared();
            if d < best.1 {
                best = (e, d);
            }
        }
        (best.0, best.1.sqrt())
    }
}

/// Distance from `p` to the polyline through `poly` (to its vertex if it has one point;
/// infinite if empty).
pub fn point_polyline_distance<const D: usize>(p: &Vector<D>, poly: &[Vector<D>]) -> f64 {
    match poly {
        [] => f64::INFINITY,
        [q] => (p - q).norm(),
        // The square root is monotone: the root of the smallest square is the smallest distance.
        _ => poly
            .windows(2)
            .map(|w| point_edge_distance_squared(p, &w[0], &w[1]))
            .fold(f64::INFINITY, f64::min)
            .sqrt(),
    }
}

/// Squared distance from `p` to the edge from `a` to `b`.
fn point_edge_distance_squared<const D: usize>(p: &Vector<D>, a: &Vector<D>, b: &Vector<D>) -> f64 {
    let e = b - a;
    let len2 = e.norm_squared();
    let s = if len2 > 0.0 {
        ((p - a).dot(&e) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + e * s)).norm_squared()
}

/// Edges per box of [`curve_to_polyline`]'s pruning.
const CHUNK: usize = 8;

/// The largest distance from the samples `C(m / s)`, `m = 0..=s`, of the cubic B-spline segment
/// `ctrl` to the polyline `poly`, and the parameter of the first sample where it is reached.
///
/// Exactly `max_m point_polyline_distance(C(m / s), poly)`, computed without scanning the whole
/// polyline for most samples: the nearest edge is followed from one sample to the next (a walk
/// while the next edge is nearer), and the distance to that edge is an upper bound of the
/// sample's distance to the polyline. The samples are then measured in the order of decreasing
/// bound, and a sample whose bound is below the largest distance so far cannot raise the maximum
/// and is skipped; the others are measured exactly, searching the polyline with the bounding
/// boxes of runs of [`CHUNK`] edges and skipping those farther than the nearest edge found.
/// Stops as soon as the maximum exceeds `cap` (then the maximum so far is returned).
pub(crate) fn curve_to_polyline<const D: usize>(
    ctrl: &[Vector<D>; 4],
    poly: &[Vector<D>],
    samples: usize,
    cap: f64,
) -> (f64, f64) {
    let edges = poly.len().saturating_sub(1);
    let sample = |m: usize| {
        let u = m as f64 / samples as f64;
        (u, combine(ctrl, bspline_basis(u)))
    };
    if edges == 0 {
        let d = poly.first().map_or(f64::INFINITY, |q| {
            (0..=samples)
                .map(|m| (sample(m).1 - q).norm())
                .fold(0.0, f64::max)
        });
        return (d, 0.0);
    }
    // (upper bound, its square, u, sample) per sample, from the walk along the polyline.
    let mut e = 0;
    let mut bounds: Vec<(f64, f64, f64, Vector<D>)> = (0..=samples)
        .map(|m| {
            let (u, p) = sample(m);
            let mut bound = point_edge_distance_squared(&p, &poly[e], &poly[e + 1]);
            while e + 1 < edges {
                let next = point_edge_distance_squared(&p, &poly[e + 1], &poly[e + 2]);
                if next >= bound {
                    break;
                }
                bound = next;
                e += 1;
            }
            (bound.sqrt(), bound, u, p)
        })
        .collect();
    let mut boxes: Vec<(Vector<D>, Vector<D>)> = Vec::new();
    let (mut worst, mut worst_u) = (0.0_f64, 0.0);
    // The sample of largest bound next (of the smallest parameter among equal bounds); usually
    // one or two are measured, so this selection is cheaper than sorting.
    while let Some(next) = (0..bounds.len()).reduce(|x, y| {
        if bounds[y].0 > bounds[x].0 || (bounds[y].0 == bounds[x].0 && bounds[y].2 < bounds[x].2) {
            y
        } else {
            x
        }
    }) {
        let (bound, bound2, u, p) = bounds.swap_remove(next);
        // The sample's distance is at most `bound`: it can raise the maximum (or reach it at an
        // earlier parameter) only if `bound` does; no sample left has a larger bound.
        if bound < worst || (bound == worst && u > worst_u) {
            break;
        }
        // The first sample measured is usually the only one: a plain scan, boxes after it.
        let d = if boxes_ready(&mut boxes, poly) {
            nearest_edge_distance(&p, poly, &boxes, bound2)
        } else {
            point_polyline_distance(&p, poly)
        };
        if d > worst || (d == worst && u < worst_u) {
            worst = d;
            worst_u = u;
            if worst > cap {
                break;
            }
        }
    }
    (worst, worst_u)
}

/// Whether the boxes of runs of [`CHUNK`] edges of `poly` are there; builds them (for the next
/// call) when they are not.
fn boxes_ready<const D: usize>(
    boxes: &mut Vec<(Vector<D>, Vector<D>)>,
    poly: &[Vector<D>],
) -> bool {
    if !boxes.is_empty() {
        return true;
    }
    boxes.extend(poly.chunks(CHUNK).enumerate().map(|(c, run)| {
        // The run's edges end at the first point of the next run.
        let end = poly.get((c + 1) * CHUNK).unwrap_or(&run[run.len() - 1]);
        let (mut lo, mut hi) = (*end, *end);
        for q in run {
            for k in 0..D {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
        (lo, hi)
    }));
    false
}

/// `min(√bound, point_polyline_distance(p, poly))` (`bound` a squared distance) for a polyline of at least two points, skipping
/// the runs of [`CHUNK`] edges whose bounding box (`boxes`) is farther than the nearest edge so far
/// (with a margin for the rounding of the edge distance).
fn nearest_edge_distance<const D: usize>(
    p: &Vector<D>,
    poly: &[Vector<D>],
    boxes: &[(Vector<D>, Vector<D>)],
    bound: f64,
) -> f64 {
    let edges = poly.len() - 1;
    let (mut best, mut best2) = (bound.sqrt(), bound);
    for (c, (lo, hi)) in boxes.iter().enumerate() {
        let gap = (lo - p).sup(&(p - hi)).sup(&Vector::<D>::default()).norm();
        let margin = 8.0 * f64::EPSILON * (p.amax() + lo.amax() + hi.amax());
        if gap - margin >= best {
            continue;
        }
        let run = (c * CHUNK..((c + 1) * CHUNK).min(edges))
            .map(|i| point_edge_distance_squared(p, &poly[i], &poly[i + 1]))
            .fold(f64::INFINITY, f64::min);
        if run < best2 {
            best2 = run;
            best = run.sqrt();
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use bez_core::Vector2;
    use proptest::prelude::*;

    fn v((x, y): (f64, f64)) -> Vector2 {
        Vector2::new(x, y)
    }

    proptest! {
        /// The pruned curve-to-polyline maximum is bit for bit the plain maximum over the
        /// samples of `point_polyline_distance` (the first parameter where it is reached
        /// included), on polylines that follow the segment with noise and on arbitrary ones; with
        /// a cap, it stops above the cap or returns the plain maximum.
        #[test]
        fn curve_to_polyline_is_the_plain_maximum(
            ctrl in prop::array::uniform4((-3.0f64..3.0, -3.0f64..3.0)),
            noise in prop::collection::vec((-0.2f64..0.2, -0.2f64..0.2), 2..60),
            follow in any::<bool>(),
            samples in 1usize..40,
            cap in prop::sample::select(vec![0.01, 0.1, 1.0, f64::INFINITY]),
        ) {
            let ctrl = ctrl.map(v);
            let m = noise.len();
            let poly: Vec<Vector2> = noise
                .iter()
                .enumerate()
                .map(|(i, &e)| {
                    let base = if follow {
                        combine(&ctrl, bspline_basis(i as f64 / (m - 1) as f64))
                    } else {
                        v((e.1 * 20.0, e.0 * 20.0))
                    };
                    base + v(e)
                })
                .collect();
            let (mut plain, mut plain_u) = (0.0_f64, 0.0);
            for k in 0..=samples {
                let u = k as f64 / samples as f64;
                let d = point_polyline_distance(&combine(&ctrl, bspline_basis(u)), &poly);
                if d > plain {
                    plain = d;
                    plain_u = u;
                }
            }
            let (got, got_u) = curve_to_polyline(&ctrl, &poly, samples, cap);
            if plain > cap {
                prop_assert!(got > cap && got <= plain);
            } else {
                prop_assert_eq!((got, got_u), (plain, plain_u));
            }
        }

        /// The foot point is converged: its distance is at most 10⁻⁹ (of the control points'
        /// scale) above the smallest distance over a fine ternary search within 0.02 of its
        /// parameter (an independent oracle), for points near the curve, starting from the
        /// parameter off by up to 0.05 or from the tangent step after a neighbouring point
        /// (`start_after`), where the curve is regular round the foot point.
        #[test]
        fn foot_point_is_converged_near_the_curve(
            ctrl in prop::array::uniform4((-3.0f64..3.0, -3.0f64..3.0)),
            u in 0.05f64..0.95,
            offset in -0.05f64..0.05,
            shift in -0.05f64..0.05,
        ) {
            let ctrl = ctrl.map(v);
            let cubic = PowerCubic::new(&ctrl);
            let derivatives = |t: f64| {
                let c = &cubic.c;
                (c[1] + (2.0 * c[2] + 3.0 * t * c[3]) * t, 2.0 * c[2] + 6.0 * t * c[3])
            };
            // Regular: the speed well above zero and the radius of curvature well above 0.05.
            let regular = |t: f64| {
                let (d1, d2) = derivatives(t);
                let speed = d1.norm();
                speed > 0.5 && d1.perp(&d2).abs() < 4.0 * speed.powi(3)
            };
            prop_assume!(regular(u));
            let (d1, _) = derivatives(u);
            let normal = v((-d1.y(), d1.x())) / d1.norm();
            let q = cubic.at(u) + normal * offset;
            let scale = 1.0 + ctrl.iter().map(Vector2::amax).fold(0.0, f64::max);
            let p = cubic.at(u - 0.01) + normal * offset;
            for t0 in [(u + shift).clamp(0.0, 1.0), cubic.start_after(u - 0.01, &p, &q)] {
                let (ft, d) = cubic.foot(&q, t0);
                if !(0.02..=0.98).contains(&ft) || ![ft - 0.02, ft, ft + 0.02].map(regular).iter().all(|&r| r) {
                    continue;
                }
                let exact = |t: f64| (cubic.at(t) - q).norm();
                let (mut lo, mut hi) = (ft - 0.02, ft + 0.02);
                for _ in 0..200 {
                    let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
                    if exact(m1) < exact(m2) { hi = m2 } else { lo = m1 }
                }
                let oracle = exact(0.5 * (lo + hi));
                prop_assert!(d <= oracle + 1e-9 * scale, "{d} vs {oracle}");
            }
        }

        /// The power form is the B-spline form (eq. 1), and the foot point is never farther than
        /// the segment's end points or a dense sampling's best by more than rounding.
        #[test]
        fn power_form_and_foot_point(
            ctrl in prop::array::uniform4((-3.0f64..3.0, -3.0f64..3.0)),
            q in (-3.0f64..3.0, -3.0f64..3.0),
            t in 0.0f64..=1.0,
        ) {
            let ctrl = ctrl.map(v);
            let cubic = PowerCubic::new(&ctrl);
            let scale = 1.0 + ctrl.iter().map(Vector2::amax).fold(0.0, f64::max);
            prop_assert!((cubic.at(t) - combine(&ctrl, bspline_basis(t))).norm() < 1e-13 * scale);
            let q = v(q);
            let (ft, d) = cubic.foot(&q, t);
            prop_assert!((0.0..=1.0).contains(&ft));
            prop_assert!(((combine(&ctrl, bspline_basis(ft)) - q).norm() - d).abs() < 1e-12 * scale);
            for e in [0.0, 1.0] {
                prop_assert!(d <= (combine(&ctrl, bspline_basis(e)) - q).norm() + 1e-12 * scale);
            }
        }
    }
}
