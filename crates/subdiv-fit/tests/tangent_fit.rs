//! Tangent joints in the fit (`fit_with_joints`): outlines whose curvature jumps where they stay
//! tangent-continuous, measured against the exact outline.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use std::f64::consts::PI;

use subdiv_fit::{
    Closure, Corner, Fit, FitOptions, Joints, Reduction, SMOOTH_JOINT_TURN, SubdivCurve,
    SubdivFitError, TANGENT_JUMP, Vector2, VertexKind, fit, fit_with_joints,
    fit_with_known_corners, point_polyline_distance,
};

/// A piece of an exact outline: a line segment or a circular arc (centre, radius, start angle,
/// signed sweep).
#[derive(Clone, Copy)]
enum Piece {
    Line(Vector2, Vector2),
    Arc(Vector2, f64, f64, f64),
}

impl Piece {
    fn at(self, s: f64) -> Vector2 {
        match self {
            Piece::Line(a, b) => a + (b - a) * s,
            Piece::Arc(c, r, a0, sweep) => {
                let a = a0 + sweep * s;
                c + Vector2::new(r * a.cos(), r * a.sin())
            }
        }
    }

    fn length(self) -> f64 {
        match self {
            Piece::Line(a, b) => (b - a).norm(),
            Piece::Arc(_, r, _, sweep) => r * sweep.abs(),
        }
    }

    /// Exact distance from `p`.
    fn distance(self, p: Vector2) -> f64 {
        match self {
            Piece::Line(a, b) => {
                let d = b - a;
                let t = ((p - a).dot(&d) / d.dot(&d)).clamp(0.0, 1.0);
                (p - (a + d * t)).norm()
            }
            Piece::Arc(c, r, a0, sweep) => {
                let q = p - c;
                // The angle of p from the arc's start, in the sweep's direction, in [0, 2π).
                let rel = (sweep.signum() * (q[1].atan2(q[0]) - a0)).rem_euclid(2.0 * PI);
                if rel <= sweep.abs() {
                    (q.norm() - r).abs()
                } else {
                    (p - self.at(0.0)).norm().min((p - self.at(1.0)).norm())
                }
            }
        }
    }
}

/// Samples about every `h` along the pieces (each piece's start kept), with the data index of
/// every piece's start; open outlines get their last point too.
fn sample(pieces: &[Piece], h: f64, closed: bool) -> (Vec<Vector2>, Vec<usize>) {
    let mut data = Vec::new();
    let mut starts = Vec::new();
    for p in pieces {
        starts.push(data.len());
        let m = (p.length() / h).ceil() as usize;
        data.extend((0..m).map(|i| p.at(i as f64 / m as f64)));
    }
    if !closed {
        data.push(pieces[pieces.len() - 1].at(1.0));
    }
    (data, starts)
}

fn outline_distance(pieces: &[Piece], p: Vector2) -> f64 {
    pieces
        .iter()
        .map(|q| q.distance(p))
        .fold(f64::INFINITY, f64::min)
}

/// The two-sided distance between a curve and the exact outline: dense curve samples against
/// the outline, dense outline samples against the curve's dense polyline.
fn error_to_outline(curve: &SubdivCurve<2>, pieces: &[Piece]) -> f64 {
    let segs = curve.segment_count();
    let per = 200;
    let poly: Vec<Vector2> = (0..=segs * per)
        .map(|i| curve.eval(i as f64 / per as f64).unwrap())
        .collect();
    let c2o = poly
        .iter()
        .map(|&p| outline_distance(pieces, p))
        .fold(0.0, f64::max);
    let o2c = pieces
        .iter()
        .flat_map(|&q| (0..=2000).map(move |i| q.at(i as f64 / 2000.0)))
        .map(|p| point_polyline_distance(&p, &poly))
        .fold(0.0, f64::max);
    c2o.max(o2c)
}

