//! Interactive typical spatial Class A curves from four points (eqs. (9)–(15)).

use crate::square::Matrix3;
use bez_core::{BezierCurve, Vector3};

use crate::{ClassAError, Interpolation, class_a_curve};

/// A typical spatial Class A curve: M = s·R(u, θ) (eqs. (9)–(12)), first leg L·v₀.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TypicalSpatial {
    /// b₀ = α₀.
    pub b0: Vector3,
    /// Unit start tangent v₀.
    pub v0: Vector3,
    /// L = |Δb₀|.
    pub length: f64,
    /// Scale s.
    pub s: f64,
    /// Axis angle φ of eq. (14).
    pub phi: f64,
    /// Unit rotation axis u.
    pub axis: Vector3,
    /// Rotation angle per leg θ = ψ/(n − 1).
    pub theta: f64,
    /// Degree n.
    pub degree: usize,
}

/// Rotation by θ about the unit axis u (right-handed, Rodrigues):
/// R = I + sin θ K + (1 − cos θ)K², with K v = u × v (K the cross-product matrix of u). The printed eq. (12) is the
/// transpose of K (it rotates by −θ); we use the usual convention and test v₁ = Rⁿ⁻¹v₀.
#[must_use]
pub fn rotation(axis: &Vector3, theta: f64) -> Matrix3 {
    let k = Matrix3::cross_matrix(axis);
    Matrix3::identity() + k * theta.sin() + k * k * (1.0 - theta.cos())
}

/// Eq. (14), corrected: u = (v₀×v₁)/|v₀×v₁| cos φ + (v₀+v₁)/|v₀+v₁| sin φ.
fn axis_of(v0: &Vector3, v1: &Vector3, phi: f64) -> Vector3 {
    let c = v0.cross(v1);
    let b = v0 + v1;
    c / c.norm() * phi.cos() + b / b.norm() * phi.sin()
}

/// Angle ψ about u from the projection of v₀ to that of v₁, in (−π, π].
fn turn_about(u: &Vector3, v0: &Vector3, v1: &Vector3) -> f64 {
    let p0 = v0 - u * u.dot(v0);
    let p1 = v1 - u * u.dot(v1);
    u.dot(&p0.cross(&p1)).atan2(p0.dot(&p1))
}

/// The validated input of the spatial problem.
#[derive(Debug, Clone, Copy)]
struct Setup {
    v0: Vector3,
    v1: Vector3,
    chord: Vector3,
    n: usize,
}

impl Setup {
    fn new(a: &[Vector3; 4], degree: usize) -> Result<Self, ClassAError> {
        crate::error::check_degree(degree, 2)?;
        for p in a {
            crate::error::check_point(p, "alpha")?;
        }
        let (t0, t1, chord) = (a[1] - a[0], a[3] - a[2], a[3] - a[0]);
        for (v, first, second) in [(&t0, 0, 1), (&t1, 2, 3), (&chord, 0, 3)] {
            if v.norm() == 0.0 {
                return Err(ClassAError::CoincidentPoints { first, second });
            }
        }
        let (v0, v1) = (t0 / t0.norm(), t1 / t1.norm());
        let cos_angle = v0.dot(&v1);
        if v0.cross(&v1).norm() < 1e-12 {
            return Err(ClassAError::ParallelTangents { cos_angle });
        }
        Ok(Self {
            v0,
            v1,
            chord,
            n: degree,
        })
    }

    /// (u, θ, Σ_{j<n} sʲRʲv₀) for (φ, s).
    fn sum(&self, phi: f64, s: f64) -> (Vector3, f64, Vector3) {
        let u = axis_of(&self.v0, &self.v1, phi);
        let theta = turn_about(&u, &self.v0, &self.v1) / (self.n - 1) as f64;
        let m = rotation(&u, theta) * s;
        let mut leg = self.v0;
        let mut sum = Vector3::zeros();
        for _ in 0..self.n {
            sum += leg;
            leg = m * leg;
        }
        (u, theta, sum)
    }

