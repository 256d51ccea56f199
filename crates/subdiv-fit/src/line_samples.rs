//! Samples of a straight path segment: every spacing, or at the spacing next to its ends and
//! sparser in between ([`LineSampling`]).
//!
//! The polyline of a line's samples is the line itself at any spacing, so the samples inside it
//! add nothing to the two-sided measure; they are where a fit can put fitting points and what its
//! least squares weigh. [`LineSampling::Graded`] keeps the first [`LINE_END_SAMPLES`] samples from
//! each end at the spacing (where the line meets a corner or a curve) and then doubles the steps
//! up to [`LINE_MAX_STEP`] spacings. A line of m spacings gets about 2 · (22 + (m/2 − 142) / 64)
//! samples instead of m − 1: on the glyph outlines of the standing comparison (61 % of their
//! length straight) 0.55 times the samples.

/// How a path's straight segments are sampled ([`crate::sample_bez_path_with`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum LineSampling {
    /// Every spacing, as the curved segments.
    #[default]
    Even,
    /// Lines with a corner (or an open end) at both ends: at the spacing for
    /// [`LINE_END_SAMPLES`] samples from each end, then at steps doubling up to
    /// [`LINE_MAX_STEP`] spacings (a line of at most 2 · 16 + 1 spacings gets equal steps). A
    /// line that meets a curve tangentially is sampled evenly: a fit across that joint weighs the
    /// line's samples as the curve's (on a stadium at 10⁻³ graded lines there took 70 control
    /// points instead of 57).
    Graded,
}

impl LineSampling {
    /// The sampling [`crate::fit_bez_path`] uses with `options`: [`LineSampling::Graded`] with
    /// [`crate::Reduction::Refit`], whose span fits need fitting points only next to a line's
    /// ends, [`LineSampling::Even`] otherwise (the fits that insert and remove fitting points
    /// along the whole contour lose places for them and keep more: with every line graded, 1,891
    /// instead of 1,786 control points on the glyph set of the standing comparison with least
    /// squares and re-spacing).
    #[must_use]
    pub fn for_fit(options: &crate::FitOptions) -> Self {
        match options.reduction {
            crate::Reduction::Refit => Self::Graded,
            _ => Self::Even,
        }
    }
}

/// Samples from each end of a straight segment at the sampling spacing.
pub const LINE_END_SAMPLES: usize = 16;

/// The longest step between samples of a straight segment, in spacings.
pub const LINE_MAX_STEP: usize = 64;

/// The offsets (in spacings) from an end of the first samples, until the step reaches
/// [`LINE_MAX_STEP`]: 1 to [`LINE_END_SAMPLES`], then steps of 2, 4, …, 64.
const HEAD: [f64; 22] = [
    1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0, 18.0,
    22.0, 30.0, 46.0, 78.0, 142.0,
];

/// The offset of sample `i` (from 0) from an end, in spacings.
fn offset(i: usize) -> f64 {
    HEAD.get(i)
        .copied()
        .unwrap_or_else(|| HEAD[HEAD.len() - 1] + ((i + 1 - HEAD.len()) * LINE_MAX_STEP) as f64)
}

/// The end of a straight segment that offsets are taken from. The samples are those of the
/// start up to the middle h = m/2 inclusive and those of the end below it, so that a sample at
/// the middle is taken once.
#[derive(Clone, Copy)]
enum End {
    Start,
    Finish,
}

/// How many offsets from `end` a segment with middle `h` (in spacings) takes: at most `h` from
/// the start, below `h` from the finish (as a float, also for the size check of huge `h`).
fn offsets_from(end: End, h: f64) -> f64 {
    let within = |p: f64| match end {
        End::Start => p <= h,
        End::Finish => p < h,
    };
    let last = HEAD[HEAD.len() - 1];
    if !within(last) {
        return HEAD.iter().filter(|&&p| within(p)).count() as f64;
    }
    let steps = (h - last) / LINE_MAX_STEP as f64;
    let beyond = match end {
        End::Start => steps.floor(),
        End::Finish => steps.ceil() - 1.0,
    };
    HEAD.len() as f64 + beyond
}

/// The number of samples inside a straight segment `m` spacings long (as a float, for the size
/// check before sampling); a segment of at most 2 [`LINE_END_SAMPLES`] + 1 spacings gets the
/// m − 1 samples of equal steps.
pub(crate) fn line_sample_count(m: f64) -> f64 {
    let h = m / 2.0;
    offsets_from(End::Start, h) + offsets_from(End::Finish, h)
}

