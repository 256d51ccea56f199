//! class-a's planar and spatial solvers from arbitrary points and degrees: a curve or an
//! error, never a panic, and returned curves are finite.
#![no_main]

use bez_core::{Vector2, Vector3};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let nums: Vec<f64> = data
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap_or([0; 8])))
        .collect();
    if nums.len() < 13 {
        return;
    }
    let degree = (nums[0].abs() as usize) % 64;
    let (a0, a1, a2) = (
        Vector2::new(nums[1], nums[2]),
        Vector2::new(nums[3], nums[4]),
        Vector2::new(nums[5], nums[6]),
    );
    if let Ok(t) = class_a::TypicalPlanar::from_points(&a0, &a1, &a2, degree) {
        if let Ok(c) = t.curve() {
            assert!(c.points().iter().all(Vector2::is_finite));
        }
    }
    let a = [
        Vector3::new(nums[1], nums[2], nums[7]),
        Vector3::new(nums[3], nums[4], nums[8]),
        Vector3::new(nums[5], nums[6], nums[9]),
        Vector3::new(nums[10], nums[11], nums[12]),
    ];
    let _ = class_a::TypicalSpatial::from_points(&a, degree);
});
