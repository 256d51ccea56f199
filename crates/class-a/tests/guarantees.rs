//! Guarantees on request: the sufficient condition cos θ ≥ (1 + σ)/(2σ) for monotone torsion
//! against the exact certificate, `SpatialRequirement::MonotoneTorsion`, and the verification of
//! planar results before `Ok`.
#![allow(clippy::unwrap_used, reason = "tests fail loudly")]

use bez_core::Vector2;
use bez_core::Vector3;
use class_a::{
    ClassAError, INTERPOLATION_TOLERANCE, Interpolation, Monotonicity, SpatialRequirement,
    TypicalPlanar, TypicalSpatial, class_a_curve, planar_feasibility, rotation,
    torsion_certificate,
};

mod common;
use common::Rng;

#[test]
fn the_condition_implies_monotone_torsion() {
    let mut rng = Rng(5);
    let (mut holds, mut fails, mut fails_not_monotone) = (0, 0, 0);
    for _ in 0..800 {
        let n = 3 + (rng.next() * 8.0) as usize;
        let s = rng.range(0.3, 3.0);
        let theta = rng.range(0.01, 1.4) * if rng.next() < 0.5 { -1.0 } else { 1.0 };
        let axis = rng.unit();
        let v0 = rng.unit();
        if axis.cross(&v0).norm() < 0.05 {
            continue;
        }
        let m = rotation(&axis, theta) * s;
        let c = class_a_curve(&Vector3::zeros(), &v0, &m, n).unwrap();
        let t = TypicalSpatial {
            b0: Vector3::zeros(),
            v0,
            length: 1.0,
            s,
            phi: 0.0,
            axis,
            theta,
            degree: n,
        };
        let verdict = torsion_certificate(&c).unwrap().verdict;
        assert!(!matches!(verdict, Monotonicity::Undecided { .. }));
        if t.torsion_condition() {
            holds += 1;
            assert!(t.class_a_margin() >= 0.0);
            assert!(
                !matches!(verdict, Monotonicity::NotMonotone { .. }),
                "n = {n}, s = {s}, θ = {theta}"
            );
        } else {
            fails += 1;
            fails_not_monotone += usize::from(matches!(verdict, Monotonicity::NotMonotone { .. }));
        }
    }
    // Not vacuous: the condition holds often, and most curves violating it are not monotone.
    assert!(
        holds > 200 && fails_not_monotone * 2 > fails,
        "{holds} {fails} {fails_not_monotone}"
    );
}

#[test]
fn monotone_torsion_is_returned_on_request() {
    let mut rng = Rng(8);
    let (mut asked, mut refused) = (0, 0);
    for _ in 0..60 {
        let n = 4 + (rng.next() * 6.0) as usize;
        let s = rng.range(1.05, 1.6);
        let theta = rng.range(0.05, (1.0 / s).acos());
        let axis = rng.unit();
        let v0 = rng.unit();
        if axis.cross(&v0).norm() < 0.2 {
            continue;
        }
        let c = class_a_curve(&Vector3::zeros(), &v0, &(rotation(&axis, theta) * s), n).unwrap();
        let p = c.points();
        let a = [p[0], p[1], p[n - 1], p[n]];
        let Ok(plain) = TypicalSpatial::from_points(&a, n) else {
            continue;
        };
        let plain_monotone = torsion_certificate(&plain.curve().unwrap())
            .unwrap()
            .is_monotone();
        match TypicalSpatial::solve(&a, n, SpatialRequirement::MonotoneTorsion) {
            Ok(t) => {
                asked += 1;
                assert!(t.class_a_margin() >= 0.0);
                assert!(
                    torsion_certificate(&t.curve().unwrap())
                        .unwrap()
                        .is_monotone()
                );
            }
            Err(ClassAError::NoMonotoneTorsion { class_a }) => {
                refused += 1;
                assert!(class_a >= 1 && !plain_monotone);
            }
            Err(e) => panic!("{e:?}"),
        }
    }
    assert!(asked > 20, "{asked} {refused}");
}

