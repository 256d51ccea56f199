//! Kept corners keep their angle (the project's addition; the paper only interpolates the corner
//! point).
//!
//! At a sharp vertex `p_j` the limit curve's one-sided tangents are the polygon edges
//! `p_j − p_{j−1}` and `p_{j+1} − p_j` (the phantom points of the closed form), so the turn of the
//! curve at a corner is the turn of the control polygon there, set by the two neighbouring control
//! points. Eq. (4) places them from the fitting points next to the corner: the turn is right to
//! about the curvature times the length of the corner's segments, and a reduction that lengthens
//! those segments moves it.
//!
//! The tangents a corner's turn is bounded against ([`CornerTangents`], found once per fit) are
//! the exact ones of a known corner that states them ([`Corner::with_tangents`]), or else the
//! data's: on each side of a corner at data point `c`, the linear coefficient `b` of
//! the least-squares quadratic `v(t) = v_c + b t + a t²` through the corner point, in the
//! polyline length `t` of the samples on that side ([`data_tangent`]): over a reach of at most
//! [`REACH_SCALES`] feature scales and half the way to the next sharp fitting point, halved while
//! the quadratic misses the samples by more than an RMS of [`MODEL_FIT`] times the reach (a bend
//! the quadratic cannot follow biases its tangent), down to one feature scale; dense data are
//! thinned to about [`SAMPLES`] samples over the reach (tested: an arc of
//! radius 1 over a reach of 0.1 to 10⁻⁴ rad, a line exactly; noise of amplitude `ε` moves the
//! estimate by about `ε / reach`). Only sharp vertices where these estimates turn by at least
//! [`MIN_TURN`] (20°, or the corner angle if smaller) count as corners: a bend found as a corner at
//! the feature scale that the data resolve as smooth keeps its turn unchecked. A known corner with
//! tangents always counts.
//!
//! [`cone_rays`] are the rays `p_j ± λ t` that a corner's free neighbours are constrained to
//! in [`Reduction::Refit`](crate::Reduction::Refit)'s least-squares refits (one unknown `λ` per
//! side, see `on_rays`); [`neighbours_on_tangents`] moves a corner's neighbouring control points
//! onto the tangent lines after each solve of the other modes (in least-squares mode the rest is
//! solved again around them; with interpolation only by up to a quarter of the tolerance, since
//! nothing else adapts); [`corner_insertions`] are the points the fitting loop inserts next to a
//! corner whose turn is still off once the distance tolerance is met (a neighbour that is sharp or
//! shared by two corners stays where the solve put it); [`corner_turns_kept`] is the check a
//! reduction step calls.
//!
//! A smooth joint ([`Corner::smooth`], or a tangent joint with `Reduction::Refit`) is a sharp
//! vertex whose turn is held at zero ([`SMOOTH_JOINT_TURN`]): in a refit, a side whose other side
//! is final (fitted in an earlier span) is put on that side's direction exactly, any other side on
//! the joint's tangent (a straight edge between two sharp vertices, which no ray turns, is
//! accepted within [`SMOOTH_SIDE`] of an estimated tangent). The other modes move both neighbours
//! onto the tangent by any distance (the fitting loop then refines next to the joint until the
//! distance holds), and insert no points for the turn.

use bez_core::Vector;

use crate::SubdivCurve;
use crate::chord::ChordLengths;
use crate::corner::Corner;
use crate::curvature::angle_between;
use crate::curved_corner::side_line;
use crate::fit::FitOptions;
use crate::insertion::segment_range;

/// A bound for [`FitOptions::corner_tolerance`] against the data's tangent estimates: 0.5° (in
/// radians), half of a 1° budget, the other half left to the estimate of the data's tangents.
pub const CORNER_TOLERANCE: f64 = 0.5 * std::f64::consts::PI / 180.0;

