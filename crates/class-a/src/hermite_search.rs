//! The global search of the planar G2 solve ([`crate::hermite_planar`]): every general-matrix
//! Class A curve with given G1 data, in two parameters.
//!
//! **Reduction.** Let the legs be wⱼ = Mʲv. By Cayley–Hamilton, Mʲ = Uⱼ M − d Uⱼ₋₁ I with the
//! Lucas sequence U₀ = 0, U₁ = 1, Uⱼ₊₁ = t Uⱼ − d Uⱼ₋₁ of t = tr M and d = det M; in the
//! (skew) basis (v, Mv) the legs are wⱼ = (−d Uⱼ₋₁, Uⱼ), so w₀ × wⱼ = Uⱼ and
//! wⱼ × wₖ = dʲ Uₖ₋ⱼ (cross products in these coordinates). A one-way polygon turning by less
//! than π has d > 0 and Uⱼ > 0 for j = 1, …, n − 1. Its tangent triangle is b₀ = 0,
//! α₁′ = λw₀, bₙ = S = Σⱼ wⱼ with S − α₁′ = μwₙ₋₁, so
//!
//! λ = P / Uₙ₋₁ with P = S × wₙ₋₁ = Σ_{j=0}^{n−2} dʲ Uₙ₋₁₋ⱼ,  μ = Σ_{j=1}^{n−1} Uⱼ / Uₙ₋₁.
//!
//! The linear map A taking this triangle to the given one (A w₀ = (l₀/λ) T₀,
//! A wₙ₋₁ = (l₁/μ) T₁ with the tangent legs l₀ = |α₁ − α₀|, l₁ = |α₂ − α₁| and unit tangents
//! T₀, T₁) makes A wⱼ the legs of a Class A curve (matrix A M A⁻¹) meeting the G1 data, and
//! every such curve arises once: the G1 solutions are exactly the pairs (t, d) above. With
//! w₁ = (d Uₙ₋₂ w₀ + wₙ₋₁)/Uₙ₋₁ and wₙ₋₂ × wₙ₋₁ = dⁿ⁻², the end curvatures of
//! [`crate::end_curvatures`] become, in the normalized form Kᵢ = κᵢ n / ((n − 1) sin ψ) times
//! l₀²/l₁ (start) or l₁²/l₀ (end),
//!
//! K₀ = λ² / (μ Uₙ₋₁),  K₁ = dⁿ⁻² μ² / (λ Uₙ₋₁):
//!
//! two equations in two unknowns, the same for every triangle of the same degree.
//!
//! **Scaling.** With m the largest eigenvalue modulus of M, Uⱼ = mʲ⁻¹ Ûⱼ where Û is the sequence
//! of (t/m, d/m²): for real eigenvalues m and ρm (0 < ρ ≤ 1), Ûⱼ = 1 + ρ + … + ρʲ⁻¹ and d/m² = ρ;
//! for complex ones m e^{±iφ} (0 < φ < π/(n − 1)), Ûⱼ = sin jφ / sin φ and d/m² = 1. Then
//! ln K₀ = 2 ln 𝒜 − 2 ln Ûₙ₋₁ − ln 𝒮 and
//! ln K₁ = (n − 2)(ln(d/m²) − ln m) + 2 ln 𝒮 − 2 ln Ûₙ₋₁ − ln 𝒜 with
//! 𝒮 = Σ_{j=1}^{n−1} mʲ⁻¹ Ûⱼ and 𝒜 = Σ_{j=0}^{n−2} (m d/m²)ʲ Ûₙ₋₁₋ⱼ, all positive sums
//! evaluated in logarithms (no overflow at any degree).
//!
//! **Search.** The shape is one coordinate y ∈ (−1, 1): ρ = 1 + y below 0, φ = φ_max √y above
//! (φ_max = π/(n − 1); y = 0 is the double eigenvalue), and ln m runs over
//! [−G/(n − 1), G/(n − 1)] ([`LOG_GROWTH`] = G: end-to-end leg ratios up to e^G). A grid of
//! cells over (ln m, y) keeps those where both residuals change sign at the corners, and
//! Newton's method from each cell's centre gives the roots, which are returned as starting
//! points of the five-unknown system, nearest to the typical curve first.

