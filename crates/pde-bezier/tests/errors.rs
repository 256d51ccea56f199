//! Every typed error of the public API.

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

use bez_core::{BezierCurve, BezierSurface, Vector3};
use pde_bezier::{
    Discretization, Method, Operator, PdeError, Problem, Side, SideCurve, Term, solve,
};

fn line(a: Vector3, b: Vector3) -> SideCurve {
    SideCurve::Bezier(BezierCurve::new(vec![a, b]).unwrap())
}

fn unit_square_problem() -> Problem {
    let x = BezierSurface::from_flat(
        1,
        1,
        vec![
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(0.0, 1.0, 0.0),
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(1.0, 1.0, 0.0),
        ],
    )
    .unwrap();
    Problem::manufactured(Operator::second_order(1.0, 1.0).unwrap(), &x).unwrap()
}

#[test]
fn operator_rejects_odd_and_high_orders() {
    for (du, dv) in [(1, 0), (2, 1), (4, 4), (0, 0)] {
        let err = Operator::new(vec![Term { coeff: 1.0, du, dv }]).unwrap_err();
        assert!(
            matches!(err, PdeError::UnsupportedOrder { .. }),
            "{du} {dv}"
        );
    }
    assert_eq!(Operator::new(vec![]).unwrap_err(), PdeError::EmptyOperator);
    assert!(matches!(
        Operator::second_order(f64::NAN, 1.0),
        Err(PdeError::NonFinite { .. })
    ));
}

#[test]
fn corner_mismatch_is_reported() {
    let mut p = unit_square_problem();
    p.v0 = Side::Fixed(vec![line(
        Vector3::new(0.0, 0.0, 0.5),
        Vector3::new(1.0, 0.0, 0.0),
    )]);
    let err = solve(
        &p,
        &Discretization::single(3, 3),
        Method::BernsteinLeastSquares,
    )
    .unwrap_err();
    assert!(
        matches!(err, PdeError::CornerMismatch { i: 0, j: 0, .. }),
        "{err}"
    );
}

#[test]
fn wrong_side_data_count_is_reported() {
    let mut p = unit_square_problem();
    p.operator = Operator::bloor_wilson(1.0).unwrap();
    let err = solve(&p, &Discretization::single(5, 5), Method::Galerkin).unwrap_err();
    assert!(matches!(
        err,
        PdeError::SideDataCount {
            expected: 2,
            given: 1,
            ..
        }
    ));
}

#[test]
fn degree_too_low_for_the_boundary_rows() {
    let x = BezierSurface::from_flat(1, 1, vec![Vector3::zeros(); 4]).unwrap();
    let p = Problem::manufactured(Operator::bloor_wilson(1.0).unwrap(), &x).unwrap();
    let err = solve(
        &p,
        &Discretization::single(2, 5),
        Method::BernsteinLeastSquares,
    )
    .unwrap_err();
    assert!(
        matches!(err, PdeError::DegreeTooLow { direction: "u", .. }),
        "{err}"
    );
}

#[test]
fn low_continuity_is_rejected() {
    let x = BezierSurface::from_flat(1, 1, vec![Vector3::zeros(); 4]).unwrap();
    let p = Problem::manufactured(Operator::bloor_wilson(1.0).unwrap(), &x).unwrap();
    let disc = Discretization {
        degree_u: 5,
        degree_v: 5,
        patches_u: 2,
        patches_v: 1,
        smoothness_u: 2,
        smoothness_v: 0,
    };
    let err = solve(&p, &disc, Method::BernsteinLeastSquares).unwrap_err();
    assert!(matches!(err, PdeError::Smoothness { min: 3, .. }), "{err}");
    let disc = Discretization {
        smoothness_u: 5,
        ..disc
    };
    let err = solve(&p, &disc, Method::BernsteinLeastSquares).unwrap_err();
    assert!(matches!(err, PdeError::Smoothness { .. }), "{err}");
}

#[test]
fn underdetermined_problem_is_reported_as_undetermined() {
    // Only u = 0 fixed, everything else free: Laplace's residual vanishes on many surfaces.
    let mut p = unit_square_problem();
    p.u1 = Side::Free;
    p.v0 = Side::Free;
    p.v1 = Side::Free;
    for method in Method::ALL {
        let err = solve(&p, &Discretization::single(4, 4), method).unwrap_err();
        assert!(
            matches!(err, PdeError::Undetermined { .. }),
            "{method:?}: {err}"
        );
    }
}

