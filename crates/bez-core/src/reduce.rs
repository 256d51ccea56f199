//! Degree reduction by one, with an error bound.

use crate::curve::BezierCurve;
use crate::error::CoreError;
use crate::math;
use crate::vector::Vector;
use alloc::vec;
use alloc::vec::Vec;

/// A degree-reduced curve and the bound on how far it is from the original.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
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
    /// endpoints may move). E is (n + 1) × n and lower bidiagonal (row i mixes Rᵢ₋₁ and Rᵢ with
    /// weights i/n and 1 − i/n), so it is solved by a QR factorization made of n Givens
    /// rotations: orthogonal transformations, so the
    /// conditioning is that of E itself, not of EᵀE as with the normal equations. The returned
    /// `error_bound` bounds the true maximum deviation, because B − R is a degree-n curve whose
    /// control points are Pᵢ − (E R)ᵢ. When the curve is an elevated degree n − 1 curve, R is
    /// that curve and the bound is at rounding level. Cost O(n·D).
    ///
    /// # Errors
    /// [`CoreError::DegreeTooLow`] for a degree-0 curve; [`CoreError::Overflow`] if a reduced
    /// control point leaves ±[`MAX_COORDINATE`](crate::MAX_COORDINATE).
    pub fn reduce_degree(&self) -> Result<Reduced<D>, CoreError> {
        let n = self.degree();
        if n == 0 {
            return Err(CoreError::DegreeTooLow {
                needed: 1,
                degree: 0,
            });
        }
        let points = least_squares_elevation(self.points());
        let curve = BezierCurve::checked_result(points, "reduce_degree")?;
        let error_bound = self
            .points()
            .iter()
            .enumerate()
            .map(|(i, p)| (elevated_point(curve.points(), i) - p).norm())
            .fold(0.0, f64::max);
        Ok(Reduced { curve, error_bound })
    }
}

/// Control point `i` of the degree-elevated polygon of `q` (degree m = q.len() − 1 to m + 1):
/// (i/(m+1)) Qᵢ₋₁ + (1 − i/(m+1)) Qᵢ, the terms at the ends omitted.
fn elevated_point<const D: usize>(q: &[Vector<D>], i: usize) -> Vector<D> {
    let n = q.len();
    let a = i as f64 / n as f64;
    let mut out = Vector::zeros();
    if let Some(prev) = i.checked_sub(1).and_then(|k| q.get(k)) {
        out += *prev * a;
    }
    if let Some(cur) = q.get(i) {
        out += *cur * (1.0 - a);
    }
    out
}

