//! subdiv-fit on real outlines: the printable ASCII glyphs of DejaVu Sans (outlines shipped in
//! `xtask/data/`, under the font's licence), fitted contour by contour at 10⁻³ and 10⁻² em,
//! against the font's own TrueType point count and kurbo's `simplify_bezpath` on the same outlines.
//!
//! Every method's error is measured the same way, against the true outline (the TrueType
//! quadratics, not samples of them): 16 points per segment of the result to the nearest point of
//! the outline, and 16 points per outline segment to the nearest point of the result.

use std::fmt::Write as _;

use kurbo::simplify::{SimplifyOptions, simplify_bezpath};
use kurbo::{
    Affine, BezPath, ParamCurve, ParamCurveArclen, ParamCurveNearest, PathEl, PathSeg, Point, Vec2,
};
use serde_json::{Value, json};
use subdiv_fit::{
    EXACT_CORNER_TOLERANCE, FitMode, FitOptions, Reduction, VertexKind, fit_bez_path,
};

use crate::DynError;
use crate::tables::Table;
use crate::timing::{Run, best_cpu_micros};

const DATA: &str = include_str!("../../data/dejavu-sans-ascii.tsv");

/// Units per em of the font.
const UNITS_PER_EM: f64 = 2048.0;

/// One glyph: code point, TrueType point count, outline in em.
pub(super) struct Glyph {
    code: u32,
    points: usize,
    pub(super) outline: BezPath,
}

pub(super) fn glyphs() -> Result<Vec<Glyph>, DynError> {
    let mut out = Vec::new();
    for line in DATA.lines().filter(|l| !l.starts_with('#')) {
        let mut fields = line.split('\t');
        let (Some(code), Some(points), Some(d)) = (fields.next(), fields.next(), fields.next())
        else {
            return Err(format!("bad glyph line: {line}").into());
        };
        out.push(Glyph {
            code: u32::from_str_radix(code, 16)?,
            points: points.parse()?,
            outline: Affine::scale(1.0 / UNITS_PER_EM) * BezPath::from_svg(d)?,
        });
    }
    Ok(out)
}

/// Largest distance from 16 samples per segment of `a` to the nearest point of `b`.
fn one_sided(a: &BezPath, b: &[PathSeg]) -> f64 {
    let mut worst = 0.0_f64;
    for seg in a.segments() {
        for k in 0..=16 {
            let p = seg.eval(f64::from(k) / 16.0);
            let d2 = b
                .iter()
                .map(|s| s.nearest(p, 1e-12).distance_sq)
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d2.sqrt());
        }
    }
    worst
}

/// The segments of a path that are not a single point (DejaVu's 'u' has a one-point contour).
fn proper_segments(path: &BezPath) -> BezPath {
    BezPath::from_path_segments(path.segments().filter(|s| {
        let start = s.start();
        s.end() != start || s.arclen(1e-9) > 0.0
    }))
}

/// The two-sided distance between a result and the true outline (one-point contours left out).
pub(super) fn outline_error(result: &BezPath, outline: &BezPath) -> f64 {
    let outline = proper_segments(outline);
    let truth: Vec<PathSeg> = outline.segments().collect();
    let fitted: Vec<PathSeg> = result.segments().collect();
    one_sided(result, &truth).max(one_sided(&outline, &fitted))
}

/// Totals of one method at one tolerance.
#[derive(Default)]
struct Totals {
    points: usize,
    max_error: f64,
    glyphs_over: usize,
    corners: usize,
    corners_sharp: usize,
    extra_sharp: usize,
    /// Largest difference, in degrees, between the turn of the fit at a kept corner that turns by
    /// at least [`BOUNDED_TURN`] (its control polygon's turn there) and the outline's.
    turn_error: f64,
}

/// Corners of the outline that turn by at least this many degrees count for the turn error (the
/// corners whose turn `FitOptions::corner_tolerance` bounds).
const BOUNDED_TURN: f64 = 20.0;

/// The unsigned angle between two directions, in degrees.
fn angle(a: Vec2, b: Vec2) -> f64 {
    a.cross(b).abs().atan2(a.dot(b)).to_degrees()
}

