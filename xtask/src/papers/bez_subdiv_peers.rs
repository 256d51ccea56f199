//! bez-subdiv's cubic flattening beside kurbo's `flatten` and lyon_geom's `for_each_flattened`:
//! the same cubics at the same absolute tolerance, segments and measured error (checked) and an
//! in-process time (reported, not checked; the criterion bench `cubic_flatten_peers` is the
//! reference for speed).

use std::fmt::Write as _;
use std::hint::black_box;

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::cases::peer_cubics;
use serde_json::{Value, json};

use crate::DynError;
use crate::tables::Table;
use crate::timing::{Run, best_micros};

/// ε of eq. (3); the absolute tolerance of every method is ε × the curve's size.
const EPS: f64 = 1e-5;

/// The Table 1 and N* tables followed by the peer and per-point tables.
pub(crate) fn tables() -> Result<Vec<Table>, DynError> {
    let mut tables = super::bez_subdiv::tables()?;
    tables.push(table()?);
    tables.push(super::bez_subdiv_per_point::table()?);
    Ok(tables)
}

/// A flattening method: its name and a function writing the polyline of (curve, absolute
/// tolerance) into a buffer (cleared first, its capacity reused).
type Method = (
    &'static str,
    fn(&BezierCurve<2>, f64, &mut Vec<Vector2>) -> Result<(), DynError>,
);

/// Index of kurbo's `flatten` in [`methods`], the reference of the ratio column.
const KURBO: usize = 3;
/// Index of the method run at the loosest ε whose measured error is within tol.
const LOOSEST: usize = 5;
/// The ε grid of that method: ε × 2^(k / 8), k = 0..=24 (1 to 8 times ε).
const LOOSEST_STEPS: std::ops::RangeInclusive<i32> = 0..=24;

/// The near-optimal mode is left out: the N* table measures it, and its cost is of another order.
fn methods() -> [Method; 6] {
    [
        (
            "bezkit fixed rule, eq. (3) control polygons",
            fixed_polygons,
        ),
        ("bezkit fixed rule, eq. (3) piece chords", fixed_chords),
        ("bezkit guaranteed", guaranteed),
        ("kurbo 0.13 `flatten`", kurbo_flatten),
        ("lyon_geom 1 `for_each_flattened`", lyon_flatten),
        (
            "bezkit fixed rule, eq. (3) control polygons, loosest ε with error ≤ tol",
            fixed_polygons,
        ),
    ]
}

/// The tolerance each method is given on `c`: tol, except for [`LOOSEST`], which gets the
/// largest tol × 2^(k/8) on its grid whose control polygons are measured within tol of the curve
/// (the eq. (3) pieces stay far inside their tolerance; this is the same accuracy as the others).
fn tolerances(c: &BezierCurve<2>, methods: &[Method]) -> Result<Vec<f64>, DynError> {
    let tol = EPS * bez_subdiv::curve_size(c);
    let mut loosest = tol;
    let mut poly = Vec::new();
    for k in LOOSEST_STEPS {
        let candidate = tol * 2f64.powf(f64::from(k) / 8.0);
        fixed_polygons(c, candidate, &mut poly)?;
        if super::bez_subdiv::hausdorff(c, &poly)? <= tol {
            loosest = candidate;
        }
    }
    Ok((0..methods.len())
        .map(|k| if k == LOOSEST { loosest } else { tol })
        .collect())
}

/// `flatten_fixed_into`'s output: the control polygons of the final pieces.
fn fixed_polygons(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    bez_subdiv::flatten_fixed_into(c, tol / bez_subdiv::curve_size(c), 40, out)?;
    Ok(())
}

/// The end points of the same pieces: every n-th point of the control polygons, compacted in
/// place after `flatten_fixed_into` (its time includes that pass).
fn fixed_chords(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    fixed_polygons(c, tol, out)?;
    let step = c.points().len() - 1;
    let kept = out.len().div_ceil(step);
    for k in 1..kept {
        out[k] = out[k * step];
    }
    out.truncate(kept);
    Ok(())
}

fn guaranteed(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    out.clear();
    bez_subdiv::Flattener::new(tol)
        .with_method(bez_subdiv::Method::Halving)
        .flatten(c, |p| out.push(p.point))?;
    Ok(())
}

fn kurbo_flatten(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    use kurbo::{CubicBez, PathEl};
    // kurbo's flatten is run on cubics only: another degree is an error. The path is two
    // elements, no allocation.
    let CubicBez { p0, p1, p2, p3 } = CubicBez::try_from(c)?;
    let path = [PathEl::MoveTo(p0), PathEl::CurveTo(p1, p2, p3)];
    out.clear();
    kurbo::flatten(path, tol, |el| match el {
        PathEl::MoveTo(q) | PathEl::LineTo(q) => out.push(q.into()),
        _ => {}
    });
    Ok(())
}

