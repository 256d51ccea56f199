//! The paper's examples (Figs. 1–5) with exact solutions.
//!
//! The paper prints only problem (5) (Figs. 1–2) and the vase (Fig. 3) completely; Figs. 4–5
//! are described in one sentence each. Every choice made here is listed in the crate's paper
//! document: the swept angle θ, the side conditions, the patch grids and the continuity r.

use crate::error::PdeError;
use crate::problem::{Discretization, Operator, Problem, Side, SideCurve};
use bez_core::Vector3;
use std::f64::consts::PI;

/// Samples per side for fitted (non-polynomial) boundary data.
pub const SIDE_SAMPLES: usize = 401;

/// An exact solution of one of the examples.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Exact {
    /// Problem (5) over the swept angle θ: X = (A(u) cos θt, A(u) sin θt, H(1 − u)),
    /// A'' = a A, A(0) = √3, A(1) = 3, H = 3.
    CircleSphereBlend {
        /// The coefficient a of ∂²/∂v².
        a: f64,
        /// The swept angle θ (v = θ t).
        theta: f64,
    },
    /// The vase of Fig. 3 (Zhang & You 2001): harmonics 1 and 9, periodic in v.
    Vase,
    /// The C1 blend of Fig. 4 between the plane z = x/√3 and a vertical cylinder.
    CylinderPlane,
    /// The generalized Enneper surface of index k (Fig. 5).
    Enneper {
        /// The index k (polynomial degree 2k + 1).
        k: u32,
    },
}

/// One example: the problem, the trial space it is solved on, and the exact solution.
#[derive(Debug, Clone)]
pub struct Case {
    /// A short label ("Fig. 1, θ = 1").
    pub label: String,
    /// The paper's figure number (1–5).
    pub figure: usize,
    /// The boundary-value problem.
    pub problem: Problem,
    /// The trial space.
    pub disc: Discretization,
    /// The exact solution.
    pub exact: Exact,
}

impl Exact {
    /// X(u, v).
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> Vector3 {
        self.eval_du(u, v, 0)
    }

    /// ∂^d X/∂u^d (u, v) for d = 0 or 1 (what the side conditions need).
    #[must_use]
    pub fn eval_du(&self, u: f64, v: f64, d: usize) -> Vector3 {
        match *self {
            Self::CircleSphereBlend { a, theta } => {
                let s = a.sqrt();
                let (a0, a1, h) = (3.0_f64.sqrt(), 3.0, 3.0);
                let denom = s.sinh();
                let (amp, z) = if d == 0 {
                    (
                        (a0 * (s * (1.0 - u)).sinh() + a1 * (s * u).sinh()) / denom,
                        h * (1.0 - u),
                    )
                } else {
                    (
                        s * (-a0 * (s * (1.0 - u)).cosh() + a1 * (s * u).cosh()) / denom,
                        -h,
                    )
                };
                let ang = theta * v;
                Vector3::new(amp * ang.cos(), amp * ang.sin(), z)
            }
            Self::Vase => {
                let harmonic = |k: f64, alpha: f64, beta: f64| {
                    let l = 2.0 * PI * k / 5.0_f64.sqrt();
                    let amp = if d == 0 {
                        alpha * (l * (1.0 - u)).sinh() + beta * (l * u).sinh()
                    } else {
                        l * (-alpha * (l * (1.0 - u)).cosh() + beta * (l * u).cosh())
                    };
                    let ang = 2.0 * PI * k * v;
                    Vector3::new(ang.cos(), ang.sin(), 0.0) * (amp / l.sinh())
                };
                let z = if d == 0 { 10.0 * (1.0 - u) } else { -10.0 };
                harmonic(1.0, 1.0, 0.6) + harmonic(9.0, 0.1, 0.05) + Vector3::new(0.0, 0.0, z)
            }
            Self::CylinderPlane => {
                let c = cylinder_plane_coefficients();
                let ang = 2.0 * PI * v;
                let a = c.radial.eval(u, d);
                let z0 = c.height.eval(u, d);
                let z1 = c.tilt.eval(u, d);
                Vector3::new(a * ang.cos(), a * ang.sin(), z0 + z1 * ang.cos())
            }
            Self::Enneper { k } => {
                let zu = (2.0 * u - 1.0, 2.0 * v - 1.0);
                let n = 2 * k + 1;
                if d == 0 {
                    let p = cpow(zu, n);
                    let q = cpow(zu, k + 1);
                    let nf = f64::from(n);
                    Vector3::new(
                        zu.0 - p.0 / nf,
                        -(zu.1 + p.1 / nf),
                        2.0 * q.0 / f64::from(k + 1),
                    )
                } else {
                    // ∂/∂u = 2 d/dz: (1 − z^{2k}, i(1 + z^{2k}), 2 z^k), real parts, times 2.
                    let p = cpow(zu, 2 * k);
                    let q = cpow(zu, k);
                    Vector3::new(2.0 * (1.0 - p.0), -2.0 * p.1, 4.0 * q.0)
                }
            }
        }
    }
}

