//! Assembly of the residual map and the four solvers on one trial space.
//!
//! Every global system is sparse: each patch touches only the (n+1)(m+1) spline
//! coefficients of its support, so assembly is linear in the number of patches and the
//! solves are sparse Cholesky (Galerkin with every side fixed or periodic, when the system is
//! definite), sparse LU (collocation, other Galerkin systems) or sparse Householder QR (the two least
//! squares methods, which never form normal equations).

use crate::bernstein_ops::{
    bernstein_values, derivative_matrix, elevation_matrix, gram_matrix, gram_root,
};
use crate::boundary::fit;
use crate::dense::Dense;
use crate::error::PdeError;
use crate::grid::PatchGrid;
use crate::limits;
use crate::problem::{Discretization, Problem, Side};
use crate::space::{End, Space};
use crate::sparse::{Kind, Storage, System};
use crate::spline_surface::BSplineSurface;
use bez_core::{BezierSurface, Vector3};

/// Control points fixed by the sides (None = free) and the largest boundary-fit error.
type Fixed = (Vec<Option<Vector3>>, f64);

/// How the free control points are determined.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Method {
    /// The paper's objective (4): minimize Σ_patches h_u h_v Σ_ij |b_ij|², the squared
    /// Bernstein coefficients of the residual R = L P − F (area-weighted, Sec. 3).
    /// Solved by sparse Householder QR.
    BernsteinLeastSquares,
    /// The exact L² norm ∫∫ |R|² du dv, as ‖(Q_u ⊗ Q_v) b‖² with Q a square root of the
    /// Bernstein Gram matrix at Gauss–Legendre points; solved by sparse Householder QR.
    IntegralLeastSquares,
    /// Bloor–Wilson collocation: R = 0 at the Greville points of the free coefficients.
    Collocation,
    /// Bloor–Wilson Galerkin: ∫∫ R φ = 0 for every free basis function φ.
    Galerkin,
}

impl Method {
    /// All four methods.
    pub const ALL: [Self; 4] = [
        Self::Collocation,
        Self::Galerkin,
        Self::BernsteinLeastSquares,
        Self::IntegralLeastSquares,
    ];

    /// A short name.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::BernsteinLeastSquares => "bernstein least squares",
            Self::IntegralLeastSquares => "integral least squares",
            Self::Collocation => "collocation",
            Self::Galerkin => "galerkin",
        }
    }
}

/// The result of a solve.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "SolutionParts"))]
#[non_exhaustive]
pub struct Solution {
    /// The approximating surface.
    pub surface: PatchGrid,
    /// The paper's objective M = Σ_patches h_u h_v Σ_ij |b_ij|² at the solution (eq. (4)),
    /// saturated at `f64::MAX` for operators whose coefficients square past the f64 range.
    pub objective: f64,
    /// The convex-hull bound max |b_ij| ≥ max |R(u, v)| (Sec. 3).
    pub residual_bound: f64,
    /// The largest sample error of the boundary fits (0 up to rounding for polynomial data).
    pub boundary_fit_error: f64,
    /// Number of free control points (unknowns per coordinate).
    pub unknowns: usize,
    /// Estimated condition number of the solved (scaled: unit diagonal for a symmetric
    /// definite system, else unit rows and columns) system: the
    /// Frobenius condition number ‖A‖_F ‖A⁺‖_F ≥ κ₂, from random probes (1 when there is
    /// nothing to solve). About log₁₀ of it digits of the coefficients may be lost.
    pub condition: f64,
    /// The same surface as one clamped B-spline surface (C^r joins as knot multiplicities).
    pub spline: BSplineSurface,
}

/// The serialized form of a [`Solution`], checked on the way in: the measures finite and
/// non-negative, the surface a valid grid (checked by its own deserialization) and the spline
/// valid.
#[cfg(feature = "serde")]
#[derive(serde::Deserialize)]
struct SolutionParts {
    surface: PatchGrid,
    objective: f64,
    residual_bound: f64,
    boundary_fit_error: f64,
    unknowns: usize,
    condition: f64,
    spline: BSplineSurface,
}

