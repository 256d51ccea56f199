//! Flattening does not depend on where a curve sits or on its units: every method gives the
//! same polyline, up to rounding, for a curve translated by 10⁹ or scaled by
//! 2^±498 (about 10^±150) with its tolerance.
#![allow(clippy::unwrap_used, reason = "tests fail loudly on unexpected errors")]

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{Flattener, Method};
use proptest::prelude::*;

const METHODS: [Method; 5] = [
    Method::Fast,
    Method::LocalWang,
    Method::Halving,
    Method::Optimal,
    Method::PaperRule(bez_subdiv::SplitRule::Fixed),
];

fn polyline(curve: &BezierCurve<2>, tolerance: f64, method: Method) -> Vec<(f64, Vector2)> {
    Flattener::new(tolerance)
        .with_method(method)
        .flatten_to_vec(curve)
        .unwrap()
        .into_iter()
        .map(|p| (p.t, p.point))
        .collect()
}

/// The largest distance from 65 samples of each piece of `curve` to its chord, relative to
/// the chord's end points `offset` away from the origin (so the test measures in the
/// coordinates near the curve, not at 10⁹).
fn sampled_deviation(curve: &BezierCurve<2>, line: &[(f64, Vector2)], offset: Vector2) -> f64 {
    let mut worst = 0.0f64;
    for w in line.windows(2) {
        let ((t0, a), (t1, b)) = (w[0], w[1]);
        let (a, b) = (a - offset, b - offset);
        for k in 0..=64 {
            let t = t0 + (t1 - t0) * f64::from(k) / 64.0;
            let p = curve.eval(t).unwrap() - offset;
            let ab = b - a;
            let s = if ab.norm_squared() > 0.0 {
                ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0)
            } else {
                0.0
            };
            worst = worst.max((p - (a + ab * s)).norm());
        }
    }
    worst
}

fn moved(curve: &BezierCurve<2>, f: impl Fn(Vector2) -> Vector2) -> BezierCurve<2> {
    BezierCurve::new(curve.points().iter().map(|&p| f(p)).collect()).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Scaling by a power of two is exact, so every method returns the scaled polyline: the
    /// same count, the same parameters up to rounding, every point scaled up to what that
    /// rounding of its parameter moves it. (`Flattener` rescales curves far from unit size by a
    /// power of two first, so the two runs compute at sizes a power of two apart and round
    /// differently: `Optimal`'s parameters were seen 1.0·10⁻¹² apart on a quintic at 2⁴⁹⁸,
    /// hence 10⁻¹¹.)
    #[test]
    fn scaling_by_powers_of_two_scales_the_polyline(
        curve in bez_core::proptest_support::curve::<2>(1..=7, 10.0),
        exponent in prop_oneof![Just(-498i32), Just(-60), Just(60), Just(498)],
    ) {
        let s = 2f64.powi(exponent);
        let tolerance = 1e-3 * 10.0;
        let scaled = moved(&curve, |p| p * s);
        // A bound on |B′|, n max|P_{i+1} − P_i|: a point at a parameter that rounding moved by
        // dt moves by at most that times dt.
        let n = (curve.points().len() - 1) as f64;
        let speed = n * curve
            .points()
            .windows(2)
            .map(|w| (w[1] - w[0]).norm())
            .fold(0.0, f64::max);
        for method in METHODS {
            let a = polyline(&curve, tolerance, method);
            let b = polyline(&scaled, tolerance * s, method);
            prop_assert_eq!(a.len(), b.len(), "{:?} at 2^{}", method, exponent);
            for ((t, p), (u, q)) in a.iter().zip(&b) {
                prop_assert!((t - u).abs() <= 1e-11, "{:?} at 2^{}: t = {} vs {}", method, exponent, t, u);
                let allowed = s * (1e-12 * 10.0 + speed * (t - u).abs());
                prop_assert!((*p * s - *q).norm() <= allowed, "{:?}: {:?} vs {:?}", method, p, q);
            }
        }
    }

    /// A translation by 10⁹ moves the coordinates' rounding to about 10⁻⁷: the counts stay
    /// within one segment (a count at a rounding boundary may flip), the methods with fixed
    /// parameters keep them, and every polyline stays within the tolerance (sampled).
    #[test]
    fn translation_moves_the_polyline(
        curve in bez_core::proptest_support::curve::<2>(1..=7, 10.0),
    ) {
        let offset = Vector2::new(1e9, -1e9);
        let tolerance = 1e-2;
        let far = moved(&curve, |p| p + offset);
        for method in METHODS {
            let a = polyline(&curve, tolerance, method);
            let b = polyline(&far, tolerance, method);
            prop_assert!(a.len().abs_diff(b.len()) <= 1, "{:?}: {} vs {} points", method, a.len(), b.len());
            if a.len() == b.len() && method != Method::Optimal {
                for ((t, _), (u, _)) in a.iter().zip(&b) {
                    prop_assert!((t - u).abs() <= 1e-9, "{:?}: t = {} vs {}", method, t, u);
                }
            }
            if matches!(method, Method::PaperRule(_)) {
                continue; // eq. (3) promises no distance (see `Method::PaperRule`)
            }
            let deviation = sampled_deviation(&far, &b, offset);
            prop_assert!(deviation <= tolerance * (1.0 + 1e-4), "{:?}: {} > {}", method, deviation, tolerance);
        }
    }
}
