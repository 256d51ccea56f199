//! Arc length by adaptive Gauss–Legendre quadrature.

use crate::casteljau::hodograph_slice;
use crate::curve::BezierCurve;
use crate::error::{CoreError, check_tolerance};
use crate::math;
use crate::vector::Vector;

/// Default accuracy for [`BezierCurve::arc_length`] and [`BezierCurve::nearest`].
pub const DEFAULT_ACCURACY: f64 = 1e-9;

/// 8-point Gauss–Legendre nodes on [−1, 1] (positive half) and weights.
const GL8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

const MAX_DEPTH: usize = 40;
/// Upper bound on the number of interval halvings, so that a tolerance below what rounding
/// allows cannot make the cost explode (2⁴⁰ intervals); the best estimate is returned then.
const MAX_SPLITS: usize = 1 << 14;

impl<const D: usize> BezierCurve<D> {
    /// Arc length ∫₀¹ |B'(t)| dt, to within `accuracy` (absolute).
    ///
    /// Adaptive 8-point Gauss–Legendre: an interval is accepted when its rule agrees with the
    /// sum over its two halves to within its share of the accuracy, else it is halved (depth
    /// capped at 40). Exact to rounding for a straight line with uniform speed; converges fast
    /// away from cusps.
    ///
    /// # Errors
    /// [`CoreError::InvalidTolerance`] unless `accuracy` is positive and finite.
    pub fn arc_length(&self, accuracy: f64) -> Result<f64, CoreError> {
        check_tolerance(accuracy)?;
        // The hodograph scaled by a power of two into [1, 2) (exact): its speed cannot overflow,
        // and the accuracy is scaled alike, so the result is that of the unscaled rule.
        let mut hodo = hodograph_slice(self.points());
        let scale = math::pow2_scale(hodo.iter().map(Vector::amax).fold(0.0, f64::max));
        for p in &mut hodo {
            *p /= scale;
        }
        let hodo = BezierCurve::from_valid(hodo);
        let speed = |t: f64| hodo.eval_unchecked(t).norm();
        let whole = gauss(&speed, 0.0, 1.0);
        let mut budget = MAX_SPLITS;
        let length = adapt(&speed, 0.0, 1.0, whole, accuracy / scale, 0, &mut budget) * scale;
        if length.is_finite() {
            Ok(length)
        } else {
            Err(CoreError::Overflow {
                operation: "arc_length",
            })
        }
    }
}

fn gauss(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    GL8.iter()
        .map(|&(x, w)| w * (f(c - h * x) + f(c + h * x)))
        .sum::<f64>()
        * h
}

fn adapt(
    f: &impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    whole: f64,
    acc: f64,
    depth: usize,
    budget: &mut usize,
) -> f64 {
    let m = 0.5 * (a + b);
    let (l, r) = (gauss(f, a, m), gauss(f, m, b));
    let sum = l + r;
    // A non-finite sum (overflowing coordinates) cannot improve by halving.
    if depth >= MAX_DEPTH || *budget == 0 || !sum.is_finite() || (sum - whole).abs() <= acc {
        return sum;
    }
    *budget -= 1;
    adapt(f, a, m, l, 0.5 * acc, depth + 1, budget)
        + adapt(f, m, b, r, 0.5 * acc, depth + 1, budget)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::Vector2;

    #[test]
    fn arc_length_of_parabola_matches_closed_form() {
        // y = x² for x ∈ [0, 1]: P = (0,0), (½,0), (1,1); L = (2√5 + asinh 2) / 4.
        let c = BezierCurve::new(vec![
            Vector2::new(0.0, 0.0),
            Vector2::new(0.5, 0.0),
            Vector2::new(1.0, 1.0),
        ])
        .unwrap();
        let exact = (2.0 * 5f64.sqrt() + 2f64.asinh()) / 4.0;
        for acc in [1e-3, 1e-6, 1e-12] {
            assert!((c.arc_length(acc).unwrap() - exact).abs() <= acc.max(1e-14));
        }
        assert!(c.arc_length(0.0).is_err());
        assert!(c.arc_length(f64::NAN).is_err());
    }
}
