//! bez-subdiv: Table 1 of Ma, Lin & Shen (2016) on seeded random curves.

use std::fmt::Write as _;
use std::time::Instant;

use bez_core::BezierCurve;
use bez_subdiv::cases::{CURVES_PER_DEGREE, TABLE1_SEED, table1_curves};
use bez_subdiv::{FlattenOptions, FlattenStats, Levels, Objective, Search, SplitRule, flatten};
use serde_json::json;

use crate::DynError;
use crate::tables::Table;

mod nstar;
mod standing;
pub(super) use nstar::hausdorff;

/// The paper's Table 1, as printed: degree, then (time s, iterations) for the fixed, flatness
/// and hull methods, then the printed improvement rates (%) of the flatness and hull methods.
const PAPER: [(usize, [f64; 6], [f64; 2]); 10] = [
    (12, [0.38, 10.0, 0.39, 10.0, 0.42, 10.0], [-1.1, -9.2]),
    (13, [1.26, 11.0, 0.43, 10.0, 1.27, 11.0], [65.5, -0.9]),
    (16, [1.78, 11.0, 0.59, 10.0, 1.82, 11.0], [66.9, -2.6]),
    (17, [1.94, 11.0, 1.84, 11.0, 1.99, 11.0], [5.1, -2.2]),
    (18, [2.27, 11.0, 2.18, 11.0, 9.09, 12.0], [2.6, -306.5]),
    (19, [2.40, 11.0, 0.77, 10.0, 10.1, 12.0], [68.0, -318.5]),
    (20, [2.62, 11.0, 2.66, 11.0, 11.4, 12.0], [-1.5, -335.6]),
    (22, [3.38, 11.0, 0.87, 10.0, 13.8, 12.0], [74.3, -308.7]),
    (24, [3.89, 11.0, 3.79, 11.0, 16.0, 12.0], [2.5, -312.5]),
    (25, [4.00, 11.0, 3.88, 11.0, 16.7, 12.0], [2.9, -318.3]),
];

/// Repetitions for the median time of one flattening.
const REPS: usize = 5;

/// The rules of Table 1: the paper's three, the exact optimum and the adaptive N.
pub(super) fn rules() -> [SplitRule; 5] {
    [
        SplitRule::Fixed,
        SplitRule::flatness(),
        SplitRule::hull_area(),
        SplitRule::Optimal {
            objective: Objective::Flatness,
            search: Search::Exact,
            levels: Levels::First(3),
        },
        SplitRule::Optimal {
            objective: Objective::Flatness,
            search: Search::Grid,
            levels: Levels::Adaptive,
        },
    ]
}

