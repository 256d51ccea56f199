//! `BezierSurface`: tensor-product Bézier patches.

use crate::vector::{Vector, Vector3};
use alloc::vec;
use alloc::vec::Vec;

use crate::casteljau::{de_casteljau, de_casteljau_split, elevate_unchecked, hodograph_slice};
use crate::curve::{BezierCurve, validate_coordinates};
use crate::error::{CoreError, check_unit};
use crate::limits::MAX_DEGREE;

/// A tensor-product Bézier surface S(u, v) = Σᵢ Σⱼ P_{ij} B_{i,m}(u) B_{j,n}(v).
///
/// The control grid has (m + 1) rows (index i, the u direction) of (n + 1) points (index j,
/// the v direction), stored row-major: P_{ij} is `points()[i * (n + 1) + j]`.
///
/// ```
/// use bez_core::{BezierSurface, Vector3};
/// // A bilinear patch.
/// let s = BezierSurface::new(vec![
///     vec![Vector3::new(0.0, 0.0, 0.0), Vector3::new(0.0, 1.0, 0.0)],
///     vec![Vector3::new(1.0, 0.0, 0.0), Vector3::new(1.0, 1.0, 1.0)],
/// ])?;
/// assert_eq!(s.eval(0.5, 0.5)?, Vector3::new(0.5, 0.5, 0.25));
/// # Ok::<(), bez_core::CoreError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "SurfaceRepr<D>", into = "SurfaceRepr<D>")
)]
pub struct BezierSurface<const D: usize> {
    degree_u: usize,
    degree_v: usize,
    points: Vec<Vector<D>>,
}

/// Serialized form of a surface: degrees and the row-major grid.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct SurfaceRepr<const D: usize> {
    degree_u: usize,
    degree_v: usize,
    points: Vec<Vector<D>>,
}

#[cfg(feature = "serde")]
impl<const D: usize> TryFrom<SurfaceRepr<D>> for BezierSurface<D> {
    type Error = CoreError;
    fn try_from(r: SurfaceRepr<D>) -> Result<Self, CoreError> {
        Self::from_flat(r.degree_u, r.degree_v, r.points)
    }
}

#[cfg(feature = "serde")]
impl<const D: usize> From<BezierSurface<D>> for SurfaceRepr<D> {
    fn from(s: BezierSurface<D>) -> Self {
        Self {
            degree_u: s.degree_u,
            degree_v: s.degree_v,
            points: s.points,
        }
    }
}

impl<const D: usize> BezierSurface<D> {
    /// Creates a surface from rows of control points (row i is P_{i0} … P_{in}).
    ///
    /// # Errors
    /// [`CoreError::Empty`] for no rows or empty rows, [`CoreError::RaggedGrid`] when rows
    /// differ in length, [`CoreError::NonFinite`] for a NaN or infinite coordinate.
    pub fn new(rows: Vec<Vec<Vector<D>>>) -> Result<Self, CoreError> {
        let expected = rows.first().map_or(0, Vec::len);
        if expected == 0 {
            return Err(CoreError::Empty);
        }
        if let Some((row, r)) = rows.iter().enumerate().find(|(_, r)| r.len() != expected) {
            return Err(CoreError::RaggedGrid {
                row,
                len: r.len(),
                expected,
            });
        }
        let degree_u = rows.len() - 1;
        let points: Vec<_> = rows.into_iter().flatten().collect();
        Self::from_flat(degree_u, expected - 1, points)
    }

    /// Creates a surface of bidegree (m, n) from a row-major list of (m+1)(n+1) points.
    ///
    /// # Errors
    /// [`CoreError::DegreeTooHigh`] for a degree above [`MAX_DEGREE`], [`CoreError::GridShape`]
    /// when the count does not match, [`CoreError::NonFinite`] for a non-finite coordinate,
    /// [`CoreError::CoordinateOutOfRange`] for one outside
    /// ±[`MAX_COORDINATE`](crate::MAX_COORDINATE).
    pub fn from_flat(
        degree_u: usize,
        degree_v: usize,
        points: Vec<Vector<D>>,
    ) -> Result<Self, CoreError> {
        let degree = degree_u.max(degree_v);
        if degree > MAX_DEGREE {
            return Err(CoreError::DegreeTooHigh {
                max: MAX_DEGREE,
                degree,
            });
        }
        // At most 4097² points: no overflow.
        let (rows, cols) = (degree_u + 1, degree_v + 1);
        let expected = rows * cols;
        if points.len() != expected {
            return Err(CoreError::GridShape {
                rows,
                cols,
                expected,
                len: points.len(),
            });
        }
        validate_coordinates(&points)?;
        Ok(Self {
            degree_u,
            degree_v,
            points,
        })
    }

