//! Random (including NaN, infinite, huge, empty, one-point and duplicate) inputs to every public
//! constructor, function and method give `Result`s or values, never panics or unbounded work, and
//! an `Ok` holding a curve, a point or an error measure never holds a NaN or an infinity.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use std::time::{Duration, Instant};

use bez_core::{BezierForm, MAX_COORDINATE};
use proptest::prelude::*;
use subdiv_fit::{
    BestCurve, CORNER_TOLERANCE, Closure, Corner, CurvePoint, EXACT_CORNER_TOLERANCE, ErrorMeasure,
    FeaturePoint, Fit, FitMode, FitOptions, Insertion, Joints, MAX_DATA_COORDINATE,
    MAX_FEATURE_SCALE, MAX_FIT_POINTS, MAX_REDUCED, MAX_ROUNDS, MAX_SAMPLES_PER_SEGMENT, Reduction,
    RoundReport, SCALE_RATIO, SMOOTH_JOINT_TURN, Seeding, Segment, SubdivCurve, SubdivFitError,
    TANGENT_JUMP, Vector2, Vector3, VertexKind, bspline_basis, bspline_basis_d1, bspline_basis_d2,
    bspline_to_bezier, discrete_curvature, feature_points, fit, fit_with_corners, fit_with_joints,
    fit_with_known_corners, foot_point, point_polyline_distance, scaled_corners, svg_path,
    turning_angle,
};

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -10.0..10.0f64,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(1e300),
        1 => Just(-1e300),
        1 => Just(MAX_COORDINATE),
        1 => Just(-MAX_COORDINATE),
        1 => Just(MAX_DATA_COORDINATE),
        1 => Just(1e-300),
        1 => Just(0.0),
        1 => Just(1.0),
    ]
}

/// Points with wild coordinates, and runs of repeated points.
fn wild_points(max: usize) -> impl Strategy<Value = Vec<Vector2>> {
    proptest::collection::vec(
        ((wild(), wild()), 1usize..3).prop_map(|((x, y), repeat)| vec![Vector2::new(x, y); repeat]),
        0..max,
    )
    .prop_map(|runs| runs.concat())
}

/// Data a fit can accept: a few dozen distinct points of a wobbly loop at a random scale and
/// offset (huge, tiny or ordinary), sometimes with a wild point spliced in.
fn plausible_data() -> impl Strategy<Value = Vec<Vector2>> {
    (
        3usize..60,
        prop_oneof![
            Just(1.0),
            Just(1e-200),
            Just(1e150),
            Just(MAX_DATA_COORDINATE),
            0.01..100.0f64
        ],
        -1e3..1e3f64,
        0.0..0.5f64,
        proptest::option::of((0usize..60, wild(), wild())),
    )
        .prop_map(|(n, scale, offset, wobble, splice)| {
            let mut pts: Vec<Vector2> = (0..n)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / n as f64;
                    let r = 1.0 + wobble * (5.0 * t).sin();
                    Vector2::new(offset + scale * r * t.cos(), scale * r * t.sin())
                })
                .collect();
            if let Some((i, x, y)) = splice {
                let i = i % n;
                pts[i] = Vector2::new(x, y);
            }
            pts
        })
}

fn options() -> impl Strategy<Value = FitOptions> {
    (
        (wild(), prop_oneof![wild(), 0.0..=std::f64::consts::PI]),
        prop_oneof![wild(), 0.0..20.0f64, Just(MAX_FEATURE_SCALE)],
        (wild(), wild()),
        prop_oneof![
            0usize..6,
            Just(MAX_ROUNDS),
            Just(MAX_ROUNDS + 1),
            Just(usize::MAX)
        ],
        prop_oneof![
            0usize..40,
            Just(MAX_SAMPLES_PER_SEGMENT + 1),
            Just(1_000_000_000)
        ],
        any::<(bool, bool, bool, bool, bool)>(),
        (
            prop_oneof![
                Just(None),
                Just(Some(CORNER_TOLERANCE)),
                wild().prop_map(Some)
            ],
            prop_oneof![Just(None), Just(Some(TANGENT_JUMP)), wild().prop_map(Some)],
            // The sharp kinds and one that is not (refused).
            prop_oneof![
                Just(VertexKind::Sharp),
                Just(VertexKind::SharpCurved),
                Just(VertexKind::Regular)
            ],
        ),
    )
        .prop_map(
            |(
                (tol, angle),
                scale,
                (floor, prominence),
                rounds,
                samples,
                flags,
                (corner, jump, kind),
            )| {
                let tol = if tol.is_finite() {
                    tol.abs().max(1e-12)
                } else {
                    tol
                };
                FitOptions::new(tol)
                    .with_sharp_angle(angle)
                    .with_feature_scale(scale)
                    .with_curvature_floor(floor)
                    .with_prominence(prominence)
                    .with_max_rounds(rounds)
                    .with_samples_per_segment(samples)
                    .with_seeding(if flags.0 {
                        Seeding::Scaled
                    } else {
                        Seeding::CurvatureMaxima
                    })
                    .with_mode(if flags.1 {
                        FitMode::Interpolate
                    } else {
                        FitMode::LeastSquares
                    })
                    .with_measure(if flags.2 {
                        ErrorMeasure::TwoSided
                    } else {
                        ErrorMeasure::DataToCurve
                    })
                    .with_insertion(if flags.3 {
                        Insertion::Bisect
                    } else {
                        Insertion::MaxError
                    })
                    .with_reduction(match (flags.4, flags.0) {
                        (true, true) if flags.3 => Reduction::RespaceAndRemove,
                        (true, true) => Reduction::Refit,
                        (true, false) => Reduction::RemovePoints,
                        (false, _) => Reduction::Off,
                    })
                    .with_corner_tolerance(corner)
                    .with_tangent_jump(jump)
                    .with_corner_kind(kind)
            },
        )
}

