//! The solution as one tensor-product B-spline surface (clamped knots), for CAD export.

use crate::error::PdeError;
use bez_core::Vector3;

/// A clamped tensor-product B-spline surface: degrees, full knot vectors and a row-major
/// control grid (row i = u index, as in STEP's u-outer list).
///
/// The approximating surface of a solve is exactly this spline: interior knots of
/// multiplicity n − r carry the C^r joins, so no continuity is lost on export.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BSplineSurface {
    /// Degree in u.
    pub degree_u: usize,
    /// Degree in v.
    pub degree_v: usize,
    /// Full knot vector in u (count_u + degree_u + 1 values).
    pub knots_u: Vec<f64>,
    /// Full knot vector in v.
    pub knots_v: Vec<f64>,
    /// Control points, count_u × count_v, row-major with u outer.
    pub points: Vec<Vector3>,
}

impl BSplineSurface {
    /// Number of control points in u.
    #[must_use]
    pub fn count_u(&self) -> usize {
        self.knots_u
            .len()
            .saturating_sub(self.degree_u.saturating_add(1))
    }

    /// Number of control points in v.
    #[must_use]
    pub fn count_v(&self) -> usize {
        self.knots_v
            .len()
            .saturating_sub(self.degree_v.saturating_add(1))
    }

    /// Checks the shape: degrees in 1..=`bez_core::MAX_DEGREE`, knot counts, non-decreasing
    /// knots with a non-empty parameter range, finite values.
    ///
    /// # Errors
    /// [`PdeError::InvalidSpline`] for a degree out of range or an empty parameter range,
    /// [`PdeError::Core`] with a grid-shape error, [`PdeError::NonFinite`],
    /// [`PdeError::DecreasingKnots`].
    pub fn validate(&self) -> Result<(), PdeError> {
        for (direction, degree) in [("u", self.degree_u), ("v", self.degree_v)] {
            if !(1..=bez_core::MAX_DEGREE).contains(&degree) {
                return Err(PdeError::InvalidSpline {
                    what: format!(
                        "degree in {direction} is {degree}, outside 1..={}",
                        bez_core::MAX_DEGREE
                    ),
                });
            }
        }
        let (cu, cv) = (self.count_u(), self.count_v());
        if cu == 0 || cv == 0 || Some(self.points.len()) != cu.checked_mul(cv) {
            return Err(bez_core::CoreError::GridShape {
                rows: cu,
                cols: cv,
                expected: cu * cv,
                len: self.points.len(),
            }
            .into());
        }
        for (direction, k) in [("u", &self.knots_u), ("v", &self.knots_v)] {
            if let Some(&bad) = k.iter().find(|x| !x.is_finite()) {
                return Err(PdeError::NonFinite {
                    what: "knot",
                    value: bad,
                });
            }
            if let Some(index) = k.windows(2).position(|w| w[1] < w[0]) {
                return Err(PdeError::DecreasingKnots {
                    direction,
                    index: index + 1,
                });
            }
        }
        for (direction, k, p, c) in [
            ("u", &self.knots_u, self.degree_u, cu),
            ("v", &self.knots_v, self.degree_v, cv),
        ] {
            // The parameter range [t_p, t_count] must not be empty (all-equal knots would
            // evaluate to NaN).
            if k[p] >= k[c] {
                return Err(PdeError::InvalidSpline {
                    what: format!("the knots in {direction} leave an empty parameter range"),
                });
            }
        }
        for p in &self.points {
            if let Some(&bad) = p.iter().find(|x| !x.is_finite()) {
                return Err(PdeError::NonFinite {
                    what: "control point coordinate",
                    value: bad,
                });
            }
        }
        Ok(())
    }

    /// Evaluates the surface at (u, v) ∈ [0, 1]² by the Cox–de Boor recurrence, after
    /// [`Self::validate`] (the fields are public, so the shape is checked on every call).
    ///
    /// # Errors
    /// Those of [`Self::validate`]; [`PdeError::ParameterOutOfRange`] outside the knot range.
    pub fn eval(&self, u: f64, v: f64) -> Result<Vector3, PdeError> {
        self.validate()?;
        let (iu, bu) = basis(&self.knots_u, self.degree_u, u)?;
        let (iv, bv) = basis(&self.knots_v, self.degree_v, v)?;
        let cv = self.count_v();
        let mut out = Vector3::zeros();
        for (a, wu) in bu.iter().enumerate() {
            for (b, wv) in bv.iter().enumerate() {
                out += self.points[(iu + a) * cv + iv + b] * (wu * wv);
            }
        }
        Ok(out)
    }
}

/// The p + 1 nonzero basis functions at t and the index of the first.
fn basis(knots: &[f64], p: usize, t: f64) -> Result<(usize, Vec<f64>), PdeError> {
    let n = knots.len().saturating_sub(p + 1);
    if n == 0 || !(knots[p]..=knots[n]).contains(&t) {
        return Err(PdeError::ParameterOutOfRange { value: t });
    }
    // Span: knots[span] ≤ t < knots[span+1], the last non-empty span at the right end.
    let mut span = p;
    while span + 1 < n && knots[span + 1] <= t {
        span += 1;
    }
    let mut b = vec![0.0; p + 1];
    b[0] = 1.0;
    let mut left = vec![0.0; p + 1];
    let mut right = vec![0.0; p + 1];
    for j in 1..=p {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = b[r] / (right[r + 1] + left[j - r]);
            b[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        b[j] = saved;
    }
    Ok((span - p, b))
}