/// The parameters in (0, 1), increasing, of the samples inside a straight segment `m` spacings
/// long ([`line_sample_count`] of them).
pub(crate) fn line_parameters(m: usize) -> impl Iterator<Item = f64> {
    let mf = m as f64;
    let h = mf / 2.0;
    // Whole numbers below m / 2.
    let (from_start, from_finish) = (
        offsets_from(End::Start, h) as usize,
        offsets_from(End::Finish, h) as usize,
    );
    (0..from_start)
        .map(move |i| offset(i) / mf)
        .chain((0..from_finish).rev().map(move |i| (mf - offset(i)) / mf))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The offsets by their definition: 1 to 16, then each step twice the last up to 64.
    fn offsets_by_steps(limit: f64) -> Vec<f64> {
        let (mut p, mut step, mut all) = (0.0, 1.0, Vec::new());
        loop {
            p += step;
            if p > limit {
                return all;
            }
            all.push(p);
            if p >= LINE_END_SAMPLES as f64 {
                step = (step * 2.0_f64).min(LINE_MAX_STEP as f64);
            }
        }
    }

    #[test]
    fn offsets_follow_their_steps() {
        let by_steps = offsets_by_steps(2000.0);
        for (i, &p) in by_steps.iter().enumerate() {
            assert_eq!(offset(i), p, "offset {i}");
        }
    }

    #[test]
    fn short_lines_are_sampled_at_equal_steps() {
        for m in 1..=2 * LINE_END_SAMPLES + 1 {
            let t: Vec<f64> = line_parameters(m).collect();
            let equal: Vec<f64> = (1..m).map(|k| k as f64 / m as f64).collect();
            assert_eq!(t.len(), equal.len(), "m = {m}");
            for (a, b) in t.iter().zip(&equal) {
                assert!((a - b).abs() < 1e-15, "m = {m}: {a} against {b}");
            }
        }
    }

    #[test]
    fn long_lines_are_dense_at_their_ends_and_sparse_inside() {
        for m in [34, 35, 100, 143, 284, 285, 300, 1000, 12_345, 100_000] {
            let t: Vec<f64> = line_parameters(m).collect();
            assert_eq!(t.len() as f64, line_sample_count(m as f64), "m = {m}");
            let mf = m as f64;
            // Increasing, inside, the first and last 16 at the spacing.
            assert!(t.windows(2).all(|w| w[0] < w[1]), "m = {m}");
            assert!(t[0] > 0.0 && t[t.len() - 1] < 1.0);
            for k in 0..LINE_END_SAMPLES {
                assert!((t[k] * mf - (k + 1) as f64).abs() < 1e-9);
                assert!(((1.0 - t[t.len() - 1 - k]) * mf - (k + 1) as f64).abs() < 1e-9);
            }
            // No step longer than the largest one but the middle one, below twice that.
            let steps: Vec<f64> = std::iter::once(t[0])
                .chain(t.windows(2).map(|w| w[1] - w[0]))
                .chain(std::iter::once(1.0 - t[t.len() - 1]))
                .map(|s| s * mf)
                .collect();
            let longest = steps.iter().copied().fold(0.0, f64::max);
            assert!(longest < 2.0 * LINE_MAX_STEP as f64, "m = {m}: {longest}");
            let inner = &steps[1..steps.len() - 1];
            let mid = inner.len() / 2;
            let others = inner
                .iter()
                .enumerate()
                .filter(|&(k, _)| k + 1 != mid && k != mid && k + 1 != mid + 1);
            for (_, &s) in others {
                assert!(s <= LINE_MAX_STEP as f64 + 1e-9, "m = {m}: {s}");
            }
            // Symmetric: the offsets from the end are those from the start.
            let from_start: Vec<f64> = t.iter().map(|&s| s * mf).collect();
            let from_end: Vec<f64> = t.iter().rev().map(|&s| (1.0 - s) * mf).collect();
            let n = from_start.len() / 2;
            for k in 0..n {
                assert!(
                    (from_start[k] - from_end[k]).abs() < 1e-9,
                    "m = {m}, k = {k}"
                );
            }
        }
        // A million spacings: about m / 64 samples.
        let count = line_sample_count(1e6);
        assert!((count - 1e6 / 64.0).abs() < 40.0, "{count}");
    }
}