    /// Residual: unit(Σ) − unit(chord), a 3-vector (2 independent components).
    fn residual(&self, phi: f64, log_s: f64) -> Vector3 {
        let (_, _, sum) = self.sum(phi, log_s.exp());
        let c = self.chord / self.chord.norm();
        let n = sum.norm();
        if n.is_finite() && n > 0.0 {
            sum / n - c
        } else {
            Vector3::repeat(f64::INFINITY)
        }
    }

    fn finish(&self, a0: &Vector3, phi: f64, s: f64) -> Result<TypicalSpatial, ClassAError> {
        let (axis, theta, sum) = self.sum(phi, s);
        let length = self.chord.norm() / sum.norm();
        if !(length.is_finite() && length > 0.0) {
            return Err(ClassAError::NonFinite { name: "length" });
        }
        Ok(TypicalSpatial {
            b0: *a0,
            v0: self.v0,
            length,
            s,
            phi,
            axis,
            theta,
            degree: self.n,
        })
    }
}

/// Half-width of the φ range searched: |φ| < π/2 (φ = ±π/2 makes ψ = π).
const PHI_MAX: f64 = 1.5607963267948966;

/// Grid over (φ, log s) for the Newton starts: 41 × 33 points.
const GRID: (usize, usize) = (41, 33);
/// Newton runs from this many best grid points.
const STARTS: usize = 12;
/// A Newton run has converged when the chord-direction residual is at most this.
const CONVERGED: f64 = 1e-12;

impl TypicalSpatial {
    /// Solves the typical spatial curve through α₀, α₃ with end tangents along α₁ − α₀ and
    /// α₃ − α₂ (eqs. (13)–(15)) and returns the converged solution with the largest Class A
    /// margin ([`TypicalSpatial::class_a_margin`]), provided that margin is ≥ 0.
    ///
    /// Method ([`TypicalSpatial::candidates`]): a grid over (φ, log s) ∈ (−π/2, π/2) × [−4, 4] of
    /// the chord-direction residual |unit(Σ sʲRʲv₀) − unit(α₃ − α₀)|, then damped Newton
    /// (finite-difference Jacobian, least squares on the 3-vector residual) from the 12 best
    /// grid points. L is |α₃ − α₀| / |Σ| (eq. (15) fixes only the direction).
    ///
    /// Guarantees: every returned curve meets the end conditions to the residual 1e-12 and is
    /// Class A (Farin's condition (3) for M, or for M⁻¹ when s < 1). Not guaranteed: that every
    /// solution of the two equations in (φ, s) is found (only those whose Newton basin holds one
    /// of the starts; solutions with s outside [e⁻⁴, e⁴] are reached only if Newton walks there),
    /// so [`ClassAError::NoClassASolution`] means no *found* solution is Class A, not that none
    /// exists.
    ///
    /// # Errors
    /// [`ClassAError::DegreeTooLow`], [`ClassAError::NonFinite`], [`ClassAError::CoincidentPoints`],
    /// [`ClassAError::ParallelTangents`], [`ClassAError::ChordUnreachable`] (no start converged;
    /// e.g. a chord pointing back against both tangents), [`ClassAError::NoClassASolution`] (every
    /// converged solution has a negative Class A margin; [`TypicalSpatial::candidates`] still
    /// returns them).
    pub fn from_points(a: &[Vector3; 4], degree: usize) -> Result<Self, ClassAError> {
        let all = Self::candidates(a, degree)?;
        match all.first() {
            Some(best) if best.class_a_margin() >= 0.0 => Ok(*best),
            Some(best) => Err(ClassAError::NoClassASolution {
                converged: all.len(),
                best_margin: best.class_a_margin(),
                s: best.s,
                theta: best.theta,
            }),
            None => Err(ClassAError::ChordUnreachable {
                residual: f64::INFINITY,
            }),
        }
    }