use bez_core::Vector2;

/// Half-width G of the searched range of ln m times (n − 1): end-to-end leg ratios up to e^G.
const LOG_GROWTH: f64 = 48.0;
/// Grid cells along ln m.
const CELLS_M: usize = 192;
/// Grid cells along each side (real, complex) of the shape coordinate y.
const CELLS_Y: usize = 32;
/// Newton iterations from a cell's centre.
const ITERATIONS: usize = 40;
/// Residual (in ln K) accepted as a root.
const ROOT_TOLERANCE: f64 = 1e-12;

/// The reduced equations for one degree and target: ln K₀ and ln K₁ (module docs) minus the
/// targets.
pub(crate) struct Reduced {
    degree: usize,
    /// Targets (ln K₀, ln K₁).
    target: [f64; 2],
    /// Tangent legs (l₀, l₁), chord scaled to 1.
    legs: [f64; 2],
    /// Unit end tangent in the frame of the start tangent.
    end_tangent: Vector2,
}

/// One point (ln m, y) of the reduced parametrization with its sequence and sums.
struct Shape {
    /// m.
    m: f64,
    /// d/m².
    det: f64,
    /// t/m.
    trace: f64,
    /// Ûₙ₋₁, Ûₙ₋₂.
    last: [f64; 2],
    /// ln 𝒮, ln 𝒜.
    log_sums: [f64; 2],
}

/// ln Σ_{j} cⱼ xʲ for x = e^{ln x} and positive cⱼ given from j = 0 up, by Horner's rule in
/// x or 1/x, whichever is at most 1.
fn log_poly<'a, I>(log_x: f64, coeffs: I) -> f64
where
    I: DoubleEndedIterator<Item = &'a f64> + ExactSizeIterator,
{
    let k = coeffs.len().saturating_sub(1) as f64;
    if log_x <= 0.0 {
        let x = log_x.exp();
        coeffs.rev().fold(0.0, |a, c| a * x + c).ln()
    } else {
        let x = (-log_x).exp();
        k * log_x + coeffs.fold(0.0, |a, c| a * x + c).ln()
    }
}

impl Reduced {
    /// The reduced system of degree n ≥ 3 for the scaled frame (start tangent e₁, chord
    /// `chord` of length 1, unit `end_tangent`) and scaled target curvatures (k₀, k₁); None when
    /// the data have no positive tangent legs or targets of the wrong sign.
    pub(crate) fn new(
        degree: usize,
        chord: Vector2,
        end_tangent: Vector2,
        k0: f64,
        k1: f64,
    ) -> Option<Self> {
        let sin = end_tangent.y();
        let l1 = chord.y() / sin;
        let l0 = chord.x() - l1 * end_tangent.x();
        let n = degree as f64;
        let unit = n / ((n - 1.0) * sin);
        let (c0, c1) = (k0 * unit * l0 * l0 / l1, k1 * unit * l1 * l1 / l0);
        (l0 > 0.0 && l1 > 0.0 && c0 > 0.0 && c1 > 0.0 && degree >= 3).then(|| Self {
            degree,
            target: [c0.ln(), c1.ln()],
            legs: [l0, l1],
            end_tangent,
        })
    }

    /// The shape at (ln m, y), with the sums; None outside the parameter domain.
    fn shape(&self, log_m: f64, y: f64, buffer: &mut Vec<f64>) -> Option<Shape> {
        let n = self.degree;
        if !(y > -1.0 && y < 1.0 && log_m.is_finite()) {
            return None;
        }
        buffer.clear();
        buffer.push(0.0);
        let (trace, det) = if y <= 0.0 {
            let rho = 1.0 + y;
            let mut u = 0.0;
            for _ in 1..n {
                u = 1.0 + rho * u;
                buffer.push(u);
            }
            (1.0 + rho, rho)
        } else {
            // Ûⱼ = sin jφ / sin φ, the angles jφ by rotation (error growing as j, not j²).
            let phi = std::f64::consts::PI / (n - 1) as f64 * y.sqrt();
            let (sin, cos) = phi.sin_cos();
            let (mut c, mut s) = (cos, sin);
            for _ in 1..n {
                buffer.push(s / sin);
                (c, s) = (c * cos - s * sin, s * cos + c * sin);
            }
            (2.0 * cos, 1.0)
        };
        if !buffer[1..].iter().all(|u| *u > 0.0) {
            return None;
        }
        let log_s = log_poly(log_m, buffer[1..].iter());
        let log_a = log_poly(log_m + det.ln(), buffer[1..].iter().rev());
        Some(Shape {
            m: log_m.exp(),
            det,
            trace,
            last: [buffer[n - 1], buffer[n - 2]],
            log_sums: [log_s, log_a],
        })
    }