/// A bound for [`FitOptions::corner_tolerance`] when the corners come with their exact tangents
/// ([`Corner::with_tangents`], as `fit_bez_path` (feature `kurbo`) gives them): 0.9° (in
/// radians). The bound is then the whole error of a kept corner's turn against the outline's, so
/// it can take nearly all of a 1° budget; the last 0.1° is a margin for the outline's tangents
/// themselves (a path's control points are often rounded to a grid, and a joint where a tangent
/// turns by less than `PATH_CORNER_ANGLE` (feature `kurbo`) counts as smooth).
pub const EXACT_CORNER_TOLERANCE: f64 = 0.9 * std::f64::consts::PI / 180.0;

/// The longest reach of a one-sided tangent estimate, in feature scales σ.
pub(crate) const REACH_SCALES: f64 = 16.0;

/// About how many samples on each side of a corner enter its tangent estimate (dense data are
/// thinned to this).
pub(crate) const SAMPLES: usize = 32;

/// The RMS residual, relative to the reach, above which a one-sided quadratic is refitted over
/// half the reach.
/// (A least-squares quadratic's tangent at its end is off by about 20 times its RMS residual over
/// the reach when the residual is the side's cubic term: 10⁻³ allowed 1.2° per side, and the
/// glyph table's corners were off by up to 3.7°; 10⁻⁴ allows 0.12°.)
pub(crate) const MODEL_FIT: f64 = 1e-4;

/// The turn of the data (at the finest scale of the estimate) from which a sharp vertex counts as
/// a corner whose turn is bounded: 20°, or the corner angle `π − sharp_angle` if that is smaller.
/// A bend found as a corner at the feature scale but resolved by the data as smooth turns by less.
pub(crate) const MIN_TURN: f64 = std::f64::consts::PI / 9.0;

/// The turn of the fit at a smooth joint ([`Corner::smooth`]): at most 10⁻⁹ rad,
/// tangent-continuous but for rounding. A side fitted after the other is held on the other's
/// direction exactly; this bound only lets the checks pass despite rounding.
pub const SMOOTH_JOINT_TURN: f64 = 1e-9;

/// How far a smooth joint's side that is a straight edge between two sharp vertices (which no ray
/// turns) may leave the joint's tangent while the other side is still open, when the tangent is
/// the data's estimate (a tangent joint of [`fit_with_joints`]): 0.45° (in radians), a side's
/// share of [`EXACT_CORNER_TOLERANCE`]. The other side then follows it exactly. Every other side,
/// and every side at a given tangent ([`Corner::smooth`]), is held on the tangent itself.
///
/// [`fit_with_joints`]: crate::fit_with_joints
pub(crate) const SMOOTH_SIDE: f64 = 0.5 * EXACT_CORNER_TOLERANCE;

/// One bounded corner: its data index, the incoming and outgoing unit tangents there, the bound
/// on its turn's error ([`FitOptions::corner_tolerance`], or [`SMOOTH_JOINT_TURN`] for a smooth
/// joint) and whether it is a smooth joint.
#[derive(Debug, Clone, Copy)]
struct Bounded<const D: usize> {
    index: usize,
    incoming: Vector<D>,
    outgoing: Vector<D>,
    bound: f64,
    /// For a smooth joint, how far a side may leave the tangent while the other is open.
    smooth: Option<f64>,
}

/// The corners whose turn [`FitOptions::corner_tolerance`] bounds and the smooth joints, with
/// their tangents and bounds: found once per fit (the sharp fitting points, which the tangent
/// estimates depend on, stay the same through the insertion loop, the span fit and the
/// reductions, which only add or remove regular points). Only the smooth joints when the option
/// is `None`.
#[derive(Debug, Clone)]
pub(crate) struct CornerTangents<const D: usize> {
    /// By increasing data index.
    list: Vec<Bounded<D>>,
}

/// A ray `anchor + λ direction`, `λ > 0`, that control point `vertex` less `partner.1` times the
/// control point `partner.0` is constrained to: the tangent of a corner on the side of `vertex`
/// (at a [`VertexKind::Sharp`](crate::VertexKind::Sharp) corner `vertex` itself on the ray from
/// the corner, at a curved one the combination that the side's tangent follows, module
/// `curved_corner`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Ray<const D: usize> {
    pub(crate) vertex: usize,
    pub(crate) partner: Option<(usize, f64)>,
    pub(crate) anchor: Vector<D>,
    /// Unit direction.
    pub(crate) direction: Vector<D>,
}

