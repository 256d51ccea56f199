//! Tensor-product λ-Bézier surfaces (Definition 3, eq. (8)), with degree and λ per direction.

use bez_core::{BezierSurface, CoreError, Vector};

use crate::curve::bezier_points;
use crate::error::LambdaError;
use crate::range::LambdaRange;

/// B(u, v) = Σ_{i=0}^{n} Σ_{j=0}^{m} P_{ij} b_{i,n+1}(u; λᵤ) b_{j,m+1}(v; λᵥ), (u, v) ∈ [0, 1]².
///
/// Definition 3 of the paper takes n = m and one λ ∈ [−2, 1]; here each direction has its own
/// n (≥ 2) and its own λ, each checked against the exact [`LambdaRange`] of its degree (the
/// paper's [−2, 1] is the n = 2 range only). Row i of the grid holds P_{i0}..P_{im} (u index
/// first, as in [`BezierSurface`]). The surface keeps its exact Bézier form of bidegree
/// (n + 1, m + 1): the corner cutting of the curve case applied to the rows, then to the columns.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "SurfaceRepr<D>", into = "SurfaceRepr<D>")
)]
pub struct LambdaBezierSurface<const D: usize> {
    rows: Vec<Vec<Vector<D>>>,
    lambda_u: f64,
    lambda_v: f64,
    bezier: BezierSurface<D>,
}

/// Serialized form: the grid and both λ (validated again on deserialization).
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct SurfaceRepr<const D: usize> {
    rows: Vec<Vec<Vector<D>>>,
    lambda_u: f64,
    lambda_v: f64,
}

#[cfg(feature = "serde")]
impl<const D: usize> TryFrom<SurfaceRepr<D>> for LambdaBezierSurface<D> {
    type Error = LambdaError;
    fn try_from(r: SurfaceRepr<D>) -> Result<Self, LambdaError> {
        Self::new(r.rows, r.lambda_u, r.lambda_v)
    }
}

#[cfg(feature = "serde")]
impl<const D: usize> From<LambdaBezierSurface<D>> for SurfaceRepr<D> {
    fn from(s: LambdaBezierSurface<D>) -> Self {
        Self {
            rows: s.rows,
            lambda_u: s.lambda_u,
            lambda_v: s.lambda_v,
        }
    }
}

impl<const D: usize> LambdaBezierSurface<D> {
    /// A surface on an (n + 1) × (m + 1) grid, n, m ≥ 2.
    ///
    /// # Errors
    /// [`CoreError::Empty`], [`CoreError::RaggedGrid`], [`CoreError::NonFinite`] (wrapped),
    /// [`LambdaError::DegreeTooLow`] in either direction, λ out of the range of its degree.
    pub fn new(
        rows: Vec<Vec<Vector<D>>>,
        lambda_u: f64,
        lambda_v: f64,
    ) -> Result<Self, LambdaError> {
        let first = rows.first().ok_or(CoreError::Empty)?;
        let cols = first.len();
        if cols == 0 {
            return Err(CoreError::Empty.into());
        }
        if let Some((row, r)) = rows.iter().enumerate().find(|(_, r)| r.len() != cols) {
            return Err(CoreError::RaggedGrid {
                row,
                len: r.len(),
                expected: cols,
            }
            .into());
        }
        if let Some(index) = rows
            .iter()
            .flatten()
            .position(|p| !p.iter().all(|x| x.is_finite()))
        {
            return Err(CoreError::NonFinite { index }.into());
        }
        let lambda_u = LambdaRange::new(rows.len() - 1)?.check(lambda_u)?;
        let lambda_v = LambdaRange::new(cols - 1)?.check(lambda_v)?;
        let bezier = to_bezier(&rows, lambda_u, lambda_v)?;
        Ok(Self {
            rows,
            lambda_u,
            lambda_v,
            bezier,
        })
    }

    /// n: the u degree is n + 1.
    #[must_use]
    pub fn n_u(&self) -> usize {
        self.rows.len() - 1
    }

