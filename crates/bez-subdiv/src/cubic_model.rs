//! Beyond the paper: a curve of degree n ≥ 4 as a chain of cubic models, each within a
//! rigorous distance r of the curve on its parameter range, made piece by piece from the left
//! (for [`Method::Optimal`](crate::Method::Optimal) above degree 3).

use bez_core::{Vector2, de_casteljau_split};

use crate::error::SubdivError;

/// The cubic C(σ) = p0 + σ (a + σ (b + σ c)), σ = (t − t0) / (t1 − t0), with
/// |B(t) − C(σ)| ≤ `r` for t in [t0, t1]; C(1) is `end` (the piece's last control point).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Model {
    pub(crate) t0: f64,
    pub(crate) t1: f64,
    /// 1 / (t1 − t0).
    pub(crate) inverse_span: f64,
    pub(crate) p0: Vector2,
    pub(crate) a: Vector2,
    pub(crate) b: Vector2,
    pub(crate) c: Vector2,
    pub(crate) end: Vector2,
    pub(crate) r: f64,
}

impl Model {
    /// σ of the curve parameter t.
    #[inline]
    pub(crate) fn sigma(&self, t: f64) -> f64 {
        ((t - self.t0) * self.inverse_span).clamp(0.0, 1.0)
    }

    /// C at the curve parameter t (exactly `p0` and `end` at the piece's ends).
    #[inline]
    pub(crate) fn point(&self, t: f64) -> Vector2 {
        if t >= self.t1 {
            return self.end;
        }
        let s = self.sigma(t);
        self.p0 + (self.a + (self.b + self.c * s) * s) * s
    }
}

/// The cubic Hermite model on [t0, t1] (w = t1 − t0) through the points `p0`, `p1` with the
/// derivatives `d0`, `d1` (in t): C(σ) = p0 + σ w d0 + σ² (3Δ − 2w d0 − w d1)
/// + σ³ (w d0 + w d1 − 2Δ), Δ = p1 − p0, so C(1) = p1 and C′(1) = w d1. Its remainder is `r`.
fn hermite(
    t0: f64,
    t1: f64,
    (p0, d0): (Vector2, Vector2),
    (p1, d1): (Vector2, Vector2),
    r: f64,
) -> Model {
    let w = t1 - t0;
    let (e0, e1, delta) = (d0 * w, d1 * w, p1 - p0);
    Model {
        t0,
        t1,
        inverse_span: 1.0 / w,
        p0,
        a: e0,
        b: delta * 3.0 - e0 * 2.0 - e1,
        c: e0 + e1 - delta * 2.0,
        end: p1,
        r,
    }
}

/// Bounds on |Bₓ⁗| and |B_y⁗| over the range of the piece `q` (degree n, `span` long in t):
/// B⁗ has the Bernstein coefficients n(n − 1)(n − 2)(n − 3) Δ⁴qᵢ / span⁴, and a Bernstein
/// polynomial lies within its coefficients. 0 below degree 4.
fn fourth_derivative_bound(q: &[Vector2], span: f64) -> (f64, f64) {
    let n = q.len().saturating_sub(1) as f64;
    let (mut x, mut y) = (0.0_f64, 0.0_f64);
    for w in q.windows(5) {
        let d = w[0] - w[1] * 4.0 + w[2] * 6.0 - w[3] * 4.0 + w[4];
        x = x.max(d.x().abs());
        y = y.max(d.y().abs());
    }
    let scale = n * (n - 1.0) * (n - 2.0) * (n - 3.0) / (span * span * span * span);
    (x * scale, y * scale)
}

