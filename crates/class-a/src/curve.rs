//! Control points of a Class A curve from its first leg and its matrix (eqs. (2), (8)), and
//! the curve value [`ClassACurve`].

use crate::square::Matrix;
use bez_core::{BezierCurve, BezierForm, Vector};

use crate::{ClassAError, TypicalPlanar, TypicalSpatial};

/// The degree-n Bézier curve with b₀ given and legs Δbⱼ = Mʲ Δb₀, j = 0..n−1 (eq. (2), printed
/// with i; eq. (8): bᵢ = b₀ + Σ_{j<i} Mʲ Δb₀).
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n = 0, [`ClassAError::NonFinite`] for a non-finite input,
/// [`ClassAError::Core`] if the points overflow.
pub fn class_a_curve<const D: usize>(
    b0: &Vector<D>,
    delta_b0: &Vector<D>,
    m: &Matrix<D>,
    degree: usize,
) -> Result<BezierCurve<D>, ClassAError> {
    crate::error::check_degree(degree, 1)?;
    if !b0.iter().all(|x| x.is_finite()) {
        return Err(ClassAError::NonFinite { name: "b0" });
    }
    if !delta_b0.iter().all(|x| x.is_finite()) {
        return Err(ClassAError::NonFinite { name: "delta_b0" });
    }
    if !m.iter().all(|x| x.is_finite()) {
        return Err(ClassAError::NonFinite { name: "matrix" });
    }
    let mut points = Vec::with_capacity(degree + 1);
    let mut p = *b0;
    let mut leg = *delta_b0;
    points.push(p);
    for _ in 0..degree {
        p += leg;
        points.push(p);
        leg = *m * leg;
    }
    Ok(BezierCurve::new(points)?)
}

/// The control points of eq. (8) built from both ends, into `out`: b₀ … b_⌊n/2⌋ forward from
/// b₀ with legs Mʲ Δb₀, then bₙ = b₀ + Σ_{j<n} Mʲ Δb₀ (the legs summed relative to b₀) and
/// bₙ₋₁ … b_⌊n/2⌋₊₁ backward from it with the last leg `last_leg` = Mⁿ⁻¹ Δb₀ given directly
/// and legs Δbⱼ = M⁻¹ Δbⱼ₊₁.
///
/// In real arithmetic this is [`class_a_curve`]. In f64 the end leg bₙ − bₙ₋₁ is then off by
/// one rounding of bₙ₋₁ instead of the rounding accumulated over n additions, so the end tangent
/// is met to about ε|bₙ| / |Δbₙ₋₁| at any degree; the mismatch of the two halves (a few ulps of
/// the points) goes into the middle leg.
pub(crate) fn two_ended_points<const D: usize>(
    b0: &Vector<D>,
    first_leg: &Vector<D>,
    last_leg: &Vector<D>,
    m: &Matrix<D>,
    m_inv: &Matrix<D>,
    degree: usize,
    out: &mut Vec<Vector<D>>,
) {
    out.clear();
    let half = degree / 2;
    let mut p = *b0;
    let mut leg = *first_leg;
    let mut total = Vector::<D>::zeros();
    out.push(p);
    for j in 0..degree {
        if j < half {
            p += leg;
            out.push(p);
        }
        total += leg;
        leg = *m * leg;
    }
    let start = out.len();
    out.resize(degree + 1, *b0);
    let mut p = b0 + total;
    let mut leg = *last_leg;
    for j in (start..=degree).rev() {
        out[j] = p;
        p -= leg;
        leg = *m_inv * leg;
    }
}

