//! Seeded data sets and the figure cases shared by tests, benchmarks and the xtask.

use crate::square::{Matrix2, Matrix3};
use bez_core::{BezierCurve, Vector2, Vector3};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::{
    ClassAError, TypicalPlanar, TypicalSpatial, class_a_curve, perturb2, perturb3, rotation,
    typical_matrix2, typical_planar_margin,
};

/// A random Class A (s, θ) pair with |θ| ≤ θ_max: s cos θ ≥ 1 (with s ≤ 2) or s ≤ cos θ (s ≥ 0.5).
fn random_scale_angle(rng: &mut ChaCha8Rng, theta_max: f64) -> (f64, f64) {
    loop {
        let theta = rng.random_range(0.01..theta_max)
            * if rng.random_range(0.0..1.0) < 0.5 {
                -1.0
            } else {
                1.0
            };
        let s = if rng.random_range(0.0..1.0) < 0.5 {
            rng.random_range(1.0..2.0)
        } else {
            rng.random_range(0.5..1.0)
        };
        if typical_planar_margin(s, theta) >= 1e-3 {
            return (s, theta);
        }
    }
}

/// `count` feasible planar inputs (α₀, α₁, α₂, n), made from random typical curves (s, θ) with
/// n ∈ [3, 12], total turn < π, first leg random: α₀ = b₀, α₁ = b₁, α₂ = bₙ... with α₁ on the
/// intersection of the end tangents (b₀b₁ and bₙ₋₁bₙ extended). Seeded by `seed`.
#[must_use]
pub fn random_planar_inputs(count: usize, seed: u64) -> Vec<([Vector2; 3], usize)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let n = rng.random_range(3..13);
        let (s, theta) = random_scale_angle(&mut rng, 2.8 / (n - 1) as f64);
        let m = typical_matrix2(s, theta);
        let b0 = Vector2::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
        let phi: f64 = rng.random_range(-3.0..3.0);
        let mut leg = Vector2::new(phi.cos(), phi.sin()) * rng.random_range(0.2..2.0);
        let d0 = leg;
        let mut p = b0;
        for _ in 0..n - 1 {
            p += leg;
            leg = m * leg;
        }
        let d_last = leg;
        let bn = p + leg;
        // α₁ = b₀ + a d₀ = bₙ − c d_last: solve the 2×2 system.
        let det = d0.x() * (-d_last.y()) - d0.y() * (-d_last.x());
        if det.abs() < 1e-9 {
            continue;
        }
        let r = bn - b0;
        let a = (r.x() * (-d_last.y()) - r.y() * (-d_last.x())) / det;
        if !(a > 0.0 && a.is_finite()) {
            continue;
        }
        out.push(([b0, b0 + d0 * a, bn], n));
    }
    out
}

/// `count` feasible spatial inputs (α₀..α₃, n) from random typical spatial curves with
/// s ∈ [1, 1.6], s cos θ ≥ 1.001, random axis, n ∈ [3, 10]: α₀ = b₀, α₁ = b₁, α₂ = bₙ₋₁, α₃ = bₙ.
#[must_use]
pub fn random_spatial_inputs(count: usize, seed: u64) -> Vec<([Vector3; 4], usize)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let n = rng.random_range(3..11);
        let s: f64 = rng.random_range(1.0..1.6);
        let theta_max = (1.001 / s).min(1.0).acos().min(2.8 / (n - 1) as f64);
        if theta_max < 0.02 {
            continue;
        }
        let theta = rng.random_range(0.01..theta_max);
        let axis = random_unit(&mut rng);
        let v0 = random_unit(&mut rng);
        if axis.cross(&v0).norm() < 0.2 {
            continue;
        }
        let m: Matrix3 = rotation(&axis, theta) * s;
        let mut p = Vector3::zeros();
        let mut leg = v0;
        let mut pts = vec![p];
        for _ in 0..n {
            p += leg;
            pts.push(p);
            leg = m * leg;
        }
        out.push(([pts[0], pts[1], pts[n - 1], pts[n]], n));
    }
    out
}

fn random_unit(rng: &mut ChaCha8Rng) -> Vector3 {
    loop {
        let v = Vector3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let n = v.norm();
        if n > 0.1 && n <= 1.0 {
            return v / n;
        }
    }
}

