//! A small fixed-size `f64` vector: the points and vectors of every curve and surface.
//!
//! [`Vector<D>`] wraps `[f64; D]` and is `Copy`; every operation is a short loop over the
//! compile-time length, inlined and free of heap allocation. The arithmetic follows the naive
//! formulas in a fixed order so results are reproducible bit for bit: sums run left to right
//! (`dot` = ((a₀b₀ + a₁b₁) + a₂b₂) + …, `norm` = √ of that sum of squares), products and quotients
//! act componentwise. In two and three dimensions these are the same operations, in the same
//! order, as nalgebra's fixed-size vectors, so values computed with either agree exactly.

use crate::math;
use core::fmt;
use core::iter::Sum;
use core::ops::{
    Add, AddAssign, Div, DivAssign, Index, IndexMut, Mul, MulAssign, Neg, Sub, SubAssign,
};

/// A point or vector in `D` dimensions with `f64` coordinates.
///
/// ```
/// use bez_core::{Vector2, Vector3};
///
/// let a = Vector2::new(3.0, 4.0);
/// assert_eq!(a.norm(), 5.0);
/// assert_eq!(a + Vector2::new(1.0, -1.0), Vector2::new(4.0, 3.0));
/// assert_eq!(2.0 * a, a * 2.0);
/// assert_eq!(a.perp(&Vector2::new(0.0, 1.0)), 3.0);
/// let z = Vector3::new(1.0, 0.0, 0.0).cross(&Vector3::new(0.0, 1.0, 0.0));
/// assert_eq!(z, Vector3::new(0.0, 0.0, 1.0));
/// assert_eq!(z.to_array(), [0.0, 0.0, 1.0]);
/// ```
#[derive(Clone, Copy, PartialEq)]
// Transparent: passed and returned exactly like `[f64; D]` (in registers); without it a
// cubic's evaluation took 3x as long.
#[repr(transparent)]
pub struct Vector<const D: usize>([f64; D]);

/// A planar point or vector.
pub type Vector2 = Vector<2>;
/// A spatial point or vector.
pub type Vector3 = Vector<3>;

impl<const D: usize> Vector<D> {
    /// The zero vector.
    pub const ZERO: Self = Self([0.0; D]);

    /// The zero vector (same as [`Vector::ZERO`]).
    #[inline]
    #[must_use]
    pub const fn zeros() -> Self {
        Self::ZERO
    }

    /// The vector with the given coordinates.
    #[inline]
    #[must_use]
    pub const fn from_array(coords: [f64; D]) -> Self {
        Self(coords)
    }

