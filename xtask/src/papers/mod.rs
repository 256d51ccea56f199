//! The registry of papers: each paper's module contributes its tables and figures.
//!
//! To add a paper's experiments, write `papers/<crate>.rs` with `tables()` and/or
//! `figures(dir)` and list it in [`PAPERS`].

use std::path::{Path, PathBuf};

mod bez_core;
mod bez_subdiv;
mod bez_subdiv_peers;
mod bez_subdiv_per_point;
mod class_a;
mod lambda_bezier;
mod pde_bezier;
pub(crate) mod pde_bezier_scale;
mod subdiv_fit;
mod subdiv_fit_glyphs;
mod subdiv_fit_joints;
mod subdiv_fit_kurbo;
pub(crate) mod subdiv_fit_scipy;
mod suites;

use crate::DynError;
use crate::tables::Table;

/// Computes a paper's tables.
pub(crate) type TablesFn = fn() -> Result<Vec<Table>, DynError>;
/// Writes a paper's figures into the given directory and returns the files written.
pub(crate) type FiguresFn = fn(&Path) -> Result<Vec<PathBuf>, DynError>;

/// One paper's experiments.
#[derive(Debug)]
pub(crate) struct Paper {
    /// The crate name, also the `--only` name and the figures' sub-directory.
    pub(crate) name: &'static str,
    pub(crate) tables: Option<TablesFn>,
    pub(crate) figures: Option<FiguresFn>,
}

/// Every paper with experiments, in the order of the README's table.
const PAPERS: &[Paper] = &[
    Paper {
        name: "bez-core",
        // The coverage of every crate's adversarial suite.
        tables: Some(suites::tables),
        figures: Some(bez_core::figures),
    },
    Paper {
        name: "bez-subdiv",
        // Table 1, the N* table, then the comparison with kurbo and lyon_geom.
        tables: Some(bez_subdiv_peers::tables),
        figures: None,
    },
    Paper {
        name: "lambda-bezier",
        tables: Some(lambda_bezier::tables),
        figures: Some(lambda_bezier::figures),
    },
    Paper {
        name: "class-a",
        tables: Some(class_a::tables),
        figures: Some(class_a::figures),
    },
    Paper {
        name: "subdiv-fit",
        tables: Some(subdiv_fit::tables),
        figures: Some(subdiv_fit::figures),
    },
    Paper {
        name: "pde-bezier",
        tables: Some(pde_bezier::tables),
        figures: Some(pde_bezier::figures),
    },
];

/// The papers selected by `--only` (all when `None`).
pub(crate) fn selected(only: Option<&str>) -> Result<Vec<&'static Paper>, DynError> {
    let all: Vec<&Paper> = PAPERS.iter().collect();
    match only {
        None => Ok(all),
        Some(name) => {
            let hit: Vec<_> = all.into_iter().filter(|p| p.name == name).collect();
            if hit.is_empty() {
                Err(format!("no experiments registered for `{name}`").into())
            } else {
                Ok(hit)
            }
        }
    }
}
