//! `LambdaBezierCurve`: the degree n + 1 λ-Bézier curve of Definition 2, eq. (6).

use bez_core::{BezierCurve, BezierForm, CoreError, Vector};

use crate::basis::corner_cut_ratio;
use crate::error::LambdaError;
use crate::range::LambdaRange;

/// The λ-Bézier curve B(t) = Σ_{i=0}^{n} Pᵢ b_{i,n+1}(t), t ∈ [0, 1] (eq. (6)), in D dimensions.
///
/// n + 1 control points P₀..Pₙ (n ≥ 2) and a shape parameter λ in the exact valid interval of
/// [`LambdaRange`]. The curve is a polynomial of degree n + 1; it keeps its exact Bézier form
/// Qⱼ = (1 − αⱼ) Pⱼ₋₁ + αⱼ Pⱼ, j = 0..=n+1 ([`corner_cut_ratio`]), and every evaluation goes
/// through that form (de Casteljau / Horner of bez-core, O(n) per point with `eval_many`), so it
/// costs exactly what an ordinary Bézier curve of degree n + 1 costs. λ = 0 gives the degree-n
/// Bézier curve of the same points; λ > 0 pulls the curve towards the control polygon.
///
/// ### Interpolation
/// B(0) = P₀ and B(1) = Pₙ exactly (curve Property 1).
///
/// ### Tangency
/// B'(0) = (n + λ)(P₁ − P₀), B'(1) = (n + λ)(Pₙ − Pₙ₋₁) (curve Property 1); both vanish at
/// λ = −n, which lies in the valid interval for n = 2..5.
///
/// ### Shape
/// Convex hull (Property 2), reversal symmetry (3), affine invariance (4), variation diminishing
/// (5): on the valid interval Qⱼ lies on the edge Pⱼ₋₁Pⱼ, so the Bézier polygon is a corner
/// cutting of the control polygon (the paper's proof of (5) is not valid, this argument is).
///
/// ### Continuity
/// See [`crate::join_g1`], [`crate::join_c1`] and [`crate::hermite_segment`].
///
/// ### The Bézier form
/// The curve implements [`BezierForm`]: [`as_bezier`](BezierForm::as_bezier) lends the exact
/// Bézier form, and evaluation (`eval`, `eval_many`, `sample_uniform`), the derivative (the
/// hodograph, a Bézier curve of degree n), `split`, `subsegment`, arc length, nearest point,
/// bounding box and curvature come from the trait (bring it into scope with
/// `use bez_core::BezierForm`), so the curve goes wherever a `BezierForm` is accepted (the
/// flatteners of bez-subdiv). Pieces of a split are ordinary Bézier curves of degree n + 1, in
/// general not λ-Bézier curves of the same n and λ: the λ-curves of degree n + 1 form a
/// subspace of codimension 1 of all degree n + 1 curves.
///
/// ### Usage
/// ```
/// use bez_core::{BezierForm, Vector2};
/// use lambda_bezier::LambdaBezierCurve;
/// let p = vec![
///     Vector2::new(0.0, 0.0),
///     Vector2::new(1.0, 2.0),
///     Vector2::new(3.0, 2.0),
///     Vector2::new(4.0, 0.0),
/// ];
/// let c = LambdaBezierCurve::new(p, 0.5)?;
/// assert_eq!(c.degree(), 4);
/// let d: Vector2 = c.start_tangent();
/// assert!((d - Vector2::new(3.5, 7.0)).norm() < 1e-12); // (n + λ)(P₁ − P₀)
/// assert_eq!(c.derivative()?.start(), c.as_bezier().derivative()?.start());
/// assert!((c.eval(0.5)? - c.as_bezier().eval(0.5)?).norm() == 0.0);
/// # Ok::<(), lambda_bezier::LambdaError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "CurveRepr<D>", into = "CurveRepr<D>")
)]
pub struct LambdaBezierCurve<const D: usize> {
    points: Vec<Vector<D>>,
    lambda: f64,
    range: LambdaRange,
    bezier: BezierCurve<D>,
}

/// Serialized form: the control points and λ (validated again on deserialization).
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct CurveRepr<const D: usize> {
    points: Vec<Vector<D>>,
    lambda: f64,
}

#[cfg(feature = "serde")]
impl<const D: usize> TryFrom<CurveRepr<D>> for LambdaBezierCurve<D> {
    type Error = LambdaError;
    fn try_from(r: CurveRepr<D>) -> Result<Self, LambdaError> {
        Self::new(r.points, r.lambda)
    }
}

