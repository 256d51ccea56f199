//! Wild inputs (NaN, ±∞, ±1e308, subnormals, −0.0, empty and one-point polygons, duplicate and
//! collinear control points, tolerances 0, negative, NaN and 1e-300, huge depths and sample
//! counts) to every public function and method give a `Result` or a value, never a panic; an
//! `Ok` never holds a NaN or an infinity; and every call returns within a time bound (work the
//! caller sizes is refused before it starts).
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::{Duration, Instant};

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{
    ADAPTIVE_BAND, Branch, Choice, FlatPoint, Flattener, HausdorffSampling, LOCAL_WANG_STEPS,
    Levels, MAX_FLATTEN_DEPTH, MAX_HAUSDORFF_WORK, MAX_STACK_DEGREE, MAX_WANG_SEGMENTS, Method,
    Objective, PAPER_LEVELS, PathPoint, Search, SplitRule, SubdivError, chord_deviation,
    curve_size, distance_to_chord_line, distance_to_segment, flatness, hull_area,
    max_chord_distance, measured_hausdorff, optimal_segment_count, wang_segment_count,
};
use proptest::prelude::*;

/// The longest one call may take in this (unoptimized) test build.
const CALL_LIMIT: Duration = Duration::from_secs(20);

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -10.0..10.0f64,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(1e308),
        1 => Just(-1e308),
        1 => Just(1e150),
        1 => Just(5e-324),
        1 => Just(-0.0),
        1 => Just(0.0),
        1 => Just(1.0),
    ]
}

fn wild_tolerance() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => 1e-4..1.0f64,
        1 => Just(0.0),
        1 => Just(-1.0),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(1e-300),
        1 => Just(1e-12),
        1 => Just(1e308),
    ]
}

/// Polygons of 0 to 9 points, with duplicates and collinear runs mixed in.
fn wild_points() -> impl Strategy<Value = Vec<Vector2>> {
    (
        proptest::collection::vec((wild(), wild()), 0..10),
        0usize..3,
    )
        .prop_map(|(xy, shape)| {
            let mut pts: Vec<Vector2> = xy.into_iter().map(|(x, y)| Vector2::new(x, y)).collect();
            match shape {
                // Duplicate every point.
                1 => pts = pts.into_iter().flat_map(|p| [p, p]).collect(),
                // Collinear: all on the x axis.
                2 => pts.iter_mut().for_each(|p| *p = Vector2::new(p.x(), 0.0)),
                _ => {}
            }
            pts
        })
}

fn methods() -> [Method; 7] {
    [
        Method::Fast,
        Method::Optimal,
        Method::LocalWang,
        Method::Halving,
        Method::PaperRule(SplitRule::Fixed),
        Method::PaperRule(SplitRule::flatness()),
        Method::PaperRule(SplitRule::Optimal {
            objective: Objective::HullArea,
            search: Search::Grid,
            levels: Levels::Adaptive,
        }),
    ]
}

/// Runs `f`, failing on a panic or on a call longer than [`CALL_LIMIT`].
fn bounded<T>(what: &str, f: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let out = catch_unwind(AssertUnwindSafe(f));
    assert!(out.is_ok(), "{what} panicked");
    let Ok(out) = out else { unreachable!() };
    let took = start.elapsed();
    assert!(took < CALL_LIMIT, "{what} took {took:?}");
    out
}

fn finite(p: &Vector2) -> bool {
    p.is_finite()
}