fn lyon_flatten(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    use lyon_geom::{CubicBezierSegment, point};
    let p: Vec<_> = c.points().iter().map(|q| point(q.x(), q.y())).collect();
    let [from, ctrl1, ctrl2, to] = p[..] else {
        return Err("lyon_geom's cubic flattening is run on cubics only".into());
    };
    let cubic = CubicBezierSegment {
        from,
        ctrl1,
        ctrl2,
        to,
    };
    out.clear();
    out.push(c.start());
    cubic.for_each_flattened(tol, &mut |seg| out.push(Vector2::new(seg.to.x, seg.to.y)));
    Ok(())
}

/// Rounds of the interleaved timing, and the wall time of each (cubic, method) in a round (µs).
const ROUNDS: usize = 60;
const ROUND_MICROS: f64 = 300.0;

/// Time of one call in µs for each method on each cubic ([`best_micros`], every pair in every
/// round, so that each pair's rounds spread over the whole measurement), row-major by cubic;
/// output written into one buffer per pair, reused across calls.
fn method_micros(
    cubics: &[(String, BezierCurve<2>)],
    methods: &[Method],
    tolerances: &[Vec<f64>],
) -> Result<Vec<f64>, DynError> {
    let mut runs: Vec<Run<'_>> = Vec::new();
    for ((_, c), tols) in cubics.iter().zip(tolerances) {
        for (&(_, flatten), &tol) in methods.iter().zip(tols) {
            let mut out = Vec::new();
            runs.push(Box::new(move || {
                flatten(black_box(c), tol, &mut out)?;
                black_box(&out);
                Ok(())
            }));
        }
    }
    best_micros(&mut runs, ROUNDS, ROUND_MICROS)
}

/// The peer table: segments, measured error / tol and time per method and cubic.
pub(crate) fn table() -> Result<Table, DynError> {
    let mut md = format!(
        "### bez-subdiv beside kurbo and lyon_geom: cubics at the same absolute tolerance (tol = {EPS} × size)\n\n\
         Error: measured Hausdorff distance between polyline and curve (20,001 curve samples to the polyline, exact nearest curve points from 5 points per segment) divided by tol.\n\
         Time: in-process, interleaved: {ROUNDS} rounds, each of which calls every method on every cubic in turn for about {ROUND_MICROS} µs; a method's time is its fastest round, on the machine that wrote this file, output written into one reused `Vec`; not checked. Ratio: time / kurbo's time on the same curve. The last row of each cubic runs the fixed rule at the loosest ε × 2^(k/8), k = 0..24, whose control polygons are measured within tol (the same accuracy as the other rows; eq. (3)'s pieces at ε stay far inside it).\n\n\
         | curve | method | segments | error / tol | time (µs) | time per segment (ns) | ratio to kurbo |\n\
         |---|---|---|---|---|---|---|\n"
    );
    let mut rows = Vec::new();
    let cubics = peer_cubics();
    let methods = methods();
    let tolerances = cubics
        .iter()
        .map(|(_, c)| tolerances(c, &methods))
        .collect::<Result<Vec<_>, _>>()?;
    let times = method_micros(&cubics, &methods, &tolerances)?;
    for (((name, c), micros), tols) in cubics
        .iter()
        .zip(times.chunks(methods.len()))
        .zip(&tolerances)
    {
        let tol = EPS * bez_subdiv::curve_size(c);
        let kurbo = micros[KURBO];
        for ((method, &micros), &given) in methods.iter().zip(micros).zip(tols) {
            let mut poly = Vec::new();
            (method.1)(c, given, &mut poly)?;
            let segments = poly.len().saturating_sub(1);
            let err = super::bez_subdiv::hausdorff(c, &poly)? / tol;
            let scale = given / tol;
            let label = if scale == 1.0 {
                method.0.to_owned()
            } else {
                format!("{} (ε × {scale:.3})", method.0)
            };
            writeln!(
                md,
                "| {name} | {label} | {segments} | {err:.3} | {micros:.2} | {:.1} | {:.2} |",
                micros * 1e3 / segments.max(1) as f64,
                micros / kurbo
            )?;
            rows.push(json!({
                "curve": name, "method": method.0, "segments": segments, "error_over_tol": err,
                "tolerance_scale": scale,
            }));
        }
    }
    Ok(Table {
        name: "bez-subdiv-peers".into(),
        markdown: md,
        checked: Value::Array(rows),
    })
}
