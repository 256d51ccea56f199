//! class-a (Zhang & Yang 2014): Figs. 5–9 and the solver comparison table.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use bez_core::BezierCurve;
use class_a::{
    ClassAReport, TypicalPlanar, TypicalSpatial, cases, curvature_certificate, curvature_samples,
    log_graph, log_graph_from_points, planar_nelder_mead, torsion_certificate, torsion_samples,
};
use serde_json::json;

use crate::DynError;
use crate::plot::{Plot, Series, Style};
use crate::tables::Table;

/// Random inputs per solver comparison.
const INPUTS: usize = 10_000;
/// Nelder–Mead iteration budget.
const NM_ITERS: u64 = 2_000;

/// The solver comparison and the figure cases' checks.
pub(crate) fn tables() -> Result<Vec<Table>, DynError> {
    Ok(vec![
        solver_table()?,
        figures_table()?,
        counterexample_table()?,
    ])
}

fn solver_table() -> Result<Table, DynError> {
    let tols = [1e-6, 1e-9];
    let planar = cases::random_planar_inputs(INPUTS, 2014);
    let (mut ours_p, mut nm_p) = ([0usize; 2], [0usize; 2]);
    let (mut t_ours_p, mut t_nm_p) = (0.0, 0.0);
    for (a, n) in &planar {
        let t0 = Instant::now();
        let e = TypicalPlanar::from_points(&a[0], &a[1], &a[2], *n)
            .and_then(|c| c.curve())
            .map_or(f64::INFINITY, |c| cases::endpoint_error(a, &c));
        t_ours_p += t0.elapsed().as_secs_f64();
        let t0 = Instant::now();
        let f = planar_nelder_mead(&a[0], &a[1], &a[2], *n, NM_ITERS)
            .and_then(|(c, _)| c.curve())
            .map_or(f64::INFINITY, |c| cases::endpoint_error(a, &c));
        t_nm_p += t0.elapsed().as_secs_f64();
        for (k, tol) in tols.iter().enumerate() {
            ours_p[k] += usize::from(e <= *tol);
            nm_p[k] += usize::from(f <= *tol);
        }
    }
    let spatial = cases::random_spatial_inputs(INPUTS, 2014);
    let (mut ours_s, mut nm_s) = ([0usize; 2], [0usize; 2]);
    let (mut t_ours_s, mut t_nm_s) = (0.0, 0.0);
    // Certificate outcomes: [proven monotone, proven not monotone, undecided, error].
    let (mut kappa, mut tau) = ([0usize; 4], [0usize; 4]);
    // Certificates decided by the exact path because the floating-point filter declined.
    let (mut kappa_exact, mut tau_exact) = (0usize, 0usize);
    let (mut kappa_dd, mut tau_dd) = (0usize, 0usize);
    for (a, n) in &spatial {
        let t0 = Instant::now();
        let curve = TypicalSpatial::from_points(a, *n).and_then(|c| c.curve());
        t_ours_s += t0.elapsed().as_secs_f64();
        let e = curve
            .as_ref()
            .map_or(f64::INFINITY, |c| cases::endpoint_error(a, c));
        if let Ok(c) = &curve {
            let (k, t) = (curvature_certificate(c), torsion_certificate(c));
            kappa_exact += usize::from(exact(&k));
            tau_exact += usize::from(exact(&t));
            kappa_dd += usize::from(double_double(&k));
            tau_dd += usize::from(double_double(&t));
            kappa[outcome(&k)] += 1;
            tau[outcome(&t)] += 1;
        }
        let t0 = Instant::now();
        let f = TypicalSpatial::nelder_mead(a, *n, NM_ITERS)
            .and_then(|(c, _)| c.curve())
            .map_or(f64::INFINITY, |c| cases::endpoint_error(a, &c));
        t_nm_s += t0.elapsed().as_secs_f64();
        for (k, tol) in tols.iter().enumerate() {
            ours_s[k] += usize::from(e <= *tol);
            nm_s[k] += usize::from(f <= *tol);
        }
    }
    let pct = |k: usize| 100.0 * k as f64 / INPUTS as f64;
    let mut md = String::new();
    writeln!(
        md,
        "Success rate over {INPUTS} seeded random feasible inputs (seed 2014): relative end-point error ≤ tolerance."
    )?;
    writeln!(
        md,
        "The paper reports no success rates; its method is Nelder–Mead ({NM_ITERS} iterations here)."
    )?;
    writeln!(md)?;
    writeln!(
        md,
        "| problem | solver | ≤ 1e-6 | ≤ 1e-9 | mean time per input (µs, this machine) |"
    )?;
    writeln!(md, "|---|---|---|---|---|")?;
    let us = |t: f64| 1e6 * t / INPUTS as f64;
    writeln!(
        md,
        "| planar (n = 3..12) | bracketed root (ours) | {:.2} % | {:.2} % | {:.1} |",
        pct(ours_p[0]),
        pct(ours_p[1]),
        us(t_ours_p)
    )?;
    writeln!(
        md,
        "| planar (n = 3..12) | Nelder–Mead on (L, s) | {:.2} % | {:.2} % | {:.1} |",
        pct(nm_p[0]),
        pct(nm_p[1]),
        us(t_nm_p)
    )?;
    writeln!(
        md,
        "| spatial (n = 3..10) | grid + Newton (ours) | {:.2} % | {:.2} % | {:.1} |",
        pct(ours_s[0]),
        pct(ours_s[1]),
        us(t_ours_s)
    )?;
    writeln!(
        md,
        "| spatial (n = 3..10) | Nelder–Mead on (φ, s), eq. (15) | {:.2} % | {:.2} % | {:.1} |",
        pct(nm_s[0]),
        pct(nm_s[1]),
        us(t_nm_s)
    )?;
    writeln!(md)?;
    writeln!(
        md,
        "Spatial typical curves from our solver (certificates: filter, else exact): curvature proven monotone on {} of {INPUTS}, proven not monotone on {}, undecided on {}, singular on {}; torsion proven monotone on {}, proven not monotone on {}, undecided on {}, singular on {}.",
        kappa[0], kappa[1], kappa[2], kappa[3], tau[0], tau[1], tau[2], tau[3]
    )?;
    writeln!(md)?;
    writeln!(
        md,
        "Exact fallback of the certificates (neither the f64 nor the double-double filter stage decided): curvature {kappa_exact} of {INPUTS}, torsion {tau_exact} of {INPUTS}; decided by the double-double stage: curvature {kappa_dd}, torsion {tau_dd}."
    )?;
    Ok(Table {
        name: "class-a-solvers".into(),
        markdown: md,
        checked: json!({
            "inputs": INPUTS,
            "planar_ours": ours_p, "planar_nelder_mead": nm_p,
            "spatial_ours": ours_s, "spatial_nelder_mead": nm_s,
            "spatial_curvature_outcomes": kappa, "spatial_torsion_outcomes": tau,
            "spatial_curvature_exact_fallback": kappa_exact, "spatial_torsion_exact_fallback": tau_exact,
            "spatial_curvature_double_double": kappa_dd, "spatial_torsion_double_double": tau_dd,
        }),
    })
}

