//! Properties 1–6 of the λ-B basis and the curve properties of section 3, over degrees 2..15.
#![allow(
    clippy::unwrap_used,
    reason = "test support functions outside #[test] fns unwrap known-good values"
)]

use bez_core::{BezierForm, Vector, Vector2, Vector3, roots_in_unit_interval};
use lambda_bezier::{
    Continuity, LambdaBasis, LambdaBezierCurve, LambdaRange, continuity, corner_cut_ratio, join_c1,
    join_g1,
};
use proptest::prelude::*;

/// (n, λ) with λ anywhere in the exact valid interval of n.
fn basis() -> impl Strategy<Value = LambdaBasis> {
    (2usize..=15, 0.0..=1.0f64).prop_map(|(n, s)| {
        let r = LambdaRange::new(n).unwrap();
        let l = r.min() + s * (r.max() - r.min());
        LambdaBasis::new(n, l.clamp(r.min(), r.max())).unwrap()
    })
}

fn curve<const D: usize>() -> impl Strategy<Value = LambdaBezierCurve<D>> {
    basis().prop_flat_map(|b| {
        let n = b.n();
        prop::collection::vec(prop::array::uniform::<_, D>(-10.0..10.0f64), n + 1).prop_map(
            move |pts| {
                let pts = pts.into_iter().map(Vector::<D>::from).collect();
                LambdaBezierCurve::new(pts, b.lambda()).unwrap()
            },
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Property 1: non-negativity and partition of unity.
    #[test]
    fn nonnegative_and_partition_of_unity(b in basis(), t in 0.0..=1.0f64) {
        let mut row = vec![0.0; b.n() + 1];
        b.row(t, &mut row).unwrap();
        prop_assert!(row.iter().all(|&v| v >= -1e-15), "{row:?}");
        prop_assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-13);
    }

    /// Outside the interval some basis function is negative somewhere (checked on its Bernstein
    /// coefficients: the negative one sits at an end where it dominates).
    #[test]
    fn negative_just_outside(n in 2usize..=15, d in 1e-6..0.5f64, below in any::<bool>()) {
        let r = LambdaRange::new(n).unwrap();
        let l = if below { r.min() - d } else { r.max() + d };
        let b = LambdaBasis::new_unrestricted(n, l).unwrap();
        let mut min = f64::INFINITY;
        for k in 0..=n {
            let c = b.bernstein_coefficients(k).unwrap();
            // The linear factor of b_k at t = 0 and t = 1 has the signs of c[k] and c[k+1].
            min = min.min(c[k]).min(c[k + 1]);
        }
        prop_assert!(min < 0.0);
        prop_assert!(LambdaBasis::new(n, l).is_err());
    }

    /// Property 2: symmetry b_{i,n+1}(1 − t) = b_{n−i,n+1}(t).
    #[test]
    fn symmetry(b in basis(), t in 0.0..=1.0f64) {
        let n = b.n();
        for i in 0..=n {
            let lhs = b.eval(i, 1.0 - t).unwrap();
            let rhs = b.eval(n - i, t).unwrap();
            prop_assert!((lhs - rhs).abs() < 1e-14);
        }
    }

    /// Property 3 (eq. (4), as intended): b_{i}^{(j)}(0) = 0 for j < i and b_{i}^{(j)}(1) = 0 for
    /// j < n − i; b₀(0) = bₙ(1) = 1 (eq. (3)).
    #[test]
    fn endpoint_derivatives(b in basis()) {
        let n = b.n();
        prop_assert_eq!(b.eval(0, 0.0).unwrap(), 1.0);
        prop_assert_eq!(b.eval(n, 1.0).unwrap(), 1.0);
        for i in 0..=n {
            for j in 0..i {
                prop_assert_eq!(b.derivative(i, 0.0, j).unwrap(), 0.0);
            }
            for j in 0..n - i {
                prop_assert_eq!(b.derivative(i, 1.0, j).unwrap(), 0.0);
            }
        }
    }

    /// Property 4, the true part: each basis function has a single peak in t (it is
    /// t^k (1 − t)^{n−k} times a positive linear factor, hence log-concave). Checked on the roots
    /// of its derivative: at most one in the open interval.
    #[test]
    fn single_peak_in_t(b in basis()) {
        let n = b.n();
        for k in 0..=n {
            let c = b.bernstein_coefficients(k).unwrap();
            let d = bez_core::bernstein_derivative_coeffs(&c);
            let interior = roots_in_unit_interval(&d)
                .into_iter()
                .filter(|&t| t > 1e-9 && t < 1.0 - 1e-9)
                .count();
            prop_assert!(interior <= 1, "k = {k}: {interior} interior critical points");
        }
    }

    /// Eq. (5) holds for λ ∈ [−2/3, 1] and every n: the values are log-concave in the index
    /// (b_k² ≥ b_{k−1} b_{k+1}), hence unimodal. Proof in the paper page; it fails below −2/3 for
    /// n = 2 (tests/paper/exact.rs).
    #[test]
    fn log_concave_in_index_from_minus_two_thirds(n in 2usize..=15, s in 0.0..=1.0f64, t in 0.0..=1.0f64) {
        let l = -2.0 / 3.0 + s * (1.0 + 2.0 / 3.0);
        let b = LambdaBasis::new(n, l).unwrap();
        let mut row = vec![0.0; n + 1];
        b.row(t, &mut row).unwrap();
        for k in 1..n {
            let (lhs, rhs) = (row[k] * row[k], row[k - 1] * row[k + 1]);
            prop_assert!(lhs >= rhs - 1e-13 * (lhs + rhs), "k = {k}: {row:?}");
        }
        let mut falling = false;
        for w in row.windows(2) {
            if w[1] < w[0] - 1e-15 { falling = true; }
            else if w[1] > w[0] + 1e-15 { prop_assert!(!falling, "{row:?}"); }
        }
    }

    /// Property 6: λ = 0 gives the degree-n Bernstein basis.
    #[test]
    fn reduces_to_bernstein(n in 2usize..=15, t in 0.0..=1.0f64) {
        let b = LambdaBasis::new(n, 0.0).unwrap();
        for i in 0..=n {
            prop_assert!((b.eval(i, t).unwrap() - bez_core::bernstein(n, i, t)).abs() < 1e-14);
        }
    }

    /// The closed Bernstein form and the recurrence (2) agree; the row agrees with single values.
    #[test]
    fn closed_form_row_and_recurrence_agree(b in basis(), t in 0.0..=1.0f64) {
        let rec = b.eval_by_recurrence(t).unwrap();
        let mut row = vec![0.0; b.n() + 1];
        b.row(t, &mut row).unwrap();
        for (k, (r, w)) in rec.iter().zip(&row).enumerate() {
            prop_assert!((r - w).abs() < 1e-13);
            prop_assert!((b.eval(k, t).unwrap() - w).abs() < 1e-14);
        }
    }

    /// Derivatives of the basis against central differences of the values.
    #[test]
    fn derivative_matches_difference(b in basis(), t in 0.05..=0.95f64) {
        let h = 1e-6;
        for k in 0..=b.n() {
            let fd = (b.eval(k, t + h).unwrap() - b.eval(k, t - h).unwrap()) / (2.0 * h);
            prop_assert!((b.derivative(k, t, 1).unwrap() - fd).abs() < 1e-5 * (1.0 + fd.abs()));
        }
    }

    /// Corner cutting: in the valid interval every αⱼ ∈ [0, 1], so Qⱼ lies on the edge Pⱼ₋₁Pⱼ
    /// (the sound proof of variation diminishing, Property 5 of the curve).
    #[test]
    fn ratios_are_corner_cuts(b in basis()) {
        for j in 0..=b.n() + 1 {
            let a = corner_cut_ratio(b.n(), j, b.lambda());
            prop_assert!((-1e-15..=1.0 + 1e-15).contains(&a));
        }
    }

    /// The Bézier conversion agrees with direct basis evaluation (recurrence (2)) to 1e-13.
    #[test]
    fn conversion_matches_basis_sum(c in curve::<3>(), t in 0.0..=1.0f64) {
        let b = LambdaBasis::new(c.n(), c.lambda()).unwrap();
        let w = b.eval_by_recurrence(t).unwrap();
        let direct: Vector3 = c.points().iter().zip(&w).map(|(p, w)| p * *w).sum();
        let scale = 1.0 + c.points().iter().map(|p| p.norm()).fold(0.0, f64::max);
        prop_assert!((c.eval(t).unwrap() - direct).norm() <= 1e-13 * scale);
    }

    /// Curve property 1: endpoints and end tangents (n + λ)(P₁ − P₀), (n + λ)(Pₙ − Pₙ₋₁).
    #[test]
    fn endpoints_and_tangents(c in curve::<2>()) {
        let p = c.points();
        let n = c.n();
        prop_assert_eq!(c.eval(0.0).unwrap(), p[0]);
        prop_assert_eq!(c.eval(1.0).unwrap(), p[n]);
        let k = n as f64 + c.lambda();
        let d = c.derivative().unwrap();
        prop_assert!((d.start() - k * (p[1] - p[0])).norm() < 1e-11);
        prop_assert!((d.end() - k * (p[n] - p[n - 1])).norm() < 1e-11);
    }

    /// Curve property 2: convex hull, via support functions in random directions.
    #[test]
    fn convex_hull(c in curve::<2>(), t in 0.0..=1.0f64, angle in 0.0..std::f64::consts::TAU) {
        let v = Vector2::new(angle.cos(), angle.sin());
        let x = c.eval(t).unwrap();
        let support = c.points().iter().map(|p| p.dot(&v)).fold(f64::NEG_INFINITY, f64::max);
        prop_assert!(x.dot(&v) <= support + 1e-12);
    }

    /// Curve property 3: reversing the control points reverses the curve.
    #[test]
    fn reversal(c in curve::<3>(), t in 0.0..=1.0f64) {
        let mut p = c.points().to_vec();
        p.reverse();
        let r = LambdaBezierCurve::new(p, c.lambda()).unwrap();
        prop_assert!((r.eval(1.0 - t).unwrap() - c.eval(t).unwrap()).norm() < 1e-12);
        prop_assert!((c.reverse().eval(t).unwrap() - r.eval(t).unwrap()).norm() < 1e-12);
    }

    /// Curve property 4: affine invariance.
    #[test]
    fn affine_invariance(c in curve::<2>(), t in 0.0..=1.0f64, a in -2.0..2.0f64, s in 0.1..3.0f64) {
        let f = |p: &Vector2| Vector2::new(s * p.x() + a * p.y() + 1.5, -a * p.x() + p.y() - 0.5);
        let mapped = c.map_points(f).unwrap();
        prop_assert!((mapped.eval(t).unwrap() - f(&c.eval(t).unwrap())).norm() < 1e-11);
    }

    /// join_g1 and join_c1 give the continuity they promise, for any degrees and λ.
    #[test]
    fn joins_are_g1_and_c1(a in curve::<2>(), b in curve::<2>()) {
        prop_assume!(a.end_tangent().norm() > 1e-6);
        prop_assume!((b.points()[1] - b.points()[0]).norm() > 1e-6);
        prop_assume!(b.n() as f64 + b.lambda() > 1e-6);
        let g = join_g1(&a, &b).unwrap();
        prop_assert!(continuity(&a, &g, 1e-9) >= Continuity::G1);
        let c = join_c1(&a, &b).unwrap();
        prop_assert_eq!(continuity(&a, &c, 1e-9), Continuity::C1);
        let (da, dc) = (a.derivative().unwrap().end(), c.derivative().unwrap().start());
        prop_assert!((da - dc).norm() <= 1e-9 * (1.0 + da.norm()));
    }
}
