//! End curvatures of Class A curves and the planar Hermite solve with prescribed end curvature
//! (G2 ends).
//!
//! # End curvature of a Bézier curve
//!
//! For a degree-n Bézier curve x(t) with legs Δbⱼ = bⱼ₊₁ − bⱼ, x'(0) = nΔb₀ and
//! x''(0) = n(n − 1)(Δb₁ − Δb₀), so the signed curvature κ = x' × x'' / |x'|³ at the ends is
//!
//! κ(0) = (n − 1)/n · Δb₀ × Δb₁ / |Δb₀|³,  κ(1) = (n − 1)/n · Δbₙ₋₂ × Δbₙ₋₁ / |Δbₙ₋₁|³
//!
//! (a × b = a_x b_y − a_y b_x; the Δb₁ − Δb₀ becomes Δb₁ since Δb₀ × Δb₀ = 0). Only the first
//! and the last three control points enter.
//!
//! For a Class A curve, Δbⱼ = Mʲv with v = Δb₀, and (Mu) × (Mw) = det M · (u × w), so
//!
//! κ(0) = (n − 1)/n · v × Mv / |v|³,  κ(1) = (n − 1)/n · (det M)ⁿ⁻² · v × Mv / |Mⁿ⁻¹v|³.
//!
//! For the typical matrix M = s·R(θ) and v = Lμ: v × Mv = L² s sin θ, det M = s² and
//! |Mⁿ⁻¹v| = L sⁿ⁻¹, so κ(0) = (n − 1) s sin θ / (nL) and κ(1) = (n − 1) sin θ / (n L sⁿ)
//! ([`TypicalPlanar::end_curvatures`]).
//!
//! # What the typical family can reach
//!
//! End points and end tangent directions fix θ = ψ/(n − 1), s (the root of
//! [`crate::solve_scale`]) and L (the chord length) for each degree n, so the end curvatures of
//! a typical curve are fixed by the G1 data and n: a discrete set of values, one pair per
//! degree. Prescribing them needs more freedom: the general 2 × 2 matrix M (four entries) and
//! the first leg's length L are five unknowns for the five conditions end point (2), end
//! tangent (1) and the two end curvatures ([`hermite_planar`]).

use bez_core::{BezierCurve, BezierForm, Vector, Vector2};

use crate::planar::signed_angle;
use crate::square::{Matrix, Matrix2};
use crate::{
    ClassACurve, ClassAError, INTERPOLATION_TOLERANCE, Interpolation, TypicalPlanar,
    curvature_certificate, solve_scale,
};

/// Signed curvatures (κ(0), κ(1)) of a planar Bézier curve from its first and last three
/// control points (module docs):
/// κ(0) = (n − 1)/n · Δb₀ × Δb₁ / |Δb₀|³ and κ(1) = (n − 1)/n · Δbₙ₋₂ × Δbₙ₋₁ / |Δbₙ₋₁|³.
///
/// ```
/// use bez_core::Vector2;
/// use class_a::end_curvatures;
/// // The quadratic (0,0), (1,0), (1,1): κ(0) = (1/2) · 1 / 1 = 0.5 at both ends.
/// let c = bez_core::BezierCurve::new(vec![
///     Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), Vector2::new(1.0, 1.0),
/// ])?;
/// let (k0, k1) = end_curvatures(&c)?;
/// assert!((k0 - 0.5).abs() < 1e-15 && (k1 - 0.5).abs() < 1e-15);
/// # Ok::<(), class_a::ClassAError>(())
/// ```
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 2; [`ClassAError::Singular`] when an end leg is zero
/// (the curvature at that end is not given by this formula); [`ClassAError::NonFinite`] when a
/// value overflows.
pub fn end_curvatures(curve: &BezierCurve<2>) -> Result<(f64, f64), ClassAError> {
    let n = curve.degree();
    crate::error::check_degree(n, 2)?;
    let p = curve.points();
    let factor = (n - 1) as f64 / n as f64;
    let at = |a: Vector2, b: Vector2, tangent: Vector2, parameter: f64| {
        let norm = tangent.norm();
        if norm == 0.0 {
            return Err(ClassAError::Singular {
                quantity: "the end leg",
                parameter,
            });
        }
        let k = factor * (a.perp(&b) / norm) / (norm * norm);
        if k.is_finite() {
            Ok(k)
        } else {
            Err(ClassAError::NonFinite { name: "curvature" })
        }
    };
    let (d0, d1) = (p[1] - p[0], p[2] - p[1]);
    let (e0, e1) = (p[n - 1] - p[n - 2], p[n] - p[n - 1]);
    Ok((at(d0, d1, d0, 0.0)?, at(e0, e1, e1, 1.0)?))
}

