//! The spatial Hermite solve with prescribed end curvature (G2 ends): [`hermite_spatial`].
//!
//! End points and end tangent directions fix a typical spatial curve's (s, u, θ, L) for each
//! degree and branch (the spatial solve), so its end curvatures and torsions are fixed too
//! ([`crate::TypicalSpatial::end_curvatures_torsions`]). Prescribing the curvatures needs the
//! general 3 × 3 matrix M: with the first leg L and M there are ten unknowns for the end point
//! (3), the end tangent (2), the two curvatures (2) and, where prescribed, the two osculating
//! planes (one each, given by the binormal): seven to nine equations, so the solve is
//! underdetermined and takes minimum-norm Newton steps from the typical curve.

use bez_core::{BezierForm, Vector, Vector3};

use crate::continuation::{
    NEWTON_ITERATIONS, NEWTON_TOLERANCE, backtrack, check_end_curvatures, continuation, max_norm,
    within_tolerance,
};
use crate::square::{Matrix, Matrix3};
use crate::{
    ClassACurve, ClassAError, INTERPOLATION_TOLERANCE, Interpolation, SpatialRequirement,
    TypicalSpatial, curvature_certificate, end_curvatures_torsions, torsion_certificate,
};

/// A spatial point with a tangent direction and, optionally, a curvature (positive) and the
/// binormal direction there (the normal of the osculating plane, oriented as tangent × normal):
/// an end of a segment ([`hermite_spatial`]) or a knot of a [`crate::SpatialClassASpline`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct SpatialKnot {
    /// The point.
    pub point: Vector3,
    /// The tangent direction (any non-zero length).
    pub tangent: Vector3,
    /// The curvature, if prescribed.
    pub curvature: Option<f64>,
    /// The binormal direction (any non-zero length, not parallel to the tangent; only its part
    /// normal to the tangent counts), if prescribed; only together with a curvature.
    pub binormal: Option<Vector3>,
}

impl SpatialKnot {
    /// A knot with point and tangent direction, curvature and osculating plane free.
    #[must_use]
    pub fn new(point: Vector3, tangent: Vector3) -> Self {
        Self {
            point,
            tangent,
            curvature: None,
            binormal: None,
        }
    }

    /// The knot with the curvature prescribed.
    #[must_use]
    pub fn with_curvature(self, curvature: f64) -> Self {
        Self {
            curvature: Some(curvature),
            ..self
        }
    }

    /// The knot with the binormal direction (the osculating plane) prescribed.
    #[must_use]
    pub fn with_binormal(self, binormal: Vector3) -> Self {
        Self {
            binormal: Some(binormal),
            ..self
        }
    }

    /// The unit tangent, after checking every field (finite point, non-zero finite tangent,
    /// finite curvature, binormal only with a curvature and not parallel to the tangent).
    fn unit_tangent(&self) -> Result<Vector3, ClassAError> {
        crate::error::check_point(&self.point, "knot point")?;
        let t = unit(&self.tangent, "knot tangent")?;
        if self.curvature.is_some_and(|k| !k.is_finite()) {
            return Err(ClassAError::NonFinite {
                name: "knot curvature",
            });
        }
        if let Some(b) = self.binormal {
            if self.curvature.is_none() {
                return Err(ClassAError::InvalidParameter {
                    name: "binormal",
                    value: b.norm(),
                    expected: "prescribed only together with a curvature",
                });
            }
            self.unit_binormal(&t)?;
        }
        Ok(t)
    }

    /// The binormal's unit part normal to the unit tangent `t`, if prescribed.
    fn unit_binormal(&self, t: &Vector3) -> Result<Option<Vector3>, ClassAError> {
        let Some(b) = self.binormal else {
            return Ok(None);
        };
        let b = unit(&b, "knot binormal")?;
        let normal = b - *t * b.dot(t);
        if normal.norm() < 1e-9 {
            return Err(ClassAError::InvalidParameter {
                name: "|binormal × tangent| / (|binormal| |tangent|)",
                value: normal.norm(),
                expected: "at least 1e-9 (a binormal not parallel to the tangent)",
            });
        }
        Ok(Some(normal / normal.norm()))
    }
}

