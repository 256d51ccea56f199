//! The planar Hermite solve with prescribed end curvature (G2 ends): [`hermite_planar`].
//!
//! End points and end tangent directions fix θ = ψ/(n − 1), s (the root of
//! [`crate::solve_scale`]) and L (the chord length) for each degree n, so the end curvatures of
//! a typical curve are fixed by the G1 data and n: a discrete set of values, one pair per
//! degree. Prescribing them needs more freedom: the general 2 × 2 matrix M (four entries) and
//! the first leg's length L are five unknowns for the five conditions end point (2), end
//! tangent (1) and the two end curvatures ([`hermite_planar`]).

use bez_core::{BezierForm, Vector, Vector2};

use crate::continuation::{
    NEWTON_ITERATIONS, NEWTON_TOLERANCE, backtrack, check_end_curvatures, continuation, max_norm,
    within_tolerance,
};
use crate::hermite_search::Reduced;
use crate::planar::signed_angle;
use crate::square::{Matrix, Matrix2};
use crate::{
    ClassACurve, ClassAError, INTERPOLATION_TOLERANCE, Interpolation, TypicalPlanar,
    curvature_certificate, end_curvatures, solve_scale,
};

/// A point with a tangent direction and, optionally, a signed curvature (positive turning left):
/// an end of a segment ([`hermite_planar`]) or a knot of a [`crate::ClassASpline`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Knot {
    /// The point.
    pub point: Vector2,
    /// The tangent direction (any non-zero length).
    pub tangent: Vector2,
    /// The signed curvature, if prescribed.
    pub curvature: Option<f64>,
}

impl Knot {
    /// A knot with point and tangent direction, curvature free.
    #[must_use]
    pub fn new(point: Vector2, tangent: Vector2) -> Self {
        Self {
            point,
            tangent,
            curvature: None,
        }
    }

    /// The knot with the signed curvature prescribed.
    #[must_use]
    pub fn with_curvature(self, curvature: f64) -> Self {
        Self {
            curvature: Some(curvature),
            ..self
        }
    }

    /// Finite point and curvature, non-zero finite tangent.
    fn check(&self) -> Result<(), ClassAError> {
        crate::error::check_point(&self.point, "knot point")?;
        if !self.tangent.is_finite() {
            return Err(ClassAError::NonFinite {
                name: "knot tangent",
            });
        }
        let norm = self.tangent.norm();
        if !(norm > 0.0 && norm.is_finite()) {
            return Err(ClassAError::InvalidParameter {
                name: "|knot tangent|",
                value: norm,
                expected: "positive and finite",
            });
        }
        match self.curvature {
            Some(k) if !k.is_finite() => Err(ClassAError::NonFinite {
                name: "knot curvature",
            }),
            _ => Ok(()),
        }
    }
}

/// The triangle of two knots: the tangent lines meet at α₁, with the turn ψ and the chord angle δ.
struct Triangle {
    alpha1: Vector2,
    turn: f64,
    chord_angle: f64,
    chord: f64,
    /// |α₁ − α₀| + |α₂ − α₁|.
    legs: f64,
}

impl Triangle {
    fn new(start: &Knot, end: &Knot) -> Result<Self, ClassAError> {
        start.check()?;
        end.check()?;
        let c = end.point - start.point;
        if c.norm() == 0.0 {
            return Err(ClassAError::CoincidentPoints {
                first: 0,
                second: 2,
            });
        }
        let turn = signed_angle(&start.tangent, &end.tangent);
        if turn == 0.0 || turn.abs() >= std::f64::consts::PI {
            return Err(ClassAError::DegenerateTurn { turn });
        }
        let chord_angle = signed_angle(&start.tangent, &c);
        if !(chord_angle * turn > 0.0 && chord_angle.abs() < turn.abs()) {
            return Err(ClassAError::ChordOutsideTangents { chord_angle, turn });
        }
        // Law of sines in α₀α₁α₂: angles δ at α₀, ψ − δ at α₂, π − ψ at α₁.
        let chord = c.norm();
        let l0 = chord * (turn - chord_angle).sin().abs() / turn.sin().abs();
        let l1 = chord * chord_angle.sin().abs() / turn.sin().abs();
        let alpha1 = start.point + start.tangent / start.tangent.norm() * l0;
        Ok(Self {
            alpha1,
            turn,
            chord_angle,
            chord,
            legs: l0 + l1,
        })
    }

