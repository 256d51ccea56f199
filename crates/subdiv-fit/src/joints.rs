//! Known joints of the data: corners (sharp vertices) and tangent joints (tangent vertices, G1
//! with a free curvature on each side), given to [`crate::fit_with_joints`].

use crate::SubdivFitError;
use crate::chord::ChordLengths;

/// Data indices where the fit must put a joint.
///
/// - **Corners** become sharp fitting points, interpolated exactly (as with
///   [`crate::fit_with_corners`]).
/// - **Tangent joints** become [`VertexKind::Tangent`](crate::VertexKind::Tangent) vertices, a
///   double knot: the curve is tangent-continuous there and its curvature may jump, as where a
///   straight side meets an arc tangentially. A tangent joint needs room: it must be an interior
///   point of open data, not a corner, and there must be data for two regular fitting points
///   between it and the nearest corner or end on each side (the fit inserts them). With
///   [`Reduction::Refit`](crate::Reduction::Refit) they become smooth joints instead (sharp
///   vertices held on one tangent, [`Corner::smooth`](crate::Corner::smooth)), which need no room.
///
/// ```
/// use subdiv_fit::Joints;
///
/// let joints = Joints::new().with_corners(&[0, 60]).with_tangents(&[30, 90]);
/// assert_eq!(joints.corners(), [0, 60]);
/// assert_eq!(joints.tangents(), [30, 90]);
/// ```
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Joints {
    corners: Vec<usize>,
    tangents: Vec<usize>,
}

impl Joints {
    /// No known joints.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// With the corners at the data indices `indices` (sorted and deduplicated).
    #[must_use]
    pub fn with_corners(mut self, indices: &[usize]) -> Self {
        self.corners = sorted(indices);
        self
    }

    /// With the tangent joints at the data indices `indices` (sorted and deduplicated).
    #[must_use]
    pub fn with_tangents(mut self, indices: &[usize]) -> Self {
        self.tangents = sorted(indices);
        self
    }

    /// The corners, increasing.
    #[must_use]
    pub fn corners(&self) -> &[usize] {
        &self.corners
    }

    /// The tangent joints, increasing.
    #[must_use]
    pub fn tangents(&self) -> &[usize] {
        &self.tangents
    }

    /// Checks the indices against `n` data points: every index inside the data, no tangent joint
    /// at an end of open data or at a corner.
    pub(crate) fn check(&self, n: usize, closed: bool) -> Result<(), SubdivFitError> {
        if let Some(&index) = self.corners.iter().find(|&&c| c >= n) {
            return Err(SubdivFitError::CornerOutOfRange { index, points: n });
        }
        for &index in &self.tangents {
            let invalid = |reason| Err(SubdivFitError::InvalidTangentJoint { index, reason });
            if index >= n {
                return invalid("not a data index");
            }
            if !closed && (index == 0 || index + 1 == n) {
                return invalid("an end of open data is always a corner");
            }
            if self.corners.binary_search(&index).is_ok() {
                return invalid("it is also given as a corner");
            }
        }
        Ok(())
    }
}

fn sorted(indices: &[usize]) -> Vec<usize> {
    let mut v = indices.to_vec();
    v.sort_unstable();
    v.dedup();
    v
}

/// Fitting points on either side of a tangent joint that must not be sharp: the double knot's
/// reach (see [`crate::SubdivCurve::new`]).
const ROOM: usize = 2;

/// Makes the tangent joints `tangents` (data indices of fitting points, increasing) regular and
/// gives each [`ROOM`] non-sharp fitting points on each side: where a sharp point (or an end of
/// open data) is nearer, the regular points between it and the nearest tangent joint are placed
/// again, one more, at equal chord-length steps (eq. (4) interpolates at uniform parameters, so
/// evenly spaced points suit it), until every joint has room (a closed polygon then has at least
/// 5 fitting points).
///
/// # Errors
/// [`SubdivFitError::InvalidTangentJoint`] when the data have no point left where one is needed.
pub(crate) fn make_room(
    fitting: &mut Vec<(usize, bool)>,
    tangents: &[usize],
    chords: &ChordLengths,
    closed: bool,
) -> Result<(), SubdivFitError> {
    let n = chords.len();
    for &t in tangents {
        match fitting.binary_search_by_key(&t, |f| f.0) {
            Ok(pos) => fitting[pos].1 = false,
            Err(pos) => fitting.insert(pos, (t, false)),
        }
    }
    // Each pass adds one point or fails, and there are at most n fitting points.
    for _ in 0..n {
        let Some((index, (a, b))) = cramped(fitting, tangents, closed, n) else {
            return Ok(());
        };
        let inside = |i: usize| {
            let u = if i < a { i + n } else { i };
            u > a && u < b
        };
        let count = fitting.iter().filter(|f| inside(f.0)).count() + 1;
        fitting.retain(|f| !inside(f.0));
        let (start, length) = (chords.at(a), chords.at(b) - chords.at(a));
        let mut last = a;
        let mut placed = 0;
        for m in 1..=count {
            let target = start + length * m as f64 / (count + 1) as f64;
            if let Some(i) = chords.nearest_interior(a, b, target) {
                let u = if i < a { i + n } else { i };
                if u > last {
                    fitting.push((i, false));
                    (last, placed) = (u, placed + 1);
                }
            }
        }
        if placed < count {
            return Err(SubdivFitError::InvalidTangentJoint {
                index,
                reason: "no room for two regular fitting points between it and a corner, an end \
                         of the data or itself",
            });
        }
        fitting.sort_unstable_by_key(|f| f.0);
    }
    Ok(())
}

