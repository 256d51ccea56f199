//! What the planar and spatial G2 solves ([`crate::hermite_planar`],
//! [`crate::hermite_spatial`]) share: the Newton tolerances, the backtracking step, the
//! continuation from the typical curve's values to the targets, and the checks of the result.

use crate::{ClassAError, INTERPOLATION_TOLERANCE};

/// Residual tolerance of the Newton iterations (relative: chord 1, curvatures divided by their
/// targets, directions as sines of angles).
pub(crate) const NEWTON_TOLERANCE: f64 = 1e-13;
/// Newton iterations per continuation step.
pub(crate) const NEWTON_ITERATIONS: usize = 16;
/// Smallest continuation step before giving up.
const MIN_STEP: f64 = 1.0 / 1024.0;
/// Most continuation steps tried (accepted or halved).
const MAX_STEPS: usize = 256;

/// The largest absolute entry.
pub(crate) fn max_norm(r: &[f64]) -> f64 {
    r.iter().fold(0.0f64, |a, v| a.max(v.abs()))
}

/// The backtracking of a Newton step: x + λ dx for λ = 1, 1/2, … down to 1e-4, the first whose
/// residual (None where not finite) has a max norm below `current`, with that residual.
pub(crate) fn backtrack<const N: usize, const E: usize>(
    x: &[f64; N],
    dx: &[f64; N],
    current: f64,
    residual: impl Fn(&[f64; N]) -> Option<[f64; E]>,
) -> Option<([f64; N], [f64; E])> {
    let mut lambda = 1.0;
    while lambda >= 1e-4 {
        let trial: [f64; N] = std::array::from_fn(|j| x[j] + lambda * dx[j]);
        if let Some(rt) = residual(&trial)
            && max_norm(&rt) < current
        {
            return Some((trial, rt));
        }
        lambda *= 0.5;
    }
    None
}

/// Continuation in τ ∈ [0, 1] from `x`: `solve(x, τ)` solves the system at τ from x; steps
/// start at 1, double after a success and halve after a failure (at most [`MAX_STEPS`] tries,
/// none below [`MIN_STEP`]). Returns the last solution and whether it is at τ = 1.
pub(crate) fn continuation<X: Copy>(
    mut x: X,
    mut solve: impl FnMut(X, f64) -> Option<X>,
) -> (X, bool) {
    let (mut done, mut step) = (0.0f64, 1.0f64);
    for _ in 0..MAX_STEPS {
        if done >= 1.0 {
            break;
        }
        let next = (done + step).min(1.0);
        match solve(x, next) {
            Some(solved) => {
                (x, done) = (solved, next);
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
    (x, done >= 1.0)
}

/// [`ClassAError::ToleranceNotMet`] naming `condition` when the error `achieved` is above
/// [`INTERPOLATION_TOLERANCE`] or NaN.
pub(crate) fn within_tolerance(condition: &'static str, achieved: f64) -> Result<(), ClassAError> {
    if achieved.is_nan() || achieved > INTERPOLATION_TOLERANCE {
        return Err(ClassAError::ToleranceNotMet {
            condition,
            achieved,
            tolerance: INTERPOLATION_TOLERANCE,
        });
    }
    Ok(())
}

/// The end curvatures `got` (start, end) against the targets `want`, relative, by
/// [`within_tolerance`].
pub(crate) fn check_end_curvatures(got: [f64; 2], want: [f64; 2]) -> Result<(), ClassAError> {
    within_tolerance("start curvature", (got[0] / want[0] - 1.0).abs())?;
    within_tolerance("end curvature", (got[1] / want[1] - 1.0).abs())
}
