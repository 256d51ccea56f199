//! serde JSON round trips (deserialization validates) and glam interop.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, BezierSurface, Vector2, Vector3};

#[test]
fn curve_and_surface_json_round_trip() {
    let c = BezierCurve::new(vec![
        Vector2::new(0.0, 1.5),
        Vector2::new(-2.0, 3.25),
        Vector2::new(4.0, 0.1),
    ])
    .unwrap();
    let json = serde_json::to_string(&c).unwrap();
    let back: BezierCurve<2> = serde_json::from_str(&json).unwrap();
    assert_eq!(back, c);

    let s = BezierSurface::new(vec![
        vec![
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(0.0, 1.0, 0.5),
            Vector3::new(0.0, 2.0, 0.0),
        ],
        vec![
            Vector3::new(1.0, 0.0, 1.0),
            Vector3::new(1.0, 1.0, 2.0),
            Vector3::new(1.0, 2.0, 1.0),
        ],
    ])
    .unwrap();
    let back: BezierSurface<3> = serde_json::from_str(&serde_json::to_string(&s).unwrap()).unwrap();
    assert_eq!(back, s);
}

#[test]
fn deserialization_validates() {
    assert!(serde_json::from_str::<BezierCurve<2>>(r#"{"points":[]}"#).is_err());
    assert!(
        serde_json::from_str::<BezierSurface<3>>(
            r#"{"degree_u":1,"degree_v":1,"points":[[0,0,0]]}"#
        )
        .is_err()
    );
}

#[test]
fn vectors_serialize_as_flat_sequences() {
    assert_eq!(
        serde_json::to_string(&Vector2::new(1.5, -2.0)).unwrap(),
        "[1.5,-2.0]"
    );
    let c = BezierCurve::new(vec![Vector2::new(0.0, 1.5), Vector2::new(2.0, 3.0)]).unwrap();
    assert_eq!(
        serde_json::to_string(&c).unwrap(),
        r#"{"points":[[0.0,1.5],[2.0,3.0]]}"#
    );
    let v: Vector3 = serde_json::from_str("[1, -2.5, 3e2]").unwrap();
    assert_eq!(v, Vector3::new(1.0, -2.5, 300.0));
    // Wrong lengths and wrong element types are rejected.
    assert!(serde_json::from_str::<Vector3>("[1, 2]").is_err());
    assert!(serde_json::from_str::<Vector3>("[1, 2, 3, 4]").is_err());
    assert!(serde_json::from_str::<Vector2>("[]").is_err());
    assert!(serde_json::from_str::<Vector2>(r#"[1, "y"]"#).is_err());
    assert!(serde_json::from_str::<Vector2>(r#"{"x": 1, "y": 2}"#).is_err());
    assert!(serde_json::from_str::<BezierCurve<2>>(r#"{"points":[[0,0],[1,2,3]]}"#).is_err());
}

#[test]
fn glam_conversions_round_trip() {
    use glam::{DVec2, DVec3};
    let v = Vector3::new(1.0, -2.0, 3.5);
    assert_eq!(DVec3::from(v), DVec3::new(1.0, -2.0, 3.5));
    assert_eq!(Vector3::from(DVec3::from(v)), v);
    let w = Vector2::new(0.25, 8.0);
    let g: DVec2 = w.into();
    assert_eq!((g.x, g.y), (0.25, 8.0));
    assert_eq!(Vector2::from(g), w);
}
