//! The coverage of the standing adversarial suites (`crates/<crate>/tests/no_panic.rs`): how
//! many public items and functions each crate has, how many its suite leaves out, and how many
//! properties and proptest cases it runs.

use std::fs;

use bez_core::proptest_support::{missing_from_suite, uncalled_in_crate_suite};
use serde_json::json;

use crate::tables::Table;
use crate::{DynError, project_root};

/// The library crates, in the README's order.
const CRATES: [&str; 6] = [
    "bez-core",
    "bez-subdiv",
    "lambda-bezier",
    "class-a",
    "subdiv-fit",
    "pde-bezier",
];

/// The `suite-coverage` table.
pub(crate) fn tables() -> Result<Vec<Table>, DynError> {
    let mut markdown = String::from(
        "| crate | re-exported items | public functions and methods | not in the suite | \
         tests | proptest cases per run |\n|---|---|---|---|---|---|\n",
    );
    let mut rows = Vec::new();
    for name in CRATES {
        let dir = project_root().join("crates").join(name);
        let lib = fs::read_to_string(dir.join("src").join("lib.rs"))?;
        let Ok(suite) = fs::read_to_string(dir.join("tests").join("no_panic.rs")) else {
            markdown.push_str(&format!("| {name} | | | no suite | | |\n"));
            rows.push(json!({ "crate": name, "suite": false }));
            continue;
        };
        let dir = dir.to_string_lossy();
        let items = missing_from_suite(&lib, "").len();
        let functions = uncalled_in_crate_suite(&dir, "").len();
        let missing =
            missing_from_suite(&lib, &suite).len() + uncalled_in_crate_suite(&dir, &suite).len();
        // `suite_completeness_tests!` expands to two tests.
        let tests = suite.matches("#[test]").count()
            + 2 * suite.matches("suite_completeness_tests!").count();
        let cases = proptest_cases(&suite);
        markdown.push_str(&format!(
            "| {name} | {items} | {functions} | {missing} | {tests} | {cases} |\n"
        ));
        rows.push(json!({
            "crate": name, "suite": true, "items": items, "functions": functions,
            "missing": missing, "tests": tests, "cases": cases,
        }));
    }
    markdown.push_str(
        "\nItems are the names `src/lib.rs` re-exports outside the `paper` feature; functions are \
         the `pub fn` of `src/` outside tests and the `paper` feature (bez-core's test helpers \
         aside). \"Not in the suite\" counts items never named and functions never called by \
         the suite (each suite fails while it is not zero). Cases per run: the sum, over the \
         suite's proptest properties, of the cases each runs (`with_cases`).\n",
    );
    Ok(vec![Table {
        name: "suite-coverage".into(),
        markdown,
        checked: json!(rows),
    }])
}

/// Σ over the `proptest!` blocks of `suite` of (cases per property) × (properties in the block).
fn proptest_cases(suite: &str) -> usize {
    suite
        .split("proptest! {")
        .skip(1)
        .map(|block| {
            let block = block.split("\nproptest! {").next().unwrap_or(block);
            let end = block.find("\n}\n").unwrap_or(block.len());
            let block = &block[..end];
            let cases = block
                .split("with_cases(")
                .nth(1)
                .and_then(|r| r.split(')').next())
                .and_then(|n| n.trim().replace('_', "").parse::<usize>().ok())
                .unwrap_or(256);
            cases * block.matches("#[test]").count()
        })
        .sum()
}
