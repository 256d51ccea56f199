//! pde-bezier at design scale: sparse Galerkin solves from 1k to 16k unknowns, a long strip,
//! and polynomial exactness of every method on a refined fourth-order grid.

use std::fmt::Write as _;
use std::time::Instant;

use bez_core::{BezierSurface, Vector3};
use pde_bezier::{Assembly, Discretization, Method, Operator, Problem, Storage};
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

/// The internal xtask command that runs one scale solve in a child process.
pub(crate) const PEAK_COMMAND: &str = "pde-bezier-peak";

/// A field of /proc/self/status in kB (Linux only).
fn status_kb(field: &str) -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(field))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// The child's side of [`solve_peak_mb`]: `pde-bezier-peak PU PV` assembles and solves the
/// scale problem on PU x PV bi-quintic C¹ patches and prints `peak_kb K`, the peak resident
/// size (VmHWM) at the end minus the resident size (VmRSS) just before the assembly.
pub(crate) fn peak_child(args: &[&str]) -> Result<(), DynError> {
    let [pu, pv] = args else {
        return Err(format!("usage: {PEAK_COMMAND} PATCHES_U PATCHES_V").into());
    };
    let x = quintic()?;
    let laplace = Problem::manufactured(Operator::second_order(1.0, 1.0)?, &x)?;
    let disc = grid(pu.parse()?, pv.parse()?, 1);
    let before = status_kb("VmRSS:").ok_or("no VmRSS")?;
    let sol = Assembly::new(&laplace, &disc)?.solve(Method::Galerkin)?;
    let after = status_kb("VmHWM:").ok_or("no VmHWM")?;
    std::hint::black_box(sol);
    println!("peak_kb {}", after - before);
    Ok(())
}

/// The memory one solve needs, in MB: assembly and solve run in a fresh xtask process, so
/// the number is not inflated by earlier tables or by pages the allocator kept; `None` where
/// /proc is missing.
fn solve_peak_mb(disc: &Discretization) -> Option<f64> {
    let out = std::process::Command::new(std::env::current_exe().ok()?)
        .args([
            PEAK_COMMAND,
            &disc.patches_u.to_string(),
            &disc.patches_v.to_string(),
        ])
        .output()
        .ok()?;
    let text = String::from_utf8(out.stdout).ok()?;
    let kb: f64 = text.strip_prefix("peak_kb ")?.trim().parse().ok()?;
    Some(kb / 1024.0)
}

pub(crate) fn scale_table() -> Result<Table, DynError> {
    let x = quintic()?;
    let laplace = Problem::manufactured(Operator::second_order(1.0, 1.0)?, &x)?;
    let mut md = String::new();
    let mut checked = Vec::new();
    let _ = writeln!(
        md,
        "### pde-bezier: scale (bi-quintic C¹ patches, Laplace with a quintic exact solution, Galerkin; assembly + solve, best of 5 interleaved rounds; growth = log(time ratio)/log(unknowns ratio) to the previous row; memory = peak resident size of one assembly and solve in a fresh process, above its resident size before)\n"
    );
    let _ = writeln!(
        md,
        "| grid | unknowns | time (s) | growth | memory (MB) | max error | condition |"
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
    let micros = best_micros(&mut runs, 5, 1.0)?;
    drop(runs);
    let mut prev: Option<(f64, f64)> = None;
    for (disc, &us) in discs.iter().zip(&micros) {
        let mem = solve_peak_mb(disc).map_or("n/a".to_string(), |m| format!("{m:.0}"));
        let assembly = Assembly::new(&laplace, disc)?;
        let sol = assembly.solve(Method::Galerkin)?;
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

/// Dense against sparse factorization of the same systems, per method, to place the
/// thresholds of `Storage::Auto` (solve only: one assembly per size, reused).
pub(crate) fn crossover_table() -> Result<Table, DynError> {
    let x = quintic()?;
    let laplace = Problem::manufactured(Operator::second_order(1.0, 1.0)?, &x)?;
    let single = |n: usize| Discretization::single(n, n);
    // (family, discretization): one patch of rising degree (nearly full matrices), and grids
    // of bi-quintic C¹ patches (sparse ones).
    let mut sizes: Vec<(&str, Discretization)> = [5, 7, 9, 11, 13]
        .into_iter()
        .map(|n| ("1 patch", single(n)))
        .collect();
    sizes.extend(
        [
            (1, 2),
            (2, 2),
            (2, 3),
            (3, 3),
            (3, 4),
            (4, 4),
            (5, 5),
            (6, 6),
            (8, 8),
        ]
        .into_iter()
        .map(|(u, v)| ("C¹ grid", grid(u, v, 1))),
    );
    let assemblies = sizes
        .iter()
        .map(|(_, disc)| Assembly::new(&laplace, disc))
        .collect::<Result<Vec<_>, _>>()?;
    let mut md = String::new();
    let mut checked = Vec::new();
    let _ = writeln!(
        md,
        "### pde-bezier: dense or sparse factorization (Laplace with a quintic exact solution, all sides fixed; solve only, ms, best of 5 interleaved rounds; ratio = sparse/dense, above 1 where dense is faster)\n"
    );
    let _ = writeln!(
        md,
        "| trial space | bidegree | unknowns | method | dense (ms) | sparse (ms) | ratio |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|---|---|");
    for method in Method::ALL {
        let mut runs: Vec<Run<'_>> = Vec::new();
        for assembly in &assemblies {
            for storage in [Storage::Dense, Storage::Sparse] {
                runs.push(Box::new(move || {
                    assembly.solve_with(method, storage)?;
                    Ok(())
                }));
            }
        }
        let micros = best_micros(&mut runs, 5, 30_000.0)?;
        drop(runs);
        let mut largest_dense_win = 0;
        for (((family, disc), assembly), pair) in
            sizes.iter().zip(&assemblies).zip(micros.chunks(2))
        {
            let (dense, sparse) = (pair[0] * 1e-3, pair[1] * 1e-3);
            let unknowns = assembly.unknowns();
            if dense < sparse {
                largest_dense_win = largest_dense_win.max(unknowns);
            }
            let _ = writeln!(
                md,
                "| {family}{} | ({}, {}) | {unknowns} | {} | {dense:.3} | {sparse:.3} | {:.2} |",
                if disc.patches_u > 1 || disc.patches_v > 1 {
                    format!(" {}x{}", disc.patches_u, disc.patches_v)
                } else {
                    String::new()
                },
                disc.degree_u,
                disc.degree_v,
                method.name(),
                sparse / dense
            );
            checked.push(json!({"method": method.name(), "unknowns": unknowns}));
        }
        let _ = writeln!(
            md,
            "| | | | {}: dense faster up to {largest_dense_win} unknowns | | | |",
            method.name()
        );
    }
    Ok(Table {
        name: "pde-bezier-crossover".to_string(),
        markdown: md,
        checked: Value::Array(checked),
    })
}
