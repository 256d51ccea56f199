//! B(t) in O(n) without allocation: Horner's rule in t/(1 − t) on the binomial-scaled control
//! points C(n, i) Pᵢ, held in a caller's buffer (bez-core's `HornerBernstein` holds them in a
//! `Vec`).

use bez_core::Vector2;

/// The highest degree [`Method::Fast`](crate::Method::Fast) and
/// [`Method::Optimal`](crate::Method::Optimal) flatten without allocating: 64. Their working
/// buffers (the binomial-scaled control points; for `Optimal` also the control points relative
/// to P₀ and three control polygons of blocks, about 5 KB) are
/// arrays of 65 points in the call's stack frame; above this degree they are vectors, a few
/// per call. (A curve whose largest coordinate is outside 2^±128 is first scaled into a new curve,
/// which allocates at every degree.)
pub const MAX_STACK_DEGREE: usize = 64;

/// Points per stack buffer.
pub(crate) const STACK_POINTS: usize = MAX_STACK_DEGREE + 1;

/// Evaluation of one curve by Horner's rule on C(n, i) Pᵢ.
pub(crate) struct StackHorner<'a> {
    scaled: &'a [Vector2],
}

impl<'a> StackHorner<'a> {
    /// Writes C(n, i) Pᵢ into the front of `buffer` (at least as long as `points`, at most
    /// [`STACK_POINTS`] used: C(64, 32) · 10¹⁵² is finite); `None` for longer or empty
    /// polygons. The binomials are built by C(n, i) = C(n, i − 1)(n − i + 1)/i in `f64` (exact
    /// up to 2⁵³, within an ulp above).
    pub(crate) fn new(points: &[Vector2], buffer: &'a mut [Vector2]) -> Option<Self> {
        let n = points.len().checked_sub(1)?;
        if points.len() > STACK_POINTS {
            return None;
        }
        let out = buffer.get_mut(..points.len())?;
        let mut c = 1.0;
        for (i, (o, &p)) in out.iter_mut().zip(points).enumerate() {
            if i > 0 {
                c = c * (n - i + 1) as f64 / i as f64;
            }
            *o = p * c;
        }
        Some(Self { scaled: out })
    }

    /// B(t) for t in [0, 1]: (1 − t)ⁿ Σ C(n, i) Pᵢ sⁱ with s = t/(1 − t) for t ≤ ½, and
    /// tⁿ Σ C(n, i) Pᵢ rⁿ⁻ⁱ with r = (1 − t)/t above (|s|, |r| ≤ 1).
    #[inline]
    pub(crate) fn eval(&self, t: f64) -> Vector2 {
        let q = self.scaled;
        let Some((&last, rest)) = q.split_last() else {
            return Vector2::zeros();
        };
        let n = i32::try_from(rest.len()).unwrap_or(i32::MAX);
        if t <= 0.5 {
            let u = 1.0 - t;
            let s = t / u;
            let mut acc = last;
            for &c in rest.iter().rev() {
                acc = acc * s + c;
            }
            acc * u.powi(n)
        } else {
            let r = (1.0 - t) / t;
            let mut acc = q[0];
            for &c in &q[1..] {
                acc = acc * r + c;
            }
            acc * t.powi(n)
        }
    }

