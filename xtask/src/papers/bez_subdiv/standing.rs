//! The standing comparison of the flatteners a renderer would pick: bez-subdiv's `Fast` and
//! `Optimal` beside kurbo's `flatten` and lyon_geom's `for_each_flattened`, on the same curves
//! at the same absolute tolerance (1e-3 × size): a seeded random set and an adversarial set of
//! cubics, and the same of quadratics.
//! Counts over N* and measured errors are checked; times are reported, not checked.

use std::fmt::Write as _;
use std::hint::black_box;

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{Flattener, Method, curve_size, optimal_segment_count};
use serde_json::{Value, json};

use crate::DynError;
use crate::tables::Table;
use crate::timing::{Run, best_micros};

/// The tolerance relative to each curve's size.
const EPS: f64 = 1e-3;
/// Random cubics (control points uniform in [0, 1]², ChaCha8, seed [`SEED`]).
const RANDOM: usize = 200;
const SEED: u64 = 2026;
/// Interleaved timing: rounds, and µs of calls per method and round.
const ROUNDS: usize = 15;
const ROUND_MICROS: f64 = 4000.0;

/// The adversarial cubics: cusps, loops, a near-cusp, collinear folds, duplicate and
/// coincident control points, a spike, a near-line.
fn adversarial() -> Vec<BezierCurve<2>> {
    let c = |p: [(f64, f64); 4]| {
        BezierCurve::new(p.iter().map(|&(x, y)| Vector2::new(x, y)).collect()).ok()
    };
    [
        c([(0.0, 0.0), (1.0, 1.0), (0.0, 1.0), (1.0, 0.0)]),
        c([(0.0, 0.0), (2.0, 2.0), (-1.0, 2.0), (1.0, 0.0)]),
        c([(0.0, 0.0), (1.0, 1.0), (1e-7, 1.0), (1.0, 0.0)]),
        c([(0.0, 0.0), (1.0, 1.0), (0.01, 1.0), (1.0, 0.0)]),
        c([(0.0, 0.0), (10.0, 0.0), (-9.0, 0.0), (1.0, 0.0)]),
        c([(0.0, 0.0), (3.0, 3.0), (-1.0, -1.0), (2.0, 2.0)]),
        c([(0.0, 0.0), (0.0, 0.0), (1.0, 1.0), (1.0, 1.0)]),
        c([(0.0, 0.0), (0.0, 0.0), (0.0, 0.0), (1.0, 3.0)]),
        c([(0.0, 0.0), (1.0, 2.0), (1.0, 2.0), (2.0, 0.0)]),
        c([(0.0, 0.0), (100.0, 1.0), (0.0, 2.0), (1.0, 3.0)]),
        c([(0.0, 0.0), (1.0, 1e-6), (2.0, -1e-6), (3.0, 0.0)]),
        c([(0.0, 0.0), (5.0, 5.0), (5.0, -5.0), (0.0, 0.0)]),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The adversarial quadratics: a fold-back (collinear control points, the middle one outside
/// the chord), a near-fold, a duplicated end control point, a closed curve, a spike, a
/// near-line.
fn adversarial_quadratics() -> Vec<BezierCurve<2>> {
    let c = |p: [(f64, f64); 3]| {
        BezierCurve::new(p.iter().map(|&(x, y)| Vector2::new(x, y)).collect()).ok()
    };
    [
        c([(0.0, 0.0), (10.0, 0.0), (1.0, 0.0)]),
        c([(0.0, 0.0), (10.0, 0.01), (1.0, 0.0)]),
        c([(0.0, 0.0), (0.0, 0.0), (1.0, 1.0)]),
        c([(0.0, 0.0), (1.0, 1.0), (0.0, 0.0)]),
        c([(0.0, 0.0), (0.5, 100.0), (1.0, 0.0)]),
        c([(0.0, 0.0), (1.0, 1e-6), (2.0, 0.0)]),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// A flattener: its name and a function writing the polyline of (curve, tolerance) into a
/// buffer (cleared first).
type Flatten = (
    &'static str,
    fn(&BezierCurve<2>, f64, &mut Vec<Vector2>) -> Result<(), DynError>,
);

fn flatteners() -> [Flatten; 4] {
    [
        ("bezkit `Method::Optimal`", |c, tol, out| {
            ours(c, tol, Method::Optimal, out)
        }),
        ("bezkit `Method::Fast`", fast),
        ("kurbo 0.13 `flatten`", kurbo_flatten),
        ("lyon_geom 1 `for_each_flattened`", lyon_flatten),
    ]
}

/// `Method::Fast` with the method fixed at compile time, as a caller of `Flattener::new` writes it
/// (the counterpart of [`lyon_flatten`]).
fn fast(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    out.clear();
    Flattener::new(tol).flatten(c, |p| out.push(p.point))?;
    Ok(())
}

/// A `Flattener` with the method `m` chosen at run time.
fn ours(c: &BezierCurve<2>, tol: f64, m: Method, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    out.clear();
    Flattener::new(tol)
        .with_method(m)
        .flatten(c, |p| out.push(p.point))?;
    Ok(())
}

/// kurbo's `flatten` of a one-curve path (a cubic, or a quadratic as `QuadTo`), given as two
/// path elements (no allocation, as the others).
fn kurbo_flatten(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    use kurbo::{CubicBez, PathEl, QuadBez};
    let path = if c.degree() == 2 {
        let QuadBez { p0, p1, p2 } = QuadBez::try_from(c)?;
        [PathEl::MoveTo(p0), PathEl::QuadTo(p1, p2)]
    } else {
        let CubicBez { p0, p1, p2, p3 } = CubicBez::try_from(c)?;
        [PathEl::MoveTo(p0), PathEl::CurveTo(p1, p2, p3)]
    };
    out.clear();
    kurbo::flatten(path, tol, |el| match el {
        PathEl::MoveTo(q) | PathEl::LineTo(q) => out.push(q.into()),
        _ => {}
    });
    Ok(())
}

/// lyon_geom's `for_each_flattened` of a cubic or a quadratic segment.
fn lyon_flatten(c: &BezierCurve<2>, tol: f64, out: &mut Vec<Vector2>) -> Result<(), DynError> {
    use lyon_geom::{CubicBezierSegment, QuadraticBezierSegment, point};
    let p = c.points();
    let q = |i: usize| point(p[i].x(), p[i].y());
    out.clear();
    out.push(c.start());
    let mut push = |seg: &lyon_geom::LineSegment<f64>| out.push(Vector2::new(seg.to.x, seg.to.y));
    match p.len() {
        3 => QuadraticBezierSegment {
            from: q(0),
            ctrl: q(1),
            to: q(2),
        }
        .for_each_flattened(tol, &mut push),
        4 => CubicBezierSegment {
            from: q(0),
            ctrl1: q(1),
            ctrl2: q(2),
            to: q(3),
        }
        .for_each_flattened(tol, &mut push),
        _ => return Err("lyon_geom's flattening is run on quadratics and cubics only".into()),
    }
    Ok(())
}

/// The value at fraction `q` of the sorted `v` (nearest rank).
fn quantile(v: &[f64], q: f64) -> f64 {
    let i = ((v.len() - 1) as f64 * q).round() as usize;
    v.get(i).copied().unwrap_or(f64::NAN)
}

/// One set's rows: per flattener, segments / N* (median, p90, max, over the curves with
/// N* ≥ 1), worst error / tol, curves over tol, total segments; and the time runs.
fn set_rows(
    set: &str,
    curves: &[BezierCurve<2>],
    md: &mut String,
    rows: &mut Vec<Value>,
) -> Result<(), DynError> {
    let methods = flatteners();
    let tols: Vec<f64> = curves
        .iter()
        .map(|c| EPS * curve_size(c).max(1e-12))
        .collect();
    let n_star: Vec<f64> = curves
        .iter()
        .zip(&tols)
        .map(|(c, &t)| optimal_segment_count(c, t))
        .collect::<Result<_, _>>()?;
    let mut runs: Vec<Run<'_>> = Vec::new();
    for &(_, f) in &methods {
        let mut out = Vec::new();
        let (curves, tols) = (curves, &tols);
        runs.push(Box::new(move || {
            for (c, &t) in curves.iter().zip(tols) {
                f(black_box(c), t, &mut out)?;
                black_box(&out);
            }
            Ok(())
        }));
    }
    let micros = best_micros(&mut runs, ROUNDS, ROUND_MICROS)?;
    drop(runs);
    for ((name, f), micros) in methods.iter().zip(micros) {
        let (mut ratios, mut worst, mut over, mut total) = (Vec::new(), 0.0_f64, 0, 0);
        let mut poly = Vec::new();
        for ((c, &tol), &ns) in curves.iter().zip(&tols).zip(&n_star) {
            f(c, tol, &mut poly)?;
            let segments = poly.len().saturating_sub(1);
            total += segments;
            if ns >= 1.0 {
                ratios.push(segments as f64 / ns);
            }
            let err = super::hausdorff(c, &poly)? / tol;
            worst = worst.max(err);
            over += usize::from(err > 1.0 + 1e-9);
        }
        ratios.sort_by(f64::total_cmp);
        let (median, p90, max) = (
            quantile(&ratios, 0.5),
            quantile(&ratios, 0.9),
            ratios.last().copied().unwrap_or(f64::NAN),
        );
        let per_call = micros / curves.len() as f64;
        writeln!(
            md,
            "| {set} | {name} | {median:.3} | {p90:.3} | {max:.3} | {worst:.3} | {over} | {total} | {per_call:.3} | {:.1} |",
            micros * 1e3 / total.max(1) as f64
        )?;
        rows.push(json!({
            "set": set, "method": name, "median": median, "p90": p90, "max": max,
            "worst_error_over_tol": worst, "curves_over_tol": over, "segments": total,
        }));
    }
    Ok(())
}

/// The standing comparison table.
pub(crate) fn standing_table() -> Result<Table, DynError> {
    let random = bez_subdiv::cases::random_curves(3, RANDOM, SEED);
    let adversarial = adversarial();
    let random_quadratics = bez_subdiv::cases::random_curves(2, RANDOM, SEED);
    let adversarial_quadratics = adversarial_quadratics();
    let mut md = format!(
        "### bez-subdiv's flatteners beside kurbo and lyon_geom (tol = {EPS} × size)\n\n\
         Sets: {RANDOM} random cubics (control points uniform in [0, 1]², ChaCha8, seed {SEED}), {} adversarial cubics \
         (cusps, a loop, near-cusps, collinear folds, duplicate and coincident control points, a spike, a near-line, a closed curve), \
         {RANDOM} random quadratics (the same generator and seed) and {} adversarial quadratics (a collinear fold-back, a near-fold, a duplicated control point, a closed curve, a spike, a near-line); \
         kurbo flattens the quadratics as `QuadTo`, lyon_geom with `QuadraticBezierSegment::for_each_flattened`. \
         Segments / N*: over the curves with N* ≥ 1 (N* = ∫ √(|κ| / (8 tol)) ds, `optimal_segment_count`). \
         Error: measured Hausdorff distance (20,001 curve samples to the polyline, exact nearest curve points from 5 points per segment) over tol; \
         \"over tol\": curves whose error exceeds tol. Time: in-process, interleaved ({ROUNDS} rounds of about {ROUND_MICROS} µs of calls per method over the whole set), \
         each method's fastest round, on the machine that wrote this file, output into one reused `Vec`; not checked.\n\n\
         | set | method | segments / N*, median | p90 | max | worst error / tol | over tol | segments | time per call (µs) | time per point (ns) |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
        adversarial.len(),
        adversarial_quadratics.len()
    );
    let mut rows = Vec::new();
    set_rows("random", &random, &mut md, &mut rows)?;
    set_rows("adversarial", &adversarial, &mut md, &mut rows)?;
    set_rows("random quadratics", &random_quadratics, &mut md, &mut rows)?;
    set_rows(
        "adversarial quadratics",
        &adversarial_quadratics,
        &mut md,
        &mut rows,
    )?;
    Ok(Table {
        name: "bez-subdiv-standing".into(),
        markdown: md,
        checked: Value::Array(rows),
    })
}
