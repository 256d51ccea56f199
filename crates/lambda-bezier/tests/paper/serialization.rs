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
