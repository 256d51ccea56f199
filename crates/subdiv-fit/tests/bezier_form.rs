//! `Segment` through the `BezierForm` trait against the B-spline evaluation of the segment.

use bez_core::proptest_support::check_bezier_form;
use bez_core::{BezierForm, Vector2, Vector3};
use subdiv_fit::{SubdivCurve, SubdivFitError};

#[test]
fn segments_match_the_bspline_evaluation_through_the_trait() {
    // Closed, with one sharp corner: segments next to it use the phantom point.
    let polygon = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(2.0, -0.5),
        Vector2::new(3.0, 1.0),
        Vector2::new(1.5, 2.5),
        Vector2::new(-0.5, 1.5),
    ];
    let curve = SubdivCurve::with_sharp(polygon, &[0, 3], subdiv_fit::Closure::Closed).unwrap();
    for i in 0..curve.segment_count() {
        let segment = curve.segment(i).unwrap();
        assert_eq!(segment.index(), i);
        assert_eq!(segment.controls(), &curve.segment_controls(i).unwrap());
        assert_eq!(segment.as_bezier(), &curve.segment_bezier(i).unwrap());
        let r = check_bezier_form(
            &segment,
            |u| curve.eval_segment(i, u).unwrap(),
            |u| curve.eval_segment_derivatives(i, u).unwrap().first,
            1e-13,
        );
        assert_eq!(r, Ok(()), "segment {i}");
    }
    assert!(matches!(
        curve.segment(5),
        Err(SubdivFitError::SegmentOutOfRange { index: 5, count: 5 })
    ));
}

#[test]
fn open_spatial_segments_match_through_the_trait() {
    let polygon: Vec<Vector3> = (0..5)
        .map(|i| {
            let a = f64::from(i);
            Vector3::new(a, (0.8 * a).sin(), 0.2 * a * a)
        })
        .collect();
    let curve = SubdivCurve::smooth(polygon, subdiv_fit::Closure::Open).unwrap();
    for i in 0..curve.segment_count() {
        let segment = curve.segment(i).unwrap();
        let r = check_bezier_form(
            &segment,
            |u| curve.eval_segment(i, u).unwrap(),
            |u| curve.eval_segment_derivatives(i, u).unwrap().first,
            1e-13,
        );
        assert_eq!(r, Ok(()), "segment {i}");
        assert_eq!(
            segment.clone().into_bezier(),
            curve.to_beziers().unwrap()[i]
        );
    }
}