impl<const D: usize> Ray<D> {
    /// The constrained point `p[vertex] − c p[partner]` of `points`.
    pub(crate) fn constrained(&self, points: &[Vector<D>]) -> Vector<D> {
        let p = points[self.vertex];
        self.partner.map_or(p, |(v, c)| p - points[v] * c)
    }

    /// `points` with `vertex` moved so that the constrained point is `target`.
    fn place(&self, points: &mut [Vector<D>], target: Vector<D>) {
        points[self.vertex] = self.partner.map_or(target, |(v, c)| target + points[v] * c);
    }
}

/// How far a curve's corner is from the tangents it is bounded against.
struct Deviation {
    /// |turn of the curve − turn of the tangents|.
    turn: f64,
    /// Angle between the curve's and the given incoming tangents.
    incoming: f64,
    /// Angle between the curve's and the given outgoing tangents.
    outgoing: f64,
}

impl<const D: usize> CornerTangents<D> {
    /// No bounded corner.
    pub(crate) fn none() -> Self {
        Self { list: Vec::new() }
    }

    /// The interior sharp vertices of the fitting points (open data's ends are not corners) that
    /// are `known` smooth joints; with [`FitOptions::corner_tolerance`] set, also those that are
    /// `known` corners with tangents, with those, or else where the data's estimates turn by at
    /// least [`MIN_TURN`] (or the corner angle), with the estimates. A smooth joint's side may
    /// leave its tangent by `smooth_side` while the other side is open (0 for a given tangent,
    /// [`SMOOTH_SIDE`] for an estimate).
    pub(crate) fn new(
        data: &[Vector<D>],
        fitting: &[(usize, bool)],
        closed: bool,
        known: &[Corner<D>],
        smooth_side: f64,
        options: &FitOptions,
    ) -> Self {
        let any_smooth = known.iter().any(Corner::is_smooth);
        let Some(bound) = options
            .corner_tolerance
            .or(any_smooth.then_some(SMOOTH_JOINT_TURN))
        else {
            return Self::none();
        };
        let n = data.len();
        let k = fitting.len();
        let sigma = options.feature_scale * options.tolerance;
        let sharp: Vec<usize> = (0..k).filter(|&j| fitting[j].1).collect();
        let min_turn = (std::f64::consts::PI - options.sharp_angle).min(MIN_TURN);
        let mut list = Vec::new();
        for (m, &j) in sharp.iter().enumerate() {
            if !closed && (j == 0 || j + 1 == k) {
                continue;
            }
            let c = fitting[j].0;
            if let Some(((incoming, outgoing), smooth)) = known
                .iter()
                .filter(|g| g.index() == c)
                .find_map(|g| Some((g.tangents()?, g.is_smooth())))
            {
                if smooth || options.corner_tolerance.is_some() {
                    list.push(Bounded {
                        index: c,
                        incoming,
                        outgoing,
                        bound: if smooth { SMOOTH_JOINT_TURN } else { bound },
                        smooth: smooth.then_some(smooth_side),
                    });
                }
                continue;
            }
            if options.corner_tolerance.is_none() {
                continue;
            }
            // Data points to the neighbouring sharp fitting points (or the data's ends).
            let (before, after) = if closed {
                let prev = fitting[sharp[(m + sharp.len() - 1) % sharp.len()]].0;
                let next = fitting[sharp[(m + 1) % sharp.len()]].0;
                let gap = |a: usize, b: usize| if b > a { b - a } else { b + n - a };
                (gap(prev, c), gap(c, next))
            } else {
                let prev = sharp[..m].last().map_or(0, |&p| fitting[p].0);
                let next = sharp.get(m + 1).map_or(n - 1, |&p| fitting[p].0);
                (c - prev, next - c)
            };
            let reach = REACH_SCALES * sigma;
            let tangent = |forwards: bool, gap: usize| {
                data_tangent(data, closed, c, forwards, gap.div_ceil(2), reach, sigma)
            };
            if let (Some(incoming), Some(outgoing)) = (tangent(false, before), tangent(true, after))
                && angle_between(&incoming, &outgoing) >= min_turn
            {
                list.push(Bounded {
                    index: c,
                    incoming,
                    outgoing,
                    bound,
                    smooth: None,
                });
            }
        }
        list.sort_unstable_by_key(|b| b.index);
        Self { list }
    }

