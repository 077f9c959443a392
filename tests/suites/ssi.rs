//! Test suite `ssi`: answers that are curves — surface ∩ surface, three surfaces,
//! sphere ∩ sphere, sections, contours, views, visibility, fillets. (Split from
//! `surfaces`: one crate of both took seven minutes of CI's build on one core.)
//!
//! One test binary per suite (Cargo.toml `[[test]]`, `autotests = false`): linking a
//! binary per file cost most of CI's build time. Each file stays a module of its own;
//! run one with `cargo test --release --features cgal --test ssi <file>::`.
//! `tests/suites_registry.rs` checks that every file of tests/ is in exactly one suite.

// Support modules (tests/*_support/) are included by each file that uses them, so that
// every file stays a self-contained module; in a suite they are therefore loaded more
// than once, which clippy flags.
#![allow(clippy::duplicate_mod)]

#[path = "../contour.rs"]
mod contour;
#[path = "../fillet.rs"]
mod fillet;
#[path = "../fillet_curved.rs"]
mod fillet_curved;
#[path = "../fillet_variable.rs"]
mod fillet_variable;
#[path = "../intersect_sphere_sphere_exact.rs"]
mod intersect_sphere_sphere_exact;
#[path = "../intersect_surface_surface_certified.rs"]
mod intersect_surface_surface_certified;
#[path = "../intersect_surface_surface_float.rs"]
mod intersect_surface_surface_float;
#[path = "../intersect_three_surfaces.rs"]
mod intersect_three_surfaces;
#[path = "../section.rs"]
mod section;
#[path = "../ssi_families.rs"]
mod ssi_families;
#[path = "../views.rs"]
mod views;
#[path = "../visibility.rs"]
mod visibility;