/// The models of a curve of degree n ≥ 4 from t = 0 to 1, one at a time, each a cubic Hermite
/// interpolant of B at its ends (B and B′ by Horner's rule, O(n)).
///
/// Remainder: per coordinate, the Hermite interpolant errs by at most
/// max |B⁗| w⁴ / 384 on a range of length w ((t − t0)²(t − t1)² / 24 ≤ w⁴ / 384), so
/// |B(t) − C(σ)| ≤ hypot(Mₓ, M_y) w⁴ / 384 with Mₓ, M_y bounds on |Bₓ⁗|, |B_y⁗|. These come
/// from blocks: the curve left to model is kept as its own control polygon on [s0, 1]
/// (`rest`), and a block is split off its left end by de Casteljau's algorithm (O(n²)); its
/// fourth differences bound B⁗ on the block ([`fourth_derivative_bound`]). The block is then cut
/// into equal models of the longest length with remainder ≤ `target`, about
/// [`MODELS_PER_BLOCK`] of them (the next block's span is set from this one's model length).
///
/// Rounding: B and B′ by Horner's rule (in one pass, `StackHorner::jet`, or on the curve and its
/// hodograph) are within 2n and 8n² ulps of the largest coordinate,
/// every split of `rest` moves its control points by at most 8n ulps (`split_rounding`), whose
/// fourth differences then move by 16 times that; all of it is added to the bounds.
pub(crate) struct ModelStream<'a, J> {
    curve: &'a [Vector2],
    /// B and B′ at t.
    jet: J,
    rest: &'a mut [Vector2],
    left: &'a mut [Vector2],
    right: &'a mut [Vector2],
    /// Start of `rest` and end of the current block.
    block_start: f64,
    block_end: f64,
    block_span: f64,
    /// hypot(Mₓ, M_y) on the current block.
    fourth: f64,
    /// The current model start with B and B′ there.
    t0: f64,
    at_t0: (Vector2, Vector2),
    target: f64,
    /// The most a model's remainder may be when rounding alone exceeds half of `target`.
    ceiling: f64,
    size: f64,
    split_rounding: f64,
    drift: f64,
    min_span: f64,
    max_depth: usize,
}

/// Models per block aimed at: one O(n²) split serves about this many O(n) models.
const MODELS_PER_BLOCK: f64 = 16.0;

