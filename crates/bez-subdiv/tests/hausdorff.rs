//! The guaranteed flattening is within tolerance in true Hausdorff distance, measured, on random
//! curves and on cusps and loops; eq. (3) alone is not.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::proptest_support::curve;
use bez_core::{BezierCurve, Vector2};
mod common;

use common::hausdorff;

use bez_subdiv::{FlattenOptions, flatten, optimal_segment_count};
use proptest::prelude::*;

/// `Method::Halving`'s points, collected.
fn flatten_guaranteed(
    c: &BezierCurve<2>,
    tol: f64,
    depth: usize,
) -> Result<Vec<bez_subdiv::FlatPoint>, bez_subdiv::SubdivError> {
    bez_subdiv::Flattener::new(tol)
        .with_method(bez_subdiv::Method::Halving)
        .with_max_depth(depth)
        .flatten_to_vec(c)
}

/// `Method::Optimal`'s points, collected.
fn flatten_near_optimal(
    c: &BezierCurve<2>,
    tol: f64,
    depth: usize,
) -> Result<Vec<bez_subdiv::FlatPoint>, bez_subdiv::SubdivError> {
    bez_subdiv::Flattener::new(tol)
        .with_method(bez_subdiv::Method::Optimal)
        .with_max_depth(depth)
        .flatten_to_vec(c)
}

fn cusp() -> BezierCurve<2> {
    bez_subdiv::cases::cusp().unwrap()
}

fn looped() -> BezierCurve<2> {
    bez_subdiv::cases::looped().unwrap()
}

#[test]
fn near_optimal_count_approaches_the_lower_bound_on_a_circle_arc() {
    // Quarter circle (cubic approximation, radius 1): N* = (π/2) / √(8 tol).
    let k = 4.0 * (2f64.sqrt() - 1.0) / 3.0;
    let c = BezierCurve::new(vec![
        Vector2::new(1.0, 0.0),
        Vector2::new(1.0, k),
        Vector2::new(k, 1.0),
        Vector2::new(0.0, 1.0),
    ])
    .unwrap();
    let tol = 1e-5;
    let n_star = optimal_segment_count(&c, tol).unwrap();
    let expected = std::f64::consts::FRAC_PI_2 / (8.0 * tol).sqrt();
    assert!(
        (n_star / expected - 1.0).abs() < 0.01,
        "{n_star} vs {expected}"
    );
    let pts = flatten_near_optimal(&c, tol, 40).unwrap();
    let segments = (pts.len() - 1) as f64;
    assert!(
        segments <= 1.15 * n_star.ceil(),
        "{segments} vs N* = {n_star}"
    );
    let poly: Vec<_> = pts.iter().map(|p| p.point).collect();
    assert!(hausdorff(&c, &poly) <= tol * (1.0 + 1e-9));
    let guaranteed = flatten_guaranteed(&c, tol, 40).unwrap();
    assert!(guaranteed.len() > pts.len());
}

#[test]
fn cusp_and_loop_are_within_tolerance() {
    for c in [cusp(), looped()] {
        for tol in [1e-2, 1e-3] {
            let pts = flatten_guaranteed(&c, tol, 40).unwrap();
            let poly: Vec<_> = pts.iter().map(|p| p.point).collect();
            assert!(hausdorff(&c, &poly) <= tol * (1.0 + 1e-9), "tol {tol}");
            let near: Vec<_> = flatten_near_optimal(&c, tol, 40)
                .unwrap()
                .iter()
                .map(|p| p.point)
                .collect();
            assert!(hausdorff(&c, &near) <= tol * (1.0 + 1e-9), "tol {tol}");
            for p in &pts {
                assert!((c.eval(p.t).unwrap() - p.point).norm() < 1e-12);
            }
        }
    }
}

#[test]
fn eq3_polyline_can_be_far_from_the_curve_when_it_folds_back() {
    // A quadratic that runs out to x = 4/3 and back to x = 1 along the x axis: every control
    // point is on the chord *line*, so eq. (3) accepts it as one piece, yet the chord [0, 1]
    // misses the stretch beyond x = 1 (Hausdorff distance 1/3, size 2: 17 % instead of 1e-5).
    let c = BezierCurve::new(vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(2.0, 0.0),
        Vector2::new(1.0, 0.0),
    ])
    .unwrap();
    let f = flatten(&c, &FlattenOptions::default()).unwrap();
    assert_eq!(f.stats.pieces, 1);
    let chord = [c.start(), c.end()];
    assert!((hausdorff(&c, &chord) - 1.0 / 3.0).abs() < 1e-6);
    let tol = 1e-5 * bez_subdiv::curve_size(&c);
    let poly: Vec<_> = flatten_guaranteed(&c, tol, 40)
        .unwrap()
        .iter()
        .map(|p| p.point)
        .collect();
    assert!(hausdorff(&c, &poly) <= tol * (1.0 + 1e-9));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    #[test]
    fn random_curves_are_within_tolerance(c in curve::<2>(2..=30, 1.0)) {
        let tol = 2e-3;
        let pts = flatten_guaranteed(&c, tol, 40).unwrap();
        let poly: Vec<_> = pts.iter().map(|p| p.point).collect();
        prop_assert!(hausdorff(&c, &poly) <= tol * (1.0 + 1e-9));
        prop_assert!(pts.windows(2).all(|w| w[0].t < w[1].t));
        let near = flatten_near_optimal(&c, tol, 40).unwrap();
        let poly: Vec<_> = near.iter().map(|p| p.point).collect();
        prop_assert!(hausdorff(&c, &poly) <= tol * (1.0 + 1e-9));
    }
}