/// The largest ratio of the chord lengths of the two segments next to a tangent joint.
///
/// The curve is C1 in its parameter at a double knot, so it leaves the joint on both sides with
/// one speed, about the length of the segments there (module `tangent_rows`); segments of very
/// different lengths on the two sides make one of them far from uniform in its parameter, where
/// the curve bends away from the data and the foot-point iteration of the error measure fails.
pub(crate) const BALANCE: f64 = 2.0;

/// Splits the longer segment next to a tangent joint (at its chord-length middle) while it is
/// more than [`BALANCE`] times as long as the other; returns the number of points inserted.
pub(crate) fn balance(
    fitting: &mut Vec<(usize, bool)>,
    tangents: &[usize],
    chords: &ChordLengths,
    closed: bool,
) -> usize {
    let n = chords.len();
    let before = fitting.len();
    for _ in 0..n {
        let k = fitting.len();
        let unwrap = |j: usize| {
            if j < k {
                fitting[j].0
            } else {
                fitting[j - k].0 + n
            }
        };
        let mut split = None;
        for j in 0..k {
            if tangents.binary_search(&fitting[j].0).is_err() || (!closed && (j == 0 || j + 1 == k))
            {
                continue;
            }
            // Unwrapped data indices of the previous, this and the next fitting point.
            let (p, c, q) = if j == 0 {
                (unwrap(k - 1), fitting[0].0 + n, unwrap(k + 1))
            } else {
                (unwrap(j - 1), unwrap(j), unwrap(j + 1))
            };
            let (left, right) = (chords.at(c) - chords.at(p), chords.at(q) - chords.at(c));
            if left > BALANCE * right {
                split = chords.middle(p, c);
            } else if right > BALANCE * left {
                split = chords.middle(c, q);
            }
            if split.is_some() {
                break;
            }
        }
        let Some(m) = split else {
            break;
        };
        match fitting.binary_search_by_key(&m, |f| f.0) {
            Ok(_) => break,
            Err(pos) => fitting.insert(pos, (m, false)),
        }
    }
    fitting.len() - before
}

/// The first tangent joint without room and the span (unwrapped data indices of its ends, `b`
/// may exceed `n`) between the sharp point (or end) that crowds it and the tangent joint nearest
/// that point; `None` when every joint has room.
fn cramped(
    fitting: &[(usize, bool)],
    tangents: &[usize],
    closed: bool,
    n: usize,
) -> Option<(usize, (usize, usize))> {
    let k = fitting.len();
    let is_tangent = |j: usize| tangents.binary_search(&fitting[j].0).is_ok();
    let blocks = |j: usize| fitting[j].1 || (!closed && (j == 0 || j + 1 == k));
    // From data index x forward to y, unwrapped.
    let span = |x: usize, y: usize| (x, if y > x { y } else { y + n });
    for j in (0..k).filter(|&j| is_tangent(j)) {
        if closed && k < 2 * ROOM + 1 {
            // Too few points to go round: from the joint to the next one (or round to itself).
            let t = (1..=k).map(|o| (j + o) % k).find(|&t| is_tangent(t))?;
            return Some((fitting[j].0, span(fitting[j].0, fitting[t].0)));
        }
        for step in 1..=ROOM {
            // Before the joint (open data have a sharp first point, so j ≥ step there).
            let c = (j + k - step) % k;
            if blocks(c) {
                // The tangent joint nearest the crowding point, on the way to j.
                let t = (1..=step).map(|o| (c + o) % k).find(|&t| is_tangent(t))?;
                return Some((fitting[j].0, span(fitting[c].0, fitting[t].0)));
            }
            // After it.
            let c = (j + step) % k;
            if blocks(c) {
                let t = (1..=step)
                    .map(|o| (c + k - o) % k)
                    .find(|&t| is_tangent(t))?;
                return Some((fitting[j].0, span(fitting[t].0, fitting[c].0)));
            }
        }
    }
    None
}
