//! Test suite `ssi`: surface ∩ surface (certified and float) and three surfaces. (Split
//! from `surfaces`, and `sections` from it: the crate that instantiates the certified
//! surface ∩ surface was the last one of CI's build to finish.)
//!
//! One test binary per suite (Cargo.toml `[[test]]`, `autotests = false`): linking a
//! binary per file cost most of CI's build time. Each file stays a module of its own;
//! run one with `cargo test --release --features cgal --test ssi <file>::`.
//! `tests/suites_registry.rs` checks that every file of tests/ is in exactly one suite.

// Support modules (tests/*_support/) are included by each file that uses them, so that
// every file stays a self-contained module; in a suite they are therefore loaded more
// than once, which clippy flags.
#![allow(clippy::duplicate_mod)]

#[path = "../intersect_surface_surface_certified.rs"]
mod intersect_surface_surface_certified;
#[path = "../intersect_surface_surface_float.rs"]
mod intersect_surface_surface_float;
#[path = "../intersect_three_surfaces.rs"]
mod intersect_three_surfaces;
#[path = "../ssi_contact_regions.rs"]
mod ssi_contact_regions;
#[path = "../ssi_families.rs"]
mod ssi_families;
