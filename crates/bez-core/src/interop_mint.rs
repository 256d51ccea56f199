//! Conversions between [`Vector2`]/[`Vector3`] and mint's point and vector types (feature
//! `mint`).
//!
//! mint is the interchange vocabulary of the Rust math ecosystem: any library that speaks it
//! (cgmath, euclid, glam, nalgebra, kurbo, …) converts to and from bez-core through these
//! `From` impls. Coordinates are copied unchanged.

use crate::vector::{Vector2, Vector3};

impl From<mint::Point2<f64>> for Vector2 {
    #[inline]
    fn from(p: mint::Point2<f64>) -> Self {
        Self::new(p.x, p.y)
    }
}

impl From<Vector2> for mint::Point2<f64> {
    #[inline]
    fn from(v: Vector2) -> Self {
        Self { x: v.x(), y: v.y() }
    }
}

impl From<mint::Vector2<f64>> for Vector2 {
    #[inline]
    fn from(p: mint::Vector2<f64>) -> Self {
        Self::new(p.x, p.y)
    }
}

impl From<Vector2> for mint::Vector2<f64> {
    #[inline]
    fn from(v: Vector2) -> Self {
        Self { x: v.x(), y: v.y() }
    }
}

impl From<mint::Point3<f64>> for Vector3 {
    #[inline]
    fn from(p: mint::Point3<f64>) -> Self {
        Self::new(p.x, p.y, p.z)
    }
}

impl From<Vector3> for mint::Point3<f64> {
    #[inline]
    fn from(v: Vector3) -> Self {
        Self {
            x: v.x(),
            y: v.y(),
            z: v.z(),
        }
    }
}

impl From<mint::Vector3<f64>> for Vector3 {
    #[inline]
    fn from(p: mint::Vector3<f64>) -> Self {
        Self::new(p.x, p.y, p.z)
    }
}

impl From<Vector3> for mint::Vector3<f64> {
    #[inline]
    fn from(v: Vector3) -> Self {
        Self {
            x: v.x(),
            y: v.y(),
            z: v.z(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mint_round_trips_keep_every_coordinate_in_place() {
        let v = Vector2::new(1.5, -2.25);
        let p: mint::Point2<f64> = v.into();
        assert_eq!((p.x, p.y), (1.5, -2.25));
        assert_eq!(Vector2::from(p), v);
        let w: mint::Vector2<f64> = v.into();
        assert_eq!((w.x, w.y), (1.5, -2.25));
        assert_eq!(Vector2::from(w), v);

        let v = Vector3::new(1.0, -2.0, 3.5);
        let p: mint::Point3<f64> = v.into();
        assert_eq!((p.x, p.y, p.z), (1.0, -2.0, 3.5));
        assert_eq!(Vector3::from(p), v);
        let w: mint::Vector3<f64> = v.into();
        assert_eq!((w.x, w.y, w.z), (1.0, -2.0, 3.5));
        assert_eq!(Vector3::from(w), v);
    }
}
