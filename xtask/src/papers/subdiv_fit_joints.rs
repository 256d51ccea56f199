//! subdiv-fit on outlines whose curvature jumps where they stay tangent-continuous (lines meeting
//! circular arcs): without joints, with the path's tangent joints as double knots (the
//! interpolating fit), and with them as smooth joints (`Reduction::Refit`), each measured against
//! the exact outline.

use std::fmt::Write as _;

use kurbo::{Arc, BezPath, PathSeg, Point, Vec2};
use serde_json::{Value, json};
use subdiv_fit::{
    EXACT_CORNER_TOLERANCE, FitOptions, Reduction, TANGENT_JUMP, VertexKind, fit_bez_path,
};

use super::subdiv_fit_glyphs::{glyphs, outline_error};
use crate::DynError;
use crate::tables::Table;

/// The arcs' cubic approximation (kurbo's `Arc::append_iter`) is within this of the circle.
const ARC_TOLERANCE: f64 = 1e-10;

/// A piece of an outline: a line to a point, or a circular arc (centre, radius, start angle,
/// sweep).
enum Piece {
    Line(Point),
    Arc(Point, f64, f64, f64),
}

/// The outline from `start` through `pieces` (closed with `ClosePath` when `closed`), with the
/// points where a line meets an arc.
fn outline(start: Point, pieces: &[Piece], closed: bool) -> (BezPath, Vec<Point>) {
    let mut path = BezPath::new();
    path.move_to(start);
    let mut last = start;
    let mut joints = Vec::new();
    for (i, piece) in pieces.iter().enumerate() {
        if i > 0 || closed {
            joints.push(last);
        }
        match *piece {
            Piece::Line(to) => {
                path.line_to(to);
                last = to;
            }
            Piece::Arc(centre, radius, angle, sweep) => {
                let arc = Arc::new(centre, (radius, radius), angle, sweep, 0.0);
                path.extend(arc.append_iter(ARC_TOLERANCE));
                last = centre + Vec2::from_angle(angle + sweep) * radius;
            }
        }
    }
    if closed {
        path.close_path();
    }
    (path, joints)
}

/// (name, outline, joints): lines of length 2 meeting arcs of radius 1 (3 for the last).
fn outlines() -> Vec<(&'static str, BezPath, Vec<Point>)> {
    use std::f64::consts::{FRAC_PI_2, PI};
    let o = Point::ORIGIN;
    let named = |name, (path, joints)| (name, path, joints);
    vec![
        named(
            "line, 90° arc, line",
            outline(
                Point::new(-2.0, 0.0),
                &[
                    Piece::Line(o),
                    Piece::Arc(Point::new(0.0, 1.0), 1.0, -FRAC_PI_2, FRAC_PI_2),
                    Piece::Line(Point::new(1.0, 3.0)),
                ],
                false,
            ),
        ),
        named(
            "line, 180° arc, line (hairpin)",
            outline(
                Point::new(-2.0, 0.0),
                &[
                    Piece::Line(o),
                    Piece::Arc(Point::new(0.0, 1.0), 1.0, -FRAC_PI_2, PI),
                    Piece::Line(Point::new(-2.0, 2.0)),
                ],
                false,
            ),
        ),
        named(
            "stadium",
            outline(
                Point::new(-1.0, -1.0),
                &[
                    Piece::Line(Point::new(1.0, -1.0)),
                    Piece::Arc(Point::new(1.0, 0.0), 1.0, -FRAC_PI_2, PI),
                    Piece::Line(Point::new(-1.0, 1.0)),
                    Piece::Arc(Point::new(-1.0, 0.0), 1.0, FRAC_PI_2, PI),
                ],
                true,
            ),
        ),
        named(
            "line into a 90° arc of radius 3",
            outline(
                Point::new(-2.0, 0.0),
                &[
                    Piece::Line(o),
                    Piece::Arc(Point::new(0.0, 3.0), 3.0, -FRAC_PI_2, FRAC_PI_2),
                ],
                false,
            ),
        ),
    ]
}