/// The joints of the outline's subpaths (closed ones wrap round) with the turn of the tangent
/// there, in degrees (tangents from the end points and points 10⁻⁷ of the parameter inside).
fn joints(outline: &BezPath) -> Vec<(Point, f64)> {
    let mut out = Vec::new();
    let mut sub: Vec<PathSeg> = Vec::new();
    let mut flush = |sub: &mut Vec<PathSeg>, closed: bool| {
        let m = sub.len();
        for i in 0..m {
            if i + 1 == m && !closed {
                break;
            }
            let (a, b) = (sub[i], sub[(i + 1) % m]);
            let t_in = a.eval(1.0) - a.eval(1.0 - 1e-7);
            let t_out = b.eval(1e-7) - b.eval(0.0);
            out.push((a.eval(1.0), angle(t_in, t_out)));
        }
        sub.clear();
    };
    let mut start = Point::ZERO;
    let mut last = Point::ZERO;
    for el in outline.elements() {
        match *el {
            PathEl::MoveTo(p) => {
                flush(&mut sub, false);
                (start, last) = (p, p);
            }
            PathEl::LineTo(p) => {
                sub.push(PathSeg::Line(kurbo::Line::new(last, p)));
                last = p;
            }
            PathEl::QuadTo(c, p) => {
                sub.push(PathSeg::Quad(kurbo::QuadBez::new(last, c, p)));
                last = p;
            }
            PathEl::CurveTo(c1, c2, p) => {
                sub.push(PathSeg::Cubic(kurbo::CubicBez::new(last, c1, c2, p)));
                last = p;
            }
            PathEl::ClosePath => {
                if last != start {
                    sub.push(PathSeg::Line(kurbo::Line::new(last, start)));
                }
                sub.retain(|s| s.arclen(1e-9) > 0.0);
                flush(&mut sub, true);
                last = start;
            }
        }
    }
    flush(&mut sub, false);
    out
}

/// The turn of the fitted curve at its sharp vertex `j`, in degrees: between its one-sided tangents
/// (the polygon edges at a `VertexKind::Sharp` vertex).
fn curve_turn(curve: &subdiv_fit::SubdivCurve<2>, j: usize) -> f64 {
    let Some((Some(a), Some(b))) = curve.corner_tangents(j) else {
        return 0.0;
    };
    angle(Vec2::new(a.x(), a.y()), Vec2::new(b.x(), b.y()))
}

/// Rounds of the interleaved timing (each fits every glyph once per method).
const ROUNDS: usize = 5;

/// Fits every glyph with subdiv-fit.
fn subdiv_fit_all(glyphs: &[Glyph], opts: &FitOptions) -> Result<(), DynError> {
    for g in glyphs {
        std::hint::black_box(fit_bez_path(&g.outline, opts)?);
    }
    Ok(())
}

/// Simplifies every glyph with kurbo.
fn kurbo_all(glyphs: &[Glyph], tol: f64) {
    for g in glyphs {
        std::hint::black_box(simplify_bezpath(
            g.outline.elements().iter().copied(),
            tol,
            &SimplifyOptions::default(),
        ));
    }
}