    /// Necessary conditions on prescribed end curvatures (see [`hermite_planar`]).
    fn check_reachable(&self, k0: f64, k1: f64) -> Result<(), ClassAError> {
        let sign = self.turn.signum();
        let signed = |a: f64, b: f64| {
            if sign > 0.0 { (a, b) } else { (-b, -a) }
        };
        for (end, k) in [("start", k0), ("end", k1)] {
            if k * sign <= 0.0 {
                let (lower, upper) = signed(0.0, f64::INFINITY);
                return Err(ClassAError::CurvatureUnreachable {
                    end,
                    curvature: k,
                    lower,
                    upper,
                    reason: "the curvature must be non-zero with the sign of the tangent turn",
                });
            }
        }
        let turn = self.turn.abs();
        let (small, large) = if k0.abs() <= k1.abs() {
            (("start", k0), ("end", k1))
        } else {
            (("end", k1), ("start", k0))
        };
        let most = turn / self.chord;
        if small.1.abs() >= most {
            let (lower, upper) = signed(0.0, most);
            return Err(ClassAError::CurvatureUnreachable {
                end: small.0,
                curvature: small.1,
                lower,
                upper,
                reason: "the smaller end curvature times the arc length is at most the turn, and the arc is longer than the chord",
            });
        }
        let least = turn / self.legs;
        if large.1.abs() <= least {
            let (lower, upper) = signed(least, f64::INFINITY);
            return Err(ClassAError::CurvatureUnreachable {
                end: large.0,
                curvature: large.1,
                lower,
                upper,
                reason: "the larger end curvature times the arc length is at least the turn, and the arc is shorter than the two tangent legs",
            });
        }
        Ok(())
    }
}

