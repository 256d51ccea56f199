//! Measures of a planar control polygon: flatness (Def. 2.2), chord distance (eq. (3)),
//! convex-hull area (Def. 2.1).

use bez_core::Vector2;

/// Distance of `p` to the line through `a` and `b`; to the point `a` when a = b.
///
/// The fallback makes pieces whose ends coincide (closed loops) measurable: NOTES decision.
#[must_use]
pub fn distance_to_chord_line(p: &Vector2, a: &Vector2, b: &Vector2) -> f64 {
    let d = b - a;
    let len = d.norm();
    let w = p - a;
    if len == 0.0 {
        w.norm()
    } else {
        (d.x() * w.y() - d.y() * w.x()).abs() / len
    }
}

/// Flatness Dis (Ma et al., Def. 2.2): Σ_{i=1}^{n−1} D(P₀Pₙ, Pᵢ)², the sum of squared distances
/// of the interior control points to the chord line P₀Pₙ (to P₀ when P₀ = Pₙ).
///
/// Zero for fewer than three points.
#[must_use]
pub fn flatness(points: &[Vector2]) -> f64 {
    match points {
        [a, interior @ .., b] => interior
            .iter()
            .map(|p| distance_to_chord_line(p, a, b).powi(2))
            .sum(),
        _ => 0.0,
    }
}

/// The numerator of eq. (3): max_{i=1..n−1} D(P₀Pₙ, Pᵢ), the largest distance of an interior
/// control point to the chord line (to P₀ when P₀ = Pₙ). Zero for fewer than three points.
///
/// Equal, bit for bit, to the largest [`distance_to_chord_line`]: the cross products are
/// compared first and divided once by |PₙP₀| (rounding is monotone, so the largest quotient is
/// the quotient of the largest numerator); one square root per polygon instead of one per point.
#[must_use]
pub fn max_chord_distance(points: &[Vector2]) -> f64 {
    let [a, interior @ .., b] = points else {
        return 0.0;
    };
    let d = b - a;
    let len = d.norm();
    if len == 0.0 {
        return interior
            .iter()
            .map(|p| distance_to_chord_line(p, a, b))
            .fold(0.0, f64::max);
    }
    max_cross(a, &d, interior) / len
}

/// c = maxᵢ |d × (Pᵢ − a)| over `interior`: |d| times the largest distance to the line through
/// `a` with direction `d` (0 for no points).
#[inline]
fn max_cross(a: &Vector2, d: &Vector2, interior: &[Vector2]) -> f64 {
    interior
        .iter()
        .map(|p| {
            let w = p - a;
            (d.x() * w.y() - d.y() * w.x()).abs()
        })
        .fold(0.0, f64::max)
}

/// Relative margin under which [`within_chord_line`] falls back to the exact quotient: far above
/// the few rounding errors (≈ 1e-15) by which the squared test can differ from the quotient.
const SQUARED_TEST_MARGIN: f64 = 1e-9;

/// Eq. (3)'s stopping test, `max_chord_distance(points) <= limit`, with the same answer bit for
/// bit, but without a square root or a division in nearly every case.
///
/// With c = max |(Pₙ − P₀) × (Pᵢ − P₀)| and l² = |Pₙ − P₀|², c / l ≤ limit ⟺ c² ≤ limit² l².
/// The squared comparison decides when the two sides differ by more than
/// [`SQUARED_TEST_MARGIN`] (relative) and limit² l² is a normal number; otherwise the quotient of
/// [`max_chord_distance`] decides.
#[inline]
pub(crate) fn within_chord_line(points: &[Vector2], limit: f64) -> bool {
    if let [a, interior @ .., b] = points {
        let d = b - a;
        let len2 = d.norm_squared();
        let cross = max_cross(a, &d, interior);
        let lhs = cross * cross;
        let rhs = limit * limit * len2;
        // With limit² l² normal and finite, an underflow of c² only makes it smaller than a
        // normal number, an overflow larger than a finite one: both answers stay right.
        if (f64::MIN_POSITIVE..=f64::MAX).contains(&rhs) {
            if lhs < rhs * (1.0 - SQUARED_TEST_MARGIN) {
                return true;
            }
            if lhs > rhs * (1.0 + SQUARED_TEST_MARGIN) {
                return false;
            }
        }
    }
    max_chord_distance(points) <= limit
}

