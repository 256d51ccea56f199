//! The spatial solve on every branch θ = (ψ + 2πk)/(n − 1): points of random typical spatial
//! curves (total turns beyond π included) are solved back to their s, θ and axis.
#![allow(clippy::unwrap_used, reason = "tests fail loudly")]

use bez_core::Vector3;
use class_a::{TypicalSpatial, class_a_curve, rotation};

mod common;
use common::Rng;

/// A random typical spatial curve: (points α₀..α₃, n, s, θ·u).
fn random_curve(rng: &mut Rng) -> ([Vector3; 4], usize, f64, Vector3) {
    loop {
        let n = 3 + (rng.next() * 18.0) as usize;
        let theta = rng.range(0.05, 1.45) * if rng.next() < 0.5 { -1.0 } else { 1.0 };
        let s = (rng.range(-3.0, 3.0) / (n - 1) as f64).exp();
        let axis = rng.unit();
        let v0 = rng.unit();
        if axis.cross(&v0).norm() < 0.2 {
            continue;
        }
        let m = rotation(&axis, theta) * s;
        let b0 = Vector3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 0.0);
        let c = class_a_curve(&b0, &(v0 * rng.range(0.2, 2.0)), &m, n).unwrap();
        let p = c.points();
        let a = [p[0], p[1], p[n - 1], p[n]];
        let (t0, t1) = ((a[1] - a[0]).normalize(), (a[3] - a[2]).normalize());
        if t0.cross(&t1).norm() < 1e-3 {
            continue;
        }
        return (a, n, s, axis * theta);
    }
}

fn margin(s: f64, theta: f64) -> f64 {
    let c = theta.cos();
    (s - 1.0)
        .min(s * c - 1.0)
        .max((1.0 / s - 1.0).min(c / s - 1.0))
}

#[test]
fn random_typical_curves_are_recovered_on_every_branch() {
    let mut rng = Rng(19);
    let (mut beyond_pi, mut class_a, mut missed_other) = (0, 0, 0);
    let total = 400;
    for _ in 0..total {
        let (a, n, s, rot) = random_curve(&mut rng);
        let theta = rot.norm();
        if theta * (n - 1) as f64 > std::f64::consts::PI {
            beyond_pi += 1;
        }
        let all = TypicalSpatial::candidates(&a, n).unwrap();
        let hit = all
            .iter()
            .find(|t| (t.axis * t.theta - rot).norm() <= 1e-9 && (t.s / s - 1.0).abs() <= 1e-9);
        let Some(hit) = hit else {
            // Only solutions that cannot be Class A may be missed (see the docs of `candidates`).
            assert!(
                margin(s, theta) < 0.0,
                "missed a Class A curve: n = {n}, s = {s}, θ = {theta}"
            );
            missed_other += 1;
            continue;
        };
        // The recovered parameters rebuild the curve through the same four points.
        let c = hit.curve().unwrap();
        let p = c.points();
        let scale = (a[3] - a[0]).norm();
        for (x, y) in [(p[0], a[0]), (p[1], a[1]), (p[n - 1], a[2]), (p[n], a[3])] {
            assert!((x - y).norm() <= 1e-9 * scale, "{}", (x - y).norm() / scale);
        }
        if margin(s, theta) >= 0.0 {
            class_a += 1;
            // The least-turning Class A solution: the generator or one turning less.
            let t = TypicalSpatial::from_points(&a, n).unwrap();
            assert!(t.class_a_margin() >= 0.0 && t.theta.abs() <= theta + 1e-9);
        }
    }
    assert!(
        beyond_pi > total / 2 && class_a > total / 4,
        "{beyond_pi} {class_a}"
    );
    assert!(missed_other * 100 <= total, "{missed_other} of {total}");
}