/// The one-sided unit tangents and curvatures at every tangent vertex of `curve`, with the
/// joint's position.
fn joints_of(curve: &SubdivCurve<2>) -> Vec<(Vector2, Vector2, Vector2, f64, f64)> {
    let kinds = curve.kinds();
    let segs = curve.segment_count();
    let curvature =
        |d: &subdiv_fit::CurvePoint<2>| d.first.perp(&d.second) / d.first.norm().powi(3);
    let mut out = Vec::new();
    let mut segment = 0;
    for (v, &kind) in kinds.iter().enumerate() {
        if kind == VertexKind::Tangent {
            // Segment `segment` starts at the joint; the one before ends there.
            let before = curve
                .eval_segment_derivatives((segment + segs - 1) % segs, 1.0)
                .unwrap();
            let after = curve.eval_segment_derivatives(segment, 0.0).unwrap();
            assert!(
                (before.position - after.position).norm() < 1e-12,
                "vertex {v}"
            );
            out.push((
                after.position,
                before.first.normalize(),
                after.first.normalize(),
                curvature(&before),
                curvature(&after),
            ));
        } else if v + 1 < kinds.len() || curve.is_closed() {
            segment += 1;
        }
    }
    out
}

/// Checks a fit with tangent joints against the exact outline: within the tolerance, one
/// tangent vertex per joint with equal one-sided directions (G1), the joint's data point within
/// the tolerance of the joint.
fn check_tangent_fit(f: &Fit<2>, data: &[Vector2], pieces: &[Piece], tol: f64) {
    let error = error_to_outline(&f.curve, pieces);
    assert!(error <= tol, "error to the outline {error} > {tol}");
    let found = joints_of(&f.curve);
    assert_eq!(found.len(), f.tangents.len());
    assert_eq!(f.curve.points().len(), f.fitting.len() + f.tangents.len());
    assert_eq!(f.last().unwrap().control_points, f.curve.points().len());
    for ((position, t0, t1, _, _), &index) in found.iter().zip(&f.tangents) {
        assert!((t0 - t1).norm() < 1e-9, "directions {t0:?} and {t1:?}");
        assert!((position - data[index]).norm() <= tol);
    }
}

/// A rounded corner: a line of length 2 meeting an arc of radius 1 tangentially (the curvature
/// jumps from 0 to 1), sweeping `sweep` radians, and leaving it along a line of length 2.
fn rounded_corner(sweep: f64) -> Vec<Piece> {
    rounded_corner_of_radius(1.0, sweep)
}

/// [`rounded_corner`] with an arc of radius `r`.
fn rounded_corner_of_radius(r: f64, sweep: f64) -> Vec<Piece> {
    let end = Vector2::new(r * sweep.sin(), r * (1.0 - sweep.cos()));
    let direction = Vector2::new(sweep.cos(), sweep.sin());
    vec![
        Piece::Line(Vector2::new(-2.0, 0.0), Vector2::new(0.0, 0.0)),
        Piece::Arc(Vector2::new(0.0, r), r, -PI / 2.0, sweep),
        Piece::Line(end, end + direction * 2.0),
    ]
}

/// A stadium: two lines of length 2 and two half circles of radius 1, four tangent joints.
fn stadium() -> Vec<Piece> {
    vec![
        Piece::Line(Vector2::new(-1.0, -1.0), Vector2::new(1.0, -1.0)),
        Piece::Arc(Vector2::new(1.0, 0.0), 1.0, -PI / 2.0, PI),
        Piece::Line(Vector2::new(1.0, 1.0), Vector2::new(-1.0, 1.0)),
        Piece::Arc(Vector2::new(-1.0, 0.0), 1.0, PI / 2.0, PI),
    ]
}