/// The Class A curve of degree n from `start` to `end` with their tangent directions, and with
/// their curvatures when both are prescribed (G2 ends); the curve's curvature is proven monotone
/// ([`curvature_certificate`]) before it is returned.
///
/// * Neither curvature given: the typical planar curve ([`TypicalPlanar::from_points`] with α₁
///   the intersection of the tangent lines), whose end curvatures are then fixed by the data and
///   n ([`TypicalPlanar::end_curvatures`]).
/// * Both given: a general matrix M and first leg length L solved for the five conditions
///   (module docs). In the frame of the start tangent, with the chord scaled to length 1, the
///   unknowns (L, M₁₁, M₁₂, M₂₁, M₂₂) start at the typical curve's and Newton's method
///   (central-difference Jacobian, backtracking) follows the curvatures from the typical
///   curve's to the prescribed ones by continuation (steps halved on failure). When that
///   fails or its curve is refused, a global search takes over: every Class A curve meeting
///   the G1 data is the affine image of a canonical one fixed by the trace and determinant of
///   M, so the two curvature conditions become two equations in two unknowns (the largest
///   eigenvalue modulus m of M and the eigenvalues' shape), solved from every cell of a grid
///   over m ∈ [e^{−48/(n−1)}, e^{48/(n−1)}] and all shapes; each solution (nearest to the
///   typical curve first) is polished by Newton's method on the five equations and checked as
///   below, and the first that passes is returned.
///
/// Before the solve the prescribed curvatures are checked against what any curve of monotone
/// curvature with a convex control polygon in the tangent triangle α₀α₁α₂ can have: the
/// curvature has the sign of the turn ψ, and with κ monotone, |ψ| = ∫|κ| ds lies between
/// min(|κ₀|, |κ₁|)·S and max(|κ₀|, |κ₁|)·S, where the arc length S is above the chord |α₂ − α₀|
/// and below |α₁ − α₀| + |α₂ − α₁|; hence min |κ| < |ψ| / |α₂ − α₀| and
/// max |κ| > |ψ| / (|α₁ − α₀| + |α₂ − α₁|). These are necessary, not sufficient: inside them the
/// solve can still fail (no solution of the five equations in the searched range, or only
/// solutions whose curvature is not monotone or whose rounded control points miss the
/// tolerance), which is an error, never an unchecked `Ok`.
///
/// The result is verified on its rounded control points: end points and tangents within
/// [`INTERPOLATION_TOLERANCE`] ([`Interpolation`]), the legs turning one way by ψ in total,
/// the end curvatures ([`end_curvatures`]) within [`INTERPOLATION_TOLERANCE`] relative, and
/// monotone curvature proven.
///
/// ```
/// use bez_core::{BezierForm, Vector2};
/// use class_a::{Knot, hermite_planar, end_curvatures};
/// let start = Knot::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
/// let end = Knot::new(Vector2::new(2.0, 1.0), Vector2::new(0.3, 1.0));
/// // G1: the typical curve; its end curvatures follow from the data and the degree.
/// let g1 = hermite_planar(&start, &end, 7)?;
/// let (k0, k1) = end_curvatures(g1.as_bezier())?;
/// assert!(k1 > k0); // curvature increasing towards the end
/// // G2: prescribe them 10 % further apart.
/// let (start, end) = (start.with_curvature(k0 / 1.1), end.with_curvature(k1 * 1.1));
/// let g2 = hermite_planar(&start, &end, 7)?;
/// let (c0, c1) = end_curvatures(g2.as_bezier())?;
/// assert!((c0 * 1.1 / k0 - 1.0).abs() < 1e-9 && (c1 / (1.1 * k1) - 1.0).abs() < 1e-9);
/// # Ok::<(), class_a::ClassAError>(())
/// ```
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] / [`ClassAError::DegreeTooHigh`]; for the knots
/// [`ClassAError::NonFinite`], [`ClassAError::InvalidParameter`] (a zero tangent, or a
/// curvature given at one end only), [`ClassAError::CoincidentPoints`],
/// [`ClassAError::DegenerateTurn`], [`ClassAError::ChordOutsideTangents`];
/// [`ClassAError::CurvatureUnreachable`] naming the end and its reachable range;
/// [`ClassAError::NoConvergence`] (no solution found by the continuation or the search);
/// [`ClassAError::ToleranceNotMet`]; [`ClassAError::CurvatureNotMonotone`] (a solution was
/// found, and none found has monotone curvature); without curvatures, the errors of
/// [`TypicalPlanar::from_points`].
pub fn hermite_planar(
    start: &Knot,
    end: &Knot,
    degree: usize,
) -> Result<ClassACurve<2>, ClassAError> {
    crate::error::check_degree(degree, 2)?;
    let tri = Triangle::new(start, end)?;
    let curve = match (start.curvature, end.curvature) {
        (None, None) => {
            let t = TypicalPlanar::from_points(&start.point, &tri.alpha1, &end.point, degree)?;
            ClassACurve::try_from(&t)?
        }
        (Some(k0), Some(k1)) => {
            tri.check_reachable(k0, k1)?;
            solve_g2(start, end, &tri, k0, k1, degree)?
        }
        (Some(value), None) | (None, Some(value)) => {
            return Err(ClassAError::InvalidParameter {
                name: "curvature",
                value,
                expected: "prescribed at both ends or at neither",
            });
        }
    };
    if start.curvature.is_none() {
        let cert = curvature_certificate(curve.as_bezier())?;
        if !cert.is_monotone() {
            return Err(ClassAError::CurvatureNotMonotone {
                verdict: cert.verdict,
            });
        }
    }
    Ok(curve)
}

/// Residual up to which a seed of the global search is checked without polishing.
const SEED_TOLERANCE: f64 = 1e-10;

/// The five equations in the frame of the start tangent (chord of length 1).
struct System {
    degree: usize,
    chord: Vector2,
    end_tangent: Vector2,
    turn: f64,
}

