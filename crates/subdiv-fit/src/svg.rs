//! Export as SVG path data.

use std::fmt::Write as _;

use crate::{SubdivCurve, SubdivFitError};

/// The curve as SVG path data of exact cubic Bézier segments (`M x y C x1 y1 x2 y2 x y …`, closed
/// with `Z`), using the first two coordinates.
///
/// # Errors
/// Only on non-finite intermediate values.
pub fn svg_path<const D: usize>(curve: &SubdivCurve<D>) -> Result<String, SubdivFitError> {
    let beziers = curve.to_beziers()?;
    let mut s = String::new();
    let xy = |p: &bez_core::Vector<D>| (p[0], if D > 1 { p[1] } else { 0.0 });
    for (i, b) in beziers.iter().enumerate() {
        let pts = b.points();
        if i == 0 {
            let (x, y) = xy(&pts[0]);
            let _ = write!(s, "M {x} {y}");
        }
        let (x1, y1) = xy(&pts[1]);
        let (x2, y2) = xy(&pts[2]);
        let (x3, y3) = xy(&pts[3]);
        let _ = write!(s, " C {x1} {y1} {x2} {y2} {x3} {y3}");
    }
    if curve.is_closed() {
        s.push_str(" Z");
    }
    Ok(s)
}
