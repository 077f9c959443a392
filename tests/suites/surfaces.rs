//! Test suite `surfaces`: Surfaces: derivatives, enclosures, facts and errors, motion
//! surfaces, curve ∩ surface, classification, projections onto surfaces, walking a surface.
//!
//! One test binary per suite (Cargo.toml `[[test]]`, `autotests = false`): linking a
//! binary per file cost most of CI's build time. Each file stays a module of its own;
//! run one with `cargo test --release --features cgal --test surfaces <file>::`.
//! `tests/suites_registry.rs` checks that every file of tests/ is in exactly one suite.

// Support modules (tests/*_support/) are included by each file that uses them, so that
// every file stays a self-contained module; in a suite they are therefore loaded more
// than once, which clippy flags.
#![allow(clippy::duplicate_mod)]

#[path = "../circle_near_surface.rs"]
mod circle_near_surface;
#[path = "../classify_closed_surface.rs"]
mod classify_closed_surface;
#[path = "../classify_polyhedron.rs"]
mod classify_polyhedron;
#[path = "../composite_surface.rs"]
mod composite_surface;
#[path = "../curve_on_surface_exact.rs"]
mod curve_on_surface_exact;
#[path = "../intersect_bisection.rs"]
mod intersect_bisection;
#[path = "../intersect_curve_surface.rs"]
mod intersect_curve_surface;
#[path = "../motion_surfaces.rs"]
mod motion_surfaces;
#[path = "../poles_front_door.rs"]
mod poles_front_door;
#[path = "../poles_repole.rs"]
mod poles_repole;
#[path = "../project_surface.rs"]
mod project_surface;
#[path = "../rational_patches.rs"]
mod rational_patches;
#[path = "../repole_pole_roots.rs"]
mod repole_pole_roots;
#[path = "../surface_derivatives.rs"]
mod surface_derivatives;
#[path = "../surface_enclosure.rs"]
mod surface_enclosure;
#[path = "../surface_errors.rs"]
mod surface_errors;
#[path = "../surface_facts.rs"]
mod surface_facts;
#[path = "../surface_json.rs"]
mod surface_json;
#[path = "../walk_surface.rs"]
mod walk_surface;
