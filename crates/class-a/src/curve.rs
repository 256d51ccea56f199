//! Control points of a Class A curve from its first leg and its matrix (eqs. (2), (8)).

use bez_core::{BezierCurve, Vector};
use nalgebra::SMatrix;

use crate::ClassAError;

/// The degree-n Bézier curve with b₀ given and legs Δbⱼ = Mʲ Δb₀, j = 0..n−1 (eq. (2), printed
/// with i; eq. (8): bᵢ = b₀ + Σ_{j<i} Mʲ Δb₀).
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n = 0, [`ClassAError::NonFinite`] for a non-finite input,
/// [`ClassAError::Core`] if the points overflow.
pub fn class_a_curve<const D: usize>(
    b0: &Vector<D>,
    delta_b0: &Vector<D>,
    m: &SMatrix<f64, D, D>,
    degree: usize,
) -> Result<BezierCurve<D>, ClassAError> {
    if degree == 0 {
        return Err(ClassAError::DegreeTooLow { degree, needed: 1 });
    }
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
        leg = (m * nalgebra::SVector::<f64, D>::from(leg)).into();
    }
    Ok(BezierCurve::new(points)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use bez_core::Vector2;
    use nalgebra::Matrix2;

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
