//! Test suite `linear`: The exact linear kernel, intervals and the CGAL oracle: worked
//! examples, properties, the integer tier, overflow, ITF1788, and the differential tests
//! against CGAL.
//!
//! One test binary per suite (Cargo.toml `[[test]]`, `autotests = false`): linking a
//! binary per file cost most of CI's build time. Each file stays a module of its own;
//! run one with `cargo test --release --features cgal --test linear <file>::`.
//! `tests/suites_registry.rs` checks that every file of tests/ is in exactly one suite.

// Support modules (tests/*_support/) are included by each file that uses them, so that
// every file stays a self-contained module; in a suite they are therefore loaded more
// than once, which clippy flags.
#![allow(clippy::duplicate_mod)]

#[path = "../cgal_gated.rs"]
mod cgal_gated;
#[path = "../diff_case_json.rs"]
mod diff_case_json;
#[path = "../diff_line_line.rs"]
mod diff_line_line;
#[path = "../diff_line_plane.rs"]
mod diff_line_plane;
#[path = "../diff_lines2.rs"]
mod diff_lines2;
#[path = "../diff_plane_plane.rs"]
mod diff_plane_plane;
#[path = "../diff_project.rs"]
mod diff_project;
#[path = "../diff_robustness_table.rs"]
mod diff_robustness_table;
#[path = "../diff_three_planes.rs"]
mod diff_three_planes;
#[path = "../generic_real.rs"]
mod generic_real;
#[path = "../interval_elementary.rs"]
mod interval_elementary;
#[path = "../itf1788.rs"]
mod itf1788;
#[path = "../line_line.rs"]
mod line_line;
#[path = "../linear_bad_input.rs"]
mod linear_bad_input;
#[path = "../linear_batch.rs"]
mod linear_batch;
#[path = "../linear_integer_tier.rs"]
mod linear_integer_tier;
#[path = "../linear_properties.rs"]
mod linear_properties;
#[path = "../linear_worked_examples.rs"]
mod linear_worked_examples;
#[path = "../oracle_kernels.rs"]
mod oracle_kernels;
#[path = "../oracle_smoke.rs"]
mod oracle_smoke;
#[path = "../overflow.rs"]
mod overflow;
#[path = "../space_rays_exact.rs"]
mod space_rays_exact;