#[test]
fn periodic_mismatch_and_piece_count() {
    let mut p = unit_square_problem();
    p.v0 = Side::Periodic;
    let err = solve(&p, &Discretization::single(4, 4), Method::Galerkin).unwrap_err();
    assert_eq!(err, PdeError::PeriodicMismatch { side: "v=0" });
    let mut p = unit_square_problem();
    p.u0 = Side::Fixed(vec![SideCurve::Pieces(vec![
        BezierCurve::new(vec![Vector3::zeros(), Vector3::new(0.0, 1.0, 0.0)]).unwrap(),
    ])]);
    let disc = Discretization {
        patches_v: 2,
        smoothness_v: 1,
        ..Discretization::single(4, 4)
    };
    let err = solve(&p, &disc, Method::Galerkin).unwrap_err();
    assert!(
        matches!(
            err,
            PdeError::PieceCount {
                given: 1,
                expected: 2,
                ..
            }
        ),
        "{err}"
    );
    let disc = Discretization {
        patches_u: 0,
        ..Discretization::single(4, 4)
    };
    assert!(matches!(
        solve(&p, &disc, Method::Galerkin),
        Err(PdeError::NoPatches { .. })
    ));
}

#[test]
fn sampled_data_needs_samples_and_jets() {
    let mut p = unit_square_problem();
    p.u0 = Side::Fixed(vec![SideCurve::Sampled {
        values: vec![Vector3::zeros(); 3],
        start_jet: vec![Vector3::zeros()],
        end_jet: vec![Vector3::new(0.0, 1.0, 0.0)],
    }]);
    let err = solve(&p, &Discretization::single(5, 5), Method::Galerkin).unwrap_err();
    assert!(
        matches!(
            err,
            PdeError::TooFewSamples {
                what: "samples",
                ..
            }
        ),
        "{err}"
    );
    p.u0 = Side::Fixed(vec![SideCurve::Sampled {
        values: vec![Vector3::zeros(); 30],
        start_jet: vec![],
        end_jet: vec![],
    }]);
    let err = solve(&p, &Discretization::single(5, 5), Method::Galerkin).unwrap_err();
    assert!(
        matches!(
            err,
            PdeError::TooFewSamples {
                what: "end derivatives",
                ..
            }
        ),
        "{err}"
    );
    p.u0 = Side::Fixed(vec![SideCurve::Sampled {
        values: vec![Vector3::new(f64::NAN, 0.0, 0.0); 30],
        start_jet: vec![Vector3::zeros()],
        end_jet: vec![Vector3::new(0.0, 1.0, 0.0)],
    }]);
    let err = solve(&p, &Discretization::single(5, 5), Method::Galerkin).unwrap_err();
    assert!(matches!(err, PdeError::NonFinite { .. }), "{err}");
}

#[test]
fn grid_eval_rejects_out_of_range() {
    let p = unit_square_problem();
    let sol = solve(&p, &Discretization::single(3, 3), Method::Collocation).unwrap();
    assert!(matches!(
        sol.surface.eval(1.5, 0.0),
        Err(PdeError::ParameterOutOfRange { .. })
    ));
    assert!(sol.surface.patch(1, 0).is_none());
}

#[test]
fn non_elliptic_operators_are_refused_before_solving() {
    let mut p = unit_square_problem();
    for op in [
        Operator::second_order(1.0, -1.0).unwrap(),
        Operator::new(vec![Term {
            coeff: 1.0,
            du: 1,
            dv: 1,
        }])
        .unwrap(),
    ] {
        p.operator = op;
        for method in Method::ALL {
            let err = solve(&p, &Discretization::single(4, 4), method).unwrap_err();
            assert!(matches!(err, PdeError::NotElliptic { .. }), "{err}");
        }
    }
}

