//! `cargo xtask figures`: write every paper's figures as SVG into `docs/figures/<paper>/`.

use std::fs;

use crate::{DynError, papers, project_root};

pub(crate) fn run(only: Option<&str>) -> Result<(), DynError> {
    let root = project_root().join("docs").join("figures");
    let mut count = 0;
    for paper in papers::selected(only)? {
        let Some(figures) = paper.figures else {
            continue;
        };
        let dir = root.join(paper.name);
        fs::create_dir_all(&dir)?;
        let written = figures(&dir)?;
        for f in &written {
            println!(
                "wrote {}",
                f.strip_prefix(project_root()).unwrap_or(f).display()
            );
        }
        count += written.len();
    }
    println!("wrote {count} figures");
    Ok(())
}