#[cfg(feature = "serde")]
impl TryFrom<SolutionParts> for Solution {
    type Error = PdeError;
    fn try_from(raw: SolutionParts) -> Result<Self, PdeError> {
        for (what, value) in [
            ("objective", raw.objective),
            ("residual bound", raw.residual_bound),
            ("boundary fit error", raw.boundary_fit_error),
            ("condition estimate", raw.condition),
        ] {
            if !value.is_finite() || value < 0.0 {
                return Err(PdeError::InvalidSolution { what, value });
            }
        }
        raw.spline.validate()?;
        Ok(Self {
            surface: raw.surface,
            objective: raw.objective,
            residual_bound: raw.residual_bound,
            boundary_fit_error: raw.boundary_fit_error,
            unknowns: raw.unknowns,
            condition: raw.condition,
            spline: raw.spline,
        })
    }
}

/// A problem assembled on a trial space: the residual map of every patch, the fixed control
/// points and the right-hand side, ready for any [`Method`].
///
/// Assembly is O(P · ((n+1)(m+1))³) for P patches, linear in P; the solves are sparse.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Assembly {
    su: Space,
    sv: Space,
    /// Residual degrees (l, r).
    l: usize,
    r: usize,
    patches: Vec<PatchMap>,
    fixed: Vec<Option<Vector3>>,
    fit_error: f64,
    k: usize,
    /// The operator and F were divided by this (the largest |coefficient|).
    scale: f64,
    /// Every direction is periodic or has both sides fixed: the boundary data determines
    /// the solution, so a numerically singular system is ill-conditioned, not undetermined.
    determined: bool,
}

#[derive(Debug, Clone)]
struct PatchMap {
    /// Patch indices (pu, pv).
    at: (usize, usize),
    /// Global coefficient indices of the local unknowns.
    support: Vec<usize>,
    /// (l+1)(r+1) × support.len(): residual Bernstein coefficients of L P.
    map: Dense,
    /// (l+1)(r+1) × 3: Bernstein coefficients of F.
    target: Dense,
}

const SIDE_NAMES: [&str; 4] = ["u=0", "u=1", "v=0", "v=1"];

