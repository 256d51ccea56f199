//! The logarithmic spiral through the control points of a typical planar curve (eqs. (18)–(19)).

use bez_core::Vector2;

use crate::ClassAError;

/// The pole ρ of the spiral similarity bᵢ₊₁ − ρ = s e^{iθ}(bᵢ − ρ):
/// ρ = b₀ + Δb₀ / (1 − s e^{iθ}) in complex notation (NOTES).
///
/// Erratum: the printed eq. (19) assumes |Δb₀| = 1 and has the wrong sign of the u_x sin θ term
/// of ρ_y; `printed_pole_eq19` (`paper` feature) keeps the printed form for comparison.
///
/// # Errors
/// [`ClassAError::NoPole`] if s e^{iθ} = 1 (or the pole is not representable),
/// [`ClassAError::NonFinite`] for non-finite input.
pub fn log_spiral_pole(
    b0: &Vector2,
    delta_b0: &Vector2,
    s: f64,
    theta: f64,
) -> Result<Vector2, ClassAError> {
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
    let (x, y) = (delta_b0.x(), delta_b0.y());
    let pole = b0 + Vector2::new(x * zr + y * zi, y * zr - x * zi) / den;
    if pole.is_finite() {
        Ok(pole)
    } else {
        // s e^{iθ} within rounding of 1, or inputs so large that the pole is not representable.
        Err(ClassAError::NoPole { s, theta })
    }
}

/// The pole as printed in eq. (19) (with unit Δb₀ = μ): kept to document the sign erratum.
/// Feature `paper`.
#[must_use]
#[cfg(feature = "paper")]
pub fn printed_pole_eq19(b0: &Vector2, mu: &Vector2, s: f64, theta: f64) -> Vector2 {
    let (sn, c) = theta.sin_cos();
    let rx = b0.x() + b0.x() * s * s + mu.x() - s * ((2.0 * b0.x() + mu.x()) * c + mu.y() * sn);
    let ry = b0.y() + b0.y() * s * s + mu.y() - s * ((2.0 * b0.y() + mu.y()) * c + mu.x() * sn);
    let rw = 1.0 + s * s - 2.0 * s * c;
    Vector2::new(rx / rw, ry / rw)
}

/// Largest relative deviation from the spiral similarity over consecutive control points:
/// max |(bᵢ₊₁ − ρ) − s e^{iθ}(bᵢ − ρ)| / |bᵢ₊₁ − ρ|. Zero (to rounding) iff all control points
/// lie on one discrete log spiral about ρ with ratio s and angle θ (triangles ρ bᵢ bᵢ₊₁ similar).
#[must_use]
pub fn spiral_deviation(points: &[Vector2], pole: &Vector2, s: f64, theta: f64) -> f64 {
    let (sn, c) = theta.sin_cos();
    points
        .windows(2)
        .map(|w| {
            let a = w[0] - pole;
            let b = w[1] - pole;
            let za = Vector2::new(s * (c * a.x() - sn * a.y()), s * (sn * a.x() + c * a.y()));
            (b - za).norm() / b.norm()
        })
        .fold(0.0, f64::max)
}

/// The pole by the paper's geometric construction (Fig. 4): with s = |b₂ − b₁| / |b₁ − b₀|, the
/// Apollonius circles Cᵢ = {q : |bᵢ₊₁ − q| = s |bᵢ − q|}, i = 0, 1, 2, all pass through the pole,
/// which is therefore their radical center: the intersection of the radical axes l₀ (of C₀, C₁)
/// and l₁ (of C₁, C₂). Needs four consecutive control points b₀..b₃.
///
/// Cᵢ normalized: |q|² − 2q·cᵢ + kᵢ = 0 with cᵢ = (bᵢ₊₁ − s²bᵢ)/(1 − s²) and
/// kᵢ = (|bᵢ₊₁|² − s²|bᵢ|²)/(1 − s²); lᵢ: 2q·(cᵢ₊₁ − cᵢ) = kᵢ₊₁ − kᵢ.
///
/// # Errors
/// [`ClassAError::NoPole`] when s = 1 (the circles degenerate to lines), the radical axes are
/// parallel or the pole is not representable; [`ClassAError::NonFinite`] for non-finite points.
pub fn apollonius_pole(b: &[Vector2; 4]) -> Result<Vector2, ClassAError> {
    if !b.iter().all(|p| p.x().is_finite() && p.y().is_finite()) {
        return Err(ClassAError::NonFinite {
            name: "control points",
        });
    }
    let l0 = (b[1] - b[0]).norm();
    let s = (b[2] - b[1]).norm() / l0;
    let s2 = s * s;
    if !s.is_finite() || (1.0 - s2).abs() < 1e-12 {
        return Err(ClassAError::NoPole { s, theta: f64::NAN });
    }
    // The construction is similarity invariant: work on (bᵢ − b₀)/|b₁ − b₀| so that the squared
    // norms below stay finite whatever the size and position of the points.
    let (origin, unit) = (b[0], l0);
    let b: [Vector2; 4] = core::array::from_fn(|i| (b[i] - origin) / unit);
    let circle = |i: usize| {
        let c = (b[i + 1] - b[i] * s2) / (1.0 - s2);
        let k = (b[i + 1].norm_squared() - s2 * b[i].norm_squared()) / (1.0 - s2);
        (c, k)
    };
    let (c0, k0) = circle(0);
    let (c1, k1) = circle(1);
    let (c2, k2) = circle(2);
    let (n0, r0) = ((c1 - c0) * 2.0, k1 - k0);
    let (n1, r1) = ((c2 - c1) * 2.0, k2 - k1);
    let det = n0.x() * n1.y() - n0.y() * n1.x();
    if det == 0.0 || !det.is_finite() {
        return Err(ClassAError::NoPole { s, theta: f64::NAN });
    }
    let pole = Vector2::new(
        (r0 * n1.y() - r1 * n0.y()) / det,
        (n0.x() * r1 - n1.x() * r0) / det,
    ) * unit
        + origin;
    if pole.is_finite() {
        Ok(pole)
    } else {
        Err(ClassAError::NoPole { s, theta: f64::NAN })
    }
}
