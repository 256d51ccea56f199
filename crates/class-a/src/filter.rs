//! Floating-point filters for the certificates: the numerators of d(κ²)/dt and dτ/dt formed by
//! the same operations as the exact path, in f64 and, when that cannot decide, in double-double
//! arithmetic (module `dd`), each coefficient with a rigorous error bound.
//!
//! The inputs are the control polygon's legs Δbₖ = bₖ₊₁ − bₖ (exact in double-double, one
//! rounding in f64), so nothing depends on where the curve lies. Every computed coefficient ṽ of
//! an expression of +, − and × satisfies |ṽ − v| ≤ γ_D · m with v the exact value, m the same
//! expression evaluated on the absolute values of the inputs with every − turned into + (the
//! magnitude, computed alongside in f64), D the largest number of roundings along any path from
//! an input to the coefficient, and γ_D = Du/(1 − Du) with u the unit of the stage: ε = 2⁻⁵² in
//! f64 (each rounding multiplies a term by some 1 + δ, |δ| ≤ ε/2), [`dd::UNIT`] = 2⁻¹⁰⁰ in
//! double-double (published bounds at most 7·2⁻¹⁰⁶). Both units also absorb the absolute error
//! of an underflowing partial product: the non-zero inputs are at least 2⁻¹²⁰ of the largest,
//! which is scaled to at most 1, and every product has at most seven input factors and integer
//! weights ≥ 1, so any partial result with a non-zero magnitude has magnitude ≥ 2⁻⁸⁴⁰, and an
//! underflow error (below 2⁻¹⁰⁶⁰) is less than 2⁻²²⁰ of it. Overflow gives an infinity or NaN,
//! which propagates to a final coefficient and makes the stage decline.
//!
//! A coefficient whose value exceeds its bound has a proven sign; when every coefficient of the
//! regularity polynomial is proven positive and every coefficient of the numerator is proven of
//! one sign, the certificate's verdict is the exact path's verdict (its first step sees the same
//! signs), otherwise the stage declines.

use bez_core::BezierCurve;

use crate::dd::{self, Dd};

/// The arithmetic of one filter stage.
pub(crate) trait Stage: Copy + PartialEq {
    /// Zero.
    const ZERO: Self;
    /// Roundings in forming a leg Δbₖ from two f64 coordinates.
    const DIFFERENCE_ROUNDINGS: u32;
    /// The small integer k (exact).
    fn int(k: f64) -> Self;
    /// a − b.
    fn difference(a: f64, b: f64) -> Self;
    /// Multiplication by the power of two p (must be exact: checked by the caller).
    fn scale(self, p: f64) -> Self;
    /// Sum (one rounding).
    fn add(self, other: Self) -> Self;
    /// Product (one rounding).
    fn mul(self, other: Self) -> Self;
    /// The nearest f64.
    fn lead(self) -> f64;
    /// No infinity or NaN.
    fn finite(self) -> bool;
    /// C(n, 0..=n) and the roundings they carry, or `None` if the stage cannot form them.
    fn binomial_row(n: usize) -> Option<(Vec<Self>, u32)>;
    /// F such that |ṽ − v| ≤ F · m̃ for a coefficient of rounding depth `depth`, m̃ its computed
    /// magnitude.
    fn error_factor(depth: u32) -> f64;
    /// The sign of the exact value, proven if the computed value exceeds `bound`.
    fn proven(self, bound: f64) -> Proven;
    /// out[i + j] += a[i]·b[j].
    fn convolve(a: &[Self], b: &[Self], out: &mut [Self]) {
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i + j] = out[i + j].add(x.mul(*y));
            }
        }
    }
}