/// A Bézier curve of eq. (2) together with its matrix: legs Δbⱼ = Mʲ Δb₀, j = 0..n−1.
///
/// The value type of a Class A curve in this crate: the control points are computed once, at
/// construction, and kept (private, so they stay those of M), and the curve implements
/// [`BezierForm`], so evaluation, derivative, splitting, arc length, nearest point, bounding box
/// and curvature come from bez-core, and the curve goes to any consumer of `BezierForm` (the
/// flatteners of bez-subdiv). [`TypicalPlanar`] and [`TypicalSpatial`] stay the solvers'
/// parameters (s, θ, L, …) from which the curve is built, fallibly, by `TryFrom`.
///
/// Being Class A is a property this type reports, not an invariant it enforces (as the rest of
/// the crate: NOTES): check M with [`crate::ClassAReport`] and the curve itself with
/// [`crate::curvature_certificate`] or [`crate::torsion_certificate`].
///
/// ```
/// use bez_core::{BezierForm, Vector2};
/// use class_a::{ClassACurve, TypicalPlanar};
///
/// let (a0, a1, a2) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), Vector2::new(1.6, 1.0));
/// let typical = TypicalPlanar::from_points(&a0, &a1, &a2, 7)?;
/// let curve = ClassACurve::try_from(&typical)?;
/// assert_eq!(curve.as_bezier(), &typical.curve()?);
/// assert_eq!(curve.matrix(), typical.matrix());
/// assert!((curve.end() - a2).norm() < 1e-12);
/// let length = curve.arc_length(1e-10)?;
/// assert!(length > (a2 - a0).norm());
/// # Ok::<(), class_a::ClassAError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ClassACurve<const D: usize> {
    matrix: Matrix<D>,
    bezier: BezierCurve<D>,
}

impl<const D: usize> ClassACurve<D> {
    /// The degree-n curve with first control point b₀ and legs Δbⱼ = Mʲ Δb₀ ([`class_a_curve`]).
    ///
    /// # Errors
    /// As [`class_a_curve`].
    pub fn new(
        b0: &Vector<D>,
        delta_b0: &Vector<D>,
        m: &Matrix<D>,
        degree: usize,
    ) -> Result<Self, ClassAError> {
        Ok(Self {
            matrix: *m,
            bezier: class_a_curve(b0, delta_b0, m, degree)?,
        })
    }

    /// The matrix M of the legs.
    #[must_use]
    pub fn matrix(&self) -> Matrix<D> {
        self.matrix
    }

    /// Consumes the curve and returns its Bézier form.
    #[must_use]
    pub fn into_bezier(self) -> BezierCurve<D> {
        self.bezier
    }
}

impl<const D: usize> BezierForm<D> for ClassACurve<D> {
    /// The control points b₀ … bₙ of eq. (8) (stored, so the borrow is free).
    fn as_bezier(&self) -> &BezierCurve<D> {
        &self.bezier
    }
}

impl TryFrom<&TypicalPlanar> for ClassACurve<2> {
    type Error = ClassAError;

    /// The curve of [`TypicalPlanar::curve`] with the matrix [`TypicalPlanar::matrix`].
    fn try_from(t: &TypicalPlanar) -> Result<Self, ClassAError> {
        Ok(Self {
            matrix: t.matrix(),
            bezier: t.curve()?,
        })
    }
}

impl TryFrom<&TypicalSpatial> for ClassACurve<3> {
    type Error = ClassAError;

    /// The curve of [`TypicalSpatial::curve`] with the matrix [`TypicalSpatial::matrix`].
    fn try_from(t: &TypicalSpatial) -> Result<Self, ClassAError> {
        Ok(Self {
            matrix: t.matrix(),
            bezier: t.curve()?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Matrix2;
    use bez_core::Vector2;

    #[test]
    fn legs_follow_matrix_powers() {
        let m = Matrix2::new(1.0, -1.0, 1.0, 1.0);
        let c = class_a_curve(&Vector2::new(1.0, 2.0), &Vector2::new(1.0, 0.0), &m, 3).unwrap();
        let p = c.points();
        assert_eq!(p[1], Vector2::new(2.0, 2.0));
        assert_eq!(p[2], Vector2::new(3.0, 3.0));
        assert_eq!(p[3], Vector2::new(3.0, 5.0));
    }

    #[test]
    fn bad_input() {
        let m = Matrix2::identity();
        let v = Vector2::new(1.0, 0.0);
        assert!(matches!(
            class_a_curve(&v, &v, &m, 0),
            Err(ClassAError::DegreeTooLow { .. })
        ));
        let nan = Vector2::new(f64::NAN, 0.0);
        assert!(matches!(
            class_a_curve(&nan, &v, &m, 2),
            Err(ClassAError::NonFinite { name: "b0" })
        ));
        assert!(matches!(
            class_a_curve(&v, &nan, &m, 2),
            Err(ClassAError::NonFinite { .. })
        ));
        let big = Matrix2::identity() * 1e200;
        assert!(matches!(
            class_a_curve(&v, &v, &big, 5),
            Err(ClassAError::Core(_))
        ));
    }
}