/// Fig. 5: Farin's example matrix as printed in the paper.
#[must_use]
pub fn fig5_matrix() -> Matrix3 {
    Matrix3::from_rows([[2.58, -0.04, 0.89], [0.45, 2.13, 0.45], [0.0, 0.0, 2.21]])
}

/// Fig. 5 start vector: the printed V = [−1, 1] is 2-D; we use (−1, 1, 1), which has a
/// component along the third axis and gives a genuinely spatial curve (NOTES).
#[must_use]
pub fn fig5_start() -> Vector3 {
    Vector3::new(-1.0, 1.0, 1.0)
}

/// Fig. 6 points (degree 49): the paper's coordinates are not printed; a documented triangle.
#[must_use]
pub fn fig6_points() -> [Vector2; 3] {
    [
        Vector2::new(0.0, 0.0),
        Vector2::new(6.0, 0.0),
        Vector2::new(8.0, 5.0),
    ]
}

/// Fig. 7 points (degree 9, δ₀..δ₃ = 0.1).
#[must_use]
pub fn fig7_points() -> [Vector2; 3] {
    [
        Vector2::new(0.0, 0.0),
        Vector2::new(4.0, 0.0),
        Vector2::new(5.0, 3.5),
    ]
}

/// Fig. 8 points (degree 7): b₀, b₁, b₆, b₇ of the typical curve with s = 1.2, θ = 0.3,
/// axis ∝ (0.3, 0.2, 1), Δb₀ = (1, 0, 0.2), rounded to 0.01 (the paper prints no coordinates).
#[must_use]
pub fn fig8_points() -> [Vector3; 4] {
    [
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(1.0, 0.0, 0.2),
        Vector3::new(6.21, 6.54, 1.79),
        Vector3::new(6.12, 9.44, 2.73),
    ]
}

/// Fig. 9 points (degree 4, δ = (0, 0.15, 0, 0.5)): b₀, b₁, b₃, b₄ of the typical curve with
/// s = 1.3, θ = 0.35, axis ∝ (0.1, −0.3, 1), Δb₀ = (1, 0.1, 0.3), rounded to 0.01.
#[must_use]
pub fn fig9_points() -> [Vector3; 4] {
    [
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(1.0, 0.1, 0.3),
        Vector3::new(3.25, 1.72, 1.67),
        Vector3::new(4.04, 3.48, 2.93),
    ]
}

/// Fig. 5 curve: degree 6 from b₀ = 0, Δb₀ = [`fig5_start`], M = [`fig5_matrix`].
///
/// # Errors
/// Never for these constants; propagated from [`class_a_curve`].
pub fn fig5_curve() -> Result<BezierCurve<3>, ClassAError> {
    class_a_curve(&Vector3::zeros(), &fig5_start(), &fig5_matrix(), 6)
}

/// Fig. 6: the typical planar curve of degree 49 through [`fig6_points`].
///
/// # Errors
/// Propagated from [`TypicalPlanar::from_points`].
pub fn fig6_typical() -> Result<TypicalPlanar, ClassAError> {
    let a = fig6_points();
    TypicalPlanar::from_points(&a[0], &a[1], &a[2], 49)
}

/// Perturbation factors of Fig. 7.
pub const FIG7_DELTA: [f64; 4] = [0.1; 4];
/// Perturbation factors of Fig. 9.
pub const FIG9_DELTA: [f64; 4] = [0.0, 0.15, 0.0, 0.5];

/// Fig. 7: the typical planar curve of degree 9 through [`fig7_points`], then M perturbed by
/// [`FIG7_DELTA`] ([`perturb2`]) with the same b₀ and Δb₀ (the end point then moves: the paper
/// does not say how the general curve is fitted to the points).
///
/// # Errors
/// Propagated from [`TypicalPlanar::from_points`].
pub fn fig7_general() -> Result<(TypicalPlanar, BezierCurve<2>), ClassAError> {
    let a = fig7_points();
    let t = TypicalPlanar::from_points(&a[0], &a[1], &a[2], 9)?;
    let c = class_a_curve(
        &t.b0(),
        &(t.mu() * t.length()),
        &perturb2(&t.matrix(), FIG7_DELTA),
        9,
    )?;
    Ok((t, c))
}