fn counterexample_table() -> Result<Table, DynError> {
    let r = cases::farin_counterexample_search(200_000, 1);
    let mut md = String::new();
    writeln!(
        md,
        "Random 2×2 matrices (seed 1; a₁₁, a₂₂ ∈ [0.5, 3), a₁₂, a₂₁ ∈ [−2, 2)), each with a random unit Δb₀ and degrees 3, 4, 5."
    )?;
    writeln!(
        md,
        "Not in the paper: it shows that Farin's matrix conditions do not certify monotone curvature (Cao & Wang 2008)."
    )?;
    writeln!(md)?;
    writeln!(
        md,
        "| matrices | meeting Farin (3) and (4) | curves with a certified interior curvature extremum | of those, meeting (4) for all sampled sub-curve matrices |"
    )?;
    writeln!(md, "|---|---|---|---|")?;
    writeln!(
        md,
        "| {} | {} | {} | {} |",
        r.matrices, r.meeting_3_and_4, r.not_monotone, r.not_monotone_with_subcurve_4
    )?;
    if let Some((m, v, n, e)) = r.first {
        writeln!(md)?;
        writeln!(
            md,
            "First counterexample: M = [[{:.6}, {:.6}], [{:.6}, {:.6}]], Δb₀ = ({:.6}, {:.6}), n = {n}, curvature extremum at t = {e:.6}.",
            m[(0, 0)],
            m[(0, 1)],
            m[(1, 0)],
            m[(1, 1)],
            v.x(),
            v.y()
        )?;
    }
    Ok(Table {
        name: "class-a-farin-counterexamples".into(),
        markdown: md,
        checked: json!({
            "matrices": r.matrices,
            "meeting_3_and_4": r.meeting_3_and_4,
            "not_monotone": r.not_monotone,
            "not_monotone_with_subcurve_4": r.not_monotone_with_subcurve_4,
        }),
    })
}