    /// Whether no corner is bounded.
    pub(crate) fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The bounded corners among the sharp vertices of `fitting`: (vertex, corner), by vertex.
    fn at<'a>(
        &'a self,
        fitting: &'a [(usize, bool)],
    ) -> impl Iterator<Item = (usize, &'a Bounded<D>)> + 'a {
        self.list.iter().filter_map(|b| {
            let j = fitting.binary_search_by_key(&b.index, |f| f.0).ok()?;
            fitting[j].1.then_some((j, b))
        })
    }
}

/// How far the curve's turn at vertex `j` is from the corner's.
fn deviation<const D: usize>(curve: &SubdivCurve<D>, j: usize, corner: &Bounded<D>) -> Deviation {
    let zero = Vector::<D>::zeros();
    let (incoming, outgoing) = curve.corner_tangents(j).map_or((zero, zero), |(i, o)| {
        (i.unwrap_or(zero), o.unwrap_or(zero))
    });
    let turn = angle_between(&incoming, &outgoing);
    let data_turn = angle_between(&corner.incoming, &corner.outgoing);
    Deviation {
        turn: (turn - data_turn).abs(),
        incoming: angle_between(&incoming, &corner.incoming),
        outgoing: angle_between(&outgoing, &corner.outgoing),
    }
}

/// One side of a bounded corner, with the ray `p_j ± λ t` along the corner's tangent there that its
/// neighbour is constrained to.
struct Side<'a, const D: usize> {
    ray: Ray<D>,
    /// The corner's vertex.
    corner: usize,
    /// The side: after the corner (`true`) or before it.
    forwards: bool,
    bounded: &'a Bounded<D>,
}

/// The sides of the corners of `curve` (fitting points `fitting`) whose neighbour `movable` holds
/// for: each side's neighbour on the corner's tangent there, unless it is sharp itself (the
/// segment between two sharp vertices is a straight line) or the neighbour of two corners.
fn corner_sides<'a, const D: usize>(
    corners: &'a CornerTangents<D>,
    fitting: &'a [(usize, bool)],
    curve: &SubdivCurve<D>,
    movable: impl Fn(usize) -> bool,
) -> Vec<Side<'a, D>> {
    let k = fitting.len();
    let found: Vec<(usize, &Bounded<D>)> = corners.at(fitting).collect();
    let mut claims = vec![0u8; k];
    for &(j, _) in &found {
        claims[(j + k - 1) % k] += 1;
        claims[(j + 1) % k] += 1;
    }
    let mut sides = Vec::new();
    for (j, c) in found {
        if !movable((j + k - 1) % k) && !movable((j + 1) % k) {
            continue;
        }
        for (forwards, direction) in [(false, -c.incoming), (true, c.outgoing)] {
            let Some(line) = side_line(curve, j, forwards) else {
                continue;
            };
            let vertex = line.vertex;
            if !fitting[vertex].1 && claims[vertex] == 1 && movable(vertex) {
                sides.push(Side {
                    ray: Ray {
                        vertex,
                        partner: line.partner,
                        anchor: line.anchor,
                        direction,
                    },
                    corner: j,
                    forwards,
                    bounded: c,
                });
            }
        }
    }
    sides
}

/// The share of the bound `bound` that one side of a corner may take (the turn's error is at most
/// the sum of the two sides' deviations): what the other side leaves when that side is settled
/// (it will not move again, with deviation `other`), else half.
fn allowance(bound: f64, other: f64, settled: bool) -> f64 {
    if settled {
        (bound - other).max(0.0)
    } else {
        0.5 * bound
    }
}

