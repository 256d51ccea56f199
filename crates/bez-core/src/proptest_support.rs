//! Shared proptest strategies (feature `proptest-support`), for this and dependent crates.

use crate::vector::Vector;
use proptest::prelude::*;

use crate::curve::BezierCurve;

/// Random finite control points with coordinates in [−range, range].
pub fn control_points<const D: usize>(
    degrees: core::ops::RangeInclusive<usize>,
    range: f64,
) -> impl Strategy<Value = Vec<Vector<D>>> {
    degrees.prop_flat_map(move |n| {
        proptest::collection::vec(
            proptest::array::uniform::<_, D>(-range..=range).prop_map(Vector::from),
            n + 1,
        )
    })
}

/// A random curve of degree in `degrees` with coordinates in [−range, range].
pub fn curve<const D: usize>(
    degrees: core::ops::RangeInclusive<usize>,
    range: f64,
) -> impl Strategy<Value = BezierCurve<D>> {
    control_points::<D>(degrees, range).prop_map(BezierCurve::from_valid)
}

/// A parameter in [0, 1], including both endpoints with positive probability.
pub fn unit_parameter() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0]
}