/// Area of the convex hull of the control points (Def. 2.1), by Andrew's monotone chain.
///
/// O(n log n). Zero for fewer than three points or collinear points.
#[must_use]
pub fn hull_area(points: &[Vector2]) -> f64 {
    if points.len() < 3 {
        return 0.0;
    }
    let mut pts: Vec<Vector2> = points.to_vec();
    pts.sort_by(|a, b| a.x().total_cmp(&b.x()).then(a.y().total_cmp(&b.y())));
    let cross = |o: &Vector2, a: &Vector2, b: &Vector2| {
        (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x())
    };
    let mut hull: Vec<Vector2> = Vec::with_capacity(2 * pts.len());
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &Vector2>> = if pass == 0 {
            Box::new(pts.iter())
        } else {
            Box::new(pts.iter().rev())
        };
        for p in iter {
            while hull.len() >= start + 2
                && cross(&hull[hull.len() - 2], &hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(*p);
        }
        hull.pop();
    }
    // Shoelace formula over the counter-clockwise hull.
    let n = hull.len();
    let twice: f64 = (0..n)
        .map(|i| {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            a.x() * b.y() - a.y() * b.x()
        })
        .sum();
    0.5 * twice.abs()
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    fn v(x: f64, y: f64) -> Vector2 {
        Vector2::new(x, y)
    }

    #[test]
    fn hull_area_of_square_with_interior_points() {
        let pts = [
            v(0.0, 0.0),
            v(0.5, 0.5),
            v(2.0, 0.0),
            v(2.0, 2.0),
            v(1.0, 1.2),
            v(0.0, 2.0),
        ];
        assert!((hull_area(&pts) - 4.0).abs() < 1e-15);
        assert_eq!(hull_area(&[v(0.0, 0.0), v(1.0, 1.0), v(2.0, 2.0)]), 0.0);
    }

    fn polygon() -> impl Strategy<Value = Vec<Vector2>> {
        proptest::collection::vec((-10.0..10.0f64, -10.0..10.0f64), 2..8)
            .prop_map(|p| p.into_iter().map(|(x, y)| v(x, y)).collect())
    }

    proptest! {
        /// The squared test answers as the quotient does, also at the limit itself and one ulp
        /// either side of it, where the margin hands over to the quotient.
        #[test]
        fn squared_test_equals_quotient_test(pts in polygon(), scale in 1e-3..1e3f64) {
            let m = max_chord_distance(&pts);
            for limit in [m, m.next_up(), m.next_down(), m * scale, m * (1.0 + 1e-12)] {
                prop_assert_eq!(within_chord_line(&pts, limit), m <= limit, "limit {}", limit);
            }
        }
    }

    #[test]
    fn squared_test_outside_the_normal_range() {
        let huge = [v(0.0, 0.0), v(1e200, 3e200), v(2e200, 0.0)];
        let tiny = [v(0.0, 0.0), v(1e-200, 3e-200), v(2e-200, 0.0)];
        for pts in [&huge[..], &tiny[..]] {
            let m = max_chord_distance(pts);
            for limit in [m, m.next_down(), m * 0.5, m * 2.0, 1e-300, 1e300] {
                assert_eq!(within_chord_line(pts, limit), m <= limit);
            }
        }
    }

    #[test]
    fn flatness_and_chord_distance() {
        let pts = [v(0.0, 0.0), v(1.0, 1.0), v(2.0, -2.0), v(3.0, 0.0)];
        assert!((flatness(&pts) - 5.0).abs() < 1e-15);
        assert!((max_chord_distance(&pts) - 2.0).abs() < 1e-15);
        // Closed piece: distances to P₀.
        let closed = [v(0.0, 0.0), v(3.0, 4.0), v(0.0, 0.0)];
        assert!((max_chord_distance(&closed) - 5.0).abs() < 1e-15);
        assert_eq!(flatness(&pts[..2]), 0.0);
    }
}