/// Whether the side of corner vertex `j` (of `curve`, fitting points `fitting`) before or after it
/// (`forwards`) is settled: its control points do not move (not `movable`) and `settled` names it
/// by the corner's data index (a straight edge to the next sharp point is not settled by itself:
/// its span may still gain points).
fn side_settled<const D: usize>(
    curve: &SubdivCurve<D>,
    fitting: &[(usize, bool)],
    j: usize,
    forwards: bool,
    movable: &impl Fn(usize) -> bool,
    settled: &impl Fn(usize, bool) -> bool,
) -> bool {
    let Some(line) = side_line(curve, j, forwards) else {
        return true;
    };
    !movable(line.vertex)
        && line.partner.is_none_or(|(w, _)| !movable(w))
        && settled(fitting[j].0, forwards)
}

/// The rays of [`corner_sides`] for the sides of the corners where the curve `fitted` (fitting points
/// `fitting`) leaves the corner's tangent by more than the side's share of its bound ([`allowance`];
/// `settled` tells which sides outside the `movable` points are final), each turned from the
/// tangent towards the curve's side by that share (capped below 90°): the boundary of the cone
/// of directions within it that is nearest to the unconstrained fit (a side that points backwards
/// gets the tangent itself). Empty when every side is within its share. The shares are just inside
/// their values, so that the side checks pass despite rounding.
pub(crate) fn cone_rays<const D: usize>(
    corners: &CornerTangents<D>,
    fitting: &[(usize, bool)],
    fitted: &SubdivCurve<D>,
    movable: impl Fn(usize) -> bool,
    settled: impl Fn(usize, bool) -> bool,
) -> Vec<Ray<D>> {
    let mut rays = Vec::new();
    for side in corner_sides(corners, fitting, fitted, &movable) {
        let d = deviation(fitted, side.corner, side.bounded);
        let other = if side.forwards {
            d.incoming
        } else {
            d.outgoing
        };
        let other_settled = side_settled(
            fitted,
            fitting,
            side.corner,
            !side.forwards,
            &movable,
            &settled,
        );
        let mut ray = side.ray;
        let slack = if side.bounded.smooth.is_some() {
            // A smooth joint: on the other side's direction where that is final, else on the
            // tangent.
            if other_settled
                && let Some(direction) = other_direction(fitted, side.corner, side.forwards)
            {
                ray.direction = direction;
            }
            0.0
        } else {
            allowance(side.bounded.bound, other, other_settled).min(1.5) * (1.0 - 1e-6)
        };
        let edge = ray.constrained(fitted.points()) - ray.anchor;
        if angle_between(&edge, &ray.direction) <= slack {
            continue;
        }
        let across = edge - ray.direction * edge.dot(&ray.direction);
        let norm = across.norm();
        if edge.dot(&ray.direction) > 0.0 && norm > 0.0 {
            ray.direction = ray.direction * slack.cos() + across * (slack.sin() / norm);
        }
        rays.push(ray);
    }
    rays
}

/// Whether the side of corner vertex `j` of `curve` after it (`forwards`) or before it is a
/// straight edge to the next sharp vertex, which no ray turns.
fn straight<const D: usize>(curve: &SubdivCurve<D>, j: usize, forwards: bool) -> bool {
    side_line(curve, j, forwards).is_some_and(|line| curve.is_sharp(line.vertex))
}

/// The direction, away from corner vertex `j` of `curve`, that continues the curve's side before
/// the corner (`forwards`: the side after it is to follow) or after it (the side before is to
/// follow, pointing backwards); `None` where that side has no tangent.
fn other_direction<const D: usize>(
    curve: &SubdivCurve<D>,
    j: usize,
    forwards: bool,
) -> Option<Vector<D>> {
    let (incoming, outgoing) = curve.corner_tangents(j)?;
    let direction = if forwards { incoming? } else { -outgoing? };
    let norm = direction.norm();
    (norm > 0.0 && norm.is_finite()).then(|| direction / norm)
}

