//! subdiv-fit's SVG path input from arbitrary text and spacing, then a fit of each small
//! contour: samples or an error, never a panic; samples are finite, corners are indices of
//! samples, and a fitted curve's control points are finite.
#![no_main]

use libfuzzer_sys::fuzz_target;
use subdiv_fit::{FitOptions, fit_with_corners, sample_svg_path};

fuzz_target!(|data: &[u8]| {
    if data.len() < 8 {
        return;
    }
    let (head, text) = data.split_at(8);
    let spacing = f64::from_le_bytes(head.try_into().unwrap_or([0; 8]));
    let Ok(text) = std::str::from_utf8(text) else { return };
    let Ok(contours) = sample_svg_path(text, spacing) else { return };
    for contour in contours {
        assert!(contour.points.iter().all(|p| p.is_finite()));
        assert!(contour.corners.iter().all(|&i| i < contour.points.len()));
        if contour.points.len() >= 3 && contour.points.len() <= 2_000 {
            let options = FitOptions::new(spacing);
            if let Ok(f) = fit_with_corners(&contour.points, contour.closure, &contour.corners, &options) {
                assert!(f.curve.points().iter().all(|p| p.is_finite()));
            }
        }
    }
});
