//! Nearest point on a curve.

use crate::vector::Vector;
use alloc::vec;
use alloc::vec::Vec;

use crate::bernstein::bernstein_product;
use crate::casteljau::hodograph_slice;
use crate::curve::BezierCurve;
use crate::error::CoreError;
use crate::limits::MAX_COORDINATE;
use crate::math;
use crate::roots::roots_in_unit_interval;

/// The result of a nearest-point query.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Nearest<const D: usize> {
    /// Parameter of the nearest point.
    pub t: f64,
    /// The nearest point B(t).
    pub point: Vector<D>,
    /// Its distance to the query point.
    pub distance: f64,
}

impl<const D: usize> BezierCurve<D> {
    /// The point of the curve nearest to `p` (global minimum over t ∈ [0, 1]).
    ///
    /// The stationary points solve (B(t) − p) · B'(t) = 0, a polynomial of degree 2n − 1 whose
    /// Bernstein coefficients are formed exactly by [`bernstein_product`]; all its roots in
    /// [0, 1] (and both endpoints) are candidates, so the answer is the global minimum, not a
    /// local one. Cost O(n²) plus root isolation.
    ///
    /// # Errors
    /// [`CoreError::NonFiniteQuery`] when `p` has a NaN or infinite coordinate,
    /// [`CoreError::QueryOutOfRange`] when one is outside ±[`MAX_COORDINATE`].
    pub fn nearest(&self, p: &Vector<D>) -> Result<Nearest<D>, CoreError> {
        if !p.iter().all(|x| x.is_finite()) {
            return Err(CoreError::NonFiniteQuery);
        }
        if let Some(&value) = p.iter().find(|x| x.abs() > MAX_COORDINATE) {
            return Err(CoreError::QueryOutOfRange {
                value,
                max: MAX_COORDINATE,
            });
        }
        let hodo = hodograph_slice(self.points());
        // Both factors scaled by powers of two into [1, 2) (exact; the roots do not change),
        // so the product's coefficients cannot overflow.
        let scale_a = math::pow2_scale(
            self.points()
                .iter()
                .map(|q| (q - p).amax())
                .fold(0.0, f64::max),
        );
        let scale_b = math::pow2_scale(hodo.iter().map(Vector::amax).fold(0.0, f64::max));
        let mut poly: Vec<f64> = Vec::new();
        let mut a = vec![0.0; self.points().len()];
        let mut b = vec![0.0; hodo.len()];
        for d in 0..D {
            for (x, q) in a.iter_mut().zip(self.points()) {
                *x = (q[d] - p[d]) / scale_a;
            }
            for (x, q) in b.iter_mut().zip(&hodo) {
                *x = q[d] / scale_b;
            }
            let prod = bernstein_product(&a, &b);
            if poly.is_empty() {
                poly = prod;
            } else {
                for (x, y) in poly.iter_mut().zip(prod) {
                    *x += y;
                }
            }
        }
        let mut best = candidate(self, p, 0.0);
        for t in roots_in_unit_interval(&poly).into_iter().chain([1.0]) {
            let c = candidate(self, p, t);
            if c.distance < best.distance {
                best = c;
            }
        }
        Ok(best)
    }
}

fn candidate<const D: usize>(c: &BezierCurve<D>, p: &Vector<D>, t: f64) -> Nearest<D> {
    let point = c.eval_unchecked(t);
    Nearest {
        t,
        point,
        distance: (point - p).norm(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::Vector2;

    #[test]
    fn nearest_on_parabola_beats_dense_sampling() {
        let c = BezierCurve::new(vec![
            Vector2::new(-1.0, 1.0),
            Vector2::new(0.0, -1.0),
            Vector2::new(1.0, 1.0),
        ])
        .unwrap();
        for q in [
            Vector2::new(0.0, 2.0),
            Vector2::new(0.7, -0.3),
            Vector2::new(3.0, 0.0),
        ] {
            let n = c.nearest(&q).unwrap();
            let sampled = (0..=20_000)
                .map(|k| (c.eval(k as f64 / 20_000.0).unwrap() - q).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(n.distance <= sampled + 1e-12);
            assert!(n.distance >= sampled - 1e-6);
        }
        assert!(c.nearest(&Vector2::new(f64::NAN, 0.0)).is_err());
    }
}