fn finite(v: &Vector2) -> bool {
    v.iter().all(|c| c.is_finite())
}

fn curve_ok<const D: usize>(c: &SubdivCurve<D>) -> bool {
    c.points().iter().all(|p| p.iter().all(|x| x.is_finite()))
}

fn report_ok(r: &RoundReport) -> bool {
    r.max_data_to_curve.is_finite()
        && r.rms_data_to_curve.is_finite()
        && r.max_curve_to_data.is_finite()
}

/// An `Ok` fit holds a finite curve, finite reports, fitting indices inside the data and one
/// control point per fitting point; an error is one of the documented kinds, and
/// `NoConvergence` carries a finite best curve.
fn check_fit(result: &Result<Fit<2>, SubdivFitError>, n: usize) -> Result<(), TestCaseError> {
    match result {
        Ok(f) => {
            prop_assert!(curve_ok(&f.curve));
            prop_assert!(f.reports.iter().all(report_ok));
            prop_assert!(f.fitting.iter().all(|&i| i < n));
            // A tangent vertex's partner is the one control point without a fitting point (a
            // smooth joint is one sharp vertex).
            let pairs = f
                .curve
                .kinds()
                .iter()
                .filter(|&&k| k == VertexKind::Tangent)
                .count();
            prop_assert_eq!(f.fitting.len() + pairs, f.curve.points().len());
            prop_assert!(pairs == 0 || pairs == f.tangents.len());
            prop_assert!(
                f.tangents
                    .iter()
                    .all(|t| f.fitting.binary_search(t).is_ok())
            );
            prop_assert!(f.initial.iter().all(|&i| i < n));
            prop_assert!(f.last().is_some() && f.rounds() + 1 == f.reports.len());
            prop_assert!(f.reduced.iter().all(report_ok));
            prop_assert_eq!(
                f.last().map(|r| r.control_points),
                Some(f.curve.points().len())
            );
            prop_assert!(f.curve.points().len() <= MAX_REDUCED || f.reduced.is_none());
            prop_assert!(svg_path(&f.curve).is_ok());
        }
        Err(SubdivFitError::NoConvergence {
            best, max_error, ..
        }) => {
            let best: &BestCurve = best;
            prop_assert!(!max_error.is_nan());
            let c: SubdivCurve<2> = best
                .curve()
                .expect("the best curve has the data's dimension");
            prop_assert!(curve_ok(&c));
            prop_assert!(best.curve::<3>().is_none());
            prop_assert!(!best.max_error().is_nan());
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn curves_never_panic(
        pts in wild_points(9),
        flags in proptest::collection::vec(0u8..4, 0..12),
        closed in any::<bool>(),
        s in wild(), u in wild(), i in 0usize..12, levels in prop_oneof![0usize..4, Just(30), Just(usize::MAX)],
        q in (wild(), wild()),
    ) {
        let closure = Closure::from_closed(closed);
        prop_assert_eq!(closure.is_closed(), closed);
        let n = pts.len();
        let _ = SubdivCurve::smooth(pts.clone(), closure);
        let kinds: Vec<VertexKind> = flags
            .iter()
            .map(|&f| match f {
                0 => VertexKind::Regular,
                1 => VertexKind::Sharp,
                2 => VertexKind::SharpCurved,
                _ => VertexKind::Tangent,
            })
            .collect();
        let mut sharp = kinds.clone();
        sharp.resize(n, VertexKind::Regular);
        let sharp_indices: Vec<usize> = (0..flags.len()).filter(|&j| flags[j] == 1).collect();
        let _ = SubdivCurve::with_sharp(pts.clone(), &sharp_indices, closure);
        // Random kinds rarely leave a tangent vertex room for its double knot: when they fail,
        // every fourth vertex from the fourth on is a tangent vertex, else the flags are padded.
        let tangents: Vec<VertexKind> = (0..n)
            .map(|j| if j % 4 == 3 { VertexKind::Tangent } else { VertexKind::Regular })
            .collect();
        let c = match SubdivCurve::new(pts.clone(), kinds, closure)
            .or_else(|_| SubdivCurve::new(pts.clone(), tangents, closure))
        {
            Ok(c) => c,
            Err(_) => match SubdivCurve::new(pts, sharp, closure) {
                Ok(c) => c,
                Err(e) => { let _ = e.to_string(); return Ok(()); }
            },
        };
        prop_assert!(curve_ok(&c));
        prop_assert_eq!(c.kinds().len(), c.points().len());
        prop_assert_eq!(c.is_sharp(i), c.kinds().get(i).is_some_and(|k| k.is_sharp()));
        prop_assert_eq!(c.is_closed(), c.closure().is_closed());
        let segs = c.segment_count();
        prop_assert!(segs >= 1);
        // Refinement stays in the hull of the polygon: finite.
        prop_assert!(curve_ok(&c.refine()));
        match c.refine_levels(levels) {
            Ok(r) => prop_assert!(curve_ok(&r) && r.points().len() <= MAX_FIT_POINTS),
            Err(e) => prop_assert!(matches!(e, SubdivFitError::TooLarge { .. }), "{}", e),
        }
        if let Ok(p) = c.limit_position(i) { prop_assert!(finite(&p)); }
        if let Ok(ctrl) = c.segment_controls(i) {
            prop_assert!(ctrl.iter().all(finite));
            prop_assert!(bspline_to_bezier(&ctrl).iter().all(finite));
        }
        if let Ok(p) = c.eval_segment(i, u) { prop_assert!(finite(&p)); }
        if let Ok(d) = c.eval_segment_derivatives(i, u) {
            let d: CurvePoint<2> = d;
            prop_assert!(finite(&d.position) && finite(&d.first) && finite(&d.second));
        }
        if let Ok((j, v)) = c.locate(s) { prop_assert!(j < segs && (0.0..=1.0).contains(&v)); }
        if let Ok(p) = c.eval(s) { prop_assert!(finite(&p)); }
        if let Ok(d) = c.eval_derivatives(s) { prop_assert!(finite(&d.position) && finite(&d.first)); }
        let mut many = Vec::new();
        let _ = c.eval_many(&[s, u, 0.0, segs as f64], &mut many);
        prop_assert!(many.iter().all(finite));
        if let Ok(b) = c.segment_bezier(i) { prop_assert!(b.points().iter().all(finite)); }
        if let Ok(all) = c.to_beziers() { prop_assert!(all.iter().all(|b| b.points().iter().all(finite))); }
        if let Ok(seg) = c.segment(i) {
            let seg: Segment<2> = seg;
            prop_assert_eq!(seg.index(), i);
            prop_assert!(seg.controls().iter().all(finite));
            if let Ok(p) = seg.eval(0.5) { prop_assert!(finite(&p)); }
            prop_assert!(seg.into_bezier().points().iter().all(finite));
        }
        if let Ok(svg) = svg_path(&c) { prop_assert!(!svg.contains("NaN") && !svg.contains("inf")); }
        let v = Vector2::new(q.0, q.1);
        if let Ok((t, d)) = foot_point(&c, i, &v, u) {
            prop_assert!((0.0..=1.0).contains(&t));
            prop_assert!(!d.is_nan() || !finite(&v));
        }
    }

    #[test]
    fn kernels_never_panic(pts in wild_points(8), t in wild(), a in wild(), b in wild(), closed in any::<bool>()) {
        for w in [bspline_basis(t), bspline_basis_d1(t), bspline_basis_d2(t)] {
            prop_assert!(w.iter().all(|x| x.is_finite()) || !t.is_finite() || t.abs() > 1e100);
        }
        if let Ok(four) = <[Vector2; 4]>::try_from(&pts[..pts.len().min(4)]) {
            let _ = bspline_to_bezier(&four);
        }
        prop_assert_eq!(turning_angle(&pts, closed).len(), pts.len());
        prop_assert_eq!(discrete_curvature(&pts, closed).len(), pts.len());
        let features: Vec<FeaturePoint> = feature_points(&pts, closed, a, b, t);
        prop_assert!(features.iter().all(|f| f.index < pts.len()));
        let _ = point_polyline_distance(&Vector2::new(a, b), &pts);
        prop_assert!(point_polyline_distance(&Vector2::new(a, b), &[]).is_infinite());
        let _ = scaled_corners(&pts, Closure::from_closed(closed), &FitOptions::new(t.abs()));
    }

    #[test]
    fn fits_never_panic(
        data in plausible_data(),
        opts in options(),
        closed in any::<bool>(),
        corners in proptest::collection::vec(prop_oneof![0usize..70, Just(usize::MAX)], 0..4),
        tangents in proptest::collection::vec((wild(), wild(), wild(), wild()), 4),
    ) {
        let closure = Closure::from_closed(closed);
        let n = data.len();
        let start = Instant::now();
        check_fit(&fit(&data, closure, &opts), n)?;
        check_fit(&fit_with_corners(&data, closure, &corners, &opts), n)?;
        // The same corners with wild tangents (the invalid ones given without), and the bound
        // that exact tangents allow.
        let known: Vec<Corner<2>> = corners
            .iter()
            .zip(&tangents)
            .map(|(&i, &(a, b, c, d))| {
                Corner::with_tangents(i, Vector2::new(a, b), Vector2::new(c, d))
                    .unwrap_or(Corner::new(i))
            })
            .collect();
        let bounded = opts.with_corner_tolerance(Some(EXACT_CORNER_TOLERANCE));
        check_fit(&fit_with_known_corners(&data, closure, &known, &bounded), n)?;
        let joints = Joints::new().with_corners(&corners[..corners.len() / 2]).with_tangents(&corners[corners.len() / 2..]);
        prop_assert!(joints.corners().windows(2).all(|w| w[0] < w[1]));
        prop_assert!(joints.tangents().windows(2).all(|w| w[0] < w[1]));
        check_fit(&fit_with_joints(&data, closure, &joints, &opts), n)?;
        // Smooth joints (wild tangents, the invalid ones as plain corners), and the tangent
        // joints as smooth joints, with `Reduction::Refit`.
        let smooth: Vec<Corner<2>> = corners
            .iter()
            .zip(&tangents)
            .map(|(&i, &(a, b, _, _))| {
                Corner::smooth(i, Vector2::new(a, b)).unwrap_or(Corner::new(i))
            })
            .collect();
        let refit = opts.with_reduction(Reduction::Refit);
        check_fit(&fit_with_known_corners(&data, closure, &smooth, &refit), n)?;
        check_fit(&fit_with_joints(&data, closure, &joints, &refit), n)?;
        if let Ok(found) = scaled_corners(&data, closure, &opts) {
            prop_assert!(found.windows(2).all(|w| w[0] < w[1]) && found.iter().all(|&i| i < n));
        }
        prop_assert!(start.elapsed() < Duration::from_secs(5), "{:?}", start.elapsed());
    }

    /// Smooth joints with valid options on plausible data, at any index and with any direction:
    /// no panic, and an `Ok` is tangent-continuous at every joint (its turn measured here, beside
    /// the fit's own check); otherwise a typed error.
    #[test]
    fn smooth_joints_hold_or_are_refused(
        data in plausible_data(),
        closed in any::<bool>(),
        rel in 1e-3..1e-1f64,
        curved in any::<bool>(),
        joints in proptest::collection::vec((0usize..60, -std::f64::consts::PI..std::f64::consts::PI), 1..4),
    ) {
        let closure = Closure::from_closed(closed);
        let n = data.len();
        let size = data.iter().map(|p| p.norm()).fold(0.0, f64::max);
        let kind = if curved { VertexKind::SharpCurved } else { VertexKind::Sharp };
        let opts = FitOptions::new(rel * size.max(1e-300))
            .with_reduction(Reduction::Refit)
            .with_corner_kind(kind);
        let known: Vec<Corner<2>> = joints
            .iter()
            .map(|&(i, a)| Corner::smooth(i % n, Vector2::new(a.cos(), a.sin())).unwrap())
            .collect();
        let result = fit_with_known_corners(&data, closure, &known, &opts);
        check_fit(&result, n)?;
        if let Ok(f) = &result {
            for c in &known {
                let Ok(j) = f.fitting.binary_search(&c.index()) else {
                    continue;
                };
                if let Some((Some(a), Some(b))) = f.curve.corner_tangents(j) {
                    let turn = a.perp(&b).abs().atan2(a.dot(&b));
                    prop_assert!(turn <= SMOOTH_JOINT_TURN, "turn {} at {}", turn, c.index());
                }
            }
        }
    }

    #[test]
    fn wild_data_never_panics(data in wild_points(12), tol in wild(), closed in any::<bool>()) {
        let closure = Closure::from_closed(closed);
        let opts = FitOptions::new(tol);
        check_fit(&fit(&data, closure, &opts), data.len())?;
        check_fit(&fit(&data, closure, &FitOptions::paper(tol)), data.len())?;
        check_fit(&fit(&data, closure, &FitOptions::new(1e-3).with_tolerance(tol)), data.len())?;
    }
}

/// Paths in and out: wild path data, spacings and options never panic; an `Ok` holds finite
/// samples and paths.
#[cfg(feature = "kurbo")]
mod paths {
    use super::*;
    use subdiv_fit::{
        JOINT_ROOM, LINE_END_SAMPLES, LINE_MAX_STEP, LineSampling, PATH_CORNER_ANGLE,
        SampledContour, TANGENT_JUMP, fit_bez_path, sample_bez_path, sample_bez_path_with,
        sample_svg_path,
    };

    fn sampled_ok(contours: &[SampledContour]) -> bool {
        contours.iter().all(|c| {
            c.points.iter().all(finite)
                && c.corners.iter().all(|&i| i < c.points.len())
                && c.smooth_joints
                    .iter()
                    .all(|j| j.0 < c.points.len() && j.1.is_finite() && j.2.is_finite())
                && c.tangent_joints(TANGENT_JUMP)
                    .iter()
                    .all(|&i| i < c.points.len())
                && c.points.windows(2).all(|w| w[0] != w[1])
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        #[test]
        fn paths_never_panic(
            coords in proptest::collection::vec(wild(), 0..16),
            ops in proptest::collection::vec(0u8..6, 0..8),
            spacing in prop_oneof![wild(), 0.01..1.0f64, Just(1e-300)],
            tol in prop_oneof![wild(), 1e-3..0.1f64],
        ) {
            let mut path = kurbo::BezPath::new();
            let mut it = coords.chunks_exact(2).map(|c| kurbo::Point::new(c[0], c[1])).cycle();
            if coords.len() >= 2 {
                // kurbo's builder asserts a leading MoveTo itself.
                path.move_to(it.next().unwrap());
                for op in &ops {
                    match op {
                        0 => path.move_to(it.next().unwrap()),
                        1 => path.line_to(it.next().unwrap()),
                        2 => path.quad_to(it.next().unwrap(), it.next().unwrap()),
                        3 => path.curve_to(it.next().unwrap(), it.next().unwrap(), it.next().unwrap()),
                        _ => path.close_path(),
                    }
                }
            }
            if let Ok(c) = sample_bez_path(&path, spacing) { prop_assert!(sampled_ok(&c)); }
            if let Ok(c) = sample_bez_path_with(&path, spacing, LineSampling::Graded) { prop_assert!(sampled_ok(&c)); }
            let start = Instant::now();
            // With the path's tangent joints too (every smooth joint whose curvature jumps at all),
            // and with `Refit` (its lines sampled graded).
            let refit = FitOptions::new(tol).with_reduction(Reduction::Refit);
            for opts in [FitOptions::new(tol), FitOptions::new(tol).with_tangent_jump(Some(1e-9)), refit] {
            if let Ok((out, fits)) = fit_bez_path(&path, &opts) {
                let path_ok = out.elements().iter().all(|e| match e {
                    kurbo::PathEl::MoveTo(p) | kurbo::PathEl::LineTo(p) => p.is_finite(),
                    kurbo::PathEl::QuadTo(a, b) => a.is_finite() && b.is_finite(),
                    kurbo::PathEl::CurveTo(a, b, c) => a.is_finite() && b.is_finite() && c.is_finite(),
                    kurbo::PathEl::ClosePath => true,
                });
                prop_assert!(path_ok);
                prop_assert!(fits.iter().all(|f| curve_ok(&f.curve)));
            }
            }
            prop_assert!(start.elapsed() < Duration::from_secs(10));
            let svg = format!("M {} {} L 1 0 Q 1 1 0 1 Z", coords.first().unwrap_or(&0.0), coords.last().unwrap_or(&0.0));
            if let Ok(c) = sample_svg_path(&svg, spacing) { prop_assert!(sampled_ok(&c)); }
        }
    }

    #[test]
    fn bad_path_input_is_typed() {
        assert!(matches!(
            sample_svg_path("M 0 0 X 3", 0.1),
            Err(SubdivFitError::InvalidPathData { .. })
        ));
        assert!(matches!(
            sample_svg_path("M 0 0 L 1e6 0", 1e-6),
            Err(SubdivFitError::TooLarge { .. })
        ));
        // The size check counts the samples each way: 10⁸ evenly, about 1.6 · 10⁶ graded.
        let long = kurbo::BezPath::from_svg("M 0 0 L 1e5 0").unwrap();
        assert!(matches!(
            sample_bez_path_with(&long, 1e-3, LineSampling::Even),
            Err(SubdivFitError::TooLarge { .. })
        ));
        let graded = sample_bez_path_with(&long, 1e-3, LineSampling::Graded).unwrap();
        assert!((graded[0].points.len() as f64 - 1e8 / 64.0).abs() < 100.0);
        assert!(matches!(
            sample_bez_path_with(&long, 1e-6, LineSampling::Graded),
            Err(SubdivFitError::TooLarge { .. })
        ));
        for spacing in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                sample_svg_path("M 0 0 L 1 0", spacing),
                Err(SubdivFitError::InvalidOption {
                    name: "spacing",
                    ..
                })
            ));
        }
        let square = sample_svg_path("M0 0 H1 V1 H0 Z", 0.25).unwrap();
        assert_eq!(square[0].corners, [0, 4, 8, 12]);
        // The path's own tangents at the corners: arriving down the left side at (0, 0), leaving
        // along the bottom.
        assert_eq!(square[0].corner_tangents.len(), 4);
        let known = square[0].known_corners();
        assert_eq!(known[0].index(), 0);
        assert_eq!(
            known[0].tangents(),
            Some((Vector2::new(0.0, -1.0), Vector2::new(1.0, 0.0)))
        );
        const { assert!(PATH_CORNER_ANGLE < 0.1) };
        const { assert!(JOINT_ROOM >= 4) };
        // A tangent joint's room fits in the samples at the spacing next to a line's end.
        const { assert!(LINE_END_SAMPLES >= JOINT_ROOM && LINE_MAX_STEP >= 2) };
        // A line into a half circle: one smooth joint, curvature 0 in and 1 out.
        let hook_path = kurbo::BezPath::from_svg("M-2 0 L0 0 A1 1 0 0 1 0 2").unwrap();
        let hook = sample_bez_path(&hook_path, 0.05).unwrap();
        assert_eq!(hook[0].tangent_joints(TANGENT_JUMP), [40]);
        // Its line meets the arc tangentially: sampled evenly when graded too; with a corner at
        // the joint, graded (samples at 1, 2, …, 16 and 18 spacings from each end).
        let graded = sample_bez_path_with(&hook_path, 0.05, LineSampling::Graded).unwrap();
        assert_eq!(graded, hook);
        let bent = kurbo::BezPath::from_svg("M-2 0 L0 0 A1 1 0 0 0 0 2").unwrap();
        let bent = sample_bez_path_with(&bent, 0.05, LineSampling::Graded).unwrap();
        assert_eq!(bent[0].corners, [35]);
        // `fit_bez_path`'s choice: graded with `Refit` only.
        let options = FitOptions::new(1e-3);
        assert_eq!(LineSampling::for_fit(&options), LineSampling::Even);
        let refit = options.with_reduction(Reduction::Refit);
        assert_eq!(LineSampling::for_fit(&refit), LineSampling::Graded);
        // With the path's tangent there as a smooth joint, beside the open ends (no corners).
        let joints = hook[0].known_joints(TANGENT_JUMP);
        assert_eq!(joints.len(), 1);
        assert!(joints[0].is_smooth() && joints[0].index() == 40);
        assert_eq!(
            joints[0].tangents(),
            Some((Vector2::new(1.0, 0.0), Vector2::new(1.0, 0.0)))
        );
        assert!(
            square[0]
                .known_joints(TANGENT_JUMP)
                .iter()
                .all(|c| !c.is_smooth())
        );
        let c = SubdivCurve::smooth(square[0].points.clone(), Closure::Closed).unwrap();
        assert_eq!(c.to_bez_path().unwrap().segments().count(), 16);
    }
}

/// Corner tangents must be finite and non-zero (typed errors naming the corner); any other length,
/// huge or subnormal, is normalized; a corner index outside the data is refused by the fit.
#[test]
fn corner_tangents_are_validated() {
    let up = Vector2::new(0.0, 1.0);
    for bad in [
        Vector2::new(0.0, 0.0),
        Vector2::new(f64::NAN, 1.0),
        Vector2::new(1.0, f64::INFINITY),
        Vector2::new(-0.0, 0.0),
    ] {
        for (a, b) in [(bad, up), (up, bad)] {
            assert!(matches!(
                Corner::with_tangents(5, a, b),
                Err(SubdivFitError::InvalidCornerTangent { index: 5, .. })
            ));
        }
    }
    for (v, unit) in [
        (
            Vector2::new(1e300, -1e300),
            Vector2::new(1.0, -1.0) / 2f64.sqrt(),
        ),
        (Vector2::new(0.0, 5e-324), up),
        (
            Vector2::new(f64::MAX, f64::MAX),
            Vector2::new(1.0, 1.0) / 2f64.sqrt(),
        ),
    ] {
        let c = Corner::with_tangents(2, v, up).unwrap();
        assert_eq!(c.index(), 2);
        let (a, b) = c.tangents().unwrap();
        assert!((a - unit).norm() < 1e-15 && b == up, "{a:?}");
    }
    assert_eq!(Corner::<2>::new(3).tangents(), None);
    assert!(!Corner::<2>::new(3).is_smooth());
    // A smooth joint's tangent likewise.
    for bad in [Vector2::new(0.0, 0.0), Vector2::new(f64::NAN, 1.0)] {
        assert!(matches!(
            Corner::smooth(5, bad),
            Err(SubdivFitError::InvalidCornerTangent { index: 5, .. })
        ));
    }
    let joint = Corner::smooth(6, Vector2::new(0.0, 1e-300)).unwrap();
    assert!(joint.is_smooth() && joint.tangents() == Some((up, up)));
    const { assert!(SMOOTH_JOINT_TURN > 0.0 && SMOOTH_JOINT_TURN < 1e-6) };
    let data: Vec<Vector2> = (0..40)
        .map(|k| Vector2::new(k as f64, (k as f64 * 0.3).sin()))
        .collect();
    let far = Corner::with_tangents(40, up, up).unwrap();
    assert!(matches!(
        fit_with_known_corners(&data, Closure::Open, &[far], &FitOptions::new(1e-3)),
        Err(SubdivFitError::CornerOutOfRange {
            index: 40,
            points: 40
        })
    ));
    // Smooth joints need `Reduction::Refit`, before any work.
    let smooth = Corner::smooth(20, Vector2::new(1.0, 0.3)).unwrap();
    for reduction in [
        Reduction::Off,
        Reduction::RemovePoints,
        Reduction::RespaceAndRemove,
    ] {
        let o = FitOptions::new(1e-3).with_reduction(reduction);
        assert!(matches!(
            fit_with_known_corners(&data, Closure::Open, &[smooth], &o),
            Err(SubdivFitError::InvalidTangentJoint { index: 20, .. })
        ));
    }
}

/// Sizes the caller chooses are refused before any work, quickly.
#[test]
fn limits_are_checked_before_work() {
    let data: Vec<Vector2> = (0..1000)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 1000.0;
            Vector2::new(t.cos(), t.sin())
        })
        .collect();
    let start = Instant::now();
    let o = FitOptions::new(1e-3);
    for opts in [
        o.with_samples_per_segment(1_000_000_000),
        o.with_samples_per_segment(usize::MAX),
        o.with_max_rounds(usize::MAX),
        o.with_feature_scale(1e300),
    ] {
        let e = fit(&data, Closure::Closed, &opts).unwrap_err();
        assert!(
            matches!(
                e,
                SubdivFitError::TooLarge { .. } | SubdivFitError::InvalidOption { .. }
            ),
            "{e}"
        );
    }
    let c = SubdivCurve::smooth(data[..8].to_vec(), Closure::Closed).unwrap();
    assert!(matches!(
        c.refine_levels(40),
        Err(SubdivFitError::TooLarge {
            max: MAX_FIT_POINTS,
            ..
        })
    ));
    assert!(
        c.refine_levels(21)
            .is_ok_and(|r| r.points().len() == MAX_FIT_POINTS)
    );
    assert!(start.elapsed() < Duration::from_secs(5));
    // A tolerance below the coordinates' precision is refused; an unreachable one ends (no point
    // left to insert) with the best curve.
    assert!(matches!(
        fit(&data, Closure::Closed, &FitOptions::new(1e-300)),
        Err(SubdivFitError::ToleranceBelowPrecision { .. })
    ));
    let start = Instant::now();
    match fit(&data, Closure::Closed, &FitOptions::new(1e-13)) {
        Err(SubdivFitError::NoConvergence {
            best, max_error, ..
        }) => {
            assert!(best.max_error() <= max_error);
            assert!(curve_ok(&best.curve::<2>().unwrap()));
        }
        other => panic!("{other:?}"),
    }
    assert!(start.elapsed() < Duration::from_secs(20));
    // Space curves and huge coordinates.
    let lifted: Vec<Vector3> = data
        .iter()
        .map(|p| Vector3::new(p.x(), p.y(), 1e150))
        .collect();
    assert!(matches!(
        fit(&lifted, Closure::Open, &FitOptions::new(1e-3)),
        Err(SubdivFitError::ToleranceBelowPrecision { .. })
    ));
    let f = fit(&lifted, Closure::Open, &FitOptions::new(1e137)).unwrap();
    assert!(curve_ok(&f.curve));
    const { assert!(SCALE_RATIO > 0.5 && SCALE_RATIO < 1.0) };
}