/// Index of a certificate outcome: 0 proven monotone, 1 proven not monotone, 2 undecided,
/// 3 error (singular curve).
fn outcome(c: &Result<class_a::Certificate, class_a::ClassAError>) -> usize {
    match c {
        Ok(c) if c.is_monotone() => 0,
        Ok(class_a::Certificate {
            verdict: class_a::Monotonicity::NotMonotone { .. },
            ..
        }) => 1,
        Ok(_) => 2,
        Err(_) => 3,
    }
}

/// The certificate was decided by the exact path (or failed).
fn exact(c: &Result<class_a::Certificate, class_a::ClassAError>) -> bool {
    !matches!(c, Ok(c) if matches!(c.proof, class_a::Proof::Filter | class_a::Proof::DoubleDouble))
}

/// The certificate was decided by the double-double filter stage.
fn double_double(c: &Result<class_a::Certificate, class_a::ClassAError>) -> bool {
    matches!(c, Ok(c) if c.proof == class_a::Proof::DoubleDouble)
}

fn verdict(c: Result<class_a::Certificate, class_a::ClassAError>) -> String {
    match c {
        Ok(c) => format!("{:?}", c.verdict),
        Err(e) => format!("n/a ({e})"),
    }
}

fn figures_table() -> Result<Table, DynError> {
    let mut md = String::new();
    let mut checked = serde_json::Map::new();
    writeln!(
        md,
        "| figure | degree | Farin (3) margin | σ_min − 1 | Farin (4) margin | sub-curve (4) margin | curvature | torsion | LCG slope | LTG slope |"
    )?;
    writeln!(md, "|---|---|---|---|---|---|---|---|---|---|")?;
    let r5 = ClassAReport::of_3x3(&cases::fig5_matrix())?;
    let c5 = cases::fig5_curve()?;
    row3(&mut md, &mut checked, "Fig. 5 (basic, paper's M)", &c5, &r5)?;
    let t6 = cases::fig6_typical()?;
    let lcg6 = log_graph_from_points(
        (0..=200)
            .filter_map(|i| t6.log_curvature_point(f64::from(i) / 200.0))
            .collect(),
    )?;
    let k6 = verdict(curvature_certificate(&t6.curve()?));
    let r6 = ClassAReport::of_2x2(&t6.matrix().try_inverse().unwrap_or(t6.matrix()))?;
    writeln!(
        md,
        "| Fig. 6 (planar typical; report of M⁻¹, s < 1) | 49 | {:.4} | {:.4} | {:.4} | {:.4} | exact (4): margin {:.3e}; certificate: {k6} | – | {:.4} | – |",
        r6.farin3.margin,
        r6.singular_values.margin,
        r6.farin4.margin,
        r6.subcurve_farin4.margin,
        t6.margin(),
        lcg6.slope
    )?;
    checked.insert("fig6".into(), json!({"s": round(t6.s()), "theta": round(t6.theta()), "margin": round(t6.margin()), "curvature": k6, "lcg_slope": round(lcg6.slope)}));
    let (t7, c7) = cases::fig7_general()?;
    let m7 = class_a::perturb2(&t7.matrix(), cases::FIG7_DELTA);
    let r7 = ClassAReport::of_2x2(&m7)?;
    row2(
        &mut md,
        &mut checked,
        "Fig. 7 (planar general, δ = 0.1)",
        &c7,
        &r7,
    )?;
    let t8 = cases::fig8_typical()?;
    let c8 = t8.curve()?;
    let r8 = ClassAReport::of_3x3(&t8.matrix())?;
    row3(&mut md, &mut checked, "Fig. 8 (spatial typical)", &c8, &r8)?;
    let (t9, c9) = cases::fig9_general()?;
    let r9 = ClassAReport::of_3x3(&class_a::perturb3(&t9.matrix(), cases::FIG9_DELTA))?;
    row3(
        &mut md,
        &mut checked,
        "Fig. 9 (spatial general, δ = (0, 0.15, 0, 0.5))",
        &c9,
        &r9,
    )?;
    writeln!(md)?;
    writeln!(
        md,
        "The paper prints no numbers for these figures; curvature/torsion verdicts are exact Bernstein certificates of the actual (f64) control points."
    )?;
    Ok(Table {
        name: "class-a-figures".into(),
        markdown: md,
        checked: serde_json::Value::Object(checked),
    })
}

