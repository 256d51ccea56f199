//! Beyond the paper: [`Method::Optimal`](crate::Method::Optimal) above degree 3, a greedy march
//! over the cubic models of [`cubic_model`](crate::cubic_model) with each chord's distance to
//! the models computed exactly.
//!
//! The curve B is covered by cubic models Cₖ on consecutive parameter ranges with
//! |B(t) − Cₖ(σ)| ≤ rₖ; each model ends where the next begins, at the same stored point. The
//! points the march sends are the models' own points Vᵢ = C(tᵢ) (each within r of B(tᵢ)), with
//! the curve's exact end points V₀ = P₀ = C(0) and Vₘ = Pₙ = C(1). For a chord over [a, b] it
//! computes e ≥ the Hausdorff distance between the models' arc C([a, b]) and the segment
//! [C(a), C(b)] (exact when the arc projects monotonically, see [`Window::bound`]), and
//! accepts the chord when e + r ≤ tol with r = maxₖ rₖ over the models the chord spans.
//!
//! Bound: every curve point B(t), t ∈ [a, b], is within r of C(t), which is within e of the
//! segment; every segment point q is within e of some C(t), which is within r of B(t). So the
//! segment and B([a, b]) are within e + r ≤ tol of each other both ways, and the polyline and
//! the curve too. (Before, the points sent were B(tᵢ) by Horner's rule, each within r of the
//! models' point, and the test was e + 2r ≤ tol.)
//!
//! A chord within one model takes a root-free upper bound on its offset instead of the exact
//! extremes ([`offset_bound`], within 0.4 % of them); one across models the exact extremes.
//!
//! Cost: a point is O(1) (a point of a model), every try O(1) per model it spans, every model
//! two O(n) evaluations (B and B′ at its end), and every block of about 16 models one O(n²) de
//! Casteljau split.

use bez_core::{HornerBernstein, Vector2, hodograph_slice};

use crate::bump::bump_bound;
use crate::cubic_model::{Model, ModelStream};
use crate::error::SubdivError;
use crate::guaranteed::FlatPoint;
use crate::stack_horner::{STACK_POINTS, StackHorner};

/// The most segments one call places (2²⁰), as up to degree 3.
const MAX_SEGMENTS: usize = crate::optimal::MAX_OPTIMAL_SEGMENTS;
/// The models' remainder target as a fraction of the tolerance: r costs 1/32 of it, about
/// 1.6 % more segments.
const MODEL_TARGET: f64 = 1.0 / 32.0;
/// The most a model's remainder may be when rounding alone exceeds the target (tolerances near
/// the rounding floor).
const MODEL_CEILING: f64 = 0.25;
/// Models held ahead of the march (a chord spans at most this many).
const WINDOW: usize = 32;
/// A chord whose bound is below this fraction of the tolerance is tried longer.
const EXTEND_BELOW: f64 = 0.92;
/// Longer tries per chord.
const MAX_EXTENSIONS: usize = 2;

