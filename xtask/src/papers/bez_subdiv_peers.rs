//! bez-subdiv's cubic flattening beside kurbo's `flatten` and lyon_geom's `for_each_flattened`:
//! the same cubics at the same absolute tolerance, segments and measured error (checked) and an
//! in-process time (reported, not checked; the criterion bench `cubic_flatten_peers` is the
//! reference for speed).

use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::cases::peer_cubics;
use serde_json::{Value, json};

use crate::DynError;
use crate::tables::Table;

/// ε of eq. (3); the absolute tolerance of every method is ε × the curve's size.
const EPS: f64 = 1e-5;

/// The Table 1 and N* tables followed by the peer table.
pub(crate) fn tables() -> Result<Vec<Table>, DynError> {
    let mut tables = super::bez_subdiv::tables()?;
    tables.push(table()?);
    Ok(tables)
}

/// A flattening method: its name and a function from (curve, absolute tolerance) to polyline.
type Method = (
    &'static str,
    fn(&BezierCurve<2>, f64) -> Result<Vec<Vector2<f64>>, DynError>,
);

/// The near-optimal mode is left out: the N* table measures it, and its cost is of another order.
fn methods() -> [Method; 5] {
    [
        (
            "bezkit fixed rule, eq. (3) control polygons",
            fixed_polygons,
        ),
        ("bezkit fixed rule, eq. (3) piece chords", fixed_chords),
        ("bezkit guaranteed", guaranteed),
        ("kurbo 0.11 `flatten`", kurbo_flatten),
        ("lyon_geom 1 `for_each_flattened`", lyon_flatten),
    ]
}

/// `flatten_fixed_into`'s output: the control polygons of the final pieces.
fn fixed_polygons(c: &BezierCurve<2>, tol: f64) -> Result<Vec<Vector2<f64>>, DynError> {
    let mut poly = Vec::new();
    bez_subdiv::flatten_fixed_into(c, tol / bez_subdiv::curve_size(c), 40, &mut poly)?;
    Ok(poly)
}

/// The end points of the same pieces (every n-th point of the control polygons).
fn fixed_chords(c: &BezierCurve<2>, tol: f64) -> Result<Vec<Vector2<f64>>, DynError> {
    let step = c.points().len() - 1;
    Ok(fixed_polygons(c, tol)?.into_iter().step_by(step).collect())
}

fn guaranteed(c: &BezierCurve<2>, tol: f64) -> Result<Vec<Vector2<f64>>, DynError> {
    let pts = bez_subdiv::flatten_guaranteed(c, tol, 40)?;
    Ok(pts.into_iter().map(|p| p.point).collect())
}

fn kurbo_flatten(c: &BezierCurve<2>, tol: f64) -> Result<Vec<Vector2<f64>>, DynError> {
    use kurbo::{BezPath, PathEl, Point};
    let p: Vec<Point> = c.points().iter().map(|q| Point::new(q.x, q.y)).collect();
    let [p0, p1, p2, p3] = p[..] else {
        return Err("kurbo's flatten is run on cubics only".into());
    };
    let path = BezPath::from_vec(vec![PathEl::MoveTo(p0), PathEl::CurveTo(p1, p2, p3)]);
    let mut out = Vec::new();
    kurbo::flatten(&path, tol, |el| match el {
        PathEl::MoveTo(q) | PathEl::LineTo(q) => out.push(Vector2::new(q.x, q.y)),
        _ => {}
    });
    Ok(out)
}

fn lyon_flatten(c: &BezierCurve<2>, tol: f64) -> Result<Vec<Vector2<f64>>, DynError> {
    use lyon_geom::{CubicBezierSegment, point};
    let p: Vec<_> = c.points().iter().map(|q| point(q.x, q.y)).collect();
    let [from, ctrl1, ctrl2, to] = p[..] else {
        return Err("lyon_geom's cubic flattening is run on cubics only".into());
    };
    let cubic = CubicBezierSegment {
        from,
        ctrl1,
        ctrl2,
        to,
    };
    let mut out = vec![c.start()];
    cubic.for_each_flattened(tol, &mut |seg| out.push(Vector2::new(seg.to.x, seg.to.y)));
    Ok(out)
}

/// Median time of one call in µs (7 batches of 200 calls).
fn median_micros(c: &BezierCurve<2>, tol: f64, method: Method) -> Result<f64, DynError> {
    let mut times = Vec::new();
    for _ in 0..7 {
        let start = Instant::now();
        for _ in 0..200 {
            black_box((method.1)(black_box(c), tol)?);
        }
        times.push(start.elapsed().as_secs_f64() * 1e6 / 200.0);
    }
    times.sort_by(f64::total_cmp);
    Ok(times[times.len() / 2])
}

/// The peer table: segments, measured error / tol and time per method and cubic.
pub(crate) fn table() -> Result<Table, DynError> {
    let mut md = format!(
        "### bez-subdiv beside kurbo and lyon_geom: cubics at the same absolute tolerance (tol = {EPS} × size)\n\n\
         Error: measured Hausdorff distance between polyline and curve (20,001 curve samples to the polyline, exact nearest curve points from 5 points per segment) divided by tol.\n\
         Time: in-process median of 7 × 200 calls on the machine that wrote this file, output collected into a `Vec`; not checked (the criterion bench `cubic_flatten_peers` is the speed reference).\n\n\
         | curve | method | segments | error / tol | time (µs) | time per segment (ns) |\n\
         |---|---|---|---|---|---|\n"
    );
    let mut rows = Vec::new();
    for (name, c) in peer_cubics() {
        let tol = EPS * bez_subdiv::curve_size(&c);
        for method in methods() {
            let poly = (method.1)(&c, tol)?;
            let segments = poly.len().saturating_sub(1);
            let err = super::bez_subdiv::hausdorff(&c, &poly)? / tol;
            let micros = median_micros(&c, tol, method)?;
            writeln!(
                md,
                "| {name} | {} | {segments} | {err:.3} | {micros:.2} | {:.1} |",
                method.0,
                micros * 1e3 / segments.max(1) as f64
            )?;
            rows.push(json!({
                "curve": name, "method": method.0, "segments": segments, "error_over_tol": err,
            }));
        }
    }
    Ok(Table {
        name: "bez-subdiv-peers".into(),
        markdown: md,
        checked: Value::Array(rows),
    })
}