fn round(x: f64) -> f64 {
    (x * 1e8).round() / 1e8
}

fn row2(
    md: &mut String,
    checked: &mut serde_json::Map<String, serde_json::Value>,
    name: &str,
    c: &BezierCurve<2>,
    r: &ClassAReport,
) -> Result<(), DynError> {
    let lcg = log_graph(&curvature_samples(c, 201)?)?;
    let k = verdict(curvature_certificate(c));
    writeln!(
        md,
        "| {name} | {} | {:.4} | {:.4} | {:.4} | {:.4} | {k} | – | {:.4} | – |",
        c.degree(),
        r.farin3.margin,
        r.singular_values.margin,
        r.farin4.margin,
        r.subcurve_farin4.margin,
        lcg.slope
    )?;
    checked.insert(name.into(), json!({"farin3": round(r.farin3.margin), "farin4": round(r.farin4.margin), "curvature": k, "lcg_slope": round(lcg.slope)}));
    Ok(())
}

fn row3(
    md: &mut String,
    checked: &mut serde_json::Map<String, serde_json::Value>,
    name: &str,
    c: &BezierCurve<3>,
    r: &ClassAReport,
) -> Result<(), DynError> {
    let lcg = log_graph(&curvature_samples(c, 201)?)?;
    let ltg = log_graph(&torsion_samples(c, 201)?)?;
    let k = verdict(curvature_certificate(c));
    let t = verdict(torsion_certificate(c));
    writeln!(
        md,
        "| {name} | {} | {:.4} | {:.4} | {:.4} | {:.4} | {k} | {t} | {:.4} | {:.4} |",
        c.degree(),
        r.farin3.margin,
        r.singular_values.margin,
        r.farin4.margin,
        r.subcurve_farin4.margin,
        lcg.slope,
        ltg.slope
    )?;
    checked.insert(name.into(), json!({"farin3": round(r.farin3.margin), "farin4": round(r.farin4.margin), "curvature": k, "torsion": t, "lcg_slope": round(lcg.slope), "ltg_slope": round(ltg.slope)}));
    Ok(())
}

fn ts(count: usize) -> impl Iterator<Item = f64> {
    (0..count).map(move |i| i as f64 / (count - 1) as f64)
}

/// Curve (x–y projection for 3-D) with control polygon.
fn curve_plot<const D: usize>(title: &str, c: &BezierCurve<D>) -> Result<Plot, DynError> {
    let pts = c.sample_uniform(400)?;
    Ok(Plot::new(title, "x", "y")
        .equal()
        .with(Series::new(
            "curve",
            pts.iter().map(|p| (p[0], p[1])).collect(),
            Style::Line,
        ))
        .with(Series::new(
            "control polygon",
            c.points().iter().map(|p| (p[0], p[1])).collect(),
            Style::LinePoints,
        )))
}