/// Streams the points of `Method::Optimal` for a curve of degree ≥ 4 with control points `p`
/// after B(0) (sent by the caller): every chord within `accept` of the curve, each point (t, C(t))
/// a point of the models, within their remainder r of B(t) (r ≤ `accept` / 32, up to
/// `accept` / 4 at tolerances near the rounding floor), the last point Pₙ at t = 1. Returns
/// the number of segments. Up to degree
/// [`MAX_STACK_DEGREE`](crate::MAX_STACK_DEGREE) nothing is allocated.
///
/// # Errors
/// [`SubdivError::DepthLimit`] when a chord or a model shorter than 2^−`max_depth` fails,
/// [`SubdivError::TooManySegments`] above 2²⁰ segments.
pub(crate) fn march_models(
    p: &[Vector2],
    accept: f64,
    max_depth: usize,
    mut sink: impl FnMut(FlatPoint),
) -> Result<usize, SubdivError> {
    let len = p.len();
    let (origin, last) = (p[0], p[len - 1]);
    // The models and B are taken relative to P₀, so that their rounding follows the curve's
    // extent, not its distance from the origin; the points sent are P₀ + (B − P₀)(t).
    let send = |t: f64, relative: Vector2| FlatPoint {
        t,
        point: if t >= 1.0 { last } else { origin + relative },
    };
    if len <= STACK_POINTS {
        let mut buffers = [[Vector2::zeros(); STACK_POINTS]; 5];
        let [relative, rest, left, right, scaled] = &mut buffers;
        for (r, &q) in relative.iter_mut().zip(p) {
            *r = q - origin;
        }
        let relative = &relative[..len];
        if let Some(horner) = StackHorner::new(relative, scaled) {
            return march(
                relative,
                |t| horner.jet(t),
                [&mut rest[..len], &mut left[..len], &mut right[..len]],
                accept,
                max_depth,
                |t, q| sink(send(t, q)),
            );
        }
    }
    let relative: Vec<Vector2> = p.iter().map(|&q| q - origin).collect();
    let mut buffer = vec![Vector2::zeros(); 3 * len];
    let (rest, others) = buffer.split_at_mut(len);
    let (left, right) = others.split_at_mut(len);
    let (point, tangent) = (
        HornerBernstein::new(&relative),
        HornerBernstein::new(&hodograph_slice(p)),
    );
    let zero = Vector2::zeros();
    march(
        &relative,
        |t| {
            (
                point.eval(t).unwrap_or(zero),
                tangent.eval(t).unwrap_or(zero),
            )
        },
        [rest, left, right],
        accept,
        max_depth,
        |t, q| sink(send(t, q)),
    )
}

/// The models from the march's position on, in a ring of [`WINDOW`].
struct Window<'a, J> {
    stream: ModelStream<'a, J>,
    models: [Model; WINDOW],
    front: usize,
    len: usize,
    done: bool,
}

