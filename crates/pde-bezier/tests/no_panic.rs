//! Random (including NaN, infinite, huge and out-of-contract) inputs to every public
//! function and method give `Result`s or values, never panics or hangs, and an `Ok` never
//! holds a NaN or an infinity.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

mod common;

use std::time::{Duration, Instant};

use bez_core::{BezierCurve, BezierSurface, Vector3};
use common::random_surface;
use pde_bezier::{
    Assembly, BSplineSurface, CONDITION_LIMIT, DENSE_LEAST_SQUARES_UNKNOWNS, DENSE_SQUARE_UNKNOWNS,
    DENSE_SYMMETRIC_UNKNOWNS, Discretization, ErrorNorms, MAX_COEFFICIENTS, MAX_DENSE_ENTRIES,
    MAX_ERROR_GRID, MAX_JET, MAX_LOCAL_ENTRIES, MAX_PATCHES, MAX_SOLVE_DEGREE, Method, Operator,
    PatchGrid, PdeError, Problem, Side, SideCurve, Solution, Storage, Term, apply_operator,
    read_iges, read_step, side_of, solve, write_iges, write_step,
};
use proptest::prelude::*;

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -10.0..10.0f64,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(1e300),
        1 => Just(-1e300),
        1 => Just(1e-300),
        1 => Just(0.0),
        1 => Just(1.0),
    ]
}

fn wild_size() -> impl Strategy<Value = usize> {
    prop_oneof![
        6 => 0usize..6,
        1 => Just(7usize),
        1 => Just(MAX_SOLVE_DEGREE + 1),
        1 => Just(1usize << 20),
        1 => Just(1usize << 40),
        1 => Just(usize::MAX),
    ]
}

fn wild_operator() -> impl Strategy<Value = Result<Operator, PdeError>> {
    proptest::collection::vec((wild(), 0usize..8, 0usize..8), 0..4).prop_map(|terms| {
        Operator::new(
            terms
                .into_iter()
                .map(|(coeff, du, dv)| Term { coeff, du, dv })
                .collect(),
        )
    })
}

fn wild_side(x: &BezierSurface<3>, side: usize, half: usize, pick: u8) -> Side {
    match pick % 4 {
        0 => Side::Free,
        1 => Side::Periodic,
        _ => side_of(x, side, half).unwrap_or(Side::Free),
    }
}

