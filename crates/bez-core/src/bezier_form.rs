//! `BezierForm`: the trait of every parametric curve on [0, 1] that is exactly a polynomial and
//! keeps its Bézier form.

use crate::vector::Vector;
use alloc::vec::Vec;

use crate::bbox::Aabb;
use crate::curve::BezierCurve;
use crate::error::CoreError;
use crate::nearest::Nearest;

/// A parametric curve C(t), t ∈ [0, 1], in D dimensions that is exactly a polynomial and keeps
/// its Bézier form: C(t) = Σ Qᵢ B_{i,n}(t) for the control points Qᵢ of [`Self::as_bezier`].
///
/// One required method, [`as_bezier`](Self::as_bezier), a free borrow of that form; every other
/// method is provided and runs bez-core's algorithm on it: evaluation, the hodograph, splitting,
/// subsegments, arc length, the nearest point, the tight bounding box, curvature. So a type that
/// stores its Bézier form (a λ-Bézier curve, a Class A curve, a subdivision-curve segment) gets
/// all of them, and a consumer written against `&C where C: BezierForm<D> + ?Sized` (the
/// flatteners of bez-subdiv) accepts every such curve, `&dyn BezierForm<D>` included.
///
/// Semantics are those of [`BezierCurve`]'s inherent methods of the same names, which the
/// defaults call: parameters outside [0, 1] and bad accuracies are [`CoreError`]s, and for a
/// [`BezierCurve`] itself the trait's results are bit for bit the inherent ones. Results that
/// are curves (the derivative, the pieces of a split) are plain [`BezierCurve`]s: a piece of a
/// λ-curve or of a Class A curve is in general not a curve of the same family.
///
/// Implementors may override a provided method only with a computation that returns the same
/// value (e.g. a cheaper route to the same end point); a closed form that differs in rounding
/// belongs in an inherent method.
///
/// ```
/// use bez_core::{BezierCurve, BezierForm, Vector2};
///
/// /// A quadratic stored with a name: it only has to lend out its Bézier form.
/// struct Named {
///     name: &'static str,
///     curve: BezierCurve<2>,
/// }
///
/// impl BezierForm<2> for Named {
///     fn as_bezier(&self) -> &BezierCurve<2> {
///         &self.curve
///     }
/// }
///
/// let arch = Named {
///     name: "arch",
///     curve: BezierCurve::new(vec![
///         Vector2::new(0.0, 0.0),
///         Vector2::new(1.0, 2.0),
///         Vector2::new(2.0, 0.0),
///     ])?,
/// };
/// assert_eq!(arch.eval(0.5)?, Vector2::new(1.0, 1.0));
/// assert_eq!(arch.bounding_box().max.y(), 1.0);
/// assert_eq!(arch.derivative()?.degree(), 1);
/// let (left, _) = arch.split(0.5)?;
/// assert_eq!(left.end(), arch.eval(0.5)?);
/// // Generic consumers take any implementor, sized or not.
/// fn chord<C: BezierForm<2> + ?Sized>(c: &C) -> f64 {
///     (c.end() - c.start()).norm()
/// }
/// assert_eq!(chord(&arch), 2.0);
/// assert_eq!(chord(&arch as &dyn BezierForm<2>), 2.0);
/// # let _ = arch.name;
/// # Ok::<(), bez_core::CoreError>(())
/// ```
pub trait BezierForm<const D: usize> {
    /// The exact Bézier form of the curve (a borrow, no computation).
    fn as_bezier(&self) -> &BezierCurve<D>;

    /// The polynomial degree n of the Bézier form.
    #[must_use]
    fn degree(&self) -> usize {
        self.as_bezier().degree()
    }

    /// C(0), exactly the first Bézier control point.
    #[must_use]
    fn start(&self) -> Vector<D> {
        self.as_bezier().start()
    }

    /// C(1), exactly the last Bézier control point.
    #[must_use]
    fn end(&self) -> Vector<D> {
        self.as_bezier().end()
    }