/// Fig. 8: the typical spatial curve of degree 7 through [`fig8_points`].
///
/// # Errors
/// Propagated from [`TypicalSpatial::from_points`].
pub fn fig8_typical() -> Result<TypicalSpatial, ClassAError> {
    TypicalSpatial::from_points(&fig8_points(), 7)
}

/// Fig. 9: the typical spatial curve of degree 4 through [`fig9_points`], M perturbed by
/// [`FIG9_DELTA`] ([`perturb3`]) with the same b₀ and Δb₀.
///
/// # Errors
/// Propagated from [`TypicalSpatial::from_points`].
pub fn fig9_general() -> Result<(TypicalSpatial, BezierCurve<3>), ClassAError> {
    let t = TypicalSpatial::from_points(&fig9_points(), 4)?;
    let c = class_a_curve(
        &t.b0,
        &(t.v0 * t.length),
        &perturb3(&t.matrix(), FIG9_DELTA),
        4,
    )?;
    Ok((t, c))
}

/// Relative end-point error |bₙ − α_last| / |α_last − α₀| of a curve built for the points `a`.
#[must_use]
pub fn endpoint_error<const D: usize>(a: &[bez_core::Vector<D>], curve: &BezierCurve<D>) -> f64 {
    match (a.first(), a.last()) {
        (Some(first), Some(last)) => (curve.end() - last).norm() / (last - first).norm(),
        _ => f64::INFINITY,
    }
}

/// Outcome of [`farin_counterexample_search`].
#[derive(Debug, Clone, PartialEq)]
pub struct CounterexampleSearch {
    /// Random matrices drawn.
    pub matrices: usize,
    /// Matrices meeting Farin's conditions (3) and (4).
    pub meeting_3_and_4: usize,
    /// Curves (from those matrices, degrees 3, 4, 5) with a certified interior curvature extremum.
    pub not_monotone: usize,
    /// Of those, how many also meet condition (4) for the sub-curve matrices (sampled).
    pub not_monotone_with_subcurve_4: usize,
    /// The first counterexample found: (M, Δb₀, degree, parameter of the extremum).
    pub first: Option<(Matrix2, Vector2, usize, f64)>,
}

/// Random search for Cao & Wang's phenomenon: 2×2 matrices with entries a₁₁, a₂₂ ∈ [0.5, 3),
/// a₁₂, a₂₁ ∈ [−2, 2) meeting Farin's (3) and (4), a random unit Δb₀, degrees 3..=5, and the
/// curvature certificate of each curve. Seeded by `seed`.
#[must_use]
pub fn farin_counterexample_search(matrices: usize, seed: u64) -> CounterexampleSearch {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut out = CounterexampleSearch {
        matrices,
        meeting_3_and_4: 0,
        not_monotone: 0,
        not_monotone_with_subcurve_4: 0,
        first: None,
    };
    for _ in 0..matrices {
        let m = Matrix2::new(
            rng.random_range(0.5..3.0),
            rng.random_range(-2.0..2.0),
            rng.random_range(-2.0..2.0),
            rng.random_range(0.5..3.0),
        );
        let ang: f64 = rng.random_range(0.0..std::f64::consts::TAU);
        let Ok(r) = crate::ClassAReport::of_2x2(&m) else {
            continue;
        };
        if !(r.farin3.holds && r.farin4.holds) {
            continue;
        }
        out.meeting_3_and_4 += 1;
        let v = Vector2::new(ang.cos(), ang.sin());
        for n in 3..=5 {
            let Ok(c) = class_a_curve(&Vector2::zeros(), &v, &m, n) else {
                continue;
            };
            if let Ok(cert) = crate::curvature_certificate(&c)
                && let crate::Monotonicity::NotMonotone { extremum, .. } = cert.verdict
            {
                out.not_monotone += 1;
                out.not_monotone_with_subcurve_4 += usize::from(r.subcurve_farin4.holds);
                if out.first.is_none() {
                    out.first = Some((m, v, n, extremum));
                }
            }
        }
    }
    out
}