impl Assembly {
    /// Assembles `problem` on the trial space `disc`.
    ///
    /// # Errors
    /// [`PdeError::TooLarge`] for sizes over the crate's limits ([`crate::MAX_SOLVE_DEGREE`],
    /// [`crate::MAX_PATCHES`], [`crate::MAX_COEFFICIENTS`], [`crate::MAX_LOCAL_ENTRIES`]),
    /// [`PdeError::NotElliptic`], [`PdeError::PeriodicMismatch`], [`PdeError::SideDataCount`],
    /// [`PdeError::DegreeTooLow`], [`PdeError::Smoothness`] (r < k − 1 between patches),
    /// [`PdeError::NoPatches`], boundary-fit errors and [`PdeError::CornerMismatch`] when
    /// adjacent sides disagree.
    pub fn new(problem: &Problem, disc: &Discretization) -> Result<Self, PdeError> {
        limits::check(disc)?;
        problem.operator.check_elliptic()?;
        let k = problem.operator.order();
        let half = k / 2;
        let sides = [&problem.u0, &problem.u1, &problem.v0, &problem.v1];
        for (pair, names) in [(0, ["u=0", "u=1"]), (2, ["v=0", "v=1"])] {
            let a = matches!(sides[pair], Side::Periodic);
            let b = matches!(sides[pair + 1], Side::Periodic);
            if a != b {
                return Err(PdeError::PeriodicMismatch {
                    side: if a { names[0] } else { names[1] },
                });
            }
        }
        for (s, side) in sides.iter().enumerate() {
            if let Side::Fixed(curves) = side
                && curves.len() != half
            {
                return Err(PdeError::SideDataCount {
                    side: SIDE_NAMES[s],
                    given: curves.len(),
                    expected: half,
                    order: k,
                });
            }
        }
        let periodic_u = matches!(problem.u0, Side::Periodic);
        let periodic_v = matches!(problem.v0, Side::Periodic);
        for (dir, degree, patches, smooth, periodic) in [
            (
                "u",
                disc.degree_u,
                disc.patches_u,
                disc.smoothness_u,
                periodic_u,
            ),
            (
                "v",
                disc.degree_v,
                disc.patches_v,
                disc.smoothness_v,
                periodic_v,
            ),
        ] {
            if (patches > 1 || periodic) && smooth.saturating_add(1) < k {
                return Err(PdeError::Smoothness {
                    direction: dir,
                    smoothness: smooth,
                    min: k - 1,
                    max: degree.saturating_sub(1),
                    why: "the residual objective needs r ≥ k − 1, or patches may kink at the joins with zero residual",
                });
            }
        }
        let su = Space::new(
            "u",
            disc.degree_u,
            disc.patches_u,
            disc.smoothness_u,
            periodic_u,
        )?;
        let sv = Space::new(
            "v",
            disc.degree_v,
            disc.patches_v,
            disc.smoothness_v,
            periodic_v,
        )?;
        for (dir, space, a, b) in [
            ("u", &su, sides[0], sides[1]),
            ("v", &sv, sides[2], sides[3]),
        ] {
            let rows = usize::from(matches!(a, Side::Fixed(_))) * half
                + usize::from(matches!(b, Side::Fixed(_))) * half;
            if rows > space.n_coef {
                return Err(PdeError::DegreeTooLow {
                    direction: dir,
                    degree: space.degree,
                    needed: space.degree + rows - space.n_coef,
                    why: "the boundary rows of opposite sides overlap",
                });
            }
        }
        let (fu, fv) = problem
            .rhs
            .as_ref()
            .map_or((0, 0), |f| (f.degree_u(), f.degree_v()));
        for (what, degree) in [("degree of F in u", fu), ("degree of F in v", fv)] {
            if degree > limits::MAX_SOLVE_DEGREE {
                return Err(PdeError::TooLarge {
                    what,
                    value: degree,
                    limit: limits::MAX_SOLVE_DEGREE,
                });
            }
        }
        let terms = problem.operator.terms();
        // L and F are divided by the largest |c|: the solution is unchanged, and
        // coefficients of any finite size give entries of order one.
        let scale = terms.iter().map(|t| t.coeff.abs()).fold(0.0, f64::max);
        let l = terms
            .iter()
            .map(|t| disc.degree_u.saturating_sub(t.du))
            .chain([fu])
            .max()
            .unwrap_or(0);
        let r = terms
            .iter()
            .map(|t| disc.degree_v.saturating_sub(t.dv))
            .chain([fv])
            .max()
            .unwrap_or(0);
        let (fixed, fit_error) = fixed_points(problem, &su, &sv, half)?;
        // 1D residual factors K^{(p)} = h^{−p} Elev(n−p → l) D^p Ext per piece.
        let factor = |space: &Space, p: usize, to: usize| -> Vec<Dense> {
            let deg = space.degree;
            let d = derivative_matrix(deg, p);
            let from = deg.saturating_sub(p);
            let e = elevation_matrix(from, to);
            let ed = (&e * &d).scaled(space.width().powi(-(p as i32)));
            space.pieces.iter().map(|piece| &ed * &piece.ext).collect()
        };
        let ku: Vec<Vec<Dense>> = terms.iter().map(|t| factor(&su, t.du, l)).collect();
        let kv: Vec<Vec<Dense>> = terms.iter().map(|t| factor(&sv, t.dv, r)).collect();
        let nv = sv.n_coef;
        let mut patches = Vec::with_capacity(disc.patches_u * disc.patches_v);
        for (pu, piece_u) in su.pieces.iter().enumerate() {
            for (pv, piece_v) in sv.pieces.iter().enumerate() {
                let mut map = Dense::zeros(
                    (l + 1) * (r + 1),
                    piece_u.support.len() * piece_v.support.len(),
                );
                for (ti, term) in terms.iter().enumerate() {
                    map.add_scaled(&ku[ti][pu].kron(&kv[ti][pv]), term.coeff / scale);
                }
                let support = piece_u
                    .support
                    .iter()
                    .flat_map(|&a| piece_v.support.iter().map(move |&b| a * nv + b))
                    .collect();
                let target = rhs_on_patch(problem.rhs.as_ref(), &su, &sv, (pu, pv), (l, r))?
                    .scaled(1.0 / scale);
                patches.push(PatchMap {
                    at: (pu, pv),
                    support,
                    map,
                    target,
                });
            }
        }
        let both_fixed = |a: &Side, b: &Side| matches!((a, b), (Side::Fixed(_), Side::Fixed(_)));
        let determined = (periodic_u || both_fixed(&problem.u0, &problem.u1))
            && (periodic_v || both_fixed(&problem.v0, &problem.v1));
        Ok(Self {
            su,
            sv,
            l,
            r,
            patches,
            fixed,
            fit_error,
            k,
            scale,
            determined,
        })
    }