/// The subdiv-fit configurations of the table at `tol`: interpolation and least squares, each
/// with the default point removal and with re-spacing first, and the least-squares refit of the
/// spans (`Reduction::Refit`), with either sharp kind, with and without the corner bound.
fn configurations(tol: f64) -> [(&'static str, FitOptions); 8] {
    let interp = FitOptions::new(tol);
    let lsq = interp.with_mode(FitMode::LeastSquares);
    let respace = Reduction::RespaceAndRemove;
    [
        ("subdiv-fit, interpolation", interp),
        ("subdiv-fit, least squares", lsq),
        (
            "subdiv-fit, interpolation, re-spaced",
            interp.with_reduction(respace),
        ),
        (
            "subdiv-fit, least squares, re-spaced",
            lsq.with_reduction(respace),
        ),
        (
            "subdiv-fit, least-squares refit of the spans",
            interp.with_reduction(Reduction::Refit),
        ),
        (
            "subdiv-fit, least-squares refit of the spans, corner bound 0.9° (exact tangents)",
            interp
                .with_reduction(Reduction::Refit)
                .with_corner_tolerance(Some(EXACT_CORNER_TOLERANCE)),
        ),
        (
            "subdiv-fit, least-squares refit of the spans, curved corners",
            interp
                .with_reduction(Reduction::Refit)
                .with_corner_kind(VertexKind::SharpCurved),
        ),
        (
            "subdiv-fit, least-squares refit of the spans, curved corners, corner bound 0.9° (exact tangents)",
            interp
                .with_reduction(Reduction::Refit)
                .with_corner_kind(VertexKind::SharpCurved)
                .with_corner_tolerance(Some(EXACT_CORNER_TOLERANCE)),
        ),
    ]
}

/// Milliseconds per glyph of each configuration and then of kurbo at `tol`, interleaved in one
/// run ([`best_cpu_micros`]: the fastest of [`ROUNDS`] rounds), and whether they are CPU times.
fn times_per_glyph(glyphs: &[Glyph], tol: f64) -> Result<(Vec<f64>, bool), DynError> {
    let configs = configurations(tol);
    let mut runs: Vec<Run<'_>> = configs
        .iter()
        .map(|(_, opts)| -> Run<'_> { Box::new(move || subdiv_fit_all(glyphs, opts)) })
        .collect();
    runs.push(Box::new(|| {
        kurbo_all(glyphs, tol);
        Ok(())
    }));
    // Rounds of at least 20 ms per method: kurbo fits all glyphs in a few ms, about one tick of
    // the thread's CPU clock.
    let (micros, cpu) = best_cpu_micros(&mut runs, ROUNDS, 20_000.0)?;
    let per_glyph = |us: f64| us / 1e3 / glyphs.len() as f64;
    Ok((micros.into_iter().map(per_glyph).collect(), cpu))
}

fn subdiv_fit_totals(glyphs: &[Glyph], tol: f64, opts: &FitOptions) -> Result<Totals, DynError> {
    let mut t = Totals::default();
    for g in glyphs {
        let (path, fits) = fit_bez_path(&g.outline, opts)?;
        // The samples the fit had, for the corners' indices.
        let lines = subdiv_fit::LineSampling::for_fit(opts);
        let corners = subdiv_fit::sample_bez_path_with(&g.outline, tol, lines)?;
        let outline_joints = joints(&g.outline);
        for (f, c) in fits.iter().zip(&corners) {
            for (j, &index) in f.fitting.iter().enumerate() {
                if !f.curve.is_sharp(j) || !c.corners.contains(&index) {
                    continue;
                }
                if f.curve.closure() == subdiv_fit::Closure::Open
                    && (j == 0 || j + 1 == f.fitting.len())
                {
                    continue;
                }
                let v = c.points[index];
                let at = Point::new(v.x(), v.y());
                let joint = outline_joints
                    .iter()
                    .min_by(|x, y| (x.0 - at).hypot2().total_cmp(&(y.0 - at).hypot2()));
                if let Some(&(p, turn)) = joint
                    && (p - at).hypot() < 1e-9
                    && turn >= BOUNDED_TURN
                {
                    t.turn_error = t.turn_error.max((curve_turn(&f.curve, j) - turn).abs());
                }
            }
            t.points += f.curve.points().len();
            let sharp: Vec<usize> = (0..f.fitting.len())
                .filter(|&j| f.curve.is_sharp(j))
                .map(|j| f.fitting[j])
                .collect();
            t.corners += c.corners.len();
            t.corners_sharp += c.corners.iter().filter(|i| sharp.contains(i)).count();
            t.extra_sharp += sharp.iter().filter(|i| !c.corners.contains(i)).count();
        }
        let e = outline_error(&path, &g.outline);
        t.max_error = t.max_error.max(e);
        t.glyphs_over += usize::from(e > tol);
    }
    Ok(t)
}

fn kurbo_totals(glyphs: &[Glyph], tol: f64) -> Totals {
    let mut t = Totals::default();
    for g in glyphs {
        let path = simplify_bezpath(
            g.outline.elements().iter().copied(),
            tol,
            &SimplifyOptions::default(),
        );
        // 3 points per cubic (the shared end point counted once), 2 per quadratic, 1 per line.
        t.points += path
            .segments()
            .map(|s| match s {
                PathSeg::Line(_) => 1,
                PathSeg::Quad(_) => 2,
                PathSeg::Cubic(_) => 3,
            })
            .sum::<usize>();
        let e = outline_error(&path, &g.outline);
        t.max_error = t.max_error.max(e);
        t.glyphs_over += usize::from(e > tol);
    }
    t
}

pub(crate) fn table() -> Result<Table, DynError> {
    let glyphs = glyphs()?;
    let truetype: usize = glyphs.iter().map(|g| g.points).sum();
    let first = glyphs.first().map_or(0, |g| g.code);
    let mut md = format!(
        "## subdiv-fit on the printable ASCII glyphs of DejaVu Sans\n\n\
         {} glyphs (U+{first:04X}..), fitted contour by contour with `fit_bez_path` (samples about every tolerance, the outline's corners given as known corners, two-sided error, default options otherwise).\n\
         TrueType: the points the font's glyph table stores ({truetype}, on- and off-curve, implied points not counted). kurbo: `simplify_bezpath` on the true outline at accuracy = tolerance, counting 3 points per cubic, 2 per quadratic, 1 per line.\n\
         Max error: the two-sided distance to the true outline (without the one-point contour of 'u') (16 samples per segment each way, nearest points on the other side), largest over the glyphs; glyphs over: glyphs whose error exceeds the tolerance.\n\
         Corners: joints of the outline where the tangent turns by more than 1°, and how many are sharp vertices of the fit; extra sharp: sharp vertices the fit added (corners at the feature scale); max corner turn error: the largest difference between the fit's turn at a kept corner that turns by at least {BOUNDED_TURN}° (the turn between the curve's one-sided tangents there: its control polygon's turn at a `VertexKind::Sharp` corner) and the outline's.\n\
         Time per glyph (not checked): {{clock}} per glyph of fitting all glyphs, the methods interleaved in one release-mode run, the fastest of {ROUNDS} rounds (on the machine that ran `cargo xtask tables`); time ratio: to kurbo's at the same tolerance.\n\n\
         | tolerance (em) | method | control points | ratio to TrueType | max error (em) | glyphs over | corners kept sharp | extra sharp | max corner turn error (°) | time per glyph (ms) | time ratio to kurbo |\n\
         |---|---|---|---|---|---|---|---|---|---|---|\n",
        glyphs.len()
    );
    let mut rows = Vec::new();
    let mut clock = "wall-clock time";
    for tol in [1e-3, 1e-2] {
        writeln!(md, "| {tol} | TrueType | {truetype} | 1.00 | | | | | | | |")?;
        let (ms, cpu) = times_per_glyph(&glyphs, tol)?;
        clock = if cpu {
            "CPU time of the fitting thread"
        } else {
            "wall-clock time"
        };
        let kurbo_ms = ms[ms.len() - 1];
        let mut methods: Vec<(&str, Option<FitOptions>)> = configurations(tol)
            .into_iter()
            .map(|(name, opts)| (name, Some(opts)))
            .collect();
        methods.push(("kurbo `simplify_bezpath`", None));
        for ((name, mode), &ms) in methods.into_iter().zip(&ms) {
            let t = match &mode {
                Some(opts) => subdiv_fit_totals(&glyphs, tol, opts)?,
                None => kurbo_totals(&glyphs, tol),
            };
            let corners = if mode.is_some() {
                format!("{} of {}", t.corners_sharp, t.corners)
            } else {
                String::new()
            };
            let (extra, turn) = if mode.is_some() {
                (t.extra_sharp.to_string(), format!("{:.2}", t.turn_error))
            } else {
                (String::new(), String::new())
            };
            writeln!(
                md,
                "| {tol} | {name} | {} | {:.2} | {:.2e} | {} | {corners} | {extra} | {turn} | {ms:.2} | {:.1} |",
                t.points,
                t.points as f64 / truetype as f64,
                t.max_error,
                t.glyphs_over,
                ms / kurbo_ms
            )?;
            rows.push(json!({
                "tolerance": tol, "method": name, "control_points": t.points,
                "max_error": t.max_error, "glyphs_over": t.glyphs_over,
                "corners": t.corners, "corners_sharp": t.corners_sharp, "extra_sharp": t.extra_sharp,
                "turn_error": t.turn_error,
            }));
        }
    }
    let md = md.replacen("{clock}", clock, 1);
    Ok(Table {
        name: "subdiv-fit-glyphs".into(),
        markdown: md,
        checked: json!({ "truetype_points": truetype, "rows": Value::Array(rows) }),
    })
}
