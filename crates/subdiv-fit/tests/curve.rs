//! Exact evaluation against repeated refinement, limit masks, eigen form, continuity.

use proptest::prelude::*;
use subdiv_fit::eigen::{
    EIGENVALUES, eigenvectors, eigenvectors_inverse, eval_sharp_segment_eigen,
    extended_sharp_matrix, sharp_matrix,
};
use subdiv_fit::{SubdivCurve, SubdivFitError, Vector, Vector2, Vector3, VertexKind};

fn polygon<const D: usize>(
    min: usize,
    max: usize,
) -> impl Strategy<Value = (Vec<Vector<D>>, Vec<VertexKind>, bool)> {
    (min..=max).prop_flat_map(|n| {
        (
            prop::collection::vec(
                prop::array::uniform::<_, D>(-10.0..10.0f64).prop_map(Vector::from),
                n,
            ),
            prop::collection::vec(
                prop_oneof![
                    2 => Just(VertexKind::Regular),
                    1 => Just(VertexKind::Sharp),
                    1 => Just(VertexKind::SharpCurved)
                ],
                n,
            ),
            any::<bool>(),
        )
    })
}

/// After `levels` refinements, vertex m of the refined polygon has its limit (mask) at the global
/// parameter m / 2^levels, and the curve must pass exactly there.
#[allow(clippy::unwrap_used, reason = "test helper")]
fn check_against_refinement<const D: usize>(c: &SubdivCurve<D>, levels: usize, tol: f64) {
    let r = c.refine_levels(levels).unwrap();
    let scale = (1u64 << levels) as f64;
    let max = c.segment_count() as f64;
    for m in 0..r.points().len() {
        let s = m as f64 / scale;
        if s > max {
            continue;
        }
        let mask = r.limit_position(m).unwrap();
        let exact = c.eval(s).unwrap();
        assert!(
            (mask - exact).norm() <= tol * (1.0 + exact.norm()),
            "level {levels}, vertex {m}: mask {mask:?} vs exact {exact:?}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn exact_matches_refinement_masks_2d((p, f, closed) in polygon::<2>(3, 8)) {
        let c = SubdivCurve::new(p, f, subdiv_fit::Closure::from_closed(closed)).unwrap();
        for levels in [1, 3, 6] {
            check_against_refinement(&c, levels, 1e-12);
        }
    }

    #[test]
    fn exact_matches_refinement_masks_3d((p, f, closed) in polygon::<3>(3, 8)) {
        let c = SubdivCurve::new(p, f, subdiv_fit::Closure::from_closed(closed)).unwrap();
        check_against_refinement(&c, 4, 1e-12);
    }

    #[test]
    fn eigen_form_equals_collapsed_form(p in prop::array::uniform3(prop::array::uniform::<_, 2>(-5.0..5.0f64).prop_map(Vector2::from)), u in 0.0..=1.0f64) {
        // Sharp p0, regular p1 (and p2): segment 0 of an open polygon with p1 regular.
        let c = SubdivCurve::with_sharp(vec![p[0], p[1], p[2]], &[0, 2], subdiv_fit::Closure::Open).unwrap();
        let collapsed = c.eval_segment(0, u).unwrap();
        let eigen = eval_sharp_segment_eigen(&p, u).unwrap();
        prop_assert!((collapsed - eigen).norm() <= 1e-12 * (1.0 + collapsed.norm()));
    }

    #[test]
    fn segment_bezier_is_exact((p, f, closed) in polygon::<3>(3, 7), u in 0.0..=1.0f64) {
        let c = SubdivCurve::new(p, f, subdiv_fit::Closure::from_closed(closed)).unwrap();
        for i in 0..c.segment_count() {
            let b = c.segment_bezier(i).unwrap();
            let x = c.eval_segment(i, u).unwrap();
            prop_assert!((b.eval(u).unwrap() - x).norm() <= 1e-12 * (1.0 + x.norm()));
            let d = c.eval_segment_derivatives(i, u).unwrap();
            let bd = b.eval_derivatives(u, 2).unwrap();
            prop_assert!((bd[1] - d.first).norm() <= 1e-11 * (1.0 + d.first.norm()));
            prop_assert!((bd[2] - d.second).norm() <= 1e-10 * (1.0 + d.second.norm()));
        }
    }

    #[test]
    fn continuity_at_joints((p, f, closed) in polygon::<2>(4, 9)) {
        let c = SubdivCurve::new(p, f, subdiv_fit::Closure::from_closed(closed)).unwrap();
        let n = c.points().len();
        for i in 0..c.segment_count() {
            let next = i + 1;
            if next == c.segment_count() && !closed {
                continue;
            }
            let (l, r) = (
                c.eval_segment_derivatives(i, 1.0).unwrap(),
                c.eval_segment_derivatives(next % c.segment_count(), 0.0).unwrap(),
            );
            let tol = 1e-12 * (1.0 + l.position.norm() + l.second.norm());
            // C0 everywhere.
            prop_assert!((l.position - r.position).norm() <= tol);
            let v = next % n;
            if !c.is_sharp(v) {
                // C2 at a regular vertex.
                prop_assert!((l.first - r.first).norm() <= tol);
                prop_assert!((l.second - r.second).norm() <= tol);
            } else if c.kinds()[v] == VertexKind::Sharp {
                // One-sided tangents along the polygon edges, zero curvature on both sides.
                let pv = c.points()[v];
                prop_assert!((r.first - (c.points()[(v + 1) % n] - pv)).norm() <= tol);
                prop_assert!((l.first - (pv - c.points()[(v + n - 1) % n])).norm() <= tol);
                prop_assert!(l.second.norm() <= tol && r.second.norm() <= tol);
            } else {
                // A curved corner: the curve passes through the vertex, its one-sided tangents
                // are `corner_tangents`, and a side with a regular vertex next to the corner
                // starts with a parabola (no third derivative on that segment).
                prop_assert!((r.position - c.points()[v]).norm() <= tol);
                let (ti, to) = c.corner_tangents(v).unwrap();
                prop_assert!((r.first - to.unwrap()).norm() <= tol * (1.0 + r.first.norm()));
                prop_assert!((l.first - ti.unwrap()).norm() <= tol * (1.0 + l.first.norm()));
                let third = |k: [Vector2; 4]| k[0] - 3.0 * k[1] + 3.0 * k[2] - k[3];
                if !c.is_sharp((v + 1) % n) {
                    let k = c.segment_controls(next % c.segment_count()).unwrap();
                    prop_assert!(third(k).norm() <= tol * (1.0 + k[0].norm()));
                }
                if !c.is_sharp((v + n - 1) % n) {
                    let k = c.segment_controls(i).unwrap();
                    prop_assert!(third(k).norm() <= tol * (1.0 + k[0].norm()));
                }
            }
        }
    }
}

#[test]
fn twelve_levels_of_refinement_converge_to_the_exact_curve() {
    let p = vec![
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(1.0, 2.0, -1.0),
        Vector3::new(3.0, 2.5, 0.5),
        Vector3::new(4.0, -1.0, 2.0),
        Vector3::new(2.0, -2.0, 1.0),
        Vector3::new(0.5, -1.5, 0.0),
    ];
    let c = SubdivCurve::with_sharp(p, &[1, 4], subdiv_fit::Closure::Closed).unwrap();
    check_against_refinement(&c, 12, 1e-12);
    // The refined vertices themselves approach the curve at rate 4^-levels.
    let r = c.refine_levels(12).unwrap();
    let worst = (0..r.points().len())
        .map(|m| (r.points()[m] - c.eval(m as f64 / 4096.0).unwrap()).norm())
        .fold(0.0, f64::max);
    assert!(worst < 1e-6, "{worst}");
    assert!(worst > 0.0);
}

#[test]
fn sharp_sharp_segment_is_the_line_of_eq_2() {
    let a = Vector2::new(1.0, 2.0);
    let b = Vector2::new(4.0, -2.0);
    let c = SubdivCurve::with_sharp(vec![a, b], &[0, 1], subdiv_fit::Closure::Open).unwrap();
    for k in 0..=8 {
        let u = k as f64 / 8.0;
        let x = c.eval_segment(0, u).unwrap();
        assert!((x - ((1.0 - u) * a + u * b)).norm() < 1e-14);
    }
}

#[test]
fn eigen_decomposition_identities() {
    let a = sharp_matrix();
    let u = eigenvectors();
    let ui = eigenvectors_inverse();
    let d = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::from(EIGENVALUES));
    assert!((u * ui - nalgebra::Matrix3::identity()).norm() == 0.0);
    assert!((a * u - u * d).norm() == 0.0);
    assert!((u * d * ui - a).norm() == 0.0);
    // Ā's first three rows are A; its last row is the E-vertex (p1 + p2) / 2.
    let ab = extended_sharp_matrix();
    assert_eq!(ab.fixed_rows::<3>(0).into_owned(), a);
    // Refining the sharp sub-polygon once is A, checked against `refine`.
    let p = [
        Vector2::new(0.0, 0.0),
        Vector2::new(2.0, 1.0),
        Vector2::new(3.0, 5.0),
    ];
    let c = SubdivCurve::with_sharp(p.to_vec(), &[0, 2], subdiv_fit::Closure::Open).unwrap();
    let r = c.refine();
    for row in 0..3 {
        let expect = p[0] * a[(row, 0)] + p[1] * a[(row, 1)] + p[2] * a[(row, 2)];
        assert_eq!(r.points()[row], expect);
    }
}