    /// The vector whose coordinate `i` is `f(i)`.
    ///
    /// ```
    /// use bez_core::Vector3;
    /// assert_eq!(Vector3::from_fn(|i| i as f64), Vector3::new(0.0, 1.0, 2.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn from_fn(f: impl FnMut(usize) -> f64) -> Self {
        Self(core::array::from_fn(f))
    }

    /// The vector with every coordinate equal to `value`.
    #[inline]
    #[must_use]
    pub const fn repeat(value: f64) -> Self {
        Self([value; D])
    }

    /// The coordinates as an array.
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [f64; D] {
        self.0
    }

    /// The coordinates as a borrowed array.
    #[inline]
    #[must_use]
    pub const fn as_array(&self) -> &[f64; D] {
        &self.0
    }

    /// The coordinates as a mutable array.
    #[inline]
    pub fn as_mut_array(&mut self) -> &mut [f64; D] {
        &mut self.0
    }

    /// The coordinates as a slice.
    #[inline]
    #[must_use]
    pub const fn as_slice(&self) -> &[f64] {
        &self.0
    }

    /// An iterator over the coordinates.
    #[inline]
    pub fn iter(&self) -> core::slice::Iter<'_, f64> {
        self.0.iter()
    }

    /// An iterator over mutable references to the coordinates.
    #[inline]
    pub fn iter_mut(&mut self) -> core::slice::IterMut<'_, f64> {
        self.0.iter_mut()
    }

    /// The vector with `f` applied to every coordinate.
    #[inline]
    #[must_use]
    pub fn map(mut self, mut f: impl FnMut(f64) -> f64) -> Self {
        for a in &mut self.0 {
            *a = f(*a);
        }
        self
    }

    /// The vector whose coordinate `i` is `f(self[i], other[i])`.
    #[inline]
    #[must_use]
    pub fn zip_map(&self, other: &Self, mut f: impl FnMut(f64, f64) -> f64) -> Self {
        let mut out = *self;
        for (a, b) in out.0.iter_mut().zip(other.0) {
            *a = f(*a, b);
        }
        out
    }

    /// The dot product a₀b₀ + a₁b₁ + …, summed left to right.
    #[inline]
    #[must_use]
    pub fn dot(&self, other: &Self) -> f64 {
        if D == 0 {
            return 0.0;
        }
        let mut acc = self.0[0] * other.0[0];
        for i in 1..D {
            acc += self.0[i] * other.0[i];
        }
        acc
    }

    /// The squared Euclidean length, `self.dot(self)`.
    #[inline]
    #[must_use]
    pub fn norm_squared(&self) -> f64 {
        self.dot(self)
    }

    /// The Euclidean length, √[`norm_squared`](Self::norm_squared).
    #[inline]
    #[must_use]
    pub fn norm(&self) -> f64 {
        math::sqrt(self.norm_squared())
    }

    /// The Euclidean distance |self − other|.
    #[inline]
    #[must_use]
    pub fn distance(&self, other: &Self) -> f64 {
        (*self - *other).norm()
    }

    /// The vector divided by its length (coordinates NaN or infinite for the zero vector).
    #[inline]
    #[must_use]
    pub fn normalize(&self) -> Self {
        *self / self.norm()
    }

    /// The vector divided by its length, or `None` when the length is at most `min_norm`.
    #[inline]
    #[must_use]
    pub fn try_normalize(&self, min_norm: f64) -> Option<Self> {
        let n = self.norm();
        (n > min_norm).then(|| *self / n)
    }

    /// The componentwise absolute value.
    #[inline]
    #[must_use]
    pub fn abs(&self) -> Self {
        self.map(f64::abs)
    }

    /// Whether every coordinate is finite (neither NaN nor infinite).
    #[inline]
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.0.iter().all(|x| x.is_finite())
    }

    /// The componentwise minimum (as [`f64::min`]).
    #[inline]
    #[must_use]
    pub fn inf(&self, other: &Self) -> Self {
        self.zip_map(other, f64::min)
    }

    /// The componentwise maximum (as [`f64::max`]).
    #[inline]
    #[must_use]
    pub fn sup(&self, other: &Self) -> Self {
        self.zip_map(other, f64::max)
    }

    /// The componentwise product.
    #[inline]
    #[must_use]
    pub fn component_mul(&self, other: &Self) -> Self {
        self.zip_map(other, |a, b| a * b)
    }

    /// The largest absolute value of a coordinate (0 in zero dimensions).
    #[inline]
    #[must_use]
    pub fn amax(&self) -> f64 {
        self.fold_first(f64::abs, |m, x| m.max(x.abs()))
    }

    /// The largest coordinate, by [`f64::max`] from the first (0 in zero dimensions).
    #[inline]
    #[must_use]
    pub fn max(&self) -> f64 {
        self.fold_first(|x| x, f64::max)
    }

    /// The smallest coordinate, by [`f64::min`] from the first (0 in zero dimensions).
    #[inline]
    #[must_use]
    pub fn min(&self) -> f64 {
        self.fold_first(|x| x, f64::min)
    }

    /// Folds the coordinates left to right, starting from `init(first)` (0 if there is none).
    #[inline]
    fn fold_first(&self, init: impl FnOnce(f64) -> f64, f: impl FnMut(f64, f64) -> f64) -> f64 {
        match self.0.split_first() {
            Some((&first, rest)) => rest.iter().copied().fold(init(first), f),
            None => 0.0,
        }
    }
}

impl Vector<2> {
    /// The planar vector (x, y).
    #[inline]
    #[must_use]
    pub const fn new(x: f64, y: f64) -> Self {
        Self([x, y])
    }

    /// The first coordinate.
    #[inline]
    #[must_use]
    pub const fn x(&self) -> f64 {
        self.0[0]
    }

