//! Beyond the paper: [`Method::Optimal`](crate::Method::Optimal) above degree 3, a greedy march
//! over the quintic models of [`quintic_model`](crate::quintic_model), each chord checked against
//! the cubic Hermite interpolant of the models' arc.
//!
//! The curve B is covered by quintic models Qₖ on consecutive parameter ranges with
//! |B(t) − Qₖ(σ)| ≤ rₖ; each model ends where the next begins, at the same stored point. The
//! points the march sends are the models' own points Vᵢ = Q(tᵢ) (each within r of B(tᵢ)), with
//! the curve's exact end points V₀ = P₀ = Q(0) and Vₘ = Pₙ = Q(1).
//!
//! A chord over [a, b] within one model: H, the cubic Hermite interpolant of Q at a and b (Q and
//! Q′ there), is within ρ = k⁴/16 · max |L| of Q on [a, b] (Q − H = y²(k − y)² L(y) with L
//! linear, [`Model::hermite_quotient`]), and e ≥ the Hausdorff distance between H([a, b]) and
//! the segment [Q(a), Q(b)] comes in closed form when H projects monotonically onto it
//! ([`hermite_chord`]; H has the same ends). The chord is accepted when e + ρ + r ≤ tol. A chord
//! across models takes each model's part [u, v] in turn: its Hermite cubic Hₖ (within ρₖ of Qₖ
//! there), whose offset from the chord line and projection onto it are cubics with exact
//! extremes; e is then hypot(max |offset|, overshoot) / |d| plus the largest ρₖ + rₖ.
//!
//! Bound: every curve point B(t), t ∈ [a, b], is within r of Q(t), which is within ρ of H(t),
//! which is within e of the segment; every segment point is within e of some H(t), within ρ of
//! Q(t), within r of B(t). So the segment and B([a, b]) are within e + ρ + r ≤ tol of each
//! other both ways, and the polyline and the curve too.
//!
//! Cost: a point is O(1) (a point of a model), every try O(1) per model it spans, every model
//! one O(n) evaluation (B, B′ and B″ at its end), and every block of about 8 models one O(n²)
//! de Casteljau split.

use bez_core::{HornerBernstein, Vector2, hodograph_slice};

