//! Cumulative chord length along the data: segment lengths, chord-length middles and positions at
//! a given arc length of the data polyline.
//!
//! On dense noisy data the length of the polyline measures the noise (a zigzag of amplitude ε at
//! spacing h ≪ ε is about ε / h times longer than the curve). [`ChordLengths::robust`] counts
//! length only from anchors at least `δ` apart: the length at point i is the larger of the length
//! at point i − 1 and the length at the last anchor plus the distance from it, and a point that far
//! from the anchor becomes the next one. Monotone, equal to the chord length when every edge is at
//! least `δ`, and within the noise of the curve's length when `δ` is well above the noise.

use bez_core::Vector;

/// Cumulative chord length along the data polyline.
pub(crate) struct ChordLengths {
    /// `cum[i]`: chord length from data point 0 to data point i.
    cum: Vec<f64>,
    /// Length of the whole polyline (with the closing edge for closed data).
    total: f64,
    closed: bool,
}

impl ChordLengths {
    #[cfg(test)]
    pub(crate) fn new<const D: usize>(data: &[Vector<D>], closed: bool) -> Self {
        Self::robust(data, closed, 0.0)
    }

    /// Chord length counted from anchors at least `delta` apart (see the module docs).
    pub(crate) fn robust<const D: usize>(data: &[Vector<D>], closed: bool, delta: f64) -> Self {
        let n = data.len();
        let mut cum = Vec::with_capacity(n);
        let (mut s, mut anchor, mut at_anchor) = (0.0_f64, 0, 0.0);
        for i in 0..n {
            if i > 0 {
                let d = (data[i] - data[anchor]).norm();
                s = s.max(at_anchor + d);
                if d >= delta {
                    anchor = i;
                    at_anchor = s;
                }
            }
            cum.push(s);
        }
        if closed && n > 1 {
            s = s.max(at_anchor + (data[0] - data[anchor]).norm());
        }
        Self {
            cum,
            total: s,
            closed,
        }
    }

    /// Number of data points.
    pub(crate) fn len(&self) -> usize {
        self.cum.len()
    }

    /// Length of the whole polyline (with the closing edge for closed data).
    pub(crate) fn total(&self) -> f64 {
        self.total
    }

    /// Chord length from point 0 to the unwrapped index `i` (`i ≥ n` goes round once more).
    pub(crate) fn at(&self, i: usize) -> f64 {
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
        self.nearest_interior(a, b, 0.5 * (self.at(a) + self.at(b)))
    }

