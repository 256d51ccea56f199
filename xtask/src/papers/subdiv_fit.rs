//! subdiv-fit (Wang, Li, Tian 2008): the fitting table at tolerance 0.01, the scaling table, and
//! Figs. 2, 4, 5 on the crate's documented test shapes.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde_json::{Value, json};
use subdiv_fit::cases::{closed_petals, open_wave, rippled_petals};
use subdiv_fit::{
    ErrorMeasure, Fit, FitMode, FitOptions, SubdivCurve, Vector2, discrete_curvature, fit,
};

use crate::DynError;
use crate::plot::{Plot, Series, Style};
use crate::tables::Table;

const TOL: f64 = 0.01;

/// Runs `f` `reps` times (at least once); returns its last result and the median wall time in ms.
pub(super) fn median_ms<T>(
    reps: usize,
    mut f: impl FnMut() -> Result<T, DynError>,
) -> Result<(T, f64), DynError> {
    let mut times = Vec::with_capacity(reps.max(1));
    let mut last = None;
    for _ in 0..reps.max(1) {
        let start = Instant::now();
        last = Some(f()?);
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    let value = last.ok_or("no repetition ran")?;
    Ok((value, times[times.len() / 2]))
}

/// (name, data, closed, the paper's rounds for its own shape of that kind).
fn shapes(density: usize) -> [(&'static str, Vec<Vector2>, bool, usize); 2] {
    [
        ("closed petals", closed_petals(density), true, 4),
        ("open wave", open_wave(density), false, 6),
    ]
}

fn configs() -> [(&'static str, FitOptions); 3] {
    [
        ("paper: one-sided, interpolation", FitOptions::paper(TOL)),
        ("two-sided, interpolation", FitOptions::new(TOL)),
        (
            "two-sided, least squares",
            FitOptions::new(TOL)
                .with_mode(FitMode::LeastSquares)
                .with_measure(ErrorMeasure::TwoSided),
        ),
    ]
}

pub(crate) fn tables() -> Result<Vec<Table>, DynError> {
    Ok(vec![
        fit_table()?,
        scaling_table()?,
        super::subdiv_fit_kurbo::table()?,
        super::subdiv_fit_glyphs::table()?,
        density_table()?,
        super::subdiv_fit_joints::table()?,
    ])
}

fn fit_table() -> Result<Table, DynError> {
    let mut md = String::from(
        "## subdiv-fit: fitting the test shapes at tolerance 0.01\n\n\
         Initial fitting points: in the paper's configuration the curvature maxima and the points whose edges meet at less than 140°; in the others (`Seeding::Scaled`, the default) the corners found at the feature scale (6 × tolerance) and evenly spaced points between them. A round inserts fitting points where the error exceeds the tolerance.\n\
         The paper's shapes are not published: its rounds (Fig. 4: 64 points, 9 maxima, 4 rounds; Fig. 5: 66 points, 8 maxima, 6 rounds) are for its own data, printed for reference only.\n\n\
         | shape | points | initial fitting points (sharp) | configuration | rounds | control points | max data→curve | RMS data→curve | max curve→data | paper's rounds |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut rows = Vec::new();
    for (name, data, closed, paper_rounds) in shapes(1) {
        for (cfg, opts) in configs() {
            let f = fit(&data, subdiv_fit::Closure::from_closed(closed), &opts)?;
            let r = f.last().ok_or("empty report")?;
            let sharp0 = f.initial.len();
            let sharp_count = f.curve.kinds().iter().filter(|k| k.is_sharp()).count();
            writeln!(
                md,
                "| {name} | {} | {sharp0} ({sharp_count}) | {cfg} | {} | {} | {:.5} | {:.5} | {:.5} | {paper_rounds} |",
                data.len(),
                f.rounds(),
                r.control_points,
                r.max_data_to_curve,
                r.rms_data_to_curve,
                r.max_curve_to_data
            )?;
            rows.push(json!({
                "shape": name, "configuration": cfg, "points": data.len(),
                "initial": sharp0, "sharp": sharp_count, "rounds": f.rounds(),
                "control_points": r.control_points,
                "max_data_to_curve": r.max_data_to_curve,
                "rms_data_to_curve": r.rms_data_to_curve,
                "max_curve_to_data": r.max_curve_to_data,
                "per_round": f.reports.iter().map(|x| json!([x.control_points, x.max_data_to_curve, x.max_curve_to_data])).collect::<Vec<Value>>(),
            }));
        }
    }
    Ok(Table {
        name: "subdiv-fit-table1".into(),
        markdown: md,
        checked: Value::Array(rows),
    })
}

/// Density invariance at a fine tolerance: the closed petals with 10k, 300k and 1M samples.
fn density_table() -> Result<Table, DynError> {
    let tol = 1e-3;
    let mut md = String::from(
        "## subdiv-fit: one outline sampled with 10k, 300k and 1M points (tolerance 0.001, default options)\n\n\
         The closed petals (`cases::closed_petals(density)`) at densities 156, 4688 and 15625. The control points must not grow with the sampling (target: within 20 % of each other).\n\
         Times (not checked) are one release-mode fit on the machine that ran `cargo xtask tables`.\n\n\
         | points | control points | sharp | max data→curve | max curve→data | time (s) |\n\
         |---|---|---|---|---|---|\n",
    );
    let mut rows = Vec::new();
    for density in [156, 4688, 15625] {
        let data = closed_petals(density);
        let (f, ms) = median_ms(1, || {
            Ok(fit(
                &data,
                subdiv_fit::Closure::Closed,
                &FitOptions::new(tol),
            )?)
        })?;
        let r = f.last().ok_or("empty report")?;
        let sharp = f.curve.kinds().iter().filter(|k| k.is_sharp()).count();
        writeln!(
            md,
            "| {} | {} | {sharp} | {:.5} | {:.5} | {:.2} |",
            data.len(),
            r.control_points,
            r.max_data_to_curve,
            r.max_curve_to_data,
            ms / 1e3
        )?;
        rows.push(json!({
            "points": data.len(), "control_points": r.control_points, "sharp": sharp,
            "max_data_to_curve": r.max_data_to_curve, "max_curve_to_data": r.max_curve_to_data,
        }));
    }
    Ok(Table {
        name: "subdiv-fit-density".into(),
        markdown: md,
        checked: Value::Array(rows),
    })
}

fn scaling_table() -> Result<Table, DynError> {
    let mut md = String::from(
        "## subdiv-fit: the same shapes sampled 1x, 10x, 100x more densely (tolerance 0.01, two-sided, interpolation)\n\n\
         \"rippled petals\" is `cases::rippled_petals(density, 0.08, 9.0, 0.0)`, many close curvature maxima.\n\
         Times are the median wall-clock of 5 release-mode fits on the machine that ran `cargo xtask tables` (not checked).\n\n\
         | shape | density | points | rounds | control points | max data→curve | max curve→data | time (ms) |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    let mut rows = Vec::new();
    for density in [1, 10, 100] {
        let rippled = (
            "rippled petals",
            rippled_petals(density, 0.08, 9.0, 0.0),
            true,
            0,
        );
        for (name, data, closed, _) in shapes(density).into_iter().chain([rippled]) {
            let opts = FitOptions::new(TOL);
            let (f, ms) = median_ms(5, || {
                Ok(fit(&data, subdiv_fit::Closure::from_closed(closed), &opts)?)
            })?;
            let r = f.last().ok_or("empty report")?;
            writeln!(
                md,
                "| {name} | {density}x | {} | {} | {} | {:.5} | {:.5} | {ms:.2} |",
                data.len(),
                f.rounds(),
                r.control_points,
                r.max_data_to_curve,
                r.max_curve_to_data
            )?;
            rows.push(json!({
                "shape": name, "density": density, "points": data.len(), "rounds": f.rounds(),
                "control_points": r.control_points,
                "max_data_to_curve": r.max_data_to_curve, "max_curve_to_data": r.max_curve_to_data,
            }));
        }
    }
    Ok(Table {
        name: "subdiv-fit-scaling".into(),
        markdown: md,
        checked: Value::Array(rows),
    })
}

fn xy(p: &[Vector2]) -> Vec<(f64, f64)> {
    p.iter().map(|q| (q.x(), q.y())).collect()
}

fn dense(curve: &SubdivCurve<2>) -> Result<Vec<(f64, f64)>, DynError> {
    let segs = curve.segment_count();
    let count = segs * 40;
    let params: Vec<f64> = (0..=count)
        .map(|k| k as f64 * segs as f64 / count as f64)
        .collect();
    let mut out = Vec::new();
    curve.eval_many(&params, &mut out)?;
    Ok(xy(&out))
}

fn polygon(curve: &SubdivCurve<2>) -> Vec<(f64, f64)> {
    let mut p = xy(curve.points());
    if curve.is_closed()
        && let Some(first) = p.first().copied()
    {
        p.push(first);
    }
    p
}

/// The figures' configuration: the paper's initial points (curvature maxima), two-sided error.
fn figure_options() -> FitOptions {
    FitOptions::paper(TOL).with_measure(ErrorMeasure::TwoSided)
}

/// The curve after round 0 (initial fit) of a fit.
fn initial_fit(data: &[Vector2], closed: bool) -> Result<(Fit<2>, SubdivCurve<2>), DynError> {
    let f = fit(
        data,
        subdiv_fit::Closure::from_closed(closed),
        &figure_options(),
    )?;
    // Round 0 alone: the same initial points with a cap of 0 rounds and a huge tolerance.
    let first = fit(
        data,
        subdiv_fit::Closure::from_closed(closed),
        &figure_options().with_tolerance(f64::MAX),
    )?;
    Ok((f, first.curve))
}

/// Plots (a) the initial fit from the curvature maxima and (b) the final fit at tolerance 0.01.
fn fit_plots(title: &str, data: &[Vector2], closed: bool) -> Result<(Plot, Plot), DynError> {
    let (f, initial) = initial_fit(data, closed)?;
    let pts_of = |idx: &[usize]| idx.iter().map(|&i| (data[i].x(), data[i].y())).collect();
    let a = Plot::new(format!("{title} (a) initial fit"), "x", "y")
        .equal()
        .with(Series::new("data", xy(data), Style::Points))
        .with(Series::new(
            "control polygon",
            polygon(&initial),
            Style::LinePoints,
        ))
        .with(Series::new("curve", dense(&initial)?, Style::Line))
        .with(Series::new(
            "fitting points",
            pts_of(&f.initial),
            Style::Points,
        ));
    let b = Plot::new(
        format!(
            "{title} (b) final fit, {} rounds, tolerance 0.01",
            f.rounds()
        ),
        "x",
        "y",
    )
    .equal()
    .with(Series::new("data", xy(data), Style::Points))
    .with(Series::new(
        "control polygon",
        polygon(&f.curve),
        Style::LinePoints,
    ))
    .with(Series::new("curve", dense(&f.curve)?, Style::Line))
    .with(Series::new(
        "fitting points",
        pts_of(&f.fitting),
        Style::Points,
    ));
    Ok((a, b))
}

pub(crate) fn figures(dir: &Path) -> Result<Vec<PathBuf>, DynError> {
    let mut out = Vec::new();
    // Fig. 2: discrete curvature of the closed shape (the data of Fig. 4) and the initial fit.
    let data = closed_petals(1);
    let k = discrete_curvature(&data, true);
    let curv: Vec<(f64, f64)> = k.iter().enumerate().map(|(i, v)| (i as f64, *v)).collect();
    let f = fit(&data, subdiv_fit::Closure::Closed, &figure_options())?;
    let maxima: Vec<(f64, f64)> = f.initial.iter().map(|&i| (i as f64, k[i])).collect();
    out.push(
        Plot::new(
            "Fig. 2 (a): discrete curvature of the closed test shape",
            "data index",
            "K = 1 / circumradius",
        )
        .with(Series::new("curvature", curv, Style::LinePoints))
        .with(Series::new("initial fitting points", maxima, Style::Points))
        .write_svg(&dir.join("fig2a-curvature.svg"))?,
    );
    let (initial, _) = fit_plots("Fig. 2 (b)", &data, true)?;
    out.push(initial.write_svg(&dir.join("fig2b-initial-fit.svg"))?);
    let (a, b) = fit_plots("Fig. 4, closed", &data, true)?;
    out.push(a.write_svg(&dir.join("fig4a-closed-initial.svg"))?);
    out.push(b.write_svg(&dir.join("fig4b-closed-final.svg"))?);
    let (a, b) = fit_plots("Fig. 5, open", &open_wave(1), false)?;
    out.push(a.write_svg(&dir.join("fig5a-open-initial.svg"))?);
    out.push(b.write_svg(&dir.join("fig5b-open-final.svg"))?);
    Ok(out)
}