/// v / |v| for a finite non-zero v.
fn unit(v: &Vector3, name: &'static str) -> Result<Vector3, ClassAError> {
    if !v.is_finite() {
        return Err(ClassAError::NonFinite { name });
    }
    let norm = v.norm();
    if !(norm > 0.0 && norm.is_finite()) {
        return Err(ClassAError::InvalidParameter {
            name,
            value: norm,
            expected: "a non-zero finite length",
        });
    }
    Ok(v / norm)
}

/// The spatial Class A curve of degree n from `start` to `end` with their tangent directions,
/// and with their curvatures (and binormals, where given) when both curvatures are prescribed
/// (G2 ends); the curve's curvature and torsion are proven monotone
/// ([`curvature_certificate`], [`torsion_certificate`]) before it is returned.
///
/// * Neither curvature given: the typical spatial curve through α₀ = start, α₁ = start + t₀,
///   α₂ = end − t₁, α₃ = end ([`TypicalSpatial::solve`] with
///   [`SpatialRequirement::MonotoneTorsion`]; only the tangent directions matter), whose end
///   curvatures and torsions are then fixed by the data and n
///   ([`TypicalSpatial::end_curvatures_torsions`]).
/// * Both given: a general matrix M and first leg length L (ten unknowns) solved for the end
///   point, the end tangent, the two curvatures and the prescribed binormals (seven to nine
///   equations). In coordinates with the chord scaled to length 1, the unknowns start at the
///   typical curve's (the least-turning converged solution of the spatial solve if none is
///   Class A) and Gauss–Newton with minimum-norm steps (central-difference Jacobian,
///   backtracking) follows the curvatures (geometrically) and the binormals (by rotation about
///   the tangent) from the typical curve's to the prescribed ones by continuation (steps halved
///   on failure). An unprescribed binormal is free: the step that changes the curve least
///   decides it.
///
/// Necessary conditions checked first: the curvatures are positive (a space curve's curvature
/// is |x' × x''| / |x'|³ ≥ 0, and a prescribed osculating plane needs it non-zero). No other
/// bound follows from the end data alone in space: the turn between the end tangents bounds the
/// total curvature ∫κ ds only from below, and the arc length has no upper bound from the data
/// (helices of any given curvature join two points with arcs as long as one likes), so unlike the planar
/// [`crate::hermite_planar`] there is no reachable range to report; the solve's reach is
/// measured (crate docs). Inside it the continuation can still stall (`NoConvergence`) or end
/// at a curve whose curvature or torsion is not monotone: an error, never an unchecked `Ok`.
///
/// The result is verified on its rounded control points: end points and tangents within
/// [`INTERPOLATION_TOLERANCE`] ([`Interpolation`]), the end curvatures
/// ([`end_curvatures_torsions`]) within [`INTERPOLATION_TOLERANCE`] relative, the binormals
/// Δb₀ × Δb₁ and Δbₙ₋₂ × Δbₙ₋₁ within [`INTERPOLATION_TOLERANCE`] rad of the prescribed ones,
/// curvature and torsion proven monotone. What is guaranteed is these proofs, not Farin's
/// matrix conditions (check them with [`crate::ClassAReport::of_3x3`]).
///
/// ```
/// use bez_core::{BezierForm, Vector3};
/// use class_a::{SpatialKnot, end_curvatures_torsions, hermite_spatial};
/// let start = SpatialKnot::new(Vector3::new(0.0, 0.0, 0.0), Vector3::new(1.0, 0.0, 0.2));
/// let end = SpatialKnot::new(Vector3::new(6.12, 9.44, 2.73), Vector3::new(-0.09, 2.9, 0.94));
/// // G1: the typical curve; its end curvatures follow from the data and the degree.
/// let g1 = hermite_spatial(&start, &end, 7)?;
/// let [(k0, _), (k1, _)] = end_curvatures_torsions(g1.as_bezier())?;
/// // G2: prescribe them 5 % apart from the typical pair.
/// let (start, end) = (start.with_curvature(k0 * 1.05), end.with_curvature(k1 / 1.05));
/// let g2 = hermite_spatial(&start, &end, 7)?;
/// let [(c0, _), (c1, _)] = end_curvatures_torsions(g2.as_bezier())?;
/// assert!((c0 / (1.05 * k0) - 1.0).abs() < 1e-9 && (c1 * 1.05 / k1 - 1.0).abs() < 1e-9);
/// # Ok::<(), class_a::ClassAError>(())
/// ```
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] (n < 3: torsion needs a cubic) /
/// [`ClassAError::DegreeTooHigh`]; for the knots [`ClassAError::NonFinite`],
/// [`ClassAError::InvalidParameter`] (a zero tangent, a curvature given at one end only, a
/// binormal without a curvature or parallel to the tangent),
/// [`ClassAError::CoincidentPoints`], [`ClassAError::ParallelTangents`];
/// [`ClassAError::CurvatureUnreachable`] for a curvature ≤ 0; [`ClassAError::NoConvergence`];
/// [`ClassAError::ToleranceNotMet`]; [`ClassAError::CurvatureNotMonotone`];
/// [`ClassAError::TorsionNotMonotone`]; the errors of the spatial solve
/// ([`TypicalSpatial::solve`]) and of the certificates ([`ClassAError::Singular`]).
pub fn hermite_spatial(
    start: &SpatialKnot,
    end: &SpatialKnot,
    degree: usize,
) -> Result<ClassACurve<3>, ClassAError> {
    crate::error::check_degree(degree, 3)?;
    let (t0, t1) = (start.unit_tangent()?, end.unit_tangent()?);
    let chord = end.point - start.point;
    let c = chord.norm();
    if c == 0.0 {
        return Err(ClassAError::CoincidentPoints {
            first: 0,
            second: 3,
        });
    }
    let a = [
        start.point,
        start.point + t0 * c,
        end.point - t1 * c,
        end.point,
    ];
    let curve = match (start.curvature, end.curvature) {
        (None, None) => {
            let t = TypicalSpatial::solve(&a, degree, SpatialRequirement::MonotoneTorsion)?;
            ClassACurve::try_from(&t)?
        }
        (Some(k0), Some(k1)) => {
            for (end, k) in [("start", k0), ("end", k1)] {
                if k <= 0.0 {
                    return Err(ClassAError::CurvatureUnreachable {
                        end,
                        curvature: k,
                        lower: 0.0,
                        upper: f64::INFINITY,
                        reason: "a space curve's curvature is positive where its osculating plane is defined",
                    });
                }
            }
            let targets = Targets {
                k0: k0 * c,
                k1: k1 * c,
                b0: start.unit_binormal(&t0)?,
                b1: end.unit_binormal(&t1)?,
            };
            solve_g2(&a, &t0, &t1, &targets, degree)?
        }
        (Some(value), None) | (None, Some(value)) => {
            return Err(ClassAError::InvalidParameter {
                name: "curvature",
                value,
                expected: "prescribed at both ends or at neither",
            });
        }
    };
    let bezier = curve.as_bezier();
    let kappa = curvature_certificate(bezier)?;
    if !kappa.is_monotone() {
        return Err(ClassAError::CurvatureNotMonotone {
            verdict: kappa.verdict,
        });
    }
    let tau = torsion_certificate(bezier)?;
    if !tau.is_monotone() {
        return Err(ClassAError::TorsionNotMonotone {
            verdict: tau.verdict,
        });
    }
    Ok(curve)
}