impl Stage for f64 {
    const ZERO: Self = 0.0;
    const DIFFERENCE_ROUNDINGS: u32 = 1;
    fn int(k: f64) -> Self {
        k
    }
    fn difference(a: f64, b: f64) -> Self {
        a - b
    }
    fn scale(self, p: f64) -> Self {
        self * p
    }
    fn add(self, other: Self) -> Self {
        self + other
    }
    fn mul(self, other: Self) -> Self {
        self * other
    }
    fn lead(self) -> f64 {
        self
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
    fn binomial_row(n: usize) -> Option<(Vec<Self>, u32)> {
        Some(binomial_row(n))
    }
    fn error_factor(depth: u32) -> f64 {
        let d = f64::from(depth + 2) * f64::EPSILON;
        let gamma = d / (1.0 - d);
        gamma / (1.0 - gamma) * (1.0 + 4.0 * f64::EPSILON)
    }
    fn proven(self, bound: f64) -> Proven {
        if self > bound {
            Proven::Positive
        } else if self < -bound {
            Proven::Negative
        } else {
            Proven::Unknown
        }
    }
}

impl Stage for Dd {
    const ZERO: Self = Dd::ZERO;
    const DIFFERENCE_ROUNDINGS: u32 = 0;
    fn int(k: f64) -> Self {
        Dd::from_f64(k)
    }
    fn difference(a: f64, b: f64) -> Self {
        Dd::difference(a, b)
    }
    fn scale(self, p: f64) -> Self {
        Dd::scale(self, p)
    }
    fn add(self, other: Self) -> Self {
        Dd::add(self, other)
    }
    fn mul(self, other: Self) -> Self {
        Dd::mul(self, other)
    }
    fn lead(self) -> f64 {
        self.hi
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
    fn binomial_row(n: usize) -> Option<(Vec<Self>, u32)> {
        let mut row = Vec::with_capacity(n + 1);
        let mut c: u128 = 1;
        row.push(Dd::from_f64(1.0));
        for k in 0..n {
            c = c.checked_mul((n - k) as u128)? / (k + 1) as u128;
            row.push(Dd::from_u128(c)?);
        }
        Some((row, 0))
    }
    fn error_factor(depth: u32) -> f64 {
        let d = f64::from(depth + 2) * dd::UNIT;
        let gamma = d / (1.0 - d);
        // The magnitude is an f64 computation of at most depth + 4 roundings.
        let e = f64::from(depth + 4) * f64::EPSILON;
        let gamma64 = e / (1.0 - e);
        gamma / (1.0 - gamma64) * (1.0 + 8.0 * f64::EPSILON)
    }
    fn proven(self, bound: f64) -> Proven {
        // |lo| ≤ ε/2 |hi|: |hi| > bound (1 + 4ε) proves |hi + lo| > bound, with the sign of hi.
        let b = bound * (1.0 + 4.0 * f64::EPSILON);
        if self.hi > b {
            Proven::Positive
        } else if self.hi < -b {
            Proven::Negative
        } else {
            Proven::Unknown
        }
    }
    fn convolve(a: &[Self], b: &[Self], out: &mut [Self]) {
        // The same products as `Dd::mul`, each high part split once.
        let bs: Vec<(f64, f64)> = b.iter().map(|y| y.split_hi()).collect();
        for (i, x) in a.iter().enumerate() {
            let xs = x.split_hi();
            for (j, (y, ys)) in b.iter().zip(&bs).enumerate() {
                out[i + j] = out[i + j].add(x.mul_split(xs, *y, *ys));
            }
        }
    }
}

/// A polynomial in the scaled Bernstein basis tᵏ(1 − t)ᴺ⁻ᵏ with coefficients in a stage's
/// arithmetic, their magnitudes, and the rounding depth bound D.
#[derive(Debug, Clone)]
struct Approx<S> {
    value: Vec<S>,
    magnitude: Vec<f64>,
    depth: u32,
}

/// The sign of a coefficient as far as a stage can prove it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Proven {
    Positive,
    Negative,
    Zero,
    Unknown,
}

impl<S: Stage> Approx<S> {
    fn degree(&self) -> usize {
        self.value.len() - 1
    }

    /// The convolution product (depth + 1 for the products, + L − 1 for a sum of L terms).
    fn mul(&self, other: &Self) -> Self {
        let len = self.value.len() + other.value.len() - 1;
        let mut value = vec![S::ZERO; len];
        let mut magnitude = vec![0.0; len];
        S::convolve(&self.value, &other.value, &mut value);
        for (i, ma) in self.magnitude.iter().enumerate() {
            for (j, mb) in other.magnitude.iter().enumerate() {
                magnitude[i + j] += ma * mb;
            }
        }
        let terms = self.value.len().min(other.value.len()) as u32;
        Self {
            value,
            magnitude,
            depth: self.depth.max(other.depth) + terms,
        }
    }