#[cfg(feature = "serde")]
impl<const D: usize> From<LambdaBezierCurve<D>> for CurveRepr<D> {
    fn from(c: LambdaBezierCurve<D>) -> Self {
        Self {
            points: c.points,
            lambda: c.lambda,
        }
    }
}

/// The Bézier control points Q₀..Q_{n+1} of the λ-Bézier curve on `points` (no validation).
pub(crate) fn bezier_points<T>(points: &[T], lambda: f64) -> Vec<T>
where
    T: Copy + core::ops::Mul<f64, Output = T> + core::ops::Add<Output = T>,
{
    let n = points.len() - 1;
    let mut q = Vec::with_capacity(n + 2);
    q.push(points[0]);
    for j in 1..=n {
        let a = corner_cut_ratio(n, j, lambda);
        q.push(points[j - 1] * (1.0 - a) + points[j] * a);
    }
    q.push(points[n]);
    q
}

impl<const D: usize> LambdaBezierCurve<D> {
    /// A λ-Bézier curve on n + 1 ≥ 3 finite control points.
    ///
    /// # Errors
    /// [`CoreError::Empty`] / [`CoreError::NonFinite`] (wrapped), [`LambdaError::DegreeTooLow`]
    /// for fewer than 3 points, [`LambdaError::NonFiniteLambda`],
    /// [`LambdaError::LambdaOutOfRange`] (the message states the valid interval).
    pub fn new(points: Vec<Vector<D>>, lambda: f64) -> Result<Self, LambdaError> {
        if points.is_empty() {
            return Err(CoreError::Empty.into());
        }
        if let Some(index) = points.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(CoreError::NonFinite { index }.into());
        }
        let n = points.len() - 1;
        let range = LambdaRange::new(n)?;
        let lambda = range.check(lambda)?;
        let bezier = BezierCurve::new(bezier_points(&points, lambda))?;
        Ok(Self {
            points,
            lambda,
            range,
            bezier,
        })
    }

    /// Like [`LambdaBezierCurve::new`] from a slice.
    ///
    /// # Errors
    /// As [`LambdaBezierCurve::new`].
    pub fn from_slice(points: &[Vector<D>], lambda: f64) -> Result<Self, LambdaError> {
        Self::new(points.to_vec(), lambda)
    }

    /// The control points P₀..Pₙ.
    #[must_use]
    pub fn points(&self) -> &[Vector<D>] {
        &self.points
    }

    /// n (number of control points − 1).
    #[must_use]
    pub fn n(&self) -> usize {
        self.points.len() - 1
    }

    /// The shape parameter λ.
    #[must_use]
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// The valid λ interval of this curve's degree.
    #[must_use]
    pub fn lambda_range(&self) -> LambdaRange {
        self.range
    }

    /// Changes λ, keeping the control points.
    ///
    /// # Errors
    /// [`LambdaError::NonFiniteLambda`], [`LambdaError::LambdaOutOfRange`]; the curve is
    /// unchanged on error.
    pub fn set_lambda(&mut self, lambda: f64) -> Result<(), LambdaError> {
        let lambda = self.lambda_range().check(lambda)?;
        self.bezier = BezierCurve::new(bezier_points(&self.points, lambda))?;
        self.lambda = lambda;
        Ok(())
    }

    /// A copy with another λ and the same control points.
    ///
    /// # Errors
    /// As [`LambdaBezierCurve::set_lambda`].
    pub fn with_lambda(&self, lambda: f64) -> Result<Self, LambdaError> {
        let mut c = self.clone();
        c.set_lambda(lambda)?;
        Ok(c)
    }

    /// Consumes the curve and returns its Bézier form (for export to any CAD system).
    #[must_use]
    pub fn into_bezier(self) -> BezierCurve<D> {
        self.bezier
    }

    /// [B(t), B'(t), …, B^{(k)}(t)].
    ///
    /// # Errors
    /// t outside [0, 1].
    pub fn eval_derivatives(&self, t: f64, k: usize) -> Result<Vec<Vector<D>>, LambdaError> {
        Ok(self.bezier.eval_derivatives(t, k)?)
    }

    /// B'(0) = (n + λ)(P₁ − P₀) (Property 1 of the curve).
    #[must_use]
    pub fn start_tangent(&self) -> Vector<D> {
        (self.n() as f64 + self.lambda) * (self.points[1] - self.points[0])
    }

    /// B'(1) = (n + λ)(Pₙ − Pₙ₋₁) (Property 1 of the curve).
    #[must_use]
    pub fn end_tangent(&self) -> Vector<D> {
        let n = self.n();
        (n as f64 + self.lambda) * (self.points[n] - self.points[n - 1])
    }

    /// The same curve traversed backwards: control points reversed, same λ (Property 3).
    #[must_use]
    pub fn reverse(&self) -> Self {
        let mut points = self.points.clone();
        points.reverse();
        let bezier = self.bezier.reverse();
        Self {
            points,
            lambda: self.lambda,
            range: self.range,
            bezier,
        }
    }

    /// The curve with every control point mapped by `f` (use an affine map for Property 4).
    ///
    /// # Errors
    /// Non-finite mapped points.
    pub fn map_points(&self, f: impl Fn(&Vector<D>) -> Vector<D>) -> Result<Self, LambdaError> {
        Self::new(self.points.iter().map(f).collect(), self.lambda)
    }
}