/// Curvature and torsion at both ends of a spatial Bézier curve, [(κ(0), τ(0)), (κ(1), τ(1))],
/// from its first and last four control points.
///
/// With x‴(0) = n(n − 1)(n − 2)(Δb₂ − 2Δb₁ + Δb₀), column operations give
/// det(x′, x″, x‴) = n³(n − 1)²(n − 2) det(Δb₀, Δb₁, Δb₂), so
///
/// κ(0) = (n − 1)/n · |Δb₀ × Δb₁| / |Δb₀|³,  τ(0) = (n − 2)/n · det(Δb₀, Δb₁, Δb₂) / |Δb₀ × Δb₁|²,
///
/// and at t = 1 the same with Δbₙ₋₃, Δbₙ₋₂, Δbₙ₋₁ (in this order) and |Δbₙ₋₁|³. For a Class A
/// curve det(Mʲv, Mʲ⁺¹v, Mʲ⁺²v) = (det M)ʲ det(v, Mv, M²v): the end torsions are tied by
/// (det M)ⁿ⁻³ as the curvatures are (module docs). A spatial G2 solve (prescribed curvature and
/// torsion with a general 3 × 3 matrix) is not provided.
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 3; [`ClassAError::Singular`] when an end leg is zero or
/// the first (last) two legs are parallel (torsion undefined there);
/// [`ClassAError::NonFinite`] when a value overflows.
pub fn end_curvatures_torsions(curve: &BezierCurve<3>) -> Result<[(f64, f64); 2], ClassAError> {
    let n = curve.degree();
    crate::error::check_degree(n, 3)?;
    let p = curve.points();
    let (nf, leg) = (n as f64, |i: usize| p[i + 1] - p[i]);
    // `cross` is that of the two legs at the end (κ and the torsion's denominator), `det` the
    // triple product of the three legs there in curve order.
    let at = |cross: Vector<3>, det: f64, tangent: Vector<3>, parameter: f64| {
        let (t, w) = (tangent.norm(), cross.norm());
        if t == 0.0 || w == 0.0 {
            return Err(ClassAError::Singular {
                quantity: if t == 0.0 {
                    "the end leg"
                } else {
                    "the cross product of the end legs"
                },
                parameter,
            });
        }
        let kappa = (nf - 1.0) / nf * (w / t) / (t * t);
        let tau = (nf - 2.0) / nf * (det / w) / w;
        if kappa.is_finite() && tau.is_finite() {
            Ok((kappa, tau))
        } else {
            Err(ClassAError::NonFinite {
                name: "curvature or torsion",
            })
        }
    };
    let (d0, d1, d2) = (leg(0), leg(1), leg(2));
    let (e0, e1, e2) = (leg(n - 3), leg(n - 2), leg(n - 1));
    let start = d0.cross(&d1);
    Ok([
        at(start, start.dot(&d2), d0, 0.0)?,
        at(e1.cross(&e2), e0.cross(&e1).dot(&e2), e2, 1.0)?,
    ])
}

impl TypicalPlanar {
    /// Signed end curvatures in closed form (module docs of the formulas):
    /// κ(0) = (n − 1) s sin θ / (nL) and κ(1) = (n − 1) sin θ / (n L sⁿ), evaluated through
    /// logarithms (never NaN; 0 or infinite only when the true value is beyond f64).
    #[must_use]
    pub fn end_curvatures(&self) -> (f64, f64) {
        let n = self.degree() as f64;
        let sin = self.theta().sin();
        if sin == 0.0 {
            return (0.0, 0.0);
        }
        let log_base = ((n - 1.0) * sin.abs() / n).ln() - self.length().ln();
        let log_s = self.s().ln();
        (
            sin.signum() * (log_base + log_s).exp(),
            sin.signum() * (log_base - n * log_s).exp(),
        )
    }
}

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
///   curve's to the prescribed ones by continuation (steps halved on failure).
///
/// Before the solve the prescribed curvatures are checked against what any curve of monotone
/// curvature with a convex control polygon in the tangent triangle α₀α₁α₂ can have: the
/// curvature has the sign of the turn ψ, and with κ monotone, |ψ| = ∫|κ| ds lies between
/// min(|κ₀|, |κ₁|)·S and max(|κ₀|, |κ₁|)·S, where the arc length S is above the chord |α₂ − α₀|
/// and below |α₁ − α₀| + |α₂ − α₁|; hence min |κ| < |ψ| / |α₂ − α₀| and
/// max |κ| > |ψ| / (|α₁ − α₀| + |α₂ − α₁|). These are necessary, not sufficient: inside them the
/// solve can still fail (a fold of the five equations, or a solution whose curvature is not
/// monotone), which is an error, never an unchecked `Ok`.
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
/// [`ClassAError::NoConvergence`]; [`ClassAError::ToleranceNotMet`];
/// [`ClassAError::CurvatureNotMonotone`]; without curvatures, the errors of
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
    let cert = curvature_certificate(curve.as_bezier())?;
    if !cert.is_monotone() {
        return Err(ClassAError::CurvatureNotMonotone {
            verdict: cert.verdict,
        });
    }
    Ok(curve)
}

