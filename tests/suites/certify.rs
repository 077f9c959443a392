//! Test suite `certify`: The certifier and the promise: univariate and system
//! certification, Jacobians, verify, correct rounding, seams and poles, extreme offsets,
//! numeric projection truths, the exact algebraic solver.
//!
//! One test binary per suite (Cargo.toml `[[test]]`, `autotests = false`): linking a
//! binary per file cost most of CI's build time. Each file stays a module of its own;
//! run one with `cargo test --release --features cgal --test certify <file>::`.
//! `tests/suites_registry.rs` checks that every file of tests/ is in exactly one suite.

// Support modules (tests/*_support/) are included by each file that uses them, so that
// every file stays a self-contained module; in a suite they are therefore loaded more
// than once, which clippy flags.
#![allow(clippy::duplicate_mod)]

#[path = "../certify_properties.rs"]
mod certify_properties;
#[path = "../certify_systems.rs"]
mod certify_systems;
#[path = "../certify_univariate.rs"]
mod certify_univariate;
#[path = "../exact_rounding.rs"]
mod exact_rounding;
#[path = "../extreme_offsets.rs"]
mod extreme_offsets;
#[path = "../ops_algebraic.rs"]
mod ops_algebraic;
#[path = "../poles_apexes.rs"]
mod poles_apexes;
#[path = "../project_numeric_truth.rs"]
mod project_numeric_truth;
#[path = "../seams_poles.rs"]
mod seams_poles;
#[path = "../system_jacobians.rs"]
mod system_jacobians;
#[path = "../verify_curved.rs"]
mod verify_curved;
#[path = "../verify_rational.rs"]
mod verify_rational;