impl System {
    /// Residuals at x = (L, M₁₁, M₁₂, M₂₁, M₂₂) for target curvatures (k0, k1) (scaled frame):
    /// Σ Mʲv − chord, (Mⁿ⁻¹v × T₁)/|Mⁿ⁻¹v| / |ψ|, and κ(0)/k0 − 1, κ(1)/k1 − 1.
    /// Also returns the curve's own (κ(0), κ(1)). None when a value is not finite.
    fn residual(&self, x: &[f64; 5], k0: f64, k1: f64) -> Option<([f64; 5], (f64, f64))> {
        let m = Matrix2::new(x[1], x[2], x[3], x[4]);
        let n = self.degree;
        let mut leg = Vector2::new(x[0], 0.0);
        let first = leg;
        let mut sum = Vector2::zeros();
        let mut last = (leg, leg);
        for j in 0..n {
            sum += leg;
            if j + 2 == n {
                last.0 = leg;
            }
            if j + 1 == n {
                last.1 = leg;
                break;
            }
            leg = m * leg;
        }
        let second = m * first;
        let factor = (n - 1) as f64 / n as f64;
        let n0 = first.norm();
        let nl = last.1.norm();
        let c0 = factor * first.perp(&second) / (n0 * n0 * n0);
        let c1 = factor * last.0.perp(&last.1) / (nl * nl * nl);
        let r = [
            sum.x() - self.chord.x(),
            sum.y() - self.chord.y(),
            last.1.perp(&self.end_tangent) / nl / self.turn.abs(),
            c0 / k0 - 1.0,
            c1 / k1 - 1.0,
        ];
        (r.iter().all(|v| v.is_finite()) && c0.is_finite() && c1.is_finite())
            .then_some((r, (c0, c1)))
    }

    /// Newton's method from x for targets (k0, k1); Some(x) when converged.
    fn newton(&self, mut x: [f64; 5], k0: f64, k1: f64) -> Option<[f64; 5]> {
        let norm = |r: &[f64; 5]| max_norm(r);
        let (mut r, _) = self.residual(&x, k0, k1)?;
        for _ in 0..NEWTON_ITERATIONS {
            let current = norm(&r);
            if current <= NEWTON_TOLERANCE {
                return Some(x);
            }
            let mut jac = Matrix::<5>::identity();
            for j in 0..5 {
                let h = 1e-7 * (x[j].abs() + 1e-3);
                let (mut xp, mut xm) = (x, x);
                xp[j] += h;
                xm[j] -= h;
                let (rp, _) = self.residual(&xp, k0, k1)?;
                let (rm, _) = self.residual(&xm, k0, k1)?;
                for i in 0..5 {
                    jac[(i, j)] = (rp[i] - rm[i]) / (2.0 * h);
                }
            }
            let dx = jac.solve(&Vector::from_array(r.map(|v| -v))).ok()?;
            (x, r) = backtrack(&x, &dx.to_array(), current, |trial| {
                self.residual(trial, k0, k1).map(|(r, _)| r)
            })?;
        }
        (norm(&r) <= NEWTON_TOLERANCE).then_some(x)
    }
}

