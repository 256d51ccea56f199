//! The curve types of three paper crates go through bez-subdiv's flatteners by their common
//! trait, `bez_core::BezierForm`, and the polylines stay within tolerance of the curves.
//!
//! This lives in xtask because a paper crate never depends on another one.
#![allow(clippy::unwrap_used, reason = "test code unwraps known-good values")]

use bez_core::{BezierCurve, BezierForm, Vector2};
use bez_subdiv::{
    FlattenOptions, Flattener, HausdorffSampling, SplitRule, flatten, flatten_fixed_into,
    measured_hausdorff,
};
use class_a::{ClassACurve, TypicalPlanar, cases as class_a_cases};
use lambda_bezier::LambdaBezierCurve;
use subdiv_fit::SubdivCurve;

/// `Method::Halving`'s points, collected.
fn flatten_guaranteed<C: BezierForm<2> + ?Sized>(
    c: &C,
    tol: f64,
    depth: usize,
) -> Result<Vec<bez_subdiv::FlatPoint>, bez_subdiv::SubdivError> {
    Flattener::new(tol)
        .with_method(bez_subdiv::Method::Halving)
        .with_max_depth(depth)
        .flatten_to_vec(c)
}

/// `Method::LocalWang`'s points, collected.
fn flatten_local_wang<C: BezierForm<2> + ?Sized>(
    c: &C,
    tol: f64,
    depth: usize,
) -> Result<Vec<bez_subdiv::FlatPoint>, bez_subdiv::SubdivError> {
    Flattener::new(tol)
        .with_method(bez_subdiv::Method::LocalWang)
        .with_max_depth(depth)
        .flatten_to_vec(c)
}

/// `Method::Optimal`'s points, collected.
fn flatten_near_optimal<C: BezierForm<2> + ?Sized>(
    c: &C,
    tol: f64,
    depth: usize,
) -> Result<Vec<bez_subdiv::FlatPoint>, bez_subdiv::SubdivError> {
    Flattener::new(tol)
        .with_method(bez_subdiv::Method::Optimal)
        .with_max_depth(depth)
        .flatten_to_vec(c)
}

fn lambda_curve() -> LambdaBezierCurve<2> {
    let p = vec![
        Vector2::new(-1.0, 0.0),
        Vector2::new(-1.0, 1.2),
        Vector2::new(1.0, 1.2),
        Vector2::new(1.0, 0.0),
    ];
    LambdaBezierCurve::new(p, 0.56).unwrap()
}

fn class_a_curve() -> ClassACurve<2> {
    let a = class_a_cases::fig7_points();
    ClassACurve::try_from(&TypicalPlanar::from_points(&a[0], &a[1], &a[2], 6).unwrap()).unwrap()
}

fn subdiv_segment() -> subdiv_fit::Segment<2> {
    let polygon = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(2.0, -0.5),
        Vector2::new(3.0, 1.0),
        Vector2::new(1.5, 2.5),
    ];
    let curve = SubdivCurve::with_sharp(polygon, &[0], subdiv_fit::Closure::Closed).unwrap();
    curve.segment(1).unwrap()
}

/// Flattens `curve` with every entry point and measures each polyline against the curve.
fn flatten_all<C: BezierForm<2> + ?Sized>(curve: &C, tolerance: f64) {
    let sampling = HausdorffSampling::default();
    let hausdorff = |poly: &[Vector2]| measured_hausdorff(curve, poly, sampling).unwrap();
    let points = |p: Vec<bez_subdiv::FlatPoint>| p.into_iter().map(|q| q.point).collect::<Vec<_>>();
    for (name, poly) in [
        (
            "guaranteed",
            points(flatten_guaranteed(curve, tolerance, 40).unwrap()),
        ),
        (
            "local_wang",
            points(flatten_local_wang(curve, tolerance, 40).unwrap()),
        ),
        (
            "near_optimal",
            points(flatten_near_optimal(curve, tolerance, 40).unwrap()),
        ),
    ] {
        let h = hausdorff(&poly);
        assert!(h <= tolerance * (1.0 + 1e-9), "{name}: {h} > {tolerance}");
        assert!(
            poly.len() >= 3,
            "{name}: a curved arc needs more than one segment"
        );
        assert_eq!(poly[0], curve.start());
    }
    // The eq. (3) flatteners bound the control points' distance to each chord's line by
    // tolerance × the curve's size, which for these smooth arcs (no cusp, no loop) bounds the
    // distance to the polyline too.
    let size = bez_subdiv::curve_size(curve.as_bezier());
    let options = FlattenOptions::default()
        .with_rule(SplitRule::flatness())
        .with_tolerance(tolerance);
    let general = flatten(curve, &options).unwrap();
    let mut fixed = Vec::new();
    flatten_fixed_into(curve, tolerance, 40, &mut fixed).unwrap();
    for (name, poly) in [("flatten", &general.polyline), ("fixed", &fixed)] {
        let h = hausdorff(poly);
        assert!(h <= tolerance * size, "{name}: {h} > {}", tolerance * size);
    }
    // The same polyline as for the curve's Bézier form, bit for bit.
    let mut direct = Vec::new();
    flatten_fixed_into(curve.as_bezier(), tolerance, 40, &mut direct).unwrap();
    assert_eq!(fixed, direct);
}

#[test]
fn lambda_class_a_and_subdivision_curves_flatten_within_tolerance() {
    for tolerance in [1e-3, 1e-6] {
        flatten_all(&lambda_curve(), tolerance);
        flatten_all(&class_a_curve(), tolerance);
        flatten_all(&subdiv_segment(), tolerance);
    }
}

#[test]
fn mixed_curves_flatten_as_trait_objects_and_in_batches() {
    let (l, a, s) = (lambda_curve(), class_a_curve(), subdiv_segment());
    let mixed: [&dyn BezierForm<2>; 3] = [&l, &a, &s];
    for curve in mixed {
        flatten_all(curve, 1e-4);
    }
    let flattener = Flattener::new(1e-4).with_method(bez_subdiv::Method::Optimal);
    let batch = flattener.flatten_batch(&[l.clone(), l.with_lambda(-1.0).unwrap()]);
    assert_eq!(batch[0], flattener.flatten_to_vec(&l));
    let beziers: Vec<BezierCurve<2>> = mixed.iter().map(|c| c.as_bezier().clone()).collect();
    for (c, r) in mixed.iter().zip(flattener.flatten_batch(&beziers)) {
        assert_eq!(r, flattener.flatten_to_vec(*c));
    }
}