/// Unknowns: L and the nine entries of M (row-major).
const UNKNOWNS: usize = 10;
/// Equations: end point (3), end tangent (2), curvatures (2), binormals (2, zero when free).
const EQUATIONS: usize = 9;

/// Targets of one continuation step, in coordinates with the chord of length 1.
#[derive(Debug, Clone, Copy)]
struct Targets {
    k0: f64,
    k1: f64,
    b0: Option<Vector3>,
    b1: Option<Vector3>,
}

/// The curve's own end curvatures and binormals (unit), in the scaled coordinates.
#[derive(Debug, Clone, Copy)]
struct Ends {
    k0: f64,
    k1: f64,
    b0: Vector3,
    b1: Vector3,
}

/// The end conditions in coordinates with the chord of length 1.
struct System {
    degree: usize,
    t0: Vector3,
    chord: Vector3,
    /// An orthonormal pair normal to the end tangent.
    normal_to_t1: [Vector3; 2],
}

impl System {
    /// Residuals at x = (L, M row-major) for the targets (module docs): Σ Mʲv − chord, the end
    /// leg's direction normal to t₁, κ(0)/k₀ − 1, κ(1)/k₁ − 1, and the second (last but one)
    /// leg's component along a prescribed start (end) binormal over its length (0 when free).
    /// Also the curve's own end values. None when a value is not finite or a leg vanishes.
    fn residual(&self, x: &[f64; UNKNOWNS], t: &Targets) -> Option<([f64; EQUATIONS], Ends)> {
        let m = matrix(x);
        let n = self.degree;
        let first = self.t0 * x[0];
        let mut leg = first;
        let mut sum = Vector3::zeros();
        let mut before_last = first;
        for j in 0..n {
            sum += leg;
            if j + 1 == n {
                break;
            }
            before_last = leg;
            leg = m * leg;
        }
        let (second, last) = (m * first, leg);
        let factor = (n - 1) as f64 / n as f64;
        let (w0, w1) = (first.cross(&second), before_last.cross(&last));
        let (n0, nl) = (first.norm(), last.norm());
        let (ends, ok) = (
            Ends {
                k0: factor * w0.norm() / (n0 * n0 * n0),
                k1: factor * w1.norm() / (nl * nl * nl),
                b0: w0 / w0.norm(),
                b1: w1 / w1.norm(),
            },
            n0 > 0.0 && nl > 0.0,
        );
        let along = |b: Option<Vector3>, v: &Vector3| b.map_or(0.0, |b| b.dot(v) / v.norm());
        let direction = last / nl;
        let r = [
            sum.x() - self.chord.x(),
            sum.y() - self.chord.y(),
            sum.z() - self.chord.z(),
            direction.dot(&self.normal_to_t1[0]),
            direction.dot(&self.normal_to_t1[1]),
            ends.k0 / t.k0 - 1.0,
            ends.k1 / t.k1 - 1.0,
            along(t.b0, &second),
            along(t.b1, &before_last),
        ];
        (ok && r.iter().all(|v| v.is_finite()) && ends.b0.is_finite() && ends.b1.is_finite())
            .then_some((r, ends))
    }

