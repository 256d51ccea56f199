//! End curvatures and torsions of a typical spatial Class A curve in closed form.
//!
//! The curve has legs Δbⱼ = Mʲ v with M = s·R(u, θ) and v = L v₀ (eqs. (9)–(12)). Split the
//! start tangent along the axis: a = u·v₀ (the cosine of the angle between axis and tangent),
//! p = v₀ − a u with ρ = |p| = √(1 − a²), and q = u × p. The rotation keeps u and turns the
//! (p, q) plane: R v₀ = a u + cos θ p + sin θ q. Then
//!
//! v₀ × R v₀ = a(cos θ − 1) q − a sin θ p + ρ² sin θ u,
//!
//! so W = |v₀ × R v₀| = 2ρ |sin(θ/2)| √g with g = a² + ρ² cos²(θ/2) = 1 − ρ² sin²(θ/2), and
//!
//! D = det(v₀, R v₀, R² v₀) = v₀ · R(v₀ × R v₀) = 2aρ² sin θ (1 − cos θ).
//!
//! Rotations keep cross products and determinants and a = u·Rʲv₀ for every j, so the end
//! formulas of [`crate::end_curvatures_torsions`] (κ(0) = (n − 1)/n · |Δb₀ × Δb₁| / |Δb₀|³,
//! τ(0) = (n − 2)/n · det(Δb₀, Δb₁, Δb₂) / |Δb₀ × Δb₁|², and the same with the last legs) give
//!
//! κ(0) = (n − 1) s W / (n L),  κ(1) = (n − 1) W / (n L sⁿ),
//!
//! τ(0) = (n − 2) s a sin θ / (n L g),  τ(1) = (n − 2) a sin θ / (n L g sⁿ),
//!
//! since |Δbⱼ| = L sʲ, |Δbⱼ × Δbⱼ₊₁| = L² s²ʲ⁺¹ W and det(Δbⱼ, Δbⱼ₊₁, Δbⱼ₊₂) = L³ s³ʲ⁺³ D with
//! D / W² = a sin θ / (2g). Both end values scale by s⁻⁽ⁿ⁺¹⁾ from start to end, so τ/κ is the
//! same at both ends: (n − 2) a sin θ / ((n − 1) g W). A planar curve (a = 0, ρ = 1) has W =
//! |sin θ| and zero torsion, the planar closed form of [`crate::TypicalPlanar::end_curvatures`].

use crate::{ClassAError, TypicalSpatial};

/// Largest deviation of |u| and |v₀| from 1 accepted by [`TypicalSpatial::end_curvatures_torsions`].
const UNIT_TOLERANCE: f64 = 1e-9;

impl TypicalSpatial {
    /// Curvature and torsion at both ends, [(κ(0), τ(0)), (κ(1), τ(1))], in closed form (module
    /// docs of [`crate::end_curvatures_torsions`] for the control-point form they agree with):
    /// κ(0) = (n − 1) s W / (n L), κ(1) = κ(0) / sⁿ⁺¹, τ(0) = (n − 2) s a sin θ / (n L g),
    /// τ(1) = τ(0) / sⁿ⁺¹, with a = u·v₀, ρ² = 1 − a², g = 1 − ρ² sin²(θ/2) and
    /// W = 2ρ |sin(θ/2)| √g. Evaluated through logarithms, so never NaN: 0 or infinite only where
    /// the true value is beyond f64.
    ///
    /// ```
    /// use bez_core::Vector3;
    /// use class_a::{TypicalSpatial, end_curvatures_torsions};
    /// let a = [
    ///     Vector3::new(0.0, 0.0, 0.0),
    ///     Vector3::new(1.0, 0.0, 0.2),
    ///     Vector3::new(6.21, 6.54, 1.79),
    ///     Vector3::new(6.12, 9.44, 2.73),
    /// ];
    /// let t = TypicalSpatial::from_points(&a, 7)?;
    /// let closed = t.end_curvatures_torsions()?;
    /// let from_points = end_curvatures_torsions(&t.curve()?)?;
    /// for (c, p) in closed.iter().zip(&from_points) {
    ///     assert!((c.0 / p.0 - 1.0).abs() < 1e-12 && (c.1 / p.1 - 1.0).abs() < 1e-9);
    /// }
    /// # Ok::<(), class_a::ClassAError>(())
    /// ```
    ///
    /// # Errors
    /// [`ClassAError::NonFinite`] for a non-finite field; [`ClassAError::InvalidParameter`] for
    /// s ≤ 0, L ≤ 0, or an axis or start tangent whose length differs from 1 by more than 1e-9
    /// (the fields are public; the formulas assume the curve [`TypicalSpatial::curve`] builds).
    pub fn end_curvatures_torsions(&self) -> Result<[(f64, f64); 2], ClassAError> {
        crate::error::check_degree(self.degree, 2)?;
        if !(self.s.is_finite()
            && self.length.is_finite()
            && self.theta.is_finite()
            && self.axis.is_finite()
            && self.v0.is_finite())
        {
            return Err(ClassAError::NonFinite {
                name: "typical spatial curve",
            });
        }
        for (name, value) in [("s", self.s), ("length", self.length)] {
            if value <= 0.0 {
                return Err(ClassAError::InvalidParameter {
                    name,
                    value,
                    expected: "positive",
                });
            }
        }
        for (name, v) in [("|axis|", self.axis), ("|v0|", self.v0)] {
            let norm = v.norm();
            if (norm - 1.0).abs() > UNIT_TOLERANCE {
                return Err(ClassAError::InvalidParameter {
                    name,
                    value: norm,
                    expected: "1 within 1e-9 (a unit vector)",
                });
            }
        }
        let u = self.axis / self.axis.norm();
        let v0 = self.v0 / self.v0.norm();
        let a = u.dot(&v0);
        let rho = (v0 - u * a).norm();
        let half = (0.5 * self.theta).sin();
        let g = a * a + rho * rho * (1.0 - half * half);
        let w = 2.0 * rho * half.abs() * g.sqrt();
        let n = self.degree as f64;
        let (log_s, log_l) = (self.s.ln(), self.length.ln());
        // x·s at the start and x/sⁿ at the end, for x = e^{log_x} with sign `sign`.
        let ends = |sign: f64, log_x: f64| {
            if sign == 0.0 || log_x == f64::NEG_INFINITY {
                (0.0, 0.0)
            } else {
                (
                    sign * (log_x + log_s).exp(),
                    sign * (log_x - n * log_s).exp(),
                )
            }
        };
        let kappa = ends(1.0, ((n - 1.0) * w / n).ln() - log_l);
        let numerator = a * self.theta.sin();
        let tau = if g > 0.0 {
            ends(
                numerator.signum() * f64::from(numerator != 0.0),
                ((n - 2.0) * numerator.abs() / (n * g)).ln() - log_l,
            )
        } else {
            (0.0, 0.0)
        };
        Ok([(kappa.0, tau.0), (kappa.1, tau.1)])
    }
}