#[test]
fn lines_meeting_an_arc_fit_with_tangent_joints_and_fewer_points() {
    for (sweep, tol) in [(PI / 2.0, 1e-3), (PI, 1e-3), (PI / 2.0, 1e-4)] {
        let pieces = rounded_corner(sweep);
        // Dense enough that the data polyline's sagitta (h² / 8) stays far below the tolerance.
        let (data, starts) = sample(&pieces, 0.002, false);
        let options = FitOptions::new(tol);
        let joints = Joints::new().with_tangents(&starts[1..]);
        let with = fit_with_joints(&data, Closure::Open, &joints, &options).unwrap();
        assert_eq!(with.tangents, starts[1..]);
        check_tangent_fit(&with, &data, &pieces, tol);
        // The curvature jumps at the joint: straight before, bent after.
        let (_, _, _, k0, k1) = joints_of(&with.curve)[0];
        assert!(k0.abs() < 0.01 && k1 > 0.5, "curvatures {k0}, {k1}");
        let without = fit(&data, Closure::Open, &options).unwrap();
        assert!(error_to_outline(&without.curve, &pieces) <= tol);
        let (a, b) = (with.curve.points().len(), without.curve.points().len());
        assert!(
            a < b,
            "sweep {sweep}, tol {tol}: {a} control points with the joint, {b} without"
        );
    }
}

#[test]
fn a_stadium_fits_with_four_tangent_joints_and_fewer_points() {
    let pieces = stadium();
    for tol in [1e-2, 1e-3] {
        let (data, starts) = sample(&pieces, 0.01, true);
        let options = FitOptions::new(tol);
        let joints = Joints::new().with_tangents(&starts);
        let with = fit_with_joints(&data, Closure::Closed, &joints, &options).unwrap();
        check_tangent_fit(&with, &data, &pieces, tol);
        let without = fit(&data, Closure::Closed, &options).unwrap();
        let (a, b) = (with.curve.points().len(), without.curve.points().len());
        assert!(
            a < b,
            "tol {tol}: {a} control points with the joints, {b} without"
        );
    }
}

/// Data sampled from a curve with a double knot: the fit with the joint given is within the
/// tolerance of that curve and G1 there, with a curvature jump like the curve's.
#[test]
fn a_double_knot_curve_is_reproduced() {
    let points: Vec<Vector2> = (0..12)
        .map(|i| {
            let t = i as f64 * 0.5;
            Vector2::new(t, (1.3 * t).sin() + 0.2 * t * t * (t > 2.6) as u8 as f64)
        })
        .collect();
    let mut kinds = vec![VertexKind::Regular; 12];
    kinds[5] = VertexKind::Tangent;
    let original = SubdivCurve::new(points, kinds, Closure::Open).unwrap();
    let (_, _, _, k0, k1) = joints_of(&original)[0];
    assert!(
        (k0 - k1).abs() > 0.1,
        "the original's curvature jumps: {k0}, {k1}"
    );
    // The joint is at the knot of vertex 5, the start of segment 5.
    // Dense enough that the data polyline's sagitta stays far below the tolerance.
    let per = 200;
    let segs = original.segment_count();
    let data: Vec<Vector2> = (0..=segs * per)
        .map(|i| original.eval(i as f64 / per as f64).unwrap())
        .collect();
    let joint = 5 * per;
    let dense: Vec<Vector2> = (0..=segs * 400)
        .map(|i| original.eval(i as f64 / 400.0).unwrap())
        .collect();
    let tol = 1e-4;
    let f = fit_with_joints(
        &data,
        Closure::Open,
        &Joints::new().with_tangents(&[joint]),
        &FitOptions::new(tol),
    )
    .unwrap();
    let samples: Vec<Vector2> = (0..=f.curve.segment_count() * 200)
        .map(|i| f.curve.eval(i as f64 / 200.0).unwrap())
        .collect();
    let c2o = samples
        .iter()
        .map(|p| point_polyline_distance(p, &dense))
        .fold(0.0, f64::max);
    let o2c = dense
        .iter()
        .map(|p| point_polyline_distance(p, &samples))
        .fold(0.0, f64::max);
    assert!(c2o <= tol && o2c <= tol, "{c2o}, {o2c}");
    let found = joints_of(&f.curve);
    assert_eq!(found.len(), 1);
    let (position, t0, t1, f0, f1) = found[0];
    assert!((t0 - t1).norm() < 1e-9);
    assert!((position - data[joint]).norm() <= tol);
    // The curvature jumps the same way, by at least half as much.
    assert!(
        (f1 - f0) / (k1 - k0) > 0.5,
        "jump {f0} → {f1}, the curve's {k0} → {k1}"
    );
}