    /// Residuals (ln K₀, ln K₁) minus the targets at (ln m, y).
    fn residual(&self, log_m: f64, y: f64, buffer: &mut Vec<f64>) -> Option<[f64; 2]> {
        let sh = self.shape(log_m, y, buffer)?;
        let [log_s, log_a] = sh.log_sums;
        let log_u = sh.last[0].ln();
        let k = (self.degree - 2) as f64;
        let r = [
            2.0 * log_a - 2.0 * log_u - log_s - self.target[0],
            k * (sh.det.ln() - log_m) + 2.0 * log_s - 2.0 * log_u - log_a - self.target[1],
        ];
        r.iter().all(|v| v.is_finite()).then_some(r)
    }

    /// Newton's method in (ln m, y) from `p` (forward-difference Jacobian, halving steps that
    /// leave the domain or do not decrease the residual).
    fn newton(&self, mut p: [f64; 2], buffer: &mut Vec<f64>) -> Option<[f64; 2]> {
        let norm = |r: &[f64; 2]| r[0].abs().max(r[1].abs());
        let mut r = self.residual(p[0], p[1], buffer)?;
        for _ in 0..ITERATIONS {
            if norm(&r) <= ROOT_TOLERANCE {
                return Some(p);
            }
            let mut jac = [[0.0; 2]; 2];
            for j in 0..2 {
                let h = 1e-7 * (1.0 + p[j].abs()) * if p[j] > 0.5 { -1.0 } else { 1.0 };
                let mut q = p;
                q[j] += h;
                let rq = self.residual(q[0], q[1], buffer)?;
                for i in 0..2 {
                    jac[i][j] = (rq[i] - r[i]) / h;
                }
            }
            let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let dx = [
                -(jac[1][1] * r[0] - jac[0][1] * r[1]) / det,
                -(jac[0][0] * r[1] - jac[1][0] * r[0]) / det,
            ];
            let mut step = 1.0;
            loop {
                let trial = [p[0] + step * dx[0], p[1] + step * dx[1]];
                if let Some(rt) = self.residual(trial[0], trial[1], buffer)
                    && norm(&rt) < norm(&r)
                {
                    (p, r) = (trial, rt);
                    break;
                }
                step *= 0.5;
                if step < 1e-6 {
                    return None;
                }
            }
        }
        (norm(&r) <= ROOT_TOLERANCE).then_some(p)
    }

    /// The five unknowns (L, M₁₁, M₁₂, M₂₁, M₂₂) of the scaled frame at a root (module docs:
    /// v = A w₀, M = A C A⁻¹ with C the companion matrix of (t, d) in the basis (w₀, w₁)).
    fn unknowns(&self, log_m: f64, y: f64, buffer: &mut Vec<f64>) -> Option<[f64; 5]> {
        let sh = self.shape(log_m, y, buffer)?;
        let [log_s, log_a] = sh.log_sums;
        let [l0, l1] = self.legs;
        // A w₀ = L e₁ with L = l₀/λ, λ = 𝒜/Ûₙ₋₁; A w₁ = α L e₁ + (l₁/𝒮) T₁ with
        // α = d Uₙ₋₂/Uₙ₋₁ = (d/m²) m Ûₙ₋₂/Ûₙ₋₁.
        let length = l0 * sh.last[0] * (-log_a).exp();
        let alpha = sh.det * sh.m * sh.last[1] / sh.last[0];
        let second = Vector2::new(alpha * length, 0.0) + self.end_tangent * (l1 * (-log_s).exp());
        // Columns of A: (L, 0) and `second`; C = [[0, −d], [1, t]].
        let (t, d) = (sh.trace * sh.m, sh.det * sh.m * sh.m);
        let (a11, a12, a21, a22) = (length, second.x(), 0.0, second.y());
        let det_a = a11 * a22 - a12 * a21;
        // A C = [[a12, −d a11 + t a12], [a22, −d a21 + t a22]]; A⁻¹ = [[a22, −a12], [−a21, a11]]/det.
        let (b11, b12, b21, b22) = (a12, -d * a11 + t * a12, a22, -d * a21 + t * a22);
        let x = [
            length,
            (b11 * a22 - b12 * a21) / det_a,
            (-b11 * a12 + b12 * a11) / det_a,
            (b21 * a22 - b22 * a21) / det_a,
            (-b21 * a12 + b22 * a11) / det_a,
        ];
        x.iter().all(|v| v.is_finite()).then_some(x)
    }

