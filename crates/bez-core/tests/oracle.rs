//! Exact-rational oracle: evaluation, split, elevation and derivative agree with exact
//! arithmetic on random curves of degrees 1..30.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, Vector2, proptest_support::control_points};
mod common;

use common::{Q, binom, q};
use num_traits::{FromPrimitive, One, ToPrimitive, Zero};
use proptest::prelude::*;

fn to_q(p: &[Vector2]) -> Vec<[Q; 2]> {
    p.iter().map(|v| [q(v.x()), q(v.y())]).collect()
}

fn casteljau_levels(p: &[[Q; 2]], t: &Q) -> (Vec<[Q; 2]>, Vec<[Q; 2]>) {
    let one = Q::one();
    let s = &one - t;
    let mut work = p.to_vec();
    let n = p.len() - 1;
    let mut left = vec![work[0].clone()];
    let mut right_rev = vec![work[n].clone()];
    for r in 1..=n {
        for i in 0..=n - r {
            let a = &work[i];
            let b = &work[i + 1];
            work[i] = [&s * &a[0] + t * &b[0], &s * &a[1] + t * &b[1]];
        }
        left.push(work[0].clone());
        right_rev.push(work[n - r].clone());
    }
    right_rev.reverse();
    (left, right_rev)
}

fn close(ours: &Vector2, exact: &[Q; 2], scale: f64) -> bool {
    let ex = [exact[0].to_f64().unwrap(), exact[1].to_f64().unwrap()];
    (ours.x() - ex[0]).abs() <= 1e-12 * scale && (ours.y() - ex[1]).abs() <= 1e-12 * scale
}

fn scale_of(p: &[Vector2]) -> f64 {
    p.iter().map(|v| v.abs().max()).fold(1.0, f64::max)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn eval_and_split_match_exact_arithmetic(
        pts in control_points::<2>(1..=30, 100.0),
        t in 0.0..=1.0f64,
    ) {
        let c = BezierCurve::new(pts.clone()).unwrap();
        let scale = scale_of(&pts);
        let (left, right) = casteljau_levels(&to_q(&pts), &q(t));
        prop_assert!(close(&c.eval(t).unwrap(), &left[left.len() - 1], scale));
        let mut many = Vec::new();
        c.eval_many(&[t], &mut many).unwrap();
        prop_assert!(close(&many[0], &left[left.len() - 1], scale));
        let (l, r) = c.split(t).unwrap();
        for (ours, ex) in l.points().iter().zip(&left) {
            prop_assert!(close(ours, ex, scale));
        }
        for (ours, ex) in r.points().iter().zip(&right) {
            prop_assert!(close(ours, ex, scale));
        }
    }

    #[test]
    fn elevation_and_derivative_match_exact_arithmetic(
        pts in control_points::<2>(1..=30, 100.0),
        r in 1usize..=5,
    ) {
        let c = BezierCurve::new(pts.clone()).unwrap();
        let scale = scale_of(&pts);
        let p = to_q(&pts);
        let n = pts.len() - 1;
        let e = c.elevate(r).unwrap();
        for (k, ours) in e.points().iter().enumerate() {
            let mut acc = [Q::zero(), Q::zero()];
            for (i, pi) in p.iter().enumerate() {
                if k >= i && k - i <= r {
                    let w = binom(n, i) * binom(r, k - i) / binom(n + r, k);
                    acc[0] += &w * &pi[0];
                    acc[1] += &w * &pi[1];
                }
            }
            prop_assert!(close(ours, &acc, scale));
        }
        let d = c.derivative().unwrap();
        let nq = Q::from_usize(n).unwrap();
        for (i, ours) in d.points().iter().enumerate() {
            let ex = [&nq * (&p[i + 1][0] - &p[i][0]), &nq * (&p[i + 1][1] - &p[i][1])];
            prop_assert!(close(ours, &ex, scale * n as f64));
        }
    }
}