    /// The second coordinate.
    #[inline]
    #[must_use]
    pub const fn y(&self) -> f64 {
        self.0[1]
    }

    /// The scalar cross product a.x b.y − a.y b.x (the z of the 3-D cross product).
    #[inline]
    #[must_use]
    pub fn perp(&self, other: &Self) -> f64 {
        self.0[0] * other.0[1] - self.0[1] * other.0[0]
    }
}

impl Vector<3> {
    /// The spatial vector (x, y, z).
    #[inline]
    #[must_use]
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Self([x, y, z])
    }

    /// The first coordinate.
    #[inline]
    #[must_use]
    pub const fn x(&self) -> f64 {
        self.0[0]
    }

    /// The second coordinate.
    #[inline]
    #[must_use]
    pub const fn y(&self) -> f64 {
        self.0[1]
    }

    /// The third coordinate.
    #[inline]
    #[must_use]
    pub const fn z(&self) -> f64 {
        self.0[2]
    }

    /// The first two coordinates.
    #[inline]
    #[must_use]
    pub const fn xy(&self) -> Vector2 {
        Vector2::new(self.0[0], self.0[1])
    }

    /// The cross product (a.y b.z − a.z b.y, a.z b.x − a.x b.z, a.x b.y − a.y b.x).
    #[inline]
    #[must_use]
    pub fn cross(&self, other: &Self) -> Self {
        let [ax, ay, az] = self.0;
        let [bx, by, bz] = other.0;
        Self([ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx])
    }
}

impl<const D: usize> Default for Vector<D> {
    #[inline]
    fn default() -> Self {
        Self::ZERO
    }
}

impl<const D: usize> fmt::Debug for Vector<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Vector")?;
        f.debug_list().entries(self.0.iter()).finish()
    }
}

/// `[x, y, …]`, each coordinate formatted with the given options (e.g. `{:.3}`).
impl<const D: usize> fmt::Display for Vector<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("[")?;
        for (i, x) in self.0.iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            fmt::Display::fmt(x, f)?;
        }
        f.write_str("]")
    }
}

impl<const D: usize> From<[f64; D]> for Vector<D> {
    #[inline]
    fn from(coords: [f64; D]) -> Self {
        Self(coords)
    }
}

impl<const D: usize> From<Vector<D>> for [f64; D] {
    #[inline]
    fn from(v: Vector<D>) -> Self {
        v.0
    }
}

impl<const D: usize> AsRef<[f64]> for Vector<D> {
    #[inline]
    fn as_ref(&self) -> &[f64] {
        &self.0
    }
}

impl<const D: usize> Index<usize> for Vector<D> {
    type Output = f64;
    #[inline]
    fn index(&self, i: usize) -> &f64 {
        &self.0[i]
    }
}

impl<const D: usize> IndexMut<usize> for Vector<D> {
    #[inline]
    fn index_mut(&mut self, i: usize) -> &mut f64 {
        &mut self.0[i]
    }
}

impl<const D: usize> IntoIterator for Vector<D> {
    type Item = f64;
    type IntoIter = core::array::IntoIter<f64, D>;
    #[inline]
    fn into_iter(self) -> Self::IntoIter {
        self.0.into_iter()
    }
}