/// Residual tolerance of the Newton iteration (relative: chord 1, curvatures and turn divided by
/// their targets).
const NEWTON_TOLERANCE: f64 = 1e-13;
/// Newton iterations per continuation step.
const NEWTON_ITERATIONS: usize = 16;
/// Smallest continuation step before giving up.
const MIN_STEP: f64 = 1.0 / 1024.0;
/// Most continuation steps tried (accepted or halved).
const MAX_STEPS: usize = 256;

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
        let norm = |r: &[f64; 5]| r.iter().fold(0.0f64, |a, v| a.max(v.abs()));
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
            let mut lambda = 1.0;
            loop {
                let mut trial = x;
                for (t, d) in trial.iter_mut().zip(dx.iter()) {
                    *t += lambda * d;
                }
                if let Some((rt, _)) = self.residual(&trial, k0, k1)
                    && norm(&rt) < current
                {
                    (x, r) = (trial, rt);
                    break;
                }
                lambda *= 0.5;
                if lambda < 1e-4 {
                    return None;
                }
            }
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
    let mut x = [1.0 / sum.norm(), s * cs, -s * sn, s * sn, s * cs];
    let no_convergence = |residual: f64| ClassAError::NoConvergence {
        method: "G2 Hermite continuation",
        residual,
    };
    let (_, (c0, c1)) = system
        .residual(&x, 1.0, 1.0)
        .ok_or(no_convergence(f64::INFINITY))?;
    let (t0, t1s) = (k0 * tri.chord, k1 * tri.chord);
    let (mut tau, mut step) = (0.0f64, 1.0f64);
    for _ in 0..MAX_STEPS {
        if tau >= 1.0 {
            break;
        }
        let next = (tau + step).min(1.0);
        let target = |from: f64, to: f64| from + (to - from) * next;
        match system.newton(x, target(c0, t0), target(c1, t1s)) {
            Some(solved) => {
                (x, tau) = (solved, next);
                step = (2.0 * step).min(1.0);
            }
            None => {
                step *= 0.5;
                if step < MIN_STEP {
                    break;
                }
            }
        }
    }
    if tau < 1.0 {
        let r = system
            .residual(&x, t0, t1s)
            .map_or(f64::INFINITY, |(r, _)| {
                r.iter().fold(0.0f64, |a, v| a.max(v.abs()))
            });
        return Err(no_convergence(r));
    }
    // Back to the world frame: M_world = R M Rᵀ with R = [e1 e2], first leg L·|chord|·e1.
    let rot = Matrix2::new(e1.x(), e2.x(), e1.y(), e2.y());
    let m = rot * Matrix2::new(x[1], x[2], x[3], x[4]) * rot.transpose();
    let curve = ClassACurve::new(&start.point, &(e1 * (x[0] * tri.chord)), &m, degree)?;
    verify(&curve, start, end, tri.turn, k0, k1)?;
    Ok(curve)
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
    if (total - turn).abs() > INTERPOLATION_TOLERANCE {
        return Err(ClassAError::ToleranceNotMet {
            condition: "total turn",
            achieved: (total - turn).abs(),
            tolerance: INTERPOLATION_TOLERANCE,
        });
    }
    let (c0, c1) = end_curvatures(bezier)?;
    for (condition, got, want) in [("start curvature", c0, k0), ("end curvature", c1, k1)] {
        let achieved = (got / want - 1.0).abs();
        if achieved.is_nan() || achieved > INTERPOLATION_TOLERANCE {
            return Err(ClassAError::ToleranceNotMet {
                condition,
                achieved,
                tolerance: INTERPOLATION_TOLERANCE,
            });
        }
    }
    Ok(())
}
