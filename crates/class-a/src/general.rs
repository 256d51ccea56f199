//! "General" Class A matrices: typical matrices with perturbation factors δ₀..δ₃ (Figs. 7, 9).

use crate::square::{Matrix2, Matrix3};

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
