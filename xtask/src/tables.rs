//! `cargo xtask tables [--check]`: compute, print, write or check every paper's tables.

use std::fmt::Write as _;
use std::fs;

use serde_json::Value;

use crate::{DynError, papers, project_root};

/// One generated table.
#[derive(Debug)]
pub(crate) struct Table {
    /// File stem under `docs/results/`, e.g. `bez-subdiv-table1`.
    pub(crate) name: String,
    /// The table for people: markdown with the paper's values beside ours (may hold timings).
    pub(crate) markdown: String,
    /// The deterministic values the regression check compares (never timings).
    pub(crate) checked: Value,
}

/// Relative tolerance of the regression check for numbers.
const REL_TOL: f64 = 1e-9;
/// Absolute tolerance of the regression check for numbers near zero.
const ABS_TOL: f64 = 1e-12;

pub(crate) fn run(check: bool, only: Option<&str>) -> Result<(), DynError> {
    let dir = project_root().join("docs").join("results");
    fs::create_dir_all(&dir)?;
    let mut failures = Vec::new();
    let mut count = 0;
    for paper in papers::selected(only)? {
        let Some(tables) = paper.tables else { continue };
        for table in tables()? {
            count += 1;
            println!("{}\n", table.markdown);
            let json_path = dir.join(format!("{}.json", table.name));
            if check {
                let committed: Value = match fs::read_to_string(&json_path) {
                    Ok(s) => serde_json::from_str(&s)?,
                    Err(_) => {
                        failures.push(format!(
                            "{}: no committed {}",
                            table.name,
                            json_path.display()
                        ));
                        continue;
                    }
                };
                let mut diffs = Vec::new();
                compare(&committed, &table.checked, "", &mut diffs);
                if !diffs.is_empty() {
                    let mut msg = format!("{} differs from the committed results:", table.name);
                    for d in diffs.iter().take(20) {
                        let _ = write!(msg, "\n    {d}");
                    }
                    if diffs.len() > 20 {
                        let _ = write!(msg, "\n    … and {} more", diffs.len() - 20);
                    }
                    failures.push(msg);
                }
            } else {
                fs::write(
                    dir.join(format!("{}.md", table.name)),
                    format!("{}\n", table.markdown),
                )?;
                fs::write(
                    &json_path,
                    format!("{}\n", serde_json::to_string_pretty(&table.checked)?),
                )?;
            }
        }
    }
    if failures.is_empty() {
        if check {
            println!("tables --check: {count} tables match the committed results");
        } else {
            println!("wrote {count} tables to docs/results/");
        }
        Ok(())
    } else {
        Err(format!(
            "{}\nrun `cargo xtask tables` and commit docs/results/ if the change is intended",
            failures.join("\n")
        )
        .into())
    }
}

/// Collects human-readable differences between two JSON values.
fn compare(old: &Value, new: &Value, path: &str, diffs: &mut Vec<String>) {
    match (old, new) {
        (Value::Number(a), Value::Number(b)) => {
            let (a, b) = (
                a.as_f64().unwrap_or(f64::NAN),
                b.as_f64().unwrap_or(f64::NAN),
            );
            let ok = (a - b).abs() <= ABS_TOL + REL_TOL * a.abs().max(b.abs());
            if !ok {
                diffs.push(format!("{path}: committed {a}, now {b}"));
            }
        }
        (Value::Array(a), Value::Array(b)) => {
            if a.len() != b.len() {
                diffs.push(format!(
                    "{path}: committed {} entries, now {}",
                    a.len(),
                    b.len()
                ));
            }
            for (i, (x, y)) in a.iter().zip(b).enumerate() {
                compare(x, y, &format!("{path}[{i}]"), diffs);
            }
        }
        (Value::Object(a), Value::Object(b)) => {
            for (k, x) in a {
                match b.get(k) {
                    Some(y) => compare(x, y, &format!("{path}.{k}"), diffs),
                    None => diffs.push(format!("{path}.{k}: missing now")),
                }
            }
            for k in b.keys().filter(|k| !a.contains_key(*k)) {
                diffs.push(format!("{path}.{k}: new"));
            }
        }
        _ if old == new => {}
        _ => diffs.push(format!("{path}: committed {old}, now {new}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn compare_reports_numbers_lengths_and_keys() {
        let old = json!({"a": 1.0, "b": [1, 2], "c": "x"});
        let same = json!({"a": 1.0 + 1e-12, "b": [1, 2], "c": "x"});
        let mut d = Vec::new();
        compare(&old, &same, "", &mut d);
        assert!(d.is_empty(), "{d:?}");
        let new = json!({"a": 1.1, "b": [1], "d": true});
        compare(&old, &new, "", &mut d);
        assert_eq!(d.len(), 4, "{d:?}");
    }
}