    /// m: the v degree is m + 1.
    #[must_use]
    pub fn n_v(&self) -> usize {
        self.rows[0].len() - 1
    }

    /// λ of the u direction.
    #[must_use]
    pub fn lambda_u(&self) -> f64 {
        self.lambda_u
    }

    /// λ of the v direction.
    #[must_use]
    pub fn lambda_v(&self) -> f64 {
        self.lambda_v
    }

    /// The control grid, row i = u index.
    #[must_use]
    pub fn rows(&self) -> &[Vec<Vector<D>>] {
        &self.rows
    }

    /// Changes both λ, keeping the control points.
    ///
    /// # Errors
    /// λ out of range; the surface is unchanged on error.
    pub fn set_lambdas(&mut self, lambda_u: f64, lambda_v: f64) -> Result<(), LambdaError> {
        let lambda_u = LambdaRange::new(self.n_u())?.check(lambda_u)?;
        let lambda_v = LambdaRange::new(self.n_v())?.check(lambda_v)?;
        self.bezier = to_bezier(&self.rows, lambda_u, lambda_v)?;
        self.lambda_u = lambda_u;
        self.lambda_v = lambda_v;
        Ok(())
    }

    /// The exact Bézier form, bidegree (n + 1, m + 1).
    #[must_use]
    pub fn as_bezier(&self) -> &BezierSurface<D> {
        &self.bezier
    }

    /// B(u, v).
    ///
    /// # Errors
    /// u or v outside [0, 1].
    pub fn eval(&self, u: f64, v: f64) -> Result<Vector<D>, LambdaError> {
        Ok(self.bezier.eval(u, v)?)
    }

    /// ∂^{p+q} B / ∂u^p ∂v^q at (u, v).
    ///
    /// # Errors
    /// u or v outside [0, 1].
    pub fn eval_partial(
        &self,
        u: f64,
        v: f64,
        p: usize,
        q: usize,
    ) -> Result<Vector<D>, LambdaError> {
        Ok(self.bezier.eval_partial(u, v, p, q)?)
    }

    /// ∂^{p+q} B / ∂u^p ∂v^q as a Bézier surface.
    ///
    /// # Errors
    /// As [`BezierSurface::partial`] (a result outside the coordinate range).
    pub fn partial(&self, p: usize, q: usize) -> Result<BezierSurface<D>, LambdaError> {
        Ok(self.bezier.partial(p, q)?)
    }
}

fn to_bezier<const D: usize>(
    rows: &[Vec<Vector<D>>],
    lambda_u: f64,
    lambda_v: f64,
) -> Result<BezierSurface<D>, LambdaError> {
    // Corner cutting along v in every row, then along u in every column.
    let along_v: Vec<Vec<Vector<D>>> = rows.iter().map(|r| bezier_points(r, lambda_v)).collect();
    let cols = along_v[0].len();
    let mut out = vec![Vec::with_capacity(cols); rows.len() + 1];
    for j in 0..cols {
        let column: Vec<Vector<D>> = along_v.iter().map(|r| r[j]).collect();
        for (i, q) in bezier_points(&column, lambda_u).into_iter().enumerate() {
            out[i].push(q);
        }
    }
    Ok(BezierSurface::new(out)?)
}

#[cfg(test)]
mod tests {
    use bez_core::{BezierForm, Vector3};

    use super::*;
    use crate::{LambdaBasis, LambdaBezierCurve};

