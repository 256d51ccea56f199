//! "General" Class A matrices: typical matrices with perturbation factors δ₀..δ₃ (Figs. 7, 9).

use bez_core::Vector;

use crate::square::{Matrix, Matrix2, Matrix3};
use crate::{ClassACurve, ClassAError};

/// The paper never says how δ₀..δ₃ enter M (NOTES). Our documented choice: they are added to
/// the upper-left 2×2 block, M' = M + [[δ₀, δ₁], [δ₂, δ₃]] (for 3×3, the third row and column
/// unchanged). The result must be checked with [`crate::ClassAReport`] and the curve with
/// [`crate::curvature_certificate`]: a perturbation can break the Class A property.
#[must_use]
pub fn perturb2(m: &Matrix2, delta: [f64; 4]) -> Matrix2 {
    *m + Matrix2::new(delta[0], delta[1], delta[2], delta[3])
}

/// As [`perturb2`] for a 3×3 matrix (upper-left block).
#[must_use]
pub fn perturb3(m: &Matrix3, delta: [f64; 4]) -> Matrix3 {
    *m + Matrix3::from_rows([
        [delta[0], delta[1], 0.0],
        [delta[2], delta[3], 0.0],
        [0.0, 0.0, 0.0],
    ])
}

/// The curve of degree n with matrix M (e.g. a perturbed one) that keeps both end points:
/// b₀ given and the first leg v solved from Σ_{j<n} Mʲ v = bₙ − b₀ (eq. (8) at i = n), a linear
/// system (Gaussian elimination with partial pivoting).
///
/// Perturbing M in [`perturb2`] / [`perturb3`] with the first leg kept moves the end point
/// (Σ Mʲ changes); solving v instead keeps b₀ and bₙ exactly (to rounding) at any perturbation
/// for which Σ Mʲ is invertible. Two conditions cannot be kept as well: the end tangent
/// directions become those of v and Mⁿ⁻¹v. Holding the tangents (and the end curvatures) too
/// is the general-matrix solve of [`crate::hermite_planar`], where M is an unknown rather than
/// a given perturbation.
///
/// ```
/// use bez_core::{BezierForm, Vector2};
/// use class_a::{end_preserving_curve, perturb2, typical_matrix2};
/// let m = perturb2(&typical_matrix2(1.1, 0.2), [0.02, -0.01, 0.0, 0.03]);
/// let (b0, bn) = (Vector2::new(0.0, 0.0), Vector2::new(3.0, 2.0));
/// let c = end_preserving_curve(&b0, &bn, &m, 6)?;
/// assert!((c.end() - bn).norm() < 1e-12);
/// # Ok::<(), class_a::ClassAError>(())
/// ```
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] / [`ClassAError::DegreeTooHigh`] (n from 1 to
/// [`crate::MAX_DEGREE`]); [`ClassAError::NonFinite`] / [`ClassAError::InvalidParameter`] for
/// the points and the matrix; [`ClassAError::InvalidParameter`] when Σ Mʲ is singular or the
/// solve overflows; [`ClassAError::Core`] if the control points overflow.
pub fn end_preserving_curve<const D: usize>(
    b0: &Vector<D>,
    bn: &Vector<D>,
    m: &Matrix<D>,
    degree: usize,
) -> Result<ClassACurve<D>, ClassAError> {
    crate::error::check_degree(degree, 1)?;
    crate::error::check_point(b0, "b0")?;
    crate::error::check_point(bn, "bn")?;
    if !m.iter().all(|x| x.is_finite()) {
        return Err(ClassAError::NonFinite { name: "matrix" });
    }
    let mut sum = Matrix::<D>::identity() * 0.0;
    let mut power = Matrix::<D>::identity();
    for _ in 0..degree {
        sum = sum + power;
        power = power * *m;
    }
    let leg = sum
        .solve(&(bn - b0))
        .map_err(|pivot| ClassAError::InvalidParameter {
            name: "pivot of the sum of matrix powers",
            value: pivot,
            expected: "non-zero, with a finite first leg (the end points fix it)",
        })?;
    ClassACurve::new(b0, &leg, m, degree)
}