/// Deserialization validates like the constructors; invalid options deserialize (their fields are
/// public) but every fit refuses them before any work.
#[cfg(feature = "serde")]
#[test]
fn invariant_violating_json_is_refused() {
    for bad in [
        r#"{"points":[],"kinds":[],"closed":true}"#,
        r#"{"points":[[0,0],[1,0]],"kinds":["Regular","Regular"],"closed":true}"#,
        r#"{"points":[[0,0],[1,0],[1,1]],"kinds":["Regular"],"closed":true}"#,
        r#"{"points":[[0,0],[1e200,0],[1,1]],"kinds":["Regular","Regular","Regular"],"closed":true}"#,
        r#"{"points":[[0,0],[1e999,0],[1,1]],"kinds":["Regular","Regular","Regular"],"closed":true}"#,
        r#"{"points":[[0,0,0],[1,0,0],[1,1,0]],"kinds":["Regular","Regular","Regular"],"closed":true}"#,
        r#"{"points":[[0,0],[1,0],[1,1]],"kinds":["Regular","Regular","Regular"]}"#,
        r#"{"points":[[0,0],[1,0],[1,1]],"kinds":["Regular","Blunt","Regular"],"closed":true}"#,
        r#"{"points":[[0,0],[1,0],[1,1]],"sharp":[false,false,false],"closed":true}"#,
        r#"[1,2,3]"#,
    ] {
        assert!(
            serde_json::from_str::<SubdivCurve<2>>(bad).is_err(),
            "{bad}"
        );
    }
    let good =
        r#"{"points":[[0,0],[1,0],[1,1]],"kinds":["Regular","Sharp","Regular"],"closed":false}"#;
    let c: SubdivCurve<2> = serde_json::from_str(good).unwrap();
    assert_eq!(c.kinds(), [VertexKind::Sharp; 3]);
    let round: SubdivCurve<2> = serde_json::from_str(&serde_json::to_string(&c).unwrap()).unwrap();
    assert_eq!(round, c);
    for bad in [r#""Sideways""#, "3", "null"] {
        assert!(serde_json::from_str::<Closure>(bad).is_err());
        assert!(serde_json::from_str::<ErrorMeasure>(bad).is_err());
        assert!(serde_json::from_str::<FitMode>(bad).is_err());
        assert!(serde_json::from_str::<Insertion>(bad).is_err());
        assert!(serde_json::from_str::<Seeding>(bad).is_err());
        assert!(serde_json::from_str::<FeaturePoint>(bad).is_err());
        assert!(serde_json::from_str::<RoundReport>(bad).is_err());
    }
    let data: Vec<Vector2> = (0..50)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 50.0;
            Vector2::new(t.cos(), t.sin())
        })
        .collect();
    let defaults = serde_json::to_value(FitOptions::new(1e-3)).unwrap();
    for (field, value) in [
        ("tolerance", serde_json::json!(-1.0)),
        ("tolerance", serde_json::json!(0.0)),
        ("sharp_angle", serde_json::json!(7.0)),
        ("feature_scale", serde_json::json!(-1.0)),
        ("feature_scale", serde_json::json!(1e300)),
        ("curvature_floor", serde_json::json!(-1.0)),
        ("prominence", serde_json::json!(-1.0)),
        ("max_rounds", serde_json::json!(u64::MAX)),
        ("samples_per_segment", serde_json::json!(1_000_000_000u64)),
        ("samples_per_segment", serde_json::json!(1)),
        ("corner_tolerance", serde_json::json!(0.0)),
        ("corner_tolerance", serde_json::json!(-0.1)),
        ("corner_tolerance", serde_json::json!(4.0)),
    ] {
        let mut v = defaults.clone();
        v[field] = value;
        if let Ok(o) = serde_json::from_value::<FitOptions>(v) {
            let start = Instant::now();
            assert!(fit(&data, Closure::Closed, &o).is_err(), "{field}");
            assert!(start.elapsed() < Duration::from_secs(1));
        }
    }
    // Options written before the corner bound existed read with its default (none); a bound
    // round-trips.
    // Likewise the corner kind (default: the paper's sharp vertex); a kind that is not sharp
    // reads and is refused by the fit.
    let mut old = defaults;
    old.as_object_mut().unwrap().remove("corner_tolerance");
    old.as_object_mut().unwrap().remove("corner_kind");
    let read: FitOptions = serde_json::from_value(old.clone()).unwrap();
    assert_eq!(read, FitOptions::new(1e-3));
    let bounded = FitOptions::new(1e-3)
        .with_corner_tolerance(Some(CORNER_TOLERANCE))
        .with_corner_kind(VertexKind::SharpCurved);
    let read: FitOptions = serde_json::from_value(serde_json::to_value(bounded).unwrap()).unwrap();
    assert_eq!(read, bounded);
    old["corner_kind"] = serde_json::json!("Regular");
    let regular: FitOptions = serde_json::from_value(old).unwrap();
    assert!(matches!(
        fit(&data, Closure::Closed, &regular),
        Err(SubdivFitError::InvalidCornerKind {
            kind: VertexKind::Regular,
            ..
        })
    ));
    // Known corners: tangents validated as by `Corner::with_tangents`, a valid one round-trips.
    for bad in [
        r#"{"index":1,"tangents":[[0,0],[1,0]]}"#,
        r#"{"index":1,"tangents":[[1e999,0],[1,0]]}"#,
        r#"{"index":1,"tangents":[[1,0]]}"#,
        r#"{"index":-1}"#,
        r#"{"tangents":null}"#,
    ] {
        assert!(serde_json::from_str::<Corner<2>>(bad).is_err(), "{bad}");
    }
    let c = Corner::with_tangents(4, Vector2::new(3.0, 4.0), Vector2::new(0.0, -2.0)).unwrap();
    let read: Corner<2> = serde_json::from_str(&serde_json::to_string(&c).unwrap()).unwrap();
    // Normalized again on reading: equal up to rounding.
    let ((a, b), (a2, b2)) = (c.tangents().unwrap(), read.tangents().unwrap());
    assert!(read.index() == 4 && (a - a2).norm() < 1e-15 && (b - b2).norm() < 1e-15);
    let plain: Corner<2> = serde_json::from_str(r#"{"index":7}"#).unwrap();
    assert_eq!(plain, Corner::new(7));
    // A smooth joint round-trips; one without a tangent, or with two, is refused.
    let joint = Corner::smooth(9, Vector2::new(0.0, 2.0)).unwrap();
    let read: Corner<2> = serde_json::from_str(&serde_json::to_string(&joint).unwrap()).unwrap();
    assert_eq!(read, joint);
    for bad in [
        r#"{"index":1,"smooth":true}"#,
        r#"{"index":1,"tangents":[[1,0],[0,1]],"smooth":true}"#,
        r#"{"index":1,"tangents":[[0,0],[0,0]],"smooth":true}"#,
    ] {
        assert!(serde_json::from_str::<Corner<2>>(bad).is_err(), "{bad}");
    }
}

bez_core::suite_completeness_tests!();
