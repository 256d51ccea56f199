//! Corners whose sides keep their curvature ([`VertexKind::SharpCurved`]): the parabolic end
//! condition (the project's addition).
//!
//! The span of the limit curve between two consecutive sharp vertices `P` (index `j`) and `Q` is a
//! uniform cubic B-spline with control points `e₋₁, e₀, e₁, …, e_m, e_{m+1}` over its `m`
//! segments, `e₁ … e_{m−1}` the regular vertices between them. Each end takes two conditions,
//! which fix the two control points beyond the regular ones:
//!
//! - **Natural** (the paper's [`VertexKind::Sharp`]): `e₀ = P` and the phantom point
//!   `e₋₁ = 2P − e₁`, so the curve passes through `P` with zero second derivative there (the
//!   natural end of a cubic spline).
//! - **Parabolic** ([`VertexKind::SharpCurved`], on a side with at least one regular vertex): the
//!   curve passes through `P`, `(e₋₁ + 4e₀ + e₁)/6 = P`, and the first segment is a parabola, its
//!   third difference `e₋₁ − 3e₀ + 3e₁ − e₂ = 0`. Solved:
//!
//!   `e₀ = (6P + 2e₁ − e₂) / 7`,  `e₋₁ = (18P − 15e₁ + 4e₂) / 7`,
//!
//!   with `e₂` the next vertex (regular, or a natural `Q`). Where `Q` is parabolic too and
//!   `m = 2`, `e₂` is `Q`'s own derived point and the two conditions couple; the span is then one
//!   parabola: `e₀ = (7P + 2e₁ − Q) / 8`, `e₋₁ = (5P − 4e₁ + Q) / 2`.
//!
//! A side without a regular vertex (`m = 1`, two corners joined by an edge) is the straight
//! segment of the natural rule at either kind. Both conditions hold for every refinement of
//! the span (the first half of a parabola is a parabola), so the kind survives refinement and
//! the derived points are unique: refinement applies the regular rules with the derived `e₀` in
//! place of `P`.
//!
//! The curve still interpolates `P`; its one-sided tangent there is
//! `C′(0) = (e₁ − e₋₁)/2 = (11e₁ − 2e₂ − 9P)/7` (`(6e₁ − 5P − Q)/4` in the coupled case; see
//! [`side_tangent`]) and its curvature there is free, as that of a TrueType quadratic leaving a
//! corner.

use bez_core::Vector;

use crate::SubdivCurve;
use crate::vertex::VertexKind;

/// A derived control point as a combination of polygon vertices: `(vertex, weight)` pairs, the
/// unused ones with weight 0.
pub(crate) type Weights = [(usize, f64); 3];

/// The two derived control points at one end of a span.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SpanEnd {
    /// The control point `e₀` that stands for the corner in the uniform B-spline.
    pub(crate) control: Weights,
    /// The phantom point `e₋₁` beyond it.
    pub(crate) phantom: Weights,
}

/// `(i ± 1) mod n`, or `None` beyond the ends of an open polygon.
fn step(i: usize, forwards: bool, n: usize, closed: bool) -> Option<usize> {
    match (forwards, closed) {
        (true, _) if i + 1 < n => Some(i + 1),
        (true, true) => Some(0),
        (false, _) if i > 0 => Some(i - 1),
        (false, true) => Some(n - 1),
        _ => None,
    }
}

