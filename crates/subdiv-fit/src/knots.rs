//! One span of a cubic B-spline on arbitrary knots, through its blossom.
//!
//! A cubic B-spline span `[u₂, u₃]` with knots `u₀ … u₅` and control points `d₀ … d₃` is the
//! diagonal `C(x) = f(x, x, x)` of its blossom `f`, the symmetric function affine in each argument
//! with `f(u_i, u_{i+1}, u_{i+2}) = d_i`. The de Boor algorithm with one argument per level
//! evaluates `f` anywhere; with three equal arguments it is de Boor's evaluation, with the knots of
//! a refined knot vector it gives the refined control points (knot insertion, Boehm / Oslo), and
//! with `f(u₂, u₂, u₂), f(u₂, u₂, u₃), f(u₂, u₃, u₃), f(u₃, u₃, u₃)` the span's Bézier points (every
//! knot inserted to full multiplicity).

use bez_core::Vector;

/// The blossom `f(x₀, x₁, x₂)` of the span `[u₂, u₃]` (with `u₂ < u₃` and `u₀ ≤ … ≤ u₅`).
pub(crate) fn blossom<const D: usize>(u: &[f64; 6], d: &[Vector<D>; 4], x: [f64; 3]) -> Vector<D> {
    let mut p = *d;
    for (r, &x) in (1..=3).zip(&x) {
        for i in (r..=3).rev() {
            let (lo, hi) = (u[i - 1], u[i + 3 - r]);
            let a = (x - lo) / (hi - lo);
            p[i] = (1.0 - a) * p[i - 1] + a * p[i];
        }
    }
    p[3]
}

/// The Bézier points of the span `[u₂, u₃]`.
pub(crate) fn span_bezier<const D: usize>(u: &[f64; 6], d: &[Vector<D>; 4]) -> [Vector<D>; 4] {
    let (a, b) = (u[2], u[3]);
    [
        blossom(u, d, [a, a, a]),
        blossom(u, d, [a, a, b]),
        blossom(u, d, [a, b, b]),
        blossom(u, d, [b, b, b]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::bspline_to_bezier;
    use bez_core::Vector2;

    fn points() -> [Vector2; 4] {
        [
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 2.0),
            Vector2::new(3.0, 1.5),
            Vector2::new(4.0, -1.0),
        ]
    }

    /// On uniform knots the Bézier points are those of the closed form.
    #[test]
    fn uniform_span_matches_the_closed_form() {
        let u = [-2.0, -1.0, 0.0, 1.0, 2.0, 3.0];
        let got = span_bezier(&u, &points());
        let want = bspline_to_bezier(&points());
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).norm() < 1e-14, "{g:?} vs {w:?}");
        }
    }

    /// The blossom at the control points' own knots gives them back, and it is symmetric.
    #[test]
    fn blossom_interpolates_its_control_points_and_is_symmetric() {
        let u = [-1.5, -1.0, 0.0, 0.0 + 1.0, 1.0 + 0.0, 2.5];
        let d = points();
        for i in 0..4 {
            let back = blossom(&u, &d, [u[i], u[i + 1], u[i + 2]]);
            assert!((back - d[i]).norm() < 1e-14, "{i}");
        }
        let x = [0.2, 0.7, 0.4];
        let a = blossom(&u, &d, x);
        let b = blossom(&u, &d, [x[2], x[0], x[1]]);
        assert!((a - b).norm() < 1e-14);
    }
}