    /// Number of free control points.
    #[must_use]
    pub fn unknowns(&self) -> usize {
        self.fixed.iter().filter(|f| f.is_none()).count()
    }

    /// The PDE order k.
    #[must_use]
    pub fn order(&self) -> usize {
        self.k
    }

    /// Solves for the free control points with `method` (three right-hand sides x, y, z).
    ///
    /// # Errors
    /// [`PdeError::Undetermined`] when the boundary data leaves the system rank deficient
    /// (a direction that is neither periodic nor fixed on both sides, or an exactly singular
    /// system); a numerically singular system under such data is [`PdeError::IllConditioned`];
    /// [`PdeError::IllConditioned`] when its condition estimate is above
    /// [`crate::CONDITION_LIMIT`].
    pub fn solve(&self, method: Method) -> Result<Solution, PdeError> {
        self.solve_with(method, Storage::Auto)
    }

    /// [`Assembly::solve`] with the storage of the linear system chosen by the caller:
    /// [`Storage::Auto`] (what `solve` does) picks the faster of dense and sparse by the
    /// number of unknowns; [`Storage::Dense`] and [`Storage::Sparse`] force one, for
    /// measurements and comparisons. The answers agree to rounding.
    ///
    /// # Errors
    /// Those of [`Assembly::solve`].
    pub fn solve_with(&self, method: Method, storage: Storage) -> Result<Solution, PdeError> {
        let n_all = self.fixed.len();
        let mut index = vec![usize::MAX; n_all];
        let mut free = Vec::new();
        for (g, f) in self.fixed.iter().enumerate() {
            if f.is_none() {
                index[g] = free.len();
                free.push(g);
            }
        }
        let nf = free.len();
        let mut coefs: Vec<Vector3> = self.fixed.iter().map(|f| f.unwrap_or_default()).collect();
        let mut condition = 1.0;
        if nf > 0 {
            let (system, kind) = match method {
                Method::Collocation => (self.collocation_system(&index, nf), Kind::Square),
                // With every side fixed or periodic the free test functions vanish on the
                // boundary with their first k/2 − 1 derivatives, so integration by parts
                // makes ∫∫ φ L ψ symmetric (every term has even order): Cholesky when ±A is
                // also definite.
                Method::Galerkin => (
                    self.galerkin_system(&index, nf),
                    if self.determined {
                        Kind::Symmetric
                    } else {
                        Kind::Square
                    },
                ),
                Method::BernsteinLeastSquares | Method::IntegralLeastSquares => (
                    self.least_squares_system(method, &index, nf),
                    Kind::LeastSquares,
                ),
            };
            let solved = match system.solve(kind, storage, method.name()) {
                // Well-posed boundary data: a finite but huge estimate is conditioning.
                Err(PdeError::Undetermined {
                    method,
                    unknowns,
                    condition,
                }) if self.determined && condition.is_finite() => {
                    return Err(PdeError::IllConditioned {
                        method,
                        unknowns,
                        condition,
                        limit: crate::CONDITION_LIMIT,
                    });
                }
                other => other?,
            };
            condition = solved.condition;
            for (k, &g) in free.iter().enumerate() {
                let [x, y, z] = solved.x[k];
                coefs[g] = Vector3::new(x, y, z);
            }
        }
        self.finish(&coefs, nf, condition)
    }