impl<const D: usize> BezierForm<D> for LambdaBezierCurve<D> {
    /// The exact Bézier form: degree n + 1, control points Qⱼ = (1 − αⱼ)Pⱼ₋₁ + αⱼPⱼ (stored,
    /// so the borrow is free).
    fn as_bezier(&self) -> &BezierCurve<D> {
        &self.bezier
    }
}

#[cfg(test)]
mod tests {
    use bez_core::Vector2;

    use super::*;

    fn pts() -> Vec<Vector2> {
        vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 2.0),
            Vector2::new(3.0, 2.5),
            Vector2::new(4.0, 0.0),
        ]
    }

    #[test]
    fn errors_are_typed() {
        assert!(matches!(
            LambdaBezierCurve::<2>::new(vec![], 0.0),
            Err(LambdaError::Core(CoreError::Empty))
        ));
        assert!(matches!(
            LambdaBezierCurve::new(pts()[..2].to_vec(), 0.0),
            Err(LambdaError::DegreeTooLow { n: 1 })
        ));
        let mut p = pts();
        p[2][0] = f64::NAN;
        assert!(matches!(
            LambdaBezierCurve::new(p, 0.0),
            Err(LambdaError::Core(CoreError::NonFinite { index: 2 }))
        ));
        let e = LambdaBezierCurve::new(pts(), -3.25).unwrap_err();
        assert!(e.to_string().contains("[-3, 1]"), "{e}");
        let mut c = LambdaBezierCurve::new(pts(), 0.3).unwrap();
        assert!(c.set_lambda(1.5).is_err());
        assert_eq!(c.lambda(), 0.3);
        assert!(c.set_lambda(f64::NAN).is_err());
        assert!(c.eval(1.1).is_err());
        assert!(c.split(-0.1).is_err());
        assert!(c.map_points(|p| p * f64::INFINITY).is_err());
    }

    #[test]
    fn lambda_zero_is_the_degree_n_bezier_curve() {
        let c = LambdaBezierCurve::new(pts(), 0.0).unwrap();
        let b = BezierCurve::new(pts()).unwrap();
        for i in 0..=20 {
            let t = f64::from(i) / 20.0;
            assert!((c.eval(t).unwrap() - b.eval(t).unwrap()).norm() < 1e-14);
        }
    }

    #[test]
    fn set_lambda_matches_new() {
        let mut c = LambdaBezierCurve::new(pts(), 0.0).unwrap();
        c.set_lambda(-2.5).unwrap();
        assert_eq!(c, LambdaBezierCurve::new(pts(), -2.5).unwrap());
        assert_eq!(c.degree(), 4);
        assert_eq!(c.n(), 3);
        assert_eq!(c.lambda_range().min(), -3.0);
    }

    #[test]
    fn derivative_matches_end_tangents() {
        let c = LambdaBezierCurve::new(pts(), 0.7).unwrap();
        let d = c.derivative().unwrap();
        assert!((d.start() - c.start_tangent()).norm() < 1e-13);
        assert!((d.end() - c.end_tangent()).norm() < 1e-13);
        let e = c.eval_derivatives(0.0, 1).unwrap();
        assert!((e[1] - c.start_tangent()).norm() < 1e-13);
    }

    #[test]
    fn split_pieces_join_and_cover() {
        let c = LambdaBezierCurve::new(pts(), -1.0).unwrap();
        let (l, r) = c.split(0.3).unwrap();
        assert!((l.end() - c.eval(0.3).unwrap()).norm() < 1e-14);
        assert_eq!(l.end(), r.start());
        assert!((r.eval(0.5).unwrap() - c.eval(0.65).unwrap()).norm() < 1e-13);
    }
}
