//! The logarithmic spiral through the control points of a typical planar curve (eqs. (18)–(19)).

use bez_core::Vector2;

use crate::ClassAError;

/// The pole ρ of the spiral similarity bᵢ₊₁ − ρ = s e^{iθ}(bᵢ − ρ):
/// ρ = b₀ + Δb₀ / (1 − s e^{iθ}) in complex notation (NOTES).
///
/// Erratum: the printed eq. (19) assumes |Δb₀| = 1 and has the wrong sign of the u_x sin θ term
/// of ρ_y; [`printed_pole_eq19`] keeps the printed form for comparison.
///
/// # Errors
/// [`ClassAError::NoPole`] if s e^{iθ} = 1, [`ClassAError::NonFinite`] for non-finite input.
pub fn log_spiral_pole(
    b0: &Vector2<f64>,
    delta_b0: &Vector2<f64>,
    s: f64,
    theta: f64,
) -> Result<Vector2<f64>, ClassAError> {
    if !(b0.iter().chain(delta_b0.iter()).all(|x| x.is_finite())
        && s.is_finite()
        && theta.is_finite())
    {
        return Err(ClassAError::NonFinite { name: "pole input" });
    }
    let (sn, c) = theta.sin_cos();
    let (zr, zi) = (1.0 - s * c, -s * sn); // 1 − z
    let den = zr * zr + zi * zi;
    if den == 0.0 {
        return Err(ClassAError::NoPole { s, theta });
    }
    // Δb₀ / (1 − z) = Δb₀ · conj(1 − z) / |1 − z|².
    let (x, y) = (delta_b0.x, delta_b0.y);
    Ok(b0 + Vector2::new(x * zr + y * zi, y * zr - x * zi) / den)
}

/// The pole as printed in eq. (19) (with unit Δb₀ = μ): kept to document the sign erratum.
#[must_use]
pub fn printed_pole_eq19(b0: &Vector2<f64>, mu: &Vector2<f64>, s: f64, theta: f64) -> Vector2<f64> {
    let (sn, c) = theta.sin_cos();
    let rx = b0.x + b0.x * s * s + mu.x - s * ((2.0 * b0.x + mu.x) * c + mu.y * sn);
    let ry = b0.y + b0.y * s * s + mu.y - s * ((2.0 * b0.y + mu.y) * c + mu.x * sn);
    let rw = 1.0 + s * s - 2.0 * s * c;
    Vector2::new(rx / rw, ry / rw)
}

/// Largest relative deviation from the spiral similarity over consecutive control points:
/// max |(bᵢ₊₁ − ρ) − s e^{iθ}(bᵢ − ρ)| / |bᵢ₊₁ − ρ|. Zero (to rounding) iff all control points
/// lie on one discrete log spiral about ρ with ratio s and angle θ (triangles ρ bᵢ bᵢ₊₁ similar).
#[must_use]
pub fn spiral_deviation(points: &[Vector2<f64>], pole: &Vector2<f64>, s: f64, theta: f64) -> f64 {
    let (sn, c) = theta.sin_cos();
    points
        .windows(2)
        .map(|w| {
            let a = w[0] - pole;
            let b = w[1] - pole;
            let za = Vector2::new(s * (c * a.x - sn * a.y), s * (sn * a.x + c * a.y));
            (b - za).norm() / b.norm()
        })
        .fold(0.0, f64::max)
}
