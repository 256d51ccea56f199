//! Interactive typical spatial Class A curves from four points (eqs. (9)–(15)).

use crate::square::Matrix3;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

use bez_core::{BezierCurve, Vector3};
use num_complex::Complex;

use crate::{ClassAError, INTERPOLATION_TOLERANCE, Interpolation, class_a_curve};

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

/// What [`TypicalSpatial::solve`] must guarantee of the curve it returns (besides the end
/// conditions, which are always verified).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum SpatialRequirement {
    /// Class A: Farin's condition (3) for M or M⁻¹ ([`TypicalSpatial::class_a_margin`] ≥ 0).
    #[default]
    ClassA,
    /// Class A and torsion proven monotone on [0, 1]: by the sufficient condition
    /// [`TypicalSpatial::torsion_condition`] when it holds, otherwise by the exact
    /// [`crate::torsion_certificate`] of the curve.
    MonotoneTorsion,
}

/// Rotation by θ about the unit axis u (right-handed, Rodrigues):
/// R = I + sin θ K + (1 − cos θ)K², with K v = u × v (K the cross-product matrix of u). The printed eq. (12) is the
/// transpose of K (it rotates by −θ); we use the usual convention and test v₁ = Rⁿ⁻¹v₀.
#[must_use]
pub fn rotation(axis: &Vector3, theta: f64) -> Matrix3 {
    let k = Matrix3::cross_matrix(axis);
    Matrix3::identity() + k * theta.sin() + k * k * (1.0 - theta.cos())
}

/// Angle ψ about u from the projection of v₀ to that of v₁, in (−π, π].
fn turn_about(u: &Vector3, v0: &Vector3, v1: &Vector3) -> f64 {
    let p0 = v0 - u * u.dot(v0);
    let p1 = v1 - u * u.dot(v1);
    u.dot(&p0.cross(&p1)).atan2(p0.dot(&p1))
}

/// Below this degree, or when |1 − q| is below [`CLOSED_FORM_GAP`], the geometric sums are
/// summed term by term; otherwise in closed form (1 − qⁿ)/(1 − q).
const CLOSED_FORM_DEGREE: usize = 32;
/// See [`CLOSED_FORM_DEGREE`].
const CLOSED_FORM_GAP: f64 = 0.5;

/// (Σ_{j<n} rʲ, Σ_{j<n} (r e^{iθ})ʲ) for 0 ≤ r ≤ 1.
fn geometric_sums(r: f64, theta: f64, n: usize) -> (f64, Complex<f64>) {
    let q = Complex::from_polar(r, theta);
    let exponent = i32::try_from(n).unwrap_or(i32::MAX);
    let real = if n < CLOSED_FORM_DEGREE || 1.0 - r < CLOSED_FORM_GAP {
        (0..n).fold((0.0, 1.0), |(sum, p), _| (sum + p, p * r)).0
    } else {
        (1.0 - r.powi(exponent)) / (1.0 - r)
    };
    let one = Complex::new(1.0, 0.0);
    let complex = if n < CLOSED_FORM_DEGREE || (one - q).norm() < CLOSED_FORM_GAP {
        let mut sum = Complex::new(0.0, 0.0);
        let mut p = one;
        for _ in 0..n {
            sum += p;
            p *= q;
        }
        sum
    } else {
        let qn = Complex::from_polar(r.powi(exponent), theta * n as f64);
        (one - qn) / (one - q)
    };
    (real, complex)
}

/// The validated input of the spatial problem.
#[derive(Debug, Clone, Copy)]
struct Setup {
    v0: Vector3,
    v1: Vector3,
    chord: Vector3,
    /// ĉ = chord / |chord|.
    unit_chord: Vector3,
    /// (v₀×v₁)/|v₀×v₁| and (v₀+v₁)/|v₀+v₁|, the axis basis of eq. (14).
    normal: Vector3,
    bisector: Vector3,
    n: usize,
}

/// One rotation R(u, θ) with Rⁿ⁻¹v₀ = v₁: the axis u(φ) of eq. (14) and branch k of
/// θ = (ψ(φ) + 2πk)/(n − 1).
#[derive(Debug, Clone, Copy)]
struct Branch {
    axis: Vector3,
    theta: f64,
}

/// The parts of a grid row at φ shared by every branch: a = u·v₀ and the frame components of
/// u, p = v₀ − a u and q = u × p ([`Setup::row_conditions`]), the turn ψ(φ) ∈ (0, 2π) and
/// e^{iψ} (= e^{i(n−1)θ} on every branch).
#[derive(Debug, Clone, Copy)]
struct RowBase {
    a: f64,
    fu: [f64; 3],
    fp: [f64; 3],
    fq: [f64; 3],
    psi: f64,
    turn: Complex<f64>,
}

/// The columns log s of the Newton-start grid, one entry per column, with the quantities every
/// row shares: r = e^{−|log s|}, rⁿ, Σ_{j<n} rʲ and the sign ± of the ratio q = r e^{±iθ}
/// (+ for log s ≤ 0). Stored by quantity, so that a row's loops run over plain arrays.
#[derive(Debug, Clone, Copy)]
struct Columns {
    log_s: [f64; GRID.1],
    r: [f64; GRID.1],
    r_n: [f64; GRID.1],
    real: [f64; GRID.1],
    sign: [f64; GRID.1],
}

impl Columns {
    fn new(log_s: [f64; GRID.1], n: usize) -> Self {
        let r = log_s.map(|l| (-l.abs()).exp());
        let exponent = i32::try_from(n).unwrap_or(i32::MAX);
        Self {
            log_s,
            r,
            r_n: r.map(|r| r.powi(exponent)),
            real: r.map(|r| (0..n).fold((0.0, 1.0), |(sum, p), _| (sum + p, p * r)).0),
            sign: log_s.map(|l| if l <= 0.0 { 1.0 } else { -1.0 }),
        }
    }
}

/// The branch-independent parts of the Newton-start grid of one solve: the rows' [`RowBase`]
/// at φᵢ = −π/2 + πi/36 (i = 0..=36) and the columns log s over [−σ, σ],
/// σ = min(4, 10/(n − 1)) ([`LOG_RATIO_SPAN`]).
#[derive(Debug, Clone, Copy)]
struct StartGrid {
    span: f64,
    columns: Columns,
    bases: [RowBase; GRID.0 + 1],
}