fn assert_finite_solution(sol: &Solution) {
    assert!(sol.objective.is_finite() && sol.residual_bound.is_finite());
    assert!(sol.condition.is_finite() && sol.condition >= 1.0 - 1e-12);
    assert!(sol.boundary_fit_error.is_finite());
    for p in sol.surface.patches() {
        assert!(p.points().iter().all(|q| q.iter().all(|c| c.is_finite())));
    }
    assert!(
        sol.spline
            .points
            .iter()
            .all(|q| q.iter().all(|c| c.is_finite()))
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn operators_never_panic(op in wild_operator(), a in wild(), b in wild(), xi in wild(), eta in wild()) {
        if let Ok(op) = op {
            let _ = op.principal_symbol(xi, eta);
            let _ = op.check_elliptic();
            prop_assert!(op.order() <= 6 && !op.terms().is_empty());
        }
        if let Ok(op) = Operator::second_order(a, b) {
            let _ = op.check_elliptic();
        }
        let _ = Operator::bloor_wilson(a);
    }

    #[test]
    fn solves_never_panic_and_stay_bounded(
        degree_u in wild_size(), degree_v in wild_size(),
        patches_u in wild_size(), patches_v in wild_size(),
        smoothness_u in wild_size(), smoothness_v in wild_size(),
        sides in proptest::array::uniform4(0u8..4),
        which in 0usize..4,
        scale in wild(),
        seed in 0u64..1000,
    ) {
        let x = random_surface(2, 3, seed);
        let op = match which {
            0 => Operator::second_order(1.0, 2.0),
            1 => Operator::bloor_wilson(0.7),
            2 => Operator::second_order(scale, scale),
            _ => Operator::second_order(1.0, -1.0),
        };
        let Ok(op) = op else { return Ok(()) };
        let Ok(mut problem) = Problem::manufactured(op, &x) else { return Ok(()) };
        let half = problem.operator.order() / 2;
        problem.u0 = wild_side(&x, 0, half, sides[0]);
        problem.u1 = wild_side(&x, 1, half, sides[1]);
        problem.v0 = wild_side(&x, 2, half, sides[2]);
        problem.v1 = wild_side(&x, 3, half, sides[3]);
        let _ = problem.default_degrees();
        let disc = Discretization { degree_u, degree_v, patches_u, patches_v, smoothness_u, smoothness_v };
        let start = Instant::now();
        match Assembly::new(&problem, &disc) {
            Ok(assembly) => {
                let _ = (assembly.unknowns(), assembly.order());
                for method in Method::ALL {
                    let _ = method.name();
                    if let Ok(sol) = assembly.solve(method) {
                        assert_finite_solution(&sol);
                    }
                    // Forced storage, only where a dense matrix stays small.
                    let storages: &[Storage] = if assembly.unknowns() <= 4 * DENSE_SQUARE_UNKNOWNS {
                        &[Storage::Dense, Storage::Sparse]
                    } else {
                        &[Storage::Sparse]
                    };
                    for &storage in storages {
                        if let Ok(sol) = assembly.solve_with(method, storage) {
                            assert_finite_solution(&sol);
                        }
                    }
                }
            }
            Err(e) => {
                let _ = e.to_string();
            }
        }
        let _ = solve(&problem, &Discretization::single(3, 3), Method::Galerkin);
        prop_assert!(start.elapsed() < Duration::from_secs(20), "{disc:?}");
    }

    #[test]
    fn grids_splines_and_files_never_panic(
        u in wild(), v in wild(), tau in wild_size(), seed in 0u64..1000,
        knot in wild(), degree in wild_size(), text in "[ -~\n]{0,200}",
        count in wild_size(), jet in wild_size(), side in wild_size(),
    ) {
        let x = random_surface(3, 2, seed);
        let problem = Problem::manufactured(Operator::second_order(1.0, 1.0).unwrap(), &x).unwrap();
        let sol = solve(&problem, &Discretization::single(3, 3), Method::Collocation).unwrap();
        let grid: &PatchGrid = &sol.surface;
        let _ = (grid.patches_u(), grid.patches_v(), grid.patch(usize::MAX, 0));
        if let Ok(p) = grid.eval(u, v) {
            prop_assert!(p.iter().all(|c| c.is_finite()));
        }
        let exact = |a: f64, b: f64| Vector3::new(a * u, b * v, 0.0);
        if let Ok(ErrorNorms { rms, max, .. }) = grid.error_norms(exact, tau.min(MAX_ERROR_GRID + 1)) {
            prop_assert!(rms.is_finite() && max.is_finite());
        }
        prop_assert!(grid.error_norms(exact, usize::MAX).is_err());
        let mut spline: BSplineSurface = sol.spline.clone();
        let _ = (spline.count_u(), spline.count_v());
        if let Ok(p) = spline.eval(u, v) {
            prop_assert!(p.iter().all(|c| c.is_finite()));
        }
        spline.knots_u[1] = knot;
        spline.degree_v = degree;
        let _ = spline.validate();
        let _ = spline.eval(u, v);
        let mut step = Vec::new();
        let _ = write_step(&spline, "wild", &mut step);
        let mut iges = Vec::new();
        let _ = write_iges(&spline, "wild", &mut iges);
        let _ = read_step(&text);
        let _ = read_iges(&text);
        let _ = read_step(std::str::from_utf8(&step).unwrap_or(""));
        let _ = read_iges(std::str::from_utf8(&iges).unwrap_or(""));
        let curve = SideCurve::from_function(count, jet, |t, _| Vector3::new(t, u, v));
        if let Ok(c) = &curve {
            let _ = c.degree();
        }
        let _ = side_of(&x, side, count);
        if let Ok(op) = Operator::second_order(u, v) {
            let _ = apply_operator(&op, &x);
        }
        let _ = SideCurve::Bezier(BezierCurve::new(vec![Vector3::new(u, v, 0.0); 2]).unwrap_or_else(|_| BezierCurve::new(vec![Vector3::zeros(); 2]).unwrap())).degree();
    }
}

#[test]
fn sizes_above_the_limits_are_errors() {
    assert!(matches!(
        SideCurve::from_function(usize::MAX, 1, |_, _| Vector3::zeros()),
        Err(PdeError::TooLarge { .. })
    ));
    assert!(matches!(
        SideCurve::from_function(10, MAX_JET + 1, |_, _| Vector3::zeros()),
        Err(PdeError::TooLarge { .. })
    ));
    let x = random_surface(2, 2, 1);
    assert!(matches!(
        side_of(&x, 0, usize::MAX),
        Err(PdeError::TooLarge { .. })
    ));
    let p = Problem::manufactured(Operator::second_order(1.0, 1.0).unwrap(), &x).unwrap();
    for disc in [
        Discretization::single(MAX_SOLVE_DEGREE + 1, 2),
        Discretization {
            patches_u: MAX_PATCHES + 1,
            smoothness_u: 1,
            ..Discretization::single(2, 2)
        },
        Discretization {
            patches_u: 300,
            patches_v: 200,
            smoothness_u: 1,
            smoothness_v: 1,
            ..Discretization::single(8, 8)
        },
    ] {
        let err = Assembly::new(&p, &disc).unwrap_err();
        assert!(matches!(err, PdeError::TooLarge { .. }), "{disc:?}: {err}");
    }
    // A forced dense solve of 96² unknowns would need 85 million entries.
    let assembly = Assembly::new(
        &p,
        &Discretization {
            patches_u: 24,
            patches_v: 24,
            smoothness_u: 1,
            smoothness_v: 1,
            ..Discretization::single(5, 5)
        },
    )
    .unwrap();
    assert_eq!(assembly.unknowns(), 96 * 96);
    match assembly.solve_with(Method::Galerkin, Storage::Dense) {
        Err(PdeError::TooLarge { value, limit, .. }) => {
            assert_eq!((value, limit), (96usize.pow(4), MAX_DENSE_ENTRIES));
        }
        other => panic!("{other:?}"),
    }
    const {
        assert!(MAX_COEFFICIENTS > 0 && MAX_LOCAL_ENTRIES > 0 && CONDITION_LIMIT > 1.0);
        assert!(MAX_DENSE_ENTRIES > DENSE_SQUARE_UNKNOWNS * DENSE_SQUARE_UNKNOWNS);
        assert!(DENSE_SYMMETRIC_UNKNOWNS > 0 && DENSE_LEAST_SQUARES_UNKNOWNS > 0);
    };
}

/// Deserialization validates like the constructors.
#[cfg(feature = "serde")]
#[test]
fn invalid_json_is_refused() {
    for bad in [
        r#"{"terms":[]}"#,
        r#"{"terms":[{"coeff":1.0,"du":1,"dv":0}]}"#,
        r#"{"terms":[{"coeff":1.0,"du":8,"dv":0}]}"#,
    ] {
        assert!(serde_json::from_str::<Operator>(bad).is_err(), "{bad}");
    }
    let ok: Operator = serde_json::from_str(r#"{"terms":[{"coeff":1.0,"du":2,"dv":0}]}"#).unwrap();
    assert_eq!(ok.order(), 2);
    let x = random_surface(2, 2, 3);
    let problem = Problem::manufactured(Operator::second_order(1.0, 1.0).unwrap(), &x).unwrap();
    let sol = solve(&problem, &Discretization::single(2, 2), Method::Galerkin).unwrap();
    let json = serde_json::to_value(&sol.surface).unwrap();
    let back: PatchGrid = serde_json::from_value(json.clone()).unwrap();
    assert_eq!(back, sol.surface);
    for (key, value) in [
        ("patches_u", serde_json::json!(0)),
        ("patches_v", serde_json::json!(5)),
        ("patches", serde_json::json!([])),
    ] {
        let mut bad = json.clone();
        bad[key] = value;
        assert!(serde_json::from_value::<PatchGrid>(bad).is_err(), "{key}");
    }
    // A solution round-trips, and one whose measures no solve gives, or whose spline is
    // invalid, is refused.
    let sj = serde_json::to_value(&sol).unwrap();
    assert_eq!(serde_json::from_value::<Solution>(sj.clone()).unwrap(), sol);
    for (key, value) in [
        ("condition", serde_json::json!(-1.0)),
        ("objective", serde_json::json!(null)),
        ("residual_bound", serde_json::json!(-0.5)),
    ] {
        let mut bad = sj.clone();
        bad[key] = value;
        assert!(serde_json::from_value::<Solution>(bad).is_err(), "{key}");
    }
    let mut bad = sj.clone();
    bad["spline"]["degree_u"] = serde_json::json!(0);
    assert!(serde_json::from_value::<Solution>(bad).is_err(), "spline");
    // A problem with an invalid operator inside is refused too.
    let mut pj = serde_json::to_value(&problem).unwrap();
    pj["operator"]["terms"] = serde_json::json!([{"coeff": 1.0, "du": 3, "dv": 0}]);
    assert!(serde_json::from_value::<Problem>(pj).is_err());
}

bez_core::suite_completeness_tests!();
