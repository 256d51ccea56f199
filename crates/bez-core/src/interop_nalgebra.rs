//! Conversions between [`Vector<D>`] and `nalgebra::SVector<f64, D>` (feature `nalgebra`).
//!
//! For crates that factor matrices with nalgebra and exchange points with bez-core: the
//! coordinates are copied unchanged, in order.

use nalgebra::SVector;

use crate::vector::Vector;

impl<const D: usize> From<SVector<f64, D>> for Vector<D> {
    #[inline]
    fn from(v: SVector<f64, D>) -> Self {
        Self::from_fn(|i| v[i])
    }
}

impl<const D: usize> From<Vector<D>> for SVector<f64, D> {
    #[inline]
    fn from(v: Vector<D>) -> Self {
        Self::from(v.to_array())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::{Vector2, Vector3};

    #[test]
    fn nalgebra_round_trip() {
        let v = Vector3::new(1.0, -2.0, 3.5);
        let n: SVector<f64, 3> = v.into();
        assert_eq!(n, nalgebra::Vector3::new(1.0, -2.0, 3.5));
        assert_eq!(Vector3::from(n), v);
        let w = nalgebra::Vector2::new(0.25, -8.0);
        assert_eq!(Vector2::from(w), Vector2::new(0.25, -8.0));
        // Same formulas, same bits.
        let a = nalgebra::Vector3::new(0.1, -2.7, 3.3);
        let b = nalgebra::Vector3::new(1.9, 0.35, -4.1);
        let (va, vb) = (Vector3::from(a), Vector3::from(b));
        assert_eq!(va.dot(&vb).to_bits(), a.dot(&b).to_bits());
        assert_eq!(va.norm().to_bits(), a.norm().to_bits());
        assert_eq!(va.cross(&vb), Vector3::from(a.cross(&b)));
        assert_eq!(va.normalize(), Vector3::from(a.normalize()));
        let (p, q) = (
            nalgebra::Vector2::new(0.3, -1.7),
            nalgebra::Vector2::new(2.2, 0.9),
        );
        assert_eq!(
            Vector2::from(p).perp(&Vector2::from(q)).to_bits(),
            p.perp(&q).to_bits()
        );
        assert_eq!(Vector2::from(p).norm().to_bits(), p.norm().to_bits());
    }
}