impl<'a, const D: usize> IntoIterator for &'a Vector<D> {
    type Item = &'a f64;
    type IntoIter = core::slice::Iter<'a, f64>;
    #[inline]
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

/// `Add`/`Sub` for every combination of owned and borrowed operands, componentwise.
macro_rules! binary_op {
    ($Trait:ident, $method:ident, $Assign:ident, $assign:ident, $op:tt, $aop:tt) => {
        impl<const D: usize> $Trait for Vector<D> {
            type Output = Self;
            #[inline]
            fn $method(mut self, rhs: Self) -> Self {
                // An in-place indexed loop: it unrolls and stays in registers.
                for i in 0..D {
                    self.0[i] $aop rhs.0[i];
                }
                self
            }
        }
        impl<const D: usize> $Trait<&Vector<D>> for Vector<D> {
            type Output = Self;
            #[inline]
            fn $method(self, rhs: &Self) -> Self {
                self.$method(*rhs)
            }
        }
        impl<const D: usize> $Trait<Vector<D>> for &Vector<D> {
            type Output = Vector<D>;
            #[inline]
            fn $method(self, rhs: Vector<D>) -> Vector<D> {
                (*self).$method(rhs)
            }
        }
        impl<const D: usize> $Trait<&Vector<D>> for &Vector<D> {
            type Output = Vector<D>;
            #[inline]
            fn $method(self, rhs: &Vector<D>) -> Vector<D> {
                (*self).$method(*rhs)
            }
        }
        impl<const D: usize> $Assign for Vector<D> {
            #[inline]
            fn $assign(&mut self, rhs: Self) {
                *self = *self $op rhs;
            }
        }
        impl<const D: usize> $Assign<&Vector<D>> for Vector<D> {
            #[inline]
            fn $assign(&mut self, rhs: &Self) {
                *self = *self $op *rhs;
            }
        }
    };
}

binary_op!(Add, add, AddAssign, add_assign, +, +=);
binary_op!(Sub, sub, SubAssign, sub_assign, -, -=);

/// `Mul<f64>`/`Div<f64>` for owned and borrowed vectors, componentwise.
macro_rules! scalar_op {
    ($Trait:ident, $method:ident, $Assign:ident, $assign:ident, $op:tt, $aop:tt) => {
        impl<const D: usize> $Trait<f64> for Vector<D> {
            type Output = Self;
            #[inline]
            fn $method(mut self, s: f64) -> Self {
                for i in 0..D {
                    self.0[i] $aop s;
                }
                self
            }
        }
        impl<const D: usize> $Trait<f64> for &Vector<D> {
            type Output = Vector<D>;
            #[inline]
            fn $method(self, s: f64) -> Vector<D> {
                (*self).$method(s)
            }
        }
        impl<const D: usize> $Assign<f64> for Vector<D> {
            #[inline]
            fn $assign(&mut self, s: f64) {
                *self = *self $op s;
            }
        }
    };
}

scalar_op!(Mul, mul, MulAssign, mul_assign, *, *=);
scalar_op!(Div, div, DivAssign, div_assign, /, /=);

impl<const D: usize> Mul<Vector<D>> for f64 {
    type Output = Vector<D>;
    #[inline]
    fn mul(self, v: Vector<D>) -> Vector<D> {
        v.map(|x| self * x)
    }
}

impl<const D: usize> Mul<&Vector<D>> for f64 {
    type Output = Vector<D>;
    #[inline]
    fn mul(self, v: &Vector<D>) -> Vector<D> {
        self * *v
    }
}

impl<const D: usize> Neg for Vector<D> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        self.map(|x| -x)
    }
}

impl<const D: usize> Neg for &Vector<D> {
    type Output = Vector<D>;
    #[inline]
    fn neg(self) -> Vector<D> {
        -*self
    }
}

/// The sum, accumulated left to right from the zero vector.
impl<const D: usize> Sum for Vector<D> {
    #[inline]
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::ZERO, |acc, v| acc + v)
    }
}

/// The sum, accumulated left to right from the zero vector.
impl<'a, const D: usize> Sum<&'a Vector<D>> for Vector<D> {
    #[inline]
    fn sum<I: Iterator<Item = &'a Self>>(iter: I) -> Self {
        iter.fold(Self::ZERO, |acc, v| acc + *v)
    }
}

/// Serialized as a flat sequence `[x, y, …]` of exactly `D` numbers.
#[cfg(feature = "serde")]
mod serde_impl {
    use core::fmt;
    use core::marker::PhantomData;

    use serde::de::{Error, SeqAccess, Visitor};
    use serde::ser::SerializeTuple;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    use super::Vector;

