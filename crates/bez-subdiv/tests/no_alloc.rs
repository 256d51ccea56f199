//! `Method::Optimal` and `Method::Fast` flatten to a sink without a single heap allocation at
//! every degree up to `MAX_STACK_DEGREE`, counted by a global allocator (allocation-counter,
//! per thread).
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{Flattener, MAX_STACK_DEGREE, Method, curve_size};

/// A wavy curve of `degree` (every control point different, curvature changing sign).
fn wavy(degree: usize) -> BezierCurve<2> {
    BezierCurve::new(
        (0..=degree)
            .map(|i| {
                let x = i as f64;
                Vector2::new(
                    x + 0.3 * (1.7 * x).sin(),
                    (0.9 * x).sin() + 0.2 * (2.3 * x).cos(),
                )
            })
            .collect(),
    )
    .unwrap()
}

/// Heap allocations made while flattening `curve` with `method` at `rel` × size, and the
/// number of segments.
fn allocations(curve: &BezierCurve<2>, method: Method, rel: f64) -> (u64, usize) {
    let flattener = Flattener::new(rel * curve_size(curve)).with_method(method);
    let mut segments = 0;
    let mut sum = 0.0;
    let info = allocation_counter::measure(|| {
        segments = flattener
            .flatten(curve, |p| sum += p.t + p.point.x())
            .unwrap();
    });
    assert!(sum.is_finite());
    (info.count_total, segments)
}

#[test]
fn optimal_and_fast_do_not_allocate_up_to_the_stack_degree() {
    // The counter counts: a vector is one allocation.
    let info = allocation_counter::measure(|| {
        std::hint::black_box(vec![1.0_f64; 4]);
    });
    assert_eq!(info.count_total, 1);
    for degree in 1..=MAX_STACK_DEGREE {
        let curve = wavy(degree);
        for method in [Method::Optimal, Method::Fast] {
            for rel in [1e-2, 1e-4] {
                let (count, segments) = allocations(&curve, method, rel);
                assert!(segments >= 1);
                assert_eq!(count, 0, "degree {degree}, {method:?}, {rel}");
            }
        }
    }
}

/// Above the limit the working buffers are vectors: the limit is where it is documented.
#[test]
fn above_the_stack_degree_the_buffers_are_allocated() {
    let curve = wavy(MAX_STACK_DEGREE + 1);
    for method in [Method::Optimal, Method::Fast] {
        let (count, _) = allocations(&curve, method, 1e-3);
        assert!(count > 0, "{method:?}");
    }
}
