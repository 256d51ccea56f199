//! A uniform grid of Bézier patches (the approximating surface) and error norms.

use crate::error::PdeError;
use bez_core::{BezierSurface, Vector3};

/// A uniform grid of Bézier patches over [0, 1]²: patch (i, j) covers
/// [i/P_u, (i+1)/P_u] × [j/P_v, (j+1)/P_v]; stored row-major (i outer).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "PatchGridParts"))]
pub struct PatchGrid {
    patches_u: usize,
    patches_v: usize,
    patches: Vec<BezierSurface<3>>,
}

/// The serialized form of a [`PatchGrid`], checked on the way in: P_u, P_v ≥ 1, P_u P_v
/// patches, all of one bidegree.
#[cfg(feature = "serde")]
#[derive(serde::Deserialize)]
struct PatchGridParts {
    patches_u: usize,
    patches_v: usize,
    patches: Vec<BezierSurface<3>>,
}

#[cfg(feature = "serde")]
impl TryFrom<PatchGridParts> for PatchGrid {
    type Error = PdeError;
    fn try_from(raw: PatchGridParts) -> Result<Self, PdeError> {
        if raw.patches_u == 0 || raw.patches_v == 0 {
            return Err(PdeError::NoPatches {
                patches_u: raw.patches_u,
                patches_v: raw.patches_v,
            });
        }
        let expected = raw.patches_u.saturating_mul(raw.patches_v);
        if raw.patches.len() != expected {
            return Err(PdeError::PieceCount {
                side: "grid",
                given: raw.patches.len(),
                expected,
            });
        }
        let first = (raw.patches[0].degree_u(), raw.patches[0].degree_v());
        if raw
            .patches
            .iter()
            .any(|p| (p.degree_u(), p.degree_v()) != first)
        {
            return Err(PdeError::InvalidSpline {
                what: "the patches of a grid must share one bidegree".to_string(),
            });
        }
        Ok(Self {
            patches_u: raw.patches_u,
            patches_v: raw.patches_v,
            patches: raw.patches,
        })
    }
}

/// The largest τ of [`PatchGrid::error_norms`] ((τ + 1)² evaluations).
pub const MAX_ERROR_GRID: usize = 4096;

/// RMS and maximum of |X − X̃| over a (τ+1) × (τ+1) grid (Xu & Wang, Sec. 4).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct ErrorNorms {
    /// E = ( (1/M) Σ |X(i/τ, j/τ) − X̃(i/τ, j/τ)|² )^{1/2}, M = (τ+1)².
    pub rms: f64,
    /// max |X(i/τ, j/τ) − X̃(i/τ, j/τ)|.
    pub max: f64,
}

impl PatchGrid {
    pub(crate) fn new(patches_u: usize, patches_v: usize, patches: Vec<BezierSurface<3>>) -> Self {
        debug_assert_eq!(patches.len(), patches_u * patches_v);
        Self {
            patches_u,
            patches_v,
            patches,
        }
    }

    /// Patches in u.
    #[must_use]
    pub fn patches_u(&self) -> usize {
        self.patches_u
    }

    /// Patches in v.
    #[must_use]
    pub fn patches_v(&self) -> usize {
        self.patches_v
    }

    /// Patch (i, j), or `None` out of range.
    #[must_use]
    pub fn patch(&self, i: usize, j: usize) -> Option<&BezierSurface<3>> {
        if i < self.patches_u && j < self.patches_v {
            self.patches.get(i * self.patches_v + j)
        } else {
            None
        }
    }

    /// All patches, row-major.
    #[must_use]
    pub fn patches(&self) -> &[BezierSurface<3>] {
        &self.patches
    }

    /// Evaluates the piecewise surface at (u, v) ∈ [0, 1]².
    ///
    /// # Errors
    /// [`PdeError::ParameterOutOfRange`] outside [0, 1]².
    pub fn eval(&self, u: f64, v: f64) -> Result<Vector3, PdeError> {
        for t in [u, v] {
            if !(0.0..=1.0).contains(&t) {
                return Err(PdeError::ParameterOutOfRange { value: t });
            }
        }
        let (i, s) = locate(u, self.patches_u);
        let (j, t) = locate(v, self.patches_v);
        Ok(self.patches[i * self.patches_v + j].eval(s, t)?)
    }

    /// PdeError norms against an exact solution on the (τ+1)² grid (the paper uses τ = 100).
    ///
    /// # Errors
    /// [`PdeError::NonFinite`] when the exact solution returns a non-finite value or the
    /// error overflows, [`PdeError::TooLarge`] for τ above [`MAX_ERROR_GRID`].
    pub fn error_norms(
        &self,
        exact: impl Fn(f64, f64) -> Vector3,
        tau: usize,
    ) -> Result<ErrorNorms, PdeError> {
        if tau > MAX_ERROR_GRID {
            return Err(PdeError::TooLarge {
                what: "error grid τ",
                value: tau,
                limit: MAX_ERROR_GRID,
            });
        }
        let tau = tau.max(1);
        let mut sum = 0.0;
        let mut max: f64 = 0.0;
        for i in 0..=tau {
            for j in 0..=tau {
                let (u, v) = (i as f64 / tau as f64, j as f64 / tau as f64);
                let e = (exact(u, v) - self.eval(u, v)?).norm();
                if !e.is_finite() {
                    return Err(PdeError::NonFinite {
                        what: "exact solution",
                        value: e,
                    });
                }
                sum += e * e;
                max = max.max(e);
            }
        }
        let count = ((tau + 1) * (tau + 1)) as f64;
        Ok(ErrorNorms {
            rms: (sum / count).sqrt(),
            max,
        })
    }
}

fn locate(t: f64, count: usize) -> (usize, f64) {
    let scaled = t * count as f64;
    let p = (scaled.floor() as usize).min(count - 1);
    (p, (scaled - p as f64).clamp(0.0, 1.0))
}
