//! Flattening many curves at once, in parallel with the `rayon` feature.

use bez_core::BezierForm;

use crate::error::SubdivError;
use crate::flatten::{FlattenOptions, Flattening, flatten};

/// [`flatten`] applied to every curve, results in input order.
///
/// The curves may be of any type with a Bézier form ([`BezierForm`]); `Sync` is asked whatever
/// the features, so that enabling `rayon` never breaks a caller.
///
/// With the `rayon` feature the curves are distributed over rayon's thread pool (each
/// flattening is independent); without it they are processed in order on the calling thread.
#[must_use]
pub fn flatten_batch<C: BezierForm<2> + Sync>(
    curves: &[C],
    options: &FlattenOptions,
) -> Vec<Result<Flattening, SubdivError>> {
    #[cfg(feature = "rayon")]
    {
        use rayon::prelude::*;
        curves.par_iter().map(|c| flatten(c, options)).collect()
    }
    #[cfg(not(feature = "rayon"))]
    {
        curves.iter().map(|c| flatten(c, options)).collect()
    }
}

#[cfg(all(test, feature = "paper"))]
mod tests {
    use super::*;
    use crate::cases::random_curves;

    #[test]
    fn batch_equals_one_by_one() {
        let curves = random_curves(9, 8, 1);
        let options = FlattenOptions::default();
        let batch = flatten_batch(&curves, &options);
        for (c, r) in curves.iter().zip(batch) {
            assert_eq!(r, flatten(c, &options));
        }
    }
}