fn write_set<const D: usize>(
    dir: &Path,
    stem: &str,
    title: &str,
    c: &BezierCurve<D>,
    torsion: Option<&BezierCurve<3>>,
    out: &mut Vec<PathBuf>,
) -> Result<(), DynError> {
    let proj = if D == 3 { " (x–y projection)" } else { "" };
    out.push(
        curve_plot(&format!("{title}{proj}"), c)?
            .write_svg(&dir.join(format!("{stem}-curve.svg")))?,
    );
    let k: Vec<(f64, f64)> = ts(400)
        .filter_map(|t| c.curvature(t).ok().map(|k| (t, k)))
        .collect();
    out.push(
        Plot::new(format!("{title}: curvature"), "t", "κ")
            .with(Series::new("κ(t)", k, Style::Line))
            .write_svg(&dir.join(format!("{stem}-curvature.svg")))?,
    );
    let lcg = log_graph(&curvature_samples(c, 201)?)?;
    out.push(
        Plot::new(
            format!("{title}: LCG, slope {:.3}", lcg.slope),
            "log ρ",
            "log(ρ |ds/dρ|)",
        )
        .with(Series::new("LCG", lcg.points, Style::Line))
        .write_svg(&dir.join(format!("{stem}-lcg.svg")))?,
    );
    if let Some(c3) = torsion {
        let tau: Vec<(f64, f64)> = ts(400)
            .filter_map(|t| c3.torsion(t).ok().map(|v| (t, v)))
            .collect();
        out.push(
            Plot::new(format!("{title}: torsion"), "t", "τ")
                .with(Series::new("τ(t)", tau, Style::Line))
                .write_svg(&dir.join(format!("{stem}-torsion.svg")))?,
        );
        let ltg = log_graph(&torsion_samples(c3, 201)?)?;
        out.push(
            Plot::new(
                format!("{title}: LTG, slope {:.3}", ltg.slope),
                "log μ",
                "log(μ |ds/dμ|)",
            )
            .with(Series::new("LTG", ltg.points, Style::Line))
            .write_svg(&dir.join(format!("{stem}-ltg.svg")))?,
        );
    }
    Ok(())
}

/// Figs. 5–9: curves, curvature/torsion plots, LCG/LTG.
pub(crate) fn figures(dir: &Path) -> Result<Vec<PathBuf>, DynError> {
    let mut out = Vec::new();
    let c5 = cases::fig5_curve()?;
    write_set(
        dir,
        "fig5",
        "Fig. 5: degree-6 basic curve",
        &c5,
        Some(&c5),
        &mut out,
    )?;
    // Fig. 6 at degree 49: closed forms (control-point differences lose accuracy).
    let t6 = cases::fig6_typical()?;
    let c6 = t6.curve()?;
    out.push(
        curve_plot("Fig. 6: degree-49 planar typical curve", &c6)?
            .write_svg(&dir.join("fig6-curve.svg"))?,
    );
    let k6: Vec<(f64, f64)> = ts(400).map(|t| (t, t6.curvature(t))).collect();
    out.push(
        Plot::new("Fig. 6: curvature (closed form)", "t", "κ")
            .with(Series::new("κ(t)", k6, Style::Line))
            .write_svg(&dir.join("fig6-curvature.svg"))?,
    );
    let lcg6 = log_graph_from_points(ts(201).filter_map(|t| t6.log_curvature_point(t)).collect())?;
    out.push(
        Plot::new(
            format!("Fig. 6: LCG (closed form), slope {:.3}", lcg6.slope),
            "log ρ",
            "log(ρ |ds/dρ|)",
        )
        .with(Series::new("LCG", lcg6.points, Style::Line))
        .write_svg(&dir.join("fig6-lcg.svg"))?,
    );
    let (_, c7) = cases::fig7_general()?;
    write_set(
        dir,
        "fig7",
        "Fig. 7: degree-9 planar general curve",
        &c7,
        None,
        &mut out,
    )?;
    let c8 = cases::fig8_typical()?.curve()?;
    write_set(
        dir,
        "fig8",
        "Fig. 8: degree-7 spatial typical curve",
        &c8,
        Some(&c8),
        &mut out,
    )?;
    let (_, c9) = cases::fig9_general()?;
    write_set(
        dir,
        "fig9",
        "Fig. 9: degree-4 spatial general curve",
        &c9,
        Some(&c9),
        &mut out,
    )?;
    Ok(out)
}