/// The end of the span that leaves the sharp vertex `j` forwards (`forwards`, towards `j + 1`) or
/// backwards: its derived control and phantom points as weights on the vertices (see the module
/// docs). `kinds[j]` must be sharp and the vertex next to it on that side must exist.
pub(crate) fn span_end(kinds: &[VertexKind], closed: bool, j: usize, forwards: bool) -> SpanEnd {
    let n = kinds.len();
    let Some(n1) = step(j, forwards, n, closed) else {
        // No segment on this side (an open polygon's end): never asked for by a segment.
        return natural(j, j);
    };
    if kinds[j] != VertexKind::SharpCurved || kinds[n1].is_sharp() {
        return natural(j, n1);
    }
    // n1 is regular and an open polygon's ends are sharp, so n2 exists.
    let n2 = step(n1, forwards, n, closed).unwrap_or(n1);
    if kinds[n2] == VertexKind::SharpCurved {
        SpanEnd {
            control: [(j, 7.0 / 8.0), (n1, 2.0 / 8.0), (n2, -1.0 / 8.0)],
            phantom: [(j, 5.0 / 2.0), (n1, -4.0 / 2.0), (n2, 1.0 / 2.0)],
        }
    } else {
        SpanEnd {
            control: [(j, 6.0 / 7.0), (n1, 2.0 / 7.0), (n2, -1.0 / 7.0)],
            phantom: [(j, 18.0 / 7.0), (n1, -15.0 / 7.0), (n2, 4.0 / 7.0)],
        }
    }
}

/// The paper's end: `e₀ = P`, `e₋₁ = 2P − e₁`.
fn natural(j: usize, n1: usize) -> SpanEnd {
    SpanEnd {
        control: [(j, 1.0), (j, 0.0), (j, 0.0)],
        phantom: [(j, 2.0), (n1, -1.0), (j, 0.0)],
    }
}

/// The point `weights` stands for.
pub(crate) fn point<const D: usize>(weights: &Weights, points: &[Vector<D>]) -> Vector<D> {
    weights
        .iter()
        .fold(Vector::<D>::zeros(), |acc, &(v, w)| acc + points[v] * w)
}

/// The control point that a regular vertex sees at its neighbour `m` when walking from it
/// (`forwards` is the direction from `m` back to the regular vertex): `p_m` for a regular
/// neighbour, the derived `e₀` of the span end at a sharp one.
pub(crate) fn neighbour_control(
    kinds: &[VertexKind],
    closed: bool,
    m: usize,
    forwards: bool,
) -> Weights {
    if kinds[m].is_sharp() {
        span_end(kinds, closed, m, forwards).control
    } else {
        [(m, 1.0), (m, 0.0), (m, 0.0)]
    }
}

/// The curve's one-sided tangent at the sharp vertex `j` on the side `forwards` (towards `j + 1`)
/// or backwards, pointing away from the corner along that side; its derivative by the span's
/// parameter, `±(e₁ − e₋₁)/2`.
pub(crate) fn side_tangent<const D: usize>(
    kinds: &[VertexKind],
    points: &[Vector<D>],
    closed: bool,
    j: usize,
    forwards: bool,
) -> Vector<D> {
    let n = kinds.len();
    let Some(n1) = step(j, forwards, n, closed) else {
        return Vector::<D>::zeros();
    };
    let end = span_end(kinds, closed, j, forwards);
    (points[n1] - point(&end.phantom, points)) * 0.5
}

/// The corner's tangent on one side as an affine condition on its neighbour: the side's
/// derivative is proportional to `p[n1] − partner.1 · p[partner.0] − anchor`, with `anchor` a
/// combination of the sharp vertices (fixed in every solve) and `partner` the regular vertex one
/// further, if the derived points use it. From `C′(0) = (e₁ − e₋₁)/2` with the phantom point's
/// weights `w`: divided by `1 − w_{n1}`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SideLine<const D: usize> {
    /// The neighbour `n1` of the corner on this side.
    pub(crate) vertex: usize,
    /// The regular vertex beyond it and its coefficient.
    pub(crate) partner: Option<(usize, f64)>,
    /// The fixed part.
    pub(crate) anchor: Vector<D>,
}