/// On feasible random planar inputs at n = 7..49, every `ToleranceNotMet` is the
/// representation limit: the achieved end-leg angle is within 4× of ε|bₙ| / |Δbₙ₋₁| (or
/// ε|b₁| / |Δb₀| at the start), which no f64 control polygon through the points can beat.
#[test]
fn planar_tolerance_failures_are_representation_limits() {
    let mut rng = Rng(11);
    let (mut feasible, mut failed) = (0, 0);
    for _ in 0..3000 {
        let n = 7 + (rng.next() * 43.0) as usize;
        let a0 = Vector2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let a1 = Vector2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let a2 = Vector2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let Ok(f) = planar_feasibility(&a0, &a1, &a2, n) else {
            continue;
        };
        if !f.is_feasible() {
            continue;
        }
        feasible += 1;
        match TypicalPlanar::from_points(&a0, &a1, &a2, n) {
            Ok(t) => {
                let c = t.curve().unwrap();
                let m = Interpolation::measure(c.points(), &a0, &(a1 - a0), &(a2 - a1), &a2);
                assert!(m.worst().1 <= INTERPOLATION_TOLERANCE);
            }
            Err(ClassAError::ToleranceNotMet {
                condition,
                achieved,
                ..
            }) => {
                failed += 1;
                let (_, _, e) = TypicalPlanar::generate(&a0, &a1, &a2, n, f64::INFINITY).unwrap();
                assert_eq!(e.worst(), (condition, achieved));
                let first = solved_first_leg(&a0, &a1, &a2, n, f.s, f.theta);
                let last = first * f.s.powi(n as i32 - 1);
                let limit = if condition == "end tangent" {
                    f64::EPSILON * a2.norm() / last
                } else {
                    f64::EPSILON * a0.norm().max(a1.norm()) / first
                };
                assert!(
                    achieved <= 4.0 * limit || last == 0.0,
                    "{condition} {achieved} vs {limit}"
                );
            }
            Err(e) => panic!("{e:?}"),
        }
    }
    assert!(feasible > 2500 && failed > 0, "{feasible} {failed}");
}

/// L = |α₂ − α₀| / |Σ zʲ|.
fn solved_first_leg(
    a0: &Vector2,
    _a1: &Vector2,
    a2: &Vector2,
    n: usize,
    s: f64,
    theta: f64,
) -> f64 {
    let (mut re, mut im, mut pr, mut pi) = (0.0, 0.0, 1.0, 0.0);
    let (zr, zi) = (s * theta.cos(), s * theta.sin());
    for _ in 0..n {
        re += pr;
        im += pi;
        (pr, pi) = (pr * zr - pi * zi, pr * zi + pi * zr);
    }
    (a2 - a0).norm() / (re * re + im * im).sqrt()
}

#[test]
fn a_vanishing_last_leg_is_an_error_not_ok() {
    // A tight turn at the end point: s ≪ 1, so at n = 49 the last leg L·s⁴⁸ is far below the
    // rounding of α₂ (it rounds to a zero leg, whose direction is undefined).
    let (a0, a1) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
    let a2 = a1 + Vector2::new(1.0f64.cos(), 1.0f64.sin()) * 0.01;
    assert!(TypicalPlanar::from_points(&a0, &a1, &a2, 3).is_ok());
    for n in [7, 49] {
        let e = TypicalPlanar::from_points(&a0, &a1, &a2, n).unwrap_err();
        assert!(
            matches!(
                e,
                ClassAError::ToleranceNotMet {
                    condition: "end tangent",
                    ..
                }
            ),
            "{e:?}"
        );
    }
    let (t, c, e) = TypicalPlanar::generate(&a0, &a1, &a2, 49, f64::INFINITY).unwrap();
    let p = c.points();
    assert!((p[49] - p[48]).norm() <= f64::EPSILON * a2.norm() && t.s() < 0.5);
    assert!(e.end_tangent > 1.0);
}