#[test]
fn sizes_over_the_limits_are_refused_before_allocating() {
    let p = unit_square_problem();
    let huge_degree = Discretization::single(1 << 40, 1 << 40);
    let err = solve(&p, &huge_degree, Method::Galerkin).unwrap_err();
    assert_eq!(
        err,
        PdeError::TooLarge {
            what: "degree in u",
            value: 1 << 40,
            limit: pde_bezier::MAX_SOLVE_DEGREE
        }
    );
    let huge_grid = Discretization {
        patches_u: 1_000_000_000,
        patches_v: 1_000_000_000,
        smoothness_u: 1,
        smoothness_v: 1,
        ..Discretization::single(3, 3)
    };
    let err = solve(&p, &huge_grid, Method::Galerkin).unwrap_err();
    assert!(
        matches!(
            err,
            PdeError::TooLarge {
                what: "the number of patches",
                ..
            }
        ),
        "{err}"
    );
    let long_strip = Discretization {
        patches_u: 1,
        patches_v: 1 << 15,
        smoothness_v: 1,
        ..Discretization::single(5, 5)
    };
    let err = solve(&p, &long_strip, Method::Galerkin).unwrap_err();
    assert!(matches!(err, PdeError::TooLarge { .. }), "{err}");
}

#[test]
fn operator_scale_does_not_change_the_solution() {
    // L = c(∂uu + 2∂vv) for c = 1, 1e300, 1e-300: the same surface, no "undetermined".
    let base = unit_square_problem();
    let reference = solve(&base, &Discretization::single(4, 4), Method::Galerkin).unwrap();
    for c in [1e300, 1e-300] {
        let mut p = base.clone();
        p.operator = Operator::second_order(c, 2.0 * c).unwrap();
        for method in Method::ALL {
            let sol = solve(&p, &Discretization::single(4, 4), method).unwrap();
            for (a, b) in sol.surface.patches()[0]
                .points()
                .iter()
                .zip(reference.surface.patches()[0].points())
            {
                assert!((*a - *b).norm() < 1e-12, "{c} {method:?}");
            }
            assert!(sol.objective.is_finite() && sol.condition.is_finite());
        }
    }
}

#[test]
fn high_degree_bezier_side_data_is_converted_exactly_or_named_too_large() {
    // A degree-20 Bézier side of a planar patch: converted exactly by blossoming.
    let mut p = unit_square_problem();
    let pts: Vec<Vector3> = (0..=20)
        .map(|i| Vector3::new(0.0, i as f64 / 20.0, 0.0))
        .collect();
    p.u0 = Side::Fixed(vec![SideCurve::Bezier(BezierCurve::new(pts).unwrap())]);
    let sol = solve(&p, &Discretization::single(20, 20), Method::Collocation);
    match sol {
        Ok(sol) => assert!(sol.boundary_fit_error < 1e-14, "{}", sol.boundary_fit_error),
        Err(e) => assert!(matches!(e, PdeError::IllConditioned { .. }), "{e}"),
    }
    // Degree 40 asks for degree 40 patches: over the limit, and the error says so.
    let pts: Vec<Vector3> = (0..=40)
        .map(|i| Vector3::new(0.0, i as f64 / 40.0, 0.0))
        .collect();
    p.u0 = Side::Fixed(vec![SideCurve::Bezier(BezierCurve::new(pts).unwrap())]);
    let (n, m) = p.default_degrees();
    let err = solve(&p, &Discretization::single(n, m), Method::Galerkin).unwrap_err();
    assert!(matches!(err, PdeError::TooLarge { value: 40, .. }), "{err}");
}

#[test]
fn high_degree_dirichlet_problem_is_ill_conditioned_not_undetermined() {
    // One patch of degree 20, all four sides fixed: well posed. Σb² and ∫∫R² (QR, Gauss–
    // Legendre root of the Gram matrix) solve it; the Bernstein-basis Galerkin matrix is
    // numerically singular, which is conditioning, not missing boundary data.
    let p = unit_square_problem();
    let disc = Discretization::single(20, 20);
    for method in [Method::BernsteinLeastSquares, Method::IntegralLeastSquares] {
        let sol = solve(&p, &disc, method).unwrap();
        let err = sol
            .surface
            .error_norms(|u, v| Vector3::new(u, v, 0.0), 10)
            .unwrap();
        assert!(err.max < 1e-9, "{method:?}: {}", err.max);
        assert!(sol.condition > 1.0 && sol.condition < 1e13);
    }
    match solve(&p, &disc, Method::Galerkin) {
        Err(PdeError::IllConditioned {
            condition, limit, ..
        }) => assert!(condition > limit, "{condition}"),
        other => panic!("{other:?}"),
    }
}
