//! Tangent vertices: a double knot in the cubic B-spline, for joints that are tangent-continuous
//! but free in curvature (a line meeting an arc).
//!
//! Every vertex `i` carries the knot `k_i` of the uniform cubic B-spline (its limit is at the
//! global parameter `k_i`, the middle knot of its basis function). A [`VertexKind::Tangent`]
//! vertex `v` shares its knot with the next vertex, `k_{v+1} = k_v`: the edge `p_v p_{v+1}` has
//! no segment, and the knot `k_v` is double. There the curve is C1 in its parameter (G1), its
//! tangent is along `p_{v+1} − p_v`, and its second derivative jumps: the segment before depends
//! on `p_{v−2} … p_{v+1}`, the one after on `p_v … p_{v+3}`. With equal knot spacing on both
//! sides the joint is the midpoint `(p_v + p_{v+1}) / 2` (the blossom `f(k, k, k)`).
//!
//! Segments whose six knots include the double knot are evaluated through their blossom
//! (module `knots`): exact evaluation by de Boor, Bézier form by full knot insertion; refinement
//! inserts the midpoint of every segment (Boehm / Oslo), which keeps the knot double and the
//! vertex a tangent vertex. Sharp vertices keep their phantom-point rule, so they must stay out of
//! the reach of the double knot (checked by [`check_tangents`]).

use bez_core::Vector;

use crate::SubdivFitError;
use crate::curve::SubdivCurve;
use crate::knots::{blossom, span_bezier};
use crate::vertex::VertexKind;

/// The tangent vertices of `kinds` (increasing), after checking that each has room for its
/// double knot: the vertices two before to three after it are not sharp, its neighbours are not
/// tangent (that would be a triple knot, only C0), a closed polygon has at least 6 vertices and
/// an open one has 3 vertices before it and 4 after it (its ends are sharp).
pub(crate) fn check_tangents(
    kinds: &[VertexKind],
    closed: bool,
) -> Result<Vec<usize>, SubdivFitError> {
    let n = kinds.len();
    let tangents: Vec<usize> = (0..n)
        .filter(|&i| kinds[i] == VertexKind::Tangent)
        .collect();
    for &index in &tangents {
        let invalid = |reason| Err(SubdivFitError::InvalidTangent { index, reason });
        if closed && n < 6 {
            return invalid("a closed polygon with a tangent vertex needs at least 6 vertices");
        }
        if !closed && (index < 3 || index + 5 > n) {
            return invalid(
                "a tangent vertex of an open polygon needs 3 vertices before it and 4 after it",
            );
        }
        let at = |offset: isize| kinds[wrap(index, offset, n)];
        if at(-1) == VertexKind::Tangent || at(1) == VertexKind::Tangent {
            return invalid("the neighbours of a tangent vertex must not be tangent vertices");
        }
        if (-2..=3).any(|o| at(o).is_sharp()) {
            return invalid("no sharp vertex may lie two before to three after a tangent vertex");
        }
    }
    Ok(tangents)
}

/// `(i + offset) mod n`.
fn wrap(i: usize, offset: isize, n: usize) -> usize {
    (i as isize + offset).rem_euclid(n as isize) as usize
}

/// The knot length of edge `j` (from `p_j` to `p_{j+1}`, modulo `n` when closed): 0 after a
/// tangent vertex, else 1 (also beyond the ends of an open polygon, where the phantom points
/// continue the uniform knots).
fn edge_length<const D: usize>(curve: &SubdivCurve<D>, j: isize) -> f64 {
    knot_length(curve.kinds(), curve.is_closed(), j)
}

/// [`edge_length`] of a polygon with these vertex kinds.
fn knot_length(kinds: &[VertexKind], closed: bool, j: isize) -> f64 {
    let n = kinds.len();
    let kind = if closed {
        Some(kinds[j.rem_euclid(n as isize) as usize])
    } else {
        usize::try_from(j)
            .ok()
            .filter(|&j| j + 1 < n)
            .map(|j| kinds[j])
    };
    if kind == Some(VertexKind::Tangent) {
        0.0
    } else {
        1.0
    }
}

/// The edge of segment `i` (segments skip the edges after tangent vertices).
pub(crate) fn edge_of_segment(tangents: &[usize], i: usize) -> usize {
    let mut e = i;
    for &t in tangents {
        if t <= e {
            e += 1;
        } else {
            break;
        }
    }
    e
}

/// Whether the six knots of the segment on edge `e` are equally spaced (no double knot among
/// them), so that the uniform closed form applies.
pub(crate) fn span_is_uniform<const D: usize>(curve: &SubdivCurve<D>, e: usize) -> bool {
    kinds_span_is_uniform(curve.kinds(), curve.is_closed(), e)
}

/// The knots `u₀ … u₅` of the segment on edge `e`, relative to its start.
fn span_knots<const D: usize>(curve: &SubdivCurve<D>, e: usize) -> [f64; 6] {
    knots_of(curve.kinds(), curve.is_closed(), e)
}

