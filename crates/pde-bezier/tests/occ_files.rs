//! Files written by Open CASCADE (committed in `tests/data/`, made by `cargo xtask cad-check`;
//! see the README there) are read with `read_step` / `read_iges`, and every surface returned
//! must agree with the surface our solver writes for the same case.
//!
//! Comparison: the degrees and control-point counts must be equal, the control nets agree point
//! by point, and the surfaces, with both knot ranges mapped onto [0, 1], agree at 21 x 21
//! parameters; every difference is taken relative to max(1, largest control coordinate). Open
//! CASCADE prints 12 significant digits in STEP and 9 decimals in IGES, so the bounds are 1e-11
//! (STEP) and 1e-8 (IGES); `cargo xtask cad-check` measured 5.9e-13 and 6.5e-10 at most. Open
//! CASCADE keeps the knots, the orientation and the control points of these surfaces, so the
//! parameter map is the identity.

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

use pde_bezier::{BSplineSurface, Method, cases, read_iges, read_step, solve};

/// Bound for files written by Open CASCADE's STEP writer (12 significant digits).
const STEP_TOLERANCE: f64 = 1e-11;
/// Bound for files written by Open CASCADE's IGES writer (9 decimals).
const IGES_TOLERANCE: f64 = 1e-8;

fn scale(s: &BSplineSurface) -> f64 {
    s.points
        .iter()
        .flat_map(|p| p.iter().map(|x| x.abs()))
        .fold(1.0_f64, f64::max)
}

/// The surface `cargo xtask cad-check` writes for `case`.
fn ours(case: &cases::Case) -> BSplineSurface {
    solve(&case.problem, &case.disc, Method::BernsteinLeastSquares)
        .unwrap()
        .spline
}

/// Fig. 5 (k = 3) on 3 x 2 patches with bidegree (5, 4), C¹ in v, as in `cargo xtask cad-check`.
fn enneper() -> BSplineSurface {
    let mut case = cases::enneper(3, 3, 2).unwrap();
    case.disc.degree_v = 4;
    case.disc.smoothness_v = 1;
    ours(&case)
}

/// Fig. 1's circle–sphere blend.
fn fig1() -> BSplineSurface {
    ours(&cases::circle_sphere_blend(1.0, 1.0).unwrap())
}

fn deviation(ours: &BSplineSurface, theirs: &BSplineSurface) -> f64 {
    let at = |k: &[f64], t: f64| {
        let (a, b) = (k[0], k[k.len() - 1]);
        a + (b - a) * t
    };
    let mut err = 0.0_f64;
    for i in 0..=20 {
        for j in 0..=20 {
            let (s, t) = (f64::from(i) / 20.0, f64::from(j) / 20.0);
            let p = ours
                .eval(at(&ours.knots_u, s), at(&ours.knots_v, t))
                .unwrap();
            let q = theirs
                .eval(at(&theirs.knots_u, s), at(&theirs.knots_v, t))
                .unwrap();
            for (x, y) in p.iter().zip(q.iter()) {
                err = err.max((x - y).abs() / scale(ours));
            }
        }
    }
    err
}

fn check(name: &str, ours: &BSplineSurface, read: &[BSplineSurface], tolerance: f64) {
    assert_eq!(read.len(), 1, "{name}: one surface expected");
    for theirs in read {
        assert_eq!(
            (theirs.degree_u, theirs.degree_v),
            (ours.degree_u, ours.degree_v)
        );
        assert_eq!(theirs.points.len(), ours.points.len());
        let net = ours
            .points
            .iter()
            .zip(&theirs.points)
            .flat_map(|(p, q)| p.iter().zip(q.iter()).map(|(x, y)| (x - y).abs()))
            .fold(0.0_f64, f64::max)
            / scale(ours);
        assert!(net <= tolerance, "{name}: control nets differ by {net:e}");
        let err = deviation(ours, theirs);
        assert!(err <= tolerance, "{name}: surfaces differ by {err:e}");
    }
}

#[test]
fn open_cascade_step_files_are_read() {
    check(
        "enneper",
        &enneper(),
        &read_step(include_str!("data/occ-enneper.stp")).unwrap(),
        STEP_TOLERANCE,
    );
    check(
        "fig1",
        &fig1(),
        &read_step(include_str!("data/occ-fig1.stp")).unwrap(),
        STEP_TOLERANCE,
    );
}

#[test]
fn open_cascade_iges_files_are_read() {
    check(
        "enneper",
        &enneper(),
        &read_iges(include_str!("data/occ-enneper.igs")).unwrap(),
        IGES_TOLERANCE,
    );
    check(
        "fig1",
        &fig1(),
        &read_iges(include_str!("data/occ-fig1.igs")).unwrap(),
        IGES_TOLERANCE,
    );
}
