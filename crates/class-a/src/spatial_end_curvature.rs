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

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use crate::dd::Dd;
    use bez_core::Vector3;

    type V = [Dd; 3];

    fn sub(a: &V, b: &V) -> V {
        std::array::from_fn(|i| a[i].add(Dd::from_f64(-b[i].hi)).add(Dd::from_f64(-b[i].lo)))
    }

    fn cross(a: &V, b: &V) -> V {
        let m = |x: Dd, y: Dd| x.mul(y);
        std::array::from_fn(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let p = m(a[j], b[k]);
            let q = m(a[k], b[j]);
            sub(&[p, Dd::ZERO, Dd::ZERO], &[q, Dd::ZERO, Dd::ZERO])[0]
        })
    }

    fn dot(a: &V, b: &V) -> f64 {
        (0..3).fold(Dd::ZERO, |acc, i| acc.add(a[i].mul(b[i]))).hi
    }

    /// κ and τ at both ends from legs Mʲv formed in double-double arithmetic (about 106 bits),
    /// with M = s(I + sin θ K + 2 sin²(θ/2) K²): a high-precision oracle for the closed forms
    /// (the only roundings that reach the result are those of the f64 sines, relative ε).
    fn oracle(t: &TypicalSpatial) -> [(f64, f64); 2] {
        let k = crate::square::Matrix3::cross_matrix(&t.axis);
        let k2 = k * k;
        let (sin, half) = (t.theta.sin(), (0.5 * t.theta).sin());
        let d = |x: f64| Dd::from_f64(x);
        let m: [[Dd; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let id = if i == j { 1.0 } else { 0.0 };
                d(id)
                    .add(d(sin).mul(d(k[(i, j)])))
                    .add(d(2.0 * half).mul(d(half)).mul(d(k2[(i, j)])))
                    .mul(d(t.s))
            })
        });
        let n = t.degree;
        let mut legs: Vec<V> = vec![std::array::from_fn(|i| d(t.v0[i]).mul(d(t.length)))];
        for _ in 1..n {
            let last = legs[legs.len() - 1];
            legs.push(std::array::from_fn(|i| {
                (0..3).fold(Dd::ZERO, |acc, j| acc.add(m[i][j].mul(last[j])))
            }));
        }
        let nf = n as f64;
        let end = |a: &V, b: &V, c: &V, tangent: &V| {
            let w = cross(a, b);
            let w2 = dot(&w, &w);
            let t = dot(tangent, tangent).sqrt();
            (
                (nf - 1.0) / nf * w2.sqrt() / (t * t * t),
                (nf - 2.0) / nf * dot(&w, c) / w2,
            )
        };
        [
            end(&legs[0], &legs[1], &legs[2], &legs[0]),
            // det(Δbₙ₋₃, Δbₙ₋₂, Δbₙ₋₁) = (Δbₙ₋₂ × Δbₙ₋₁)·Δbₙ₋₃.
            end(&legs[n - 2], &legs[n - 1], &legs[n - 3], &legs[n - 1]),
        ]
    }

    #[test]
    fn closed_forms_agree_with_double_double_legs() {
        let v0 = Vector3::new(0.6, 0.0, 0.8);
        for n in [3usize, 7, 20, 30] {
            for theta in [-1.2, -0.01, 1e-3, 0.3, 1.2] {
                for polar in [0.2f64, 0.9, std::f64::consts::FRAC_PI_2, 2.6] {
                    for s in [0.93, 1.0, 1.07] {
                        let axis = Vector3::new(polar.sin(), 0.3 * polar.cos(), polar.cos());
                        let axis = axis / axis.norm();
                        let t = TypicalSpatial {
                            b0: Vector3::zeros(),
                            v0,
                            length: 1.7,
                            s,
                            phi: 0.0,
                            axis,
                            theta,
                            degree: n,
                        };
                        let closed = t.end_curvatures_torsions().unwrap();
                        for (c, o) in closed.iter().zip(oracle(&t)) {
                            assert!(
                                (c.0 / o.0 - 1.0).abs() < 1e-13,
                                "n {n} θ {theta} polar {polar} s {s}: κ {} vs {}",
                                c.0,
                                o.0
                            );
                            assert!(
                                (c.1 - o.1).abs() < 1e-12 * (o.1.abs() + o.0),
                                "n {n} θ {theta} polar {polar} s {s}: τ {} vs {}",
                                c.1,
                                o.1
                            );
                        }
                    }
                }
            }
        }
    }
}