    /// The local residual rows with the fixed coefficients moved to the right-hand side:
    /// calls `emit(local row, global unknown, value)` and returns the right-hand side rows.
    fn eliminate(
        &self,
        patch: &PatchMap,
        rows: &Dense,
        target: &Dense,
        index: &[usize],
        mut emit: impl FnMut(usize, usize, f64),
    ) -> Vec<[f64; 3]> {
        (0..rows.nrows())
            .map(|ra| {
                let mut rhs = [target[(ra, 0)], target[(ra, 1)], target[(ra, 2)]];
                for (cb, &gb) in patch.support.iter().enumerate() {
                    let v = rows[(ra, cb)];
                    if v == 0.0 {
                        continue;
                    }
                    match self.fixed[gb] {
                        Some(p) => {
                            for (c, x) in rhs.iter_mut().enumerate() {
                                *x -= v * p[c];
                            }
                        }
                        None => emit(ra, index[gb], v),
                    }
                }
                rhs
            })
            .collect()
    }

    /// The stacked residual rows √(h_u h_v) W M c ≈ √(h_u h_v) W f of every patch, with
    /// W = I (Bernstein coefficients) or W = Q_l ⊗ Q_r (Gauss–Legendre root of the Gram
    /// matrix): the objective is the squared norm, minimized by QR.
    fn least_squares_system(&self, method: Method, index: &[usize], nf: usize) -> System {
        let rows_per = (self.l + 1) * (self.r + 1);
        let root_weight = (self.su.width() * self.sv.width()).sqrt();
        let w = match method {
            Method::IntegralLeastSquares => Some(gram_root(self.l).kron(&gram_root(self.r))),
            _ => None,
        };
        let mut system = System::new(self.patches.len() * rows_per, nf);
        for (p, patch) in self.patches.iter().enumerate() {
            let (rows, target) = match &w {
                Some(w) => (
                    (w * &patch.map).scaled(root_weight),
                    (w * &patch.target).scaled(root_weight),
                ),
                None => (
                    patch.map.clone().scaled(root_weight),
                    patch.target.clone().scaled(root_weight),
                ),
            };
            let base = p * rows_per;
            let rhs = self.eliminate(patch, &rows, &target, index, |ra, col, v| {
                system.push(base + ra, col, v);
            });
            for (ra, b) in rhs.into_iter().enumerate() {
                system.rhs[base + ra] = b;
            }
        }
        system
    }

    /// Σ_patches ∫∫ φ R = 0 for the free test functions φ (Galerkin).
    fn galerkin_system(&self, index: &[usize], nf: usize) -> System {
        let (n, m, l, r) = (self.su.degree, self.sv.degree, self.l, self.r);
        let weight = self.su.width() * self.sv.width();
        let gram = gram_matrix(n, l).kron(&gram_matrix(m, r));
        let mut system = System::new(nf, nf);
        for patch in &self.patches {
            let (pu, pv) = patch.at;
            let ext = self.su.pieces[pu].ext.kron(&self.sv.pieces[pv].ext);
            let tw = (&ext.transpose() * &gram).scaled(weight);
            let rows = &tw * &patch.map;
            let target = &tw * &patch.target;
            let rhs = self.eliminate(patch, &rows, &target, index, |ra, col, v| {
                let row = index[patch.support[ra]];
                if row != usize::MAX {
                    system.push(row, col, v);
                }
            });
            for (ra, b) in rhs.into_iter().enumerate() {
                let row = index[patch.support[ra]];
                if row != usize::MAX {
                    for (acc, x) in system.rhs[row].iter_mut().zip(b) {
                        *acc += x;
                    }
                }
            }
        }
        system
    }

    /// R = 0 at the tensor Greville points of the free coefficients.
    fn collocation_system(&self, index: &[usize], nf: usize) -> System {
        let nv = self.sv.n_coef;
        let mut system = System::new(nf, nf);
        for (g, &row) in index.iter().enumerate() {
            if row == usize::MAX {
                continue;
            }
            let (i, j) = (g / nv, g % nv);
            let (pu, s) = self.su.locate(self.su.greville[i]);
            let (pv, t) = self.sv.locate(self.sv.greville[j]);
            let patch = &self.patches[pu * self.sv.pieces.len() + pv];
            let bu = bernstein_values(self.l, s);
            let bv = bernstein_values(self.r, t);
            let w = Dense::from_fn(1, bu.len() * bv.len(), |_, k| {
                bu[k / bv.len()] * bv[k % bv.len()]
            });
            let lrow = &w * &patch.map;
            let target = &w * &patch.target;
            let rhs = self.eliminate(patch, &lrow, &target, index, |_, col, v| {
                system.push(row, col, v);
            });
            system.rhs[row] = rhs[0];
        }
        system
    }