#[test]
fn a_total_turn_of_three_half_turns_is_solved() {
    // n = 12, θ = 0.35, s = 1.25 (Class A): the tangent turns by 3.85 rad about the axis;
    // θ = ψ/(n − 1) with ψ in (−π, π] alone gave `ChordUnreachable`.
    let axis = Vector3::new(0.2, -0.3, 1.0).normalize();
    let m = rotation(&axis, 0.35) * 1.25;
    let c = class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.2, 0.1), &m, 12).unwrap();
    let p = c.points();
    let t = TypicalSpatial::from_points(&[p[0], p[1], p[11], p[12]], 12).unwrap();
    assert!((t.axis * t.theta - axis * 0.35).norm() < 1e-10 && (t.s - 1.25).abs() < 1e-10);
}

#[test]
fn a_drag_is_followed_by_continuation() {
    let mut rng = Rng(4);
    let axis = Vector3::new(0.3, -0.2, 1.0).normalize();
    let m = rotation(&axis, 0.3) * 1.2;
    let c = class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.1, 0.2), &m, 9).unwrap();
    let p = c.points();
    let mut a = [p[0], p[1], p[8], p[9]];
    let mut t = TypicalSpatial::from_points(&a, 9).unwrap();
    let scale = (a[3] - a[0]).norm();
    for _ in 0..100 {
        let step = Vector3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        );
        a[3] += step * (0.01 * scale);
        let frame = t.edit(&a).unwrap();
        let next = frame.solution;
        assert_eq!(frame.curve, next.curve().unwrap());
        // The continued solution is one of the full search's, Class A, and close to the last.
        let all = TypicalSpatial::candidates(&a, 9).unwrap();
        assert!(all.iter().any(|c| {
            (c.axis * c.theta - next.axis * next.theta).norm() <= 1e-8
                && (c.s / next.s - 1.0).abs() <= 1e-8
        }));
        assert!(next.class_a_margin() >= 0.0);
        assert!((next.axis * next.theta - t.axis * t.theta).norm() < 0.1);
        let curve = next.curve().unwrap();
        let pts = curve.points();
        assert!((pts[9] - a[3]).norm() <= 1e-9 * scale);
        t = next;
    }
}

/// `solve` searches the branches by increasing turn and stops at the first that settles the
/// answer; the result must be the one a selection from the full candidate list gives.
#[test]
fn the_early_stop_returns_the_full_search_answer() {
    use class_a::{INTERPOLATION_TOLERANCE, Interpolation, SpatialRequirement};
    let mut rng = Rng(41);
    for _ in 0..120 {
        let (a, n, _, _) = random_curve(&mut rng);
        let all = TypicalSpatial::candidates(&a, n).unwrap();
        let mut class_a: Vec<&TypicalSpatial> =
            all.iter().filter(|t| t.class_a_margin() >= 0.0).collect();
        class_a.sort_by(|x, y| {
            x.theta
                .abs()
                .total_cmp(&y.theta.abs())
                .then(y.class_a_margin().total_cmp(&x.class_a_margin()))
        });
        for requirement in [
            SpatialRequirement::ClassA,
            SpatialRequirement::MonotoneTorsion,
        ] {
            let want = class_a.iter().find(|t| {
                let c = t.curve().unwrap();
                let torsion_ok = requirement == SpatialRequirement::ClassA
                    || t.torsion_condition()
                    || class_a::torsion_certificate(&c).is_ok_and(|k| k.is_monotone());
                torsion_ok
                    && Interpolation::measure(
                        c.points(),
                        &a[0],
                        &(a[1] - a[0]),
                        &(a[3] - a[2]),
                        &a[3],
                    )
                    .within(INTERPOLATION_TOLERANCE)
                    .is_ok()
            });
            match (TypicalSpatial::solve(&a, n, requirement), want) {
                (Ok(got), Some(want)) => assert_eq!(&got, *want, "n = {n}"),
                (Err(_), None) => {}
                (got, want) => panic!("n = {n}: {got:?} vs {want:?}"),
            }
        }
    }
}
