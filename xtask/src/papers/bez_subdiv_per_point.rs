//! bez-subdiv's speed target at degree 25: time per output point of each flattening mode on
//! one seeded degree-25 curve (output point counts checked, times reported).

use std::fmt::Write as _;
use std::hint::black_box;

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::cases::degree25_curve;
use bez_subdiv::{FlattenOptions, Flattener, Method};
use serde_json::{Value, json};

use super::bez_subdiv::rules;
use crate::DynError;
use crate::tables::Table;
use crate::timing::{Run, best_micros};

/// ε of the fixed rule; the absolute tolerance of the other modes is ε × the curve's size.
const EPS: f64 = 1e-5;
/// The speed target, µs per output point.
const TARGET_MICROS: f64 = 0.3;
/// `Method::Optimal`'s own target, µs per output point.
const OPTIMAL_TARGET_MICROS: f64 = 0.1;
/// The coarser tolerance of the second `Method::Optimal` row, as a multiple of ε.
const COARSE: f64 = 100.0;
/// Rounds of the interleaved timing, and the wall time of each mode in a round (µs).
const ROUNDS: usize = 20;
const ROUND_MICROS: f64 = 2000.0;

/// A mode: its name and a function from (curve, absolute tolerance) to its output points.
type Mode = (
    String,
    Box<dyn Fn(&BezierCurve<2>, f64, &mut Vec<Vector2>) -> Result<(), DynError>>,
);

/// The allocation-free fixed rule, Table 1's rules through the general `flatten`, and the modes
/// with a Hausdorff guarantee.
fn modes() -> Vec<Mode> {
    let mut modes: Vec<Mode> = vec![(
        "fixed rule, `flatten_fixed_into` (control polygons)".into(),
        Box::new(fixed),
    )];
    for rule in rules() {
        modes.push((
            format!("{}, `flatten` (control polygons)", rule.name()),
            Box::new(move |c, tol, out| {
                let options = FlattenOptions::default()
                    .with_rule(rule)
                    .with_tolerance(tol / bez_subdiv::curve_size(c));
                *out = bez_subdiv::flatten(c, &options)?.polyline;
                Ok(())
            }),
        ));
    }
    modes.push((
        "guaranteed (halving), `Method::Halving`".into(),
        Box::new(|c, tol, out| points(c, tol, Method::Halving, out)),
    ));
    modes.push((
        "guaranteed (local Wang), `Method::LocalWang`".into(),
        Box::new(|c, tol, out| points(c, tol, Method::LocalWang, out)),
    ));
    modes.push((
        "near-optimal, `Method::Optimal`".into(),
        Box::new(|c, tol, out| points(c, tol, Method::Optimal, out)),
    ));
    modes.push((
        format!(
            "near-optimal at tol = {} × size, `Method::Optimal`",
            COARSE * EPS
        ),
        Box::new(|c, tol, out| points(c, COARSE * tol, Method::Optimal, out)),
    ));
    modes
}

fn fixed(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    bez_subdiv::flatten_fixed_into(c, tol / bez_subdiv::curve_size(c), 40, out)?;
    Ok(())
}

/// The points of `method`, streamed into `out` (cleared first, its capacity reused).
fn points(
    c: &BezierCurve<2>,
    tol: f64,
    method: Method,
    out: &mut Vec<Vector2>,
) -> Result<(), DynError> {
    out.clear();
    Flattener::new(tol)
        .with_method(method)
        .flatten(c, |p| out.push(p.point))?;
    Ok(())
}

/// The per-point table.
pub(crate) fn table() -> Result<Table, DynError> {
    let c = degree25_curve().ok_or("the degree-25 curve could not be built")?;
    let tol = EPS * bez_subdiv::curve_size(&c);
    let modes = modes();
    let mut runs: Vec<Run<'_>> = modes
        .iter()
        .map(|(_, flatten)| {
            let mut out = Vec::new();
            let c = &c;
            Box::new(move || {
                flatten(black_box(c), tol, &mut out)?;
                black_box(&out);
                Ok(())
            }) as Run<'_>
        })
        .collect();
    let micros = best_micros(&mut runs, ROUNDS, ROUND_MICROS)?;
    let mut md = format!(
        "### bez-subdiv at degree 25: time per output point (tol = {EPS} × size)\n\n\
         The degree-25 curve of `cases::degree25_curve` (the N* table's). Output points: the \
         polyline's points (for the eq. (3) rules the pieces' control polygons, 25 segments per \
         piece; Table 1's rules through the general `flatten`, which allocates per piece). Time: in-process, interleaved: {ROUNDS} rounds of about {ROUND_MICROS} µs of \
         calls of every mode in turn, each mode's fastest round, on the machine that wrote this \
         file; not checked. Target: under {TARGET_MICROS} µs per output point, for \
         `Method::Optimal` under {OPTIMAL_TARGET_MICROS} µs.\n\n\
         | mode | output points | time (µs) | per point (µs) | under {TARGET_MICROS} µs |\n\
         |---|---|---|---|---|\n"
    );
    let mut rows = Vec::new();
    for (mode, micros) in modes.iter().zip(micros) {
        let mut out = Vec::new();
        (mode.1)(&c, tol, &mut out)?;
        let per_point = micros / out.len().max(1) as f64;
        let met = if per_point < TARGET_MICROS {
            "yes"
        } else {
            "no"
        };
        writeln!(
            md,
            "| {} | {} | {micros:.1} | {per_point:.3} | {met} |",
            mode.0,
            out.len()
        )?;
        rows.push(json!({ "mode": mode.0, "points": out.len() }));
    }
    Ok(Table {
        name: "bez-subdiv-per-point".into(),
        markdown: md,
        checked: Value::Array(rows),
    })
}
