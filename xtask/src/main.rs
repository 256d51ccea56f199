//! `cargo xtask`: the project's automation.
//!
//! - `cargo xtask tables [--check] [--only PAPER]` recomputes every paper's tables, prints them,
//!   and writes `docs/results/<table>.md` and `.json`; with `--check` it compares the recomputed
//!   deterministic values with the committed JSON instead and fails with a readable diff.
//! - `cargo xtask figures [--only PAPER]` writes the papers' figures as SVG to `docs/figures/`.
//! - `cargo xtask cad-check` reads pde-bezier's STEP and IGES export with Open CASCADE.
//! - `cargo xtask build-weight [--rounds N] [--only CRATE]` measures each library crate's cold
//!   release build beside kurbo's and lyon_geom's into `docs/results/build-weight.md` (with
//!   `--only`, one crate beside kurbo, printed only).
//! - `cargo xtask scipy` compares subdiv-fit with SciPy's `splprep` and writes
//!   `docs/results/subdiv-fit-scipy.md` and `.json` (optional, needs Python 3).
#![allow(
    clippy::print_stdout,
    clippy::print_stderr,
    reason = "a command-line tool talks to its user"
)]

mod build_weight;
mod cad_check;
mod figures;
mod papers;
mod plot;
mod tables;
mod timing;
mod venv;

use std::path::PathBuf;
use std::process::ExitCode;

/// The error type of every xtask step.
pub(crate) type DynError = Box<dyn std::error::Error>;

fn main() -> ExitCode {
    match try_main() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn try_main() -> Result<(), DynError> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let (cmd, rest) = args.split_first().map_or(("", &[][..]), |(c, r)| (*c, r));
    if cmd == papers::pde_bezier_scale::PEAK_COMMAND {
        // Internal: one solve in a fresh process, for the scale table's memory column.
        return papers::pde_bezier_scale::peak_child(rest);
    }
    let mut check = false;
    let mut only: Option<&str> = None;
    let mut rounds = 1;
    let mut it = rest.iter();
    while let Some(&a) = it.next() {
        match a {
            "--check" => check = true,
            "--only" => only = Some(it.next().copied().ok_or("--only needs a paper name")?),
            "--rounds" => rounds = it.next().ok_or("--rounds needs a number")?.parse()?,
            other => return Err(format!("unknown argument `{other}`\n{HELP}").into()),
        }
    }
    match cmd {
        "tables" => tables::run(check, only),
        "figures" if !check => figures::run(only),
        "cad-check" if !check && only.is_none() => cad_check::run(),
        "scipy" if !check && only.is_none() => papers::subdiv_fit_scipy::run(),
        "build-weight" if !check => build_weight::run(rounds, only),
        _ => {
            println!("{HELP}");
            Ok(())
        }
    }
}

const HELP: &str = "usage:
  cargo xtask tables [--check] [--only PAPER]   recompute the papers' tables (--check: compare with docs/results)
  cargo xtask figures [--only PAPER]            write the papers' figures to docs/figures
  cargo xtask cad-check                         read pde-bezier's STEP/IGES export with Open CASCADE (PyPI)
  cargo xtask build-weight [--rounds N] [--only CRATE]
                                                cold release build of each crate beside kurbo and lyon_geom
                                                (--only: one crate and kurbo, printed, not written)
  cargo xtask scipy                             compare subdiv-fit with SciPy's splprep (PyPI) into docs/results
papers: bez-subdiv, lambda-bezier, class-a, subdiv-fit, pde-bezier";

/// The workspace root (the parent of this crate's directory).
pub(crate) fn project_root() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    dir.parent().map_or(dir.clone(), PathBuf::from)
}