    /// Gauss–Newton with minimum-norm steps from x for the targets; Some(x) when converged.
    fn newton(&self, mut x: [f64; UNKNOWNS], t: &Targets) -> Option<[f64; UNKNOWNS]> {
        let norm = |r: &[f64; EQUATIONS]| max_norm(r);
        let active = [
            true,
            true,
            true,
            true,
            true,
            true,
            true,
            t.b0.is_some(),
            t.b1.is_some(),
        ];
        let (mut r, _) = self.residual(&x, t)?;
        for _ in 0..NEWTON_ITERATIONS {
            let current = norm(&r);
            if current <= NEWTON_TOLERANCE {
                return Some(x);
            }
            let mut jac = [[0.0; UNKNOWNS]; EQUATIONS];
            for j in 0..UNKNOWNS {
                let h = 1e-7 * (x[j].abs() + 1e-3);
                let (mut xp, mut xm) = (x, x);
                xp[j] += h;
                xm[j] -= h;
                let (rp, _) = self.residual(&xp, t)?;
                let (rm, _) = self.residual(&xm, t)?;
                for i in 0..EQUATIONS {
                    jac[i][j] = (rp[i] - rm[i]) / (2.0 * h);
                }
            }
            // Minimum-norm step dx = Jᵀy with (J Jᵀ) y = −r; a free equation has a zero row and
            // gets y = 0.
            let gram = Matrix::<EQUATIONS>::from_fn(|i, k| {
                if !active[i] || !active[k] {
                    f64::from(u8::from(i == k))
                } else {
                    (0..UNKNOWNS).map(|j| jac[i][j] * jac[k][j]).sum()
                }
            });
            let y = gram
                .solve(&Vector::from_array(r.map(|v| -v)))
                .ok()?
                .to_array();
            let dx: [f64; UNKNOWNS] =
                std::array::from_fn(|j| (0..EQUATIONS).map(|i| jac[i][j] * y[i]).sum());
            (x, r) = backtrack(&x, &dx, current, |trial| {
                self.residual(trial, t).map(|(r, _)| r)
            })?;
        }
        (norm(&r) <= NEWTON_TOLERANCE).then_some(x)
    }
}

/// M from the unknowns (entries 1..10, row-major).
fn matrix(x: &[f64; UNKNOWNS]) -> Matrix3 {
    Matrix3::from_fn(|i, j| x[1 + 3 * i + j])
}

/// A unit vector normal to the unit vector t, and t × it.
fn normal_pair(t: &Vector3) -> [Vector3; 2] {
    let helper = if t.x().abs() < 0.6 {
        Vector3::new(1.0, 0.0, 0.0)
    } else {
        Vector3::new(0.0, 1.0, 0.0)
    };
    let e = t.cross(&helper);
    let e = e / e.norm();
    [e, t.cross(&e)]
}

