//! Test suite `cli`: The command line and the front door: case reading, solve/verify/run,
//! golden answers, the supported-pairs table, README examples, the result schema, fuzz
//! corpus, time limits, robustness plots, and the module layering.
//!
//! One test binary per suite (Cargo.toml `[[test]]`, `autotests = false`): linking a
//! binary per file cost most of CI's build time. Each file stays a module of its own;
//! run one with `cargo test --release --features cgal --test cli <file>::`.
//! `tests/suites_registry.rs` checks that every file of tests/ is in exactly one suite.

// Support modules (tests/*_support/) are included by each file that uses them, so that
// every file stays a self-contained module; in a suite they are therefore loaded more
// than once, which clippy flags.
#![allow(clippy::duplicate_mod)]

#[path = "../budgets.rs"]
mod budgets;
#[path = "../cli_curved.rs"]
mod cli_curved;
#[path = "../cli_input.rs"]
mod cli_input;
#[path = "../cli_rays.rs"]
mod cli_rays;
#[path = "../cli_run.rs"]
mod cli_run;
#[path = "../cli_solve.rs"]
mod cli_solve;
#[path = "../cli_stream.rs"]
mod cli_stream;
#[path = "../cli_surface_surface.rs"]
mod cli_surface_surface;
#[path = "../cli_verify.rs"]
mod cli_verify;
#[path = "../front_door.rs"]
mod front_door;
#[path = "../fuzz_corpus.rs"]
mod fuzz_corpus;
#[path = "../layers.rs"]
mod layers;
#[path = "../never_hang.rs"]
mod never_hang;
#[path = "../readme_examples.rs"]
mod readme_examples;
#[path = "../render.rs"]
mod render;
#[path = "../result_schema.rs"]
mod result_schema;
#[path = "../robustness_curved.rs"]
mod robustness_curved;
#[path = "../robustness_plots.rs"]
mod robustness_plots;
#[path = "../suites_registry.rs"]
mod suites_registry;
#[path = "../supported_pairs.rs"]
mod supported_pairs;
