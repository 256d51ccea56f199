//! Beyond the paper: a curve of degree n ≥ 4 as a chain of quintic models, each within a
//! rigorous distance r of the curve on its parameter range, made piece by piece from the left
//! (for [`Method::Optimal`](crate::Method::Optimal) above degree 3).

use bez_core::{Vector2, de_casteljau_split};

use crate::error::SubdivError;
use crate::order::greater;

/// B, B′ and B″ at a parameter.
pub(crate) type Jet2 = (Vector2, Vector2, Vector2);

/// The quintic Q(σ) = p0 + σ (q₁ + σ (q₂ + σ (q₃ + σ (q₄ + σ q₅)))), σ = (t − t0) / (t1 − t0),
/// with |B(t) − Q(σ)| ≤ `r` for t in [t0, t1]; Q(1) is `end` (B(t1) as evaluated).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Model {
    pub(crate) t0: f64,
    pub(crate) t1: f64,
    /// 1 / (t1 − t0).
    pub(crate) inverse_span: f64,
    pub(crate) p0: Vector2,
    pub(crate) q: [Vector2; 5],
    /// Q′ in t: (i + 1) qᵢ₊₁ / (t1 − t0), the power coefficients of the derivative.
    pub(crate) dq: [Vector2; 5],
    pub(crate) end: Vector2,
    pub(crate) r: f64,
    /// max(|q₄|, |q₄ + 5q₅|), a bound on the quotient L of [`Model::hermite_quotient`] over the
    /// whole model (its argument q₄ + q₅ (5σₐ + 2k + y) has 5σₐ + 2k + y ∈ [0, 5]).
    pub(crate) quartic: f64,
}

impl Model {
    /// Q and its derivative in t at the curve parameter t in [t0, t1] (the point exactly `p0`
    /// and `end` at the model's ends).
    #[inline(always)]
    pub(crate) fn jet(&self, t: f64) -> (Vector2, Vector2) {
        (self.point(t), self.slope(t))
    }

    /// Q at the curve parameter t in [t0, t1] (exactly `p0` and `end` at the model's ends).
    #[inline(always)]
    pub(crate) fn point(&self, t: f64) -> Vector2 {
        if t >= self.t1 {
            return self.end;
        }
        let s = (t - self.t0) * self.inverse_span;
        let [q1, q2, q3, q4, q5] = self.q;
        // Estrin's scheme: the same polynomial, half the dependent steps of Horner's.
        let s2 = s * s;
        self.p0 + ((q1 + q2 * s) + ((q3 + q4 * s) + q5 * s2) * s2) * s
    }

    /// Q − H over [a, b] ⊆ [t0, t1], H the cubic Hermite interpolant of Q at a and b (Q and Q′
    /// there), as (L(0), L(k), k⁴/16): |Q − H| ≤ k⁴/16 · |L| with L between the two (and so
    /// is each of its components along any direction).
    ///
    /// In σ, with y = σ − σₐ ∈ [0, k] (k = (b − a) / (t1 − t0)): Q − H is a quintic that
    /// vanishes with its derivative at y = 0 and y = k, so Q − H = y²(k − y)² L(y) with L linear;
    /// its y⁵ and y⁴ coefficients are Q's (H is cubic): q₅ and k₄ = q₄ + 5q₅σₐ, so
    /// L(y) = k₄ + q₅ (2k + y), and y²(k − y)² ≤ k⁴/16.
    #[inline(always)]
    pub(crate) fn hermite_quotient(&self, a: f64, b: f64) -> (Vector2, Vector2, f64) {
        let (s, k) = (
            (a - self.t0) * self.inverse_span,
            (b - a) * self.inverse_span,
        );
        let [_, _, _, q4, q5] = self.q;
        let near = q4 + q5 * (5.0 * s + 2.0 * k);
        let k2 = k * k;
        (near, near + q5 * k, k2 * k2 / 16.0)
    }

