//! The test files are grouped into a few test binaries (`tests/suites/*.rs`, listed as
//! `[[test]]` in Cargo.toml with `autotests = false`). With automatic discovery off, a
//! new file in tests/ that no suite includes would never run, without a word: this test
//! keeps the grouping complete — every `tests/*.rs` is in exactly one suite (or is a
//! `[[test]]` of its own), and every suite is a `[[test]]`.

use std::collections::BTreeMap;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn rs_files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("directory is readable")
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "rs"))
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    names.sort();
    names
}

/// The `path = "…"` values of the `[[test]]` tables of Cargo.toml.
fn test_targets() -> Vec<String> {
    let toml = std::fs::read_to_string(root().join("Cargo.toml")).expect("Cargo.toml");
    assert!(
        toml.lines().any(|l| l.trim() == "autotests = false"),
        "Cargo.toml must set autotests = false (the suites include the files)"
    );
    let mut paths = Vec::new();
    let mut in_test = false;
    for line in toml.lines().map(str::trim) {
        if line.starts_with('[') {
            in_test = line == "[[test]]";
        } else if in_test {
            if let Some(rest) = line.strip_prefix("path") {
                let value = rest.trim_start().trim_start_matches('=').trim();
                paths.push(value.trim_matches('"').to_string());
            }
        }
    }
    paths
}

#[test]
fn every_test_file_is_in_exactly_one_suite() {
    let targets = test_targets();
    let mut owners: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for suite in rs_files(&root().join("tests/suites")) {
        let path = format!("tests/suites/{suite}");
        assert!(
            targets.contains(&path),
            "{path} is not a [[test]] in Cargo.toml"
        );
        let text = std::fs::read_to_string(root().join(&path)).expect("suite readable");
        for line in text.lines().map(str::trim) {
            if let Some(rest) = line.strip_prefix("#[path = \"../") {
                let file = rest.trim_end_matches("\"]").to_string();
                owners.entry(file).or_default().push(suite.clone());
            }
        }
    }
    for file in rs_files(&root().join("tests")) {
        let own_target = targets.contains(&format!("tests/{file}"));
        let suites = owners.remove(&file).unwrap_or_default();
        assert_eq!(
            suites.len() + usize::from(own_target),
            1,
            "tests/{file} must be in exactly one suite of tests/suites/ (or be its own [[test]]); it is in {suites:?}"
        );
    }
    assert!(
        owners.is_empty(),
        "suites include files that do not exist: {owners:?}"
    );
}