    fn finish(
        &self,
        coefs: &[Vector3],
        unknowns: usize,
        condition: f64,
    ) -> Result<Solution, PdeError> {
        let weight = self.su.width() * self.sv.width();
        let mut objective = 0.0;
        let mut bound: f64 = 0.0;
        let mut surfaces = Vec::with_capacity(self.patches.len());
        let (n, m) = (self.su.degree, self.sv.degree);
        for patch in &self.patches {
            let local = Dense::from_fn(patch.support.len(), 3, |i, c| coefs[patch.support[i]][c]);
            let res = &patch.map * &local;
            for ra in 0..res.nrows() {
                let s: f64 = (0..3)
                    .map(|c| (res[(ra, c)] - patch.target[(ra, c)]).powi(2))
                    .sum();
                objective += weight * s;
                bound = bound.max(s.sqrt());
            }
            let (pu, pv) = patch.at;
            let ext = self.su.pieces[pu].ext.kron(&self.sv.pieces[pv].ext);
            let pts = &ext * &local;
            let points = (0..pts.nrows())
                .map(|i| Vector3::new(pts[(i, 0)], pts[(i, 1)], pts[(i, 2)]))
                .collect();
            surfaces.push(BezierSurface::from_flat(n, m, points)?);
        }
        // Back to the caller's scale of L and F; saturated at f64::MAX where the product
        // overflows (coefficients beyond about 1e154 square past the f64 range).
        let objective = (objective * self.scale * self.scale).min(f64::MAX);
        let residual_bound = (bound * self.scale).min(f64::MAX);
        for (what, value) in [("objective", objective), ("residual bound", residual_bound)] {
            if value.is_nan() {
                return Err(PdeError::NonFinite { what, value });
            }
        }
        Ok(Solution {
            spline: self.spline(coefs),
            surface: PatchGrid::new(self.su.pieces.len(), self.sv.pieces.len(), surfaces),
            objective,
            residual_bound,
            boundary_fit_error: self.fit_error,
            unknowns,
            condition,
        })
    }

    /// The clamped B-spline form: c_clamped = Z_u c Z_vᵀ (Z the sparse periodic closure, or I).
    fn spline(&self, coefs: &[Vector3]) -> BSplineSurface {
        let nv = self.sv.n_coef;
        let expand = |space: &Space| -> Vec<Vec<(usize, f64)>> {
            space
                .to_clamped
                .clone()
                .unwrap_or_else(|| (0..space.n_coef).map(|i| vec![(i, 1.0)]).collect())
        };
        let (zu, zv) = (expand(&self.su), expand(&self.sv));
        let mut points = Vec::with_capacity(zu.len() * zv.len());
        for ru in &zu {
            for rv in &zv {
                let mut p = Vector3::zeros();
                for &(i, wu) in ru {
                    for &(j, wv) in rv {
                        p += coefs[i * nv + j] * (wu * wv);
                    }
                }
                points.push(p);
            }
        }
        BSplineSurface {
            degree_u: self.su.degree,
            degree_v: self.sv.degree,
            knots_u: self.su.knots.clone(),
            knots_v: self.sv.knots.clone(),
            points,
        }
    }
}

/// Solves `problem` on `disc` with `method` (assembly and solve in one call).
///
/// # Errors
/// Those of [`Assembly::new`] and [`Assembly::solve`].
pub fn solve(
    problem: &Problem,
    disc: &Discretization,
    method: Method,
) -> Result<Solution, PdeError> {
    Assembly::new(problem, disc)?.solve(method)
}

