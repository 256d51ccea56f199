//! Accuracy beyond the peers: high-degree subdivision and compensated evaluation.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, Vector, Vector2, compensated_de_casteljau, de_casteljau};
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

/// Derivatives are formed from control-point differences, and the measures are scaled by
/// powers of two internally: a curve translated by 2³⁰ (exactly, dyadic coordinates) has the
/// same derivatives bit for bit, and one scaled by 2^±480 has the scaled curvature, arc length
/// and nearest parameter, even where |B'|³ or squared distances would leave the f64 range.
#[test]
fn derivatives_and_measures_do_not_depend_on_where_the_curve_sits() {
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1);
        ((state >> 40) % 129) as f64 / 64.0 - 1.0
    };
    for degree in 2..=7 {
        let pts: Vec<Vector2> = (0..=degree).map(|_| Vector2::new(next(), next())).collect();
        let c = BezierCurve::new(pts.clone()).unwrap();
        let offset = Vector2::new(2f64.powi(30), -(2f64.powi(30)));
        let moved = BezierCurve::new(pts.iter().map(|p| p + offset).collect()).unwrap();
        for &t in &[0.0, 0.3, 0.71, 1.0] {
            let (a, b) = (
                c.eval_derivatives(t, 3).unwrap(),
                moved.eval_derivatives(t, 3).unwrap(),
            );
            assert_eq!(a[1..], b[1..], "degree {degree}, t = {t}");
            if let (Ok(k), Ok(km)) = (c.curvature(t), moved.curvature(t)) {
                assert_eq!(k, km);
            }
        }
        for e in [480, -480] {
            let s = 2f64.powi(e);
            let scaled = BezierCurve::new(pts.iter().map(|p| p * s).collect()).unwrap();
            for &t in &[0.0, 0.3, 0.71, 1.0] {
                if let (Ok(k), Ok(ks)) = (c.curvature(t), scaled.curvature(t)) {
                    assert!(
                        (ks * s / k - 1.0).abs() < 1e-14,
                        "degree {degree}, 2^{e}: {k} vs {ks}"
                    );
                }
            }
            let (l, ls) = (
                c.arc_length(1e-12).unwrap(),
                scaled.arc_length(1e-12 * s).unwrap(),
            );
            assert!((ls / s / l - 1.0).abs() < 1e-14, "arc length {l} vs {ls}");
            let q = Vector2::new(0.25, 0.5);
            let (n, ns) = (c.nearest(&q).unwrap(), scaled.nearest(&(q * s)).unwrap());
            assert!((n.t - ns.t).abs() < 1e-12, "nearest t {} vs {}", n.t, ns.t);
        }
    }
}