    impl<const D: usize> Serialize for Vector<D> {
        fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
            let mut tuple = serializer.serialize_tuple(D)?;
            for x in &self.0 {
                tuple.serialize_element(x)?;
            }
            tuple.end()
        }
    }

    struct VectorVisitor<const D: usize>(PhantomData<[f64; D]>);

    impl<'de, const D: usize> Visitor<'de> for VectorVisitor<D> {
        type Value = Vector<D>;

        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            write!(f, "a sequence of {D} numbers")
        }

        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vector<D>, A::Error> {
            let mut out = [0.0; D];
            for (i, slot) in out.iter_mut().enumerate() {
                *slot = seq
                    .next_element()?
                    .ok_or_else(|| Error::invalid_length(i, &self))?;
            }
            if seq.next_element::<serde::de::IgnoredAny>()?.is_some() {
                return Err(Error::invalid_length(D + 1, &self));
            }
            Ok(Vector(out))
        }
    }

    impl<'de, const D: usize> Deserialize<'de> for Vector<D> {
        fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
            deserializer.deserialize_tuple(D, VectorVisitor::<D>(PhantomData))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const A3: [f64; 3] = [0.1, -2.7, 3.3];
    const B3: [f64; 3] = [1.9, 0.35, -4.1];

    #[test]
    fn constructors_and_accessors() {
        let v = Vector2::new(1.5, -2.0);
        assert_eq!((v.x(), v.y()), (1.5, -2.0));
        let w = Vector3::new(1.0, 2.0, 3.0);
        assert_eq!((w.x(), w.y(), w.z()), (1.0, 2.0, 3.0));
        assert_eq!(w.xy(), Vector2::new(1.0, 2.0));
        assert_eq!(Vector3::from_array(A3).to_array(), A3);
        assert_eq!(Vector3::from(A3).as_array(), &A3);
        assert_eq!(<[f64; 3]>::from(Vector3::from(A3)), A3);
        assert_eq!(Vector3::from(A3).as_slice(), &A3[..]);
        assert_eq!(Vector::<4>::ZERO.to_array(), [0.0; 4]);
        assert_eq!(Vector::<4>::zeros(), Vector::<4>::default());
        assert_eq!(Vector2::repeat(7.0), Vector2::new(7.0, 7.0));
        assert_eq!(
            Vector3::from_fn(|i| (i * i) as f64),
            Vector3::new(0.0, 1.0, 4.0)
        );
        let mut m = Vector3::ZERO;
        m[1] = 4.0;
        m.as_mut_array()[2] = 5.0;
        assert_eq!(m, Vector3::new(0.0, 4.0, 5.0));
        for x in m.iter_mut() {
            *x += 1.0;
        }
        assert_eq!(m.iter().copied().collect::<Vec<_>>(), [1.0, 5.0, 6.0]);
        assert_eq!(m.into_iter().collect::<Vec<_>>(), [1.0, 5.0, 6.0]);
        assert_eq!((&m).into_iter().count(), 3);
        assert_eq!(format!("{m:?}"), "Vector[1.0, 5.0, 6.0]");
        assert_eq!(format!("{m}"), "[1, 5, 6]");
        assert_eq!(format!("{:.2}", Vector2::new(0.5, -1.0)), "[0.50, -1.00]");
    }

    #[test]
    #[allow(
        clippy::op_ref,
        reason = "the impls for borrowed operands are under test"
    )]
    fn arithmetic_is_componentwise_and_bit_exact() {
        let (a, b) = (Vector3::from(A3), Vector3::from(B3));
        let s = 0.3;
        for i in 0..3 {
            assert_eq!((a + b)[i].to_bits(), (A3[i] + B3[i]).to_bits());
            assert_eq!((a - b)[i].to_bits(), (A3[i] - B3[i]).to_bits());
            assert_eq!((&a + &b)[i], A3[i] + B3[i]);
            assert_eq!((&a - b)[i], A3[i] - B3[i]);
            assert_eq!((a + &b)[i], A3[i] + B3[i]);
            assert_eq!((-a)[i].to_bits(), (-A3[i]).to_bits());
            assert_eq!((-&a)[i], -A3[i]);
            assert_eq!((a * s)[i].to_bits(), (A3[i] * s).to_bits());
            assert_eq!((&a * s)[i], A3[i] * s);
            assert_eq!((s * a)[i].to_bits(), (s * A3[i]).to_bits());
            assert_eq!((s * &a)[i], s * A3[i]);
            assert_eq!((a / s)[i].to_bits(), (A3[i] / s).to_bits());
            assert_eq!((&a / s)[i], A3[i] / s);
            assert_eq!(a.abs()[i], A3[i].abs());
            assert_eq!(a.map(|x| x * x)[i], A3[i] * A3[i]);
            assert_eq!(a.component_mul(&b)[i], A3[i] * B3[i]);
            assert_eq!(a.inf(&b)[i], A3[i].min(B3[i]));
            assert_eq!(a.sup(&b)[i], A3[i].max(B3[i]));
        }
        let mut c = a;
        c += b;
        assert_eq!(c, a + b);
        c -= &b;
        c += &b;
        c -= b;
        assert_eq!(c, a + b - b);
        c *= s;
        assert_eq!(c, (a + b - b) * s);
        c /= s;
        assert_eq!(c, (a + b - b) * s / s);
    }

    #[test]
    fn reductions_sum_left_to_right() {
        let (a, b) = (Vector3::from(A3), Vector3::from(B3));
        let dot = A3[0] * B3[0] + A3[1] * B3[1] + A3[2] * B3[2];
        assert_eq!(a.dot(&b).to_bits(), dot.to_bits());
        let nsq = A3[0] * A3[0] + A3[1] * A3[1] + A3[2] * A3[2];
        assert_eq!(a.norm_squared().to_bits(), nsq.to_bits());
        assert_eq!(a.norm().to_bits(), nsq.sqrt().to_bits());
        assert_eq!(Vector2::new(3.0, 4.0).norm(), 5.0);
        assert_eq!(a.distance(&b), (a - b).norm());
        assert_eq!(Vector::<0>::ZERO.dot(&Vector::<0>::ZERO), 0.0);
        assert_eq!(Vector::<1>::from([-3.0]).norm(), 3.0);
        let n = a.normalize();
        for i in 0..3 {
            assert_eq!(n[i].to_bits(), (A3[i] / nsq.sqrt()).to_bits());
        }
        assert_eq!(a.try_normalize(0.0), Some(n));
        assert_eq!(Vector3::ZERO.try_normalize(0.0), None);
        assert_eq!(a.amax(), 3.3);
        assert_eq!(Vector3::new(-5.0, 1.0, 2.0).amax(), 5.0);
        assert_eq!(a.max(), 3.3);
        assert_eq!(a.min(), -2.7);
        assert_eq!(Vector::<0>::ZERO.max(), 0.0);
        let list = [a, b, a];
        let total: Vector3 = list.iter().sum();
        let owned: Vector3 = list.into_iter().sum();
        for i in 0..3 {
            assert_eq!(total[i].to_bits(), (0.0 + A3[i] + B3[i] + A3[i]).to_bits());
        }
        assert_eq!(total, owned);
    }

    #[test]
    fn cross_and_perp_match_their_determinants() {
        let (a, b) = (Vector3::from(A3), Vector3::from(B3));
        let c = a.cross(&b);
        assert_eq!(c[0], A3[1] * B3[2] - A3[2] * B3[1]);
        assert_eq!(c[1], A3[2] * B3[0] - A3[0] * B3[2]);
        assert_eq!(c[2], A3[0] * B3[1] - A3[1] * B3[0]);
        // Orthogonal to both factors, and the right-handed basis.
        assert!(c.dot(&a).abs() < 1e-13 && c.dot(&b).abs() < 1e-13);
        let (ex, ey) = (Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 1.0, 0.0));
        assert_eq!(ex.cross(&ey), Vector3::new(0.0, 0.0, 1.0));
        let (p, q) = (Vector2::new(A3[0], A3[1]), Vector2::new(B3[0], B3[1]));
        let lifted = Vector3::new(p.x(), p.y(), 0.0).cross(&Vector3::new(q.x(), q.y(), 0.0));
        assert_eq!(p.perp(&q), lifted.z());
        assert_eq!(Vector2::new(1.0, 0.0).perp(&Vector2::new(0.0, 1.0)), 1.0);
    }

    #[test]
    fn finiteness() {
        assert!(Vector3::from(A3).is_finite());
        assert!(!Vector2::new(f64::NAN, 0.0).is_finite());
        assert!(!Vector2::new(0.0, f64::NEG_INFINITY).is_finite());
    }
}