/// The general-matrix solve of [`hermite_planar`] (both curvatures given, already checked).
fn solve_g2(
    start: &Knot,
    end: &Knot,
    tri: &Triangle,
    k0: f64,
    k1: f64,
    degree: usize,
) -> Result<ClassACurve<2>, ClassAError> {
    let e1 = start.tangent / start.tangent.norm();
    let e2 = Vector2::new(-e1.y(), e1.x());
    let local = |v: Vector2| Vector2::new(v.dot(&e1), v.dot(&e2));
    let t1 = end.tangent / end.tangent.norm();
    let system = System {
        degree,
        chord: local(end.point - start.point) / tri.chord,
        end_tangent: local(t1),
        turn: tri.turn,
    };
    // The typical curve of the same G1 data (not necessarily Class A) as the start.
    let theta = tri.turn / (degree - 1) as f64;
    let s = solve_scale(theta, tri.chord_angle, degree);
    let (sn, cs) = theta.sin_cos();
    let mut sum = Vector2::zeros();
    let mut power = Vector2::new(1.0, 0.0);
    for _ in 0..degree {
        sum += power;
        power = Vector2::new(
            cs * power.x() - sn * power.y(),
            sn * power.x() + cs * power.y(),
        ) * s;
    }
    let x = [1.0 / sum.norm(), s * cs, -s * sn, s * sn, s * cs];
    let no_convergence = |residual: f64| ClassAError::NoConvergence {
        method: "G2 Hermite continuation and global search",
        residual,
    };
    let (_, (c0, c1)) = system
        .residual(&x, 1.0, 1.0)
        .ok_or(no_convergence(f64::INFINITY))?;
    let (t0, t1s) = (k0 * tri.chord, k1 * tri.chord);
    let (x, reached) = continuation(x, |from, next| {
        let target = |a: f64, b: f64| a + (b - a) * next;
        system.newton(from, target(c0, t0), target(c1, t1s))
    });
    let continued = reached.then_some(x);
    // The global search (module `hermite_search`) when the continuation's curve is refused.
    let near = [s.ln(), (tri.turn / std::f64::consts::PI).powi(2)];
    let searched = std::iter::once_with(|| {
        Reduced::new(degree, system.chord, system.end_tangent, t0, t1s)
            .map_or_else(Vec::new, |r| r.seeds(near))
    })
    .flatten();
    // Back to the world frame: M_world = R M Rᵀ with R = [e1 e2], first leg L·|chord|·e1.
    let rot = Matrix2::new(e1.x(), e2.x(), e1.y(), e2.y());
    let mut refusal = None;
    for seed in continued.into_iter().chain(searched) {
        // A seed of the search already meets the equations to about 1e-12; where rounding
        // keeps Newton from improving it further, it goes to the checks as it is.
        let polished = system.newton(seed, t0, t1s).or_else(|| {
            system
                .residual(&seed, t0, t1s)
                .filter(|(r, _)| r.iter().all(|v| v.abs() <= SEED_TOLERANCE))
                .map(|_| seed)
        });
        let Some(x) = polished else {
            continue;
        };
        let m = rot * Matrix2::new(x[1], x[2], x[3], x[4]) * rot.transpose();
        let checked = ClassACurve::new(&start.point, &(e1 * (x[0] * tri.chord)), &m, degree)
            .and_then(|curve| {
                verify(&curve, start, end, tri.turn, k0, k1)?;
                let cert = curvature_certificate(curve.as_bezier())?;
                if cert.is_monotone() {
                    Ok(curve)
                } else {
                    Err(ClassAError::CurvatureNotMonotone {
                        verdict: cert.verdict,
                    })
                }
            });
        match checked {
            Ok(curve) => return Ok(curve),
            // A solution whose curvature is not monotone says more than one off by rounding.
            Err(e) => {
                if !matches!(refusal, Some(ClassAError::CurvatureNotMonotone { .. })) {
                    refusal = Some(e);
                }
            }
        }
    }
    Err(refusal.unwrap_or_else(|| {
        no_convergence(
            system
                .residual(&x, t0, t1s)
                .map_or(f64::INFINITY, |(r, _)| max_norm(&r)),
        )
    }))
}

/// The checks of [`hermite_planar`] on the rounded control points.
fn verify(
    curve: &ClassACurve<2>,
    start: &Knot,
    end: &Knot,
    turn: f64,
    k0: f64,
    k1: f64,
) -> Result<(), ClassAError> {
    let bezier = curve.as_bezier();
    let p = bezier.points();
    Interpolation::measure(p, &start.point, &start.tangent, &end.tangent, &end.point)
        .within(INTERPOLATION_TOLERANCE)?;
    let mut total = 0.0;
    for w in p.windows(3) {
        let a = signed_angle(&(w[1] - w[0]), &(w[2] - w[1]));
        if a * turn <= 0.0 {
            return Err(ClassAError::ToleranceNotMet {
                condition: "legs turning one way",
                achieved: a,
                tolerance: 0.0,
            });
        }
        total += a;
    }
    within_tolerance("total turn", (total - turn).abs())?;
    let (c0, c1) = end_curvatures(bezier)?;
    check_end_curvatures([c0, c1], [k0, k1])?;
    Ok(())
}
