//! Eq. (4) with tangent joints: the rows of a tangent vertex and its partner.
//!
//! A tangent joint is a fitting point with two control points, the tangent vertex `v` and its
//! partner `v + 1`, which share the joint's knot `K` (a double knot, module `tangent`). There the
//! blossom gives `C(K) = (p_v + p_{v+1}) / 2` and `C'(K) = 3/2 (p_{v+1} − p_v)` on both sides
//! (the knots next to `K` are one unit away), so the pair's rows are
//!
//! - `(p_v + p_{v+1}) / 2 = q`, the joint's data point, interpolated as every fitting point is;
//! - `3/2 (p_{v+1} − p_v) = L t`, with `t` the data's unit tangent at the joint (the mean of the
//!   one-sided quadratic estimates of module `corner_angles`) and `L` the mean chord length of the
//!   two segments next to it, the speed a uniform B-spline through points `L` apart has.
//!
//! These two rows fix `p_v` and `p_{v+1}` by themselves, so the two sides of a tangent joint
//! solve independently, as on either side of a sharp vertex: a straight side stays straight up to
//! the joint while the other bends. Every other row is that of eq. (4) at the vertex's knot, whose
//! weights next to the double knot come from the blossom of unit control points; the rows then
//! couple unknowns up to two apart, a band (module `band_lu`) instead of a tridiagonal system.
//!
//! Interpolating at the pair's Greville abscissae `K ∓ 1/3` instead (the data polyline a third of
//! a segment before and after the joint) was tried first and rejected: it couples the two sides
//! through `p_v` and `p_{v+1}`, so the arc's curvature leaked into the line (curvature 0.54 on the
//! straight side), and the insertion loop graded the points towards the joint; on the outline of
//! `tests/tangent_fit.rs` it needed more control points than no joint at all.

use bez_core::Vector;

use crate::assess::segment_polyline;
use crate::band_lu::{REACH, WIDTH, solve_band};
use crate::corner_angles::{REACH_SCALES, data_tangent};
use crate::curve::Closure;
use crate::insertion::segment_range;
use crate::tangent::{check_tangents, kinds_span_is_uniform, span_weights};
use crate::vertex::VertexKind;
use crate::{SubdivCurve, SubdivFitError};

/// What the row of a vertex interpolates.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Row {
    /// Its fitting point `j`, at its knot.
    Knot(usize),
    /// The tangent joint `j` (the tangent vertex's row).
    Joint(usize),
    /// The derivative at the tangent joint `j` (its partner's row), from the data's tangent
    /// number `t` (in `tangents`).
    Derivative(usize, usize),
}

/// The vertex kinds of the polygon of `fitting` (`(data index, sharp)`, one per knot) with the
/// tangent joints `tangents` (data indices, increasing), and the row of every vertex. The ends
/// of open data are sharp.
fn layout(
    fitting: &[(usize, bool)],
    tangents: &[usize],
    closed: bool,
) -> (Vec<VertexKind>, Vec<Row>) {
    let k = fitting.len();
    let mut kinds = Vec::with_capacity(k + tangents.len());
    let mut rows = Vec::with_capacity(k + tangents.len());
    for (j, &(index, sharp)) in fitting.iter().enumerate() {
        let end = !closed && (j == 0 || j + 1 == k);
        let tangent = tangents
            .binary_search(&index)
            .ok()
            .filter(|_| !(sharp || end));
        if let Some(t) = tangent {
            kinds.extend([VertexKind::Tangent, VertexKind::Regular]);
            rows.extend([Row::Joint(j), Row::Derivative(j, t)]);
        } else {
            kinds.push(if sharp || end {
                VertexKind::Sharp
            } else {
                VertexKind::Regular
            });
            rows.push(Row::Knot(j));
        }
    }
    (kinds, rows)
}

/// The data's unit tangent at each tangent joint (data indices, increasing): the mean of the
/// one-sided quadratic estimates (reach up to [`REACH_SCALES`] feature scales `sigma`, at most
/// half-way to the neighbouring sharp or tangent fitting point), or the chord through the joint's
/// neighbours where an estimate degenerates.
pub(crate) fn joint_tangents<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    tangents: &[usize],
    closed: bool,
    sigma: f64,
) -> Vec<Vector<D>> {
    each_joint(data, fitting, tangents, closed, sigma, |side| {
        Some(side(false, 1.0)? + side(true, 1.0)?)
    })
}