    fn grid(n: usize, m: usize) -> Vec<Vec<Vector3>> {
        (0..=n)
            .map(|i| {
                (0..=m)
                    .map(|j| {
                        let (x, y) = (i as f64, j as f64);
                        Vector3::new(x, y, (x * 1.3 + y * 0.7).sin() + 0.1 * x * y)
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn matches_the_double_sum_of_eq_8() {
        let (n, m, lu, lv) = (3, 5, -2.5, 0.8);
        let g = grid(n, m);
        let s = LambdaBezierSurface::new(g.clone(), lu, lv).unwrap();
        let bu = LambdaBasis::new(n, lu).unwrap();
        let bv = LambdaBasis::new(m, lv).unwrap();
        for &(u, v) in &[(0.0, 0.0), (0.3, 0.7), (1.0, 0.25), (0.9, 1.0)] {
            let mut want = Vector3::zeros();
            for (i, row) in g.iter().enumerate() {
                for (j, p) in row.iter().enumerate() {
                    want += p * bu.eval(i, u).unwrap() * bv.eval(j, v).unwrap();
                }
            }
            assert!((s.eval(u, v).unwrap() - want).norm() < 1e-12);
            // ∂/∂u by the basis derivatives.
            let mut du = Vector3::zeros();
            for (i, row) in g.iter().enumerate() {
                for (j, p) in row.iter().enumerate() {
                    du += p * bu.derivative(i, u, 1).unwrap() * bv.eval(j, v).unwrap();
                }
            }
            assert!((s.eval_partial(u, v, 1, 0).unwrap() - du).norm() < 1e-11);
        }
        assert_eq!(s.as_bezier().degree_u(), n + 1);
        assert_eq!(s.as_bezier().degree_v(), m + 1);
        assert_eq!(s.partial(1, 1).unwrap().degree_u(), n);
    }

    #[test]
    fn lambda_zero_is_the_bezier_surface_of_the_grid() {
        let g = grid(3, 2);
        let s = LambdaBezierSurface::new(g.clone(), 0.0, 0.0).unwrap();
        let b = BezierSurface::new(g).unwrap();
        for &(u, v) in &[(0.0, 0.5), (0.25, 0.75), (0.6, 0.1), (1.0, 1.0)] {
            assert!((s.eval(u, v).unwrap() - b.eval(u, v).unwrap()).norm() < 1e-13);
        }
    }

    #[test]
    fn boundary_curves_are_lambda_curves() {
        let g = grid(4, 2);
        let s = LambdaBezierSurface::new(g.clone(), -3.0, 0.5).unwrap();
        let edge = LambdaBezierCurve::new(g[0].clone(), 0.5).unwrap();
        for k in 0..=10 {
            let v = f64::from(k) / 10.0;
            assert!((s.eval(0.0, v).unwrap() - edge.eval(v).unwrap()).norm() < 1e-13);
        }
    }

    #[test]
    fn errors() {
        assert!(LambdaBezierSurface::<3>::new(vec![], 0.0, 0.0).is_err());
        let mut g = grid(3, 3);
        g[1].pop();
        assert!(matches!(
            LambdaBezierSurface::new(g, 0.0, 0.0),
            Err(LambdaError::Core(CoreError::RaggedGrid { row: 1, .. }))
        ));
        assert!(matches!(
            LambdaBezierSurface::new(grid(1, 3), 0.0, 0.0),
            Err(LambdaError::DegreeTooLow { n: 1 })
        ));
        // n = 4 allows λ = −3.5 in u; m = 2 does not in v.
        assert!(LambdaBezierSurface::new(grid(4, 4), -3.5, -3.5).is_ok());
        assert!(matches!(
            LambdaBezierSurface::new(grid(4, 2), -3.5, -3.5),
            Err(LambdaError::LambdaOutOfRange { n: 2, .. })
        ));
        let mut g = grid(2, 2);
        g[2][1][2] = f64::NAN;
        assert!(LambdaBezierSurface::new(g, 0.0, 0.0).is_err());
        let mut s = LambdaBezierSurface::new(grid(2, 3), 0.0, 0.0).unwrap();
        assert!(s.set_lambdas(0.0, -3.1).is_err());
        assert_eq!(s.lambda_v(), 0.0);
        s.set_lambdas(-2.0, -3.0).unwrap();
        assert_eq!(
            (s.lambda_u(), s.lambda_v(), s.n_u(), s.n_v()),
            (-2.0, -3.0, 2, 3)
        );
        assert!(s.eval(1.2, 0.0).is_err());
        assert_eq!(s.rows().len(), 3);
    }
}