fn configurations(tol: f64) -> [(&'static str, FitOptions); 4] {
    let refit = FitOptions::new(tol)
        .with_reduction(Reduction::Refit)
        .with_corner_kind(VertexKind::SharpCurved);
    [
        ("no joints (default options)", FitOptions::new(tol)),
        (
            "tangent joints as double knots (default options, `tangent_jump`)",
            FitOptions::new(tol).with_tangent_jump(Some(TANGENT_JUMP)),
        ),
        ("no joints (`Refit`, curved corners)", refit),
        (
            "smooth joints (`Refit`, curved corners, `tangent_jump`)",
            refit.with_tangent_jump(Some(TANGENT_JUMP)),
        ),
    ]
}

/// The largest turn (radians) of `fitted` (cubic segments) at the points `at`: between the end
/// tangent of the segment arriving there and the start tangent of the one leaving, from their
/// control points; `None` where a point is no joint of two segments of `fitted`.
fn turn_at(fitted: &BezPath, at: &[Point]) -> Option<f64> {
    let cubics: Vec<kurbo::CubicBez> = fitted
        .segments()
        .filter_map(|s| match s {
            PathSeg::Cubic(c) => Some(c),
            _ => None,
        })
        .collect();
    let m = cubics.len();
    let mut worst = 0.0_f64;
    for p in at {
        let i = (0..m).find(|&i| (cubics[i].p3 - *p).hypot() < 1e-9)?;
        let (a, b) = (cubics[i], cubics[(i + 1) % m]);
        let (u, v): (Vec2, Vec2) = (a.p3 - a.p2, b.p1 - b.p0);
        worst = worst.max(u.cross(v).abs().atan2(u.dot(v)));
    }
    Some(worst)
}

pub(crate) fn table() -> Result<Table, DynError> {
    let mut md = String::from(
        "## subdiv-fit: tangent joints where lines meet arcs\n\n\
         Outlines of lines (length 2) meeting circular arcs (radius 1, or 3) tangentially, so that the curvature jumps at each joint (the arcs as kurbo's cubic approximation within 10⁻¹⁰ of the circle), fitted with `fit_bez_path` (samples about every tolerance). With `tangent_jump`, the path's smooth joints where the curvature jumps are the tangent joints: double knots in the interpolating fit, smooth joints (sharp vertices held on the path's tangent, `Corner::smooth`) with `Reduction::Refit`.\n\
         Max error: the two-sided distance to the exact outline (16 samples per segment each way, nearest points on the other side). Max turn at the joints: between the fit's one-sided tangents there, from the control points of the Bézier segments that meet at the joint (not measured where the fit has no knot at the joint).\n\n\
         | outline | tolerance | fit | joints | control points | max error | max turn at the joints (rad) |\n\
         |---|---|---|---|---|---|---|\n",
    );
    let mut rows = Vec::new();
    for (name, outline, at) in outlines() {
        for tol in [1e-2, 1e-3, 1e-4] {
            for (fit_name, options) in configurations(tol) {
                let (fitted, fits) = fit_bez_path(&outline, &options)?;
                let joints: usize = fits.iter().map(|f| f.tangents.len()).sum();
                let points: usize = fits.iter().map(|f| f.curve.points().len()).sum();
                let error = outline_error(&fitted, &outline);
                let turn = if joints > 0 {
                    turn_at(&fitted, &at)
                } else {
                    None
                };
                writeln!(
                    md,
                    "| {name} | {tol:e} | {fit_name} | {joints} | {points} | {error:.2e} | {} |",
                    turn.map_or(String::new(), |t| format!("{t:.1e}"))
                )?;
                rows.push(json!({
                    "outline": name, "tolerance": tol, "fit": fit_name, "joints": joints,
                    "control_points": points, "max_error": error,
                    "within_tolerance": error <= tol, "max_turn": turn,
                }));
            }
        }
    }
    let glyph_rows = glyph_rows(&mut md)?;
    Ok(Table {
        name: "subdiv-fit-joints".into(),
        markdown: md,
        checked: json!({ "outlines": rows, "glyphs": glyph_rows }),
    })
}

/// The glyph table's outlines (DejaVu Sans, printable ASCII) at 10⁻³ em with `Reduction::Refit`
/// and curved corners, without and with the corner bound, each without and with the path's
/// tangent joints as smooth joints; appends its section to `md` and returns its rows.
fn glyph_rows(md: &mut String) -> Result<Vec<Value>, DynError> {
    let glyphs = glyphs()?;
    let tol = 1e-3;
    let curved = FitOptions::new(tol)
        .with_reduction(Reduction::Refit)
        .with_corner_kind(VertexKind::SharpCurved);
    let bound = curved.with_corner_tolerance(Some(EXACT_CORNER_TOLERANCE));
    let joints = Some(TANGENT_JUMP);
    write!(
        md,
        "\n### The same on glyph outlines\n\n\
         The printable ASCII glyphs of DejaVu Sans (the glyph table's {} outlines) at 10⁻³ em, `Reduction::Refit` with curved corners, without and with the 0.9° bound on the corners' turns, each without and with `tangent_jump` = `TANGENT_JUMP` (the implied on-curve points of the TrueType quadratics are smooth joints where the curvature usually jumps). Max error as above, largest over the glyphs; max turn at the joints: between the fit's one-sided tangents at its smooth joints.\n\n\
         | fit | joints | control points | max error (em) | glyphs over | max turn at the joints (rad) |\n\
         |---|---|---|---|---|---|\n",
        glyphs.len()
    )?;
    let mut rows = Vec::new();
    for (name, options) in [
        ("curved corners", curved),
        (
            "curved corners, smooth joints",
            curved.with_tangent_jump(joints),
        ),
        ("curved corners, bound 0.9°", bound),
        (
            "curved corners, bound 0.9°, smooth joints",
            bound.with_tangent_jump(joints),
        ),
    ] {
        let (mut points, mut found, mut error, mut over, mut turn) = (0, 0, 0.0_f64, 0, 0.0_f64);
        for g in &glyphs {
            let (path, fits) = fit_bez_path(&g.outline, &options)?;
            for f in &fits {
                points += f.curve.points().len();
                found += f.tangents.len();
                for index in &f.tangents {
                    let j = f
                        .fitting
                        .binary_search(index)
                        .map_err(|_| "joint not a knot")?;
                    let Some((Some(a), Some(b))) = f.curve.corner_tangents(j) else {
                        return Err("joint not a sharp vertex".into());
                    };
                    turn = turn.max(a.perp(&b).abs().atan2(a.dot(&b)));
                }
            }
            let e = outline_error(&path, &g.outline);
            error = error.max(e);
            over += usize::from(e > tol);
        }
        let turn = (found > 0).then_some(turn);
        writeln!(
            md,
            "| {name} | {found} | {points} | {error:.2e} | {over} | {} |",
            turn.map_or(String::new(), |t| format!("{t:.1e}"))
        )?;
        rows.push(json!({
            "fit": name, "joints": found, "control_points": points, "max_error": error,
            "glyphs_over": over, "max_turn": turn,
        }));
    }
    Ok(rows)
}
