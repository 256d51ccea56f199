//! The uniform cubic B-spline basis on one segment.

use bez_core::Vector;

/// `B(u) = ((1−u)³, 3u³ − 6u² + 4, −3u³ + 3u² + 3u + 1, u³) / 6`, the uniform cubic B-spline
/// basis of eq. (1) on `u ∈ [0, 1]`; the segment runs between the 2nd and 3rd control points.
#[must_use]
pub fn bspline_basis(u: f64) -> [f64; 4] {
    let v = 1.0 - u;
    let u2 = u * u;
    let u3 = u2 * u;
    [
        v * v * v / 6.0,
        (3.0 * u3 - 6.0 * u2 + 4.0) / 6.0,
        (-3.0 * u3 + 3.0 * u2 + 3.0 * u + 1.0) / 6.0,
        u3 / 6.0,
    ]
}

/// `B'(u)`.
#[must_use]
pub fn bspline_basis_d1(u: f64) -> [f64; 4] {
    let v = 1.0 - u;
    [
        -v * v / 2.0,
        (3.0 * u * u - 4.0 * u) / 2.0,
        (-3.0 * u * u + 2.0 * u + 1.0) / 2.0,
        u * u / 2.0,
    ]
}

/// `B''(u)`.
#[must_use]
pub fn bspline_basis_d2(u: f64) -> [f64; 4] {
    [1.0 - u, 3.0 * u - 2.0, 1.0 - 3.0 * u, u]
}

/// Exact conversion of one uniform cubic B-spline segment `(a, b, c, d)` to Bézier form:
/// `((a + 4b + c)/6, (2b + c)/3, (b + 2c)/3, (b + 4c + d)/6)`.
#[must_use]
pub fn bspline_to_bezier<const D: usize>(ctrl: &[Vector<D>; 4]) -> [Vector<D>; 4] {
    let [a, b, c, d] = *ctrl;
    [
        (a + 4.0 * b + c) / 6.0,
        (2.0 * b + c) / 3.0,
        (b + 2.0 * c) / 3.0,
        (b + 4.0 * c + d) / 6.0,
    ]
}

/// The inverse of [`bspline_to_bezier`]: the uniform cubic B-spline control points
/// `(6 B₀ − 4b − c, b, c, 6 B₃ − b − 4c)` with `b = 2 B₁ − B₂`, `c = 2 B₂ − B₁` of the cubic with
/// Bézier points `B`; every cubic on `[0, 1]` has exactly one such form.
pub(crate) fn bezier_to_bspline<const D: usize>(bez: &[Vector<D>; 4]) -> [Vector<D>; 4] {
    let [b0, b1, b2, b3] = *bez;
    let b = 2.0 * b1 - b2;
    let c = 2.0 * b2 - b1;
    [6.0 * b0 - 4.0 * b - c, b, c, 6.0 * b3 - b - 4.0 * c]
}