#[test]
fn tangent_joints_without_room_are_refused() {
    let pieces = rounded_corner(2.0);
    let (data, starts) = sample(&pieces, 0.01, false);
    let n = data.len();
    let options = FitOptions::new(1e-3);
    let refused = |joints: Joints| {
        matches!(
            fit_with_joints(&data, Closure::Open, &joints, &options),
            Err(SubdivFitError::InvalidTangentJoint { .. })
        )
    };
    assert!(refused(Joints::new().with_tangents(&[n])));
    assert!(refused(Joints::new().with_tangents(&[0])));
    assert!(refused(Joints::new().with_tangents(&[n - 1])));
    assert!(refused(Joints::new().with_tangents(&[1])));
    assert!(refused(
        Joints::new()
            .with_corners(&[starts[1]])
            .with_tangents(&[starts[1]])
    ));
    assert!(refused(
        Joints::new()
            .with_corners(&[starts[1] + 2])
            .with_tangents(&[starts[1]])
    ));
    assert!(matches!(
        fit_with_joints(
            &data,
            Closure::Open,
            &Joints::new().with_corners(&[n]),
            &options
        ),
        Err(SubdivFitError::CornerOutOfRange { .. })
    ));
    // With room (three data points from a corner: two regular points fit between).
    let ok = Joints::new()
        .with_corners(&[starts[1] + 3])
        .with_tangents(&[starts[1]]);
    let f = fit_with_joints(&data, Closure::Open, &ok, &options).unwrap();
    assert_eq!(f.tangents, [starts[1]]);
}

/// Detection (`FitOptions::tangent_jump`) finds the joints of lines meeting arcs where they are,
/// and none on a circle, an ellipse (smooth, the curvature varying by a factor 8) or a densely
/// sampled noisy circle.
#[test]
fn tangent_joints_are_detected_where_the_curvature_jumps() {
    let tol = 1e-3;
    let detecting = FitOptions::new(tol).with_tangent_jump(Some(TANGENT_JUMP));
    for (pieces, closed, tol) in [
        (rounded_corner(PI / 2.0), false, 1e-4),
        (stadium(), true, 1e-3),
    ] {
        let detecting = detecting.with_tolerance(tol);
        let (data, starts) = sample(&pieces, 0.002, closed);
        let closure = Closure::from_closed(closed);
        let f = fit(&data, closure, &detecting).unwrap();
        let expected = if closed { &starts[..] } else { &starts[1..] };
        assert_eq!(f.tangents, expected);
        check_tangent_fit(&f, &data, &pieces, tol);
        let given = fit_with_joints(
            &data,
            closure,
            &Joints::new().with_tangents(expected),
            &FitOptions::new(tol),
        )
        .unwrap();
        assert_eq!(f.curve, given.curve);
    }
    let ellipse: Vec<Vector2> = (0..3000)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / 3000.0;
            Vector2::new(2.0 * t.cos(), t.sin())
        })
        .collect();
    let circle: Vec<Vector2> = ellipse
        .iter()
        .map(|p| Vector2::new(p[0] / 2.0, p[1]))
        .collect();
    // 20,000 points of the unit circle with radial noise of ±2.5·10⁻⁴ (a quarter of the
    // tolerance).
    let mut state = 7_u64;
    let noisy: Vec<Vector2> = (0..20_000)
        .map(|k| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let noise = 2.5e-4 * (2.0 * ((state >> 11) as f64 / (1u64 << 53) as f64) - 1.0);
            let t = 2.0 * PI * k as f64 / 20_000.0;
            Vector2::new((1.0 + noise) * t.cos(), (1.0 + noise) * t.sin())
        })
        .collect();
    for data in [ellipse, circle, noisy] {
        let f = fit(&data, Closure::Closed, &detecting).unwrap();
        assert!(f.tangents.is_empty(), "{:?}", f.tangents);
    }
    // Thresholds out of range are refused before any work.
    for bad in [0.0, -1.0, 1.5, f64::NAN, f64::INFINITY] {
        let options = FitOptions::new(tol).with_tangent_jump(Some(bad));
        assert!(matches!(
            fit(&[Vector2::new(0.0, 0.0); 2], Closure::Open, &options),
            Err(SubdivFitError::TooFewPoints { .. })
        ));
        let (data, _) = sample(&stadium(), 0.01, true);
        assert!(matches!(
            fit(&data, Closure::Closed, &options),
            Err(SubdivFitError::InvalidOption {
                name: "tangent_jump",
                ..
            })
        ));
    }
}