impl StartGrid {
    fn new(setup: &Setup) -> Self {
        let (np, ns) = GRID;
        let span = (LOG_RATIO_SPAN / (setup.n - 1) as f64).min(4.0);
        let frame = setup.chord_frame();
        Self {
            span,
            columns: Columns::new(
                std::array::from_fn(|j| -span + 2.0 * span * j as f64 / (ns - 1) as f64),
                setup.n,
            ),
            bases: std::array::from_fn(|i| {
                setup.row_base(-FRAC_PI_2 + PI * i as f64 / np as f64, &frame)
            }),
        }
    }
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
        let (c, b) = (v0.cross(&v1), v0 + v1);
        Ok(Self {
            v0,
            v1,
            chord,
            unit_chord: chord / chord.norm(),
            normal: c / c.norm(),
            bisector: b / b.norm(),
            n: degree,
        })
    }

    /// The rotation of branch k at φ ∈ ℝ. The turn ψ(φ) about u(φ) is taken in (0, 2π): it
    /// never reaches 0 (v₀ ≠ v₁), so it is continuous in φ, ψ(φ + π) = 2π − ψ(φ) with
    /// u(φ + π) = −u(φ), and (φ + π, k) is the rotation (φ, −1 − k).
    fn branch(&self, phi: f64, k: i64) -> Branch {
        // Eq. (14), corrected: u = (v₀×v₁)/|v₀×v₁| cos φ + (v₀+v₁)/|v₀+v₁| sin φ.
        let axis = self.normal * phi.cos() + self.bisector * phi.sin();
        let psi = turn_about(&axis, &self.v0, &self.v1).rem_euclid(TAU);
        Branch {
            axis,
            theta: (psi + TAU * k as f64) / (self.n - 1) as f64,
        }
    }

    /// Σ_{j<n} sʲRʲv₀ / max(1, s)ⁿ⁻¹ (the direction of the chord, without overflow), with
    /// Rʲv₀ = a u + cos(jθ) p + sin(jθ) u × p for a = u·v₀, p = v₀ − a u.
    fn scaled_sum(&self, b: &Branch, log_s: f64) -> Vector3 {
        let u = b.axis;
        let a = u.dot(&self.v0);
        let p = self.v0 - u * a;
        let q = u.cross(&p);
        let (real, complex) = if log_s <= 0.0 {
            geometric_sums(log_s.exp(), b.theta, self.n)
        } else {
            // sⁿ⁻¹ e^{i(n−1)θ} Σ (s⁻¹e^{−iθ})ᵐ, divided by sⁿ⁻¹.
            let (real, c) = geometric_sums((-log_s).exp(), -b.theta, self.n);
            let turn = Complex::from_polar(1.0, b.theta * (self.n - 1) as f64);
            (real, c * turn)
        };
        u * (a * real) + p * complex.re + q * complex.im
    }

    /// Residual: unit(Σ) − unit(chord), a 3-vector (2 independent components).
    fn residual(&self, phi: f64, log_s: f64, k: i64) -> Vector3 {
        let sum = self.scaled_sum(&self.branch(phi, k), log_s);
        let c = self.unit_chord;
        let n = sum.norm();
        if n.is_finite() && n > 0.0 {
            sum / n - c
        } else {
            Vector3::repeat(f64::INFINITY)
        }
    }

    /// The residual r = unit(Σ) − ĉ of [`Setup::residual`] and its partial derivatives
    /// (∂r/∂φ, ∂r/∂log s) in closed form, for Newton's steps.
    ///
    /// With Σ = a·R·u + Re(C)·p + Im(C)·q (a = u·v₀, p = v₀ − a u, q = u × v₀,
    /// R = Σ_j e^{(j−J)λ}, C = Σ_j e^{(j−J)λ} e^{ijθ}, λ = log s, J = 0 for λ ≤ 0 and n − 1
    /// above, the scaling of [`Setup::scaled_sum`]):
    ///
    /// * ∂R/∂λ = Σ (j − J) e^{(j−J)λ} =: R', ∂C/∂λ = Σ (j − J) e^{(j−J)λ} e^{ijθ} =: C' and
    ///   ∂C/∂θ = i(C' + J C);
    /// * u(φ) = N cos φ + B sin φ (eq. (14)), u' = −N sin φ + B cos φ; since u·v₀ = u·v₁ = a, the
    ///   turn is ψ = atan2(u·(v₀ × v₁), v₀·v₁ − a²), so ψ' = (x y' − y x')/(x² + y²) with
    ///   y = u·(v₀ × v₁), x = v₀·v₁ − a², y' = u'·(v₀ × v₁), x' = −2a a', a' = u'·v₀, and
    ///   θ' = ψ'/(n − 1); p' = −a'u − a u', q' = u' × v₀;
    /// * the unit vector's derivative is (I − ûûᵀ) Σ' / |Σ| (û = Σ/|Σ|), so the scale factor
    ///   e^{−Jλ} of Σ drops out.
    ///
    /// Tested against central differences of an explicit rotation-matrix sum.
    fn residual_jacobian(&self, phi: f64, log_s: f64, k: i64) -> (Vector3, Vector3, Vector3) {
        let b = self.branch(phi, k);
        let n = self.n;
        let u = b.axis;
        let (sin_phi, cos_phi) = phi.sin_cos();
        let du = self.bisector * cos_phi - self.normal * sin_phi;
        let a = u.dot(&self.v0);
        let da = du.dot(&self.v0);
        let p = self.v0 - u * a;
        let q = u.cross(&self.v0);
        let w = self.v0.cross(&self.v1);
        let (y, x) = (u.dot(&w), self.v0.dot(&self.v1) - a * a);
        let (dy, dx) = (du.dot(&w), -2.0 * a * da);
        let dtheta = (x * dy - y * dx) / (x * x + y * y) / (n - 1) as f64;
        let dp = -(u * da + du * a);
        let dq = du.cross(&self.v0);
        // Term by term from the largest term 1 (j = J) down: e^{−m|λ|} e^{±imθ}, m = |j − J|.
        let (r, sign) = if log_s <= 0.0 {
            ((log_s).exp(), 1.0)
        } else {
            ((-log_s).exp(), -1.0)
        };
        let ratio = Complex::from_polar(r, sign * b.theta);
        let (mut real, mut dreal) = (0.0, 0.0);
        let (mut c, mut dc) = (Complex::new(0.0, 0.0), Complex::new(0.0, 0.0));
        let (mut power, mut real_power) = (Complex::new(1.0, 0.0), 1.0);
        for m in 0..n {
            let mf = m as f64;
            real += real_power;
            dreal += mf * real_power;
            c += power;
            dc += power * mf;
            real_power *= r;
            power *= ratio;
        }
        let big_j = if log_s <= 0.0 {
            0.0
        } else {
            // j − J = −m and e^{ijθ} = e^{i(n−1)θ} e^{−imθ}.
            let turn = Complex::from_polar(1.0, b.theta * (n - 1) as f64);
            c *= turn;
            dc *= -turn;
            dreal = -dreal;
            (n - 1) as f64
        };
        let dc_theta = Complex::new(0.0, 1.0) * (dc + c * big_j);
        let sum = u * (a * real) + p * c.re + q * c.im;
        let d_ls = u * (a * dreal) + p * dc.re + q * dc.im;
        let d_phi = u * (da * real)
            + du * (a * real)
            + dp * c.re
            + dq * c.im
            + (p * dc_theta.re + q * dc_theta.im) * dtheta;
        let norm = sum.norm();
        if !(norm.is_finite() && norm > 0.0) {
            let bad = Vector3::repeat(f64::INFINITY);
            return (bad, bad, bad);
        }
        let unit = sum / norm;
        let project = |d: Vector3| (d - unit * unit.dot(&d)) / norm;
        (unit - self.unit_chord, project(d_phi), project(d_ls))
    }

    /// The parts of a grid row at φ that every branch k shares ([`RowBase`]); ψ(φ) exactly as
    /// in [`Setup::branch`].
    fn row_base(&self, phi: f64, frame: &[Vector3; 3]) -> RowBase {
        let u = self.normal * phi.cos() + self.bisector * phi.sin();
        let a = u.dot(&self.v0);
        let p = self.v0 - u * a;
        let q = u.cross(&p);
        let p1 = self.v1 - u * u.dot(&self.v1);
        let (y, x) = (u.dot(&p.cross(&p1)), p.dot(&p1));
        let along = |v: &Vector3| [v.dot(&frame[0]), v.dot(&frame[1]), v.dot(&frame[2])];
        let h = x.hypot(y);
        RowBase {
            a,
            fu: along(&u),
            fp: along(&p),
            fq: along(&q),
            psi: y.atan2(x).rem_euclid(TAU),
            turn: if h > 0.0 {
                Complex::new(x / h, y / h)
            } else {
                Complex::new(1.0, 0.0)
            },
        }
    }

    /// The frame components of Σ along one grid row (fixed φ and branch angle θ), for every
    /// grid column, each up to a positive factor of its own: (Σ·e₁, Σ·e₂, Σ·ĉ) for an
    /// orthonormal frame (e₁, e₂, ĉ) with ĉ the chord direction (Σ divided by max(1, s)ⁿ⁻¹, as in
    /// [`Setup::scaled_sum`]). Smooth in (φ, log s); Σ ∥ chord with the same sense iff the first
    /// two vanish and the third is positive, and the factor changes neither the signs nor the
    /// direction. From degree [`ROW_CLOSED_FORM_DEGREE`] the sums Σ (r e^{±iθ})ʲ are
    /// (1 − qⁿ)/(1 − q), multiplied by |1 − q|² so that no division is needed (the factor); below,
    /// or next to q = 1, the columns' sums advance together term by term in the order of
    /// [`geometric_sums`]. e^{i(n−1)θ} = e^{iψ} (θ = (ψ + 2πk)/(n − 1)) comes from the row and
    /// e^{inθ} = e^{iψ}e^{iθ}: one sine and cosine per row and branch.
    fn row_conditions(
        &self,
        base: &RowBase,
        theta: f64,
        columns: &Columns,
        out: &mut [[f64; GRID.1]; 3],
    ) {
        let (sin, cos) = theta.sin_cos();
        let turn = base.turn;
        // q = r e^{±iθ} per column, and the factor e^{i(n−1)θ} of the columns with log s > 0
        // (1 elsewhere, which multiplies exactly).
        let q_re: [f64; GRID.1] = std::array::from_fn(|j| columns.r[j] * cos);
        let q_im: [f64; GRID.1] = std::array::from_fn(|j| columns.r[j] * (columns.sign[j] * sin));
        let t_re = columns.log_s.map(|l| if l > 0.0 { turn.re } else { 1.0 });
        let t_im = columns.log_s.map(|l| if l > 0.0 { turn.im } else { 0.0 });
        let mut s_re = [0.0; GRID.1];
        let mut s_im = [0.0; GRID.1];
        let mut factor = [1.0; GRID.1];
        if self.n >= ROW_CLOSED_FORM_DEGREE {
            // (1 − qⁿ)·conj(1 − q) with qⁿ = rⁿ e^{±inθ}; cells too close to q = 1 term by term.
            let full = turn * Complex::new(cos, sin);
            let (sin_n, cos_n) = (full.im, full.re);
            for j in 0..GRID.1 {
                let (g_re, g_im) = (1.0 - q_re[j], 0.0 - q_im[j]);
                let (a_re, a_im) = (
                    1.0 - columns.r_n[j] * cos_n,
                    0.0 - columns.r_n[j] * (columns.sign[j] * sin_n),
                );
                // (a_re + i a_im)(g_re − i g_im)
                s_re[j] = a_re * g_re + a_im * g_im;
                s_im[j] = a_im * g_re - a_re * g_im;
                factor[j] = g_re * g_re + g_im * g_im;
            }
            for j in 0..GRID.1 {
                if factor[j] < ROW_CLOSED_FORM_GAP * ROW_CLOSED_FORM_GAP {
                    let ratio = Complex::new(q_re[j], q_im[j]);
                    let (mut sum, mut power) = (Complex::new(0.0, 0.0), Complex::new(1.0, 0.0));
                    for _ in 0..self.n {
                        sum += power;
                        power *= ratio;
                    }
                    (s_re[j], s_im[j], factor[j]) = (sum.re, sum.im, 1.0);
                }
            }
        } else {
            let (mut p_re, mut p_im) = ([1.0; GRID.1], [0.0; GRID.1]);
            for _ in 0..self.n {
                for j in 0..GRID.1 {
                    s_re[j] += p_re[j];
                    s_im[j] += p_im[j];
                    (p_re[j], p_im[j]) = (
                        p_re[j] * q_re[j] - p_im[j] * q_im[j],
                        p_re[j] * q_im[j] + p_im[j] * q_re[j],
                    );
                }
            }
        }
        let re: [f64; GRID.1] = std::array::from_fn(|j| s_re[j] * t_re[j] - s_im[j] * t_im[j]);
        let im: [f64; GRID.1] = std::array::from_fn(|j| s_re[j] * t_im[j] + s_im[j] * t_re[j]);
        let axial: [f64; GRID.1] = std::array::from_fn(|j| base.a * columns.real[j] * factor[j]);
        for (m, out) in out.iter_mut().enumerate() {
            for j in 0..GRID.1 {
                out[j] = axial[j] * base.fu[m] + re[j] * base.fp[m] + im[j] * base.fq[m];
            }
        }
    }

    /// An orthonormal frame (e₁, e₂, ĉ) with ĉ the unit chord.
    fn chord_frame(&self) -> [Vector3; 3] {
        let c = self.unit_chord;
        let helper = if c.x().abs() < 0.6 {
            Vector3::new(1.0, 0.0, 0.0)
        } else {
            Vector3::new(0.0, 1.0, 0.0)
        };
        let e1 = c.cross(&helper);
        let e1 = e1 / e1.norm();
        [e1, c.cross(&e1), c]
    }

    /// The curve of (φ, log s) on branch k, with φ moved into [−π/2, π/2) (u and θ flip sign
    /// with each shift by π) and L = |α₃ − α₀| / |Σ sʲRʲv₀|.
    fn finish(
        &self,
        a0: &Vector3,
        phi: f64,
        log_s: f64,
        k: i64,
    ) -> Result<TypicalSpatial, ClassAError> {
        let b = self.branch(phi, k);
        let sum = self.scaled_sum(&b, log_s);
        let scale = (log_s.max(0.0) * (self.n - 1) as f64).exp();
        let length = self.chord.norm() / sum.norm() / scale;
        let s = log_s.exp();
        if !(length.is_finite() && length > 0.0 && s.is_finite() && s > 0.0) {
            return Err(ClassAError::NonFinite { name: "length" });
        }
        let shifts = ((phi + FRAC_PI_2) / PI).floor();
        let (phi, sign) = (
            phi - shifts * PI,
            if shifts % 2.0 == 0.0 { 1.0 } else { -1.0 },
        );
        Ok(TypicalSpatial {
            b0: *a0,
            v0: self.v0,
            length,
            s,
            phi,
            axis: b.axis * sign,
            theta: b.theta * sign,
            degree: self.n,
        })
    }

    /// The branches k whose θ can lie in (−π/2, π/2) for φ ∈ [−π/2, π/2) (where ψ ∈ (0, π]):
    /// the only ones that can be Class A (the margin needs cos θ > 0).
    fn branches(&self) -> std::ops::RangeInclusive<i64> {
        let quarter = (self.n - 1) as f64 / 4.0;
        let lo = (-quarter - 0.5).floor() as i64;
        let hi = quarter.ceil() as i64;
        lo..=hi
    }
}