/// The least-squares solution Q (n points) of E Q ≈ P (n + 1 points, n ≥ 1), E the
/// (n + 1) × n degree-elevation matrix, one column of P per coordinate.
///
/// Givens QR of the bidiagonal E: step j rotates rows j and j + 1 so that the entry (j + 1, j)
/// vanishes. Before step j, row j holds only a diagonal a (the earlier rotations removed its
/// entry in column j − 1) and row j + 1 holds b = (j + 1)/n in column j and c = 1 − (j + 1)/n in
/// column j + 1. With r = hypot(a, b) > 0 (b > 0), cos = a/r, sin = b/r, row j becomes
/// (r, sin·c) and row j + 1 becomes (0, cos·c); the same rotation applied to the right-hand side
/// yields Qᵀ P. R is then upper bidiagonal with a positive diagonal and back substitution gives
/// Q; the last rotated right-hand-side row is the residual, which is dropped.
fn least_squares_elevation<const D: usize>(p: &[Vector<D>]) -> Vec<Vector<D>> {
    let n = p.len().saturating_sub(1);
    let nf = n as f64;
    let mut rhs = p.to_vec();
    // Diagonal and superdiagonal of R.
    let mut diag = vec![0.0; n];
    let mut sup = vec![0.0; n];
    // Diagonal of row 0 before any rotation: E(0, 0) = 1.
    let mut a: f64 = 1.0;
    for j in 0..n {
        let b = (j + 1) as f64 / nf;
        let c = 1.0 - b;
        let r = math::hypot(a, b);
        let (cos, sin) = (a / r, b / r);
        diag[j] = r;
        sup[j] = sin * c;
        a = cos * c;
        let (yj, yk) = (rhs[j], rhs[j + 1]);
        rhs[j] = yj * cos + yk * sin;
        rhs[j + 1] = yk * cos - yj * sin;
    }
    let mut q = vec![Vector::zeros(); n];
    for j in (0..n).rev() {
        let next = if j + 1 < n {
            q[j + 1] * sup[j]
        } else {
            Vector::zeros()
        };
        q[j] = (rhs[j] - next) / diag[j];
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::Vector2;

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

    /// The exact least-squares solution, from the normal equations EᵀE Q = Eᵀ P solved by
    /// Gauss–Jordan elimination in rational arithmetic (P converted exactly from f64).
    fn exact_reduction(p: &[f64]) -> Vec<f64> {
        use num_rational::BigRational;
        use num_traits::{ToPrimitive, Zero};
        let n = p.len() - 1;
        let frac = |i: usize| BigRational::new(i.into(), n.into());
        let one = BigRational::from_integer(1.into());
        let e = |i: usize, j: usize| {
            if j + 1 == i {
                frac(i)
            } else if j == i && i < n {
                &one - frac(i)
            } else {
                BigRational::zero()
            }
        };
        let pr: Vec<BigRational> = p
            .iter()
            .map(|&x| BigRational::from_float(x).unwrap())
            .collect();
        let mut m: Vec<Vec<BigRational>> = (0..n)
            .map(|r| {
                let mut row: Vec<BigRational> = (0..n)
                    .map(|c| (0..=n).map(|i| e(i, r) * e(i, c)).sum())
                    .collect();
                row.push((0..=n).map(|i| e(i, r) * &pr[i]).sum());
                row
            })
            .collect();
        for col in 0..n {
            let piv = (col..n).find(|&r| !m[r][col].is_zero()).unwrap();
            m.swap(col, piv);
            let inv = &one / &m[col][col];
            let pivot_row: Vec<BigRational> = m[col].iter().map(|x| x * &inv).collect();
            m[col] = pivot_row.clone();
            for (r, row) in m.iter_mut().enumerate() {
                if r != col && !row[col].is_zero() {
                    let f = row[col].clone();
                    for (x, y) in row.iter_mut().zip(&pivot_row) {
                        *x -= &f * y;
                    }
                }
            }
        }
        m.iter().map(|row| row[n].to_f64().unwrap()).collect()
    }

    #[test]
    fn reduction_matches_exact_least_squares() {
        let xs = [0.0, 1.0, 2.0, 4.0, 3.5, -1.25, 0.75, 2.5];
        let ys = [0.0, 3.0, -1.0, 0.5, 2.0, 1.5, -3.0, 0.25];
        for len in 2..=xs.len() {
            let c =
                BezierCurve::new((0..len).map(|i| Vector2::new(xs[i], ys[i])).collect()).unwrap();
            let r = c.reduce_degree().unwrap();
            let (ex, ey) = (exact_reduction(&xs[..len]), exact_reduction(&ys[..len]));
            assert_eq!(r.curve.points().len(), len - 1);
            for (i, q) in r.curve.points().iter().enumerate() {
                assert!(
                    (q.x() - ex[i]).abs() <= 1e-14 * (1.0 + ex[i].abs()),
                    "{len} {i}"
                );
                assert!(
                    (q.y() - ey[i]).abs() <= 1e-14 * (1.0 + ey[i].abs()),
                    "{len} {i}"
                );
            }
        }
    }

    #[test]
    fn elevated_point_is_the_elevation_formula() {
        let q = [Vector2::new(1.0, 2.0), Vector2::new(4.0, -2.0)];
        let c = BezierCurve::new(q.to_vec()).unwrap().elevate(1).unwrap();
        for (i, p) in c.points().iter().enumerate() {
            assert!((elevated_point(&q, i) - p).norm() < 1e-15);
        }
    }
}
