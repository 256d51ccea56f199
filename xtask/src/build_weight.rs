//! `cargo xtask build-weight`: what each library crate costs a consumer's build, beside kurbo and
//! lyon_geom, measured in one run.
//!
//! For every crate, a throwaway package under `target/build-weight/` depends on it alone (default
//! features, as a consumer would) and is built with `cargo build --release` into an empty target
//! directory. Reported: the CPU time (user + system) of that cold build, read from the
//! children's times in `/proc/self/stat` (Linux), its wall time, and the number of crates in its
//! normal dependency tree. The builds run one after the other, in rounds, and each crate keeps
//! its lowest CPU time. Writes `docs/results/build-weight.md` (timings are never checked).

use std::fmt::Write as _;
use std::fs;
use std::path::Path;
use std::process::Command;
use std::time::Instant;

use crate::{DynError, project_root};

/// The crates measured: (name, dependency line of the throwaway package).
fn subjects(root: &Path) -> Vec<(String, String)> {
    let mut v: Vec<(String, String)> = [
        "bez-core",
        "bez-subdiv",
        "lambda-bezier",
        "class-a",
        "subdiv-fit",
        "pde-bezier",
    ]
    .iter()
    .map(|c| {
        let path = root.join("crates").join(c);
        (
            c.to_string(),
            format!("{c} = {{ path = {:?} }}", path.display().to_string()),
        )
    })
    .collect();
    // The peers at the newest release the workspace uses.
    v.push((
        "kurbo".into(),
        format!("kurbo = \"={}\"", locked_version(root, "kurbo")),
    ));
    v.push((
        "lyon_geom".into(),
        format!("lyon_geom = \"={}\"", locked_version(root, "lyon_geom")),
    ));
    v
}

/// The version of `name` in the workspace's Cargo.lock (the newest one if several).
fn locked_version(root: &Path, name: &str) -> String {
    let lock = fs::read_to_string(root.join("Cargo.lock")).unwrap_or_default();
    let mut versions: Vec<String> = Vec::new();
    let mut lines = lock.lines();
    while let Some(line) = lines.next() {
        if line == format!("name = \"{name}\"")
            && let Some(v) = lines.next().and_then(|l| l.strip_prefix("version = \""))
        {
            versions.push(v.trim_end_matches('"').to_string());
        }
    }
    versions.sort_by_key(|v| {
        v.split('.')
            .map(|p| p.parse::<u64>().unwrap_or(0))
            .collect::<Vec<_>>()
    });
    versions.pop().unwrap_or_else(|| "*".into())
}

/// CPU seconds (user + system) of this process's waited-for descendants.
fn children_cpu_seconds() -> Result<f64, DynError> {
    let stat = fs::read_to_string("/proc/self/stat")?;
    // Fields after the command name (which is in parentheses and may contain spaces).
    let rest = stat.rsplit_once(')').ok_or("unexpected /proc/self/stat")?.1;
    let fields: Vec<&str> = rest.split_whitespace().collect();
    // Fields 16 and 17 of stat(5) (cutime, cstime) are at 13 and 14 after the name.
    let ticks: f64 = fields.get(13).ok_or("no cutime")?.parse::<f64>()?
        + fields.get(14).ok_or("no cstime")?.parse::<f64>()?;
    let hz = Command::new("getconf")
        .arg("CLK_TCK")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .and_then(|s| s.trim().parse::<f64>().ok())
        .unwrap_or(100.0);
    Ok(ticks / hz)
}

struct Measure {
    cpu: f64,
    wall: f64,
    deps: usize,
}

fn measure(dir: &Path, name: &str, dep: &str) -> Result<Measure, DynError> {
    let pkg = dir.join(format!("consumer-{name}"));
    fs::create_dir_all(pkg.join("src"))?;
    fs::write(
        pkg.join("Cargo.toml"),
        format!(
            "[package]\nname = \"consumer-{name}\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n[dependencies]\n{dep}\n\n[workspace]\n"
        ),
    )?;
    fs::write(pkg.join("src/lib.rs"), "//! Depends on one crate.\n")?;
    let target = dir.join(format!("target-{name}"));
    if target.exists() {
        fs::remove_dir_all(&target)?;
    }
    // Resolve (and download) first, so the timed build only compiles.
    let fetched = Command::new("cargo")
        .arg("fetch")
        .current_dir(&pkg)
        .status()?;
    if !fetched.success() {
        return Err(format!("cargo fetch failed for {name}").into());
    }
    let cpu0 = children_cpu_seconds()?;
    let start = Instant::now();
    let status = Command::new("cargo")
        .args(["build", "--release", "--quiet"])
        .env("CARGO_TARGET_DIR", &target)
        .current_dir(&pkg)
        .status()?;
    let wall = start.elapsed().as_secs_f64();
    let cpu = children_cpu_seconds()? - cpu0;
    if !status.success() {
        return Err(format!("cold build of {name} failed").into());
    }
    let tree = Command::new("cargo")
        .args([
            "tree", "-e", "normal", "--prefix", "none", "--format", "{p}",
        ])
        .current_dir(&pkg)
        .output()?;
    let mut lines: Vec<String> = String::from_utf8(tree.stdout)?
        .lines()
        .map(|l| l.trim_end_matches(" (*)").to_string())
        .filter(|l| !l.is_empty() && !l.starts_with("consumer-"))
        .collect();
    lines.sort();
    lines.dedup();
    fs::remove_dir_all(&target)?;
    Ok(Measure {
        cpu,
        wall,
        deps: lines.len(),
    })
}