/// From this degree on, the grid rows sum Σ (r e^{±iθ})ʲ in closed form (1 − qⁿ)/(1 − q) (one
/// complex division per node instead of n steps), except where |1 − q| is below
/// [`ROW_CLOSED_FORM_GAP`]. The grid only places Newton starts, which converge to the same
/// solutions; the rounding of the closed form (relative ε/|1 − q|) moves a node's sign only where
/// a condition is within that of zero.
const ROW_CLOSED_FORM_DEGREE: usize = 4;
/// See [`ROW_CLOSED_FORM_DEGREE`].
const ROW_CLOSED_FORM_GAP: f64 = 0.05;

/// Grid over (φ, log s) per branch for the Newton starts.
const GRID: (usize, usize) = (36, 20);
/// Local minima of the direction error start Newton only below this error.
const MINIMUM_START: f64 = 0.3;
/// At most this many local minima per branch start Newton.
const MINIMUM_STARTS: usize = 4;
/// A Newton run has converged when the chord-direction residual is at most this.
const CONVERGED: f64 = 1e-12;
/// The grid spans (n − 1)|log s| ≤ this (last leg / first leg within e^±10), and |log s| ≤ 4.
const LOG_RATIO_SPAN: f64 = 10.0;

impl TypicalSpatial {
    /// Solves the typical spatial curve through α₀, α₃ with end tangents along α₁ − α₀ and
    /// α₃ − α₂ (eqs. (13)–(15)) and returns the least-turning Class A solution: among the
    /// converged solutions with Class A margin ([`TypicalSpatial::class_a_margin`]) ≥ 0 the one
    /// with the smallest |θ| (then the largest margin), verified as in [`TypicalSpatial::solve`].
    ///
    /// Every total turn is solved: the rotations with Rⁿ⁻¹v₀ = v₁ are R(u(φ), θ) with the axis
    /// u(φ) of eq. (14) and θ = (ψ(φ) + 2πk)/(n − 1) for every branch k, not only ψ ∈ (−π, π]
    /// (a curve of degree n can turn its tangent by up to (n − 1)θ). Method
    /// ([`TypicalSpatial::candidates`]): on each branch that can be Class A (|θ| < π/2), a
    /// 36 × 20 grid over (φ, log s) ∈ [−π/2, π/2) × [−σ, σ], σ = min(4, 10/(n − 1)), of the two
    /// components of Σ sʲRʲv₀ normal to the chord; damped Newton (Jacobian in closed form,
    /// least squares on the 3-vector direction residual) starts in every cell where both
    /// components change sign, and at the four best local minima of the direction error. L is
    /// |α₃ − α₀| / |Σ| (eq. (15) fixes only the direction).
    ///
    /// Guarantees: every returned curve meets the end conditions to the direction residual
    /// 1e-12 and is Class A (Farin's condition (3) for M, or for M⁻¹ when s < 1). Not
    /// guaranteed: that every solution is found. On 6,000 seeded random typical curves of degree
    /// 3..20 (about 70 % turning by more than π) 0–0.1 % of the Class A generators and 0.15–0.2 %
    /// of the others were missed, depending on the seeds (a zero curve of the two components
    /// folding back inside a grid cell). So [`ClassAError::NoClassASolution`] means no *found*
    /// solution is Class A.
    ///
    /// # Errors
    /// [`ClassAError::DegreeTooLow`], [`ClassAError::NonFinite`], [`ClassAError::CoincidentPoints`],
    /// [`ClassAError::ParallelTangents`], [`ClassAError::ChordUnreachable`] (no start converged;
    /// e.g. a chord pointing back against both tangents), [`ClassAError::NoClassASolution`] (every
    /// converged solution has a negative Class A margin; [`TypicalSpatial::candidates`] still
    /// returns them).
    pub fn from_points(a: &[Vector3; 4], degree: usize) -> Result<Self, ClassAError> {
        Self::solve(a, degree, SpatialRequirement::ClassA)
    }