    /// A bound on |Q − H| over [a, b] ([`Model::hermite_quotient`]; |L| is convex, so largest
    /// at an end).
    #[inline(always)]
    pub(crate) fn hermite_remainder(&self, a: f64, b: f64) -> f64 {
        let (near, far, scale) = self.hermite_quotient(a, b);
        scale * greater(near.dot(&near), far.dot(&far)).sqrt()
    }

    /// Q′ in t at the curve parameter t in [t0, t1].
    #[inline(always)]
    pub(crate) fn slope(&self, t: f64) -> Vector2 {
        let s = (t - self.t0) * self.inverse_span;
        let [d0, d1, d2, d3, d4] = self.dq;
        let s2 = s * s;
        (d0 + d1 * s) + ((d2 + d3 * s) + d4 * s2) * s2
    }
}

/// Bound on the quintic Hermite basis functions of the derivatives: |G₀| + |G₁| ≤ 5/16 for the
/// first derivatives' (σ(1 − σ)³(1 + 3σ) and σ³(1 − σ)(3σ − 4), largest at σ = ½) and
/// |K₀| + |K₁| ≤ 1/32 for the second derivatives' (σ²(1 − σ)³/2 and σ³(1 − σ)²/2).
const FIRST_BASIS: f64 = 5.0 / 16.0;
const SECOND_BASIS: f64 = 1.0 / 32.0;

/// The quintic Hermite model on [t0, t1] (w = t1 − t0) through `a` = (p₀, d₀, s₀) and `b` =
/// (p₁, d₁, s₁), points, first and second derivatives in t: with e = w d, f = w² s and
/// Δ = p₁ − p₀, A = Δ − e₀ − f₀/2, B = e₁ − e₀ − f₀, C = f₁ − f₀ (the conditions Q(1) = p₁,
/// Q′(1) = e₁, Q″(1) = f₁ on q₃ + q₄ + q₅, 3q₃ + 4q₄ + 5q₅, 6q₃ + 12q₄ + 20q₅):
/// q₁ = e₀, q₂ = f₀/2, q₃ = 10A − 4B + C/2, q₄ = −15A + 7B − C, q₅ = 6A − 3B + C/2.
#[inline(always)]
fn hermite(t0: f64, t1: f64, a: Jet2, b: Jet2, r: f64) -> Model {
    let w = t1 - t0;
    let inverse_span = 1.0 / w;
    let (p0, e0, f0) = (a.0, a.1 * w, a.2 * (w * w));
    let (p1, e1, f1) = (b.0, b.1 * w, b.2 * (w * w));
    let big_a = p1 - p0 - e0 - f0 * 0.5;
    let big_b = e1 - e0 - f0;
    let big_c = f1 - f0;
    let q3 = big_a * 10.0 - big_b * 4.0 + big_c * 0.5;
    let q4 = big_a * -15.0 + big_b * 7.0 - big_c;
    let q5 = big_a * 6.0 - big_b * 3.0 + big_c * 0.5;
    Model {
        t0,
        t1,
        inverse_span,
        p0,
        q: [e0, f0 * 0.5, q3, q4, q5],
        dq: [
            a.1,
            f0 * inverse_span,
            q3 * (3.0 * inverse_span),
            q4 * (4.0 * inverse_span),
            q5 * (5.0 * inverse_span),
        ],
        end: p1,
        r,
        quartic: greater(q4.norm(), (q4 + q5 * 5.0).norm()),
    }
}

/// Bounds on |Bₓ⁽⁶⁾| and |B_y⁽⁶⁾| over the range of the piece `q` (degree n, `span` long in t):
/// B⁽⁶⁾ has the Bernstein coefficients n(n − 1)⋯(n − 5) Δ⁶qᵢ / span⁶, and a Bernstein
/// polynomial lies within its coefficients. 0 below degree 6.
fn sixth_derivative_bound(q: &[Vector2], span: f64) -> (f64, f64) {
    let n = q.len().saturating_sub(1) as f64;
    let (mut x, mut y) = (0.0_f64, 0.0_f64);
    for w in q.windows(7) {
        let d = (w[0] + w[6]) - (w[1] + w[5]) * 6.0 + (w[2] + w[4]) * 15.0 - w[3] * 20.0;
        x = greater(x, d.x().abs());
        y = greater(y, d.y().abs());
    }
    let span3 = span * span * span;
    let scale = falling6(n) / (span3 * span3);
    (x * scale, y * scale)
}

