//! Beyond the paper: the uniform points of `Method::Fast` on quadratics and cubics by forward
//! differences, with a bound on their rounding error.
//!
//! For a polynomial of degree n and a parameter step h, the k-th forward differences of its
//! values at 0, h, 2h, … are polynomials of degree n − k, and the n-th is constant: starting
//! from the differences at 0, each next value costs n additions (p += Δ₁; Δ₁ += Δ₂; …) instead
//! of an evaluation. In floating point the additions round, and the rounding errors of the
//! differences accumulate into the points. [`rounding_allowance`] bounds that error; the
//! caller takes this path only where the bound fits in the tolerance beside the chord error,
//! and otherwise evaluates every point.
//!
//! # The bound
//!
//! Notation: u = 2⁻⁵³ (the unit roundoff of f64, round to nearest), s the sum of the absolute
//! coordinates of the control points (so Σᵢ |vᵢ| ≤ s for each coordinate v of the control
//! points Pᵢ), N ≥ 1 the number of segments and h = fl(1/N) the step (so h ≤ (1 + u)/N and
//! (N − 1) h < 1). The points sent are P₀, the points p₁, …, p_{N−1} of the recurrence, and Pₙ;
//! the exact values they approximate are B(k h) of the curve B with the given (exact) f64
//! control points. Per coordinate, to first order in u (the second-order terms are covered by
//! the rounding up of the constants at the end):
//!
//! *Cubic*, B(t) = v₀ + a t + b t² + c t³ with a = 3(v₁ − v₀), b = 3 d₀, c = d₁ − d₀,
//! dᵢ = vᵢ − 2vᵢ₊₁ + vᵢ₊₂. Magnitudes: |a| ≤ 3s, |b| ≤ 6s, |c| ≤ 3s, |dᵢ| ≤ 2s; on [0, 1],
//! |B| ≤ s, |B′| ≤ 3s, |B″| ≤ 12s (convex combinations of the control values and of their
//! differences). The computed coefficients (two roundings for each dᵢ, one more for a, b and
//! c) are within 6us, 18us and 12us of a, b and c. The initial differences
//! Δ₃ = 6c h³, Δ₂ = 2b h² + Δ₃, Δ₁ = a h + b h² + c h³ are computed with h², h³ (two
//! roundings) and seven more operations, within e₃ = 144 us h³, e₂ = 234 us h² and
//! e₁ = 81 us h of their exact values at the computed h. Step k of the recurrence rounds
//! each of the three sums once, by at most u times |Δ₂| ≤ 12 s h², |Δ₁| ≤ 3 s h and |B| ≤ s
//! (the exact differences at kh, which stay in [0, 1]). An error in Δ₂ reaches the points
//! after summing twice, one in Δ₃ after summing three times, so after k ≤ N − 1 steps the
//! point is off by at most
//!
//! k e₁ + k²/2 e₂ + k³/6 e₃ + (k³/6 · 12 s h² + k²/2 · 3 s h + k s) u
//! ≤ us (81 + 117 + 24 + 4.5 N)   (k h ≤ 1).
//!
//! *Quadratic*, B(t) = v₀ + a t + d t², a = 2(v₁ − v₀), |a| ≤ 2s, |d| ≤ 2s, |B′| ≤ 2s:
//! Δ₂ = 2d h² within 16 us h², Δ₁ = a h + d h² within 16 us h, and after k steps the point is
//! off by at most us (16 + 8 + 2N).
//!
//! Both coordinates together (each bounded with the same s): at most √2 times that, below
//! us (7N + 320). The chord bound that the caller compares with the tolerance uses the
//! computed second differences, within 6us of the exact ones in norm, which can raise the
//! true chord error by at most (3/4) · 6 us / N² ≤ 4.5 us; and the last segment, from
//! (N − 1)h to 1, is longer than 1/N by at most a relative N u, which is in the caller's
//! test. Rounded up: every point is within
//!
//! **E = 2⁻⁵⁰ s (N + 64) = us (8N + 512)**
//!
//! of B(k h), with the chord bound's rounding included: [`rounding_allowance`]. So the
//! polyline through the points is within chord + E of the curve in Hausdorff distance (moving
//! each vertex by at most E moves every point of the polyline by at most E). Underflow adds at
//! most 2⁻¹⁰⁷⁴ per operation, far below u s when s ≥ 2⁻¹²⁷ (the caller's unit-size check).
//! The test `points_are_within_the_rounding_allowance` checks E against exact rational
//! arithmetic.
//!
//! Per point: 2 vector additions for a quadratic, 3 for a cubic (4 and 6 flops), against 4 and
//! 7–8 flops (and the parameter) for an evaluation by Horner's rule.

