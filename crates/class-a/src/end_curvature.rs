//! End curvatures (and spatial end torsions) of Bézier and Class A curves from their first and
//! last control points.
//!
//! For a degree-n Bézier curve x(t) with legs Δbⱼ = bⱼ₊₁ − bⱼ, x'(0) = nΔb₀ and
//! x''(0) = n(n − 1)(Δb₁ − Δb₀), so the signed curvature κ = x' × x'' / |x'|³ at the ends is
//!
//! κ(0) = (n − 1)/n · Δb₀ × Δb₁ / |Δb₀|³,  κ(1) = (n − 1)/n · Δbₙ₋₂ × Δbₙ₋₁ / |Δbₙ₋₁|³
//!
//! (a × b = a_x b_y − a_y b_x; the Δb₁ − Δb₀ becomes Δb₁ since Δb₀ × Δb₀ = 0). Only the first
//! and the last three control points enter.
//!
//! For a Class A curve, Δbⱼ = Mʲv with v = Δb₀, and (Mu) × (Mw) = det M · (u × w), so
//!
//! κ(0) = (n − 1)/n · v × Mv / |v|³,  κ(1) = (n − 1)/n · (det M)ⁿ⁻² · v × Mv / |Mⁿ⁻¹v|³.
//!
//! For the typical matrix M = s·R(θ) and v = Lμ: v × Mv = L² s sin θ, det M = s² and
//! |Mⁿ⁻¹v| = L sⁿ⁻¹, so κ(0) = (n − 1) s sin θ / (nL) and κ(1) = (n − 1) sin θ / (n L sⁿ)
//! ([`TypicalPlanar::end_curvatures`]).

use bez_core::{BezierCurve, Vector, Vector2};

use crate::{ClassAError, TypicalPlanar};

/// Signed curvatures (κ(0), κ(1)) of a planar Bézier curve from its first and last three
/// control points (module docs):
/// κ(0) = (n − 1)/n · Δb₀ × Δb₁ / |Δb₀|³ and κ(1) = (n − 1)/n · Δbₙ₋₂ × Δbₙ₋₁ / |Δbₙ₋₁|³.
///
/// ```
/// use bez_core::Vector2;
/// use class_a::end_curvatures;
/// // The quadratic (0,0), (1,0), (1,1): κ(0) = (1/2) · 1 / 1 = 0.5 at both ends.
/// let c = bez_core::BezierCurve::new(vec![
///     Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), Vector2::new(1.0, 1.0),
/// ])?;
/// let (k0, k1) = end_curvatures(&c)?;
/// assert!((k0 - 0.5).abs() < 1e-15 && (k1 - 0.5).abs() < 1e-15);
/// # Ok::<(), class_a::ClassAError>(())
/// ```
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 2; [`ClassAError::Singular`] when an end leg is zero
/// (the curvature at that end is not given by this formula); [`ClassAError::NonFinite`] when a
/// value overflows.
pub fn end_curvatures(curve: &BezierCurve<2>) -> Result<(f64, f64), ClassAError> {
    let n = curve.degree();
    crate::error::check_degree(n, 2)?;
    let p = curve.points();
    let factor = (n - 1) as f64 / n as f64;
    let at = |a: Vector2, b: Vector2, tangent: Vector2, parameter: f64| {
        let norm = tangent.norm();
        if norm == 0.0 {
            return Err(ClassAError::Singular {
                quantity: "the end leg",
                parameter,
            });
        }
        let k = factor * (a.perp(&b) / norm) / (norm * norm);
        if k.is_finite() {
            Ok(k)
        } else {
            Err(ClassAError::NonFinite { name: "curvature" })
        }
    };
    let (d0, d1) = (p[1] - p[0], p[2] - p[1]);
    let (e0, e1) = (p[n - 1] - p[n - 2], p[n] - p[n - 1]);
    Ok((at(d0, d1, d0, 0.0)?, at(e0, e1, e1, 1.0)?))
}

