//! Conversions between nalgebra vectors and glam's `DVec2`/`DVec3` (feature `glam`).
//!
//! Both types are foreign to this crate, so the conversions are functions rather than `From`
//! impls; curves get constructors and accessors in glam types.

use glam::{DVec2, DVec3};
use nalgebra::{Vector2, Vector3};

use crate::curve::BezierCurve;
use crate::error::CoreError;

/// `DVec2` → `Vector2<f64>`.
#[must_use]
pub fn from_dvec2(v: DVec2) -> Vector2<f64> {
    Vector2::new(v.x, v.y)
}

/// `Vector2<f64>` → `DVec2`.
#[must_use]
pub fn to_dvec2(v: &Vector2<f64>) -> DVec2 {
    DVec2::new(v.x, v.y)
}

/// `DVec3` → `Vector3<f64>`.
#[must_use]
pub fn from_dvec3(v: DVec3) -> Vector3<f64> {
    Vector3::new(v.x, v.y, v.z)
}

/// `Vector3<f64>` → `DVec3`.
#[must_use]
pub fn to_dvec3(v: &Vector3<f64>) -> DVec3 {
    DVec3::new(v.x, v.y, v.z)
}

impl BezierCurve<2> {
    /// A planar curve from glam control points.
    ///
    /// # Errors
    /// As [`BezierCurve::new`].
    pub fn from_dvec2(points: &[DVec2]) -> Result<Self, CoreError> {
        Self::new(points.iter().copied().map(from_dvec2).collect())
    }

    /// The control points as glam vectors.
    #[must_use]
    pub fn to_dvec2(&self) -> Vec<DVec2> {
        self.points().iter().map(to_dvec2).collect()
    }
}

impl BezierCurve<3> {
    /// A spatial curve from glam control points.
    ///
    /// # Errors
    /// As [`BezierCurve::new`].
    pub fn from_dvec3(points: &[DVec3]) -> Result<Self, CoreError> {
        Self::new(points.iter().copied().map(from_dvec3).collect())
    }

    /// The control points as glam vectors.
    #[must_use]
    pub fn to_dvec3(&self) -> Vec<DVec3> {
        self.points().iter().map(to_dvec3).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glam_round_trip() {
        let pts = [DVec2::new(0.0, 1.0), DVec2::new(2.0, 3.0)];
        let c = BezierCurve::from_dvec2(&pts).unwrap();
        assert_eq!(c.to_dvec2(), pts);
        let p3 = [DVec3::new(0.0, 1.0, 2.0)];
        assert_eq!(BezierCurve::from_dvec3(&p3).unwrap().to_dvec3(), p3);
        assert!(BezierCurve::from_dvec2(&[DVec2::new(f64::NAN, 0.0)]).is_err());
    }
}
