//! The problem description: operator, right-hand side, boundary data, discretization.

use crate::error::PdeError;
use bez_core::{BezierCurve, BezierSurface, Vector3};

/// One term c·∂^{du+dv}/∂u^{du}∂v^{dv} of the operator L (Xu & Wang 2007, Sec. 1).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Term {
    /// The constant coefficient c.
    pub coeff: f64,
    /// Derivative order in u.
    pub du: usize,
    /// Derivative order in v.
    pub dv: usize,
}

/// A linear operator L = Σ c·∂^{du+dv}/∂u^{du}∂v^{dv} with constant coefficients.
///
/// The paper's L combines ∂²/∂u², ∂²/∂v², ∂⁴/∂u⁴, ∂⁴/∂u²∂v², … up to order 6; every term
/// must have an even total order 2, 4 or 6. The PDE order k is the largest total order.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "OperatorTerms"))]
pub struct Operator {
    terms: Vec<Term>,
}

/// The serialized form of an [`Operator`], validated by [`Operator::new`] on the way in.
#[cfg(feature = "serde")]
#[derive(serde::Deserialize)]
struct OperatorTerms {
    terms: Vec<Term>,
}

#[cfg(feature = "serde")]
impl TryFrom<OperatorTerms> for Operator {
    type Error = PdeError;
    fn try_from(raw: OperatorTerms) -> Result<Self, PdeError> {
        Self::new(raw.terms)
    }
}

impl Operator {
    /// Validates and wraps the terms.
    ///
    /// # Errors
    /// [`PdeError::EmptyOperator`], [`PdeError::UnsupportedOrder`] for an odd, zero or > 6 order,
    /// [`PdeError::NonFinite`] for a non-finite coefficient.
    pub fn new(terms: Vec<Term>) -> Result<Self, PdeError> {
        if terms.is_empty() {
            return Err(PdeError::EmptyOperator);
        }
        for t in &terms {
            let order = t.du + t.dv;
            if order == 0 || order % 2 == 1 || order > 6 {
                return Err(PdeError::UnsupportedOrder {
                    du: t.du,
                    dv: t.dv,
                    order,
                });
            }
            if !t.coeff.is_finite() {
                return Err(PdeError::NonFinite {
                    what: "operator coefficient",
                    value: t.coeff,
                });
            }
        }
        Ok(Self { terms })
    }

    /// ∂²/∂u² + a ∂²/∂v², the operator of the paper's problem (5) and of the vase (with 5, 1).
    ///
    /// # Errors
    /// [`PdeError::NonFinite`] when a coefficient is not finite.
    pub fn second_order(cu: f64, cv: f64) -> Result<Self, PdeError> {
        Self::new(vec![
            Term {
                coeff: cu,
                du: 2,
                dv: 0,
            },
            Term {
                coeff: cv,
                du: 0,
                dv: 2,
            },
        ])
    }

    /// Bloor and Wilson's (∂²/∂u² + a² ∂²/∂v²)² = ∂⁴/∂u⁴ + 2a² ∂⁴/∂u²∂v² + a⁴ ∂⁴/∂v⁴.
    ///
    /// # Errors
    /// [`PdeError::NonFinite`] when a is not finite.
    pub fn bloor_wilson(a: f64) -> Result<Self, PdeError> {
        let a2 = a * a;
        Self::new(vec![
            Term {
                coeff: 1.0,
                du: 4,
                dv: 0,
            },
            Term {
                coeff: 2.0 * a2,
                du: 2,
                dv: 2,
            },
            Term {
                coeff: a2 * a2,
                du: 0,
                dv: 4,
            },
        ])
    }

    /// The terms.
    #[must_use]
    pub fn terms(&self) -> &[Term] {
        &self.terms
    }

    /// The PDE order k (largest total order).
    #[must_use]
    pub fn order(&self) -> usize {
        self.terms.iter().map(|t| t.du + t.dv).max().unwrap_or(0)
    }
}

/// The longest end jet [`SideCurve::from_function`] records (orders 0..16).
pub const MAX_JET: usize = 16;

/// A boundary curve: a function of the side's parameter t ∈ [0, 1].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum SideCurve {
    /// One Bézier curve over [0, 1].
    Bezier(BezierCurve<3>),
    /// Uniform pieces, one per patch along the side: piece p covers [p/P, (p+1)/P].
    Pieces(Vec<BezierCurve<3>>),
    /// A function sampled at t_i = i/(N−1), with its derivatives of orders 0, 1, … at t = 0
    /// and t = 1 (to clamp the fit so that corners meet). Fitted by clamped least squares.
    Sampled {
        /// Samples at uniform parameters, first at t = 0, last at t = 1.
        values: Vec<Vector3>,
        /// [f(0), f'(0), f''(0), …].
        start_jet: Vec<Vector3>,
        /// [f(1), f'(1), f''(1), …].
        end_jet: Vec<Vector3>,
    },
}

