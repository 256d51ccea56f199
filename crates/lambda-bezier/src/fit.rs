//! Choosing λ by optimization: the value in the valid interval that brings a curve closest to
//! a target (a point to pass near, a curvature to reach), or that minimizes any cost.

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::brent::BrentOpt;
use bez_core::{BezierForm, CoreError, Vector};

use crate::curve::LambdaBezierCurve;
use crate::error::LambdaError;
use crate::range::LambdaRange;

/// What λ should achieve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum LambdaTarget<const D: usize> {
    /// The curve passes as close as possible to this point (residual: the distance from the
    /// point to the curve).
    Point(Vector<D>),
    /// The curvature at parameter `t` is as close as possible to `kappa` (residual:
    /// |κ(t) − kappa|; unsigned curvature in any dimension).
    Curvature {
        /// The parameter in [0, 1].
        t: f64,
        /// The curvature wanted (≥ 0).
        kappa: f64,
    },
}

/// The λ found and how far from the target it leaves the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct LambdaFit {
    /// The shape parameter, inside the valid interval.
    pub lambda: f64,
    /// The remaining distance to the target (0 when it is met exactly).
    pub residual: f64,
}

/// Scan points that bracket the minimum before Brent refines it.
const SCAN: u32 = 400;

/// The λ in the valid interval of the control polygon's n that minimizes the residual of
/// `target` ([`minimize_over_range`] on it).
///
/// # Errors
/// The errors of [`LambdaBezierCurve::new`] for the points; [`bez_core::CoreError`] variants
/// for a non-finite target point or a parameter t outside [0, 1];
/// [`LambdaError::NoMinimum`] when no λ gives a finite residual.
pub fn fit_lambda<const D: usize>(
    points: &[Vector<D>],
    target: &LambdaTarget<D>,
) -> Result<LambdaFit, LambdaError> {
    let curve = LambdaBezierCurve::new(points.to_vec(), 0.0)?;
    let residual = |lambda: f64| -> Result<f64, LambdaError> {
        let c = curve.with_lambda(lambda)?;
        Ok(match *target {
            LambdaTarget::Point(p) => c.nearest(&p)?.distance,
            LambdaTarget::Curvature { t, kappa } => (c.curvature(t)? - kappa).abs(),
        })
    };
    // Input errors (a bad target) show at any λ: report them rather than "no minimum".
    if let LambdaTarget::Point(p) = target {
        curve.nearest(p)?;
    }
    if let LambdaTarget::Curvature { t, .. } = *target
        && !(0.0..=1.0).contains(&t)
    {
        return Err(CoreError::ParameterOutOfRange {
            name: "t",
            value: t,
        }
        .into());
    }
    let range = curve.lambda_range();
    let lambda = minimize_over_range(&range, |l| residual(l).unwrap_or(f64::INFINITY))?;
    Ok(LambdaFit {
        lambda,
        residual: residual(lambda)?,
    })
}

/// Minimizes `cost` over the valid λ interval of `range`: a scan of 401 evenly spaced values
/// brackets the smallest, and argmin's Brent method refines it in the neighbouring interval
/// (tolerance √ε relative, 10⁻¹³ absolute). A cost that is not finite at some λ counts as +∞
/// there. The result is a global minimum up to the scan's resolution (a basin narrower than
/// 1/400 of the interval can be missed).
///
/// # Errors
/// [`LambdaError::NoMinimum`] when the cost is not finite anywhere on the scan or Brent fails.
pub fn minimize_over_range(
    range: &LambdaRange,
    cost: impl Fn(f64) -> f64,
) -> Result<f64, LambdaError> {
    let (a, b) = (range.min(), range.max());
    let step = (b - a) / f64::from(SCAN);
    let mut best = (f64::INFINITY, a);
    for i in 0..=SCAN {
        let x = a + step * f64::from(i);
        let v = cost(x);
        if v < best.0 {
            best = (v, x);
        }
    }
    if !best.0.is_finite() {
        return Err(LambdaError::NoMinimum);
    }
    let lo = (best.1 - step).max(a);
    let hi = (best.1 + step).min(b);
    let solver = BrentOpt::new(lo, hi).set_tolerance(f64::EPSILON.sqrt(), 1e-13);
    let result = Executor::new(Cost(cost), solver)
        .configure(|s| s.max_iters(200))
        .run()
        .map_err(|_| LambdaError::NoMinimum)?;
    let lambda = result
        .state()
        .get_best_param()
        .copied()
        .ok_or(LambdaError::NoMinimum)?;
    Ok(lambda.clamp(a, b))
}

/// A cost in λ for argmin; non-finite values become +∞ (Brent then moves away from them).
struct Cost<F: Fn(f64) -> f64>(F);

impl<F: Fn(f64) -> f64> CostFunction for Cost<F> {
    type Param = f64;
    type Output = f64;
    fn cost(&self, x: &f64) -> Result<f64, argmin::core::Error> {
        let v = (self.0)(*x);
        Ok(if v.is_nan() { f64::INFINITY } else { v })
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use bez_core::Vector2;

    fn polygon() -> Vec<Vector2> {
        vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 2.0),
            Vector2::new(3.0, 2.5),
            Vector2::new(4.0, 0.0),
        ]
    }

    /// Targets read off the curve of a known λ give that λ back with zero residual.
    #[test]
    fn recovers_the_lambda_a_target_was_taken_from() {
        for lambda0 in [-2.1, -0.4, 0.37, 0.9] {
            let c = LambdaBezierCurve::new(polygon(), lambda0).unwrap();
            let on_curve = c.eval(0.5).unwrap();
            let fit = fit_lambda(&polygon(), &LambdaTarget::Point(on_curve)).unwrap();
            assert!(fit.residual < 1e-7, "{fit:?}");
            assert!((fit.lambda - lambda0).abs() < 1e-6, "{fit:?} vs {lambda0}");
            let kappa = c.curvature(0.5).unwrap();
            let fit = fit_lambda(&polygon(), &LambdaTarget::Curvature { t: 0.5, kappa }).unwrap();
            assert!(fit.residual < 1e-7 * kappa, "{fit:?}");
            let back = LambdaBezierCurve::new(polygon(), fit.lambda).unwrap();
            assert!((back.curvature(0.5).unwrap() - kappa).abs() < 1e-7 * kappa);
        }
    }

    #[test]
    fn minimizes_a_cost_over_the_valid_interval() {
        let range = LambdaRange::new(3).unwrap();
        let l = minimize_over_range(&range, |l| (l - 0.2) * (l - 0.2)).unwrap();
        assert!((l - 0.2).abs() < 1e-7, "{l}");
        // A minimum outside the interval lands on its end.
        let l = minimize_over_range(&range, |l| (l - 7.0).abs()).unwrap();
        assert!((l - range.max()).abs() < 1e-7, "{l}");
        assert_eq!(
            minimize_over_range(&range, |_| f64::NAN),
            Err(LambdaError::NoMinimum)
        );
    }

    #[test]
    fn bad_targets_are_errors() {
        let far = LambdaTarget::Point(Vector2::new(f64::NAN, 0.0));
        assert!(matches!(
            fit_lambda(&polygon(), &far),
            Err(LambdaError::Core(_))
        ));
        let t = LambdaTarget::Curvature { t: 1.5, kappa: 1.0 };
        assert!(matches!(
            fit_lambda(&polygon(), &t),
            Err(LambdaError::Core(_))
        ));
        assert!(fit_lambda(&polygon()[..2], &t).is_err());
    }
}