    /// self + k·other, both of one degree (`None` otherwise; the numerators never need
    /// elevation).
    fn add_scaled(&self, other: &Self, k: f64) -> Option<Self> {
        if self.degree() != other.degree() {
            return None;
        }
        let kk = S::int(k);
        Some(Self {
            value: self
                .value
                .iter()
                .zip(&other.value)
                .map(|(x, y)| x.add(kk.mul(*y)))
                .collect(),
            magnitude: self
                .magnitude
                .iter()
                .zip(&other.magnitude)
                .map(|(x, y)| x + k.abs() * y)
                .collect(),
            depth: self.depth.max(other.depth) + 2,
        })
    }

    /// aₖ' = (k + 1)aₖ₊₁ − (N − k)aₖ.
    fn derivative(&self) -> Self {
        let n = self.degree();
        if n == 0 {
            return Self {
                value: vec![S::ZERO],
                magnitude: vec![0.0],
                depth: self.depth,
            };
        }
        let (mut value, mut magnitude) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for k in 0..n {
            let (p, q) = ((k + 1) as f64, (n - k) as f64);
            value.push(
                S::int(p)
                    .mul(self.value[k + 1])
                    .add(S::int(-q).mul(self.value[k])),
            );
            magnitude.push(p * self.magnitude[k + 1] + q * self.magnitude[k]);
        }
        Self {
            value,
            magnitude,
            depth: self.depth + 2,
        }
    }