/// `from` turned about the unit axis t towards `to` by the fraction `f` of the angle between
/// them (both normal to t).
fn turn_towards(from: &Vector3, to: &Vector3, t: &Vector3, f: f64) -> Vector3 {
    let angle = from.cross(to).dot(t).atan2(from.dot(to));
    let (sin, cos) = (f * angle).sin_cos();
    *from * cos + t.cross(from) * sin
}

/// The typical spatial curve of the G1 data, the start of the continuation: the least-turning
/// Class A one, else the least-turning converged solution.
fn typical_start(a: &[Vector3; 4], degree: usize) -> Result<TypicalSpatial, ClassAError> {
    TypicalSpatial::from_points(a, degree).or_else(|e| {
        TypicalSpatial::candidates(a, degree)?
            .into_iter()
            .min_by(|x, y| x.theta.abs().total_cmp(&y.theta.abs()))
            .ok_or(e)
    })
}

/// The general-matrix solve of [`hermite_spatial`] (both curvatures given, already checked;
/// `targets` scaled to the chord of length 1).
fn solve_g2(
    a: &[Vector3; 4],
    t0: &Vector3,
    t1: &Vector3,
    targets: &Targets,
    degree: usize,
) -> Result<ClassACurve<3>, ClassAError> {
    let chord = a[3] - a[0];
    let c = chord.norm();
    let system = System {
        degree,
        t0: *t0,
        chord: chord / c,
        normal_to_t1: normal_pair(t1),
    };
    let typical = typical_start(a, degree)?;
    let m = typical.matrix();
    let mut x = [0.0; UNKNOWNS];
    x[0] = typical.length / c;
    for i in 0..3 {
        for j in 0..3 {
            x[1 + 3 * i + j] = m[(i, j)];
        }
    }
    let no_convergence = |residual: f64| ClassAError::NoConvergence {
        method: "spatial G2 Hermite continuation",
        residual,
    };
    let (_, from) = system
        .residual(&x, targets)
        .ok_or(no_convergence(f64::INFINITY))?;
    let at = |f: f64| Targets {
        k0: from.k0 * (targets.k0 / from.k0).powf(f),
        k1: from.k1 * (targets.k1 / from.k1).powf(f),
        b0: targets.b0.map(|b| turn_towards(&from.b0, &b, t0, f)),
        b1: targets.b1.map(|b| turn_towards(&from.b1, &b, t1, f)),
    };
    let (x, reached) = continuation(x, |from, next| {
        system.newton(from, &if next >= 1.0 { *targets } else { at(next) })
    });
    if !reached {
        let r = system
            .residual(&x, targets)
            .map_or(f64::INFINITY, |(r, _)| max_norm(&r));
        return Err(no_convergence(r));
    }
    let curve = ClassACurve::new(&a[0], &(*t0 * (x[0] * c)), &matrix(&x), degree)?;
    verify(&curve, a, t0, t1, targets, c)?;
    Ok(curve)
}

/// The checks of [`hermite_spatial`] on the rounded control points (targets scaled by the chord
/// length `c`).
fn verify(
    curve: &ClassACurve<3>,
    a: &[Vector3; 4],
    t0: &Vector3,
    t1: &Vector3,
    targets: &Targets,
    c: f64,
) -> Result<(), ClassAError> {
    let p = curve.as_bezier().points();
    Interpolation::measure(p, &a[0], t0, t1, &a[3]).within(INTERPOLATION_TOLERANCE)?;
    let [(c0, _), (c1, _)] = end_curvatures_torsions(curve.as_bezier())?;
    check_end_curvatures([c0 * c, c1 * c], [targets.k0, targets.k1])?;
    let n = p.len() - 1;
    let leg = |i: usize| p[i + 1] - p[i];
    for (condition, want, got) in [
        ("start binormal", targets.b0, leg(0).cross(&leg(1))),
        ("end binormal", targets.b1, leg(n - 2).cross(&leg(n - 1))),
    ] {
        if let Some(b) = want {
            let g = got / got.norm();
            within_tolerance(condition, 2.0 * (0.5 * (g - b).norm()).min(1.0).asin())?;
        }
    }
    Ok(())
}