fn cpow(z: (f64, f64), n: u32) -> (f64, f64) {
    let mut out = (1.0, 0.0);
    for _ in 0..n {
        out = (out.0 * z.0 - out.1 * z.1, out.0 * z.1 + out.1 * z.0);
    }
    out
}

/// f(u) = (c₀ + c₁ u) e^{a u} + (c₂ + c₃ u) e^{−a u}, or a cubic when a = 0.
#[derive(Debug, Clone, Copy)]
struct Kernel {
    a: f64,
    c: [f64; 4],
}

impl Kernel {
    fn basis(a: f64, u: f64, d: usize) -> [f64; 4] {
        if a == 0.0 {
            return if d == 0 {
                [1.0, u, u * u, u * u * u]
            } else {
                [0.0, 1.0, 2.0 * u, 3.0 * u * u]
            };
        }
        let (ep, em) = ((a * u).exp(), (-a * u).exp());
        if d == 0 {
            [ep, u * ep, em, u * em]
        } else {
            [a * ep, (1.0 + a * u) * ep, -a * em, (1.0 - a * u) * em]
        }
    }

    /// The kernel function with f(0), f'(0), f(1), f'(1) prescribed (a 4 × 4 solve).
    fn hermite(a: f64, values: [f64; 4]) -> Self {
        let rows = [
            Self::basis(a, 0.0, 0),
            Self::basis(a, 0.0, 1),
            Self::basis(a, 1.0, 0),
            Self::basis(a, 1.0, 1),
        ];
        let m = crate::dense::Dense::from_fn(4, 4, |i, j| rows[i][j]);
        let c = m
            .solve(&crate::dense::Dense::from_fn(4, 1, |i, _| values[i]))
            .map_or([0.0; 4], |c| [c[(0, 0)], c[(1, 0)], c[(2, 0)], c[(3, 0)]]);
        Self { a, c }
    }

    fn eval(&self, u: f64, d: usize) -> f64 {
        let b = Self::basis(self.a, u, d);
        (0..4).map(|i| b[i] * self.c[i]).sum()
    }
}

struct CylinderPlaneCoefficients {
    radial: Kernel,
    height: Kernel,
    tilt: Kernel,
}

/// Fig. 4's parameters: a = 1, plane trim radius R = 2, cylinder radius r = 1 at height H = 2,
/// cross-derivative magnitude 2 at both ends, tan α = 1/√3.
fn cylinder_plane_coefficients() -> CylinderPlaneCoefficients {
    let tan = 1.0 / 3.0_f64.sqrt();
    let (big_r, r, h, mag) = (2.0, 1.0, 2.0, 2.0);
    CylinderPlaneCoefficients {
        radial: Kernel::hermite(1.0, [big_r, -mag, r, 0.0]),
        height: Kernel::hermite(0.0, [0.0, 0.0, h, mag]),
        tilt: Kernel::hermite(1.0, [big_r * tan, -mag * tan, 0.0, 0.0]),
    }
}

/// `SIDE_SAMPLES` uniform samples of f with its values at both ends (a jet of length 1).
fn sampled(f: impl Fn(f64) -> Vector3) -> SideCurve {
    let values = (0..SIDE_SAMPLES)
        .map(|i| f(i as f64 / (SIDE_SAMPLES - 1) as f64))
        .collect();
    SideCurve::Sampled {
        values,
        start_jet: vec![f(0.0)],
        end_jet: vec![f(1.0)],
    }
}

/// Dirichlet data of `exact` on the u-sides and, unless `periodic`, on the v-sides;
/// for fourth order also ∂X/∂u on the u-sides.
fn sides_from(exact: Exact, half: usize, periodic: bool) -> [Side; 4] {
    let u_side = |u: f64| {
        Side::Fixed(
            (0..half)
                .map(|d| sampled(move |t| exact.eval_du(u, t, d)))
                .collect(),
        )
    };
    if periodic {
        [u_side(0.0), u_side(1.0), Side::Periodic, Side::Periodic]
    } else {
        let v_side = |v: f64| Side::Fixed(vec![sampled(move |t| exact.eval(t, v))]);
        [u_side(0.0), u_side(1.0), v_side(0.0), v_side(1.0)]
    }
}

fn problem(operator: Operator, sides: [Side; 4]) -> Problem {
    let [u0, u1, v0, v1] = sides;
    Problem {
        operator,
        rhs: None,
        u0,
        u1,
        v0,
        v1,
    }
}

