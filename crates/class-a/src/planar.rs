//! Interactive typical planar Class A curves from three points (eqs. (5)–(8)).

use bez_core::{BezierCurve, Vector2};
use num_complex::Complex;

use crate::square::Matrix2;

use crate::INTERPOLATION_TOLERANCE;
use crate::matrix::{typical_matrix2, typical_planar_margin};
use crate::{ClassAError, Interpolation};

/// A typical planar Class A curve: b₀, first leg L·μ, and M = s·R(θ) (eq. (5)).
///
/// Fields are private: [`TypicalPlanar::from_points`] solves them from three points and
/// [`TypicalPlanar::new`] checks given ones (deserialization goes through it too).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "PlanarRepr", into = "PlanarRepr")
)]
pub struct TypicalPlanar {
    b0: Vector2,
    mu: Vector2,
    length: f64,
    s: f64,
    theta: f64,
    degree: usize,
}

/// Serialized form of [`TypicalPlanar`], checked by [`TypicalPlanar::new`] when read.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct PlanarRepr {
    b0: Vector2,
    mu: Vector2,
    length: f64,
    s: f64,
    theta: f64,
    degree: usize,
}

#[cfg(feature = "serde")]
impl TryFrom<PlanarRepr> for TypicalPlanar {
    type Error = ClassAError;
    fn try_from(r: PlanarRepr) -> Result<Self, ClassAError> {
        Self::new(r.b0, r.mu, r.length, r.s, r.theta, r.degree)
    }
}

#[cfg(feature = "serde")]
impl From<TypicalPlanar> for PlanarRepr {
    fn from(t: TypicalPlanar) -> Self {
        Self {
            b0: t.b0,
            mu: t.mu,
            length: t.length,
            s: t.s,
            theta: t.theta,
            degree: t.degree,
        }
    }
}

/// Signed angle from a to b in (−π, π].
pub(crate) fn signed_angle(a: &Vector2, b: &Vector2) -> f64 {
    (a.x() * b.y() - a.y() * b.x()).atan2(a.dot(b))
}

/// The geometry of three interactive points: ψ (tangent turn), δ (chord angle), |chord|.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct PlanarGeometry {
    /// Unit start tangent μ = (α₁ − α₀)/|α₁ − α₀|.
    pub mu: Vector2,
    /// Signed turn ψ from α₁ − α₀ to α₂ − α₁.
    pub turn: f64,
    /// Signed angle δ of α₂ − α₀ measured from α₁ − α₀.
    pub chord_angle: f64,
    /// |α₂ − α₀|.
    pub chord_length: f64,
}

impl PlanarGeometry {
    /// Validates the three points.
    ///
    /// # Errors
    /// [`ClassAError::NonFinite`], [`ClassAError::InvalidParameter`] (a coordinate beyond
    /// ±`bez_core::MAX_COORDINATE`), [`ClassAError::CoincidentPoints`],
    /// [`ClassAError::DegenerateTurn`] (collinear, or a turn of π),
    /// [`ClassAError::ChordOutsideTangents`] (δ not strictly between 0 and ψ).
    pub fn new(a0: &Vector2, a1: &Vector2, a2: &Vector2) -> Result<Self, ClassAError> {
        for (p, name) in [(a0, "alpha0"), (a1, "alpha1"), (a2, "alpha2")] {
            crate::error::check_point(p, name)?;
        }
        let (t0, t1, c) = (a1 - a0, a2 - a1, a2 - a0);
        for (v, first, second) in [(&t0, 0, 1), (&t1, 1, 2), (&c, 0, 2)] {
            if v.norm() == 0.0 {
                return Err(ClassAError::CoincidentPoints { first, second });
            }
        }
        let turn = signed_angle(&t0, &t1);
        if turn == 0.0 || turn.abs() >= std::f64::consts::PI {
            return Err(ClassAError::DegenerateTurn { turn });
        }
        let chord_angle = signed_angle(&t0, &c);
        let inside = if turn > 0.0 {
            chord_angle > 0.0 && chord_angle < turn
        } else {
            chord_angle < 0.0 && chord_angle > turn
        };
        if !inside {
            return Err(ClassAError::ChordOutsideTangents { chord_angle, turn });
        }
        Ok(Self {
            mu: t0 / t0.norm(),
            turn,
            chord_angle,
            chord_length: c.norm(),
        })
    }
}