    /// [`TypicalSpatial::from_points`], then the curve and its achieved interpolation errors
    /// ([`Interpolation`]), which must be within `tolerance` (the issue asks for 1e-9).
    ///
    /// # Errors
    /// As [`TypicalSpatial::from_points`] and [`TypicalSpatial::curve`];
    /// [`ClassAError::ToleranceNotMet`] when the rounded control points cannot meet the end
    /// conditions.
    pub fn generate(
        a: &[Vector3; 4],
        degree: usize,
        tolerance: f64,
    ) -> Result<(Self, BezierCurve<3>, Interpolation), ClassAError> {
        let t = Self::from_points(a, degree)?;
        let c = t.curve()?;
        let e = Interpolation::measure(c.points(), &a[0], &(a[1] - a[0]), &(a[3] - a[2]), &a[3])
            .within(tolerance)?;
        Ok((t, c, e))
    }

    /// All distinct converged solutions of the end conditions found by the grid + Newton search
    /// of [`TypicalSpatial::from_points`], Class A or not, sorted by decreasing Class A margin
    /// (the first is the best candidate).
    ///
    /// # Errors
    /// As [`TypicalSpatial::from_points`], except [`ClassAError::NoClassASolution`].
    pub fn candidates(a: &[Vector3; 4], degree: usize) -> Result<Vec<Self>, ClassAError> {
        let setup = Setup::new(a, degree)?;
        let (np, ns) = GRID;
        let mut grid = Vec::with_capacity(np * ns);
        for i in 0..np {
            let phi = -PHI_MAX + 2.0 * PHI_MAX * i as f64 / (np - 1) as f64;
            for j in 0..ns {
                let ls = -4.0 + 8.0 * j as f64 / (ns - 1) as f64;
                grid.push((setup.residual(phi, ls).norm(), phi, ls));
            }
        }
        grid.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut found: Vec<Self> = Vec::new();
        let mut best_res = f64::INFINITY;
        for &(_, phi, ls) in grid.iter().take(STARTS) {
            let (phi, ls, r) = newton(&setup, phi, ls);
            best_res = best_res.min(r);
            if r <= CONVERGED {
                let t = setup.finish(&a[0], phi, ls.exp())?;
                let duplicate = found
                    .iter()
                    .any(|f| (f.phi - t.phi).abs() <= 1e-9 && (f.s / t.s - 1.0).abs() <= 1e-9);
                if !duplicate {
                    found.push(t);
                }
            }
        }
        if found.is_empty() {
            return Err(ClassAError::ChordUnreachable { residual: best_res });
        }
        found.sort_by(|x, y| y.class_a_margin().total_cmp(&x.class_a_margin()));
        Ok(found)
    }

    /// The paper's method: Nelder–Mead (argmin) on (φ, s) minimizing −f of eq. (15),
    /// f = unit(Σ sʲRʲv₀) · unit(α₃ − α₀) − 1 ≤ 0, from (φ, s) = (0, 1) with a 0.1 simplex.
    /// Returns the curve and the final value of −f. Since −f ≈ angle²/2 is computed as
    /// 1 − cos, it cannot resolve chord angles below about 1.5e-8.
    ///
    /// Feature `paper`.
    ///
    /// # Errors
    /// As [`TypicalSpatial::from_points`], [`ClassAError::Optimizer`] if argmin fails.
    #[cfg(feature = "paper")]
    pub fn nelder_mead(
        a: &[Vector3; 4],
        degree: usize,
        max_iters: u64,
    ) -> Result<(Self, f64), ClassAError> {
        use argmin::core::{CostFunction, Executor, State};
        use argmin::solver::neldermead::NelderMead;
        let setup = Setup::new(a, degree)?;
        struct Cost(Setup);
        impl CostFunction for Cost {
            type Param = Vec<f64>;
            type Output = f64;
            fn cost(&self, p: &Self::Param) -> Result<f64, argmin::core::Error> {
                if p[1] <= 0.0 || p[0].abs() >= PHI_MAX {
                    return Ok(4.0);
                }
                let (_, _, sum) = self.0.sum(p[0], p[1]);
                let c = self.0.chord / self.0.chord.norm();
                let v = 1.0 - sum.dot(&c) / sum.norm();
                Ok(if v.is_finite() { v } else { 4.0 })
            }
        }
        let simplex = vec![vec![0.0, 1.0], vec![0.1, 1.0], vec![0.0, 1.1]];
        let solver = NelderMead::new(simplex)
            .with_sd_tolerance(1e-30)
            .map_err(|e| ClassAError::Optimizer {
                message: e.to_string(),
            })?;
        let res = Executor::new(Cost(setup), solver)
            .configure(|st| st.max_iters(max_iters))
            .run()
            .map_err(|e| ClassAError::Optimizer {
                message: e.to_string(),
            })?;
        let cost = res.state().get_best_cost();
        match res.state().get_best_param().map(Vec::as_slice) {
            Some([phi, s]) if *s > 0.0 => Ok((setup.finish(&a[0], *phi, *s)?, cost)),
            _ => Err(ClassAError::NoConvergence {
                method: "Nelder-Mead",
                residual: cost,
            }),
        }
    }

