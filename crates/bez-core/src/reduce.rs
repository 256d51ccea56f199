//! Degree reduction by one, with an error bound.

use nalgebra::{DMatrix, SVector};

use crate::curve::BezierCurve;
use crate::error::CoreError;

/// A degree-reduced curve and the bound on how far it is from the original.
#[derive(Debug, Clone, PartialEq)]
pub struct Reduced<const D: usize> {
    /// The curve of degree n − 1.
    pub curve: BezierCurve<D>,
    /// An upper bound on max_t |B(t) − R(t)|: the largest distance between the original
    /// control points and those of R elevated back to degree n (convex hull property).
    pub error_bound: f64,
}

impl<const D: usize> BezierCurve<D> {
    /// The degree n − 1 curve R minimizing Σᵢ |Pᵢ − (E R)ᵢ|², E the degree-elevation matrix.
    ///
    /// This is the discrete least-squares reduction on control points (unconstrained, so the
    /// endpoints may move): solved per coordinate by an SVD of E. The returned `error_bound`
    /// bounds the true maximum deviation, because B − R is a degree-n curve whose control
    /// points are Pᵢ − (E R)ᵢ. When the curve is an elevated degree n − 1 curve, R is that curve
    /// and the bound is at rounding level. Cost O(n³).
    ///
    /// # Errors
    /// [`CoreError::DegreeTooLow`] for a degree-0 curve.
    pub fn reduce_degree(&self) -> Result<Reduced<D>, CoreError> {
        let n = self.degree();
        if n == 0 {
            return Err(CoreError::DegreeTooLow {
                needed: 1,
                degree: 0,
            });
        }
        // E maps degree n − 1 control points to degree n: row i mixes Q_{i−1} and Q_i.
        let mut e = DMatrix::<f64>::zeros(n + 1, n);
        for i in 0..=n {
            let a = i as f64 / n as f64;
            if i > 0 {
                e[(i, i - 1)] = a;
            }
            if i < n {
                e[(i, i)] = 1.0 - a;
            }
        }
        let rhs = DMatrix::from_fn(n + 1, D, |i, d| self.points()[i][d]);
        let svd = e.clone().svd(true, true);
        let sol = svd
            .solve(&rhs, 1e-14)
            .map_err(|_| CoreError::DegreeTooLow {
                needed: 1,
                degree: n,
            })?;
        let points: Vec<SVector<f64, D>> = (0..n)
            .map(|i| SVector::from_fn(|d, _| sol[(i, d)]))
            .collect();
        if let Some(index) = points.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(CoreError::NonFinite { index });
        }
        let back = &e * &sol;
        let error_bound = (0..=n)
            .map(|i| (SVector::<f64, D>::from_fn(|d, _| back[(i, d)]) - self.points()[i]).norm())
            .fold(0.0, f64::max);
        Ok(Reduced {
            curve: BezierCurve::from_valid(points),
            error_bound,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    #[test]
    fn reduction_inverts_elevation() {
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 3.0),
            Vector2::new(2.0, -1.0),
            Vector2::new(4.0, 0.5),
        ])
        .unwrap();
        let r = c.elevate(1).unwrap().reduce_degree().unwrap();
        assert!(r.error_bound < 1e-13);
        for (a, b) in r.curve.points().iter().zip(c.points()) {
            assert!((a - b).norm() < 1e-13);
        }
    }

    #[test]
    fn reduction_bound_holds_on_the_curve() {
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 3.0),
            Vector2::new(2.0, -1.0),
            Vector2::new(4.0, 0.5),
        ])
        .unwrap();
        let r = c.reduce_degree().unwrap();
        assert!(r.error_bound > 1e-3);
        for k in 0..=100 {
            let t = k as f64 / 100.0;
            let d = (c.eval(t).unwrap() - r.curve.eval(t).unwrap()).norm();
            assert!(d <= r.error_bound + 1e-14);
        }
        let point = BezierCurve::new(vec![Vector2::new(1.0, 1.0)]).unwrap();
        assert_eq!(
            point.reduce_degree(),
            Err(CoreError::DegreeTooLow {
                needed: 1,
                degree: 0
            })
        );
    }
}
