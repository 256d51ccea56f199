//! Fixtures shared by the unit tests of the flattening modes.

use bez_core::{BezierCurve, Vector2};

use crate::SubdivError;

/// The curve with control points `points` (at least one).
pub(crate) fn curve(points: &[(f64, f64)]) -> BezierCurve<2> {
    BezierCurve::new(points.iter().map(|&(x, y)| Vector2::new(x, y)).collect())
        .unwrap_or_else(|_| unreachable!("valid test points"))
}

/// Checks the typed errors of a mode `flatten(curve, tolerance, max_depth)`: every invalid
/// tolerance, a depth cap too small for the tolerance, a degree-0 curve.
pub(crate) fn assert_typed_errors<T: core::fmt::Debug>(
    flatten: impl Fn(&BezierCurve<2>, f64, usize) -> Result<T, SubdivError>,
) {
    let c = curve(&[(0.0, 0.0), (1.0, 5.0), (2.0, 0.0)]);
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let result = flatten(&c, bad, 40);
        assert!(
            matches!(result, Err(SubdivError::InvalidTolerance { .. })),
            "tolerance {bad}: {result:?}"
        );
    }
    let result = flatten(&c, 1e-9, 3);
    assert!(
        matches!(result, Err(SubdivError::DepthLimit { limit: 3 })),
        "{result:?}"
    );
    let result = flatten(&curve(&[(0.0, 0.0)]), 1.0, 40);
    assert!(
        matches!(result, Err(SubdivError::TooFewPoints { got: 1 })),
        "{result:?}"
    );
}