use crate::bump::{bump_bound, cubic_offset};
use crate::error::SubdivError;
use crate::guaranteed::FlatPoint;
use crate::order::{greater, lesser, limited};
use crate::quintic_model::{Jet2, Model, ModelStream};
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
                |t| horner.jet2(t),
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
    let hodograph = hodograph_slice(p);
    let (point, tangent, curl) = (
        HornerBernstein::new(&relative),
        HornerBernstein::new(&hodograph),
        HornerBernstein::new(&hodograph_slice(&hodograph)),
    );
    let zero = Vector2::zeros();
    march(
        &relative,
        |t| {
            (
                point.eval(t).unwrap_or(zero),
                tangent.eval(t).unwrap_or(zero),
                curl.eval(t).unwrap_or(zero),
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
    /// The last chord start's parameter, its model's start and Q′ there.
    start: (f64, f64, Vector2),
}

impl<J: Fn(f64) -> Jet2> Window<'_, J> {
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
    #[inline(always)]
    fn drop_before(&mut self, t: f64) {
        while self.len > 1 && self.get(0).t1 <= t {
            self.front = (self.front + 1) % WINDOW;
            self.len -= 1;
        }
    }

    /// Takes models from the stream until they reach t, the window is full or the curve ends
    /// (the check inline: on most tries there is nothing to take).
    #[inline(always)]
    fn fill_to(&mut self, t: f64) -> Result<(), SubdivError> {
        if self.done || self.len == WINDOW || (self.len > 0 && self.reach() >= t) {
            return Ok(());
        }
        self.take_to(t)
    }

    /// The stream's part of [`Window::fill_to`].
    #[inline(never)]
    fn take_to(&mut self, t: f64) -> Result<(), SubdivError> {
        while !self.done && self.len < WINDOW && (self.len == 0 || self.reach() < t) {
            if self
                .stream
                .next_model(&mut self.models[(self.front + self.len) % WINDOW])?
            {
                self.len += 1;
            } else {
                self.done = true;
            }
        }
        Ok(())
    }

    /// The bound on the distance between the curve over [`ta`, `tb`] and the chord between
    /// its points there, and the models' point at `tb`; `pa` is the models' point at `ta` and
    /// `accept` the tolerance (the bounds stop early when it is met).
    ///
    /// Within one model whose arc H projects monotonically onto the chord: [`hermite_chord`]
    /// for the cubic Hermite interpolant H of the model Q at `ta` and `tb`, plus the model's
    /// remainder r and Q − H = y²(k − y)² L(y) ([`Model::hermite_quotient`]): first with the
    /// model's bound on |L|, and where that fails by its parts across and along the chord: every
    /// arc point Q(t) is then within hypot(|u × (H − pa)| + across, along) of the chord (H's
    /// projection lies in [0, |d|], Q's leaves it by at most `along`), and every chord point
    /// within max |u × (Q − pa)| of the arc (Q's projection covers [0, |d|]).
    ///
    /// Across models: on each model's part [u, v] of [`ta`, `tb`], Hₖ(λ) = Qₖ(u) + λE₀ +
    /// λ²(3Δ − 2E₀ − E₁) + λ³(E₀ + E₁ − 2Δ) with E = (v − u) Q′ and Δ = Qₖ(v) − Qₖ(u); with
    /// d = Q(b) − `pa` and u = d / |d|, its offset u × (Hₖ − `pa`) and projection u · (Hₖ − `pa`)
    /// are cubics in λ whose extremes over [0, 1] are found exactly (the ends and the roots of
    /// the quadratic derivative). Every arc point is within hypot(max |offset|, overshoot) of
    /// the chord (overshoot: how far the projection leaves [0, |d|]), and the continuous
    /// projection covers [0, |d|], so every chord point has an arc point at distance
    /// ≤ max |offset|. (The cubics are taken along d, |d| times these, and divided by |d| once.)
    /// Then add the largest ρₖ + rₖ.
    fn bound(&mut self, ta: f64, pa: Vector2, tb: f64, accept: f64) -> (f64, Vector2) {
        let mut k = 0;
        while k + 1 < self.len && self.get(k).t1 < tb {
            k += 1;
        }
        let single = k == 0 || self.get(k - 1).t1 <= ta;
        // Q′ at `ta` is the same for every try from it on the same model.
        let da = if !single {
            Vector2::zeros()
        } else if self.start.0 == ta && self.start.1 == self.get(k).t0 {
            self.start.2
        } else {
            let da = self.get(k).slope(ta);
            self.start = (ta, self.get(k).t0, da);
            da
        };
        let last = self.get(k);
        let pb = last.point(tb);
        let d = pb - pa;
        // Offsets and projections are taken along d itself (|d| times their values along the
        // unit vector) and divided by |d| once at the end. Coordinates within 2^±129 keep
        // their squares finite; for |d| below 1e-90 (far below any tolerance, ≥ 16 ulps of
        // coordinates ≥ 2^−128) the distance to `pa` bounds the chord instead, so that what
        // underflows in the cubics' discriminants is below 1e-200 after the division by |d|.
        let len2 = d.dot(&d);
        let projected = len2 >= 1e-180;
        if projected && single {
            let len = len2.sqrt();
            let db = last.slope(tb);
            let h = tb - ta;
            // |Q − H| ≤ k⁴/16 · |L| with the model's bound on |L| first (k = h / w).
            let k = h * last.inverse_span;
            let k2 = k * k;
            let rough = k2 * k2 / 16.0 * last.quartic;
            if let Some(e) = hermite_chord(d, len2, len, da, db, h, accept - last.r - rough) {
                if e + rough + last.r <= accept {
                    return (e + rough + last.r, pb);
                }
                // Failing: Q − H = y²(k − y)² L(y) by its parts across and along the chord
                // (|d| times); the arc point is then within hypot(offset + across, along) of
                // the chord.
                let (near, far, scale) = last.hermite_quotient(ta, tb);
                let across = scale * greater(d.perp(&near).abs(), d.perp(&far).abs()) / len;
                let along = scale * greater(d.dot(&near).abs(), d.dot(&far).abs()) / len;
                let offset = e + across;
                return ((offset * offset + along * along).sqrt() + last.r, pb);
            }
        }
        let (mut offset, mut lo, mut hi, mut slack) = (0.0_f64, 0.0_f64, len2, 0.0_f64);
        for j in 0..=k {
            let m = self.get(j);
            if m.t1 <= ta {
                continue;
            }
            let (u, v) = (greater(ta, m.t0), lesser(tb, m.t1));
            let (pu, du) = m.jet(u);
            let (pv, dv) = m.jet(v);
            let h = v - u;
            slack = greater(slack, m.r + m.hermite_remainder(u, v));
            let (e0, e1, delta) = (du * h, dv * h, pv - pu);
            let (rel, a, b, c) = (
                pu - pa,
                e0,
                delta * 3.0 - e0 * 2.0 - e1,
                e0 + e1 - delta * 2.0,
            );
            if projected {
                let cross = [d.perp(&rel), d.perp(&a), d.perp(&b), d.perp(&c)];
                let (low, high) = cubic_range(cross, 0.0, 1.0);
                offset = greater(greater(offset, high), -low);
                let along = [d.dot(&rel), d.dot(&a), d.dot(&b), d.dot(&c)];
                if !increasing(along, 0.0, 1.0) {
                    let (low, high) = cubic_range(along, 0.0, 1.0);
                    lo = lesser(lo, low);
                    hi = greater(hi, high);
                }
            } else {
                // A closed chord: the distance to its point, bounded term by term.
                let reach = rel.norm() + a.norm() + b.norm() + c.norm();
                offset = greater(offset, reach);
            }
        }
        let len = len2.sqrt();
        let e = if projected {
            let overshoot = greater(-lo, hi - len2);
            if overshoot > 0.0 {
                offset.hypot(overshoot) / len
            } else {
                offset / len
            }
        } else {
            // Every chord point is within |d| of `pa`, a point of the arc.
            greater(offset, len)
        };
        (e + slack, pb)
    }
}

/// A bound on the Hausdorff distance between the arc H([a, b]) of the cubic Hermite
/// interpolant H through Q(a), Q(b) with the derivatives `da`, `db` and its chord d = Q(b) − Q(a)
/// (`len2` = |d|², h = b − a), or `None` when the arc may not project monotonically onto the
/// chord (then the caller takes the exact extremes).
///
/// H′ has the Bernstein coefficients Q′(a), 3d/h − Q′(a) − Q′(b), Q′(b) (H's control points
/// Q(a), Q(a) + h Q′(a)/3, Q(b) − h Q′(b)/3, Q(b)), so the projection u · (H − Q(a)) increases
/// when all three project ≥ 0 onto d; the offset is then the distance both ways. With
/// u = d / |d|, Xₐ = u × Q′(a), X_b = u × Q′(b), the offset u × (H(a + hσ) − Q(a)) vanishes at
/// both ends and has the slopes h Xₐ, h X_b there: it is h σ(1 − σ)(Xₐ − (Xₐ + X_b) σ), at most
/// h max(|Xₐ|, |X_b|) / 4 (the linear factor lies between Xₐ and −X_b); with y = 2σ − 1 it is
/// (h/4)(1 − y²)(m + δy), m = (Xₐ − X_b)/2, δ = −(Xₐ + X_b)/2, whose maximum lies between
/// h|m|/4 and the root-free [`bump_bound`]; the exact maximum [`cubic_offset`] only when
/// `accept` lies between the two.
#[inline(always)]
fn hermite_chord(
    d: Vector2,
    len2: f64,
    len: f64,
    da: Vector2,
    db: Vector2,
    h: f64,
    accept: f64,
) -> Option<f64> {
    let (along_a, along_b) = (d.dot(&da), d.dot(&db));
    if !(along_a >= 0.0 && along_b >= 0.0 && 3.0 * len2 >= h * (along_a + along_b)) {
        return None;
    }
    // |d| Xₐ and |d| X_b: divided by |d| once.
    let (xa, xb) = (d.perp(&da), d.perp(&db));
    // The first test before any division.
    let quarter = 0.25 * h * greater(xa.abs(), xb.abs());
    if quarter <= accept * len {
        return Some(quarter / len);
    }
    let scale = h / len;
    let cheap = quarter / len;
    let m = 0.5 * (xa - xb);
    if let Some((bump, denominator)) = bump_bound(m, -0.5 * (xa + xb), 1.0) {
        let bump = scale * bump / denominator;
        if bump <= accept || 0.25 * scale * m.abs() > accept {
            return Some(lesser(bump, cheap));
        }
    }
    Some(lesser(scale * cubic_offset(xa, -(xa + xb)), cheap))
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
    let (mut lo, mut hi) = (lesser(f0, f1), greater(f0, f1));
    let mut visit = |s: f64| {
        if s > s0 && s < s1 {
            let v = f(s);
            lo = lesser(lo, v);
            hi = greater(hi, v);
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
fn march<J: Fn(f64) -> Jet2>(
    p: &[Vector2],
    jet: J,
    buffers: [&mut [Vector2]; 3],
    accept: f64,
    max_depth: usize,
    mut sink: impl FnMut(f64, Vector2),
) -> Result<usize, SubdivError> {
    let min_step = crate::optimal::min_step(max_depth);
    let stream = ModelStream::new(
        p,
        jet,
        buffers,
        (accept * MODEL_TARGET, accept * MODEL_CEILING),
        (min_step, max_depth),
    );
    let mut window = Window {
        stream,
        models: [Model {
            t0: 0.0,
            t1: 0.0,
            inverse_span: 0.0,
            p0: Vector2::zeros(),
            q: [Vector2::zeros(); 5],
            dq: [Vector2::zeros(); 5],
            end: Vector2::zeros(),
            r: 0.0,
            quartic: 0.0,
        }; WINDOW],
        front: 0,
        len: 0,
        done: false,
        start: (f64::NAN, f64::NAN, Vector2::zeros()),
    };
    window.fill_to(0.0)?;
    let (mut ta, mut pa) = (0.0_f64, p[0]);
    let mut step = first_step(window.get(0), accept);
    let mut segments = 0;
    let (mut previous, root_accept) = (0.0_f64, accept.sqrt());
    while ta < 1.0 {
        window.drop_before(ta);
        let mut best: Option<(f64, Vector2, f64)> = None;
        let mut extensions = 0;
        loop {
            let want = if ta + step >= 1.0 { 1.0 } else { ta + step };
            window.fill_to(want)?;
            let tb = lesser(want, window.reach());
            let (e, pb) = window.bound(ta, pa, tb, accept);
            let h = tb - ta;
            if e <= accept {
                best = Some((tb, pb, e));
                if e >= EXTEND_BELOW * accept || tb >= 1.0 || extensions == MAX_EXTENSIONS {
                    break;
                }
                // Well inside: try longer (the bound grows like h²).
                extensions += 1;
                let grow = if e > 0.0 {
                    lesser(0.995 * (accept / e).sqrt(), 2.0)
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
                limited(0.995 * (accept / e).sqrt(), 0.3, 0.99)
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
        // The next chord's first try: this one's length h, rescaled to fill the tolerance,
        // 0.995 √(accept / e), and by the trend T = (√e / h) / (√e₋ / h₋) of the density from
        // the chord before (within 0.8–1.25), within 0.5–2 in all. With q = h √e₋ / h₋,
        // T = √e / q, so while T is within its clamp (e between 0.64 q² and 1.5625 q²) the
        // factor is 0.995 √accept · q / e: one division and no square root between this
        // chord's bound and the next try.
        let h = tb - ta;
        let q = h * previous;
        let factor = if q > 0.0 && e >= 0.64 * q * q && e <= 1.5625 * q * q {
            0.995 * root_accept * q / e
        } else {
            let trend = if q > 0.0 && e < 0.64 * q * q {
                0.8
            } else if q > 0.0 {
                1.25
            } else {
                1.0
            };
            0.995 * root_accept / (e.sqrt() * trend)
        };
        step = if e > 0.0 {
            h * limited(factor, 0.5, 2.0)
        } else {
            2.0 * h
        };
        previous = e.sqrt() / h;
        (ta, pa) = (tb, pb);
    }
    Ok(segments)
}

/// The first chord's length from the density √(|Q′ × Q″| / |Q′|) of the first model at t = 0
/// (an arc of curvature κ and parameter length h deviates from its chord by about
/// κ |Q′|² h² / 8), the whole first model where it vanishes.
fn first_step(m: &Model, accept: f64) -> f64 {
    let w = m.t1 - m.t0;
    let (d1, d2) = (m.q[0] / w, m.q[1] * (2.0 / (w * w)));
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

    /// Where the rounding of the block splits dominates the bound on B⁽⁶⁾ (degrees 60 and 100
    /// at 1e-8 × size: that part grows like span⁻⁶, so shorter blocks do not help), the blocks
    /// are not split ever shorter: the march ends within about 1.1 N* (it ran into the depth
    /// limit from degree 60 on before).
    #[test]
    fn rounding_dominated_blocks_do_not_shrink() {
        for degree in [60_u32, 100] {
            let points: Vec<Vector2> = (0..=degree)
                .map(|i| {
                    let x = f64::from(i);
                    Vector2::new((x * 0.37).sin() + x / f64::from(degree), (x * 1.3).cos())
                })
                .collect();
            let curve = bez_core::BezierCurve::new(points.clone()).unwrap();
            let tol = 1e-8 * crate::curve_size(&curve);
            let segments = march_models(&points, tol, 40, |_| {}).unwrap();
            let n_star = crate::optimal_segment_count(&curve, tol).unwrap();
            assert!(
                f64::from(u32::try_from(segments).unwrap()) <= 1.25 * n_star,
                "{degree}: {segments} against {n_star}"
            );
        }
    }

    proptest! {
        /// `hermite_chord` against `chord_deviation` (root isolation on the arc's Bernstein
        /// form, an independent computation) for random Hermite data: where it answers, never
        /// below the exact distance, and it accepts a tolerance just above, between or just
        /// below the exact distance exactly when the distance is within it (the cheap, bump and
        /// root paths decide as the exact maximum would).
        #[test]
        fn hermite_chord_decides_as_the_exact_distance(
            b in proptest::array::uniform2(-10.0f64..10.0),
            da in proptest::array::uniform2(-10.0f64..10.0),
            db in proptest::array::uniform2(-10.0f64..10.0),
            h in 0.01f64..1.0,
            ratio in prop::sample::select(vec![0.5, 0.9, 0.999, 0.999_999, 1.000_001, 1.001, 1.1, 2.0]),
        ) {
            let (pa, pb) = (Vector2::zeros(), Vector2::new(b[0], b[1]));
            let (da, db) = (Vector2::new(da[0], da[1]), Vector2::new(db[0], db[1]));
            let d = pb - pa;
            let len2 = d.dot(&d);
            prop_assume!(len2 > 1e-6);
            let curve = bez_core::BezierCurve::new(vec![
                pa,
                pa + da * (h / 3.0),
                pb - db * (h / 3.0),
                pb,
            ])
            .unwrap();
            let exact = crate::chord_deviation(&curve, 0.0, 1.0).unwrap();
            let scale = 1e-9 * (1.0 + exact);
            if let Some(e) = hermite_chord(d, len2, len2.sqrt(), da, db, h, exact * ratio) {
                prop_assert!(e >= exact - scale, "{} < {}", e, exact);
                if (ratio - 1.0).abs() > 1e-4 {
                    prop_assert_eq!(e <= exact * ratio, exact <= exact * ratio, "{} {}", e, exact);
                }
            }
        }
    }

    /// `hermite_chord` answers on monotone arcs (a gentle S-curve and a bump) and refuses an arc
    /// whose projection turns back (a derivative against the chord).
    #[test]
    fn hermite_chord_refuses_arcs_that_turn_back() {
        let v = Vector2::new;
        let d = v(1.0, 0.0);
        for (da, db) in [(v(1.0, 0.3), v(1.0, -0.2)), (v(1.0, 1.0), v(1.0, -1.0))] {
            let e = hermite_chord(d, 1.0, 1.0, da, db, 1.0, 1e-3).unwrap();
            let curve =
                bez_core::BezierCurve::new(vec![v(0.0, 0.0), da / 3.0, d - db / 3.0, d]).unwrap();
            let exact = crate::chord_deviation(&curve, 0.0, 1.0).unwrap();
            assert!(e >= exact && e <= exact * 1.5, "{e} {exact}");
        }
        assert!(hermite_chord(d, 1.0, 1.0, v(-1.0, 0.5), v(1.0, 0.0), 1.0, 1e-3).is_none());
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
