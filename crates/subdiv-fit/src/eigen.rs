//! The eigen-structure form of Sec. 2.2.3 (Theorems 1 and 2), corrected.
//!
//! Near a sharp vertex `p_i` followed by regular vertices, one refinement maps
//! `P̃ = (p_i, p_{i+1}, p_{i+2})` to `A P̃` with
//! `A = [[1, 0, 0], [1/2, 1/2, 0], [1/8, 3/4, 1/8]]`
//! (the paper prints the first row as `[1/8, 0, 0]`: erratum, the sharp vertex is kept),
//! and the four regular B-spline control points of the right half of the segment are `Ā P̃` with the
//! extended matrix `Ā = [A; [0, 1/2, 1/2]]`.
//! `A = U D U⁻¹` with `D = diag(1/8, 1/2, 1)` and eigenvectors `(0, 0, 1)`, `(0, 1, 2)`, `(1, 1, 1)`
//! (the printed `U` has a zero first column and is singular: erratum).
//! On `u ∈ (2^-(k+1), 2^-k]`, with `t = 2^(k+1) u − 1`:
//! `C(u) = B(t) Ā A^k P̃ = Σ_l x_l(t) λ_l^k c_l`, `x(t) = B(t) Ā U`, `c = U⁻¹ P̃`
//! (the paper prints `A^(k−1)` and `B(u) A U`: off by one and the wrong matrix and argument).
//! The collapsed form in [`crate::SubdivCurve::segment_controls`] equals this for every `u`;
//! the tests check the identity.

use bez_core::Vector;
use nalgebra::{Matrix3, Matrix4x3, RowVector4};

use crate::SubdivFitError;
use crate::bspline::bspline_basis;

/// The subdivision matrix `A` next to a sharp vertex (corrected first row).
#[must_use]
pub fn sharp_matrix() -> Matrix3<f64> {
    Matrix3::new(1.0, 0.0, 0.0, 0.5, 0.5, 0.0, 0.125, 0.75, 0.125)
}

/// The extended subdivision matrix `Ā` (4×3): `A` with the row `[0, 1/2, 1/2]` appended.
#[must_use]
pub fn extended_sharp_matrix() -> Matrix4x3<f64> {
    Matrix4x3::new(
        1.0, 0.0, 0.0, 0.5, 0.5, 0.0, 0.125, 0.75, 0.125, 0.0, 0.5, 0.5,
    )
}

/// Eigenvalues of `A`, in the order of `D = diag(1/8, 1/2, 1)`.
pub const EIGENVALUES: [f64; 3] = [0.125, 0.5, 1.0];

/// Eigenvectors of `A` as the columns of `U` (unnormalized: `(0,0,1)`, `(0,1,2)`, `(1,1,1)`).
#[must_use]
pub fn eigenvectors() -> Matrix3<f64> {
    Matrix3::new(0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 2.0, 1.0)
}

/// `U⁻¹`, exact: rows `(1, −2, 1)`, `(−1, 1, 0)`, `(1, 0, 0)`.
#[must_use]
pub fn eigenvectors_inverse() -> Matrix3<f64> {
    Matrix3::new(1.0, -2.0, 1.0, -1.0, 1.0, 0.0, 1.0, 0.0, 0.0)
}

/// The eigen basis functions `x(t) = B(t) Ā U` (Theorem 2's `x_l`, with the corrected matrix).
#[must_use]
pub fn eigen_basis(t: f64) -> [f64; 3] {
    let b = RowVector4::from(bspline_basis(t));
    let x = b * extended_sharp_matrix() * eigenvectors();
    [x[0], x[1], x[2]]
}

/// The level `k` and local parameter `t = 2^(k+1) u − 1` with `u ∈ (2^-(k+1), 2^-k]`.
#[must_use]
pub fn level_of(u: f64) -> (i32, f64) {
    let mut k = 0_i32;
    let mut scale = 2.0_f64;
    while u * scale <= 1.0 && k < 1070 {
        k += 1;
        scale *= 2.0;
    }
    (k, scale * u - 1.0)
}

/// Eq. (3): the segment from a sharp `p0` towards regular `p1` (followed by `p2`) at `u ∈ [0, 1]`,
/// by the eigen-structure form `C(u) = Σ_l x_l(t) λ_l^k c_l`, `c = U⁻¹ (p0, p1, p2)`.
///
/// # Errors
/// [`SubdivFitError::ParameterOutOfRange`] if `u ∉ [0, 1]`.
pub fn eval_sharp_segment_eigen<const D: usize>(
    p: &[Vector<D>; 3],
    u: f64,
) -> Result<Vector<D>, SubdivFitError> {
    if !(0.0..=1.0).contains(&u) {
        return Err(SubdivFitError::ParameterOutOfRange {
            name: "u",
            value: u,
            min: 0.0,
            max: 1.0,
        });
    }
    // Below 2^-1000 the level passes 1000 and every term but p0's (eigenvalue 1) is scaled
    // by 2^-1000 or less: the point is p0 up to rounding, and 2^(k+1) would overflow near
    // the smallest subnormals.
    if u < 2f64.powi(-1000) {
        return Ok(p[0]);
    }
    let (k, t) = level_of(u);
    let x = eigen_basis(t);
    let ui = eigenvectors_inverse();
    let mut out = Vector::<D>::zeros();
    for l in 0..3 {
        let c = p[0] * ui[(l, 0)] + p[1] * ui[(l, 1)] + p[2] * ui[(l, 2)];
        out += c * (x[l] * EIGENVALUES[l].powi(k));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use bez_core::Vector2;

    /// At the smallest parameters (down to the smallest subnormal) the point is finite and
    /// equals p0; just above the cut it is within rounding of p0, as at the cut.
    #[test]
    fn tiny_parameters_give_the_sharp_vertex() {
        let p = [
            Vector2::new(1.0, 2.0),
            Vector2::new(3.0, -1.0),
            Vector2::new(4.0, 5.0),
        ];
        for u in [5e-324, 1e-310, 2f64.powi(-1001)] {
            assert_eq!(eval_sharp_segment_eigen(&p, u).unwrap(), p[0], "u = {u:e}");
        }
        let just_above = eval_sharp_segment_eigen(&p, 2f64.powi(-999)).unwrap();
        assert!((just_above - p[0]).norm() <= 1e-15, "{just_above:?}");
        let at_a_tenth = eval_sharp_segment_eigen(&p, 0.1).unwrap();
        assert!(at_a_tenth.is_finite() && (at_a_tenth - p[0]).norm() > 1e-3);
    }
}