#[test]
fn limit_masks() {
    let p = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(6.0, 0.0),
        Vector2::new(6.0, 6.0),
        Vector2::new(0.0, 6.0),
    ];
    let c = SubdivCurve::with_sharp(p, &[2], subdiv_fit::Closure::Closed).unwrap();
    assert_eq!(c.eval(2.0).unwrap(), Vector2::new(6.0, 6.0));
    assert!((c.eval(1.0).unwrap() - Vector2::new(5.0, 1.0)).norm() < 1e-14);
    assert!((c.eval(0.0).unwrap() - Vector2::new(1.0, 1.0)).norm() < 1e-14);
}

#[test]
fn bad_input_gives_typed_errors() {
    let p = vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0)];
    assert!(matches!(
        SubdivCurve::smooth(p.clone(), subdiv_fit::Closure::Closed),
        Err(SubdivFitError::TooFewPoints { got: 2, needed: 3 })
    ));
    assert!(matches!(
        SubdivCurve::with_sharp(p[..1].to_vec(), &[], subdiv_fit::Closure::Open),
        Err(SubdivFitError::TooFewPoints { .. })
    ));
    assert!(matches!(
        SubdivCurve::new(
            p.clone(),
            vec![VertexKind::Regular; 3],
            subdiv_fit::Closure::Open
        ),
        Err(SubdivFitError::FlagCount {
            flags: 3,
            points: 2
        })
    ));
    assert!(matches!(
        SubdivCurve::new(
            vec![p[0], Vector2::new(f64::NAN, 0.0)],
            vec![VertexKind::Regular; 2],
            subdiv_fit::Closure::Open
        ),
        Err(SubdivFitError::NonFinite { index: 1 })
    ));
    assert!(matches!(
        SubdivCurve::with_sharp(p.clone(), &[2], subdiv_fit::Closure::Open),
        Err(SubdivFitError::SegmentOutOfRange { index: 2, count: 2 })
    ));
    let c = SubdivCurve::smooth(p, subdiv_fit::Closure::Open).unwrap();
    assert_eq!(c.kinds(), &[VertexKind::Sharp, VertexKind::Sharp]);
    assert!(matches!(
        c.eval(1.5),
        Err(SubdivFitError::ParameterOutOfRange { .. })
    ));
    assert!(matches!(
        c.eval_segment(0, -0.1),
        Err(SubdivFitError::ParameterOutOfRange { .. })
    ));
    assert!(matches!(
        c.eval_segment(1, 0.5),
        Err(SubdivFitError::SegmentOutOfRange { index: 1, count: 1 })
    ));
    assert!(matches!(
        c.limit_position(2),
        Err(SubdivFitError::SegmentOutOfRange { .. })
    ));
    assert!(eval_sharp_segment_eigen(&[c.points()[0]; 3], 2.0).is_err());
}

#[test]
fn svg_path_has_one_cubic_per_segment() {
    let p = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 0.0),
        Vector2::new(1.0, 1.0),
    ];
    let c = SubdivCurve::smooth(p, subdiv_fit::Closure::Closed).unwrap();
    let s = subdiv_fit::svg_path(&c).unwrap();
    assert_eq!(s.matches(" C ").count(), 3);
    assert!(s.starts_with("M ") && s.ends_with(" Z"));
}