/// Curvature and torsion at both ends of a spatial Bézier curve, [(κ(0), τ(0)), (κ(1), τ(1))],
/// from its first and last four control points.
///
/// With x‴(0) = n(n − 1)(n − 2)(Δb₂ − 2Δb₁ + Δb₀), column operations give
/// det(x′, x″, x‴) = n³(n − 1)²(n − 2) det(Δb₀, Δb₁, Δb₂), so
///
/// κ(0) = (n − 1)/n · |Δb₀ × Δb₁| / |Δb₀|³,  τ(0) = (n − 2)/n · det(Δb₀, Δb₁, Δb₂) / |Δb₀ × Δb₁|²,
///
/// and at t = 1 the same with Δbₙ₋₃, Δbₙ₋₂, Δbₙ₋₁ (in this order) and |Δbₙ₋₁|³. For a Class A
/// curve det(Mʲv, Mʲ⁺¹v, Mʲ⁺²v) = (det M)ʲ det(v, Mv, M²v): the end torsions are tied by
/// (det M)ⁿ⁻³ as the curvatures are (module docs). Closed forms for typical spatial curves:
/// [`crate::TypicalSpatial::end_curvatures_torsions`]; prescribed end curvatures and osculating
/// planes: [`crate::hermite_spatial`].
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 3; [`ClassAError::Singular`] when an end leg is zero or
/// the first (last) two legs are parallel (torsion undefined there);
/// [`ClassAError::NonFinite`] when a value overflows.
pub fn end_curvatures_torsions(curve: &BezierCurve<3>) -> Result<[(f64, f64); 2], ClassAError> {
    let n = curve.degree();
    crate::error::check_degree(n, 3)?;
    let p = curve.points();
    let (nf, leg) = (n as f64, |i: usize| p[i + 1] - p[i]);
    // `cross` is that of the two legs at the end (κ and the torsion's denominator), `det` the
    // triple product of the three legs there in curve order.
    let at = |cross: Vector<3>, det: f64, tangent: Vector<3>, parameter: f64| {
        let (t, w) = (tangent.norm(), cross.norm());
        if t == 0.0 || w == 0.0 {
            return Err(ClassAError::Singular {
                quantity: if t == 0.0 {
                    "the end leg"
                } else {
                    "the cross product of the end legs"
                },
                parameter,
            });
        }
        let kappa = (nf - 1.0) / nf * (w / t) / (t * t);
        let tau = (nf - 2.0) / nf * (det / w) / w;
        if kappa.is_finite() && tau.is_finite() {
            Ok((kappa, tau))
        } else {
            Err(ClassAError::NonFinite {
                name: "curvature or torsion",
            })
        }
    };
    let (d0, d1, d2) = (leg(0), leg(1), leg(2));
    let (e0, e1, e2) = (leg(n - 3), leg(n - 2), leg(n - 1));
    let start = d0.cross(&d1);
    Ok([
        at(start, start.dot(&d2), d0, 0.0)?,
        at(e1.cross(&e2), e0.cross(&e1).dot(&e2), e2, 1.0)?,
    ])
}

impl TypicalPlanar {
    /// Signed end curvatures in closed form (module docs of the formulas):
    /// κ(0) = (n − 1) s sin θ / (nL) and κ(1) = (n − 1) sin θ / (n L sⁿ), evaluated through
    /// logarithms (never NaN; 0 or infinite only when the true value is beyond f64).
    #[must_use]
    pub fn end_curvatures(&self) -> (f64, f64) {
        let n = self.degree() as f64;
        let sin = self.theta().sin();
        if sin == 0.0 {
            return (0.0, 0.0);
        }
        let log_base = ((n - 1.0) * sin.abs() / n).ln() - self.length().ln();
        let log_s = self.s().ln();
        (
            sin.signum() * (log_base + log_s).exp(),
            sin.signum() * (log_base - n * log_s).exp(),
        )
    }
}