/// p(x) = Σⱼ cⱼ xʲ by Horner (x ≤ 1), or its reversal xⁿ⁻¹p(1/x) (x = 1/s ≤ 1).
fn poly(coeffs: &[f64], x: f64, reversed: bool) -> f64 {
    if reversed {
        coeffs.iter().fold(0.0, |acc, c| acc * x + c)
    } else {
        coeffs.iter().rev().fold(0.0, |acc, c| acc * x + c)
    }
}

fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let mut flo = f(lo);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let fm = f(mid);
        if fm == 0.0 {
            return mid;
        }
        if (fm < 0.0) == (flo < 0.0) {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The unique positive root s of Σ_{j=0}^{n−1} sin(jθ − δ) sʲ = 0 (NOTES; from eq. (6) by
/// dividing by L μ e^{iδ} and taking the imaginary part).
///
/// The coefficients sin(jθ − δ) change sign exactly once (jθ − δ runs monotonically from −δ to
/// ψ − δ, an interval of length |ψ| < π containing 0), so by Descartes' rule there is exactly one
/// positive root. It is bracketed in (0, 1] by p, or in (0, 1) in u = 1/s by the reversed
/// polynomial, and found by bisection to full precision (no overflow: |s|, |u| ≤ 1 in Horner).
#[must_use]
pub fn solve_scale(theta: f64, delta: f64, degree: usize) -> f64 {
    let coeffs: Vec<f64> = (0..degree)
        .map(|j| (j as f64 * theta - delta).sin())
        .collect();
    let p1 = poly(&coeffs, 1.0, false);
    if p1 == 0.0 {
        return 1.0;
    }
    let p0 = poly(&coeffs, 0.0, false);
    if (p0 < 0.0) != (p1 < 0.0) {
        bisect(|s| poly(&coeffs, s, false), 0.0, 1.0)
    } else {
        let u = bisect(|u| poly(&coeffs, u, true), 0.0, 1.0);
        1.0 / u
    }
}

/// Whether three points admit a typical Class A curve of degree n, and by which margin.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct PlanarFeasibility {
    /// The scale s solved from the points.
    pub s: f64,
    /// θ = ψ/(n − 1).
    pub theta: f64,
    /// Margin of condition (4), [`typical_planar_margin`]: ≥ 0 iff feasible.
    pub margin: f64,
    /// The chord angles δ (from the start tangent) that are forbidden for this turn ψ and
    /// degree: the open interval between the chord angles given by s = cos θ and s = 1/cos θ.
    /// An interactive tool can shade this wedge at α₀.
    pub forbidden_chord_angles: (f64, f64),
}

impl PlanarFeasibility {
    /// The points admit a Class A curve.
    #[must_use]
    pub fn is_feasible(&self) -> bool {
        self.margin >= 0.0
    }
}

/// arg Σ_{j<n} (s e^{iθ})ʲ: the chord angle δ produced by a given s.
fn chord_angle_of(s: f64, theta: f64, n: usize) -> f64 {
    let z = Complex::from_polar(s, theta);
    let mut sum = Complex::new(0.0, 0.0);
    let mut p = Complex::new(1.0, 0.0);
    for _ in 0..n {
        sum += p;
        p *= z;
    }
    sum.im.atan2(sum.re)
}

/// Feasibility of the points α₀, α₁, α₂ for degree n, computed in advance (no curve built).
///
/// # Errors
/// As [`PlanarGeometry::new`], and [`ClassAError::DegreeTooLow`] for n < 2.
pub fn planar_feasibility(
    a0: &Vector2,
    a1: &Vector2,
    a2: &Vector2,
    degree: usize,
) -> Result<PlanarFeasibility, ClassAError> {
    crate::error::check_degree(degree, 2)?;
    let g = PlanarGeometry::new(a0, a1, a2)?;
    let theta = g.turn / (degree - 1) as f64;
    let s = solve_scale(theta, g.chord_angle, degree);
    let c = theta.cos();
    let forbidden = if c > 0.0 {
        let (x, y) = (
            chord_angle_of(c, theta, degree),
            chord_angle_of(1.0 / c, theta, degree),
        );
        (x.min(y), x.max(y))
    } else {
        (g.turn.min(0.0), g.turn.max(0.0))
    };
    Ok(PlanarFeasibility {
        s,
        theta,
        margin: typical_planar_margin(s, theta),
        forbidden_chord_angles: forbidden,
    })
}

impl TypicalPlanar {
    /// The curve with first control point b₀, unit start direction μ, first leg length L > 0,
    /// M = s·R(θ) with s > 0, and degree n ≥ 2. Being Class A is reported
    /// ([`TypicalPlanar::margin`]), not required.
    ///
    /// # Errors
    /// [`ClassAError::NonFinite`], [`ClassAError::InvalidParameter`] (|μ| not 1 within 1e-12,
    /// L ≤ 0 or s ≤ 0), [`ClassAError::DegreeTooLow`].
    pub fn new(
        b0: Vector2,
        mu: Vector2,
        length: f64,
        s: f64,
        theta: f64,
        degree: usize,
    ) -> Result<Self, ClassAError> {
        for (name, ok) in [
            ("b0", b0.is_finite()),
            ("mu", mu.is_finite()),
            ("length", length.is_finite()),
            ("s", s.is_finite()),
            ("theta", theta.is_finite()),
        ] {
            if !ok {
                return Err(ClassAError::NonFinite { name });
            }
        }
        if (mu.norm() - 1.0).abs() > 1e-12 {
            return Err(ClassAError::InvalidParameter {
                name: "|mu|",
                value: mu.norm(),
                expected: "1 within 1e-12",
            });
        }
        for (name, value) in [("length", length), ("s", s)] {
            if value <= 0.0 {
                return Err(ClassAError::InvalidParameter {
                    name,
                    value,
                    expected: "positive",
                });
            }
        }
        crate::error::check_degree(degree, 2)?;
        Ok(Self {
            b0,
            mu,
            length,
            s,
            theta,
            degree,
        })
    }

    /// First control point b₀ = α₀.
    #[must_use]
    pub fn b0(&self) -> Vector2 {
        self.b0
    }

    /// Unit start tangent μ.
    #[must_use]
    pub fn mu(&self) -> Vector2 {
        self.mu
    }

    /// Length L = |Δb₀| of the first leg (the paper's second meaning of "b₀").
    #[must_use]
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Scale s of M.
    #[must_use]
    pub fn s(&self) -> f64 {
        self.s
    }

    /// Rotation angle θ per leg (signed).
    #[must_use]
    pub fn theta(&self) -> f64 {
        self.theta
    }

    /// Degree n.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Solves the typical planar Class A curve of degree n through α₀ and α₂ with end tangents
    /// along α₁ − α₀ and α₂ − α₁ (eqs. (5)–(8)): θ = ψ/(n − 1), s from [`solve_scale`],
    /// L = |α₂ − α₀| / |Σ zʲ| with z = s e^{iθ}.
    ///
    /// The result is verified before it is returned: its control points
    /// ([`TypicalPlanar::control_points_into`]) have non-zero end legs and meet the end points
    /// and tangent directions to [`INTERPOLATION_TOLERANCE`] ([`Interpolation`]); a curve that
    /// does not is an error, not an `Ok`.
    ///
    /// # Errors
    /// As [`planar_feasibility`]; [`ClassAError::NotClassA`] when s violates condition (4)
    /// (cos θ < s < 1/cos θ; an isosceles triangle gives s = 1); [`ClassAError::ToleranceNotMet`]
    /// when the rounded control points miss an end condition, e.g. a last leg L·sⁿ⁻¹ below the
    /// rounding of α₂ (s ≪ 1 at high degree; a zero leg counts as a tangent error of π).
    pub fn from_points(
        a0: &Vector2,
        a1: &Vector2,
        a2: &Vector2,
        degree: usize,
    ) -> Result<Self, ClassAError> {
        let t = Self::unverified(a0, a1, a2, degree)?;
        let mut points = Vec::with_capacity(degree + 1);
        t.control_points_into(&mut points);
        Interpolation::measure(&points, a0, &(a1 - a0), &(a2 - a1), a2)
            .within(INTERPOLATION_TOLERANCE)?;
        Ok(t)
    }

    /// The solved parameters without the interpolation check.
    fn unverified(
        a0: &Vector2,
        a1: &Vector2,
        a2: &Vector2,
        degree: usize,
    ) -> Result<Self, ClassAError> {
        let f = planar_feasibility(a0, a1, a2, degree)?;
        if !f.is_feasible() {
            let c = f.theta.cos();
            return Err(ClassAError::NotClassA {
                s: f.s,
                theta: f.theta,
                lower: c,
                upper: 1.0 / c,
            });
        }
        Self::from_points_unchecked(a0, a1, a2, degree, f.s, f.theta)
    }

    fn from_points_unchecked(
        a0: &Vector2,
        a1: &Vector2,
        a2: &Vector2,
        degree: usize,
        s: f64,
        theta: f64,
    ) -> Result<Self, ClassAError> {
        let g = PlanarGeometry::new(a0, a1, a2)?;
        let sum = geometric_sum(s, theta, degree);
        let length = g.chord_length / sum.norm();
        if !length.is_finite() || length <= 0.0 {
            return Err(ClassAError::NonFinite { name: "length" });
        }
        Ok(Self {
            b0: *a0,
            mu: g.mu,
            length,
            s,
            theta,
            degree,
        })
    }

    /// [`TypicalPlanar::from_points`], then the curve and its achieved interpolation errors
    /// ([`Interpolation`]), which must be within `tolerance` (the issue's [`INTERPOLATION_TOLERANCE`]
    /// is 1e-9).
    ///
    /// # Errors
    /// As [`TypicalPlanar::from_points`] and [`TypicalPlanar::curve`];
    /// [`ClassAError::ToleranceNotMet`] when the rounded control points cannot meet the end
    /// conditions (typically the end tangent when s ≪ 1 at high degree, where the last leg
    /// L·sⁿ⁻¹ is below the rounding of bₙ).
    pub fn generate(
        a0: &Vector2,
        a1: &Vector2,
        a2: &Vector2,
        degree: usize,
        tolerance: f64,
    ) -> Result<(Self, BezierCurve<2>, Interpolation), ClassAError> {
        let t = Self::unverified(a0, a1, a2, degree)?;
        let c = t.curve()?;
        let e =
            Interpolation::measure(c.points(), a0, &(a1 - a0), &(a2 - a1), a2).within(tolerance)?;
        Ok((t, c, e))
    }

    /// M = s·R(θ).
    #[must_use]
    pub fn matrix(&self) -> Matrix2 {
        typical_matrix2(self.s, self.theta)
    }

    /// The Bézier curve (eq. (8)), its control points built from both ends
    /// ([`TypicalPlanar::control_points_into`]).
    ///
    /// # Errors
    /// [`ClassAError::Core`] if the control points overflow.
    pub fn curve(&self) -> Result<BezierCurve<2>, ClassAError> {
        let mut points = Vec::with_capacity(self.degree + 1);
        self.control_points_into(&mut points);
        Ok(BezierCurve::new(points)?)
    }

    /// Control points written in place (no allocation beyond `out`), for interactive updates:
    /// b₀ … b_⌊n/2⌋ forward from b₀, the rest backward from bₙ = b₀ + L μ Σ zʲ with the last
    /// leg L sⁿ⁻¹ R((n − 1)θ) μ computed directly, so the end tangent carries one rounding of
    /// bₙ₋₁ rather than n (in real arithmetic, eq. (8)).
    pub fn control_points_into(&self, out: &mut Vec<Vector2>) {
        let n = self.degree;
        let turn = (n - 1) as f64;
        let magnitude = (self.length.ln() + turn * self.s.ln()).exp();
        let (sn, cs) = (self.theta * turn).sin_cos();
        let mu = self.mu;
        let last = Vector2::new(cs * mu.x() - sn * mu.y(), sn * mu.x() + cs * mu.y()) * magnitude;
        crate::curve::two_ended_points(
            &self.b0,
            &(self.mu * self.length),
            &last,
            &self.matrix(),
            &typical_matrix2(1.0 / self.s, -self.theta),
            n,
            out,
        );
    }

    /// Margin of condition (4) (≥ 0: monotone curvature, exactly).
    #[must_use]
    pub fn margin(&self) -> f64 {
        typical_planar_margin(self.s, self.theta)
    }

    /// w(t) = 1 + t(s e^{iθ} − 1): x'(t) = nLμ w(t)ⁿ⁻¹ in complex notation.
    fn w(&self, t: f64) -> Complex<f64> {
        let z = Complex::from_polar(self.s, self.theta);
        Complex::new(1.0, 0.0) + (z - 1.0) * t
    }

    /// Signed curvature in closed form: κ(t) = (n − 1) s sin θ / (n L |w(t)|ⁿ⁺¹), accurate at
    /// high degree where differences of control points are not (NOTES).
    #[must_use]
    pub fn curvature(&self, t: f64) -> f64 {
        let n = self.degree as f64;
        (n - 1.0) * self.s * self.theta.sin() / (n * self.length * self.w(t).norm().powf(n + 1.0))
    }

    /// (log |κ|, log(|κ| / |dκ/ds|)) at t in closed form: one point of the LCG as
    /// (−x, y) = (log κ, log(ρ |ds/dρ|)); see [`crate::log_graph`]. None where dκ/ds = 0.
    #[must_use]
    pub fn log_curvature_point(&self, t: f64) -> Option<(f64, f64)> {
        let n = self.degree as f64;
        let z = Complex::from_polar(self.s, self.theta);
        let w = self.w(t);
        let aw = w.norm();
        let daw = ((z - 1.0) * w.conj()).re / aw;
        if daw == 0.0 || self.theta == 0.0 {
            return None;
        }
        let log_k = ((n - 1.0) * self.s * self.theta.sin().abs() / (n * self.length)).ln()
            - (n + 1.0) * aw.ln();
        let y = (n * self.length).ln() + n * aw.ln() - (n + 1.0).ln() - daw.abs().ln();
        Some((-log_k, y))
    }
}

fn geometric_sum(s: f64, theta: f64, n: usize) -> Complex<f64> {
    let z = Complex::from_polar(s, theta);
    let mut sum = Complex::new(0.0, 0.0);
    let mut p = Complex::new(1.0, 0.0);
    for _ in 0..n {
        sum += p;
        p *= z;
    }
    sum
}

/// The paper's method (eq. (7)): minimize |L Σ Mʲμ − (α₂ − α₀)|² / |α₂ − α₀|² over (L, s) with
/// Nelder–Mead (argmin), θ = ψ/(n − 1) fixed; start (|α₂ − α₀|/n, 1) with a 10 % simplex.
///
/// Kept for comparison with [`TypicalPlanar::from_points`]. Returns the curve and the final
/// relative endpoint residual.
///
/// Feature `paper`.
///
/// # Errors
/// As [`planar_feasibility`], [`ClassAError::Optimizer`] if argmin fails,
/// [`ClassAError::NoConvergence`] for a non-positive L or s.
#[cfg(feature = "paper")]
pub fn planar_nelder_mead(
    a0: &Vector2,
    a1: &Vector2,
    a2: &Vector2,
    degree: usize,
    max_iters: u64,
) -> Result<(TypicalPlanar, f64), ClassAError> {
    use argmin::core::{CostFunction, Executor, State};
    use argmin::solver::neldermead::NelderMead;
    crate::error::check_degree(degree, 2)?;
    let g = PlanarGeometry::new(a0, a1, a2)?;
    let theta = g.turn / (degree - 1) as f64;
    let target = Complex::from_polar(g.chord_length, g.chord_angle);
    struct Cost {
        theta: f64,
        n: usize,
        target: Complex<f64>,
    }
    impl CostFunction for Cost {
        type Param = Vec<f64>;
        type Output = f64;
        fn cost(&self, p: &Self::Param) -> Result<f64, argmin::core::Error> {
            let r = geometric_sum(p[1], self.theta, self.n) * p[0] - self.target;
            Ok(r.norm_sqr() / self.target.norm_sqr())
        }
    }
    let l0 = g.chord_length / degree as f64;
    let simplex = vec![vec![l0, 1.0], vec![1.1 * l0, 1.0], vec![l0, 1.1]];
    let solver = NelderMead::new(simplex)
        .with_sd_tolerance(1e-30)
        .map_err(|e| ClassAError::Optimizer {
            message: e.to_string(),
        })?;
    let res = Executor::new(
        Cost {
            theta,
            n: degree,
            target,
        },
        solver,
    )
    .configure(|st| st.max_iters(max_iters))
    .run()
    .map_err(|e| ClassAError::Optimizer {
        message: e.to_string(),
    })?;
    let best = res.state().get_best_param().cloned().unwrap_or_default();
    let residual = res.state().get_best_cost().sqrt();
    match best.as_slice() {
        [l, s] if *l > 0.0 && *s > 0.0 && l.is_finite() && s.is_finite() => Ok((
            TypicalPlanar {
                b0: *a0,
                mu: g.mu,
                length: *l,
                s: *s,
                theta,
                degree,
            },
            residual,
        )),
        _ => Err(ClassAError::NoConvergence {
            method: "Nelder-Mead",
            residual,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn new_checks_every_parameter_and_agrees_with_from_points() {
        let (a0, a1, a2) = (
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 0.0),
            Vector2::new(1.6, 1.0),
        );
        let solved = TypicalPlanar::from_points(&a0, &a1, &a2, 7).unwrap();
        let rebuilt = TypicalPlanar::new(
            solved.b0(),
            solved.mu(),
            solved.length(),
            solved.s(),
            solved.theta(),
            solved.degree(),
        )
        .unwrap();
        assert_eq!(rebuilt, solved);
        let (b0, mu) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
        assert!(matches!(
            TypicalPlanar::new(b0, mu, f64::NAN, 1.0, 0.1, 5),
            Err(ClassAError::NonFinite { name: "length" })
        ));
        assert!(matches!(
            TypicalPlanar::new(b0, Vector2::new(2.0, 0.0), 1.0, 1.0, 0.1, 5),
            Err(ClassAError::InvalidParameter { name: "|mu|", .. })
        ));
        assert!(matches!(
            TypicalPlanar::new(b0, mu, 1.0, -1.0, 0.1, 5),
            Err(ClassAError::InvalidParameter { name: "s", .. })
        ));
        assert!(matches!(
            TypicalPlanar::new(b0, mu, 0.0, 1.0, 0.1, 5),
            Err(ClassAError::InvalidParameter { name: "length", .. })
        ));
        assert!(matches!(
            TypicalPlanar::new(b0, mu, 1.0, 1.0, 0.1, 1),
            Err(ClassAError::DegreeTooLow {
                degree: 1,
                needed: 2
            })
        ));
    }
}