/// [`span_knots`] of a polygon with these vertex kinds.
fn knots_of(kinds: &[VertexKind], closed: bool, e: usize) -> [f64; 6] {
    let e = e as isize;
    let u1 = -knot_length(kinds, closed, e - 1);
    let u0 = u1 - knot_length(kinds, closed, e - 2);
    let u4 = 1.0 + knot_length(kinds, closed, e + 1);
    let u5 = u4 + knot_length(kinds, closed, e + 2);
    [u0, u1, 0.0, 1.0, u4, u5]
}

/// The weights of the control points `p_{e−1} … p_{e+2}` (indices modulo `n`) in the point at
/// `x ∈ [0, 1]` of the segment on edge `e` of a polygon with these kinds, where that segment is
/// next to a double knot (no phantom point): the blossom `f(x, x, x)` of unit control points.
pub(crate) fn span_weights(
    kinds: &[VertexKind],
    closed: bool,
    e: usize,
    x: f64,
) -> [(usize, f64); 4] {
    let unit =
        |i: usize| Vector::<4>::from(std::array::from_fn(|c| if c == i { 1.0 } else { 0.0 }));
    let w = blossom(
        &knots_of(kinds, closed, e),
        &[unit(0), unit(1), unit(2), unit(3)],
        [x, x, x],
    );
    let n = kinds.len();
    [0, 1, 2, 3].map(|c| (wrap(e, c as isize - 1, n), w[c]))
}

/// Whether the segment on edge `e` of a polygon with these kinds has uniform knots.
pub(crate) fn kinds_span_is_uniform(kinds: &[VertexKind], closed: bool, e: usize) -> bool {
    (-2..=2).all(|o| knot_length(kinds, closed, e as isize + o) == 1.0)
}

/// The control points `p_{e−1} … p_{e+2}` of a segment next to a double knot (no phantom point:
/// [`check_tangents`] keeps sharp vertices away, and the ends of an open polygon too).
fn span_points<const D: usize>(curve: &SubdivCurve<D>, e: usize) -> [Vector<D>; 4] {
    let p = curve.points();
    let n = p.len();
    [-1, 0, 1, 2].map(|o| p[wrap(e, o, n)])
}

/// The Bézier points of the segment on edge `e`, next to a double knot.
pub(crate) fn span_bezier_points<const D: usize>(
    curve: &SubdivCurve<D>,
    e: usize,
) -> [Vector<D>; 4] {
    span_bezier(&span_knots(curve, e), &span_points(curve, e))
}

/// The segment next to vertex `i` used for its values (the one starting there, or the one ending
/// there after a tangent vertex) and `i`'s knot relative to that segment's start.
fn vertex_span<const D: usize>(curve: &SubdivCurve<D>, i: usize) -> (usize, f64) {
    let n = curve.points().len();
    if edge_length(curve, i as isize) == 1.0 {
        (i, 0.0)
    } else {
        ((i + n - 1) % n, 1.0)
    }
}

/// The limit position `C(k_i)` of a regular or tangent vertex `i` whose segment is next to a
/// double knot (`None` where the uniform mask applies).
pub(crate) fn vertex_limit<const D: usize>(curve: &SubdivCurve<D>, i: usize) -> Option<Vector<D>> {
    if curve.is_sharp(i) {
        return None;
    }
    let (e, x) = vertex_span(curve, i);
    (!span_is_uniform(curve, e))
        .then(|| blossom(&span_knots(curve, e), &span_points(curve, e), [x, x, x]))
}

/// One level of refinement of a polygon with tangent vertices: the midpoint of every segment is
/// inserted as a knot. The V-vertex of vertex `i` is the blossom `f(k_i − ℓ_{i−1}/2, k_i,
/// k_i + ℓ_i/2)` and the E-vertex of a segment `f(k_i, k_i + 1/2, k_i + 1)` (ℓ the edges' knot
/// lengths); where the knots are uniform these are the rules of Sec. 2.1. V-vertices keep their
/// kind, E-vertices are regular, and an edge of knot length 0 gets no E-vertex.
pub(crate) fn refine_with_tangents<const D: usize>(
    curve: &SubdivCurve<D>,
) -> (Vec<Vector<D>>, Vec<VertexKind>) {
    let p = curve.points();
    let n = p.len();
    let edges = if curve.is_closed() { n } else { n - 1 };
    let mut points = Vec::with_capacity(2 * n);
    let mut kinds = Vec::with_capacity(2 * n);
    for i in 0..n {
        let v = if curve.is_sharp(i) {
            p[i]
        } else {
            let (e, x) = vertex_span(curve, i);
            if span_is_uniform(curve, e) {
                (p[(i + n - 1) % n] + 6.0 * p[i] + p[(i + 1) % n]) / 8.0
            } else {
                let before = edge_length(curve, i as isize - 1);
                let after = edge_length(curve, i as isize);
                let args = [x - 0.5 * before, x, x + 0.5 * after];
                blossom(&span_knots(curve, e), &span_points(curve, e), args)
            }
        };
        points.push(v);
        kinds.push(curve.kinds()[i]);
        if i < edges && edge_length(curve, i as isize) == 1.0 {
            points.push(if span_is_uniform(curve, i) {
                (p[i] + p[(i + 1) % n]) * 0.5
            } else {
                blossom(
                    &span_knots(curve, i),
                    &span_points(curve, i),
                    [0.0, 0.5, 1.0],
                )
            });
            kinds.push(VertexKind::Regular);
        }
    }
    (points, kinds)
}
