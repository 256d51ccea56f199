//! Helpers shared by the integration tests.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{HausdorffSampling, measured_hausdorff};

/// [`measured_hausdorff`] at the density the tests use: 3001 curve samples, 9 per segment.
pub(crate) fn hausdorff(c: &BezierCurve<2>, poly: &[Vector2]) -> f64 {
    let sampling = HausdorffSampling {
        curve_samples: 3001,
        segment_samples: 9,
    };
    measured_hausdorff(c, poly, sampling).unwrap()
}