    fn from_valid(degree_u: usize, degree_v: usize, points: Vec<Vector<D>>) -> Self {
        debug_assert_eq!(points.len(), (degree_u + 1) * (degree_v + 1));
        Self {
            degree_u,
            degree_v,
            points,
        }
    }

    /// Degree m in u.
    #[must_use]
    pub fn degree_u(&self) -> usize {
        self.degree_u
    }

    /// Degree n in v.
    #[must_use]
    pub fn degree_v(&self) -> usize {
        self.degree_v
    }

    /// The row-major control grid.
    #[must_use]
    pub fn points(&self) -> &[Vector<D>] {
        &self.points
    }

    /// Control point P_{ij}, or `None` outside the grid.
    #[must_use]
    pub fn control_point(&self, i: usize, j: usize) -> Option<Vector<D>> {
        if i > self.degree_u || j > self.degree_v {
            return None;
        }
        self.points.get(i * (self.degree_v + 1) + j).copied()
    }

    fn row(&self, i: usize) -> &[Vector<D>] {
        let c = self.degree_v + 1;
        &self.points[i * c..(i + 1) * c]
    }

    fn column(&self, j: usize) -> Vec<Vector<D>> {
        (0..=self.degree_u)
            .map(|i| self.points[i * (self.degree_v + 1) + j])
            .collect()
    }

    /// S(u, v): de Casteljau in v along each row, then in u. Cost O(m n² + m²).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when u or v ∉ [0, 1].
    pub fn eval(&self, u: f64, v: f64) -> Result<Vector<D>, CoreError> {
        check_unit("u", u)?;
        check_unit("v", v)?;
        Ok(self.eval_unchecked(u, v))
    }

    fn eval_unchecked(&self, u: f64, v: f64) -> Vector<D> {
        let col: Vec<_> = (0..=self.degree_u)
            .map(|i| de_casteljau(self.row(i), v).unwrap_or_else(Vector::zeros))
            .collect();
        de_casteljau(&col, u).unwrap_or_else(Vector::zeros)
    }

    /// The isoparametric curve v ↦ S(u, v) at fixed u, a degree-n Bézier curve.
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when u ∉ [0, 1].
    pub fn curve_at_u(&self, u: f64) -> Result<BezierCurve<D>, CoreError> {
        check_unit("u", u)?;
        let pts = (0..=self.degree_v)
            .map(|j| de_casteljau(&self.column(j), u).unwrap_or_else(Vector::zeros))
            .collect();
        BezierCurve::new(pts)
    }

    /// The isoparametric curve u ↦ S(u, v) at fixed v, a degree-m Bézier curve.
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when v ∉ [0, 1].
    pub fn curve_at_v(&self, v: f64) -> Result<BezierCurve<D>, CoreError> {
        check_unit("v", v)?;
        let pts = (0..=self.degree_u)
            .map(|i| de_casteljau(self.row(i), v).unwrap_or_else(Vector::zeros))
            .collect();
        BezierCurve::new(pts)
    }

    /// Applies `f` to every column (u direction), producing a grid with new degree in u.
    fn map_columns(&self, f: impl Fn(&[Vector<D>]) -> Vec<Vector<D>>) -> Self {
        let cols: Vec<Vec<_>> = (0..=self.degree_v).map(|j| f(&self.column(j))).collect();
        let new_rows = cols.first().map_or(1, Vec::len);
        let mut points = Vec::with_capacity(new_rows * cols.len());
        for i in 0..new_rows {
            for c in &cols {
                points.push(c[i]);
            }
        }
        Self::from_valid(new_rows - 1, self.degree_v, points)
    }