/// The data's unit tangent at each tangent joint held as a smooth joint: the one-sided estimate
/// (as in [`joint_tangents`]) of the side whose estimate moves least between the full reach and a
/// quarter of it. A straight side's does not move at all, so where a line meets an arc this is the
/// line's own direction (the mean is off it by about 10⁻⁵ rad at 10⁻³, more than the straight
/// side, fixed between two sharp vertices, can follow); the chord through the joint's neighbours
/// where an estimate degenerates.
pub(crate) fn smooth_joint_tangents<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    tangents: &[usize],
    closed: bool,
    sigma: f64,
) -> Vec<Vector<D>> {
    each_joint(data, fitting, tangents, closed, sigma, |side| {
        let stable = |forwards: bool| {
            let (full, quarter) = (side(forwards, 1.0)?, side(forwards, 0.25)?);
            Some((full, (full - quarter).norm()))
        };
        let ((a, da), (b, db)) = (stable(false)?, stable(true)?);
        Some(if da <= db { a } else { b })
    })
}

/// `estimate(side)` normalized for each tangent joint `c`, where `side(forwards, scale)` is the
/// data's one-sided tangent estimate leaving `c` forwards or backwards (reach `scale` times up to
/// [`REACH_SCALES`] feature scales `sigma`, at most half-way to the neighbouring sharp or tangent
/// fitting point, pointing along the data); the chord through `c`'s neighbours where `estimate`
/// has none.
fn each_joint<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    tangents: &[usize],
    closed: bool,
    sigma: f64,
    estimate: impl Fn(&dyn Fn(bool, f64) -> Option<Vector<D>>) -> Option<Vector<D>>,
) -> Vec<Vector<D>> {
    let n = data.len();
    // The joints (sharp or tangent fitting points) in data order; open data's ends are sharp.
    let bounds: Vec<usize> = fitting
        .iter()
        .filter(|f| f.1 || tangents.binary_search(&f.0).is_ok())
        .map(|f| f.0)
        .chain((!closed).then_some([0, n - 1]).into_iter().flatten())
        .collect::<std::collections::BTreeSet<usize>>()
        .into_iter()
        .collect();
    tangents
        .iter()
        .map(|&c| {
            let at = bounds.partition_point(|&b| b < c);
            let m = bounds.len();
            let (prev, next) = if closed {
                (bounds[(at + m - 1) % m], bounds[(at + 1) % m])
            } else {
                (bounds[at.saturating_sub(1)], bounds[(at + 1).min(m - 1)])
            };
            let gap = |a: usize, b: usize| if b > a { b - a } else { b + n - a };
            let (before, after) = (gap(prev, c), gap(c, next));
            let side = |forwards: bool, scale: f64| {
                let gap = if forwards { after } else { before };
                let reach = scale * REACH_SCALES * sigma;
                data_tangent(
                    data,
                    closed,
                    c,
                    forwards,
                    gap.div_ceil(2),
                    reach,
                    sigma.min(reach),
                )
            };
            let direction =
                estimate(&side).unwrap_or_else(|| data[(c + 1) % n] - data[(c + n - 1) % n]);
            let norm = direction.norm();
            if norm > 0.0 && norm.is_finite() {
                direction / norm
            } else {
                direction
            }
        })
        .collect()
}

/// The chord length of the data polyline `a..=b` (indices mod n).
fn polyline_length<const D: usize>(data: &[Vector<D>], a: usize, b: usize) -> f64 {
    segment_polyline(data, a, b)
        .windows(2)
        .map(|w| (w[1] - w[0]).norm())
        .sum()
}

/// Solves eq. (4) for the fitting points `fitting` with the tangent joints `tangents` (data
/// indices of fitting points, increasing) and the data's unit tangents `directions` there
/// ([`joint_tangents`]): sharp rows `p_i = q_i`, regular rows `C(k_i) = q_i`, and the pair of
/// each tangent joint as in the module documentation.
///
/// # Errors
/// [`SubdivFitError::InvalidTangent`] when a tangent joint has no room for its double knot (the
/// fit makes room before), [`SubdivFitError::SingularSystem`].
pub(crate) fn solve_with_tangents<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    tangents: &[usize],
    directions: &[Vector<D>],
    closed: bool,
) -> Result<SubdivCurve<D>, SubdivFitError> {
    let (kinds, rows) = layout(fitting, tangents, closed);
    check_tangents(&kinds, closed)?;
    let (n, k) = (data.len(), fitting.len());
    let targets: Vec<Vector<D>> = rows
        .iter()
        .map(|&row| match row {
            Row::Knot(j) | Row::Joint(j) => data[fitting[j].0],
            Row::Derivative(j, t) => {
                let (a, b) = segment_range(fitting, (j + k - 1) % k, n);
                let (c, d) = segment_range(fitting, j, n);
                // The shorter side's: a side whose segment is longer than the speed is only
                // slower near the joint, while a faster start would overshoot the shorter one.
                let speed = polyline_length(data, a, b).min(polyline_length(data, c, d));
                directions[t] * speed
            }
        })
        .collect();
    let points = interpolate(&kinds, closed, &targets)
        .ok_or(SubdivFitError::SingularSystem { size: kinds.len() })?;
    SubdivCurve::new(points, kinds, Closure::from_closed(closed))
}

