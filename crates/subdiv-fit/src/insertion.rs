//! Where new fitting points go. Sec. 4.3 only says "insert new fitting points where the error is not
//! met"; the rules here are the project's (see [`crate::Insertion`]).

use bez_core::Vector;

use crate::fit::Insertion;

/// Cumulative chord length along the data, for segment lengths and chord-length middles.
pub(crate) struct ChordLengths {
    /// `cum[i]`: chord length from data point 0 to data point i.
    cum: Vec<f64>,
    /// Length of the whole polyline (with the closing edge for closed data).
    total: f64,
}

impl ChordLengths {
    pub(crate) fn new<const D: usize>(data: &[Vector<D>], closed: bool) -> Self {
        let n = data.len();
        let mut cum = Vec::with_capacity(n);
        let mut s = 0.0;
        for i in 0..n {
            if i > 0 {
                s += (data[i] - data[i - 1]).norm();
            }
            cum.push(s);
        }
        if closed && n > 1 {
            s += (data[0] - data[n - 1]).norm();
        }
        Self { cum, total: s }
    }

    /// Chord length from point 0 to the unwrapped index `i` (`i ≥ n` goes round once more).
    fn at(&self, i: usize) -> f64 {
        let n = self.cum.len();
        if i >= n {
            self.total + self.cum[i - n]
        } else {
            self.cum[i]
        }
    }

    /// The interior data point of `a..=b` nearest the chord-length middle (wrapped to `0..n`), or
    /// `None` when the segment has no interior data point.
    pub(crate) fn middle(&self, a: usize, b: usize) -> Option<usize> {
        if b < a + 2 {
            return None;
        }
        let target = 0.5 * (self.at(a) + self.at(b));
        // First interior index at or past the middle, then the nearer of it and its predecessor.
        let (mut lo, mut hi) = (a + 1, b - 1);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if self.at(mid) < target {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        let best = if lo > a + 1 && target - self.at(lo - 1) < self.at(lo) - target {
            lo - 1
        } else {
            lo
        };
        Some(best % self.cum.len())
    }
}

/// One segment's outcome of a round.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Verdict {
    /// An error measure exceeds the tolerance on this segment.
    pub(crate) fails: bool,
    /// For [`Insertion::MaxError`]: the interior data point of largest error (or nearest the worst
    /// curve sample).
    pub(crate) worst_point: Option<usize>,
}

/// Data indices of segment j: from fitting[j] to fitting[j+1] inclusive (unwrapped, may exceed n).
pub(crate) fn segment_range(fitting: &[(usize, bool)], j: usize, n: usize) -> (usize, usize) {
    let a = fitting[j].0;
    let b = if j + 1 < fitting.len() {
        fitting[j + 1].0
    } else {
        fitting[0].0 + n
    };
    (a, b)
}

fn insert_regular(fitting: &mut Vec<(usize, bool)>, idx: usize) -> bool {
    match fitting.binary_search_by_key(&idx, |f| f.0) {
        Ok(_) => false,
        Err(pos) => {
            fitting.insert(pos, (idx, false));
            true
        }
    }
}

/// Inserts the new fitting points of one round (all regular) and returns how many were added.
///
/// A failing segment gets one point inside it (by `rule`). A failing segment without interior data
/// (it can only fail the curve-to-data measure) is shaped by its neighbours' control points, so the
/// neighbours across its regular end vertices are bisected instead; a sharp end vertex decouples
/// the neighbour beyond it (the segment uses the phantom point there), so that side is left alone.
///
/// Every round with a failure thus adds at least one point or returns 0, and the fitting points only
/// grow: the loop ends after at most `n` rounds, in practice after about `log2(n)` since each split
/// halves a segment. Once no failing segment (or regular-side neighbour of one) has interior data,
/// nothing can be inserted and the remaining error is that of the data polyline itself.
pub(crate) fn insert_points(
    fitting: &mut Vec<(usize, bool)>,
    verdicts: &[Verdict],
    rule: Insertion,
    chords: &ChordLengths,
    closed: bool,
) -> usize {
    let n = chords.cum.len();
    let before = fitting.len();
    let segs = verdicts.len();
    let mut new = Vec::new();
    for (j, v) in verdicts.iter().enumerate() {
        if !v.fails {
            continue;
        }
        let (a, b) = segment_range(fitting, j, n);
        let inside = match rule {
            Insertion::MaxError => v.worst_point,
            Insertion::Bisect => chords.middle(a, b),
        };
        if let Some(i) = inside {
            new.push(i);
            continue;
        }
        let k = fitting.len();
        let left = (closed || j > 0).then(|| (j + segs - 1) % segs);
        let right = (closed || j + 1 < segs).then(|| (j + 1) % segs);
        if let Some(l) = left.filter(|_| !fitting[j].1) {
            let (a, b) = segment_range(fitting, l, n);
            new.extend(chords.middle(a, b));
        }
        if let Some(r) = right.filter(|_| !fitting[(j + 1) % k].1) {
            let (a, b) = segment_range(fitting, r, n);
            new.extend(chords.middle(a, b));
        }
    }
    for i in new {
        insert_regular(fitting, i);
    }
    fitting.len() - before
}

#[cfg(test)]
mod tests {
    use super::*;
    use bez_core::Vector2;
    use proptest::prelude::*;

    proptest! {
        /// `middle` (binary search on cumulative chord length) against a linear scan of the
        /// interior points, with wrap-around for closed data.
        #[test]
        fn middle_is_the_interior_point_nearest_half_the_chord_length(
            steps in prop::collection::vec(0.01f64..3.0, 3..40),
            start in 0usize..40,
            span in 0usize..40,
        ) {
            let mut x = 0.0;
            let data: Vec<Vector2> = steps
                .iter()
                .map(|s| {
                    x += s;
                    Vector2::new(x, 0.0)
                })
                .collect();
            let n = data.len();
            let chords = ChordLengths::new(&data, true);
            let a = start % n;
            let b = a + span % n;
            let arc = |i: usize| chords.at(i);
            let expected = (a + 1..b)
                .min_by(|&i, &j| {
                    let half = 0.5 * (arc(a) + arc(b));
                    (arc(i) - half).abs().total_cmp(&(arc(j) - half).abs())
                })
                .map(|i| i % n);
            let got = chords.middle(a, b);
            match (got, expected) {
                (None, None) => {}
                (Some(g), Some(e)) => {
                    let half = 0.5 * (arc(a) + arc(b));
                    let unwrap = |i: usize| if i < a { i + n } else { i };
                    // Ties may pick either point: compare distances, not indices.
                    prop_assert!(
                        ((arc(unwrap(g)) - half).abs() - (arc(unwrap(e)) - half).abs()).abs() < 1e-12
                    );
                }
                _ => prop_assert!(false, "{got:?} vs {expected:?}"),
            }
        }
    }

    #[test]
    fn closed_chord_length_includes_the_closing_edge() {
        let square =
            [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(|(x, y)| Vector2::new(x, y));
        let chords = ChordLengths::new(&square, true);
        assert_eq!(chords.total, 4.0);
        assert_eq!(chords.at(5), 5.0); // once round (4) and one more edge
        assert_eq!(chords.middle(3, 7), Some(1)); // 3 → 0 → 1 → 2 → 3: middle at 1 (= 5 unwrapped)
        assert_eq!(chords.middle(2, 3), None);
        assert_eq!(ChordLengths::new(&square, false).total, 3.0);
    }
}
