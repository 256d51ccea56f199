//! bez-subdiv's flattening from arbitrary control points, tolerances, methods and depth
//! limits: a polyline or an error, never a panic or unbounded work, and every point finite.
#![no_main]

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{Flattener, Method};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else { return };
    let nums: Vec<f64> = rest
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap_or([0; 8])))
        .collect();
    let Some((&tolerance, coords)) = nums.split_first() else { return };
    let points: Vec<Vector2> = coords.chunks_exact(2).map(|c| Vector2::new(c[0], c[1])).collect();
    let Ok(curve) = BezierCurve::new(points) else { return };
    let method = match selector % 4 {
        0 => Method::Fast,
        1 => Method::LocalWang,
        2 => Method::Halving,
        _ => Method::Optimal,
    };
    let flattener = Flattener::new(tolerance)
        .with_method(method)
        .with_max_depth(usize::from(selector / 4));
    let mut count = 0usize;
    if let Ok(segments) = flattener.flatten(&curve, |p| {
        assert!(p.point.is_finite() && p.t.is_finite());
        count += 1;
    }) {
        assert_eq!(count, segments + 1);
    }
});
