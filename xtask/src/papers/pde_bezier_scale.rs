//! pde-bezier at design scale: sparse Galerkin solves from 1k to 16k unknowns, a long strip,
//! and polynomial exactness of every method on a refined fourth-order grid.

use std::fmt::Write as _;
use std::time::Instant;

use bez_core::{BezierSurface, Vector3};
use pde_bezier::{Assembly, Discretization, Method, Operator, Problem};
use serde_json::{Value, json};

use crate::DynError;
use crate::tables::Table;
use crate::timing::{Run, best_micros};

/// A bi-quintic polynomial surface with scattered control points (deterministic).
fn quintic() -> Result<BezierSurface<3>, DynError> {
    let pts = (0..36)
        .map(|i| {
            let t = f64::from(i);
            Vector3::new((0.7 * t).sin(), (1.3 * t).cos(), (0.37 * t).sin())
        })
        .collect();
    Ok(BezierSurface::from_flat(5, 5, pts)?)
}

fn grid(patches_u: usize, patches_v: usize, smoothness: usize) -> Discretization {
    Discretization {
        degree_u: 5,
        degree_v: 5,
        patches_u,
        patches_v,
        smoothness_u: smoothness,
        smoothness_v: smoothness,
    }
}

/// Peak resident memory in MB since the last reset (Linux: VmHWM, reset by writing 5 to
/// /proc/self/clear_refs); `None` elsewhere.
fn reset_peak() {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
}

fn peak_mb() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb / 1024.0)
}

pub(crate) fn scale_table() -> Result<Table, DynError> {
    let x = quintic()?;
    let laplace = Problem::manufactured(Operator::second_order(1.0, 1.0)?, &x)?;
    let mut md = String::new();
    let mut checked = Vec::new();
    let _ = writeln!(
        md,
        "### pde-bezier: scale (bi-quintic C¹ patches, Laplace with a quintic exact solution, Galerkin; assembly + sparse solve, best of 3 interleaved rounds; growth = log(time ratio)/log(unknowns ratio) to the previous row)\n"
    );
    let _ = writeln!(
        md,
        "| grid | unknowns | time (s) | growth | peak memory (MB) | max error | condition |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|---|---|");
    let grids = [(8, 8), (12, 12), (16, 16), (23, 23), (32, 32), (1, 800)];
    let discs: Vec<Discretization> = grids.iter().map(|&(u, v)| grid(u, v, 1)).collect();
    let mut runs: Vec<Run<'_>> = discs
        .iter()
        .map(|disc| -> Run<'_> {
            let problem = &laplace;
            Box::new(move || {
                Assembly::new(problem, disc)?.solve(Method::Galerkin)?;
                Ok(())
            })
        })
        .collect();
    let micros = best_micros(&mut runs, 3, 1.0)?;
    drop(runs);
    let mut prev: Option<(f64, f64)> = None;
    for (disc, &us) in discs.iter().zip(&micros) {
        reset_peak();
        let assembly = Assembly::new(&laplace, disc)?;
        let sol = assembly.solve(Method::Galerkin)?;
        let mem = peak_mb().map_or("n/a".to_string(), |m| format!("{m:.0}"));
        let err = sol
            .surface
            .error_norms(|u, v| x.eval(u, v).unwrap_or_default(), 50)?
            .max;
        let n = assembly.unknowns() as f64;
        let secs = us * 1e-6;
        let growth = match prev {
            Some((n0, t0)) if disc.patches_u > 1 => {
                format!("{:.2}", (secs / t0).ln() / (n / n0).ln())
            }
            _ => "–".to_string(),
        };
        if disc.patches_u > 1 {
            prev = Some((n, secs));
        }
        let _ = writeln!(
            md,
            "| {}x{} | {} | {secs:.3} | {growth} | {mem} | {:.1e} | {:.1e} |",
            disc.patches_u,
            disc.patches_v,
            assembly.unknowns(),
            err,
            sol.condition
        );
        checked.push(json!({"grid": [disc.patches_u, disc.patches_v], "unknowns": assembly.unknowns(), "exact_to_1e-9": err <= 1e-9}));
    }
    let _ = writeln!(
        md,
        "\nPolynomial exactness on the biharmonic (∂uu + ∂vv)², 32 x 32 quintic C³ patches (normal equations gave 1.8e-5 for Σb²):\n"
    );
    let _ = writeln!(
        md,
        "| method | unknowns | time (s) | max error | condition |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|");
    let biharmonic = Problem::manufactured(Operator::bloor_wilson(1.0)?, &x)?;
    let assembly = Assembly::new(&biharmonic, &grid(32, 32, 3))?;
    for method in Method::ALL {
        let start = Instant::now();
        let sol = assembly.solve(method)?;
        let secs = start.elapsed().as_secs_f64();
        let err = sol
            .surface
            .error_norms(|u, v| x.eval(u, v).unwrap_or_default(), 50)?
            .max;
        let _ = writeln!(
            md,
            "| {} | {} | {secs:.2} | {err:.1e} | {:.1e} |",
            method.name(),
            assembly.unknowns(),
            sol.condition
        );
        checked.push(json!({"biharmonic_32x32": method.name(), "exact_to_1e-9": err <= 1e-9}));
    }
    Ok(Table {
        name: "pde-bezier-scale".to_string(),
        markdown: md,
        checked: Value::Array(checked),
    })
}