/// Bernstein coefficients of F restricted to patch (pu, pv), elevated to (l, r).
fn rhs_on_patch(
    rhs: Option<&BezierSurface<3>>,
    su: &Space,
    sv: &Space,
    (pu, pv): (usize, usize),
    (l, r): (usize, usize),
) -> Result<Dense, PdeError> {
    let count = (l + 1) * (r + 1);
    let Some(f) = rhs else {
        return Ok(Dense::zeros(count, 3));
    };
    let restrict_u = |s: &BezierSurface<3>, a: f64, b: f64| -> Result<BezierSurface<3>, PdeError> {
        let s = if b < 1.0 { s.split_u(b)?.0 } else { s.clone() };
        Ok(if a > 0.0 { s.split_u(a / b)?.1 } else { s })
    };
    let restrict_v = |s: &BezierSurface<3>, a: f64, b: f64| -> Result<BezierSurface<3>, PdeError> {
        let s = if b < 1.0 { s.split_v(b)?.0 } else { s.clone() };
        Ok(if a > 0.0 { s.split_v(a / b)?.1 } else { s })
    };
    let (hu, hv) = (su.width(), sv.width());
    let s = restrict_u(f, pu as f64 * hu, ((pu + 1) as f64 * hu).min(1.0))?;
    let s = restrict_v(&s, pv as f64 * hv, ((pv + 1) as f64 * hv).min(1.0))?;
    let s = s.elevate_u(l - s.degree_u())?.elevate_v(r - s.degree_v())?;
    Ok(Dense::from_fn(count, 3, |i, c| s.points()[i][c]))
}

/// The control points fixed by the sides, with corner consistency checked.
fn fixed_points(problem: &Problem, su: &Space, sv: &Space, half: usize) -> Result<Fixed, PdeError> {
    let (nu, nv) = (su.n_coef, sv.n_coef);
    let mut fixed: Vec<Option<(Vector3, usize)>> = vec![None; nu * nv];
    let mut fit_error: f64 = 0.0;
    let sides = [&problem.u0, &problem.u1, &problem.v0, &problem.v1];
    let is_fixed = |s: &Side| matches!(s, Side::Fixed(_));
    for (s, side) in sides.iter().enumerate() {
        let Side::Fixed(curves) = side else { continue };
        let along_u = s >= 2; // v-sides carry curves in u.
        let (along, across) = if along_u { (su, sv) } else { (sv, su) };
        let end = if s % 2 == 1 { End::Finish } else { End::Start };
        let (clamp_a, clamp_b) = if along_u {
            (is_fixed(sides[0]), is_fixed(sides[1]))
        } else {
            (is_fixed(sides[2]), is_fixed(sides[3]))
        };
        let mut fitted = Vec::with_capacity(half);
        for curve in curves.iter() {
            let f = fit(
                SIDE_NAMES[s],
                curve,
                along,
                usize::from(clamp_a) * half,
                usize::from(clamp_b) * half,
            )?;
            fit_error = fit_error.max(f.error);
            fitted.push(f.coefs);
        }
        // Σ_l D[i][l] c_l = φ_i for the rows/columns next to the side.
        let d = across.end_derivatives(end, half);
        let na = across.n_coef;
        let cols: Vec<usize> = if end == End::Finish {
            (na - half..na).collect()
        } else {
            (0..half).collect()
        };
        let block = Dense::from_fn(half, half, |a, b| d[(a, cols[b])]);
        let rhs = Dense::from_fn(half, 3 * along.n_coef, |i, k| {
            fitted
                .get(i)
                .map_or(0.0, |f: &Vec<Vector3>| f[k / 3][k % 3])
        });
        let all = block.solve(&rhs).ok_or(PdeError::Undetermined {
            method: "boundary rows",
            unknowns: half,
            condition: f64::INFINITY,
        })?;
        for t in 0..along.n_coef {
            let sol = Dense::from_fn(half, 3, |i, c| all[(i, 3 * t + c)]);
            for (a, &row) in cols.iter().enumerate() {
                let value = Vector3::new(sol[(a, 0)], sol[(a, 1)], sol[(a, 2)]);
                let (i, j) = if along_u { (t, row) } else { (row, t) };
                let slot = &mut fixed[i * nv + j];
                match slot {
                    Some((prev, by)) => {
                        let gap = (*prev - value).norm();
                        let scale = 1.0 + prev.norm().max(value.norm());
                        if gap > 1e-8 * scale {
                            return Err(PdeError::CornerMismatch {
                                first: SIDE_NAMES[*by],
                                second: SIDE_NAMES[s],
                                i,
                                j,
                                gap,
                            });
                        }
                    }
                    None => *slot = Some((value, s)),
                }
            }
        }
    }
    Ok((
        fixed.into_iter().map(|f| f.map(|(v, _)| v)).collect(),
        fit_error,
    ))
}