    /// Applies `f` to every row (v direction), producing a grid with new degree in v.
    fn map_rows(&self, f: impl Fn(&[Vector<D>]) -> Vec<Vector<D>>) -> Self {
        let rows: Vec<Vec<_>> = (0..=self.degree_u).map(|i| f(self.row(i))).collect();
        let new_cols = rows.first().map_or(1, Vec::len);
        Self::from_valid(
            self.degree_u,
            new_cols - 1,
            rows.into_iter().flatten().collect(),
        )
    }

    /// The partial derivative ∂^{p+q} S / ∂uᵖ ∂v^q as a Bézier surface of bidegree
    /// (max(m − p, 0), max(n − q, 0)) (hodographs in each direction; zero beyond the degree).
    ///
    /// # Errors
    /// [`CoreError::Overflow`] when a control point of the result leaves
    /// ±[`MAX_COORDINATE`](crate::MAX_COORDINATE).
    pub fn partial(&self, p: usize, q: usize) -> Result<Self, CoreError> {
        let mut s = self.clone();
        // Beyond the degree every further derivative is the zero surface.
        for _ in 0..p.min(self.degree_u + 1) {
            s = s.map_columns(hodograph_slice);
        }
        for _ in 0..q.min(self.degree_v + 1) {
            s = s.map_rows(hodograph_slice);
        }
        match validate_coordinates(&s.points) {
            Ok(()) => Ok(s),
            Err(_) => Err(CoreError::Overflow {
                operation: "partial",
            }),
        }
    }

    /// The value of ∂^{p+q} S / ∂uᵖ ∂v^q at (u, v).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when u or v ∉ [0, 1]; as [`Self::partial`].
    pub fn eval_partial(&self, u: f64, v: f64, p: usize, q: usize) -> Result<Vector<D>, CoreError> {
        check_unit("u", u)?;
        check_unit("v", v)?;
        self.partial(p, q)?.eval(u, v)
    }

    /// The same surface with degree m + r in u (exact elevation of every column).
    ///
    /// # Errors
    /// [`CoreError::DegreeTooHigh`] when m + r exceeds [`MAX_DEGREE`] (checked before
    /// allocating).
    pub fn elevate_u(&self, r: usize) -> Result<Self, CoreError> {
        check_elevation(self.degree_u, r)?;
        Ok(self.map_columns(|c| elevate_unchecked(c, r)))
    }

    /// The same surface with degree n + r in v (exact elevation of every row).
    ///
    /// # Errors
    /// As [`Self::elevate_u`].
    pub fn elevate_v(&self, r: usize) -> Result<Self, CoreError> {
        check_elevation(self.degree_v, r)?;
        Ok(self.map_rows(|c| elevate_unchecked(c, r)))
    }

    /// Splits at u = t into the patches on [0, t] × [0, 1] and [t, 1] × [0, 1].
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when t ∉ [0, 1].
    pub fn split_u(&self, t: f64) -> Result<(Self, Self), CoreError> {
        check_unit("u", t)?;
        Ok((
            self.map_columns(|c| split_half(c, t, true)),
            self.map_columns(|c| split_half(c, t, false)),
        ))
    }

    /// Splits at v = t into the patches on [0, 1] × [0, t] and [0, 1] × [t, 1].
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when t ∉ [0, 1].
    pub fn split_v(&self, t: f64) -> Result<(Self, Self), CoreError> {
        check_unit("v", t)?;
        Ok((
            self.map_rows(|c| split_half(c, t, true)),
            self.map_rows(|c| split_half(c, t, false)),
        ))
    }
}

fn split_half<const D: usize>(c: &[Vector<D>], t: f64, left: bool) -> Vec<Vector<D>> {
    let mut l = vec![Vector::zeros(); c.len()];
    let mut r = vec![Vector::zeros(); c.len()];
    let _ = de_casteljau_split(c, t, &mut l, &mut r);
    if left { l } else { r }
}

impl BezierSurface<3> {
    /// The unit normal S_u × S_v / |S_u × S_v| at (u, v).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`]; [`CoreError::ZeroTangent`] (with t = u) where the
    /// surface is not regular (S_u × S_v vanishes, e.g. at a collapsed corner).
    pub fn normal(&self, u: f64, v: f64) -> Result<Vector3, CoreError> {
        let su = self.eval_partial(u, v, 1, 0)?;
        let sv = self.eval_partial(u, v, 0, 1)?;
        let n = su.cross(&sv);
        let len = n.norm();
        if len <= 1e-14 * su.norm() * sv.norm() || len == 0.0 {
            return Err(CoreError::ZeroTangent { t: u });
        }
        Ok(n / len)
    }
}