    /// [`TypicalSpatial::from_points`] with a requirement on the returned curve: the first
    /// candidate (by increasing |θ|, then decreasing margin) that is Class A, meets the requirement, and whose
    /// rounded control points have non-zero end legs and meet the end conditions to
    /// [`INTERPOLATION_TOLERANCE`] ([`Interpolation`]).
    ///
    /// ```
    /// use bez_core::Vector3;
    /// use class_a::{SpatialRequirement, TypicalSpatial};
    /// let a = [
    ///     Vector3::new(0.0, 0.0, 0.0),
    ///     Vector3::new(1.0, 0.0, 0.2),
    ///     Vector3::new(6.21, 6.54, 1.79),
    ///     Vector3::new(6.12, 9.44, 2.73),
    /// ];
    /// let t = TypicalSpatial::solve(&a, 7, SpatialRequirement::MonotoneTorsion)?;
    /// assert!(class_a::torsion_certificate(&t.curve()?)?.is_monotone());
    /// # Ok::<(), class_a::ClassAError>(())
    /// ```
    ///
    /// # Errors
    /// As [`TypicalSpatial::from_points`]; [`ClassAError::NoMonotoneTorsion`] when no Class A
    /// candidate has proven monotone torsion; [`ClassAError::ToleranceNotMet`] (the best
    /// candidate's worst condition) when no qualifying candidate's control points meet the end
    /// conditions, e.g. a last leg L·sⁿ⁻¹ below the rounding of α₃ (a zero leg has no
    /// direction and counts as a tangent error of π).
    pub fn solve(
        a: &[Vector3; 4],
        degree: usize,
        requirement: SpatialRequirement,
    ) -> Result<Self, ClassAError> {
        let setup = Setup::new(a, degree)?;
        let (lo, hi) = (*setup.branches().start(), *setup.branches().end());
        let mut all: Vec<Self> = Vec::new();
        let mut best_res = f64::INFINITY;
        // Branches k and −1 − k turn by |θ| ∈ (mτ, (m + 1)τ), τ = 2π/(n − 1), m = max(k, −1 − k):
        // searched by increasing m, the least-turning qualifying candidate is final as soon as
        // its |θ| ≤ (m + 1)τ (every later branch turns more). −1 − m before m, as in the full
        // search, so a rotation found on both is kept in the same representation.
        let step = TAU / (degree - 1) as f64;
        let grid = StartGrid::new(&setup);
        for m in 0i64.. {
            let group: Vec<i64> = [-1 - m, m]
                .into_iter()
                .filter(|k| (lo..=hi).contains(k))
                .collect();
            if group.is_empty() {
                break;
            }
            Self::search(&setup, &grid, &a[0], &group, &mut all, &mut best_res)?;
            let bound = step * (m + 1) as f64;
            if let (Some(t), _) = Self::select(a, &all, requirement)
                && t.theta.abs() <= bound
            {
                return Ok(t);
            }
        }
        all.sort_by(|x, y| y.class_a_margin().total_cmp(&x.class_a_margin()));
        let Some(best) = all.first() else {
            return Err(ClassAError::ChordUnreachable { residual: best_res });
        };
        let class_a = all.iter().filter(|t| t.class_a_margin() >= 0.0).count();
        if class_a == 0 {
            return Err(ClassAError::NoClassASolution {
                converged: all.len(),
                best_margin: best.class_a_margin(),
                s: best.s,
                theta: best.theta,
            });
        }
        match Self::select(a, &all, requirement) {
            (Some(t), _) => Ok(t),
            (None, Some(e)) => Err(e),
            (None, None) => Err(ClassAError::NoMonotoneTorsion { class_a }),
        }
    }