    /// The proven sign of every coefficient.
    fn signs(&self) -> Vec<Proven> {
        let factor = S::error_factor(self.depth);
        self.value
            .iter()
            .zip(&self.magnitude)
            .map(|(&v, &m)| {
                if !(v.finite() && m.is_finite()) || (m != 0.0 && m < f64::MIN_POSITIVE) {
                    Proven::Unknown
                } else if m == 0.0 {
                    Proven::Zero
                } else {
                    v.proven(factor * m)
                }
            })
            .collect()
    }
}

/// C(n, 0..=n) in f64 and the roundings they carry: exact integers (u128) rounded once to
/// f64 while they fit, else the f64 recurrence (two roundings per step).
fn binomial_row(n: usize) -> (Vec<f64>, u32) {
    let mut exact = Vec::with_capacity(n + 1);
    let mut c: u128 = 1;
    exact.push(1.0);
    for k in 0..n {
        match c.checked_mul((n - k) as u128) {
            Some(x) => {
                c = x / (k + 1) as u128;
                exact.push(c as f64);
            }
            None => {
                let mut row = Vec::with_capacity(n + 1);
                let mut c = 1.0f64;
                row.push(c);
                for k in 0..n {
                    c = c * (n - k) as f64 / (k + 1) as f64;
                    row.push(c);
                }
                return (row, 2 * u32::try_from(n).unwrap_or(u32::MAX / 4));
            }
        }
    }
    (exact, 1)
}

/// Smallest magnitude (after normalization) a non-zero leg coordinate may have: seven
/// factors of 2⁻¹²⁰ stay above the smallest normal f64, so no product underflows.
const SMALLEST_INPUT: f64 = 7.523_163_845_262_64e-37; // 2⁻¹²⁰

/// The hodographs of order 1..=k (each times a positive constant), from the legs Δbₖ
/// normalized by a power of two; `None` when a coordinate is not finite, a leg coordinate is
/// too small next to the largest for the error model, or all points coincide.
fn hodographs<S: Stage, const D: usize>(
    curve: &BezierCurve<D>,
    k: usize,
) -> Option<Vec<Vec<Approx<S>>>> {
    let pts = curve.points();
    let n = pts.len() - 1;
    if n == 0 || !pts.iter().all(|p| p.iter().all(|x| x.is_finite())) {
        return None;
    }
    let legs: Vec<Vec<S>> = (0..D)
        .map(|d| {
            pts.windows(2)
                .map(|w| S::difference(w[1][d], w[0][d]))
                .collect()
        })
        .collect();
    let largest = legs
        .iter()
        .flatten()
        .map(|x| x.lead().abs())
        .fold(0.0f64, f64::max);
    if !largest.is_finite() || largest == 0.0 {
        return None;
    }
    // 2⁻ᵉ with |largest| ≤ 2ᵉ, formed in two steps so that neither factor overflows.
    let e = largest.log2().ceil() as i32;
    let (s1, s2) = (2f64.powi(-e / 2), 2f64.powi(-e + e / 2));
    let (row, row_depth) = S::binomial_row(n - 1)?;
    let mut cur: Vec<Approx<S>> = Vec::with_capacity(D);
    for coord in legs {
        let mut value = Vec::with_capacity(n);
        let mut magnitude = Vec::with_capacity(n);
        for (x, c) in coord.iter().zip(&row) {
            let y = x.scale(s1).scale(s2);
            let back = y.scale(1.0 / s2).scale(1.0 / s1);
            let small = y.lead() != 0.0 && y.lead().abs() < SMALLEST_INPUT;
            if small || !y.finite() || back != *x {
                return None;
            }
            value.push(y.mul(*c));
            magnitude.push(y.lead().abs() * c.lead());
        }
        cur.push(Approx {
            value,
            magnitude,
            depth: S::DIFFERENCE_ROUNDINGS + row_depth + 1,
        });
    }
    let mut out = Vec::with_capacity(k);
    out.push(cur.clone());
    for _ in 1..k {
        cur = cur.iter().map(Approx::derivative).collect();
        out.push(cur.clone());
    }
    Some(out)
}

fn dot<S: Stage>(a: &[Approx<S>], b: &[Approx<S>]) -> Option<Approx<S>> {
    let mut terms = a.iter().zip(b).map(|(x, y)| x.mul(y));
    let first = terms.next()?;
    terms.try_fold(first, |acc, p| acc.add_scaled(&p, 1.0))
}

fn cross<S: Stage>(d1: &[Approx<S>], d2: &[Approx<S>], i: usize, j: usize) -> Option<Approx<S>> {
    d1[i].mul(&d2[j]).add_scaled(&d1[j].mul(&d2[i]), -1.0)
}

/// What a filter stage proved: the sign of the numerator on [0, 1] (the quantity increases,
/// decreases or is constant), or nothing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Filtered {
    Increasing,
    Decreasing,
    Constant,
    Declined,
}

/// Regularity (every coefficient of `regular` proven positive) and one proven sign of `num`.
fn decide<S: Stage>(num: &Approx<S>, regular: &Approx<S>) -> Filtered {
    if !regular.signs().iter().all(|s| *s == Proven::Positive) {
        return Filtered::Declined;
    }
    let signs = num.signs();
    if signs.contains(&Proven::Unknown) {
        return Filtered::Declined;
    }
    match (
        signs.contains(&Proven::Positive),
        signs.contains(&Proven::Negative),
    ) {
        (true, false) => Filtered::Increasing,
        (false, true) => Filtered::Decreasing,
        (false, false) => Filtered::Constant,
        (true, true) => Filtered::Declined,
    }
}

/// The filter stage `S` for d(κ²)/dt: N = G'P − 3GP' with P = |x'|²,
/// G = Σ_{i<j}(x'ᵢx''ⱼ − x'ⱼx''ᵢ)².
pub(crate) fn curvature<S: Stage, const D: usize>(curve: &BezierCurve<D>) -> Filtered {
    let formed = || {
        let d = hodographs::<S, D>(curve, 2)?;
        let p = dot(&d[0], &d[0])?;
        let mut terms = Vec::new();
        for i in 0..D {
            for j in i + 1..D {
                terms.push(cross(&d[0], &d[1], i, j)?);
            }
        }
        let g = dot(&terms, &terms)?;
        let num = g
            .derivative()
            .mul(&p)
            .add_scaled(&g.mul(&p.derivative()), -3.0)?;
        Some((num, p))
    };
    formed().map_or(Filtered::Declined, |(num, p)| decide(&num, &p))
}

