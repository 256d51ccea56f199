//! The allocation-free fixed-rule path gives exactly the general path's polyline and counts.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::proptest_support::curve;
use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{FlattenOptions, SplitRule, SubdivError, flatten, flatten_fixed_into};
use proptest::prelude::*;

/// The fast path's result in the shape of the general path's.
fn fast(
    c: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
) -> Result<(Vec<Vector2>, bez_subdiv::FlattenStats), SubdivError> {
    // A dirty, reused buffer: the function must clear it.
    let mut polyline = vec![Vector2::new(9.0, 9.0); 3];
    let stats = flatten_fixed_into(c, tolerance, max_depth, &mut polyline)?;
    Ok((polyline, stats))
}

fn general(
    c: &BezierCurve<2>,
    tolerance: f64,
    max_depth: usize,
) -> Result<(Vec<Vector2>, bez_subdiv::FlattenStats), SubdivError> {
    let options = FlattenOptions::default()
        .with_tolerance(tolerance)
        .with_rule(SplitRule::Fixed)
        .with_max_depth(max_depth);
    flatten(c, &options).map(|f| (f.polyline, f.stats))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Bit-for-bit equal points and equal counts on random curves of degree 1..30 (arrays for
    /// degree ≤ 3, the flat buffer above), tolerances 1e-1..1e-6, and depth caps that are
    /// sometimes hit (then both fail with the same error).
    #[test]
    fn fast_path_equals_general_path(
        c in curve::<2>(1..=30, 10.0),
        exponent in 1.0..6.0f64,
        max_depth in prop_oneof![Just(40usize), 3..12usize],
    ) {
        let tolerance = 10f64.powf(-exponent);
        prop_assert_eq!(fast(&c, tolerance, max_depth), general(&c, tolerance, max_depth));
    }
}

#[test]
fn fast_path_on_collapsed_and_degenerate_input() {
    let dot = BezierCurve::new(vec![Vector2::new(1.0, 1.0); 4]).unwrap();
    assert_eq!(fast(&dot, 1e-5, 40), general(&dot, 1e-5, 40));
    assert_eq!(fast(&dot, 1e-5, 40).unwrap().0.len(), 4);
    // A closed cubic (P₀ = P₃): distances to P₀.
    let closed = BezierCurve::new(vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(3.0, 1.0),
        Vector2::new(-1.0, 2.0),
        Vector2::new(0.0, 0.0),
    ])
    .unwrap();
    assert_eq!(fast(&closed, 1e-4, 40), general(&closed, 1e-4, 40));
    let point = BezierCurve::new(vec![Vector2::new(1.0, 2.0)]).unwrap();
    assert_eq!(
        fast(&point, 1e-5, 40),
        Err(SubdivError::TooFewPoints { got: 1 })
    );
    let line = BezierCurve::new(vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0)]).unwrap();
    for bad in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            fast(&line, bad, 40),
            Err(SubdivError::InvalidTolerance { .. })
        ));
    }
}
