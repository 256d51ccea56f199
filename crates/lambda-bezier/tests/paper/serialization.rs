//! Serialization round trips and validation on deserialization (feature `serde`).
#![cfg(feature = "serde")]

use bez_core::Vector2;
use lambda_bezier::{LambdaBezierCurve, LambdaBezierSurface};

#[test]
fn curve_round_trip_and_rejects_bad_lambda() {
    let c = LambdaBezierCurve::new(
        vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 1.0),
            Vector2::new(2.0, 0.0),
        ],
        -1.5,
    )
    .unwrap();
    let s = serde_json::to_string(&c).unwrap();
    let back: LambdaBezierCurve<2> = serde_json::from_str(&s).unwrap();
    assert_eq!(back, c);
    let bad = s.replace("-1.5", "-2.5");
    assert!(serde_json::from_str::<LambdaBezierCurve<2>>(&bad).is_err());
}

#[test]
fn surface_round_trip() {
    let rows: Vec<Vec<Vector2>> = (0..3)
        .map(|i| {
            (0..4)
                .map(|j| Vector2::new(f64::from(i), f64::from(j)))
                .collect()
        })
        .collect();
    let s = LambdaBezierSurface::new(rows, 0.5, -3.0).unwrap();
    let json = serde_json::to_string(&s).unwrap();
    let back: LambdaBezierSurface<2> = serde_json::from_str(&json).unwrap();
    assert_eq!(back, s);
}

#[test]
fn basis_and_range_deserialization_validates() {
    use lambda_bezier::{LambdaBasis, LambdaRange};
    let b = LambdaBasis::new(4, 0.5).unwrap();
    let back: LambdaBasis = serde_json::from_str(&serde_json::to_string(&b).unwrap()).unwrap();
    assert_eq!(back, b);
    for bad in [
        r#"{"n":1,"lambda":0.5}"#,
        r#"{"n":18446744073709551615,"lambda":0.5}"#,
        r#"{"n":4,"lambda":1e999}"#,
    ] {
        assert!(serde_json::from_str::<LambdaBasis>(bad).is_err(), "{bad}");
    }
    let r = LambdaRange::new(6).unwrap();
    let json = serde_json::to_string(&r).unwrap();
    assert_eq!(json, r#"{"n":6}"#);
    let back: LambdaRange = serde_json::from_str(&json).unwrap();
    assert_eq!((back.min(), back.max()), (r.min(), r.max()));
    for bad in [r#"{"n":0}"#, r#"{"n":18446744073709551615}"#] {
        assert!(serde_json::from_str::<LambdaRange>(bad).is_err(), "{bad}");
    }
}
