//! Every `Deserialize` data type from arbitrary JSON: deserialization validates like the
//! constructors, so a value that deserializes behaves like a constructed one (its methods
//! give a value or an error, never a panic, and no `Ok` holds a NaN or an infinity).
#![no_main]

use bez_core::{BezierCurve, BezierForm, BezierSurface, Vector2, Vector3};
use libfuzzer_sys::fuzz_target;

/// Deserializes `json` as `T` and, when that succeeds, serializes it again: a value that
/// was accepted must round-trip.
fn round_trip<T: serde::de::DeserializeOwned + serde::Serialize>(json: &[u8]) -> Option<T> {
    let value: T = serde_json::from_slice(json).ok()?;
    let again = serde_json::to_vec(&value).expect("an accepted value serializes");
    assert!(serde_json::from_slice::<T>(&again).is_ok(), "an accepted value round-trips");
    Some(value)
}

fuzz_target!(|data: &[u8]| {
    let Some((&which, json)) = data.split_first() else { return };
    match which % 12 {
        0 => {
            if let Some(c) = round_trip::<BezierCurve<2>>(json) {
                if let Ok(p) = c.eval(0.5) {
                    assert!(p.is_finite());
                }
                let b = c.bounding_box();
                assert!(b.min.is_finite() && b.max.is_finite());
            }
        }
        1 => {
            if let Some(c) = round_trip::<BezierCurve<3>>(json) {
                if let Ok(k) = c.curvature(0.25) {
                    assert!(k.is_finite());
                }
            }
        }
        2 => {
            if let Some(s) = round_trip::<BezierSurface<3>>(json) {
                if let Ok(p) = s.eval(0.5, 0.5) {
                    assert!(p.is_finite());
                }
            }
        }
        3 => {
            if let Some(b) = round_trip::<lambda_bezier::LambdaBasis>(json) {
                let mut row = vec![0.0; b.n() + 1];
                if b.row(0.5, &mut row).is_ok() {
                    assert!(row.iter().all(|v| v.is_finite()));
                }
            }
        }
        4 => {
            let _ = round_trip::<lambda_bezier::LambdaRange>(json);
        }
        5 => {
            if let Some(c) = round_trip::<lambda_bezier::LambdaBezierCurve<2>>(json) {
                if let Ok(p) = c.eval(0.5) {
                    assert!(p.is_finite());
                }
            }
        }
        6 => {
            if let Some(s) = round_trip::<lambda_bezier::LambdaBezierSurface<3>>(json) {
                if let Ok(p) = s.as_bezier().eval(0.5, 0.5) {
                    assert!(p.is_finite());
                }
            }
        }
        7 => {
            if let Some(t) = round_trip::<class_a::TypicalPlanar>(json) {
                if let Ok(c) = t.curve() {
                    assert!(c.points().iter().all(Vector2::is_finite));
                }
            }
        }
        8 => {
            if let Some(t) = round_trip::<class_a::TypicalSpatial>(json) {
                if let Ok(c) = t.curve() {
                    assert!(c.points().iter().all(Vector3::is_finite));
                }
            }
        }
        9 => {
            if let Some(c) = round_trip::<subdiv_fit::SubdivCurve<2>>(json) {
                let _ = subdiv_fit::svg_path(&c);
            }
        }
        10 => {
            if let Some(s) = round_trip::<pde_bezier::BSplineSurface>(json) {
                if s.validate().is_ok() {
                    if let Ok(p) = s.eval(0.5, 0.5) {
                        assert!(p.is_finite());
                    }
                }
            }
        }
        _ => {
            let _ = round_trip::<pde_bezier::Problem>(json);
            let _ = round_trip::<pde_bezier::Discretization>(json);
            let _ = round_trip::<pde_bezier::PatchGrid>(json);
        }
    }
});
