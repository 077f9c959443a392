//! Test suite `curves`: Curves: derivatives, enclosures, facts and errors, curve ∩
//! line/plane/curve, projections onto curves, exact conic and spline routes, near-
//! tangencies, nearest ties, walking a curve.
//!
//! One test binary per suite (Cargo.toml `[[test]]`, `autotests = false`): linking a
//! binary per file cost most of CI's build time. Each file stays a module of its own;
//! run one with `cargo test --release --features cgal --test curves <file>::`.
//! `tests/suites_registry.rs` checks that every file of tests/ is in exactly one suite.

// Support modules (tests/*_support/) are included by each file that uses them, so that
// every file stays a self-contained module; in a suite they are therefore loaded more
// than once, which clippy flags.
#![allow(clippy::duplicate_mod)]

#[path = "../closed_curves_wrap.rs"]
mod closed_curves_wrap;
#[path = "../conic_arcs_exact.rs"]
mod conic_arcs_exact;
#[path = "../curve_derivatives.rs"]
mod curve_derivatives;
#[path = "../curve_enclosure.rs"]
mod curve_enclosure;
#[path = "../curve_errors.rs"]
mod curve_errors;
#[path = "../curve_facts.rs"]
mod curve_facts;
#[path = "../curve_json.rs"]
mod curve_json;
#[path = "../curve_overlap.rs"]
mod curve_overlap;
#[path = "../curved_forms.rs"]
mod curved_forms;
#[path = "../curved_forms_3d.rs"]
mod curved_forms_3d;
#[path = "../derived_curves.rs"]
mod derived_curves;
#[path = "../derived_curves_json.rs"]
mod derived_curves_json;
#[path = "../helix_implicit_plane.rs"]
mod helix_implicit_plane;
#[path = "../intersect_curve_line2.rs"]
mod intersect_curve_line2;
#[path = "../intersect_curve_plane.rs"]
mod intersect_curve_plane;
#[path = "../intersect_curves.rs"]
mod intersect_curves;
#[path = "../near_tangency_counts.rs"]
mod near_tangency_counts;
#[path = "../near_tangency_curves.rs"]
mod near_tangency_curves;
#[path = "../nearest_ties.rs"]
mod nearest_ties;
#[path = "../nurbs_exact.rs"]
mod nurbs_exact;
#[path = "../polylines_exact.rs"]
mod polylines_exact;
#[path = "../project_conic_exact.rs"]
mod project_conic_exact;
#[path = "../project_curve.rs"]
mod project_curve;
#[path = "../rational_conics.rs"]
mod rational_conics;
#[path = "../rays_carrier.rs"]
mod rays_carrier;
#[path = "../space_conic_feet.rs"]
mod space_conic_feet;
#[path = "../space_conics_exact.rs"]
mod space_conics_exact;
#[path = "../space_pairs_exact.rs"]
mod space_pairs_exact;
#[path = "../spline_conic_exact.rs"]
mod spline_conic_exact;
#[path = "../verify_arc.rs"]
mod verify_arc;
#[path = "../verify_coincident.rs"]
mod verify_coincident;
#[path = "../walk_curve.rs"]
mod walk_curve;
