//! Assembly of the residual map and the four solvers on one trial space.

use crate::bernstein_ops::{bernstein_values, derivative_matrix, elevation_matrix, gram_matrix};
use crate::boundary::fit;
use crate::error::PdeError;
use crate::grid::PatchGrid;
use crate::problem::{Discretization, Problem, Side};
use crate::space::Space;
use crate::spline_surface::BSplineSurface;
use bez_core::{BezierSurface, Vector3};
use nalgebra::{DMatrix, Dyn, OMatrix, U3};

/// Three right-hand sides (x, y, z) as columns.
type Rhs3 = OMatrix<f64, Dyn, U3>;
/// Control points fixed by the sides (None = free) and the largest boundary-fit error.
type Fixed = (Vec<Option<Vector3>>, f64);

/// How the free control points are determined.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Method {
    /// The paper's objective (4): minimize Σ_patches h_u h_v Σ_ij |b_ij|², the squared
    /// Bernstein coefficients of the residual R = L P − F (area-weighted, Sec. 3).
    BernsteinLeastSquares,
    /// The exact L² norm ∫∫ |R|² du dv (Bernstein Gram matrices instead of the identity).
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
#[non_exhaustive]
pub struct Solution {
    /// The approximating surface.
    pub surface: PatchGrid,
    /// The paper's objective M = Σ_patches h_u h_v Σ_ij |b_ij|² at the solution (eq. (4)).
    pub objective: f64,
    /// The convex-hull bound max |b_ij| ≥ max |R(u, v)| (Sec. 3).
    pub residual_bound: f64,
    /// The largest sample error of the boundary fits (0 up to rounding for polynomial data).
    pub boundary_fit_error: f64,
    /// Number of free control points (unknowns per coordinate).
    pub unknowns: usize,
    /// The same surface as one clamped B-spline surface (C^r joins as knot multiplicities).
    pub spline: BSplineSurface,
}

/// A problem assembled on a trial space: the residual map of every patch, the fixed control
/// points and the right-hand side, ready for any [`Method`].
///
/// Assembly is O(P · (n m)²) for P patches; the solves are dense in the free unknowns.
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
}

#[derive(Debug, Clone)]
struct PatchMap {
    /// Global coefficient indices of the local unknowns.
    support: Vec<usize>,
    /// (l+1)(r+1) × support.len(): residual Bernstein coefficients of L P.
    map: DMatrix<f64>,
    /// (l+1)(r+1) × 3: Bernstein coefficients of F.
    target: OMatrix<f64, Dyn, U3>,
    /// (n+1)(m+1) × support.len(): the patch's control points.
    ext: DMatrix<f64>,
}

const SIDE_NAMES: [&str; 4] = ["u=0", "u=1", "v=0", "v=1"];

