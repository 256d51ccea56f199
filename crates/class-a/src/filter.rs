//! A floating-point filter for the certificates: the numerators of d(κ²)/dt and dτ/dt formed in
//! f64 by the same operations as the exact path, each coefficient with a rigorous error bound.
//!
//! Every computed coefficient ṽ of an expression of +, − and × evaluated in f64 satisfies
//! |ṽ − v| ≤ γ_D · m with v the exact value, m the same expression evaluated on the absolute
//! values of the inputs with every − turned into + (the magnitude, computed alongside in f64),
//! D the largest number of roundings along any path from an input to the coefficient, and
//! γ_D = Dε/(1 − Dε) (each rounding multiplies a term by some 1 + δ, |δ| ≤ ε/2; we use ε to
//! leave room for the absolute error of an underflowing product, ruled out by the input check
//! below). A coefficient whose value exceeds that bound has a proven sign; when every
//! coefficient of the regularity polynomial is proven positive and every coefficient of the
//! numerator is proven of one sign, the certificate's verdict is the exact path's verdict (its
//! first step sees the same signs), otherwise the filter declines and the exact path decides.

use bez_core::BezierCurve;

/// A polynomial in the scaled Bernstein basis tᵏ(1 − t)ᴺ⁻ᵏ with f64 coefficients, their
/// magnitudes, and the rounding depth bound D.
#[derive(Debug, Clone)]
struct Approx {
    value: Vec<f64>,
    magnitude: Vec<f64>,
    depth: u32,
}

/// The sign of a coefficient as far as the filter can prove it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Proven {
    Positive,
    Negative,
    Zero,
    Unknown,
}

impl Approx {
    fn degree(&self) -> usize {
        self.value.len() - 1
    }