/// n(n − 1)(n − 2)(n − 3)(n − 4)(n − 5), 0 below degree 6.
fn falling6(n: f64) -> f64 {
    if n < 6.0 {
        0.0
    } else {
        n * (n - 1.0) * (n - 2.0) * (n - 3.0) * (n - 4.0) * (n - 5.0)
    }
}

/// The models of a curve of degree n ≥ 4 from t = 0 to 1, one at a time, each the quintic
/// Hermite interpolant of B at its ends (B, B′ and B″ by Horner's rule, O(n)).
///
/// Remainder: per coordinate, the quintic Hermite interpolant errs by
/// B⁽⁶⁾(ξ) (t − t0)³(t − t1)³ / 720, at most max |B⁽⁶⁾| w⁶ / 46080 on a range of length w
/// ((t − t0)³(t − t1)³ ≤ (w/2)⁶), so |B(t) − Q(σ)| ≤ hypot(Mₓ, M_y) w⁶ / 46080 with Mₓ, M_y
/// bounds on |Bₓ⁽⁶⁾|, |B_y⁽⁶⁾|. These come from blocks: the curve left to model is kept as its
/// own control polygon on [s0, 1] (`rest`), and a block is split off its left end by de
/// Casteljau's algorithm (O(n²)); its sixth differences bound B⁽⁶⁾ on the block
/// ([`sixth_derivative_bound`]). The block is then cut into equal models of the longest length
/// with remainder ≤ `target`, about [`MODELS_PER_BLOCK`] of them (the next block's span is set
/// from this one's model length).
///
/// Rounding: B, B′ and B″ by Horner's rule (in one pass, `StackHorner::jet2`, or on the curve
/// and its hodographs) are within 2n, 8n² and 32n³ ulps of the largest coordinate; through the
/// Hermite basis (the points' weights sum to 1, the derivatives' are within
/// [`FIRST_BASIS`] and [`SECOND_BASIS`]) the model moves by at most the point's error plus
/// 5/16 w and 1/32 w² times the derivatives'. Every split of `rest` moves its control points
/// by at most 8n ulps (`split_rounding`), whose sixth differences then move by 64 times that;
/// all of it is added to the bounds.
pub(crate) struct ModelStream<'a, J> {
    curve: &'a [Vector2],
    /// B, B′ and B″ at t.
    jet: J,
    rest: &'a mut [Vector2],
    left: &'a mut [Vector2],
    right: &'a mut [Vector2],
    /// Start of `rest` and end of the current block.
    block_start: f64,
    block_end: f64,
    block_span: f64,
    /// hypot(Mₓ, M_y) on the current block.
    sixth: f64,
    /// The current model start with B, B′ and B″ there.
    t0: f64,
    at_t0: Jet2,
    target: f64,
    /// The most a model's remainder may be when rounding alone exceeds half of `target`.
    ceiling: f64,
    split_rounding: f64,
    drift: f64,
    min_span: f64,
    max_depth: usize,
    /// How far B, B′ and B″ by Horner's rule move a model: its point's error, and 5/16 w and
    /// 1/32 w² times twice the derivatives' (2n, 8n² and 32n³ ulps of the largest coordinate).
    rounding: (f64, f64, f64),
    /// The longest model in the current block.
    model_span: f64,
}

/// Models per block aimed at: one O(n²) split serves about this many O(n) models.
const MODELS_PER_BLOCK: f64 = 8.0;