    /// The interior data point of `a..=b` (unwrapped) whose chord length is nearest `target`
    /// (unwrapped), wrapped to `0..n`; `None` without interior points.
    pub(crate) fn nearest_interior(&self, a: usize, b: usize, target: f64) -> Option<usize> {
        if b < a + 2 {
            return None;
        }
        // First interior index at or past the target, then the nearer of it and its predecessor.
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

    /// The point of the data polyline at chord length `s` from point 0: wrapped round for closed
    /// data, clamped to the ends for open data.
    #[cfg(test)]
    pub(crate) fn position<const D: usize>(&self, data: &[Vector<D>], s: f64) -> Vector<D> {
        let s = self.wrap(s);
        // Last index whose chord length is at or below s.
        let i = self.cum.partition_point(|&c| c <= s).saturating_sub(1);
        self.point_on_edge(data, s, i)
    }

    /// [`ChordLengths::position`], with the edge searched from `hint` (updated) instead of by
    /// bisection: linear in the number of points between the hint and the result, so a sweep
    /// whose positions move little from one call to the next costs O(1) per call.
    pub(crate) fn position_from<const D: usize>(
        &self,
        data: &[Vector<D>],
        s: f64,
        hint: &mut usize,
    ) -> Vector<D> {
        let s = self.wrap(s);
        let n = self.cum.len();
        // Last index whose chord length is at or below s (0 if none), as by bisection.
        let mut i = (*hint).min(n - 1);
        while i + 1 < n && self.cum[i + 1] <= s {
            i += 1;
        }
        while i > 0 && self.cum[i] > s {
            i -= 1;
        }
        *hint = i;
        self.point_on_edge(data, s, i)
    }

    /// `s` wrapped round for closed data, clamped to `[0, total]` for open data.
    fn wrap(&self, s: f64) -> f64 {
        if self.closed && self.total > 0.0 {
            // Within one turn either way (every caller) the wrap is one exact subtraction or the
            // addition `rem_euclid` makes, without its floating-point remainder.
            if (0.0..self.total).contains(&s) {
                s
            } else if (-self.total..0.0).contains(&s) {
                s + self.total
            } else if (self.total..2.0 * self.total).contains(&s) {
                s - self.total
            } else {
                s.rem_euclid(self.total)
            }
        } else {
            s.clamp(0.0, self.total)
        }
    }

    /// The point at chord length `s` on the edge from data point `i` to the next.
    fn point_on_edge<const D: usize>(&self, data: &[Vector<D>], s: f64, i: usize) -> Vector<D> {
        let n = self.cum.len();
        let (j, end) = if i + 1 < n {
            (i + 1, self.cum[i + 1])
        } else if self.closed {
            (0, self.total)
        } else {
            return data[n - 1];
        };
        let len = end - self.cum[i];
        if len > 0.0 {
            let f = ((s - self.cum[i]) / len).clamp(0.0, 1.0);
            data[i] + (data[j] - data[i]) * f
        } else {
            data[i]
        }
    }
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

        /// `position` lies on the polyline at the requested distance from point 0 along it
        /// (checked by walking the edges).
        #[test]
        fn position_walks_the_polyline(
            raw in prop::collection::vec((-5.0f64..5.0, -5.0f64..5.0), 3..20),
            frac in -0.5f64..1.5,
            closed in any::<bool>(),
        ) {
            let data: Vec<Vector2> = raw.iter().map(|&(x, y)| Vector2::new(x, y)).collect();
            let chords = ChordLengths::new(&data, closed);
            let s = frac * chords.total();
            let got = chords.position(&data, s);
            let mut edges: Vec<(Vector2, Vector2)> = data.windows(2).map(|w| (w[0], w[1])).collect();
            if closed {
                edges.push((data[data.len() - 1], data[0]));
            }
            let total = chords.total();
            let mut left = if closed { s.rem_euclid(total) } else { s.clamp(0.0, total) };
            let mut expected = if closed { data[0] } else { data[data.len() - 1] };
            for (a, b) in edges {
                let len = (b - a).norm();
                if left <= len {
                    expected = if len > 0.0 { a + (b - a) * (left / len) } else { a };
                    break;
                }
                left -= len;
            }
            prop_assert!((got - expected).norm() < 1e-9, "{got:?} vs {expected:?}");
        }

        /// `position_from` from any hint is bit for bit `position` (bisection), for positions
        /// up to two turns away either way (the wrap without a remainder, and beyond it), with
        /// repeated chord lengths (robust chord length on a zigzag).
        #[test]
        fn position_from_any_hint_is_position(
            raw in prop::collection::vec((-5.0f64..5.0, -5.0f64..5.0), 3..20),
            fracs in prop::collection::vec(-2.5f64..2.5, 1..8),
            hint0 in 0usize..40,
            delta in prop::sample::select(vec![0.0, 1.0, 4.0]),
            closed in any::<bool>(),
        ) {
            let data: Vec<Vector2> = raw.iter().map(|&(x, y)| Vector2::new(x, y)).collect();
            let chords = ChordLengths::robust(&data, closed, delta);
            let mut hint = hint0;
            for frac in fracs {
                let s = frac * chords.total();
                let expected = chords.position(&data, s);
                let got = chords.position_from(&data, s, &mut hint);
                prop_assert_eq!(got, expected);
                prop_assert!(hint < data.len());
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
        assert_eq!(chords.position(&square, 3.5), Vector2::new(0.0, 0.5));
        assert_eq!(chords.position(&square, -0.5), Vector2::new(0.0, 0.5));
        let open = ChordLengths::new(&square, false);
        assert_eq!(open.position(&square, 3.5), Vector2::new(0.0, 1.0));
    }
}