use bez_core::Vector2;

use crate::guaranteed::FlatPoint;

/// 2⁻⁵⁰: E = [`ROUNDING_UNIT`] · s · (N + [`ROUNDING_OFFSET`]), see the module docs.
const ROUNDING_UNIT: f64 = 1.0 / (1_u64 << 50) as f64;
/// The constant term of the bound in units of 2⁻⁵⁰ s.
const ROUNDING_OFFSET: f64 = 64.0;

/// E = 2⁻⁵⁰ s (N + 64): the largest distance of a forward-differenced point of a quadratic or
/// a cubic from the curve point at its parameter, with `size` = s the sum of the absolute
/// coordinates of the control points and `segments` = N (module docs).
#[inline(always)]
pub(crate) fn rounding_allowance(size: f64, segments: f64) -> f64 {
    ROUNDING_UNIT * size * (segments + ROUNDING_OFFSET)
}

/// The step h = fl(1/N) of the forward differences with its powers as the initial differences
/// use them, fl(h²) and fl(fl(h²) h) (module docs): computed by [`Step::new`] at run time or,
/// the same values, read from a table built with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Step {
    /// h.
    pub(crate) h: f64,
    /// fl(h²).
    pub(crate) h2: f64,
    /// fl(fl(h²) h).
    pub(crate) h3: f64,
}

impl Step {
    /// The powers of `h`, rounded as in the module docs (also at compile time: the same
    /// correctly rounded products).
    #[inline(always)]
    pub(crate) const fn new(h: f64) -> Self {
        let h2 = h * h;
        Self { h, h2, h3: h2 * h }
    }
}

/// Sends P₀ = `p0`, the points B(k h), k = 1..n, of B(t) = P₀ + a t + d t² by forward
/// differences (two vector additions per point), and `last` = P₂ to `sink`; returns n. The
/// points are within [`rounding_allowance`] of the curve; the parameters sent are fl(k h), as
/// on the evaluating path.
#[inline(always)]
pub(crate) fn quadratic(
    [p0, a, d]: [Vector2; 3],
    last: Vector2,
    n: usize,
    Step { h, h2, .. }: Step,
    mut sink: impl FnMut(FlatPoint),
) -> usize {
    // Δ₁ = B(h) − B(0) = a h + d h², Δ₂ = 2 d h².
    let dh = d * h2;
    let mut d1 = a * h + dh;
    let d2 = dh * 2.0;
    let mut p = p0;
    sink(FlatPoint { t: 0.0, point: p0 });
    // k counted in f64 (exact below 2⁵³), as on the evaluating path.
    let mut k = 0.0;
    for _ in 1..n {
        k += 1.0;
        p += d1;
        d1 += d2;
        sink(FlatPoint { t: k * h, point: p });
    }
    sink(FlatPoint {
        t: 1.0,
        point: last,
    });
    n
}