impl<J: Fn(f64) -> (Vector2, Vector2)> Window<'_, J> {
    fn get(&self, k: usize) -> &Model {
        &self.models[(self.front + k) % WINDOW]
    }

    /// The end of the last model held.
    fn reach(&self) -> f64 {
        if self.len == 0 {
            0.0
        } else {
            self.get(self.len - 1).t1
        }
    }

    /// Drops the models that end at or before t.
    fn drop_before(&mut self, t: f64) {
        while self.len > 1 && self.get(0).t1 <= t {
            self.front = (self.front + 1) % WINDOW;
            self.len -= 1;
        }
    }

    /// Takes models from the stream until they reach t, the window is full or the curve ends.
    fn fill_to(&mut self, t: f64) -> Result<(), SubdivError> {
        while !self.done && self.len < WINDOW && (self.len == 0 || self.reach() < t) {
            match self.stream.next_model()? {
                Some(model) => {
                    self.models[(self.front + self.len) % WINDOW] = model;
                    self.len += 1;
                }
                None => self.done = true,
            }
        }
        Ok(())
    }

    /// The bound on the distance between the curve over [`ta`, `tb`] and the chord between
    /// its points there, and the models' point at `tb`; `pa` is the models' point at `ta`.
    ///
    /// With d = C(tb) − `pa` and u = d / |d|, on each model the arc's offset u × (C − `pa`) and
    /// projection u · (C − `pa`) are cubics in σ, whose extremes over the model's part of
    /// [`ta`, `tb`] are found exactly (the ends and the roots of the quadratic derivative).
    /// Every arc point is within hypot(max |offset|, overshoot) of the chord (overshoot: how
    /// far the projection leaves [0, |d|]), and the continuous projection covers [0, |d|], so
    /// every chord point has an arc point at distance ≤ max |offset|: that is the Hausdorff
    /// distance between arc and chord when the projection stays inside. (The cubics are taken
    /// along d, |d| times these, and divided by |d| once.) Then add maxₖ rₖ (the
    /// curve is within r of the models' arc, and the chord's ends are the models' points).
    ///
    /// A chord within one model (about two thirds of the tries at 1e-5 × size) whose
    /// projection is monotone takes the root-free upper bound of [`offset_bound`] instead of
    /// the exact extremes (within 0.4 % of them): no square root and one division less per
    /// try.
    fn bound(&self, ta: f64, pa: Vector2, tb: f64) -> (f64, Vector2) {
        let mut k = 0;
        while k + 1 < self.len && self.get(k).t1 < tb {
            k += 1;
        }
        let pb = self.get(k).point(tb);
        let d = pb - pa;
        // Offsets and projections are taken along d itself (|d| times their values along the
        // unit vector) and divided by |d| once at the end. Coordinates within 2^±129 keep
        // their squares finite; for |d| below 1e-90 (far below any tolerance, ≥ 16 ulps of
        // coordinates ≥ 2^−128) the distance to `pa` bounds the chord instead, so that what
        // underflows in the cubics' discriminants is below 1e-200 after the division by |d|.
        let len2 = d.dot(&d);
        let projected = len2 >= 1e-180;
        if projected && (k == 0 || self.get(k - 1).t1 <= ta) {
            // The chord within one model: its offset bounded without roots when the arc
            // projects monotonically (see `offset_bound`), else the exact extremes below.
            let m = self.get(k);
            let (s0, s1) = (m.sigma(ta), m.sigma(tb));
            let rel = m.p0 - pa;
            let along = [d.dot(&rel), d.dot(&m.a), d.dot(&m.b), d.dot(&m.c)];
            if increasing(along, s0, s1) {
                let cross = [d.perp(&rel), d.perp(&m.a), d.perp(&m.b), d.perp(&m.c)];
                if let Some((numerator, denominator)) = offset_bound(cross, s0, s1) {
                    return (numerator / (denominator * len2.sqrt()) + m.r, pb);
                }
            }
        }
        let (mut offset, mut lo, mut hi, mut r) = (0.0_f64, 0.0_f64, len2, 0.0_f64);
        for j in 0..=k {
            let m = self.get(j);
            if m.t1 <= ta {
                continue;
            }
            r = r.max(m.r);
            let (s0, s1) = (m.sigma(ta.max(m.t0)), m.sigma(tb.min(m.t1)));
            let rel = m.p0 - pa;
            if projected {
                let cross = [d.perp(&rel), d.perp(&m.a), d.perp(&m.b), d.perp(&m.c)];
                let (low, high) = cubic_range(cross, s0, s1);
                offset = offset.max(high).max(-low);
                let along = [d.dot(&rel), d.dot(&m.a), d.dot(&m.b), d.dot(&m.c)];
                if !increasing(along, s0, s1) {
                    let (low, high) = cubic_range(along, s0, s1);
                    lo = lo.min(low);
                    hi = hi.max(high);
                }
            } else {
                // A closed chord: the distance to its point, bounded term by term.
                let reach = rel.norm() + s1 * (m.a.norm() + s1 * (m.b.norm() + s1 * m.c.norm()));
                offset = offset.max(reach);
            }
        }
        let len = len2.sqrt();
        let e = if projected {
            let overshoot = (-lo).max(hi - len2);
            if overshoot > 0.0 {
                offset.hypot(overshoot) / len
            } else {
                offset / len
            }
        } else {
            // Every chord point is within |d| of `pa`, a point of the arc.
            offset.max(len)
        };
        (e + r, pb)
    }
}

/// The largest ratio (c₃ / 2)² / (c₂ + 3c₃ / 2)² for which [`offset_bound`] answers: its bound
/// is then within 1/64 · ¼ = 0.4 % of the exact maximum of the bump.
const BUMP_SKEW: f64 = 1.0 / 64.0;

