//! The paper's properties 2.1–2.3 and the guarantees of the flattening.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::proptest_support::curve;
use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{
    Branch, FlattenOptions, Levels, Objective, Search, SplitRule, curve_size,
    distance_to_chord_line, flatten, split_objective,
};
use proptest::prelude::*;

fn exact(objective: Objective) -> SplitRule {
    SplitRule::Optimal {
        objective,
        search: Search::Exact,
        levels: Levels::First(1),
    }
}

fn rules() -> Vec<SplitRule> {
    vec![
        SplitRule::Fixed,
        SplitRule::flatness(),
        SplitRule::hull_area(),
        exact(Objective::Flatness),
        SplitRule::Optimal {
            objective: Objective::Flatness,
            search: Search::Grid,
            levels: Levels::Adaptive,
        },
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Property 2.1: for every quadratic the hull-optimal parameter is 0.5.
    #[test]
    fn property_2_1_quadratic_hull_optimum_is_one_half(
        p in proptest::array::uniform3((-10.0..10.0f64, -10.0..10.0f64)),
    ) {
        let pts: Vec<_> = p.iter().map(|&(x, y)| Vector2::new(x, y)).collect();
        prop_assume!(bez_subdiv::hull_area(&pts) > 1e-3);
        let c = exact(Objective::HullArea).choose(&pts, 0, Branch::Searching).unwrap();
        prop_assert!((c.t - 0.5).abs() < 1e-6, "t* = {}", c.t);
    }

    /// Property 2.3: a symmetric quadratic (P₁ on the perpendicular bisector of P₀P₂) has
    /// flatness-optimal parameter 0.5.
    #[test]
    fn property_2_3_symmetric_quadratic_flatness_optimum_is_one_half(w in 0.1..10.0f64, h in 0.1..10.0f64) {
        let pts = [Vector2::new(-w, 0.0), Vector2::new(0.0, h), Vector2::new(w, 0.0)];
        let c = exact(Objective::Flatness).choose(&pts, 0, Branch::Searching).unwrap();
        prop_assert!((c.t - 0.5).abs() < 1e-6, "t* = {}", c.t);
    }

    /// Property 2.2: for an axis-symmetric curve both objectives are symmetric about 0.5, so 0.5
    /// is an extremum (the one-sided values at 0.5 ± h agree).
    #[test]
    fn property_2_2_symmetric_curves_have_an_extremum_at_one_half(
        half in proptest::collection::vec((0.0..5.0f64, 0.1..5.0f64), 1..6),
        h in 0.01..0.3f64,
    ) {
        // Mirror the left half of the control polygon about the y axis.
        let mut pts: Vec<_> = half.iter().enumerate().map(|(i, &(x, y))| Vector2::new(-(i as f64) - 1.0 - x, y)).collect();
        pts.sort_by(|a, b| a.x().total_cmp(&b.x()));
        let mirror: Vec<_> = pts.iter().rev().map(|p| Vector2::new(-p.x(), p.y())).collect();
        pts.extend(mirror);
        for o in [Objective::Flatness, Objective::HullArea] {
            let a = split_objective(o, &pts, 0.5 - h);
            let b = split_objective(o, &pts, 0.5 + h);
            prop_assert!((a - b).abs() <= 1e-9 * a.abs().max(1.0));
        }
    }

    /// Wang's a-priori depth bounds the depth the fixed rule reaches.
    #[test]
    fn fixed_rule_depth_never_exceeds_wang_bound(c in curve::<2>(1..=30, 1.0), e in 1..7i32) {
        let eps = 10f64.powi(-e);
        let f = flatten(&c, &FlattenOptions::default().with_tolerance(eps)).unwrap();
        prop_assert!(f.stats.depth <= bez_subdiv::wang_depth(&c, eps), "{} > {}", f.stats.depth, bez_subdiv::wang_depth(&c, eps));
    }

    /// Every rule's pieces re-evaluate onto the original curve, tile [0, 1], and lie within
    /// ε · size of their chord lines (what eq. (3) guarantees by the convex hull property).
    #[test]
    fn pieces_reproduce_the_curve_within_tolerance(c in curve::<2>(2..=30, 1.0)) {
        let size = curve_size(&c);
        for rule in rules() {
            let options = FlattenOptions::default().with_tolerance(1e-3).with_rule(rule);
            let f = flatten(&c, &options).unwrap();
            prop_assert_eq!(f.pieces.first().unwrap().t0, 0.0);
            prop_assert_eq!(f.pieces.last().unwrap().t1, 1.0);
            prop_assert_eq!(f.stats.splits + 1, f.stats.pieces);
            for w in f.pieces.windows(2) {
                prop_assert_eq!(w[0].t1, w[1].t0);
                prop_assert_eq!(w[0].points.last(), w[1].points.first());
            }
            for piece in &f.pieces {
                let pc = BezierCurve::new(piece.points.clone()).unwrap();
                let (a, b) = (pc.start(), pc.end());
                for k in 0..=8 {
                    let s = f64::from(k) / 8.0;
                    let q = c.eval(piece.t0 + s * (piece.t1 - piece.t0)).unwrap();
                    prop_assert!((pc.eval(s).unwrap() - q).norm() <= 1e-9 * size.max(1.0));
                    prop_assert!(distance_to_chord_line(&q, &a, &b) <= 1e-3 * size * (1.0 + 1e-9) + 1e-12);
                }
            }
            prop_assert_eq!(f.polyline.len(), f.pieces.len() * c.degree() + 1);
        }
    }
}

#[test]
fn flatness_rule_splits_at_the_grid_optimum() {
    let pts = [
        Vector2::new(0.0, 0.0),
        Vector2::new(0.2, 3.0),
        Vector2::new(1.0, 3.0),
        Vector2::new(5.0, 0.0),
    ];
    let c = SplitRule::flatness()
        .choose(&pts, 0, Branch::Searching)
        .unwrap();
    // Brute force over the same grid.
    let best = (0..=12)
        .map(|k| 0.2 + 0.05 * f64::from(k))
        .min_by(|a, b| {
            split_objective(Objective::Flatness, &pts, *a).total_cmp(&split_objective(
                Objective::Flatness,
                &pts,
                *b,
            ))
        })
        .unwrap();
    assert_eq!(c.t, best);
    // The exact optimum is at least as good as the grid's.
    let e = exact(Objective::Flatness)
        .choose(&pts, 0, Branch::Searching)
        .unwrap();
    assert!(
        split_objective(Objective::Flatness, &pts, e.t)
            <= split_objective(Objective::Flatness, &pts, best) + 1e-15
    );
}