/// [`quadratic`] for B(t) = P₀ + a t + b t² + c t³ (three vector additions per point).
#[inline(always)]
pub(crate) fn cubic(
    [p0, a, b, c]: [Vector2; 4],
    last: Vector2,
    n: usize,
    Step { h, h2, h3 }: Step,
    mut sink: impl FnMut(FlatPoint),
) -> usize {
    // Δ₃ = 6 c h³, Δ₂ = 2 b h² + 6 c h³, Δ₁ = a h + b h² + c h³.
    let (bh2, ch3) = (b * h2, c * h3);
    let d3 = ch3 * 6.0;
    let mut d2 = bh2 * 2.0 + d3;
    let mut d1 = a * h + bh2 + ch3;
    let mut p = p0;
    sink(FlatPoint { t: 0.0, point: p0 });
    let mut k = 0.0;
    for _ in 1..n {
        k += 1.0;
        p += d1;
        d1 += d2;
        d2 += d3;
        sink(FlatPoint { t: k * h, point: p });
    }
    sink(FlatPoint {
        t: 1.0,
        point: last,
    });
    n
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use num_traits::ToPrimitive;

    fn exact(v: f64) -> BigRational {
        BigRational::from_float(v).unwrap()
    }

    /// B(t) of the control values `v` (one coordinate) at the exact parameter `t`, in exact
    /// rational arithmetic (Bernstein form, no rounding).
    fn exact_value(v: &[f64], t: &BigRational) -> BigRational {
        let n = v.len() - 1;
        let one = BigRational::from_integer(BigInt::from(1));
        let s = &one - t;
        let mut binomial = BigInt::from(1);
        let mut sum = BigRational::from_integer(BigInt::from(0));
        for (i, &vi) in v.iter().enumerate() {
            let mut term = exact(vi) * BigRational::from_integer(binomial.clone());
            for _ in 0..i {
                term *= t;
            }
            for _ in i..n {
                term *= &s;
            }
            sum += term;
            binomial = binomial * BigInt::from(n - i) / BigInt::from(i + 1);
        }
        sum
    }

    /// Splitmix64.
    fn stream(mut state: u64) -> impl FnMut() -> f64 {
        move || {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            (z ^ (z >> 31)) as f64 / u64::MAX as f64
        }
    }

    /// Every forward-differenced point of random quadratics and cubics (unit size, offset far
    /// from the origin, tiny, with counts from 1 to 3,000) is within E = 2⁻⁵⁰ s (N + 64) of
    /// the exact B(k h), h = fl(1/N), computed in rational arithmetic; and the bound is not
    /// vacuous: the largest error seen is above 1 % of the part of E that grows with N
    /// (about 6 % in this run).
    #[test]
    fn points_are_within_the_rounding_allowance() {
        let mut unit = stream(2026);
        let mut worst = 0.0_f64;
        for case in 0..48 {
            let len = 3 + case % 2;
            let (scale, offset) = match case % 6 {
                0 | 1 => (1.0, 0.0),
                2 | 3 => (1.0, 1e6),
                4 => (1e-30, -3e-30),
                _ => (1e20, 5e20),
            };
            let points: Vec<Vector2> = (0..len)
                .map(|_| {
                    Vector2::new(unit() - 0.5, unit() - 0.5) * (2.0 * scale)
                        + Vector2::new(offset, -offset)
                })
                .collect();
            let n = [1, 2, 3, 7, 31, 97, 400, 3_000][case % 8];
            let h = 1.0 / n as f64;
            let mut sent = Vec::new();
            let (p0, last) = (points[0], points[len - 1]);
            let count = if len == 3 {
                let d = p0 - points[1] * 2.0 + points[2];
                quadratic(
                    [p0, (points[1] - p0) * 2.0, d],
                    last,
                    n,
                    Step::new(h),
                    |p| {
                        sent.push(p);
                    },
                )
            } else {
                let (d0, d1) = (
                    p0 - points[1] * 2.0 + points[2],
                    points[1] - points[2] * 2.0 + points[3],
                );
                let coefficients = [p0, (points[1] - p0) * 3.0, d0 * 3.0, d1 - d0];
                cubic(coefficients, last, n, Step::new(h), |p| {
                    sent.push(p);
                })
            };
            assert_eq!((count, sent.len()), (n, n + 1));
            assert_eq!((sent[0].point, sent[n].point), (p0, last));
            let size: f64 = points.iter().map(|p| p.x().abs() + p.y().abs()).sum();
            let allowance = rounding_allowance(size, n as f64);
            let xs: Vec<f64> = points.iter().map(Vector2::x).collect();
            let ys: Vec<f64> = points.iter().map(Vector2::y).collect();
            // Every point of the short runs, every 37th of the long ones (the error grows
            // with k, so the last interior point is always checked).
            let step = if n > 100 { 37 } else { 1 };
            for k in (1..n).step_by(step).chain([n - 1]).filter(|&k| k >= 1) {
                let t = exact(h) * BigRational::from_integer(BigInt::from(k));
                let ex = (exact(sent[k].point.x()) - exact_value(&xs, &t))
                    .to_f64()
                    .unwrap();
                let ey = (exact(sent[k].point.y()) - exact_value(&ys, &t))
                    .to_f64()
                    .unwrap();
                let error = ex.hypot(ey);
                assert!(
                    error <= allowance,
                    "{points:?}, N = {n}, k = {k}: {error} > {allowance}"
                );
                assert_eq!(sent[k].t, k as f64 * h);
                worst = worst.max(error / (ROUNDING_UNIT * size * n as f64));
            }
        }
        assert!(worst > 0.01, "{worst}");
    }
}