/// Figs. 1–2: problem (5) with coefficient a over the swept angle θ, one bi-quintic patch.
///
/// In t = v/θ the operator is ∂²/∂u² + (a/θ²) ∂²/∂t²; sides t = 0, 1 come from the exact
/// solution; every side is fitted to a quintic by clamped least squares.
///
/// # Errors
/// [`PdeError::NonFinite`] for a non-finite or zero θ.
pub fn circle_sphere_blend(a: f64, theta: f64) -> Result<Case, PdeError> {
    if !(theta.is_finite() && a.is_finite()) || theta == 0.0 {
        return Err(PdeError::NonFinite {
            what: "swept angle",
            value: theta,
        });
    }
    let exact = Exact::CircleSphereBlend { a, theta };
    Ok(Case {
        label: format!(
            "Fig. {}, θ = {}",
            if a == 1.0 { 1 } else { 2 },
            angle_label(theta)
        ),
        figure: if a == 1.0 { 1 } else { 2 },
        problem: problem(
            Operator::second_order(1.0, a / (theta * theta))?,
            sides_from(exact, 1, false),
        ),
        disc: Discretization::single(5, 5),
        exact,
    })
}

fn angle_label(theta: f64) -> String {
    if (theta - PI).abs() < 1e-12 {
        "π".to_string()
    } else if (theta - PI / 2.0).abs() < 1e-12 {
        "π/2".to_string()
    } else {
        format!("{theta}")
    }
}

/// Fig. 3: the vase, (5 ∂²/∂u² + ∂²/∂v²) X = 0, periodic in v, on a grid of
/// `patches_u` × `patches_v` bi-quintic C² patches.
///
/// # Errors
/// None in practice (the operator is valid).
pub fn vase(patches_u: usize, patches_v: usize) -> Result<Case, PdeError> {
    let exact = Exact::Vase;
    Ok(Case {
        label: format!("Fig. 3, {patches_u}x{patches_v} C2"),
        figure: 3,
        problem: problem(
            Operator::second_order(5.0, 1.0)?,
            sides_from(exact, 1, true),
        ),
        disc: grid(5, patches_u, patches_v, 2),
        exact,
    })
}

/// Fig. 4: the C1 cylinder–plane blend, (∂²/∂u² + a²/(2π)² ∂²/∂t²)² X = 0 (v = 2πt the
/// angle, a = 1), periodic in t, positions and ∂X/∂u on both u-sides, bi-quintic C⁴ grid.
///
/// # Errors
/// None in practice.
pub fn cylinder_plane(patches_u: usize, patches_v: usize) -> Result<Case, PdeError> {
    let exact = Exact::CylinderPlane;
    Ok(Case {
        label: format!("Fig. 4, {patches_u}x{patches_v} C4"),
        figure: 4,
        problem: problem(
            Operator::bloor_wilson(1.0 / (2.0 * PI))?,
            sides_from(exact, 2, true),
        ),
        disc: grid(5, patches_u, patches_v, 4),
        exact,
    })
}

/// Fig. 5: the generalized Enneper surface of index k, Laplace's equation, Dirichlet data on
/// all four sides (degree 2k + 1, fitted when above the patch degree), bi-quintic C² grid.
///
/// # Errors
/// None in practice.
pub fn enneper(k: u32, patches_u: usize, patches_v: usize) -> Result<Case, PdeError> {
    let exact = Exact::Enneper { k };
    Ok(Case {
        label: format!("Fig. 5, k = {k}, {patches_u}x{patches_v} C2"),
        figure: 5,
        problem: problem(
            Operator::second_order(1.0, 1.0)?,
            sides_from(exact, 1, false),
        ),
        disc: grid(5, patches_u, patches_v, 2),
        exact,
    })
}

fn grid(degree: usize, patches_u: usize, patches_v: usize, smoothness: usize) -> Discretization {
    Discretization {
        degree_u: degree,
        degree_v: degree,
        patches_u,
        patches_v,
        smoothness_u: smoothness,
        smoothness_v: smoothness,
    }
}

/// The examples of Tables 1–2 in the project's chosen set-up.
///
/// # Errors
/// None in practice.
pub fn paper_cases() -> Result<Vec<Case>, PdeError> {
    let mut out = Vec::new();
    for a in [1.0, 3.0] {
        for theta in [1.0, PI / 2.0, PI] {
            out.push(circle_sphere_blend(a, theta)?);
        }
    }
    out.push(vase(8, 16)?);
    out.push(cylinder_plane(4, 16)?);
    out.push(enneper(3, 1, 1)?);
    out.push(enneper(3, 4, 4)?);
    Ok(out)
}