/// The control points of `curve` with the neighbours of its corners moved onto the corners'
/// tangent lines there (orthogonal projection, kept ahead of the corner), and which were moved;
/// `None` when none was. Only vertices for which `movable` holds move; a neighbour shared by two
/// corners, or sharp itself, or one that would move by more than `max_move` (unless its corner is
/// a smooth joint), stays.
pub(crate) fn neighbours_on_tangents<const D: usize>(
    corners: &CornerTangents<D>,
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    max_move: f64,
    movable: impl Fn(usize) -> bool,
) -> Option<(SubdivCurve<D>, Vec<bool>)> {
    let mut points = curve.points().to_vec();
    let mut moved = vec![false; points.len()];
    for side in corner_sides(corners, fitting, curve, movable) {
        let ray = side.ray;
        let q = ray.constrained(&points);
        let along = (q - ray.anchor).dot(&ray.direction);
        let target = ray.anchor + ray.direction * along;
        // The vertex moves by as much as the constrained point; a smooth joint's by any distance
        // (the fitting loop then refines next to it until the distance holds too).
        let within = side.bounded.smooth.is_some() || (target - q).norm() <= max_move;
        if along > 0.0 && within {
            ray.place(&mut points, target);
            moved[ray.vertex] = true;
        }
    }
    if !moved.contains(&true) {
        return None;
    }
    let curve = SubdivCurve::new(points, curve.kinds().to_vec(), curve.closure()).ok()?;
    Some((curve, moved))
}

/// The corner check of a reduction step: whether the trial curve `next` (fitting points `trial`)
/// keeps every corner's turn within [`FitOptions::corner_tolerance`] of the corner's, or at least
/// as close as the current curve `curve` (fitting points `fitting`, the same sharp vertices) has
/// it (a smooth joint within [`SMOOTH_JOINT_TURN`]). Always `true` without bounded corners.
pub(crate) fn corner_turns_kept<const D: usize>(
    corners: &CornerTangents<D>,
    trial: &[(usize, bool)],
    next: &SubdivCurve<D>,
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
) -> bool {
    corners
        .at(trial)
        .zip(corners.at(fitting))
        .all(|((t, c), (j, _))| {
            deviation(next, t, c).turn <= c.bound.max(deviation(curve, j, c).turn)
        })
}

/// The side check of [`Reduction::Refit`](crate::Reduction::Refit)'s span fit: whether the trial
/// curve `next` (fitting points `trial`) has the tangents of the corners at the ends of the span
/// between data indices `start` and `end` (the span's side of each) within their share of
/// [`FitOptions::corner_tolerance`] ([`allowance`]: what the other side leaves where it is settled,
/// as `settled` says by the corner's data index and side; else half), so that
/// the two spans at a corner keep its turn within the bound (a smooth joint's,
/// [`SMOOTH_JOINT_TURN`]). Always `true` without bounded corners.
pub(crate) fn span_sides_kept<const D: usize>(
    corners: &CornerTangents<D>,
    trial: &[(usize, bool)],
    next: &SubdivCurve<D>,
    n: usize,
    (start, end): (usize, usize),
    settled: impl Fn(usize, bool) -> bool,
) -> bool {
    let outside = |_: usize| false;
    corners.at(trial).all(|(j, c)| {
        if c.index != start % n && c.index != end % n {
            return true;
        }
        let d = deviation(next, j, c);
        let kept = |forwards: bool| {
            let (this, other) = if forwards {
                (d.outgoing, d.incoming)
            } else {
                (d.incoming, d.outgoing)
            };
            let other_settled = side_settled(next, trial, j, !forwards, &outside, &settled);
            if let Some(side) = c.smooth {
                // Along the other side where that is final; else on the tangent, or near it for
                // a straight edge to the next sharp vertex, which no ray turns.
                if other_settled {
                    d.turn <= c.bound
                } else if straight(next, j, forwards) {
                    this <= side.max(c.bound)
                } else {
                    this <= c.bound
                }
            } else {
                this <= allowance(c.bound, other, other_settled)
            }
        };
        (c.index != start % n || kept(true)) && (c.index != end % n || kept(false))
    })
}