/// The filter stage `S` for dτ/dt: N = Δ'G − ΔG' with Δ = det(x', x'', x'''),
/// G = |x' × x''|².
pub(crate) fn torsion<S: Stage>(curve: &BezierCurve<3>) -> Filtered {
    let formed = || {
        let d = hodographs::<S, 3>(curve, 3)?;
        let c = (0..3)
            .map(|k| cross(&d[0], &d[1], (k + 1) % 3, (k + 2) % 3))
            .collect::<Option<Vec<_>>>()?;
        let g = dot(&c, &c)?;
        let delta = dot(&c, &d[2])?;
        let num = delta
            .derivative()
            .mul(&g)
            .add_scaled(&delta.mul(&g.derivative()), -1.0)?;
        Some((num, g))
    };
    formed().map_or(Filtered::Declined, |(num, g)| decide(&num, &g))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use crate::certificate::{curvature_certificate_exact, torsion_certificate_exact};
    use crate::{
        Matrix2, Proof, class_a_curve, curvature_certificate, rotation, torsion_certificate,
    };
    use bez_core::{Vector2, Vector3};

    /// SplitMix64.
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            (z ^ (z >> 31)) as f64 / u64::MAX as f64
        }
        fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.next()
        }
    }

    #[test]
    fn filter_verdicts_agree_with_the_exact_path() {
        let mut rng = Rng(2);
        let (mut planar_filtered, mut spatial_filtered, mut total) = (0, 0, 0);
        for _ in 0..250 {
            total += 1;
            let n = 3 + (rng.next() * 14.0) as usize;
            let (s, th) = (rng.range(0.5, 1.8), rng.range(-0.6, 0.6));
            let e = rng.range(0.0, 0.3);
            let m = crate::typical_matrix2(s, th)
                + Matrix2::new(
                    rng.range(-e, e),
                    rng.range(-e, e),
                    rng.range(-e, e),
                    rng.range(-e, e),
                );
            let b0 = Vector2::new(rng.range(-9.0, 9.0), rng.range(-9.0, 9.0));
            let c = class_a_curve(&b0, &Vector2::new(1.0, rng.range(-1.0, 1.0)), &m, n).unwrap();
            let fast = curvature_certificate(&c);
            let exact = curvature_certificate_exact(&c);
            match (&fast, &exact) {
                (Ok(f), Ok(x)) => {
                    assert_eq!(f.verdict, x.verdict, "n = {n}");
                    planar_filtered += usize::from(f.proof == Proof::Filter);
                }
                (Err(f), Err(x)) => assert_eq!(f, x),
                _ => panic!("{fast:?} vs {exact:?}"),
            }
            let axis = Vector3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0);
            let m3 = rotation(&(axis / axis.norm()), th) * s;
            let v0 = Vector3::new(1.0, rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
            let c3 = class_a_curve(&Vector3::zeros(), &v0, &m3, n).unwrap();
            for (fast, exact) in [
                (curvature_certificate(&c3), curvature_certificate_exact(&c3)),
                (torsion_certificate(&c3), torsion_certificate_exact(&c3)),
            ] {
                match (&fast, &exact) {
                    (Ok(f), Ok(x)) => {
                        assert_eq!(f.verdict, x.verdict, "n = {n}");
                        spatial_filtered += usize::from(f.proof == Proof::Filter);
                    }
                    (Err(f), Err(x)) => assert_eq!(f, x),
                    _ => panic!("{fast:?} vs {exact:?}"),
                }
            }
        }
        // The filter decides most curves (the exact path the rest).
        assert!(
            planar_filtered * 2 > total && spatial_filtered > total,
            "{planar_filtered} {spatial_filtered}"
        );
    }

    /// The exact verdict as the filter would report it, if the exact path proved one sign.
    fn as_filtered(c: &crate::Certificate) -> Option<Filtered> {
        match c.verdict {
            crate::Monotonicity::Increasing => Some(Filtered::Increasing),
            crate::Monotonicity::Decreasing => Some(Filtered::Decreasing),
            crate::Monotonicity::Constant => Some(Filtered::Constant),
            _ => None,
        }
    }

    #[test]
    fn each_stage_agrees_with_the_exact_path_on_nearly_straight_curves() {
        // Small turns θ: the torsion numerator's coefficients cancel to 1e-13 .. 1e-20 of their
        // magnitude, below what f64 resolves; placed far from the origin (the legs, not the
        // points, enter the filter).
        let mut rng = Rng(11);
        let (mut f64_decided, mut dd_decided, mut dd_only) = (0, 0, 0);
        for _ in 0..300 {
            let n = 3 + (rng.next() * 10.0) as usize;
            let s = rng.range(1.0, 1.6);
            let th = rng.range(0.003, 0.03);
            let axis = Vector3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0);
            let m3 = rotation(&(axis / axis.norm()), th) * s;
            let v0 = Vector3::new(1.0, rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
            let b0 = Vector3::new(rng.range(-1e3, 1e3), 0.0, rng.range(-1e3, 1e3));
            let c = class_a_curve(&b0, &v0, &m3, n).unwrap();
            let exact = torsion_certificate_exact(&c).ok();
            let want = exact.as_ref().and_then(as_filtered);
            let (a, b) = (torsion::<f64>(&c), torsion::<Dd>(&c));
            for got in [a, b] {
                if got != Filtered::Declined {
                    assert_eq!(Some(got), want, "n = {n}, s = {s}, θ = {th}");
                }
            }
            f64_decided += usize::from(a != Filtered::Declined);
            dd_decided += usize::from(b != Filtered::Declined);
            dd_only += usize::from(a == Filtered::Declined && b != Filtered::Declined);
            // The certificate reports the stage that decided.
            let cert = torsion_certificate(&c).unwrap();
            assert_eq!(Some(&cert.verdict), exact.as_ref().map(|x| &x.verdict));
            let stage = match (a, b) {
                (Filtered::Declined, Filtered::Declined) => Proof::Exact,
                (Filtered::Declined, _) => Proof::DoubleDouble,
                _ => Proof::Filter,
            };
            assert_eq!(cert.proof, stage);
        }
        // Double-double decides everything f64 does, and more.
        assert!(
            dd_decided >= f64_decided && dd_only >= 50,
            "{f64_decided} {dd_decided} {dd_only}"
        );
    }

    #[test]
    fn the_filter_declines_what_it_cannot_prove() {
        // A planar curve in the plane z = 0: every torsion term is an exact zero (magnitude 0),
        // so the filter proves `Constant` itself; tilted, it decides a sign.
        let m = rotation(&Vector3::new(0.0, 0.0, 1.0), 0.3) * 1.2;
        let c = class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.5, 0.0), &m, 6).unwrap();
        assert_eq!(torsion::<f64>(&c), Filtered::Constant);
        assert_eq!(torsion::<Dd>(&c), Filtered::Constant);
        let m = rotation(&Vector3::new(0.3, 0.1, 1.0).normalize(), 0.3) * 1.2;
        let c = class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.5, 0.0), &m, 6).unwrap();
        assert_ne!(torsion::<f64>(&c), Filtered::Declined);
        // A cusp (x' = 0 at t = 1/2): regularity is not proven in f64.
        let cusp = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(2.0, 2.0),
            Vector2::new(-1.0, 2.0),
            Vector2::new(1.0, 0.0),
        ])
        .unwrap();
        assert_eq!(curvature::<f64, 2>(&cusp), Filtered::Declined);
        assert_eq!(curvature::<Dd, 2>(&cusp), Filtered::Declined);
        // Non-finite or too small coordinates are declined before any arithmetic.
        let tiny = BezierCurve::new(vec![
            Vector2::new(1.0, 0.0),
            Vector2::new(1.0, 1e-300),
            Vector2::new(2.0, 0.0),
        ])
        .unwrap();
        assert_eq!(curvature::<f64, 2>(&tiny), Filtered::Declined);
        assert_eq!(curvature::<Dd, 2>(&tiny), Filtered::Declined);
    }
}