    /// B(t), B′(t) and B″(t) for t in [0, 1] in one pass (for the quintic models of
    /// [`quintic_model`](crate::quintic_model)): Horner's rule gives P(s) = Σ C(n, i) Pᵢ sⁱ, P′(s)
    /// and P″(s) together, and with B = uⁿ P(s), u = 1 − t, s = t / u, ds/dt = 1 / u²,
    /// B′(t) = u^(n−2) (P′(s) − n u P(s)) and
    /// B″(t) = u^(n−4) (P″(s) − 2(n − 1) u P′(s) + n(n − 1) u² P(s)) for t ≤ ½; above, the same
    /// in r = u / t with t for u (B(t) = tⁿ Q(r), the reversed curve's expansion), B′ with the
    /// opposite sign. The terms of B′ are at most 2n times the largest control point and those
    /// of B″ 4n² times, so their rounding is within about 8n² and 32n³ ulps of it, as for
    /// Horner's rule on the hodographs.
    #[inline]
    pub(crate) fn jet2(&self, t: f64) -> (Vector2, Vector2, Vector2) {
        let q = self.scaled;
        let z = Vector2::zeros();
        let Some((&last, rest)) = q.split_last() else {
            return (z, z, z);
        };
        let n = rest.len();
        let degree = i32::try_from(n).unwrap_or(i32::MAX);
        let n = n as f64;
        let (flip, x, acc, slope, curl) = if t <= 0.5 {
            let u = 1.0 - t;
            let s = t / u;
            let (mut acc, mut slope, mut curl) = (last, z, z);
            for &c in rest.iter().rev() {
                curl = curl * s + slope;
                slope = slope * s + acc;
                acc = acc * s + c;
            }
            (1.0, u, acc, slope, curl)
        } else {
            let r = (1.0 - t) / t;
            let (mut acc, mut slope, mut curl) = (q[0], z, z);
            for &c in &q[1..] {
                curl = curl * r + slope;
                slope = slope * r + acc;
                acc = acc * r + c;
            }
            (-1.0, t, acc, slope, curl)
        };
        // Horner's `curl` is P″ / 2.
        let power = x.powi(degree - 4);
        let x2 = x * x;
        (
            acc * (power * x2 * x2),
            (slope - acc * (n * x)) * (flip * power * x2),
            (curl * 2.0 - slope * (2.0 * (n - 1.0) * x) + acc * (n * (n - 1.0) * x2)) * power,
        )
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]

    use bez_core::proptest_support::curve;
    use bez_core::{BezierCurve, hodograph_slice};
    use proptest::prelude::*;

    use super::*;

    proptest! {
        /// The same points as de Casteljau's algorithm (bez-core's `eval`), to 1e-12 of the
        /// control points' size, at every degree the buffer takes; longer polygons are refused.
        #[test]
        fn matches_de_casteljau(c in curve::<2>(1..=64, 10.0), t in 0.0..=1.0f64) {
            let mut buffer = [Vector2::zeros(); STACK_POINTS];
            let horner = StackHorner::new(c.points(), &mut buffer);
            prop_assert!(horner.is_some());
            if let (Some(h), Ok(exact)) = (horner, c.eval(t)) {
                let scale = c.points().iter().map(Vector2::amax).fold(1.0, f64::max);
                prop_assert!((h.eval(t) - exact).norm() <= 1e-12 * scale);
            }
        }
    }

    proptest! {
        /// The point and the first two derivatives in one pass: de Casteljau's point of the
        /// curve and of its first and second hodographs (bez-core's `eval`, `hodograph_slice`),
        /// to 1e-12 of the control points' size times n and n² (the derivatives' scales), from
        /// degree 2 to the buffer's.
        #[test]
        fn jet_matches_de_casteljau(c in curve::<2>(2..=64, 10.0), t in 0.0..=1.0f64) {
            let mut buffer = [Vector2::zeros(); STACK_POINTS];
            let h = StackHorner::new(c.points(), &mut buffer).unwrap();
            let hodograph = BezierCurve::new(hodograph_slice(c.points())).unwrap();
            let scale = c.points().iter().map(Vector2::amax).fold(1.0, f64::max);
            let n = c.degree() as f64;
            let second = BezierCurve::new(hodograph_slice(hodograph.points())).unwrap();
            let (p, v, a) = h.jet2(t);
            prop_assert!((p - c.eval(t).unwrap()).norm() <= 1e-12 * scale);
            let slope = hodograph.eval(t).unwrap();
            prop_assert!((v - slope).norm() <= 1e-12 * n * scale, "{:?} {:?}", v, slope);
            let curl = second.eval(t).unwrap();
            prop_assert!((a - curl).norm() <= 1e-12 * n * n * scale, "{:?} {:?}", a, curl);
        }
    }

    #[test]
    fn refuses_polygons_beyond_the_buffer() {
        let mut buffer = [Vector2::zeros(); STACK_POINTS + 1];
        let long = [Vector2::zeros(); STACK_POINTS + 1];
        assert!(StackHorner::new(&long, &mut buffer).is_none());
        assert!(StackHorner::new(&[], &mut buffer).is_none());
    }
}