/// [`CoreError::DegreeTooHigh`] unless degree + r ≤ [`MAX_DEGREE`].
fn check_elevation(degree: usize, r: usize) -> Result<(), CoreError> {
    let elevated = degree.saturating_add(r);
    if elevated > MAX_DEGREE {
        return Err(CoreError::DegreeTooHigh {
            max: MAX_DEGREE,
            degree: elevated,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn patch() -> BezierSurface<3> {
        let rows = (0..4)
            .map(|i| {
                (0..3)
                    .map(|j| {
                        let (x, y) = (i as f64, j as f64);
                        Vector3::new(x, y, (x * 1.3 - y * 0.7).sin())
                    })
                    .collect()
            })
            .collect();
        BezierSurface::new(rows).unwrap()
    }

    #[test]
    fn surface_validation() {
        assert_eq!(BezierSurface::<3>::new(vec![]), Err(CoreError::Empty));
        let ragged = vec![vec![Vector3::zeros(); 2], vec![Vector3::zeros(); 3]];
        assert_eq!(
            BezierSurface::new(ragged),
            Err(CoreError::RaggedGrid {
                row: 1,
                len: 3,
                expected: 2
            })
        );
        assert!(matches!(
            BezierSurface::from_flat(1, 1, vec![Vector3::zeros(); 3]),
            Err(CoreError::GridShape { .. })
        ));
        assert!(patch().eval(0.5, 1.2).is_err());
    }

    #[test]
    fn corners_interpolate_and_partials_match_finite_differences() {
        let s = patch();
        assert_eq!(s.eval(0.0, 0.0).unwrap(), s.control_point(0, 0).unwrap());
        assert_eq!(s.eval(1.0, 1.0).unwrap(), s.control_point(3, 2).unwrap());
        let h = 1e-6;
        let (u, v) = (0.3, 0.6);
        let fu = (s.eval(u + h, v).unwrap() - s.eval(u - h, v).unwrap()) / (2.0 * h);
        let fv = (s.eval(u, v + h).unwrap() - s.eval(u, v - h).unwrap()) / (2.0 * h);
        assert!((s.eval_partial(u, v, 1, 0).unwrap() - fu).norm() < 1e-7);
        assert!((s.eval_partial(u, v, 0, 1).unwrap() - fv).norm() < 1e-7);
    }

    #[test]
    fn elevation_and_split_preserve_the_surface() {
        let s = patch();
        let e = s.elevate_u(2).unwrap().elevate_v(1).unwrap();
        let (a, b) = s.split_u(0.4).unwrap();
        let (c, _) = s.split_v(0.25).unwrap();
        for &(u, v) in &[(0.1, 0.2), (0.5, 0.5), (0.9, 0.7)] {
            let p = s.eval(u, v).unwrap();
            assert!((e.eval(u, v).unwrap() - p).norm() < 1e-13);
            let q = if u <= 0.4 {
                a.eval(u / 0.4, v)
            } else {
                b.eval((u - 0.4) / 0.6, v)
            };
            assert!((q.unwrap() - p).norm() < 1e-13);
            assert!((c.eval(u, v).unwrap() - s.eval(u, 0.25 * v).unwrap()).norm() < 1e-13);
        }
        assert!((c.eval(0.5, 1.0).unwrap() - s.eval(0.5, 0.25).unwrap()).norm() < 1e-13);
    }

    #[test]
    fn normal_of_a_plane() {
        let s = BezierSurface::new(vec![
            vec![Vector3::new(0.0, 0.0, 0.0), Vector3::new(0.0, 1.0, 0.0)],
            vec![Vector3::new(1.0, 0.0, 0.0), Vector3::new(1.0, 1.0, 0.0)],
        ])
        .unwrap();
        assert!((s.normal(0.3, 0.8).unwrap() - Vector3::new(0.0, 0.0, 1.0)).norm() < 1e-15);
        let collapsed = BezierSurface::new(vec![vec![Vector3::zeros(); 2]; 2]).unwrap();
        assert!(collapsed.normal(0.5, 0.5).is_err());
    }
}