/// Every method of a `Flattener` on `c`: finite points in parameter order from B(0) to B(1),
/// as many as the count returned.
fn check_flattener(c: &BezierCurve<2>, tol: f64, depth: usize) {
    for method in methods() {
        let f = Flattener::new(tol)
            .with_method(method)
            .with_max_depth(depth);
        let mut pts: Vec<FlatPoint> = Vec::new();
        let result = bounded(&format!("{method:?} tol {tol} depth {depth}"), || {
            f.flatten(c, |p| pts.push(p))
        });
        if let Ok(n) = result {
            assert_eq!(pts.len(), n + 1, "{method:?}");
            assert!(pts.iter().all(|p| finite(&p.point) && p.t.is_finite()));
            assert!(pts.windows(2).all(|w| w[0].t <= w[1].t), "{method:?}");
            assert_eq!((pts[0].t, pts[n].t), (0.0, 1.0), "{method:?}");
        }
    }
    let f = Flattener::new(tol).with_max_depth(depth);
    let path: Vec<PathPoint> = Vec::new();
    let mut path = path;
    if bounded("flatten_path", || {
        f.flatten_path(&[c.clone(), c.clone()], |p| path.push(p))
    })
    .is_ok()
    {
        assert!(path.iter().all(|p| finite(&p.point) && p.curve < 2));
    }
    for pts in bounded("flatten_batch", || f.flatten_batch(std::slice::from_ref(c)))
        .into_iter()
        .flatten()
    {
        assert!(pts.iter().all(|p| finite(&p.point)));
    }
    if let Ok(pts) = bounded("flatten_to_vec", || f.flatten_to_vec(c)) {
        assert!(pts.iter().all(|p| finite(&p.point)));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn flattening_never_panics_or_runs_away(
        pts in wild_points(),
        tol in wild_tolerance(),
        depth in prop_oneof![Just(0usize), Just(5), Just(40), Just(MAX_FLATTEN_DEPTH), Just(usize::MAX)],
    ) {
        let Ok(c) = BezierCurve::new(pts) else { return Ok(()); };
        check_flattener(&c, tol, depth);
        if let Ok(n) = bounded("wang_segment_count", || wang_segment_count(&c, tol)) {
            prop_assert!(n >= 1);
        }
        if let Ok(n) = bounded("optimal_segment_count", || optimal_segment_count(&c, tol)) {
            prop_assert!(n.is_finite() && n >= 0.0);
        }
        prop_assert!(!curve_size(&c).is_nan());
    }

    #[test]
    fn measures_never_panic(pts in wild_points(), a in wild(), b in wild(), t in wild(), depth in 0usize..5) {
        let q = pts.first().copied().unwrap_or_else(Vector2::zeros);
        let (u, v) = (Vector2::new(a, b), Vector2::new(b, a));
        let _ = bounded("distance_to_segment", || distance_to_segment(&q, &u, &v));
        let _ = bounded("distance_to_chord_line", || distance_to_chord_line(&q, &u, &v));
        let _ = bounded("flatness", || flatness(&pts));
        let _ = bounded("hull_area", || hull_area(&pts));
        let _ = bounded("max_chord_distance", || max_chord_distance(&pts));
        for rule in [SplitRule::Fixed, SplitRule::flatness(), SplitRule::hull_area()] {
            for branch in [Branch::Searching, Branch::Settled] {
                if let Ok(Choice { t, .. }) = bounded("choose", || rule.choose(&pts, depth, branch)) {
                    prop_assert!(t.is_finite());
                }
            }
            let _ = rule.name();
        }
        let Ok(c) = BezierCurve::new(pts.clone()) else { return Ok(()); };
        if let Ok(d) = bounded("chord_deviation", || chord_deviation(&c, a, t)) {
            prop_assert!(d.is_finite());
        }
        let poly = [c.start(), c.end()];
        for sampling in [
            HausdorffSampling::default(),
            HausdorffSampling { curve_samples: 0, segment_samples: 0 },
            HausdorffSampling { curve_samples: usize::MAX, segment_samples: 3 },
            HausdorffSampling { curve_samples: 11, segment_samples: usize::MAX },
        ] {
            if let Ok(h) = bounded("measured_hausdorff", || measured_hausdorff(&c, &poly, sampling)) {
                prop_assert!(h.is_finite());
            }
        }
        let _ = bounded("measured_hausdorff (wild polyline)", || {
            measured_hausdorff(&c, &pts, HausdorffSampling { curve_samples: 101, segment_samples: 3 })
        });
    }
}

/// The inputs that ran long before their work was bounded: a high degree at a tolerance just
/// above the rounding floor (hundreds of millions of pieces for the subdividing methods), a
/// huge Hausdorff sampling, N* of a curve of degree 1024.
#[test]
fn worst_cases_are_refused_quickly() {
    let zigzag = |n: usize| {
        BezierCurve::new(
            (0..=n)
                .map(|i| Vector2::new(i as f64, if i % 2 == 0 { 0.0 } else { 1.0 }))
                .collect(),
        )
        .unwrap()
    };
    for n in [3, 12, 30] {
        let c = zigzag(n);
        // 16 ulps of 30 is about 1e-13.
        for tol in [1e-13, 1e-11, 1e-9] {
            check_flattener(&c, tol, MAX_FLATTEN_DEPTH);
        }
    }
    let big = zigzag(1024);
    let _ = bounded("optimal_segment_count at degree 1024", || {
        optimal_segment_count(&big, 1e-3)
    });
    let c = zigzag(3);
    let long: Vec<Vector2> = (0..1_000_000)
        .map(|i| Vector2::new(f64::from(i), 0.0))
        .collect();
    let r = bounded("measured_hausdorff of a long polyline", || {
        measured_hausdorff(&c, &long, HausdorffSampling::default())
    });
    assert!(r.is_err(), "{r:?}");
}

/// Constants and error values: the limits are what the docs say, and errors display.
#[test]
fn constants_and_errors() {
    assert_eq!(MAX_FLATTEN_DEPTH, 48);
    assert_eq!(MAX_WANG_SEGMENTS, 1 << 24);
    assert_eq!(LOCAL_WANG_STEPS, 16);
    assert_eq!(MAX_STACK_DEGREE, 64);
    assert_eq!(PAPER_LEVELS, 3);
    assert_eq!(MAX_HAUSDORFF_WORK, 2f64.powi(32));
    const { assert!(ADAPTIVE_BAND > 0.0 && ADAPTIVE_BAND < 0.5) };
    let e = SubdivError::InvalidTolerance { value: f64::NAN };
    assert!(!e.to_string().is_empty());
}

/// kurbo paths with wild coordinates and tolerances: points or an error, never a panic, and
/// every point finite.
#[cfg(feature = "kurbo")]
#[test]
fn kurbo_paths_never_panic() {
    use kurbo::{BezPath, Point};
    for x in [f64::NAN, f64::INFINITY, 1e300, 1e152, 0.5, -0.0] {
        for tolerance in [f64::NAN, 0.0, -1.0, 1e-300, 1e-3, 1e308] {
            let mut path = BezPath::new();
            path.move_to(Point::new(0.0, 0.0));
            path.curve_to(Point::new(x, 1.0), Point::new(2.0, x), Point::new(3.0, 0.0));
            path.close_path();
            let _ = Flattener::new(tolerance).flatten_bez_path(&path, |_, p| {
                assert!(p.point.is_finite() && p.t.is_finite());
            });
        }
    }
}

// Every public function and method of the crate is called above, but for the builders of the
// reproduction-only `FlattenOptions` and `split_objective`, which only the `paper` feature exports:
// paper-only: with_tolerance, with_rule, split_objective

bez_core::suite_completeness_tests!();