/// With `--only CRATE`: that crate beside kurbo, plus, for pde-bezier, faer alone with its
/// default features and with the feature set the workspace uses (what the feature choice
/// saves). Printed only: the committed table keeps one run over all crates.
fn only_subjects(root: &Path, only: &str) -> Result<Vec<(String, String)>, DynError> {
    let mut v: Vec<(String, String)> = subjects(root)
        .into_iter()
        .filter(|(name, _)| name == only || name == "kurbo")
        .collect();
    if v.len() < 2 {
        return Err(format!("build-weight --only: unknown crate `{only}`").into());
    }
    if only == "pde-bezier" {
        let faer = locked_version(root, "faer");
        v.push(("faer-default".into(), format!("faer = \"={faer}\"")));
        v.push((
            "faer-sparse".into(),
            format!(
                "faer = {{ version = \"={faer}\", default-features = false, features = [\"std\", \"sparse-linalg\"] }}"
            ),
        ));
    }
    Ok(v)
}

/// Runs the measurement: `rounds` rounds over all crates (or `only` one, see
/// [`only_subjects`]), each crate's fastest round.
pub(crate) fn run(rounds: usize, only: Option<&str>) -> Result<(), DynError> {
    let root = project_root();
    let dir = root.join("target").join("build-weight");
    fs::create_dir_all(&dir)?;
    let subjects = match only {
        Some(name) => only_subjects(&root, name)?,
        None => subjects(&root),
    };
    let mut best: Vec<Option<Measure>> = subjects.iter().map(|_| None).collect();
    for round in 0..rounds {
        for ((name, dep), best) in subjects.iter().zip(&mut best) {
            let m = measure(&dir, name, dep)?;
            println!(
                "round {}: {name}: {:.1} s CPU, {:.1} s wall, {} crates",
                round + 1,
                m.cpu,
                m.wall,
                m.deps
            );
            if best.as_ref().is_none_or(|b| m.cpu < b.cpu) {
                *best = Some(m);
            }
        }
    }
    let kurbo = subjects
        .iter()
        .zip(&best)
        .find(|(s, _)| s.0 == "kurbo")
        .and_then(|(_, m)| m.as_ref().map(|m| m.cpu))
        .ok_or("kurbo was not measured")?;
    let mut md = String::from(
        "# Build weight: cold release build of one crate as a consumer's only dependency\n\n\
         Generated by `cargo xtask build-weight` (not checked: timings depend on the machine). \
         Each row is a package that depends on the crate alone, with default features, built \
         with `cargo build --release` into an empty target directory; CPU is user + system time \
         of the whole build, the lowest over the rounds, and the ratio is to kurbo's CPU time \
         in the same run. Crates: the distinct packages of `cargo tree -e normal`.\n\n\
         | crate | CPU s | ratio to kurbo | wall s | crates in the tree |\n|---|---|---|---|---|\n",
    );
    for ((name, _), m) in subjects.iter().zip(&best) {
        if let Some(m) = m {
            writeln!(
                md,
                "| {name} | {:.1} | {:.2} | {:.1} | {} |",
                m.cpu,
                m.cpu / kurbo,
                m.wall,
                m.deps
            )?;
        }
    }
    writeln!(md, "\nRounds: {rounds}.")?;
    if only.is_some() {
        println!("{md}");
        return Ok(());
    }
    let out = root.join("docs/results/build-weight.md");
    fs::write(&out, &md)?;
    println!("{md}");
    println!(
        "wrote {}",
        out.strip_prefix(&root).unwrap_or(&out).display()
    );
    Ok(())
}