/// The control points of the curve, for a polygon with these kinds (tangent vertices with room,
/// see [`check_tangents`]), that takes the values `targets`: `p_i` itself at a sharp vertex, the
/// value at the knot at a regular vertex and at a tangent vertex, and at a tangent vertex's
/// partner the first derivative at their common knot. `None` when the system is singular.
pub(crate) fn interpolate<const D: usize>(
    kinds: &[VertexKind],
    closed: bool,
    targets: &[Vector<D>],
) -> Option<Vec<Vector<D>>> {
    let nv = kinds.len();
    let mut band = vec![[0.0; WIDTH]; nv];
    for (v, row) in band.iter_mut().enumerate() {
        let previous = (v + nv - 1) % nv;
        let next = (v + 1) % nv;
        let weights: Vec<(usize, f64)> = match kinds[v] {
            VertexKind::Sharp => vec![(v, 1.0)],
            VertexKind::Tangent => vec![(v, 0.5), (next, 0.5)],
            _ if (closed || v > 0) && kinds[previous] == VertexKind::Tangent => {
                vec![(previous, -1.5), (v, 1.5)]
            }
            _ if kinds_span_is_uniform(kinds, closed, v) => {
                vec![(previous, 1.0 / 6.0), (v, 4.0 / 6.0), (next, 1.0 / 6.0)]
            }
            _ => span_weights(kinds, closed, v, 0.0).to_vec(),
        };
        for (col, w) in weights {
            // The offset of `col` from `v`, cyclically within ±REACH.
            let mut o = col as isize - v as isize;
            if closed && o > REACH as isize {
                o -= nv as isize;
            } else if closed && o < -(REACH as isize) {
                o += nv as isize;
            }
            if w != 0.0 {
                *row.get_mut(usize::try_from(o + REACH as isize).ok()?)? += w;
            }
        }
    }
    let rhs: Vec<[f64; D]> = targets.iter().map(|&t| <[f64; D]>::from(t)).collect();
    let x = solve_band(&band, &rhs, closed)?;
    Some(x.into_iter().map(Vector::<D>::from).collect())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use bez_core::Vector2;

    /// A closed and an open polygon with tangent vertices, sharp ones and regular ones.
    fn curves() -> Vec<SubdivCurve<2>> {
        let ring: Vec<Vector2> = (0..16)
            .map(|i| {
                let t = i as f64 * 0.4;
                Vector2::new((1.0 + 0.3 * (3.0 * t).sin()) * t.cos(), t.sin() + 0.1 * t)
            })
            .collect();
        let kinds_at = |n: usize, tangent: &[usize], sharp: &[usize]| {
            let mut kinds = vec![VertexKind::Regular; n];
            for &t in tangent {
                kinds[t] = VertexKind::Tangent;
            }
            for &s in sharp {
                kinds[s] = VertexKind::Sharp;
            }
            kinds
        };
        vec![
            SubdivCurve::new(
                ring[..14].to_vec(),
                kinds_at(14, &[2, 4, 12], &[9]),
                Closure::Closed,
            )
            .unwrap(),
            SubdivCurve::new(ring.clone(), kinds_at(16, &[3, 10], &[7]), Closure::Open).unwrap(),
            SubdivCurve::new(ring[..7].to_vec(), kinds_at(7, &[0], &[]), Closure::Closed).unwrap(),
            SubdivCurve::new(ring, kinds_at(16, &[], &[5]), Closure::Closed).unwrap(),
        ]
    }

    /// The curve's values at the knots and its derivatives at the double knots (evaluated
    /// independently, by `eval` and `eval_derivatives`) give its control polygon back.
    #[test]
    fn knot_values_and_joint_derivatives_give_the_polygon_back() {
        for curve in curves() {
            let kinds = curve.kinds();
            let nv = kinds.len();
            let mut knot = 0.0;
            let mut targets = Vec::new();
            for v in 0..nv {
                let target = match kinds[v] {
                    VertexKind::Sharp => curve.points()[v],
                    _ if v > 0 && kinds[v - 1] == VertexKind::Tangent => {
                        curve.eval_derivatives(knot).unwrap().first
                    }
                    _ => curve.eval(knot).unwrap(),
                };
                targets.push(target);
                if kinds[v] != VertexKind::Tangent {
                    knot += 1.0;
                }
            }
            let back = interpolate(kinds, curve.is_closed(), &targets).unwrap();
            for (b, p) in back.iter().zip(curve.points()) {
                assert!((b - p).norm() < 1e-12, "{b:?} vs {p:?}");
            }
        }
    }
}
