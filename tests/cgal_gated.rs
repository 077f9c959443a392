//! The differential tests against CGAL and the oracle's own tests compile only with
//! `--features cgal` (they link the C++ oracle). A plain `cargo test` would run
//! none of them without a word: this test names them, says how to run them, and
//! keeps its list equal to the files that are actually gated (a newly gated file must
//! be added here, so it is never skipped silently).

/// The test files whose whole crate is `#![cfg(feature = "cgal")]`.
const GATED: [&str; 8] = [
    "diff_line_line.rs",
    "diff_line_plane.rs",
    "diff_lines2.rs",
    "diff_plane_plane.rs",
    "diff_project.rs",
    "diff_three_planes.rs",
    "oracle_kernels.rs",
    "oracle_smoke.rs",
];

fn gated_on_disk() -> Vec<String> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let mut found: Vec<String> = std::fs::read_dir(&dir)
        .expect("tests/ is readable")
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .filter(|p| {
            std::fs::read_to_string(p)
                .map(|t| t.lines().any(|l| l.trim() == "#![cfg(feature = \"cgal\")]"))
                .unwrap_or(false)
        })
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    found.sort();
    found
}

#[test]
fn the_list_of_cgal_gated_test_files_is_complete() {
    assert_eq!(gated_on_disk(), GATED.to_vec());
}

#[cfg(not(feature = "cgal"))]
#[test]
fn differential_tests_against_cgal_did_not_run_build_with_features_cgal() {
    eprintln!(
        "NOTE: {} differential/oracle test files were not compiled: {}. \
         Run `cargo test --release --features cgal` (scripts/test.sh does).",
        GATED.len(),
        GATED.join(", ")
    );
}

#[cfg(feature = "cgal")]
#[test]
fn differential_tests_against_cgal_are_compiled_in() {
    eprintln!("{} CGAL-gated test files compiled in", GATED.len());
}
