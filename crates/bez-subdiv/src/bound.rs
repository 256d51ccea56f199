//! Beyond the paper: an a-priori bound on the subdivision depth (after Wang Guo-Zhao, 1984).

use bez_core::BezierCurve;

use crate::flatten::curve_size;

/// The largest second difference M = maxᵢ |Pᵢ − 2Pᵢ₊₁ + Pᵢ₊₂| (0 below degree 2).
#[must_use]
pub fn max_second_difference(curve: &BezierCurve<2>) -> f64 {
    curve
        .points()
        .windows(3)
        .map(|w| (w[0] - w[1] * 2.0 + w[2]).norm())
        .fold(0.0, f64::max)
}

/// A depth r that uniform halving never needs to exceed for eq. (3) with tolerance ε:
/// r = ⌈log₄(n² M / (8 ε s))⌉ (0 if that is ≤ 0), s the size of eq. (3).
///
/// Why: a control polygon whose second differences are bounded by M deviates from the line
/// through its end points by at most M i(n − i)/2 ≤ M n²/8 at control point i, and each de
/// Casteljau halving divides the bound on the second differences by 4. This is Wang's formula
/// adapted to eq. (3)'s relative tolerance. The fixed rule's depth never exceeds it (tested).
#[must_use]
pub fn wang_depth(curve: &BezierCurve<2>, tolerance: f64) -> usize {
    let n = curve.degree() as f64;
    let m = max_second_difference(curve);
    let s = curve_size(curve);
    if m == 0.0 || s == 0.0 || tolerance.is_nan() || tolerance <= 0.0 {
        return 0;
    }
    let ratio = n * n * m / (8.0 * tolerance * s);
    if ratio <= 1.0 {
        0
    } else {
        // log₄ of a finite positive ratio; the cast saturates for absurd inputs.
        ratio.log(4.0).ceil() as usize
    }
}