    /// All roots found on the grid, as starting points of the five-unknown system, the one
    /// nearest (in (ln m, y)) to `near` first.
    pub(crate) fn seeds(&self, near: [f64; 2]) -> Vec<[f64; 5]> {
        let (roots, mut buffer) = self.roots(near, LOG_GROWTH, CELLS_M, CELLS_Y);
        roots
            .iter()
            .filter_map(|r| self.unknowns(r[0], r[1], &mut buffer))
            .collect()
    }

    /// The roots in (ln m, y) found on a grid, nearest to `near` first.
    fn roots(
        &self,
        near: [f64; 2],
        growth: f64,
        cells_m: usize,
        cells_y: usize,
    ) -> (Vec<[f64; 2]>, Vec<f64>) {
        let n1 = (self.degree - 1) as f64;
        let half = growth / n1;
        let mut buffer = Vec::with_capacity(self.degree);
        let ms: Vec<f64> = (0..=cells_m)
            .map(|i| -half + 2.0 * half * i as f64 / cells_m as f64)
            .collect();
        // y nodes strictly inside (−1, 1), denser towards both ends.
        let ys: Vec<f64> = (0..=2 * cells_y)
            .map(|k| {
                let u = (k as f64 + 0.5) / (2 * cells_y + 1) as f64 * 2.0 - 1.0;
                u.signum() * (1.0 - (1.0 - u.abs()).powi(2))
            })
            .collect();
        let values: Vec<Vec<Option<[f64; 2]>>> = ms
            .iter()
            .map(|&lm| {
                ys.iter()
                    .map(|&y| self.residual(lm, y, &mut buffer))
                    .collect()
            })
            .collect();
        let mut roots: Vec<[f64; 2]> = Vec::new();
        // A cell is tried when both residuals change sign over the nodes of the 3 × 3 block of
        // cells around it (a root inside a cell need not change the signs at its own corners).
        for i in 0..cells_m {
            for k in 0..ys.len() - 1 {
                let block = (i.saturating_sub(1)..=(i + 2).min(cells_m)).flat_map(|a| {
                    (k.saturating_sub(1)..=(k + 2).min(ys.len() - 1)).map(move |b| (a, b))
                });
                let brackets = (0..2).all(|c| {
                    let (lo, hi) = block
                        .clone()
                        .filter_map(|(a, b)| values[a][b])
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| {
                            (lo.min(r[c]), hi.max(r[c]))
                        });
                    lo <= 0.0 && hi >= 0.0
                });
                if !brackets {
                    continue;
                }
                let centre = [0.5 * (ms[i] + ms[i + 1]), 0.5 * (ys[k] + ys[k + 1])];
                if let Some(root) = self.newton(centre, &mut buffer)
                    && roots
                        .iter()
                        .all(|r| (r[0] - root[0]).abs() + (r[1] - root[1]).abs() > 1e-7)
                {
                    roots.push(root);
                }
            }
        }
        let distance = |r: &[f64; 2]| (r[0] - near[0]).powi(2) + (r[1] - near[1]).powi(2);
        roots.sort_by(|a, b| distance(a).total_cmp(&distance(b)));
        (roots, buffer)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{class_a_curve, end_curvatures, square::Matrix2};
    use proptest::prelude::*;