    /// The first of the Class A candidates (by increasing |θ|, then decreasing margin) that
    /// meets the requirement and whose control points pass [`Interpolation`] at
    /// [`INTERPOLATION_TOLERANCE`]; else the first interpolation error of a candidate that met
    /// the requirement, if any.
    fn select(
        a: &[Vector3; 4],
        all: &[Self],
        requirement: SpatialRequirement,
    ) -> (Option<Self>, Option<ClassAError>) {
        let mut class_a: Vec<&Self> = all.iter().filter(|t| t.class_a_margin() >= 0.0).collect();
        class_a.sort_by(|x, y| {
            x.theta
                .abs()
                .total_cmp(&y.theta.abs())
                .then(y.class_a_margin().total_cmp(&x.class_a_margin()))
        });
        let mut first_error = None;
        for t in class_a {
            let Ok(curve) = t.curve() else {
                continue;
            };
            if requirement == SpatialRequirement::MonotoneTorsion
                && !t.torsion_condition()
                && !crate::torsion_certificate(&curve).is_ok_and(|c| c.is_monotone())
            {
                continue;
            }
            match Interpolation::measure(
                curve.points(),
                &a[0],
                &(a[1] - a[0]),
                &(a[3] - a[2]),
                &a[3],
            )
            .within(INTERPOLATION_TOLERANCE)
            {
                Ok(_) => return (Some(*t), None),
                Err(e) => {
                    first_error.get_or_insert(e);
                }
            }
        }
        (None, first_error)
    }

