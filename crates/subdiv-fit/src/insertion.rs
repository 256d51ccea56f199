//! Where new fitting points go. Sec. 4.3 only says "insert new fitting points where the error is not
//! met"; the rules here are the project's (see [`crate::Insertion`]).

use crate::chord::ChordLengths;
use crate::fit::Insertion;

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
    let n = chords.len();
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