    proptest! {
        /// The closed forms against the control points: the curve built from a point (ln m, y)
        /// meets the G1 data (end point, end tangent), and its end curvatures by
        /// [`end_curvatures`] (finite differences of the control points) make the residual of
        /// that point vanish.
        #[test]
        fn reduced_equations_match_the_control_points(
            degree in 3usize..=16,
            turn in 0.1f64..3.0,
            chord_share in 0.1f64..0.9,
            clockwise in proptest::bool::ANY,
            growth in -4.0f64..4.0,
            y in -0.6f64..0.95,
        ) {
            let sign = if clockwise { -1.0 } else { 1.0 };
            let delta = sign * turn * chord_share;
            let chord = Vector2::new(delta.cos(), delta.sin());
            let end_tangent = Vector2::new(turn.cos(), sign * turn.sin());
            let log_m = growth / (degree - 1) as f64;
            let probe = Reduced::new(degree, chord, end_tangent, sign, sign).unwrap();
            let mut buffer = Vec::new();
            let x = probe.unknowns(log_m, y, &mut buffer).unwrap();
            let m = Matrix2::new(x[1], x[2], x[3], x[4]);
            let curve = class_a_curve(&Vector2::zeros(), &Vector2::new(x[0], 0.0), &m, degree).unwrap();
            let p = curve.points();
            prop_assert!((p[degree] - chord).norm() < 1e-9, "end point {:?}", p[degree]);
            let last = p[degree] - p[degree - 1];
            prop_assert!(last.perp(&end_tangent).abs() < 1e-9 * last.norm() && last.dot(&end_tangent) > 0.0);
            let (k0, k1) = end_curvatures(&curve).unwrap();
            let reduced = Reduced::new(degree, chord, end_tangent, k0, k1).unwrap();
            let r = reduced.residual(log_m, y, &mut buffer).unwrap();
            // The oracle's rounding: the cross product of two nearly parallel end legs loses
            // about ε |a| |b| / |a × b| relative.
            let condition = |a: Vector2, b: Vector2| a.norm() * b.norm() / a.perp(&b).abs();
            let tolerance = [
                1e-10 + 1e-13 * condition(p[1] - p[0], p[2] - p[1]),
                1e-10 + 1e-13 * condition(p[degree - 1] - p[degree - 2], last),
            ];
            prop_assert!(
                r[0].abs() < tolerance[0] && r[1].abs() < tolerance[1],
                "residual {r:?}, tolerance {tolerance:?}"
            );
        }
    }

    /// The search's grid against one twice as wide and about twice as fine in both
    /// coordinates, on targets of the reach table (typical G1 data, curvatures scaled): the
    /// same roots.
    #[test]
    fn the_grid_finds_the_roots_of_a_wider_finer_grid() {
        for (n, turn, s, f0, f1) in [
            (4usize, 0.3f64, 1.1f64, 0.7, 1.4),
            (7, 1.2, 1.12, 1.0, 1.05),
            (7, 0.6, 0.9, 0.5, 1.15),
            (12, 2.0, 1.12, 0.85, 0.5),
        ] {
            let theta = turn / (n - 1) as f64;
            let m = crate::typical_matrix2(s, theta);
            let curve = class_a_curve(&Vector2::zeros(), &Vector2::new(1.0, 0.0), &m, n).unwrap();
            let p = curve.points();
            let (k0, k1) = end_curvatures(&curve).unwrap();
            let chord = p[n] - p[0];
            let length = chord.norm();
            let tangent = (p[n] - p[n - 1]) / (p[n] - p[n - 1]).norm();
            let reduced = Reduced::new(
                n,
                chord / length,
                tangent,
                k0 * f0 * length,
                k1 * f1 * length,
            )
            .unwrap();
            let near = [s.ln(), (turn / std::f64::consts::PI).powi(2)];
            let found = reduced.roots(near, LOG_GROWTH, CELLS_M, CELLS_Y).0;
            let wide = reduced
                .roots(near, 2.0 * LOG_GROWTH, 4 * CELLS_M, 2 * CELLS_Y)
                .0;
            assert!(!found.is_empty(), "n {n}, turn {turn}");
            assert_eq!(
                found.len(),
                wide.len(),
                "n {n}, turn {turn}: {found:?} {wide:?}"
            );
            for (a, b) in found.iter().zip(&wide) {
                assert!((a[0] - b[0]).abs() + (a[1] - b[1]).abs() < 1e-9);
            }
        }
    }
}