    /// The convolution product (depth + 1 for the products, + L − 1 for a sum of L terms).
    fn mul(&self, other: &Self) -> Self {
        let len = self.value.len() + other.value.len() - 1;
        let mut value = vec![0.0; len];
        let mut magnitude = vec![0.0; len];
        for (i, (a, ma)) in self.value.iter().zip(&self.magnitude).enumerate() {
            for (j, (b, mb)) in other.value.iter().zip(&other.magnitude).enumerate() {
                value[i + j] += a * b;
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

    /// Multiplication by ((1 − t) + t)ʳ (binomial coefficients, rounded above 2⁵³).
    fn elevate(&self, r: usize) -> Self {
        if r == 0 {
            return self.clone();
        }
        let (row, depth) = binomial_row(r);
        self.mul(&Self {
            magnitude: row.clone(),
            value: row,
            depth,
        })
    }

    /// self + k·other after elevating the lower degree.
    fn add_scaled(&self, other: &Self, k: f64) -> Self {
        let n = self.degree().max(other.degree());
        let a = self.elevate(n - self.degree());
        let b = other.elevate(n - other.degree());
        Self {
            value: a
                .value
                .iter()
                .zip(&b.value)
                .map(|(x, y)| x + k * y)
                .collect(),
            magnitude: a
                .magnitude
                .iter()
                .zip(&b.magnitude)
                .map(|(x, y)| x + k.abs() * y)
                .collect(),
            depth: a.depth.max(b.depth) + 2,
        }
    }

    /// aₖ' = (k + 1)aₖ₊₁ − (N − k)aₖ.
    fn derivative(&self) -> Self {
        let n = self.degree();
        if n == 0 {
            return Self {
                value: vec![0.0],
                magnitude: vec![0.0],
                depth: self.depth,
            };
        }
        let (mut value, mut magnitude) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for k in 0..n {
            let (p, q) = ((k + 1) as f64, (n - k) as f64);
            value.push(p * self.value[k + 1] - q * self.value[k]);
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
        let d = f64::from(self.depth + 2) * f64::EPSILON;
        let gamma = d / (1.0 - d);
        let factor = gamma / (1.0 - gamma) * (1.0 + 4.0 * f64::EPSILON);
        self.value
            .iter()
            .zip(&self.magnitude)
            .map(|(&v, &m)| {
                if !(v.is_finite() && m.is_finite()) || (m != 0.0 && m < f64::MIN_POSITIVE) {
                    Proven::Unknown
                } else if m == 0.0 {
                    Proven::Zero
                } else if v > factor * m {
                    Proven::Positive
                } else if v < -factor * m {
                    Proven::Negative
                } else {
                    Proven::Unknown
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

/// Smallest magnitude (after normalization) a non-zero input coordinate may have: seven
/// factors of 2⁻¹²⁰ stay above the smallest normal f64, so no product underflows.
const SMALLEST_INPUT: f64 = 7.523_163_845_262_64e-37; // 2⁻¹²⁰

/// The hodographs of order 1..=k, coordinates normalized by a power of two (exact); `None`
/// when a coordinate is not finite or too small next to the largest for the error model.
fn hodographs<const D: usize>(curve: &BezierCurve<D>, k: usize) -> Option<Vec<Vec<Approx>>> {
    let pts = curve.points();
    let largest = pts
        .iter()
        .flat_map(|p| p.iter().map(|x| x.abs()))
        .fold(0.0f64, f64::max);
    if !largest.is_finite() || largest == 0.0 {
        return None;
    }
    let scale = 2f64.powi(-largest.log2().ceil() as i32);
    let n = pts.len() - 1;
    let (row, row_depth) = binomial_row(n);
    let mut cur: Vec<Approx> = Vec::with_capacity(D);
    for d in 0..D {
        let mut value = Vec::with_capacity(n + 1);
        let mut magnitude = Vec::with_capacity(n + 1);
        for (p, c) in pts.iter().zip(&row) {
            let x = p[d] * scale;
            if x != 0.0 && x.abs() < SMALLEST_INPUT {
                return None;
            }
            value.push(x * c);
            magnitude.push(x.abs() * c);
        }
        cur.push(Approx {
            value,
            magnitude,
            depth: row_depth + 1,
        });
    }
    let mut out = Vec::with_capacity(k);
    for _ in 0..k {
        cur = cur.iter().map(Approx::derivative).collect();
        out.push(cur.clone());
    }
    Some(out)
}

fn dot(a: &[Approx], b: &[Approx]) -> Approx {
    let mut terms = a.iter().zip(b).map(|(x, y)| x.mul(y));
    let first = terms.next().unwrap_or(Approx {
        value: vec![0.0],
        magnitude: vec![0.0],
        depth: 0,
    });
    terms.fold(first, |acc, p| acc.add_scaled(&p, 1.0))
}

fn cross(d1: &[Approx], d2: &[Approx], i: usize, j: usize) -> Approx {
    d1[i].mul(&d2[j]).add_scaled(&d1[j].mul(&d2[i]), -1.0)
}

/// What the filter proved: the sign of the numerator on [0, 1] (the quantity increases,
/// decreases or is constant), or nothing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Filtered {
    Increasing,
    Decreasing,
    Constant,
    Declined,
}

/// Regularity (every coefficient of `regular` proven positive) and one proven sign of `num`.
fn decide(num: &Approx, regular: &Approx) -> Filtered {
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

/// The filter for d(κ²)/dt: N = G'P − 3GP' with P = |x'|², G = Σ_{i<j}(x'ᵢx''ⱼ − x'ⱼx''ᵢ)².
pub(crate) fn curvature<const D: usize>(curve: &BezierCurve<D>) -> Filtered {
    let Some(d) = hodographs(curve, 2) else {
        return Filtered::Declined;
    };
    let p = dot(&d[0], &d[0]);
    let mut terms = Vec::new();
    for i in 0..D {
        for j in i + 1..D {
            terms.push(cross(&d[0], &d[1], i, j));
        }
    }
    let g = dot(&terms, &terms);
    let num = g
        .derivative()
        .mul(&p)
        .add_scaled(&g.mul(&p.derivative()), -3.0);
    decide(&num, &p)
}

/// The filter for dτ/dt: N = Δ'G − ΔG' with Δ = det(x', x'', x'''), G = |x' × x''|².
pub(crate) fn torsion(curve: &BezierCurve<3>) -> Filtered {
    let Some(d) = hodographs(curve, 3) else {
        return Filtered::Declined;
    };
    let c: Vec<Approx> = (0..3)
        .map(|k| cross(&d[0], &d[1], (k + 1) % 3, (k + 2) % 3))
        .collect();
    let g = dot(&c, &c);
    let delta = dot(&c, &d[2]);
    let num = delta
        .derivative()
        .mul(&g)
        .add_scaled(&delta.mul(&g.derivative()), -1.0);
    decide(&num, &g)
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

    #[test]
    fn the_filter_declines_what_it_cannot_prove() {
        // A planar curve in the plane z = 0: every torsion term is an exact zero (magnitude 0),
        // so the filter proves `Constant` itself; tilted, it decides a sign.
        let m = rotation(&Vector3::new(0.0, 0.0, 1.0), 0.3) * 1.2;
        let c = class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.5, 0.0), &m, 6).unwrap();
        assert_eq!(torsion(&c), Filtered::Constant);
        let m = rotation(&Vector3::new(0.3, 0.1, 1.0).normalize(), 0.3) * 1.2;
        let c = class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.5, 0.0), &m, 6).unwrap();
        assert_ne!(torsion(&c), Filtered::Declined);
        // A cusp (x' = 0 at t = 1/2): regularity is not proven in f64.
        let cusp = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(2.0, 2.0),
            Vector2::new(-1.0, 2.0),
            Vector2::new(1.0, 0.0),
        ])
        .unwrap();
        assert_eq!(curvature(&cusp), Filtered::Declined);
        // Non-finite or too small coordinates are declined before any arithmetic.
        let tiny = BezierCurve::new(vec![
            Vector2::new(1.0, 0.0),
            Vector2::new(1.0, 1e-300),
            Vector2::new(2.0, 0.0),
        ])
        .unwrap();
        assert_eq!(curvature(&tiny), Filtered::Declined);
    }
}