    /// The least-turning Class A candidate, without the interpolation check (which
    /// [`TypicalSpatial::generate`] makes with the caller's tolerance).
    fn unverified(a: &[Vector3; 4], degree: usize) -> Result<Self, ClassAError> {
        let all = Self::candidates(a, degree)?;
        let least_turning = all
            .iter()
            .filter(|t| t.class_a_margin() >= 0.0)
            .min_by(|x, y| x.theta.abs().total_cmp(&y.theta.abs()));
        if let Some(t) = least_turning {
            return Ok(*t);
        }
        match all.first() {
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

    /// The solution for moved points α₀..α₃ continued from `self` (an interactive drag): damped
    /// Newton from `self`'s (φ, log s) on its branch k, without the grid; if it does not converge
    /// to a Class A curve that passes the checks of [`TypicalSpatial::solve`], the full
    /// [`TypicalSpatial::from_points`] is run. Following the branch keeps the curve continuous
    /// during a drag (it need not be the least-turning solution `from_points` would pick).
    /// Public through [`TypicalSpatial::edit`], which adds the curve, its certificate and slope.
    pub(crate) fn update(&self, a: &[Vector3; 4]) -> Result<Self, ClassAError> {
        let setup = Setup::new(a, self.degree)?;
        let psi = setup.branch(self.phi, 0).theta * (self.degree - 1) as f64;
        let turns = ((self.theta * (self.degree - 1) as f64 - psi) / TAU).round();
        let (phi, ls, r) = newton(&setup, self.phi, self.s.ln(), turns as i64);
        if r <= CONVERGED {
            let t = setup.finish(&a[0], phi, ls, turns as i64)?;
            if t.class_a_margin() >= 0.0 {
                let curve = t.curve()?;
                let met = Interpolation::measure(
                    curve.points(),
                    &a[0],
                    &(a[1] - a[0]),
                    &(a[3] - a[2]),
                    &a[3],
                )
                .within(INTERPOLATION_TOLERANCE);
                if met.is_ok() {
                    return Ok(t);
                }
            }
        }
        Self::from_points(a, self.degree)
    }

    /// The sufficient condition for monotone torsion, cos θ ≥ (1 + σ)/(2σ) with σ = max(s, 1/s)
    /// (tested against the exact [`crate::torsion_certificate`] on thousands of random typical
    /// curves of degree 3..10 with s ∈ [0.3, 3], no exception; about 60 % of the curves that
    /// violate it have an interior torsion extremum, the nearest 0.004 from the bound). It
    /// implies the Class A margin is ≥ 0 (σ cos θ ≥ (1 + σ)/2 ≥ 1).
    #[must_use]
    pub fn torsion_condition(&self) -> bool {
        let sigma = self.s.max(1.0 / self.s);
        self.theta.cos() >= (1.0 + sigma) / (2.0 * sigma)
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
        let t = Self::unverified(a, degree)?;
        let c = t.curve()?;
        let e = Interpolation::measure(c.points(), &a[0], &(a[1] - a[0]), &(a[3] - a[2]), &a[3])
            .within(tolerance)?;
        Ok((t, c, e))
    }

    /// All distinct converged solutions of the end conditions found by the grid + Newton search
    /// of [`TypicalSpatial::from_points`], Class A or not, sorted by decreasing Class A margin
    /// (the first is the best candidate). The search covers the branches where |θ| < π/2 is
    /// possible (the only ones that can be Class A: the margin needs cos θ > 0); Newton may
    /// still converge to a solution beyond. `phi` is reported in [−π/2, π/2) (u and θ change
    /// sign together when it is moved by π).
    ///
    /// # Errors
    /// As [`TypicalSpatial::from_points`], except [`ClassAError::NoClassASolution`].
    pub fn candidates(a: &[Vector3; 4], degree: usize) -> Result<Vec<Self>, ClassAError> {
        let setup = Setup::new(a, degree)?;
        let mut found: Vec<Self> = Vec::new();
        let mut best_res = f64::INFINITY;
        let all: Vec<i64> = setup.branches().collect();
        Self::search(
            &setup,
            &StartGrid::new(&setup),
            &a[0],
            &all,
            &mut found,
            &mut best_res,
        )?;
        if found.is_empty() {
            return Err(ClassAError::ChordUnreachable { residual: best_res });
        }
        found.sort_by(|x, y| y.class_a_margin().total_cmp(&x.class_a_margin()));
        Ok(found)
    }

    /// The grid and Newton search of [`TypicalSpatial::candidates`] on the branches `ks`,
    /// adding distinct converged solutions to `found` and the smallest residual to `best_res`.
    fn search(
        setup: &Setup,
        grid: &StartGrid,
        a0: &Vector3,
        ks: &[i64],
        found: &mut Vec<Self>,
        best_res: &mut f64,
    ) -> Result<(), ClassAError> {
        let degree = setup.n;
        let (np, ns) = GRID;
        // Corner values of the two conditions on a (φ, log s) grid closed over the period
        // (φ = π/2 is φ = −π/2 of the same branch continued); a cell where both change sign
        // holds a crossing of their zero curves, and Newton starts at its centre. Only each
        // node's sign bits and start error are kept.
        let mut errors = [2.0; (GRID.0 + 1) * GRID.1];
        let mut signs = [[0u32; 4]; GRID.0 + 1];
        let mut row = [[0.0; GRID.1]; 3];
        for &k in ks {
            let thetas: [f64; GRID.0 + 1] =
                std::array::from_fn(|i| (grid.bases[i].psi + TAU * k as f64) / (degree - 1) as f64);
            let near = |i: usize| {
                (i.saturating_sub(1)..=(i + 1).min(np)).any(|x| thetas[x].abs() < FRAC_PI_2)
            };
            if !(0..=np).any(near) {
                continue;
            }
            for ((i, base), signs) in grid.bases.iter().enumerate().zip(&mut signs) {
                let errors = &mut errors[i * ns..(i + 1) * ns];
                if near(i) {
                    setup.row_conditions(base, thetas[i], &grid.columns, &mut row);
                    for (j, e) in errors.iter_mut().enumerate() {
                        *e = start_error(&[row[0][j], row[1][j], row[2][j]]);
                    }
                    *signs = sign_masks(&row);
                } else {
                    // Not evaluated: no signs, no start.
                    errors.fill(2.0);
                    *signs = [0; 4];
                }
            }
            let mut starts: Vec<(f64, f64)> = Vec::new();
            for i in 0..np {
                if thetas[i].abs() >= FRAC_PI_2 && thetas[i + 1].abs() >= FRAC_PI_2 {
                    continue;
                }
                let mut cells = sign_change_cells(&signs[i], &signs[i + 1]);
                while cells != 0 {
                    let j = cells.trailing_zeros();
                    starts.push((i as f64 + 0.5, f64::from(j) + 0.5));
                    cells &= cells - 1;
                }
            }
            // Crossings thinner than a cell (a zero curve folding back inside it) show as
            // local minima of the direction error instead.
            starts.extend(
                local_minima(&errors, np, ns, &thetas)
                    .into_iter()
                    .map(|(i, j)| (i as f64, j as f64)),
            );
            let (dphi, dls) = (PI / np as f64, 2.0 * grid.span / (ns - 1) as f64);
            let mut converged: Vec<(f64, f64)> = Vec::new();
            for (i, j) in starts {
                let phi = -FRAC_PI_2 + dphi * i;
                let ls = -grid.span + dls * j;
                // A start within half a cell of a solution of this branch finds it again.
                if converged
                    .iter()
                    .any(|&(p, l)| (p - phi).abs() < 0.5 * dphi && (l - ls).abs() < 0.5 * dls)
                {
                    continue;
                }
                let (phi, ls, r) = newton(setup, phi, ls, k);
                *best_res = best_res.min(r);
                if r <= CONVERGED {
                    converged.push((phi, ls));
                    let t = setup.finish(a0, phi, ls, k)?;
                    let duplicate = found.iter().any(|f| {
                        (f.axis * f.theta - t.axis * t.theta).norm() <= 1e-9
                            && (f.s / t.s - 1.0).abs() <= 1e-9
                    });
                    if !duplicate {
                        found.push(t);
                    }
                }
            }
        }
        Ok(())
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
        /// The paper's φ range: |φ| < π/2 (φ = ±π/2 makes ψ = π).
        const PHI_MAX: f64 = 1.5607963267948966;
        let setup = Setup::new(a, degree)?;
        struct Cost(Setup);
        impl CostFunction for Cost {
            type Param = Vec<f64>;
            type Output = f64;
            fn cost(&self, p: &Self::Param) -> Result<f64, argmin::core::Error> {
                if p[1] <= 0.0 || p[0].abs() >= PHI_MAX {
                    return Ok(4.0);
                }
                let sum = self.0.scaled_sum(&self.0.branch(p[0], 0), p[1].ln());
                let c = self.0.unit_chord;
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
            Some([phi, s]) if *s > 0.0 => Ok((setup.finish(&a[0], *phi, s.ln(), 0)?, cost)),
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

/// Direction error |unit(Σ) − ĉ| from the frame components of Σ.
fn direction_error(c: &[f64; 3]) -> f64 {
    let norm = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    if norm > 0.0 && norm.is_finite() {
        ((c[0] * c[0] + c[1] * c[1] + (c[2] - norm) * (c[2] - norm)).sqrt() / norm).min(2.0)
    } else {
        2.0
    }
}

/// The signs of the two conditions along a grid row, as bit masks over the columns j: bit j of
/// mask 2m is set where component m is ≤ 0, of mask 2m + 1 where it is ≥ 0 (m = 0, 1; a zero
/// sets both, NaN neither).
fn sign_masks(row: &[[f64; GRID.1]; 3]) -> [u32; 4] {
    let mut masks = [0u32; 4];
    for (m, component) in row[..2].iter().enumerate() {
        for (j, &c) in component.iter().enumerate() {
            masks[2 * m] |= u32::from(c <= 0.0) << j;
            masks[2 * m + 1] |= u32::from(c >= 0.0) << j;
        }
    }
    masks
}

/// The cells between two adjacent rows (their [`sign_masks`]) where both components change
/// sign, as a bit mask over j < [`GRID`].1 − 1 (the cell of columns j, j + 1): the union of the
/// four corners' signs holds ≤ 0 and ≥ 0 of each component.
fn sign_change_cells(lower: &[u32; 4], upper: &[u32; 4]) -> u32 {
    let mut cells = (1u32 << (GRID.1 - 1)) - 1;
    for (l, u) in lower.iter().zip(upper) {
        let both = l | u;
        cells &= both | (both >> 1);
    }
    cells
}

/// [`direction_error`] where it can be at most [`MINIMUM_START`], else 2 (no local minimum
/// there, and larger than every error that can be one, so the comparisons of
/// [`local_minima`] come out as with the exact errors). The test needs no square root: an error
/// e ≤ 0.3 has cos ∠(Σ, ĉ) = 1 − e²/2 ≥ 0.955, so a node with Σ·ĉ ≤ 0 or
/// (Σ·ĉ)² < 0.9 |Σ|² (error above 0.32) is skipped.
fn start_error(c: &[f64; 3]) -> f64 {
    let norm2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    if c[2] > 0.0 && c[2] * c[2] >= 0.9 * norm2 {
        direction_error(c)
    } else {
        2.0
    }
}

/// Cells (i, j) whose lower corner is a local minimum of the direction error (`errors`, one per
/// grid node) below [`MINIMUM_START`] among its neighbours, at most [`MINIMUM_STARTS`], best
/// first.
fn local_minima(errors: &[f64], np: usize, ns: usize, thetas: &[f64]) -> Vec<(usize, usize)> {
    let err = |i: usize, j: usize| errors[i * ns + j];
    let mut minima: Vec<(f64, usize, usize)> = Vec::new();
    for (i, theta) in thetas.iter().enumerate().take(np) {
        if theta.abs() >= FRAC_PI_2 {
            continue;
        }
        for j in 0..ns - 1 {
            let r = err(i, j);
            if r > MINIMUM_START {
                continue;
            }
            let lowest = (i.saturating_sub(1)..=(i + 1).min(np))
                .all(|x| (j.saturating_sub(1)..=(j + 1).min(ns - 1)).all(|y| err(x, y) >= r));
            if lowest {
                minima.push((r, i, j));
            }
        }
    }
    minima.sort_by(|x, y| x.0.total_cmp(&y.0));
    minima
        .into_iter()
        .take(MINIMUM_STARTS)
        .map(|(_, i, j)| (i, j))
        .collect()
}

/// Damped Newton (Gauss–Newton with backtracking) on the residual in (φ, log s) on branch k,
/// with the Jacobian in closed form ([`Setup::residual_jacobian`]); φ is free (the branch is
/// continuous in φ).
fn newton(setup: &Setup, mut phi: f64, mut ls: f64, k: i64) -> (f64, f64, f64) {
    let max_ls = 700.0 / (setup.n - 1) as f64;
    let mut rn = setup.residual(phi, ls, k).norm();
    for iteration in 0..60 {
        // Converged, or (after a dozen steps still far off) not in a solution's basin.
        if rn <= 1e-15 || !rn.is_finite() || (iteration >= 10 && rn > 1e-3) {
            break;
        }
        let (r, jp, js) = setup.residual_jacobian(phi, ls, k);
        // Normal equations of the 3×2 least-squares step.
        let (a, b, c) = (jp.dot(&jp), jp.dot(&js), js.dot(&js));
        let (g0, g1) = (jp.dot(&r), js.dot(&r));
        let det = a * c - b * b;
        if det.abs() <= 1e-300 || !det.is_finite() {
            break;
        }
        let dp = -(c * g0 - b * g1) / det;
        let ds = -(a * g1 - b * g0) / det;
        let mut step = 1.0;
        let mut improved = false;
        for _ in 0..30 {
            let (np, ns) = (phi + step * dp, ls + step * ds);
            if ns.abs() < max_ls && np.is_finite() {
                let nr = setup.residual(np, ns, k).norm();
                if nr < rn {
                    phi = np;
                    ls = ns;
                    rn = nr;
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
    (phi, ls, rn)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed-form Jacobian of the direction residual against central differences, on
    /// every branch, both signs of log s, low and high degree.
    #[test]
    fn residual_jacobian_matches_central_differences() {
        // The residual from the rotation matrices themselves, Σ_j sʲ R(u, θ)ʲ v₀ with the axis
        // of eq. (14) and θ of `turn_about`, without the closed
        // forms (an independent evaluation).
        fn explicit(setup: &Setup, phi: f64, ls: f64, k: i64) -> Vector3 {
            let b = setup.branch(phi, k);
            let m = rotation(&b.axis, b.theta) * ls.exp();
            let (mut sum, mut leg) = (Vector3::zeros(), setup.v0);
            for _ in 0..setup.n {
                sum += leg;
                leg = m * leg;
            }
            sum / sum.norm() - setup.unit_chord
        }
        let a = [
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(1.0, 0.0, 0.2),
            Vector3::new(6.21, 6.54, 1.79),
            Vector3::new(6.12, 9.44, 2.73),
        ];
        let h = 1e-7;
        let mut checked = 0;
        for n in [3, 4, 7, 20, 45] {
            let setup = Setup::new(&a, n).unwrap();
            for k in setup.branches() {
                for phi in [-1.4, -0.6, 0.0, 0.45, 1.3] {
                    for ls in [-0.9, -0.2, 0.0, 0.15, 0.7] {
                        let (r, jp, js) = setup.residual_jacobian(phi, ls, k);
                        let direct = setup.residual(phi, ls, k);
                        // Term by term against the closed form of `geometric_sums` from degree 32.
                        assert!(
                            (r - direct).norm() <= 1e-11,
                            "n {n} k {k} phi {phi} ls {ls}: {r:?} {direct:?}"
                        );
                        // Fourth-order central differences.
                        let diff = |f: &dyn Fn(f64) -> Vector3| {
                            ((f(h) - f(-h)) * 8.0 - (f(2.0 * h) - f(-2.0 * h))) / (12.0 * h)
                        };
                        let fp = diff(&|d| explicit(&setup, phi + d, ls, k));
                        let fs = diff(&|d| explicit(&setup, phi, ls + d, k));
                        let scale = 1.0 + fp.norm() + fs.norm();
                        assert!(
                            (jp - fp).norm() <= 1e-6 * scale && (js - fs).norm() <= 1e-6 * scale,
                            "n {n} k {k} phi {phi} ls {ls}: {jp:?} {fp:?} / {js:?} {fs:?}"
                        );
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked > 500, "{checked}");
    }

    /// The grid rows (shared columns, closed form from degree 4) agree with the term-by-term
    /// [`Setup::scaled_sum`] at every node, including the nodes next to q = 1.
    #[test]
    fn grid_rows_match_the_term_by_term_sum() {
        let a = [
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(1.0, 0.0, 0.2),
            Vector3::new(6.21, 6.54, 1.79),
            Vector3::new(6.12, 9.44, 2.73),
        ];
        for n in [3, 7, 8, 13, 20, 31] {
            let setup = Setup::new(&a, n).unwrap();
            let frame = setup.chord_frame();
            let span = (LOG_RATIO_SPAN / (n - 1) as f64).min(4.0);
            let columns = Columns::new(
                std::array::from_fn(|j| -span + 2.0 * span * j as f64 / (GRID.1 - 1) as f64),
                n,
            );
            for k in setup.branches() {
                for phi in [-1.5, -0.7, 0.0, 0.3, 1.2] {
                    let b = setup.branch(phi, k);
                    let base = setup.row_base(phi, &frame);
                    assert_eq!((base.psi + TAU * k as f64) / (n - 1) as f64, b.theta);
                    let mut row = [[0.0; GRID.1]; 3];
                    setup.row_conditions(&base, b.theta, &columns, &mut row);
                    for (j, log_s) in columns.log_s.into_iter().enumerate() {
                        let cell = [row[0][j], row[1][j], row[2][j]];
                        // Each cell is Σ's frame components times a positive factor: equal
                        // directions, and signs.
                        let sum = setup.scaled_sum(&b, log_s);
                        let want = frame.map(|e| sum.dot(&e) / sum.norm());
                        let norm =
                            (cell[0] * cell[0] + cell[1] * cell[1] + cell[2] * cell[2]).sqrt();
                        for m in 0..3 {
                            assert!(
                                (cell[m] / norm - want[m]).abs() <= 2e-12,
                                "n {n} k {k} phi {phi} log s {}: {} vs {}",
                                log_s,
                                cell[m] / norm,
                                want[m]
                            );
                        }
                    }
                }
            }
        }
    }
}