/// The turn of the fit at the sharp vertex on data index `index` and the one-sided curvatures
/// there (before, after).
fn smooth_joint_of(f: &Fit<2>, index: usize) -> (f64, f64, f64) {
    let j = f.fitting.binary_search(&index).expect("a fitting point");
    assert!(f.curve.is_sharp(j), "joint {index} is a sharp vertex");
    let (a, b) = f.curve.corner_tangents(j).unwrap();
    let (a, b) = (a.unwrap(), b.unwrap());
    let turn = a.perp(&b).atan2(a.dot(&b)).abs();
    let curvature =
        |d: &subdiv_fit::CurvePoint<2>| d.first.perp(&d.second) / d.first.norm().powi(3);
    let segs = f.curve.segment_count();
    let before = f
        .curve
        .eval_segment_derivatives((j + segs - 1) % segs, 1.0)
        .unwrap();
    let after = f.curve.eval_segment_derivatives(j % segs, 0.0).unwrap();
    (turn, curvature(&before), curvature(&after))
}

/// With `Reduction::Refit`, tangent joints are sharp vertices whose sides are held on one tangent
/// (smooth joints): tangent-continuous to `SMOOTH_JOINT_TURN`, with curved corners each side keeps
/// its own curvature (straight before a line-to-arc joint, bent after), within the tolerance of the
/// exact outline, and with fewer control points than the interpolating fit with double knots.
#[test]
fn refit_holds_tangent_joints_as_smooth_joints_with_fewer_points() {
    let cases = [
        (rounded_corner(PI / 2.0), false, 1e-3),
        (rounded_corner(PI / 2.0), false, 1e-4),
        (rounded_corner(PI), false, 1e-3),
        (stadium(), true, 1e-3),
    ];
    for (pieces, closed, tol) in cases {
        let closure = if closed {
            Closure::Closed
        } else {
            Closure::Open
        };
        let (data, starts) = sample(&pieces, 0.002, closed);
        let joints_at = if closed { &starts[..] } else { &starts[1..] };
        let joints = Joints::new().with_tangents(joints_at);
        let double_knots = fit_with_joints(&data, closure, &joints, &FitOptions::new(tol)).unwrap();
        for kind in [VertexKind::SharpCurved, VertexKind::Sharp] {
            let options = FitOptions::new(tol)
                .with_reduction(Reduction::Refit)
                .with_corner_kind(kind);
            let f = fit_with_joints(&data, closure, &joints, &options).unwrap();
            assert_eq!(f.tangents, joints_at);
            let error = error_to_outline(&f.curve, &pieces);
            assert!(error <= tol, "{kind:?}, tol {tol}: error {error}");
            for &index in joints_at {
                let (turn, k0, k1) = smooth_joint_of(&f, index);
                assert!(turn <= SMOOTH_JOINT_TURN, "turn {turn} at {index}");
                // A sharp vertex is interpolated.
                let j = f.fitting.binary_search(&index).unwrap();
                assert!((f.curve.eval(j as f64).unwrap() - data[index]).norm() < 1e-12);
                if kind == VertexKind::SharpCurved {
                    // Lines meet arcs of radius 1 at every joint, in either order.
                    let (line, arc) = if k0.abs() < k1.abs() {
                        (k0, k1)
                    } else {
                        (k1, k0)
                    };
                    assert!(line.abs() < 0.05 && arc > 0.5, "curvatures {k0}, {k1}");
                } else {
                    assert!(k0.abs() < 1e-9 && k1.abs() < 1e-9, "curvatures {k0}, {k1}");
                }
            }
            let (a, b) = (f.curve.points().len(), double_knots.curve.points().len());
            if kind == VertexKind::SharpCurved {
                assert!(
                    a < b,
                    "tol {tol}: {a} control points, {b} with double knots"
                );
            }
        }
    }
}

