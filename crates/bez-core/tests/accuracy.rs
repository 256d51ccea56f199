//! Accuracy beyond the peers: high-degree subdivision and compensated evaluation.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, Vector, compensated_de_casteljau, de_casteljau};
mod common;

use common::{Q, binom, q};
use num_traits::{One, ToPrimitive, Zero};

/// Exact Bernstein evaluation Σ cᵢ C(n,i) tⁱ (1−t)ⁿ⁻ⁱ in rationals.
fn exact_eval(c: &[Q], t: &Q) -> Q {
    let n = c.len() - 1;
    let s = Q::one() - t;
    let mut acc = Q::zero();
    for (i, ci) in c.iter().enumerate() {
        let mut term = ci * binom(n, i);
        for _ in 0..i {
            term *= t;
        }
        for _ in 0..n - i {
            term *= &s;
        }
        acc += term;
    }
    acc
}

#[test]
fn compensated_evaluation_beats_de_casteljau_near_a_multiple_root() {
    // p(s) = (s − 1)(s − 3/4)⁷, expanded exactly into Bernstein form of degree 8, then rounded.
    // Monomial coefficients: multiply out in rationals.
    let mut mono = vec![Q::one()];
    let factors: Vec<Q> = std::iter::once(Q::one())
        .chain(std::iter::repeat_n(Q::new(3.into(), 4.into()), 7))
        .collect();
    for r in &factors {
        let mut next = vec![Q::zero(); mono.len() + 1];
        for (k, m) in mono.iter().enumerate() {
            next[k + 1] += m;
            next[k] -= m * r;
        }
        mono = next;
    }
    // Monomial → Bernstein: c_i = Σ_{k ≤ i} C(i,k)/C(n,k) a_k.
    let n = mono.len() - 1;
    let bern: Vec<Q> = (0..=n)
        .map(|i| {
            (0..=i)
                .map(|k| binom(i, k) / binom(n, k) * &mono[k])
                .fold(Q::zero(), |a, b| a + b)
        })
        .collect();
    let coeffs: Vec<f64> = bern.iter().map(|c| c.to_f64().unwrap()).collect();
    let rounded: Vec<Q> = coeffs.iter().map(|&c| q(c)).collect();

    let (mut err_plain, mut err_comp) = (0.0_f64, 0.0_f64);
    for k in 0..=200 {
        let t = 0.74 + 0.02 * f64::from(k) / 200.0;
        let exact = exact_eval(&rounded, &q(t)).to_f64().unwrap();
        if exact == 0.0 {
            continue;
        }
        let rel = |x: f64| ((x - exact) / exact).abs();
        err_plain = err_plain.max(rel(de_casteljau(&coeffs, t).unwrap()));
        err_comp = err_comp.max(rel(compensated_de_casteljau(&coeffs, t)));
    }
    // Plain de Casteljau loses most digits here; the compensated one keeps almost all.
    // Measured: plain ≈ 1e8 (not a single correct digit), compensated ≈ 2e-8.
    assert!(err_plain > 1.0, "plain error {err_plain:e}");
    assert!(err_comp < 1e-6, "compensated error {err_comp:e}");
    assert!(err_comp * 1e10 < err_plain);

    // The curve-level method agrees with the scalar kernel.
    let curve = BezierCurve::new(coeffs.iter().map(|&c| Vector::from([c])).collect()).unwrap();
    assert_eq!(
        curve.eval_compensated(0.75).unwrap()[0],
        compensated_de_casteljau(&coeffs, 0.75)
    );
}

#[test]
fn subsegment_is_accurate_at_degree_100() {
    // A degree-100 curve with O(1) control points; compare a subsegment's control points with
    // exact rational subdivision.
    let pts: Vec<Vector<1>> = (0..=100)
        .map(|i| Vector::from([((i * 7919 % 101) as f64 / 50.0) - 1.0]))
        .collect();
    let c = BezierCurve::new(pts.clone()).unwrap();
    // Dyadic parameters keep the exact rationals small (and the test fast).
    let (a, b) = (0.3125, 0.5625);
    let sub = c.subsegment(a, b).unwrap();
    let exact_pts: Vec<Q> = pts.iter().map(|p| q(p[0])).collect();
    for k in 0..=8 {
        let s = f64::from(k) / 8.0;
        let t = a + s * (b - a);
        let exact = exact_eval(&exact_pts, &q(t)).to_f64().unwrap();
        assert!((sub.eval(s).unwrap()[0] - exact).abs() < 1e-12, "s = {s}");
    }
}