/// Inserts, next to every corner whose turn in `curve` is off by more than
/// [`FitOptions::corner_tolerance`], a regular fitting point at the chord-length middle of the
/// corner's segment on each side whose tangent is off by more than half of it (at least one side
/// is: the turn's error is at most the sum of the sides'). Returns the number inserted: 0 when
/// every corner is within its bound, none is bounded, or the segments have no interior data.
pub(crate) fn corner_insertions<const D: usize>(
    corners: &CornerTangents<D>,
    chords: &ChordLengths,
    fitting: &mut Vec<(usize, bool)>,
    curve: &SubdivCurve<D>,
    n: usize,
) -> usize {
    let k = fitting.len();
    let mut new = Vec::new();
    // A smooth joint's sides are placed on its tangent by the refits, not by inserted points.
    for (j, corner) in corners.at(fitting).filter(|(_, c)| c.smooth.is_none()) {
        let bound = corner.bound;
        let d = deviation(curve, j, corner);
        if d.turn <= bound {
            continue;
        }
        for (off, segment) in [(d.incoming, (j + k - 1) % k), (d.outgoing, j)] {
            if off > 0.5 * bound {
                let (a, b) = segment_range(fitting, segment, n);
                new.extend(chords.middle(a, b));
            }
        }
    }
    let before = fitting.len();
    for i in new {
        if let Err(pos) = fitting.binary_search_by_key(&i, |f| f.0) {
            fitting.insert(pos, (i, false));
        }
    }
    fitting.len() - before
}

/// The data's unit tangent at data point `c`, leaving it forwards (`forwards`) or backwards along
/// the data, from at most `max_points` samples within `reach` of polyline length (at least one
/// sample), refined down to `min_reach` (see the module docs). `None` for a degenerate side.
pub(crate) fn data_tangent<const D: usize>(
    data: &[Vector<D>],
    closed: bool,
    c: usize,
    forwards: bool,
    max_points: usize,
    reach: f64,
    min_reach: f64,
) -> Option<Vector<D>> {
    let n = data.len();
    let origin = data[c];
    // (polyline length, offset from the corner) of the samples on this side.
    let mut side: Vec<(f64, Vector<D>)> = Vec::new();
    let (mut t, mut prev) = (0.0, origin);
    // About SAMPLES samples over the reach at the spacing next to the corner (lengths still add
    // every edge).
    let spacing = (data[(c + 1) % n] - origin)
        .norm()
        .max((data[(c + n - 1) % n] - origin).norm());
    let stride = (reach / (SAMPLES as f64 * spacing)).floor().max(1.0) as usize;
    for k in 1..=max_points.min(n - 1) {
        let i = if forwards {
            if !closed && c + k >= n {
                break;
            }
            (c + k) % n
        } else {
            if !closed && k > c {
                break;
            }
            (c + n - k) % n
        };
        t += (data[i] - prev).norm();
        prev = data[i];
        if t > reach && side.len() >= 2 {
            break;
        }
        if k % stride == 0 || k == 1 {
            side.push((t, data[i] - origin));
        }
    }
    let mut reach = side.last()?.0;
    loop {
        let used = side.partition_point(|s| s.0 <= reach).max(1);
        let (b, rms) = quadratic_tangent(&side[..used]);
        let norm = b.norm();
        if !(norm.is_finite() && norm > 0.0) {
            return None;
        }
        if used <= 2 || reach <= min_reach || rms <= MODEL_FIT * reach {
            return Some(if forwards { b / norm } else { -b / norm });
        }
        reach *= 0.5;
    }
}