/// Smooth joints given with their exact tangents (`Corner::smooth`) are held on those tangents,
/// and the fit through `fit_bez_path` with `tangent_jump` takes the path's own.
#[test]
fn smooth_joints_follow_given_tangents() {
    let pieces = rounded_corner(PI / 2.0);
    let (data, starts) = sample(&pieces, 0.002, false);
    let tangents = [Vector2::new(1.0, 0.0), Vector2::new(0.0, 1.0)];
    let known: Vec<Corner<2>> = starts[1..]
        .iter()
        .zip(tangents)
        .map(|(&i, t)| Corner::smooth(i, t).unwrap())
        .collect();
    let options = FitOptions::new(1e-3)
        .with_reduction(Reduction::Refit)
        .with_corner_kind(VertexKind::SharpCurved);
    let f = fit_with_known_corners(&data, Closure::Open, &known, &options).unwrap();
    assert!(error_to_outline(&f.curve, &pieces) <= 1e-3);
    for (&index, t) in starts[1..].iter().zip(tangents) {
        let j = f.fitting.binary_search(&index).unwrap();
        let (a, b) = f.curve.corner_tangents(j).unwrap();
        for side in [a.unwrap(), b.unwrap()] {
            assert!(
                (side.normalize() - t).norm() < 1e-9,
                "{side:?} against {t:?}"
            );
        }
    }
}

/// A smooth joint that the fit cannot hold tangent-continuous is an error naming it: here its
/// given tangent points back against the data, which no side can leave along.
#[test]
fn a_smooth_joint_that_cannot_be_held_is_an_error() {
    let pieces = rounded_corner(PI / 2.0);
    let (data, starts) = sample(&pieces, 0.002, false);
    let joint = Corner::smooth(starts[1], Vector2::new(-1.0, 0.0)).unwrap();
    let options = FitOptions::new(1e-3)
        .with_reduction(Reduction::Refit)
        .with_corner_kind(VertexKind::Sharp);
    match fit_with_known_corners(&data, Closure::Open, &[joint], &options) {
        Err(SubdivFitError::SmoothJointNotKept { index, turn, max }) => {
            assert_eq!(index, starts[1]);
            assert!(turn > max && max == SMOOTH_JOINT_TURN, "{turn}");
        }
        other => panic!("expected SmoothJointNotKept, got {other:?}"),
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(12))]

    /// On rounded corners of any radius and sweep, `Reduction::Refit` with the two joints given
    /// stays within the tolerance of the exact outline and holds both joints tangent-continuous.
    #[test]
    fn smooth_joints_hold_on_random_rounded_corners(
        r in 0.3f64..3.0,
        sweep in 0.3f64..3.0,
        fine in proptest::bool::ANY,
    ) {
        let tol = if fine { 1e-3 } else { 1e-2 };
        let pieces = rounded_corner_of_radius(r, sweep);
        let (data, starts) = sample(&pieces, 0.004, false);
        let joints = Joints::new().with_tangents(&starts[1..]);
        let options = FitOptions::new(tol)
            .with_reduction(Reduction::Refit)
            .with_corner_kind(VertexKind::SharpCurved);
        let f = fit_with_joints(&data, Closure::Open, &joints, &options).unwrap();
        let error = error_to_outline(&f.curve, &pieces);
        proptest::prop_assert!(error <= tol, "error {} > {}", error, tol);
        for &index in &starts[1..] {
            let (turn, _, _) = smooth_joint_of(&f, index);
            proptest::prop_assert!(turn <= SMOOTH_JOINT_TURN, "turn {} at {}", turn, index);
        }
    }
}