impl SideCurve {
    /// Samples a function given with its derivatives: `f(t, d)` is the d-th derivative at t.
    ///
    /// `jet` derivative orders 0..jet are recorded at both ends for clamping.
    ///
    /// # Errors
    /// [`PdeError::TooLarge`] for more than `bez_core::MAX_SAMPLES` samples or a jet longer
    /// than [`MAX_JET`] (checked before `f` is called).
    pub fn from_function(
        count: usize,
        jet: usize,
        f: impl Fn(f64, usize) -> Vector3,
    ) -> Result<Self, PdeError> {
        for (what, value, limit) in [
            ("sample count", count, bez_core::MAX_SAMPLES),
            ("jet length", jet, MAX_JET),
        ] {
            if value > limit {
                return Err(PdeError::TooLarge { what, value, limit });
            }
        }
        let count = count.max(2);
        let values = (0..count)
            .map(|i| f(i as f64 / (count - 1) as f64, 0))
            .collect();
        Ok(Self::Sampled {
            values,
            start_jet: (0..jet).map(|d| f(0.0, d)).collect(),
            end_jet: (0..jet).map(|d| f(1.0, d)).collect(),
        })
    }

    /// Degree of the curve (for [`Problem::default_degrees`]); sampled data has none.
    #[must_use]
    pub fn degree(&self) -> Option<usize> {
        match self {
            Self::Bezier(c) => Some(c.degree()),
            Self::Pieces(p) => p.iter().map(BezierCurve::degree).max(),
            Self::Sampled { .. } => None,
        }
    }
}

/// What is prescribed on one side of the unit square.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Side {
    /// No condition.
    Free,
    /// The surface closes up with its opposite side (both must be `Periodic`).
    Periodic,
    /// Position and cross-boundary derivatives of orders 0..k/2 − 1, in that order
    /// (∂^i X/∂u^i on the u-sides, as functions of v; ∂^i X/∂v^i on the v-sides).
    Fixed(Vec<SideCurve>),
}

/// A boundary-value problem L X = F with conditions on the four sides (Xu & Wang, eq. (1)).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Problem {
    /// The operator L.
    pub operator: Operator,
    /// The polynomial right-hand side F over [0, 1]² in Bernstein form; `None` for F = 0.
    pub rhs: Option<BezierSurface<3>>,
    /// Side u = 0 (curves in v).
    pub u0: Side,
    /// Side u = 1 (curves in v).
    pub u1: Side,
    /// Side v = 0 (curves in u).
    pub v0: Side,
    /// Side v = 1 (curves in u).
    pub v1: Side,
}

/// The trial space: degrees, the uniform patch grid and the continuity between patches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Discretization {
    /// Degree n in u.
    pub degree_u: usize,
    /// Degree m in v.
    pub degree_v: usize,
    /// Patches in u (1 = the single-patch algorithm of Sec. 2).
    pub patches_u: usize,
    /// Patches in v.
    pub patches_v: usize,
    /// Continuity C^r between patches in u (and across a periodic seam).
    pub smoothness_u: usize,
    /// Continuity C^r between patches in v.
    pub smoothness_v: usize,
}

impl Discretization {
    /// One patch of bidegree (n, m) (the single-patch algorithm of Sec. 2).
    #[must_use]
    pub const fn single(degree_u: usize, degree_v: usize) -> Self {
        Self {
            degree_u,
            degree_v,
            patches_u: 1,
            patches_v: 1,
            smoothness_u: 0,
            smoothness_v: 0,
        }
    }
}

impl Problem {
    /// The degrees of step 1: n = max{k+1, deg r₀, deg s₀, deg^u F},
    /// m = max{deg f₀, deg g₀, deg^v F} (Xu & Wang, Sec. 2, step 1).
    ///
    /// Sampled data has no degree and does not count. The paper's m has no k + 1 term;
    /// we keep that, but raise m to k + 1 when the v-sides carry conditions or are
    /// periodic, since otherwise the boundary rows alone would fill the v direction.
    #[must_use]
    pub fn default_degrees(&self) -> (usize, usize) {
        let k = self.operator.order();
        let first_deg = |side: &Side| match side {
            Side::Fixed(curves) => curves.first().and_then(SideCurve::degree).unwrap_or(0),
            _ => 0,
        };
        let (fu, fv) = self
            .rhs
            .as_ref()
            .map_or((0, 0), |f| (f.degree_u(), f.degree_v()));
        let n = (k + 1)
            .max(first_deg(&self.v0))
            .max(first_deg(&self.v1))
            .max(fu);
        let mut m = first_deg(&self.u0).max(first_deg(&self.u1)).max(fv);
        if !matches!(self.v0, Side::Free) || !matches!(self.v1, Side::Free) {
            m = m.max(k + 1);
        }
        (n, m.max(1))
    }
}