impl Assembly {
    /// Assembles `problem` on the trial space `disc`.
    ///
    /// # Errors
    /// [`PdeError::PeriodicMismatch`], [`PdeError::SideDataCount`], [`PdeError::DegreeTooLow`],
    /// [`PdeError::Smoothness`] (r < k − 1 between patches), [`PdeError::NoPatches`], boundary-fit
    /// errors and [`PdeError::CornerMismatch`] when adjacent sides disagree.
    pub fn new(problem: &Problem, disc: &Discretization) -> Result<Self, PdeError> {
        let k = problem.operator.order();
        let half = k / 2;
        if disc.patches_u == 0 || disc.patches_v == 0 {
            return Err(PdeError::NoPatches {
                patches_u: disc.patches_u,
                patches_v: disc.patches_v,
            });
        }
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
            if (patches > 1 || periodic) && smooth + 1 < k {
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
        let terms = problem.operator.terms();
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
        let factor = |space: &Space, p: usize, to: usize| -> Vec<DMatrix<f64>> {
            let deg = space.degree;
            let d = derivative_matrix(deg, p);
            let from = deg.saturating_sub(p);
            let e = elevation_matrix(from, to);
            let scale = space.width().powi(-(p as i32));
            let ed = e * d * scale;
            space.pieces.iter().map(|piece| &ed * &piece.ext).collect()
        };
        let ku: Vec<Vec<DMatrix<f64>>> = terms.iter().map(|t| factor(&su, t.du, l)).collect();
        let kv: Vec<Vec<DMatrix<f64>>> = terms.iter().map(|t| factor(&sv, t.dv, r)).collect();
        let nv = sv.n_coef;
        let mut patches = Vec::with_capacity(disc.patches_u * disc.patches_v);
        for (pu, piece_u) in su.pieces.iter().enumerate() {
            for (pv, piece_v) in sv.pieces.iter().enumerate() {
                let mut map = DMatrix::<f64>::zeros(
                    (l + 1) * (r + 1),
                    piece_u.support.len() * piece_v.support.len(),
                );
                for (ti, term) in terms.iter().enumerate() {
                    map += ku[ti][pu].kronecker(&kv[ti][pv]) * term.coeff;
                }
                let support = piece_u
                    .support
                    .iter()
                    .flat_map(|&a| piece_v.support.iter().map(move |&b| a * nv + b))
                    .collect();
                let target = rhs_on_patch(problem.rhs.as_ref(), &su, &sv, pu, pv, l, r)?;
                let ext = piece_u.ext.kronecker(&piece_v.ext);
                patches.push(PatchMap {
                    support,
                    map,
                    target,
                    ext,
                });
            }
        }
        Ok(Self {
            su,
            sv,
            l,
            r,
            patches,
            fixed,
            fit_error,
            k,
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
    /// [`PdeError::SingularSystem`] when the system is singular or too ill-conditioned.
    pub fn solve(&self, method: Method) -> Result<Solution, PdeError> {
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
        if nf > 0 {
            let (a, b) = match method {
                Method::Collocation => self.collocation_system(&index, nf)?,
                _ => self.projection_system(method, &index, nf),
            };
            let x = match method {
                Method::BernsteinLeastSquares | Method::IntegralLeastSquares => {
                    solve_spd(a, &b, method)?
                }
                _ => solve_general(a, &b, method)?,
            };
            for (k, &g) in free.iter().enumerate() {
                coefs[g] = Vector3::new(x[(k, 0)], x[(k, 1)], x[(k, 2)]);
            }
        }
        self.finish(&coefs, nf)
    }

    /// Σ_patches T^T W (M c − f) = 0 restricted to the free test functions.
    fn projection_system(
        &self,
        method: Method,
        index: &[usize],
        nf: usize,
    ) -> (DMatrix<f64>, OMatrix<f64, Dyn, U3>) {
        let (n, m, l, r) = (self.su.degree, self.sv.degree, self.l, self.r);
        let weight = self.su.width() * self.sv.width();
        let gram = match method {
            Method::IntegralLeastSquares => Some(gram_matrix(l, l).kronecker(&gram_matrix(r, r))),
            Method::Galerkin => Some(gram_matrix(n, l).kronecker(&gram_matrix(m, r))),
            _ => None,
        };
        let mut a = DMatrix::<f64>::zeros(nf, nf);
        let mut b = OMatrix::<f64, Dyn, U3>::zeros(nf);
        for patch in &self.patches {
            // Test functions T (rows of the weak form) and the weighted product T^T W.
            let tw: DMatrix<f64> = match (method, &gram) {
                (Method::Galerkin, Some(g)) => patch.ext.transpose() * g * weight,
                (_, Some(g)) => patch.map.transpose() * g * weight,
                _ => patch.map.transpose() * weight,
            };
            let local_a = &tw * &patch.map;
            let local_b = &tw * &patch.target;
            for (ra, &ga) in patch.support.iter().enumerate() {
                let ia = index[ga];
                if ia == usize::MAX {
                    continue;
                }
                let mut rhs = local_b.row(ra).into_owned();
                for (cb, &gb) in patch.support.iter().enumerate() {
                    let v = local_a[(ra, cb)];
                    match self.fixed[gb] {
                        Some(p) => rhs -= nalgebra::RowVector3::from(p.to_array()) * v,
                        None => a[(ia, index[gb])] += v,
                    }
                }
                let cur = b.row(ia) + rhs;
                b.set_row(ia, &cur);
            }
        }
        (a, b)
    }

    /// R = 0 at the tensor Greville points of the free coefficients.
    fn collocation_system(
        &self,
        index: &[usize],
        nf: usize,
    ) -> Result<(DMatrix<f64>, Rhs3), PdeError> {
        let nv = self.sv.n_coef;
        let mut a = DMatrix::<f64>::zeros(nf, nf);
        let mut b = OMatrix::<f64, Dyn, U3>::zeros(nf);
        let mut row = 0;
        for (g, &slot) in index.iter().enumerate() {
            if slot == usize::MAX {
                continue;
            }
            let (i, j) = (g / nv, g % nv);
            let (u, v) = (self.su.greville[i], self.sv.greville[j]);
            let (pu, s) = self.su.locate(u);
            let (pv, t) = self.sv.locate(v);
            let patch = &self.patches[pu * self.sv.pieces.len() + pv];
            let bu = bernstein_values(self.l, s);
            let bv = bernstein_values(self.r, t);
            let mut weights = Vec::with_capacity((self.l + 1) * (self.r + 1));
            for x in &bu {
                for y in &bv {
                    weights.push(x * y);
                }
            }
            let w = nalgebra::DVector::from_vec(weights);
            let lrow = w.transpose() * &patch.map;
            let mut rhs = w.transpose() * &patch.target;
            for (c, &gc) in patch.support.iter().enumerate() {
                match self.fixed[gc] {
                    Some(p) => rhs -= nalgebra::RowVector3::from(p.to_array()) * lrow[c],
                    None => a[(row, index[gc])] += lrow[c],
                }
            }
            b.set_row(row, &rhs);
            row += 1;
        }
        if row != nf {
            return Err(PdeError::SingularSystem {
                method: "collocation",
                unknowns: nf,
                pivot_ratio: 0.0,
            });
        }
        Ok((a, b))
    }

    fn finish(&self, coefs: &[Vector3], unknowns: usize) -> Result<Solution, PdeError> {
        let weight = self.su.width() * self.sv.width();
        let mut objective = 0.0;
        let mut bound: f64 = 0.0;
        let mut surfaces = Vec::with_capacity(self.patches.len());
        let (n, m) = (self.su.degree, self.sv.degree);
        for patch in &self.patches {
            let local = OMatrix::<f64, Dyn, U3>::from_fn(patch.support.len(), |i, c| {
                coefs[patch.support[i]][c]
            });
            let res = &patch.map * &local - &patch.target;
            for row in res.row_iter() {
                let s = row.norm_squared();
                objective += weight * s;
                bound = bound.max(s.sqrt());
            }
            let pts = &patch.ext * &local;
            let points = pts
                .row_iter()
                .map(|row| Vector3::new(row[0], row[1], row[2]))
                .collect();
            surfaces.push(BezierSurface::from_flat(n, m, points)?);
        }
        Ok(Solution {
            spline: self.spline(coefs),
            surface: PatchGrid::new(self.su.pieces.len(), self.sv.pieces.len(), surfaces),
            objective,
            residual_bound: bound,
            boundary_fit_error: self.fit_error,
            unknowns,
        })
    }
}

impl Assembly {
    /// The clamped B-spline form: c_clamped = Z_u c Z_vᵀ (Z the periodic closure, or I).
    fn spline(&self, coefs: &[Vector3]) -> BSplineSurface {
        let (nu, nv) = (self.su.n_coef, self.sv.n_coef);
        let expand = |space: &Space| -> DMatrix<f64> {
            space
                .to_clamped
                .clone()
                .unwrap_or_else(|| DMatrix::identity(space.n_coef, space.n_coef))
        };
        let (zu, zv) = (expand(&self.su), expand(&self.sv));
        let (cu, cv) = (zu.nrows(), zv.nrows());
        let mut points = vec![Vector3::zeros(); cu * cv];
        for d in 0..3 {
            let c = DMatrix::from_fn(nu, nv, |i, j| coefs[i * nv + j][d]);
            let full = &zu * c * zv.transpose();
            for i in 0..cu {
                for j in 0..cv {
                    points[i * cv + j][d] = full[(i, j)];
                }
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

/// Cholesky of the Jacobi-scaled normal matrix, with a pivot-ratio check.
fn solve_spd(
    a: DMatrix<f64>,
    b: &OMatrix<f64, Dyn, U3>,
    method: Method,
) -> Result<OMatrix<f64, Dyn, U3>, PdeError> {
    let n = a.nrows();
    let singular = |ratio: f64| PdeError::SingularSystem {
        method: method.name(),
        unknowns: n,
        pivot_ratio: ratio,
    };
    let scale: Vec<f64> = (0..n)
        .map(|i| {
            let d = a[(i, i)];
            if d > 0.0 { 1.0 / d.sqrt() } else { 0.0 }
        })
        .collect();
    if scale.iter().any(|&s| s == 0.0 || !s.is_finite()) {
        return Err(singular(0.0));
    }
    let scaled = DMatrix::from_fn(n, n, |i, j| a[(i, j)] * scale[i] * scale[j]);
    let chol = scaled.cholesky().ok_or_else(|| singular(0.0))?;
    let diag = chol.l_dirty().diagonal();
    let ratio = diag.min() / diag.max();
    // The scaled matrix has unit diagonal; a pivot below 1e-7 means cond > 1e14.
    if ratio.is_nan() || ratio <= 1e-7 {
        return Err(singular(ratio));
    }
    let rhs = OMatrix::<f64, Dyn, U3>::from_fn(n, |i, c| b[(i, c)] * scale[i]);
    let y = chol.solve(&rhs);
    Ok(OMatrix::<f64, Dyn, U3>::from_fn(n, |i, c| {
        y[(i, c)] * scale[i]
    }))
}

/// LU with partial pivoting, with a pivot-ratio check.
fn solve_general(
    a: DMatrix<f64>,
    b: &OMatrix<f64, Dyn, U3>,
    method: Method,
) -> Result<OMatrix<f64, Dyn, U3>, PdeError> {
    let n = a.nrows();
    let lu = a.lu();
    let u = lu.u();
    let diag = u.diagonal().map(f64::abs);
    let ratio = diag.min() / diag.max();
    let singular = PdeError::SingularSystem {
        method: method.name(),
        unknowns: n,
        pivot_ratio: ratio,
    };
    if ratio.is_nan() || ratio <= 1e-13 {
        return Err(singular);
    }
    lu.solve(b).ok_or(singular)
}

/// Bernstein coefficients of F restricted to patch (pu, pv), elevated to (l, r).
fn rhs_on_patch(
    rhs: Option<&BezierSurface<3>>,
    su: &Space,
    sv: &Space,
    pu: usize,
    pv: usize,
    l: usize,
    r: usize,
) -> Result<OMatrix<f64, Dyn, U3>, PdeError> {
    let count = (l + 1) * (r + 1);
    let Some(f) = rhs else {
        return Ok(OMatrix::<f64, Dyn, U3>::zeros(count));
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
    Ok(OMatrix::<f64, Dyn, U3>::from_fn(count, |i, c| {
        s.points()[i][c]
    }))
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
        let at_end = s % 2 == 1;
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
        let d = across.end_derivatives(at_end, half);
        let na = across.n_coef;
        let cols: Vec<usize> = if at_end {
            (na - half..na).collect()
        } else {
            (0..half).collect()
        };
        let block = DMatrix::from_fn(half, half, |a, b| d[(a, cols[b])]);
        let lu = block.lu();
        for t in 0..along.n_coef {
            let rhs = DMatrix::from_fn(half, 3, |i, c| fitted.get(i).map_or(0.0, |f| f[t][c]));
            let sol = lu.solve(&rhs).ok_or(PdeError::SingularSystem {
                method: "boundary rows",
                unknowns: half,
                pivot_ratio: 0.0,
            })?;
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