impl<'a, J: Fn(f64) -> (Vector2, Vector2)> ModelStream<'a, J> {
    /// A stream over `curve` (at least 5 points) with `jet` = (B, B′), using
    /// three buffers of the curve's length; models within `target` (plus rounding) and at
    /// least 2^−`max_depth` long.
    pub(crate) fn new(
        curve: &'a [Vector2],
        jet: J,
        buffers: [&'a mut [Vector2]; 3],
        (target, ceiling): (f64, f64),
        max_depth: usize,
    ) -> Self {
        let [rest, left, right] = buffers;
        rest.copy_from_slice(curve);
        let n = (curve.len() - 1) as f64;
        let size = curve.iter().map(Vector2::amax).fold(0.0, f64::max);
        let at_t0 = (curve[0], jet(0.0).1);
        Self {
            curve,
            jet,
            rest,
            left,
            right,
            block_start: 0.0,
            block_end: 0.0,
            block_span: 1.0,
            fourth: 0.0,
            t0: 0.0,
            at_t0,
            target,
            ceiling,
            size,
            split_rounding: 8.0 * n * f64::EPSILON * size,
            drift: 0.0,
            min_span: 0.5_f64.powi(i32::try_from(max_depth).unwrap_or(i32::MAX)),
            max_depth,
        }
    }

    /// Splits the next block off `rest` and sets the next block's span from its models'
    /// length.
    fn next_block(&mut self) -> Result<(), SubdivError> {
        if self.drift > 1e3 * self.split_rounding {
            // `rest` afresh: the curve split at the block's start.
            de_casteljau_split(self.curve, self.block_start, self.left, self.rest)?;
            self.drift = 0.0;
        }
        let n = (self.curve.len() - 1) as f64;
        let remaining = 1.0 - self.block_start;
        let (mut span, mut longest);
        let last = loop {
            let last = self.block_span >= remaining;
            span = if last { remaining } else { self.block_span };
            let piece: &[Vector2] = if last {
                self.rest
            } else {
                de_casteljau_split(self.rest, span / remaining, self.left, self.right)?;
                self.left
            };
            let (x, y) = fourth_derivative_bound(piece, span);
            // The rounding of the block's control points, through the fourth differences.
            let span2 = span * span;
            let moved =
                16.0 * (self.drift + self.split_rounding) * n * (n - 1.0) * (n - 2.0) * (n - 3.0)
                    / (span2 * span2);
            self.fourth = ((x + moved) * (x + moved) + (y + moved) * (y + moved)).sqrt();
            longest = (384.0 * self.target / self.fourth).sqrt().sqrt();
            // A block that would hold far more models than aimed at is split again shorter
            // (its bound on B⁗ covers more of the curve than its models need).
            let aimed = MODELS_PER_BLOCK * longest;
            if !(span > 2.0 * aimed && aimed >= self.min_span) {
                break last;
            }
            self.block_span = aimed;
        };
        if !last {
            core::mem::swap(&mut self.rest, &mut self.right);
            self.drift += self.split_rounding;
        }
        self.block_start += span;
        self.block_end = if last { 1.0 } else { self.block_start };
        self.block_span = if longest.is_finite() {
            (longest * MODELS_PER_BLOCK).clamp(0.25 * span, 4.0 * span)
        } else {
            4.0 * span
        };
        Ok(())
    }

    /// The next model, `None` once t = 1 is reached.
    ///
    /// # Errors
    /// [`SubdivError::DepthLimit`] when a model would have to be shorter than 2^−`max_depth`.
    pub(crate) fn next_model(&mut self) -> Result<Option<Model>, SubdivError> {
        if self.t0 >= 1.0 {
            return Ok(None);
        }
        if self.t0 >= self.block_end {
            self.next_block()?;
        }
        let n = (self.curve.len() - 1) as f64;
        let eps = f64::EPSILON * self.size;
        // B and B′ by Horner: within 2n and 8n² ulps; the model moves by at most the point's
        // error plus w times the derivative's.
        let (point_rounding, tangent_rounding) = (4.0 * n * eps, 16.0 * n * n * eps);
        let left = self.block_end - self.t0;
        let fixed = point_rounding + left * tangent_rounding;
        // Near the rounding floor the target gives way to the ceiling.
        let budget = if fixed < 0.5 * self.target {
            self.target - fixed
        } else {
            self.ceiling - fixed
        };
        // The longest w with fourth · w⁴ / 384 ≤ budget, then the block's rest in equal parts.
        let longest = (384.0 * budget / self.fourth).sqrt().sqrt();
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
            (c[c.len() - 1], (c[c.len() - 1] - c[c.len() - 2]) * n)
        } else {
            (self.jet)(t1)
        };
        let w2 = w * w;
        let r = self.fourth * w2 * w2 / 384.0 + point_rounding + w * tangent_rounding;
        let model = hermite(self.t0, t1, self.at_t0, at_t1, r);
        self.t0 = t1;
        self.at_t0 = at_t1;
        Ok(Some(model))
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
        let mut stream =
            ModelStream::new(p, |t| horner.jet(t), [a, b, d], (target, 4.0 * target), 40);
        let mut out: Vec<Model> = Vec::new();
        while let Some(m) = stream.next_model().unwrap() {
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
        /// points), and r is within the target.
        #[test]
        fn models_are_within_their_remainder(c in curve::<2>(4..=30, 10.0), rel in 1e-5f64..1e-1) {
            let size = c.points().iter().map(Vector2::amax).fold(1.0, f64::max);
            let target = rel * size;
            for m in models(&c, target) {
                prop_assert!(m.r <= target);
                for k in 0..=64 {
                    let s = f64::from(k) / 64.0;
                    let t = m.t0 + s * (m.t1 - m.t0);
                    let error = (m.point(t) - c.eval(t).unwrap()).norm();
                    prop_assert!(error <= m.r + 1e-12 * size, "{} > {}", error, m.r);
                }
            }
        }
    }

    /// A cubic elevated to degree 7 has B⁗ = 0: one model, the cubic itself.
    #[test]
    fn an_elevated_cubic_is_its_own_model() {
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 2.0),
            Vector2::new(3.0, -1.0),
            Vector2::new(4.0, 1.0),
        ])
        .unwrap();
        let e = c.elevate(4).unwrap();
        let m = models(&e, 1e-6);
        assert_eq!(m.len(), 1);
        assert!(m[0].r < 1e-11, "{}", m[0].r);
        for k in 0..=10 {
            let t = f64::from(k) / 10.0;
            assert!((m[0].point(t) - c.eval(t).unwrap()).norm() < 1e-13);
        }
    }
}