/// An upper bound on max |K(s)| over [s0, s1] for the cubic K(s) = k₀ + k₁ s + k₂ s² + k₃ s³,
/// without roots, as a fraction (numerator, denominator > 0); `None` when the bound would be
/// loose (then the exact extremes are taken).
///
/// With h = s1 − s0 and s = s0 + h x, K = c₀ + c₁ x + c₂ x² + c₃ x³ (c₀ = K(s0), c₁ = h K′(s0),
/// c₂ = h² K″(s0) / 2, c₃ = h³ k₃), and K = (1 − x) K(s0) + x K(s1) + q(x) with the bump
/// q(x) = −x(1 − x)(c₂ + c₃ + c₃ x) (it vanishes at both ends). With y = 2x − 1 ∈ [−1, 1],
/// q = −¼ (1 − y²)(m + δ y), m = c₂ + 3c₃/2, δ = c₃/2, and |q| ≤ (4m² + δ²) / (16 |m|) by
/// [`bump_bound`] (within [`BUMP_SKEW`]/4 of its maximum). Then
/// |K| ≤ max(|K(s0)|, |K(s1)|) + |q|, returned as
/// (16 |m| max(|K(s0)|, |K(s1)|) + 4m² + δ², 16 |m|). For a chord within one model K(s0) and
/// K(s1) are the chord's ends' offsets, zero up to rounding, and the bound is the bump's.
#[inline(always)]
fn offset_bound(k: [f64; 4], s0: f64, s1: f64) -> Option<(f64, f64)> {
    let h = s1 - s0;
    let h2 = h * h;
    let c0 = k[0] + s0 * (k[1] + s0 * (k[2] + s0 * k[3]));
    let c1 = h * (k[1] + s0 * (2.0 * k[2] + 3.0 * s0 * k[3]));
    let c2 = h2 * (k[2] + 3.0 * s0 * k[3]);
    let c3 = h2 * h * k[3];
    let ends = c0.abs().max((c0 + c1 + c2 + c3).abs());
    // A vanishing m (a straight piece) goes to the exact extremes.
    bump_bound(c2 + 1.5 * c3, 0.5 * c3, BUMP_SKEW)
        .map(|(bump, denominator)| (denominator * ends + bump, denominator))
}

/// Whether k₀ + k₁ s + k₂ s² + k₃ s³ is non-decreasing on [s0, s1], by a sufficient test
/// without divisions: its derivative, a quadratic, lies above its Bernstein coefficients on
/// [s0, s1] (the values at both ends and the one between), which are then ≥ 0. A monotone
/// projection has no overshoot: its values stay between those at the chord's ends.
#[inline]
fn increasing(k: [f64; 4], s0: f64, s1: f64) -> bool {
    let slope = |s: f64| k[1] + s * (2.0 * k[2] + s * 3.0 * k[3]);
    let (d0, d1) = (slope(s0), slope(s1));
    let middle = d0 + 0.5 * (s1 - s0) * (2.0 * k[2] + 6.0 * k[3] * s0);
    d0 >= 0.0 && d1 >= 0.0 && middle >= 0.0
}

/// The least and greatest values of k₀ + k₁ s + k₂ s² + k₃ s³ over [s0, s1]: at the ends and at
/// the roots of the derivative k₁ + 2k₂ s + 3k₃ s² inside (the cancellation-free pair q / A,
/// C / q of the quadratic A s² + B s + C). Inlined: it runs once or twice per model on every
/// try.
#[inline(always)]
fn cubic_range(k: [f64; 4], s0: f64, s1: f64) -> (f64, f64) {
    let f = |s: f64| k[0] + s * (k[1] + s * (k[2] + s * k[3]));
    let (f0, f1) = (f(s0), f(s1));
    let (mut lo, mut hi) = (f0.min(f1), f0.max(f1));
    let mut visit = |s: f64| {
        if s > s0 && s < s1 {
            let v = f(s);
            lo = lo.min(v);
            hi = hi.max(v);
        }
    };
    let (qa, qb, qc) = (3.0 * k[3], 2.0 * k[2], k[1]);
    if qa == 0.0 {
        if qb != 0.0 {
            visit(-qc / qb);
        }
    } else {
        let disc = qb * qb - 4.0 * qa * qc;
        if disc >= 0.0 {
            let q = -0.5 * (qb + qb.signum() * disc.sqrt());
            visit(q / qa);
            if q != 0.0 {
                visit(qc / q);
            }
        }
    }
    (lo, hi)
}

