//! Axis-aligned bounding boxes of control polygons and of curves.

use crate::vector::Vector;
use alloc::vec;

use crate::casteljau::hodograph_slice;
use crate::curve::BezierCurve;
use crate::roots::roots_in_unit_interval;

/// An axis-aligned box [min, max] in D dimensions.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Aabb<const D: usize> {
    /// Componentwise minimum.
    pub min: Vector<D>,
    /// Componentwise maximum.
    pub max: Vector<D>,
}

impl<const D: usize> Aabb<D> {
    /// The smallest box containing all `points`; `None` for an empty slice.
    #[must_use]
    pub fn from_points(points: &[Vector<D>]) -> Option<Self> {
        let first = *points.first()?;
        let mut b = Self {
            min: first,
            max: first,
        };
        for p in &points[1..] {
            b.include(p);
        }
        Some(b)
    }

    /// Grows the box to contain `p`.
    pub fn include(&mut self, p: &Vector<D>) {
        self.min = self.min.inf(p);
        self.max = self.max.sup(p);
    }

    /// Edge lengths max − min.
    #[must_use]
    pub fn size(&self) -> Vector<D> {
        self.max - self.min
    }

    /// Whether `p` lies in the box, with a tolerance `eps` on every side.
    #[must_use]
    pub fn contains(&self, p: &Vector<D>, eps: f64) -> bool {
        (0..D).all(|d| p[d] >= self.min[d] - eps && p[d] <= self.max[d] + eps)
    }
}

impl<const D: usize> BezierCurve<D> {
    /// Bounding box of the control points (contains the curve, by the convex hull property).
    #[must_use]
    pub fn control_bounding_box(&self) -> Aabb<D> {
        let p0 = self.start();
        let mut b = Aabb { min: p0, max: p0 };
        for p in self.points() {
            b.include(p);
        }
        b
    }

    /// The tight bounding box of the curve itself.
    ///
    /// Per coordinate: the endpoints and the curve at every root in [0, 1] of that coordinate's
    /// derivative (a polynomial in Bernstein form, roots by [`roots_in_unit_interval`]).
    /// Cost O(n²) per coordinate.
    #[must_use]
    pub fn bounding_box(&self) -> Aabb<D> {
        let mut b = Aabb {
            min: self.start(),
            max: self.start(),
        };
        b.include(&self.end());
        let hodo = hodograph_slice(self.points());
        let mut coeffs = vec![0.0; hodo.len()];
        for d in 0..D {
            for (c, p) in coeffs.iter_mut().zip(&hodo) {
                *c = p[d];
            }
            for t in roots_in_unit_interval(&coeffs) {
                b.include(&self.eval_unchecked(t));
            }
        }
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::Vector2;

    #[test]
    fn tight_box_of_a_symmetric_cubic() {
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(0.0, 4.0),
            Vector2::new(4.0, 4.0),
            Vector2::new(4.0, 0.0),
        ])
        .unwrap();
        let b = c.bounding_box();
        // y(½) = 3 is the maximum; x spans [0, 4].
        assert!((b.max.y() - 3.0).abs() < 1e-14);
        assert_eq!(b.min, Vector2::new(0.0, 0.0));
        assert!((b.max.x() - 4.0).abs() < 1e-14);
        assert_eq!(c.control_bounding_box().max, Vector2::new(4.0, 4.0));
    }
}
