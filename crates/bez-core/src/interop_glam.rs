//! Conversions between [`Vector2`]/[`Vector3`] and glam's `DVec2`/`DVec3` (feature `glam`).
//!
//! `From` both ways (coordinates copied unchanged), plus curve constructors and accessors in
//! glam types.

use glam::{DVec2, DVec3};

use crate::curve::BezierCurve;
use crate::error::CoreError;
use crate::vector::{Vector2, Vector3};

impl From<DVec2> for Vector2 {
    #[inline]
    fn from(v: DVec2) -> Self {
        Self::new(v.x, v.y)
    }
}

impl From<Vector2> for DVec2 {
    #[inline]
    fn from(v: Vector2) -> Self {
        Self::new(v.x(), v.y())
    }
}

impl From<DVec3> for Vector3 {
    #[inline]
    fn from(v: DVec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<Vector3> for DVec3 {
    #[inline]
    fn from(v: Vector3) -> Self {
        Self::new(v.x(), v.y(), v.z())
    }
}

impl BezierCurve<2> {
    /// A planar curve from glam control points.
    ///
    /// # Errors
    /// As [`BezierCurve::new`].
    pub fn from_dvec2(points: &[DVec2]) -> Result<Self, CoreError> {
        Self::new(points.iter().copied().map(Vector2::from).collect())
    }

    /// The control points as glam vectors.
    #[must_use]
    pub fn to_dvec2(&self) -> Vec<DVec2> {
        self.points().iter().copied().map(DVec2::from).collect()
    }
}

impl BezierCurve<3> {
    /// A spatial curve from glam control points.
    ///
    /// # Errors
    /// As [`BezierCurve::new`].
    pub fn from_dvec3(points: &[DVec3]) -> Result<Self, CoreError> {
        Self::new(points.iter().copied().map(Vector3::from).collect())
    }

    /// The control points as glam vectors.
    #[must_use]
    pub fn to_dvec3(&self) -> Vec<DVec3> {
        self.points().iter().copied().map(DVec3::from).collect()
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
        let v = Vector3::new(1.0, -2.0, 3.5);
        assert_eq!(DVec3::from(v), DVec3::new(1.0, -2.0, 3.5));
        assert_eq!(Vector3::from(DVec3::from(v)), v);
        assert_eq!(
            Vector2::from(DVec2::new(0.25, 8.0)),
            Vector2::new(0.25, 8.0)
        );
    }
}
