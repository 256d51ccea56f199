//! What several test files share: a seeded generator without dependencies.

use bez_core::Vector3;

/// SplitMix64 with uniform reals, ranges and unit vectors.
pub(crate) struct Rng(pub(crate) u64);

impl Rng {
    /// Uniform in [0, 1].
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64
    }

    /// Uniform in [lo, hi].
    pub(crate) fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    /// A random unit vector (rejection from the unit ball without its core).
    pub(crate) fn unit(&mut self) -> Vector3 {
        loop {
            let v = Vector3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            if v.norm() > 0.1 && v.norm() <= 1.0 {
                return v / v.norm();
            }
        }
    }
}