/// The march on the models of `p` (buffers for [`ModelStream`]) with `jet` for B and B′, sending
/// each point (t, C(t)) after the first to `sink` (C the models, within r of B; C(1) = Pₙ).
fn march<J: Fn(f64) -> (Vector2, Vector2)>(
    p: &[Vector2],
    jet: J,
    buffers: [&mut [Vector2]; 3],
    accept: f64,
    max_depth: usize,
    mut sink: impl FnMut(f64, Vector2),
) -> Result<usize, SubdivError> {
    let stream = ModelStream::new(
        p,
        jet,
        buffers,
        (accept * MODEL_TARGET, accept * MODEL_CEILING),
        max_depth,
    );
    let mut window = Window {
        stream,
        models: [Model {
            t0: 0.0,
            t1: 0.0,
            inverse_span: 0.0,
            p0: Vector2::zeros(),
            a: Vector2::zeros(),
            b: Vector2::zeros(),
            c: Vector2::zeros(),
            end: Vector2::zeros(),
            r: 0.0,
        }; WINDOW],
        front: 0,
        len: 0,
        done: false,
    };
    window.fill_to(0.0)?;
    let min_step = 0.5_f64.powi(i32::try_from(max_depth).unwrap_or(i32::MAX));
    let (mut ta, mut pa) = (0.0_f64, p[0]);
    let mut step = first_step(window.get(0), accept);
    let mut segments = 0;
    let mut previous = 0.0_f64;
    while ta < 1.0 {
        window.drop_before(ta);
        let mut best: Option<(f64, Vector2, f64)> = None;
        let mut extensions = 0;
        loop {
            let want = if ta + step >= 1.0 { 1.0 } else { ta + step };
            window.fill_to(want)?;
            let tb = want.min(window.reach());
            let (e, pb) = window.bound(ta, pa, tb);
            let h = tb - ta;
            if e <= accept {
                best = Some((tb, pb, e));
                if e >= EXTEND_BELOW * accept || tb >= 1.0 || extensions == MAX_EXTENSIONS {
                    break;
                }
                // Well inside: try longer (the bound grows like h²).
                extensions += 1;
                let grow = if e > 0.0 {
                    (0.995 * (accept / e).sqrt()).min(2.0)
                } else {
                    2.0
                };
                if tb < want {
                    // The window is full: the chord cannot be longer.
                    break;
                }
                step = h * grow;
                continue;
            }
            if best.is_some() {
                // A longer try failed: keep the one that passed.
                break;
            }
            // Also for a NaN bound: the depth limit ends the shortening.
            let shrink = if e.is_finite() {
                (0.995 * (accept / e).sqrt()).clamp(0.3, 0.99)
            } else {
                0.5
            };
            if h * shrink < min_step {
                return Err(SubdivError::DepthLimit { limit: max_depth });
            }
            step = h * shrink;
        }
        let Some((tb, pb, e)) = best else {
            break;
        };
        segments += 1;
        if segments > MAX_SEGMENTS {
            return Err(SubdivError::TooManySegments {
                tolerance: accept,
                limit: MAX_SEGMENTS,
            });
        }
        sink(tb, pb);
        // The next chord's first try: this one's length, rescaled to fill the tolerance and by
        // the trend of the density √e / h from the chord before (within 0.8–1.25).
        let h = tb - ta;
        let density = e.sqrt() / h;
        let trend = if previous > 0.0 && density > 0.0 {
            (density / previous).clamp(0.8, 1.25)
        } else {
            1.0
        };
        previous = density;
        step = if e > 0.0 {
            h * (0.995 * (accept / e).sqrt() / trend).clamp(0.5, 2.0)
        } else {
            2.0 * h
        };
        (ta, pa) = (tb, pb);
    }
    Ok(segments)
}

