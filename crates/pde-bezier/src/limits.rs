//! Size limits, checked before anything is allocated.

use crate::error::PdeError;
use crate::problem::Discretization;

/// The largest degree in either direction of a [`Discretization`]. The local maps of one
/// patch have ((n+1)(m+1))² entries and cost O(((n+1)(m+1))³) to form.
pub const MAX_SOLVE_DEGREE: usize = 32;

/// The largest number of patches (P_u · P_v) of a [`Discretization`].
pub const MAX_PATCHES: usize = 1 << 16;

/// The largest number of spline coefficients (unknowns before the boundary rows are
/// eliminated) of a [`Discretization`].
pub const MAX_COEFFICIENTS: usize = 1 << 20;

/// The largest number of stored local-map entries, P_u P_v ((n+1)(m+1))², about 128 MiB.
pub const MAX_LOCAL_ENTRIES: usize = 1 << 24;

/// The largest dense system (rows · unknowns, about 128 MiB) a solve forced to
/// [`crate::Storage::Dense`] may allocate.
pub const MAX_DENSE_ENTRIES: usize = 1 << 24;

/// Checks the sizes a discretization asks for against the limits above.
///
/// # Errors
/// [`PdeError::TooLarge`] naming the first size over its limit, [`PdeError::NoPatches`].
pub(crate) fn check(disc: &Discretization) -> Result<(), PdeError> {
    if disc.patches_u == 0 || disc.patches_v == 0 {
        return Err(PdeError::NoPatches {
            patches_u: disc.patches_u,
            patches_v: disc.patches_v,
        });
    }
    let too_large = |what, value, limit| Err(PdeError::TooLarge { what, value, limit });
    for (what, degree) in [
        ("degree in u", disc.degree_u),
        ("degree in v", disc.degree_v),
    ] {
        if degree > MAX_SOLVE_DEGREE {
            return too_large(what, degree, MAX_SOLVE_DEGREE);
        }
    }
    let patches = disc.patches_u.saturating_mul(disc.patches_v);
    if patches > MAX_PATCHES {
        return too_large("the number of patches", patches, MAX_PATCHES);
    }
    // Coefficients per direction: at most n + 1 + (P − 1) n.
    let per = |n: usize, p: usize| (n + 1).saturating_add(p.saturating_sub(1).saturating_mul(n));
    let coefficients =
        per(disc.degree_u, disc.patches_u).saturating_mul(per(disc.degree_v, disc.patches_v));
    if coefficients > MAX_COEFFICIENTS {
        return too_large(
            "the number of spline coefficients",
            coefficients,
            MAX_COEFFICIENTS,
        );
    }
    let local = (disc.degree_u + 1) * (disc.degree_v + 1);
    let entries = patches.saturating_mul(local * local);
    if entries > MAX_LOCAL_ENTRIES {
        return too_large(
            "the number of local-map entries",
            entries,
            MAX_LOCAL_ENTRIES,
        );
    }
    Ok(())
}
