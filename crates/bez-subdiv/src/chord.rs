//! Beyond the paper: how far an arc of the curve is from its chord *segment*, exactly.

use bez_core::{
    BezierCurve, bernstein_derivative_coeffs, eval_bernstein_poly, roots_in_unit_interval,
};

use crate::error::SubdivError;

/// The range [min, max] of a polynomial in Bernstein form on [0, 1]: its values at the end
/// points and at the roots of its derivative.
fn bernstein_range(coeffs: &[f64]) -> (f64, f64) {
    roots_in_unit_interval(&bernstein_derivative_coeffs(coeffs))
        .into_iter()
        .chain([0.0, 1.0])
        .map(|t| eval_bernstein_poly(coeffs, t))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        })
}

/// A bound on the distance of the arc B([a, b]) to its chord segment B(a)B(b), exact when the
/// arc projects inside the chord (the usual case): √(d² + o²), with d the largest
/// perpendicular offset of the arc from the chord line and o the largest overshoot of its
/// projection beyond either end of the chord (0 if none).
///
/// d and o are exact (o is replaced by its control-point bound when that is below 1e-12 of the
/// chord length, i.e. at the rounding level): with u the unit chord direction, the signed offset u × (B(t) − B(a)) and
/// the projection u · (B(t) − B(a)) are polynomials whose Bernstein coefficients come from the
/// control points of the arc, maximized at their end points or at the roots of their
/// derivatives. A degenerate chord (B(a) = B(b)) gives the largest control-point distance to
/// B(a), a bound on the arc's distance by the convex hull property.
///
/// When the bound is ≤ tol, the polyline through B(a), B(b) is within tol of the arc in
/// Hausdorff distance both ways (the arc joins the chord's end points, so its projection covers
/// the chord).
///
/// # Errors
/// [`SubdivError::Core`] when [a, b] is not a subinterval of [0, 1] with a < b.
pub fn chord_deviation(curve: &BezierCurve<2>, a: f64, b: f64) -> Result<f64, SubdivError> {
    let piece = curve.subsegment(a, b)?;
    let (p0, p1) = (piece.start(), piece.end());
    let d = p1 - p0;
    let len = d.norm();
    if len == 0.0 {
        return Ok(piece
            .points()
            .iter()
            .map(|p| (p - p0).norm())
            .fold(0.0, f64::max));
    }
    let u = d / len;
    let offset: Vec<f64> = piece
        .points()
        .iter()
        .map(|p| u.x() * (p.y() - p0.y()) - u.y() * (p.x() - p0.x()))
        .collect();
    let along: Vec<f64> = piece.points().iter().map(|p| u.dot(&(p - p0))).collect();
    let (dlo, dhi) = bernstein_range(&offset);
    let perpendicular = dlo.abs().max(dhi.abs());
    // The projection lies within the hull of its coefficients, so their overshoot bounds the
    // arc's. When that bound is at the rounding level (the usual case: the last coefficient is
    // len up to an ulp), it is used as is and no root isolation is needed for the projection.
    let (clo, chi) = along
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    let hull_overshoot = (-clo).max(chi - len).max(0.0);
    let overshoot = if hull_overshoot <= 1e-12 * len {
        hull_overshoot
    } else {
        let (plo, phi) = bernstein_range(&along);
        (-plo).max(phi - len).max(0.0)
    };
    Ok(perpendicular.hypot(overshoot))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::guaranteed::distance_to_segment;
    use crate::test_support::curve;

    #[test]
    fn parabola_arc_deviates_by_a_quarter_of_its_control_height() -> Result<(), SubdivError> {
        // y = 4h t(1 − t): the apex is at height h, the middle control point at 2h.
        let c = curve(&[(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)]);
        assert!((chord_deviation(&c, 0.0, 1.0)? - 1.0).abs() < 1e-14);
        // On [0, ½] the arc is the parabola's left half; its deviation from the chord
        // (0,0)–(1,1) is the distance of the parallel tangent point (t = ¼: (½, ¾)): 1/(4√2).
        let expected = 0.25 / 2f64.sqrt();
        assert!((chord_deviation(&c, 0.0, 0.5)? - expected).abs() < 1e-14);
        Ok(())
    }

    #[test]
    fn bound_matches_dense_sampling_and_sees_overshoot() -> Result<(), SubdivError> {
        let cases = [
            curve(&[(0.0, 0.0), (1.0, 3.0), (2.0, -2.0), (3.0, 1.0), (4.0, 0.0)]),
            // Folds back beyond its end point: the overshoot counts.
            curve(&[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0)]),
        ];
        for c in &cases {
            for (a, b) in [(0.0, 1.0), (0.1, 0.35), (0.6, 1.0)] {
                let bound = chord_deviation(c, a, b)?;
                let (pa, pb) = (c.eval(a)?, c.eval(b)?);
                let sampled = (0..=4000)
                    .map(|k| {
                        let t = a + (b - a) * f64::from(k) / 4000.0;
                        c.eval(t).map(|p| distance_to_segment(&p, &pa, &pb))
                    })
                    .try_fold(0.0, |m: f64, d| d.map(|d| m.max(d)))?;
                assert!(bound >= sampled - 1e-12, "{bound} < {sampled}");
                assert!(bound <= sampled * 1.01 + 1e-12, "{bound} vs {sampled}");
            }
        }
        Ok(())
    }

    #[test]
    fn bad_interval_is_an_error() {
        let c = curve(&[(0.0, 0.0), (1.0, 1.0)]);
        assert!(chord_deviation(&c, 0.5, 0.5).is_err());
        assert!(chord_deviation(&c, -0.1, 0.5).is_err());
    }
}