/// [`SideLine`] of the sharp vertex `j` of `curve` on the side `forwards`; `None` beyond an open
/// end.
pub(crate) fn side_line<const D: usize>(
    curve: &SubdivCurve<D>,
    j: usize,
    forwards: bool,
) -> Option<SideLine<D>> {
    let (kinds, points, closed) = (curve.kinds(), curve.points(), curve.is_closed());
    let n1 = step(j, forwards, kinds.len(), closed)?;
    let phantom = span_end(kinds, closed, j, forwards).phantom;
    let w1: f64 = phantom.iter().filter(|e| e.0 == n1).map(|e| e.1).sum();
    let scale = 1.0 / (1.0 - w1);
    let mut anchor = Vector::<D>::zeros();
    let mut partner = None;
    for &(v, w) in &phantom {
        if v == n1 || w == 0.0 {
            continue;
        }
        if kinds[v].is_sharp() {
            anchor += points[v] * (w * scale);
        } else {
            partner = Some((v, w * scale));
        }
    }
    Some(SideLine {
        vertex: n1,
        partner,
        anchor,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Closure, SubdivCurve, Vector2};

    fn polygon() -> Vec<Vector2> {
        [
            (0.0, 0.0),
            (1.0, 1.2),
            (2.5, 1.6),
            (4.0, 0.9),
            (4.6, -0.5),
            (3.0, -1.6),
            (1.2, -1.3),
        ]
        .iter()
        .map(|&(x, y)| Vector2::new(x, y))
        .collect()
    }

    /// The uniform B-spline control points of a span, rebuilt from the curve's segments, satisfy
    /// both end conditions: the curve passes through the corner and the first segment's third
    /// difference vanishes (a parabola), for spans of 2, 3 and 4 segments on both sides.
    #[test]
    fn parabolic_ends_pass_through_the_corner_as_parabolas() {
        let p = polygon();
        for corners in [vec![0, 3], vec![0, 4], vec![0, 2], vec![0, 1, 4], vec![0]] {
            let mut kinds = vec![VertexKind::Regular; p.len()];
            for &c in &corners {
                kinds[c] = VertexKind::SharpCurved;
            }
            let curve = SubdivCurve::new(p.clone(), kinds.clone(), Closure::Closed).unwrap();
            for s in 0..curve.segment_count() {
                let [a, b, c, d] = curve.segment_controls(s).unwrap();
                let start = (a + 4.0 * b + c) / 6.0;
                let end = (b + 4.0 * c + d) / 6.0;
                let e = s + 1;
                let e = if e == p.len() { 0 } else { e };
                if kinds[s].is_sharp() {
                    assert!((start - p[s]).norm() < 1e-14, "{corners:?} {s}");
                }
                if kinds[e].is_sharp() {
                    assert!((end - p[e]).norm() < 1e-14, "{corners:?} {s}");
                }
                let neighbour_sharp = kinds[e].is_sharp();
                let third = a - 3.0 * b + 3.0 * c - d;
                if (kinds[s].is_sharp() || neighbour_sharp)
                    && !(kinds[s].is_sharp() && neighbour_sharp)
                {
                    assert!(third.norm() < 1e-13, "{corners:?} segment {s}: {third:?}");
                }
            }
        }
    }

    /// The side line's direction is the side tangent's, at both kinds and in the coupled case.
    #[test]
    fn side_lines_point_along_the_tangents() {
        let p = polygon();
        for corners in [vec![0, 3], vec![0, 2], vec![0, 1]] {
            for kind in [VertexKind::Sharp, VertexKind::SharpCurved] {
                let mut kinds = vec![VertexKind::Regular; p.len()];
                for &c in &corners {
                    kinds[c] = kind;
                }
                let curve = SubdivCurve::new(p.clone(), kinds.clone(), Closure::Closed).unwrap();
                for forwards in [true, false] {
                    let line = side_line(&curve, 0, forwards).unwrap();
                    let mut q = p[line.vertex] - line.anchor;
                    if let Some((v, c)) = line.partner {
                        q -= p[v] * c;
                    }
                    let t = side_tangent(&kinds, &p, true, 0, forwards);
                    let cross = q.x() * t.y() - q.y() * t.x();
                    assert!(
                        cross.abs() < 1e-12 && q.dot(&t) > 0.0,
                        "{corners:?} {kind:?}"
                    );
                }
            }
        }
    }

    /// The tangent formula agrees with the first derivative of the segment at the corner.
    #[test]
    fn side_tangents_are_the_segment_derivatives() {
        let p = polygon();
        let mut kinds = vec![VertexKind::Regular; p.len()];
        kinds[0] = VertexKind::SharpCurved;
        kinds[3] = VertexKind::SharpCurved;
        let curve = SubdivCurve::new(p.clone(), kinds.clone(), Closure::Closed).unwrap();
        let out = side_tangent(&kinds, &p, true, 3, true);
        let d = curve.eval_segment_derivatives(3, 0.0).unwrap().first;
        assert!((out - d).norm() < 1e-13);
        let back = side_tangent(&kinds, &p, true, 3, false);
        let d = curve.eval_segment_derivatives(2, 1.0).unwrap().first;
        assert!((back + d).norm() < 1e-13);
    }

    /// Refinement keeps the limit curve: the refined curve at `2s` is the curve at `s`, for every
    /// mix of the two sharp kinds, closed and open, through two levels.
    #[test]
    fn refinement_keeps_the_limit_curve() {
        let p = polygon();
        let mixes: [&[(usize, VertexKind)]; 5] = [
            &[(0, VertexKind::SharpCurved), (3, VertexKind::SharpCurved)],
            &[(0, VertexKind::SharpCurved), (2, VertexKind::SharpCurved)],
            &[
                (0, VertexKind::SharpCurved),
                (1, VertexKind::SharpCurved),
                (4, VertexKind::Sharp),
            ],
            &[
                (0, VertexKind::SharpCurved),
                (2, VertexKind::Sharp),
                (5, VertexKind::SharpCurved),
            ],
            &[(6, VertexKind::SharpCurved)],
        ];
        for closure in [Closure::Closed, Closure::Open] {
            for mix in mixes {
                let mut kinds = vec![VertexKind::Regular; p.len()];
                for &(v, k) in mix {
                    kinds[v] = k;
                }
                if closure == Closure::Open {
                    kinds[0] = VertexKind::SharpCurved;
                }
                let curve = SubdivCurve::new(p.clone(), kinds, closure).unwrap();
                let fine = curve.refine_levels(2).unwrap();
                assert_eq!(fine.segment_count(), 4 * curve.segment_count());
                let total = curve.segment_count() as f64;
                for m in 0..=64 {
                    let s = total * f64::from(m) / 64.0;
                    let a = curve.eval(s).unwrap();
                    let b = fine.eval(4.0 * s).unwrap();
                    assert!(
                        (a - b).norm() < 1e-12,
                        "{closure:?} {mix:?} s = {s}: {a:?} vs {b:?}"
                    );
                }
                for i in 0..p.len() {
                    let want = curve.eval((i as f64).min(total)).unwrap();
                    if closure == Closure::Closed || i < p.len() {
                        let got = curve.limit_position(i).unwrap();
                        assert!(
                            (got - want).norm() < 1e-12,
                            "{closure:?} {mix:?} vertex {i}"
                        );
                    }
                }
            }
        }
    }

    /// A curved corner that turns keeps curvature on a side where the paper's sharp vertex has
    /// none.
    #[test]
    fn curved_sides_have_curvature_at_the_corner() {
        let p = polygon();
        let mut kinds = vec![VertexKind::Regular; p.len()];
        kinds[0] = VertexKind::Sharp;
        let flat = SubdivCurve::new(p.clone(), kinds.clone(), Closure::Closed).unwrap();
        kinds[0] = VertexKind::SharpCurved;
        let curved = SubdivCurve::new(p, kinds, Closure::Closed).unwrap();
        let cross = |c: &SubdivCurve<2>| {
            let d = c.eval_segment_derivatives(0, 0.0).unwrap();
            d.first.x() * d.second.y() - d.first.y() * d.second.x()
        };
        assert!(cross(&flat).abs() < 1e-12);
        assert!(cross(&curved).abs() > 0.1);
    }
}