    /// C(t), as [`BezierCurve::eval`] (de Casteljau).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when t ∉ [0, 1] or t is NaN.
    #[inline]
    fn eval(&self, t: f64) -> Result<Vector<D>, CoreError> {
        self.as_bezier().eval(t)
    }

    /// C(t) at many parameters, appended to `out`, as [`BezierCurve::eval_many`] (O(n) each).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] for the first parameter outside [0, 1]; `out` then
    /// keeps the values computed before it.
    fn eval_many(&self, ts: &[f64], out: &mut Vec<Vector<D>>) -> Result<(), CoreError> {
        self.as_bezier().eval_many(ts, out)
    }

    /// C(t) at `count` uniformly spaced parameters 0, 1/(count−1), …, 1, as
    /// [`BezierCurve::sample_uniform`].
    ///
    /// # Errors
    /// [`CoreError::TooLarge`] when `count` exceeds [`MAX_SAMPLES`](crate::MAX_SAMPLES).
    fn sample_uniform(&self, count: usize) -> Result<Vec<Vector<D>>, CoreError> {
        self.as_bezier().sample_uniform(count)
    }

    /// The derivative C'(t) as a Bézier curve of degree n − 1 (the hodograph of the Bézier form).
    ///
    /// # Errors
    /// [`CoreError::Overflow`] when the hodograph leaves the coordinate range
    /// ([`MAX_COORDINATE`](crate::MAX_COORDINATE)).
    fn derivative(&self) -> Result<BezierCurve<D>, CoreError> {
        self.as_bezier().derivative()
    }

    /// The pieces on [0, t] and [t, 1], each reparametrized to [0, 1] (de Casteljau subdivision
    /// of the Bézier form, as [`BezierCurve::split`]).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] when t ∉ [0, 1].
    fn split(&self, t: f64) -> Result<(BezierCurve<D>, BezierCurve<D>), CoreError> {
        self.as_bezier().split(t)
    }

    /// The piece on [a, b] ⊆ [0, 1], reparametrized to [0, 1], as [`BezierCurve::subsegment`].
    ///
    /// # Errors
    /// [`CoreError::InvalidInterval`] unless 0 ≤ a < b ≤ 1.
    fn subsegment(&self, a: f64, b: f64) -> Result<BezierCurve<D>, CoreError> {
        self.as_bezier().subsegment(a, b)
    }

    /// The arc length ∫₀¹ |C'(t)| dt to within `accuracy` (absolute), by adaptive Gauss–Legendre
    /// quadrature ([`BezierCurve::arc_length`]).
    ///
    /// # Errors
    /// [`CoreError::InvalidTolerance`] unless `accuracy` is positive and finite.
    fn arc_length(&self, accuracy: f64) -> Result<f64, CoreError> {
        self.as_bezier().arc_length(accuracy)
    }

    /// The point of the curve nearest to `p`, the global minimum over t ∈ [0, 1]
    /// ([`BezierCurve::nearest`]: every root of (C(t) − p) · C'(t) is a candidate, so no
    /// accuracy parameter is needed).
    ///
    /// # Errors
    /// [`CoreError::NonFiniteQuery`] when `p` has a NaN or infinite coordinate.
    fn nearest(&self, p: &Vector<D>) -> Result<Nearest<D>, CoreError> {
        self.as_bezier().nearest(p)
    }

    /// The tight axis-aligned bounding box of the curve ([`BezierCurve::bounding_box`]).
    #[must_use]
    fn bounding_box(&self) -> Aabb<D> {
        self.as_bezier().bounding_box()
    }

    /// Unsigned curvature κ(t) = |C' ∧ C''| / |C'|³ ([`BezierCurve::curvature`]).
    ///
    /// # Errors
    /// [`CoreError::ParameterOutOfRange`] for t ∉ [0, 1]; [`CoreError::ZeroTangent`] where C'
    /// vanishes.
    fn curvature(&self, t: f64) -> Result<f64, CoreError> {
        self.as_bezier().curvature(t)
    }