/// Flattens with the paper's ε and returns the counts and the median wall time in ms.
fn run(curve: &BezierCurve<2>, rule: SplitRule) -> Result<(FlattenStats, f64), DynError> {
    let options = FlattenOptions::default().with_rule(rule);
    let mut times = Vec::with_capacity(REPS);
    let mut stats = FlattenStats::default();
    for _ in 0..REPS {
        let start = Instant::now();
        stats = flatten(curve, &options)?.stats;
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    Ok((stats, times[REPS / 2]))
}

fn pct(base: f64, x: f64) -> f64 {
    if base == 0.0 {
        0.0
    } else {
        100.0 * (base - x) / base
    }
}

/// Table 1 (per degree: the first curve alone, and the sum over all curves of that degree).
pub(crate) fn tables() -> Result<Vec<Table>, DynError> {
    let rules = rules();
    let mut md = String::new();
    let _ = writeln!(
        md,
        "### bez-subdiv, Table 1: fixed t = 0.5 vs flatness- and hull-optimal splits (ε = 1e-5, N = 3)\n\n\
         Curves: control points uniform in [0, 1]², ChaCha8 seeded {TABLE1_SEED} + degree, {CURVES_PER_DEGREE} curves per degree (the paper's curves are not given).\n\
         *depth* is Table 1's iteration count (deepest level reached), *splits* the number of subdivisions (= pieces − 1), *evals* the objective evaluations of the parameter search.\n\
         Single-curve rows use the first curve of each degree; the aggregate rows sum splits and evaluations over all {CURVES_PER_DEGREE} curves.\n\
         Improvement = (fixed − method) / fixed, by splits + evals (work, deterministic) and by median time (5 runs, this machine; not checked in CI).\n"
    );
    let _ = writeln!(
        md,
        "| degree | fixed depth / splits | flatness depth / splits / evals | hull depth / splits / evals | flatness improvement (work, time) | hull improvement (work, time) | paper: depth fixed / flat / hull | paper: improvement flat / hull |\n|---|---|---|---|---|---|---|---|"
    );
    let mut rows_json = Vec::new();
    let mut agg_md = String::from(
        "\n| degree | rule | depth (max) | splits (sum) | evals (sum) | work vs fixed | time vs fixed |\n|---|---|---|---|---|---|---|\n",
    );
    let mut totals = vec![(0usize, 0usize, 0.0f64); rules.len()];
    for ((degree, curves), paper) in table1_curves().into_iter().zip(PAPER) {
        debug_assert_eq!(degree, paper.0);
        let mut per_rule: Vec<(FlattenStats, f64)> = Vec::new();
        for rule in rules {
            per_rule.push(run(&curves[0], rule)?);
        }
        let (fx, ft) = per_rule[0];
        let work = |s: &FlattenStats| (s.splits + s.evaluations) as f64;
        let (fl, flt) = per_rule[1];
        let (hu, hut) = per_rule[2];
        let _ = writeln!(
            md,
            "| {degree} | {} / {} | {} / {} / {} | {} / {} / {} | {:.1} %, {:.1} % | {:.1} %, {:.1} % | {} / {} / {} | {:.1} / {:.1} |",
            fx.depth,
            fx.splits,
            fl.depth,
            fl.splits,
            fl.evaluations,
            hu.depth,
            hu.splits,
            hu.evaluations,
            pct(work(&fx), work(&fl)),
            pct(ft, flt),
            pct(work(&fx), work(&hu)),
            pct(ft, hut),
            paper.1[1],
            paper.1[3],
            paper.1[5],
            paper.2[0],
            paper.2[1],
        );
        // Aggregates over all curves of the degree, every rule.
        let mut agg = Vec::new();
        for (k, rule) in rules.iter().enumerate() {
            let (mut depth, mut splits, mut evals, mut time) = (0, 0, 0, 0.0);
            for c in &curves {
                let (s, t) = run(c, *rule)?;
                depth = depth.max(s.depth);
                splits += s.splits;
                evals += s.evaluations;
                time += t;
            }
            totals[k].0 += splits;
            totals[k].1 += evals;
            totals[k].2 += time;
            agg.push((rule.name(), depth, splits, evals, time));
        }
        let (base_work, base_time) = ((agg[0].2 + agg[0].3) as f64, agg[0].4);
        for (name, depth, splits, evals, time) in &agg {
            let _ = writeln!(
                agg_md,
                "| {degree} | {name} | {depth} | {splits} | {evals} | {:.1} % | {:.1} % |",
                pct(base_work, (splits + evals) as f64),
                pct(base_time, *time)
            );
        }
        rows_json.push(json!({
            "degree": degree,
            "first_curve": per_rule.iter().zip(rules.iter()).map(|((s, _), r)| json!({
                "rule": r.name(), "depth": s.depth, "splits": s.splits, "pieces": s.pieces, "evaluations": s.evaluations
            })).collect::<Vec<_>>(),
            "all_curves": agg.iter().map(|(name, depth, splits, evals, _)| json!({
                "rule": name, "max_depth": depth, "splits": splits, "evaluations": evals
            })).collect::<Vec<_>>(),
        }));
    }
    let _ = writeln!(md, "{agg_md}");
    let _ = writeln!(
        md,
        "Totals over all {} curves:\n\n| rule | splits | evals | work vs fixed | time (ms) |\n|---|---|---|---|---|",
        10 * CURVES_PER_DEGREE
    );
    let base = (totals[0].0 + totals[0].1) as f64;
    for (rule, (splits, evals, time)) in rules.iter().zip(&totals) {
        let _ = writeln!(
            md,
            "| {} | {splits} | {evals} | {:.1} % | {time:.2} |",
            rule.name(),
            pct(base, (splits + evals) as f64)
        );
    }
    Ok(vec![
        Table {
            name: "bez-subdiv-table1".into(),
            markdown: md,
            checked: json!({ "rows": rows_json }),
        },
        nstar::nstar_table()?,
        standing::standing_table()?,
    ])
}
