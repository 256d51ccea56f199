//! Private Python virtual environments under `target/` for the optional commands that compare
//! with Python libraries. Nothing in `cargo test` or `cargo xtask tables` uses them.

use std::io::ErrorKind;
use std::path::PathBuf;
use std::process::Command;

use crate::{DynError, project_root};

/// The Python interpreter of `target/<name>`, created with `python3 -m venv` and given `packages`
/// (by pip, from PyPI) unless `import <module>` already works there.
///
/// # Errors
/// A clear message when `python3` is not on the `PATH`, or when venv creation or pip fails.
pub(crate) fn python_env(name: &str, module: &str, packages: &[&str]) -> Result<PathBuf, DynError> {
    let venv = project_root().join("target").join(name);
    let python = venv.join("bin").join("python");
    if !python.exists() {
        let status = match Command::new("python3")
            .arg("-m")
            .arg("venv")
            .arg(&venv)
            .status()
        {
            Ok(status) => status,
            Err(e) if e.kind() == ErrorKind::NotFound => {
                return Err(
                    "python3 was not found on the PATH; this optional command needs Python 3 \
                     (with its venv module) to install its Python packages into target/"
                        .into(),
                );
            }
            Err(e) => return Err(e.into()),
        };
        if !status.success() {
            return Err(format!(
                "`python3 -m venv {}` failed (on Debian/Ubuntu the venv module is the python3-venv package)",
                venv.display()
            )
            .into());
        }
    }
    let have = Command::new(&python)
        .args(["-c", &format!("import {module}")])
        .status()?;
    if !have.success() {
        let ok = Command::new(&python)
            .args(["-m", "pip", "install", "--quiet"])
            .args(packages)
            .status()?;
        if !ok.success() {
            return Err(format!("pip install {} failed", packages.join(" ")).into());
        }
    }
    Ok(python)
}