    /// Signed curvature of a planar curve, κ(t) = (x'y'' − y'x'') / |C'|³, positive when turning
    /// left ([`BezierCurve::signed_curvature`]). Only for D = 2, and only on sized types (a
    /// trait object stays dyn compatible that way): through `&dyn BezierForm<2>` call
    /// `as_bezier().signed_curvature(t)`.
    ///
    /// # Errors
    /// As [`Self::curvature`].
    fn signed_curvature(&self, t: f64) -> Result<f64, CoreError>
    where
        Self: BezierForm<2> + Sized,
    {
        BezierForm::<2>::as_bezier(self).signed_curvature(t)
    }
}

impl<const D: usize> BezierForm<D> for BezierCurve<D> {
    #[inline(always)]
    fn as_bezier(&self) -> &BezierCurve<D> {
        self
    }
}

impl<const D: usize, C: BezierForm<D> + ?Sized> BezierForm<D> for &C {
    #[inline(always)]
    fn as_bezier(&self) -> &BezierCurve<D> {
        (**self).as_bezier()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Vector2, Vector3};

    fn cubic() -> BezierCurve<2> {
        BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 2.5),
            Vector2::new(3.0, -1.0),
            Vector2::new(4.0, 1.0),
        ])
        .unwrap()
    }

    /// Calls every provided method through the trait (never the inherent method).
    fn via_trait<C: BezierForm<2> + ?Sized>(c: &C, t: f64) -> Vec<f64> {
        let mut v = via_trait_unsized(c, t);
        v.push(c.as_bezier().signed_curvature(t).unwrap());
        v
    }

    fn via_trait_unsized<C: BezierForm<2> + ?Sized>(c: &C, t: f64) -> Vec<f64> {
        let mut out = Vec::new();
        c.eval_many(&[0.0, t, 1.0], &mut out).unwrap();
        let (l, r) = c.split(t).unwrap();
        let s = c.subsegment(0.25, t).unwrap();
        let n = c.nearest(&Vector2::new(2.0, 2.0)).unwrap();
        let b = c.bounding_box();
        let mut v = vec![c.degree() as f64];
        for p in [
            c.start(),
            c.end(),
            c.eval(t).unwrap(),
            out[1],
            l.end(),
            r.start(),
        ] {
            v.extend(p.iter());
        }
        v.extend(s.points().iter().flat_map(|p| p.iter().copied()));
        v.extend(
            c.derivative()
                .unwrap()
                .points()
                .iter()
                .flat_map(|p| p.iter().copied()),
        );
        v.extend(
            c.sample_uniform(5)
                .unwrap()
                .iter()
                .flat_map(|p| p.iter().copied()),
        );
        v.extend([n.t, n.distance, b.min.x(), b.min.y(), b.max.x(), b.max.y()]);
        v.push(c.arc_length(1e-10).unwrap());
        v.push(c.curvature(t).unwrap());
        v
    }

    #[test]
    fn trait_methods_are_bit_identical_to_inherent_ones() {
        let c = cubic();
        let t = 0.37;
        let (l, r) = c.split(t).unwrap();
        let n = c.nearest(&Vector2::new(2.0, 2.0)).unwrap();
        let b = c.bounding_box();
        let mut many = Vec::new();
        c.eval_many(&[0.0, t, 1.0], &mut many).unwrap();
        let mut expected = vec![c.degree() as f64];
        for p in [
            c.start(),
            c.end(),
            c.eval(t).unwrap(),
            many[1],
            l.end(),
            r.start(),
        ] {
            expected.extend(p.iter());
        }
        let s = c.subsegment(0.25, t).unwrap();
        expected.extend(s.points().iter().flat_map(|p| p.iter().copied()));
        expected.extend(
            c.derivative()
                .unwrap()
                .points()
                .iter()
                .flat_map(|p| p.iter().copied()),
        );
        expected.extend(
            c.sample_uniform(5)
                .unwrap()
                .iter()
                .flat_map(|p| p.iter().copied()),
        );
        expected.extend([n.t, n.distance, b.min.x(), b.min.y(), b.max.x(), b.max.y()]);
        expected.push(c.arc_length(1e-10).unwrap());
        expected.push(c.curvature(t).unwrap());
        expected.push(c.signed_curvature(t).unwrap());
        assert_eq!(via_trait(&c, t), expected);
        // Through a reference and a trait object: the same numbers.
        assert_eq!(via_trait(&&c, t), expected);
        let dynamic: &dyn BezierForm<2> = &c;
        assert_eq!(via_trait(dynamic, t), expected);
        // The sized-only method, through the trait.
        assert_eq!(BezierForm::signed_curvature(&c, t), c.signed_curvature(t));
    }

    #[test]
    fn trait_methods_keep_the_checked_semantics() {
        let c = cubic();
        let f: &dyn BezierForm<2> = &c;
        assert!(matches!(
            f.eval(1.5),
            Err(CoreError::ParameterOutOfRange { .. })
        ));
        assert!(f.eval_many(&[0.5, f64::NAN], &mut Vec::new()).is_err());
        assert!(f.split(-0.1).is_err());
        assert!(matches!(
            f.subsegment(0.6, 0.4),
            Err(CoreError::InvalidInterval { .. })
        ));
        assert!(matches!(
            f.arc_length(0.0),
            Err(CoreError::InvalidTolerance { .. })
        ));
        assert_eq!(
            f.nearest(&Vector2::new(f64::INFINITY, 0.0)),
            Err(CoreError::NonFiniteQuery)
        );
        let dot = BezierCurve::new(vec![Vector2::new(1.0, 1.0); 3]).unwrap();
        assert_eq!(
            BezierForm::signed_curvature(&dot, 0.5),
            Err(CoreError::ZeroTangent { t: 0.5 })
        );
    }

    #[test]
    #[cfg(feature = "proptest-support")]
    fn oracle_check_accepts_the_truth_and_rejects_a_shifted_oracle() {
        use crate::proptest_support::check_bezier_form;
        // (t, t²) in Bernstein form.
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(0.5, 0.0),
            Vector2::new(1.0, 1.0),
        ])
        .unwrap();
        let pos = |t: f64| Vector2::new(t, t * t);
        let vel = |t: f64| Vector2::new(1.0, 2.0 * t);
        assert_eq!(check_bezier_form(&c, pos, vel, 1e-14), Ok(()));
        let shifted = |t: f64| Vector2::new(t, t * t + 1e-9);
        let e = check_bezier_form(&c, shifted, vel, 1e-12).unwrap_err();
        assert!(e.starts_with("eval at t = 0"), "{e}");
        let slow = |t: f64| Vector2::new(1.0, 2.0 * t) * (1.0 - 1e-6);
        let e = check_bezier_form(&c, pos, slow, 1e-12).unwrap_err();
        assert!(e.starts_with("derivative"), "{e}");
    }

    #[test]
    fn spatial_curves_implement_the_trait() {
        // (t, t², t³) in Bernstein form: length by an independent fine midpoint rule.
        let c = BezierCurve::new(vec![
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(1.0 / 3.0, 0.0, 0.0),
            Vector3::new(2.0 / 3.0, 1.0 / 3.0, 0.0),
            Vector3::new(1.0, 1.0, 1.0),
        ])
        .unwrap();
        let f: &dyn BezierForm<3> = &c;
        let m = 200_000;
        let midpoint: f64 = (0..m)
            .map(|k| {
                let t = (k as f64 + 0.5) / m as f64;
                (1.0 + 4.0 * t * t + 9.0 * t.powi(4)).sqrt()
            })
            .sum::<f64>()
            / m as f64;
        assert!((f.arc_length(1e-12).unwrap() - midpoint).abs() < 1e-9);
        let b = f.bounding_box();
        assert_eq!(
            (b.min, b.max),
            (Vector3::zeros(), Vector3::new(1.0, 1.0, 1.0))
        );
        // κ(0) = 2 for the twisted cubic.
        assert!((f.curvature(0.0).unwrap() - 2.0).abs() < 1e-12);
    }
}