impl<'a, J: Fn(f64) -> Jet2> ModelStream<'a, J> {
    /// A stream over `curve` (at least 5 points) with `jet` = (B, B′, B″), using three buffers
    /// of the curve's length; models within `target` (plus rounding) and at least 2^−`min_span`
    /// long (`min_span` = 2^−`max_depth`).
    pub(crate) fn new(
        curve: &'a [Vector2],
        jet: J,
        buffers: [&'a mut [Vector2]; 3],
        (target, ceiling): (f64, f64),
        (min_span, max_depth): (f64, usize),
    ) -> Self {
        let [rest, left, right] = buffers;
        rest.copy_from_slice(curve);
        let n = (curve.len() - 1) as f64;
        let size = curve.iter().map(Vector2::amax).fold(0.0, f64::max);
        let (_, d1, d2) = jet(0.0);
        let at_t0 = (curve[0], d1, d2);
        let eps = f64::EPSILON * size;
        let rounding = (
            4.0 * n * eps,
            2.0 * FIRST_BASIS * 16.0 * n * n * eps,
            2.0 * SECOND_BASIS * 64.0 * n * n * n * eps,
        );
        Self {
            curve,
            jet,
            rest,
            left,
            right,
            block_start: 0.0,
            block_end: 0.0,
            block_span: 1.0,
            sixth: 0.0,
            t0: 0.0,
            at_t0,
            target,
            ceiling,
            split_rounding: 8.0 * n * f64::EPSILON * size,
            drift: 0.0,
            min_span,
            max_depth,
            rounding,
            model_span: 0.0,
        }
    }

    /// Splits the next block off `rest` and sets the next block's span from its models'
    /// length.
    fn next_block(&mut self) -> Result<(), SubdivError> {
        if self.drift > 32.0 * self.split_rounding {
            // `rest` afresh: the curve split at the block's start.
            de_casteljau_split(self.curve, self.block_start, self.left, self.rest)?;
            self.drift = 0.0;
        }
        let n = (self.curve.len() - 1) as f64;
        let remaining = 1.0 - self.block_start;
        let (mut span, mut longest, mut rounding_dominates);
        let last = loop {
            let last = self.block_span >= remaining;
            span = if last { remaining } else { self.block_span };
            let piece: &[Vector2] = if last {
                self.rest
            } else {
                de_casteljau_split(self.rest, span / remaining, self.left, self.right)?;
                self.left
            };
            let (x, y) = sixth_derivative_bound(piece, span);
            // The rounding of the block's control points, through the sixth differences.
            let span3 = span * span * span;
            let moved = 64.0 * (self.drift + self.split_rounding) * falling6(n) / (span3 * span3);
            self.sixth = ((x + moved) * (x + moved) + (y + moved) * (y + moved)).sqrt();
            longest = (46080.0 * self.target / self.sixth).powf(1.0 / 6.0);
            // A block that would hold far more models than aimed at is split again shorter
            // (its bound on B⁽⁶⁾ covers more of the curve than its models need), unless the
            // rounding dominates the bound: that part grows like span⁻⁶, so that the models'
            // length it allows is a fixed fraction of the block's, however short the block.
            let aimed = MODELS_PER_BLOCK * longest;
            rounding_dominates = moved >= x.max(y);
            if rounding_dominates || !(span > 2.0 * aimed && aimed >= self.min_span) {
                break last;
            }
            self.block_span = aimed;
        };
        // The longest model w with sixth · w⁶ / 46080 ≤ budget (the target less the rounding
        // of a model as long as the whole block, so within the target for every shorter one).
        let (point_rounding, tangent_rounding, curl_rounding) = self.rounding;
        let fixed = point_rounding + span * (tangent_rounding + span * curl_rounding);
        // Near the rounding floor the target gives way to the ceiling.
        let budget = if fixed < 0.5 * self.target {
            self.target - fixed
        } else {
            self.ceiling - fixed
        };
        self.model_span = (46080.0 * budget / self.sixth).powf(1.0 / 6.0);
        if !last {
            core::mem::swap(&mut self.rest, &mut self.right);
            self.drift += self.split_rounding;
        }
        self.block_start += span;
        self.block_end = if last { 1.0 } else { self.block_start };
        self.block_span = if rounding_dominates {
            2.0 * span
        } else if longest.is_finite() {
            (longest * MODELS_PER_BLOCK).clamp(0.25 * span, 4.0 * span)
        } else {
            4.0 * span
        };
        Ok(())
    }

    /// Writes the next model into `slot` (in place: a model is 29 numbers), `false` once t = 1
    /// is reached.
    ///
    /// # Errors
    /// [`SubdivError::DepthLimit`] when a model would have to be shorter than 2^−`max_depth`.
    pub(crate) fn next_model(&mut self, slot: &mut Model) -> Result<bool, SubdivError> {
        if self.t0 >= 1.0 {
            return Ok(false);
        }
        if self.t0 >= self.block_end {
            self.next_block()?;
        }
        let n = (self.curve.len() - 1) as f64;
        let (point_rounding, tangent_rounding, curl_rounding) = self.rounding;
        let left = self.block_end - self.t0;
        let longest = self.model_span;
        let parts = if longest > 0.0 && longest.is_finite() {
            (left / longest).ceil().max(1.0)
        } else if longest.is_nan() || longest <= 0.0 {
            f64::INFINITY
        } else {
            1.0
        };
        let w = left / parts;
        if w.is_nan() || w < self.min_span {
            return Err(SubdivError::DepthLimit {
                limit: self.max_depth,
            });
        }
        let t1 = if parts <= 1.0 {
            self.block_end
        } else {
            self.t0 + w
        };
        let at_t1 = if t1 >= 1.0 {
            let c = self.curve;
            let k = c.len() - 1;
            (
                c[k],
                (c[k] - c[k - 1]) * n,
                (c[k] - c[k - 1] * 2.0 + c[k - 2]) * (n * (n - 1.0)),
            )
        } else {
            (self.jet)(t1)
        };
        let w2 = w * w;
        let w3 = w2 * w;
        let r = self.sixth * w3 * w3 / 46080.0
            + point_rounding
            + w * (tangent_rounding + w * curl_rounding);
        *slot = hermite(self.t0, t1, self.at_t0, at_t1, r);
        self.t0 = t1;
        self.at_t0 = at_t1;
        Ok(true)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]

    use bez_core::BezierCurve;
    use bez_core::proptest_support::curve;
    use proptest::prelude::*;

    use super::*;
    use crate::stack_horner::StackHorner;

    /// Every model of `c` with its `target`, after checking that the models tile [0, 1] and
    /// join exactly.
    fn models(c: &BezierCurve<2>, target: f64) -> Vec<Model> {
        let p = c.points();
        let mut scaled = [Vector2::zeros(); crate::stack_horner::STACK_POINTS];
        let horner = StackHorner::new(p, &mut scaled).unwrap();
        let mut buffers = vec![vec![Vector2::zeros(); p.len()]; 3];
        let [a, b, d] = &mut buffers[..] else {
            unreachable!()
        };
        let mut stream = ModelStream::new(
            p,
            |t| horner.jet2(t),
            [a, b, d],
            (target, 4.0 * target),
            (0.5_f64.powi(40), 40),
        );
        let mut out: Vec<Model> = Vec::new();
        let mut m = hermite(
            0.0,
            1.0,
            (Vector2::zeros(), Vector2::zeros(), Vector2::zeros()),
            (Vector2::zeros(), Vector2::zeros(), Vector2::zeros()),
            0.0,
        );
        while stream.next_model(&mut m).unwrap() {
            let (t0, p0) = out.last().map_or((0.0, c.start()), |l| (l.t1, l.end));
            assert_eq!((m.t0, m.p0), (t0, p0));
            assert!(m.t1 > m.t0);
            out.push(m);
        }
        let last = out.last().unwrap();
        assert_eq!((last.t1, last.end), (1.0, c.end()));
        out
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Every model is within its r of the curve (dense samples against de Casteljau's
        /// points), r is within the target, Q′ is the derivative of Q (a central difference)
        /// and `hermite_remainder` bounds the cubic Hermite interpolant's distance (sampled).
        #[test]
        fn models_are_within_their_remainder(c in curve::<2>(4..=30, 10.0), rel in 1e-5f64..1e-1) {
            let size = c.points().iter().map(Vector2::amax).fold(1.0, f64::max);
            let target = rel * size;
            for m in models(&c, target) {
                prop_assert!(m.r <= target);
                let w = m.t1 - m.t0;
                for k in 0..=64 {
                    let s = f64::from(k) / 64.0;
                    let t = m.t0 + s * w;
                    let error = (m.point(t) - c.eval(t).unwrap()).norm();
                    prop_assert!(error <= m.r + 1e-12 * size, "{} > {}", error, m.r);
                }
                let (t, e) = (m.t0 + 0.4 * w, 1e-4 * w);
                let central = (m.point(t + e) - m.point(t - e)) / (2.0 * e);
                let slope = m.slope(t);
                prop_assert!((central - slope).norm() <= 1e-5 * (1.0 + slope.norm()));
                // The Hermite remainder against the sampled |Q − H| on a sub-range.
                let (a, b) = (m.t0 + 0.2 * w, m.t0 + 0.7 * w);
                let (pa, pb, da, db) = (m.point(a), m.point(b), m.slope(a), m.slope(b));
                let h = b - a;
                let bound = m.hermite_remainder(a, b);
                let mut largest = 0.0_f64;
                for k in 0..=200 {
                    let x = f64::from(k) / 200.0;
                    let (h00, h10) = ((1.0 + 2.0 * x) * (1.0 - x) * (1.0 - x), x * (1.0 - x) * (1.0 - x));
                    let (h01, h11) = (x * x * (3.0 - 2.0 * x), x * x * (x - 1.0));
                    let hermite = pa * h00 + da * (h * h10) + pb * h01 + db * (h * h11);
                    largest = largest.max((m.point(a + x * h) - hermite).norm());
                }
                prop_assert!(largest <= bound * (1.0 + 1e-9) + 1e-12 * size, "{} > {}", largest, bound);
                // y²(k − y)² |L| reaches a quarter of the bound or more (L changing sign: 4.07).
                prop_assert!(bound <= 4.2 * largest + 1e-12 * size, "{} vs {}", bound, largest);
            }
        }
    }

    /// A quintic elevated to degree 9 has B⁽⁶⁾ = 0: one model, the quintic itself.
    #[test]
    fn an_elevated_quintic_is_its_own_model() {
        let v = Vector2::new;
        let c = BezierCurve::new(vec![
            v(0.0, 0.0),
            v(1.0, 2.0),
            v(3.0, -1.0),
            v(4.0, 1.0),
            v(5.0, 3.0),
            v(7.0, 0.0),
        ])
        .unwrap();
        let e = c.elevate(4).unwrap();
        let m = models(&e, 1e-6);
        assert_eq!(m.len(), 1);
        assert!(m[0].r < 1e-10, "{}", m[0].r);
        for k in 0..=10 {
            let t = f64::from(k) / 10.0;
            assert!((m[0].point(t) - c.eval(t).unwrap()).norm() < 1e-12);
        }
    }

    /// The quintic Hermite basis bounds: |G₀| + |G₁| ≤ 5/16 and |K₀| + |K₁| ≤ 1/32 on [0, 1]
    /// (dense sampling), both reached at σ = ½.
    #[test]
    fn hermite_basis_bounds() {
        let (mut first, mut second) = (0.0_f64, 0.0_f64);
        for k in 0..=10_000 {
            let s = f64::from(k) / 10_000.0;
            let u = 1.0 - s;
            first = first.max(
                (s * u * u * u * (1.0 + 3.0 * s)).abs() + (s * s * s * u * (3.0 * s - 4.0)).abs(),
            );
            second = second.max(s * s * u * u * u / 2.0 + s * s * s * u * u / 2.0);
        }
        assert!(
            (FIRST_BASIS * (1.0 - 1e-9)..=FIRST_BASIS).contains(&first),
            "{first}"
        );
        assert!(
            (SECOND_BASIS * (1.0 - 1e-9)..=SECOND_BASIS).contains(&second),
            "{second}"
        );
    }
}