    /// M = s·R(u, θ) (eq. (9)).
    #[must_use]
    pub fn matrix(&self) -> Matrix3 {
        rotation(&self.axis, self.theta) * self.s
    }

    /// Margin of Farin's condition (3) for M or, when s < 1, for M⁻¹ (reversed curve):
    /// the eigenvalues of M + Mᵀ − 2I are 2s − 2 (along u) and 2s cos θ − 2, so the margin is
    /// min(s − 1, s cos θ − 1) for M and min(1/s − 1, cos θ/s − 1) for M⁻¹; the larger is returned.
    #[must_use]
    pub fn class_a_margin(&self) -> f64 {
        let c = self.theta.cos();
        let fwd = (self.s - 1.0).min(self.s * c - 1.0);
        let rev = (1.0 / self.s - 1.0).min(c / self.s - 1.0);
        fwd.max(rev)
    }

    /// The Bézier curve.
    ///
    /// # Errors
    /// [`ClassAError::Core`] if the control points overflow.
    pub fn curve(&self) -> Result<BezierCurve<3>, ClassAError> {
        class_a_curve(
            &self.b0,
            &(self.v0 * self.length),
            &self.matrix(),
            self.degree,
        )
    }
}

/// Damped Newton (Gauss–Newton with backtracking) on the residual in (φ, log s).
fn newton(setup: &Setup, mut phi: f64, mut ls: f64) -> (f64, f64, f64) {
    let mut r = setup.residual(phi, ls);
    for _ in 0..60 {
        let rn = r.norm();
        if rn <= 1e-15 || !rn.is_finite() {
            break;
        }
        let h = 1e-7;
        let jp = (setup.residual(phi + h, ls) - setup.residual(phi - h, ls)) / (2.0 * h);
        let js = (setup.residual(phi, ls + h) - setup.residual(phi, ls - h)) / (2.0 * h);
        // Normal equations of the 3×2 least-squares step.
        let (a, b, c) = (jp.dot(&jp), jp.dot(&js), js.dot(&js));
        let (g0, g1) = (jp.dot(&r), js.dot(&r));
        let det = a * c - b * b;
        if det.abs() <= 1e-300 || det.is_nan() {
            break;
        }
        let dp = -(c * g0 - b * g1) / det;
        let ds = -(a * g1 - b * g0) / det;
        let mut step = 1.0;
        let mut improved = false;
        for _ in 0..30 {
            let (np, ns) = (phi + step * dp, ls + step * ds);
            if np.abs() < PHI_MAX {
                let nr = setup.residual(np, ns);
                if nr.norm() < rn {
                    phi = np;
                    ls = ns;
                    r = nr;
                    improved = true;
                    break;
                }
            }
            step *= 0.5;
        }
        if !improved {
            break;
        }
    }
    (phi, ls, r.norm())
}