/// The first chord's length from the density √(|C′ × C″| / |C′|) of the first model at t = 0
/// (an arc of curvature κ and parameter length h deviates from its chord by about
/// κ |C′|² h² / 8), the whole first model where it vanishes.
fn first_step(m: &Model, accept: f64) -> f64 {
    let w = m.t1 - m.t0;
    let (d1, d2) = (m.a / w, m.b * (2.0 / (w * w)));
    let speed = d1.norm();
    let density = if speed > 0.0 {
        (d1.perp(&d2).abs() / speed).sqrt()
    } else {
        0.0
    };
    let h = (8.0 * accept).sqrt() / density;
    if h.is_finite() && h > 0.0 {
        h.min(1.0)
    } else {
        w
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]

    use bez_core::proptest_support::curve;
    use proptest::prelude::*;

    use super::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Every point sent is a point of the models: within r ≤ accept / 32 of B(t) (de
        /// Casteljau's point, an independent evaluation), the parameters increasing, the last
        /// point Pₙ exactly at t = 1, and the count returned the number of points.
        #[test]
        fn points_are_within_the_remainder(c in curve::<2>(4..=30, 10.0), rel in 1e-5f64..1e-1) {
            let size = c.points().iter().map(Vector2::amax).fold(1.0, f64::max);
            let accept = rel * size;
            let mut points = Vec::new();
            let segments = march_models(c.points(), accept, 40, |q| points.push(q)).unwrap();
            prop_assert_eq!(points.len(), segments);
            let last = points.last().unwrap();
            prop_assert_eq!((last.t, last.point), (1.0, c.end()));
            let mut t = 0.0;
            for q in &points {
                prop_assert!(q.t > t);
                t = q.t;
                let error = (q.point - c.eval(q.t).unwrap()).norm();
                prop_assert!(
                    error <= MODEL_TARGET * accept + 1e-12 * size,
                    "{} > {}", error, MODEL_TARGET * accept
                );
            }
        }
    }

    /// The chord bound's cubics are taken along the unnormalized chord, whose squares must stay
    /// finite and normal: a curve scaled by 2^±120 (near the range the flattener keeps
    /// coordinates in) gives the same points, scaled, and stays within the tolerance.
    #[test]
    fn power_of_two_scaling_is_exact() {
        let points: Vec<Vector2> = (0..=12)
            .map(|i| {
                let x = f64::from(i);
                Vector2::new(x + (x * 1.7).sin(), ((i * 7) % 5) as f64 - 2.0)
            })
            .collect();
        let curve = bez_core::BezierCurve::new(points.clone()).unwrap();
        let accept = 1e-4 * crate::curve_size(&curve);
        let mut reference = Vec::new();
        march_models(&points, accept, 40, |q| reference.push(q)).unwrap();
        for scale in [2.0_f64.powi(120), 2.0_f64.powi(-120)] {
            let scaled: Vec<Vector2> = points.iter().map(|&p| p * scale).collect();
            let mut out = Vec::new();
            march_models(&scaled, accept * scale, 40, |q| out.push(q)).unwrap();
            assert_eq!(out.len(), reference.len());
            for (a, b) in out.iter().zip(&reference) {
                assert_eq!((a.t, a.point), (b.t, b.point * scale));
            }
            let mut polyline = vec![scaled[0]];
            polyline.extend(out.iter().map(|q| q.point));
            let c = bez_core::BezierCurve::new(scaled).unwrap();
            let sampling = crate::HausdorffSampling {
                curve_samples: 4001,
                segment_samples: 3,
            };
            let error = crate::measured_hausdorff(&c, &polyline, sampling).unwrap();
            assert!(error <= accept * scale, "{}", error / (accept * scale));
        }
    }

    /// The largest |K| over [s0, s1] by dense sampling (the oracle of the bounds below).
    fn sampled_max(k: [f64; 4], s0: f64, s1: f64) -> f64 {
        (0..=20_000)
            .map(|i| {
                let s = s0 + (s1 - s0) * f64::from(i) / 20_000.0;
                (k[0] + s * (k[1] + s * (k[2] + s * k[3]))).abs()
            })
            .fold(0.0, f64::max)
    }

    proptest! {
        /// `offset_bound` is an upper bound on max |K| (dense sampling), on any cubic and
        /// range where it answers.
        #[test]
        fn offset_bound_is_an_upper_bound(
            k in proptest::array::uniform4(-10.0f64..10.0),
            a in 0.0f64..1.0,
            b in 0.0f64..1.0,
        ) {
            let (s0, s1) = (a.min(b), a.max(b));
            if let Some((numerator, denominator)) = offset_bound(k, s0, s1) {
                prop_assert!(denominator > 0.0);
                let bound = numerator / denominator;
                let exact = sampled_max(k, s0, s1);
                prop_assert!(bound >= exact - 1e-12, "{} < {}", bound, exact);
            }
        }

        /// On a chord within one model the offset K vanishes at both ends, K = (s − s0)(s − s1)
        /// (α s + β): there the bound answers whenever (c₃/2)² ≤ m²/64 and is within
        /// `BUMP_SKEW` / 4 (relative) of the exact maximum (dense sampling, and
        /// `cubic_range`).
        #[test]
        fn offset_bound_is_tight_between_zeros(
            alpha in -10.0f64..10.0,
            beta in -10.0f64..10.0,
            a in 0.0f64..1.0,
            b in 0.0f64..1.0,
        ) {
            let (s0, s1) = (a.min(b), a.max(b));
            prop_assume!(s1 - s0 > 1e-3);
            // (s² − (s0 + s1) s + s0 s1)(α s + β)
            let (p, q) = (-(s0 + s1), s0 * s1);
            let k = [q * beta, q * alpha + p * beta, p * alpha + beta, alpha];
            let exact = sampled_max(k, s0, s1);
            let (low, high) = cubic_range(k, s0, s1);
            let h = s1 - s0;
            // m and δ of `offset_bound` for this K: c₂ = h² (k₂ + 3 k₃ s0), c₃ = h³ k₃.
            let (c2, c3) = (h * h * (k[2] + 3.0 * k[3] * s0), h * h * h * k[3]);
            let (m, delta) = (c2 + 1.5 * c3, 0.5 * c3);
            let answered = offset_bound(k, s0, s1);
            if m != 0.0 && delta * delta <= BUMP_SKEW * m * m * (1.0 - 1e-9) {
                prop_assert!(answered.is_some());
            }
            if let Some((numerator, denominator)) = answered {
                let bound = numerator / denominator;
                let scale = 1e-12 * (alpha.abs() + beta.abs());
                prop_assert!(bound >= exact - scale);
                prop_assert!(bound >= high.max(-low) - scale);
                prop_assert!(
                    bound <= exact * (1.0 + BUMP_SKEW / 4.0) + scale,
                    "{} against {}", bound, exact
                );
            }
        }
    }

    /// `cubic_range` against dense sampling, with extremes inside and outside the range.
    #[test]
    fn cubic_range_is_the_range() {
        for k in [
            [0.0, 1.0, -3.0, 2.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.5, -2.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
            [-1.0, 4.0, -6.0, 1.5],
        ] {
            for (s0, s1) in [(0.0, 1.0), (0.2, 0.7), (0.5, 0.5)] {
                let (lo, hi) = cubic_range(k, s0, s1);
                let (mut slo, mut shi) = (f64::INFINITY, f64::NEG_INFINITY);
                for i in 0..=100_000 {
                    let s = s0 + (s1 - s0) * f64::from(i) / 100_000.0;
                    let v = k[0] + s * (k[1] + s * (k[2] + s * k[3]));
                    slo = slo.min(v);
                    shi = shi.max(v);
                }
                assert!(lo <= slo && lo >= slo - 1e-9, "{k:?} {s0} {s1}: {lo} {slo}");
                assert!(hi >= shi && hi <= shi + 1e-9, "{k:?} {s0} {s1}: {hi} {shi}");
            }
        }
    }
}