/// The linear coefficient of the least-squares quadratic `b t + a t²` through the origin of the
/// samples `(t, v)` (in the units of `t` / `t_max`), and the RMS residual (in data units).
/// With one sample, or samples that do not determine a quadratic, the chord to the last one.
fn quadratic_tangent<const D: usize>(side: &[(f64, Vector<D>)]) -> (Vector<D>, f64) {
    let Some(&(scale, last)) = side.last() else {
        return (Vector::<D>::zeros(), 0.0);
    };
    let chord = (last, 0.0);
    if side.len() < 2 || scale <= 0.0 {
        return chord;
    }
    let (mut s2, mut s3, mut s4) = (0.0, 0.0, 0.0);
    let (mut r1, mut r2) = (Vector::<D>::zeros(), Vector::<D>::zeros());
    for &(t, v) in side {
        let x = t / scale;
        let x2 = x * x;
        s2 += x2;
        s3 += x2 * x;
        s4 += x2 * x2;
        r1 += v * x;
        r2 += v * x2;
    }
    let det = s2 * s4 - s3 * s3;
    if det <= 1e-12 * s2 * s4 {
        return chord;
    }
    let b = (r1 * s4 - r2 * s3) / det;
    let a = (r2 * s2 - r1 * s3) / det;
    let sum2: f64 = side
        .iter()
        .map(|&(t, v)| {
            let x = t / scale;
            (v - b * x - a * (x * x)).norm_squared()
        })
        .sum();
    (b, (sum2 / side.len() as f64).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use bez_core::Vector2;

    /// The one-sided quadratic recovers the tangent of an arc to far better than 0.01°, from
    /// either side, and a straight side exactly.
    #[test]
    fn one_sided_tangents_of_an_arc_and_a_line() {
        // Arc of radius 1 from angle 0 (the corner) counter-clockwise, then back along a line.
        let mut data: Vec<Vector2> = (0..200)
            .rev()
            .map(|k| {
                let t = 0.002 * k as f64;
                Vector2::new(t.cos(), t.sin())
            })
            .collect();
        let c = data.len() - 1;
        data.extend((1..100).map(|k| Vector2::new(1.0 - 0.003 * k as f64, -0.002 * k as f64)));
        // The arc arrives at (1, 0) heading down (clockwise traversal): tangent (0, −1).
        let incoming = data_tangent(&data, false, c, false, 200, 0.1, 0.006).unwrap();
        assert!(angle_between(&incoming, &Vector2::new(0.0, -1.0)) < 1e-4);
        let outgoing = data_tangent(&data, false, c, true, 100, 0.1, 0.006).unwrap();
        let exact = Vector2::new(-3.0, -2.0);
        assert!(angle_between(&outgoing, &exact) < 1e-12);
        // One sample: the chord.
        let chord = data_tangent(&data, false, c, true, 1, 0.1, 0.006).unwrap();
        assert!(angle_between(&chord, &exact) < 1e-12);
    }

    /// A short straight side that runs into a flat arc inside the reach (a glyph's stem meeting
    /// a bowl): the quadratic over line and arc misses the samples by little but bends towards
    /// the arc; the reach must shrink until the tangent is the line's to well within half of
    /// [`CORNER_TOLERANCE`] (with a residual bound of 10⁻³ of the reach it was 1.13° off).
    #[test]
    fn a_side_that_turns_into_an_arc_keeps_the_straight_tangent() {
        // From the corner at the origin along +x for 0.005, then an arc of radius 0.2 to the
        // left, sampled every 0.001.
        let mut data: Vec<Vector2> = (0..=5)
            .map(|k| Vector2::new(0.001 * k as f64, 0.0))
            .collect();
        data.extend((1..200).map(|k| {
            let t = 0.001 * k as f64 / 0.2;
            Vector2::new(0.005 + 0.2 * t.sin(), 0.2 * (1.0 - t.cos()))
        }));
        let t = data_tangent(&data, false, 0, true, data.len(), 0.096, 0.006).unwrap();
        let error = angle_between(&t, &Vector2::new(1.0, 0.0)).to_degrees();
        assert!(error < 0.1 * CORNER_TOLERANCE.to_degrees(), "{error}°");
    }

    /// A side that bends too much for one quadratic over the whole reach is refitted over less.
    #[test]
    fn a_tight_bend_shortens_the_reach() {
        // A quarter circle of radius 0.02 after the corner point: the long reach would see it.
        let data: Vec<Vector2> = (0..=400)
            .map(|k| {
                let t = std::f64::consts::FRAC_PI_2 * k as f64 / 400.0;
                Vector2::new(0.02 * t.sin(), 0.02 * (1.0 - t.cos()))
            })
            .collect();
        let t = data_tangent(&data, false, 0, true, 400, 0.03, 0.001).unwrap();
        assert!(angle_between(&t, &Vector2::new(1.0, 0.0)).to_degrees() < 0.1);
    }
}
