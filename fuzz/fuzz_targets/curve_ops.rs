//! bez-core curves and lambda-bezier curves from arbitrary numbers: every operation returns
//! a value or an error, and no `Ok` holds a NaN or an infinity.
#![no_main]

use bez_core::{BezierCurve, BezierForm, Vector2};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let nums: Vec<f64> = data
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap_or([0; 8])))
        .collect();
    let Some((&t, rest)) = nums.split_first() else { return };
    let Some((&lambda, rest)) = rest.split_first() else { return };
    let pts: Vec<Vector2> = rest.chunks_exact(2).map(|c| Vector2::new(c[0], c[1])).collect();
    if let Ok(c) = BezierCurve::new(pts.clone()) {
        if let Ok(p) = c.eval(t) {
            assert!(p.is_finite());
        }
        if let Ok((l, r)) = c.split(t) {
            assert!(l.points().iter().chain(r.points()).all(Vector2::is_finite));
        }
        if let Ok(k) = c.curvature(t) {
            assert!(k.is_finite());
        }
        if let Ok(n) = c.nearest(&Vector2::new(lambda, t)) {
            assert!(n.distance.is_finite());
        }
        if let Ok(l) = c.arc_length(1e-6) {
            assert!(l.is_finite());
        }
        let b = c.bounding_box();
        assert!(b.min.is_finite() && b.max.is_finite());
    }
    if let Ok(c) = lambda_bezier::LambdaBezierCurve::new(pts, lambda) {
        if let Ok(p) = c.eval(t) {
            assert!(p.is_finite());
        }
    }
});
