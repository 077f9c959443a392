//! Test suite `sections`: answers built from curves of known form — sphere ∩ sphere,
//! plane sections, contours, views, visibility, fillets and chamfers. (Split from `ssi`,
//! whose crate was the last of CI's build to finish; these files instantiate little of
//! the library's generic code, so the split costs almost no build time.)
//!
//! One test binary per suite (Cargo.toml `[[test]]`, `autotests = false`): linking a
//! binary per file cost most of CI's build time. Each file stays a module of its own;
//! run one with `cargo test --release --features cgal --test sections <file>::`.
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
#[path = "../section.rs"]
mod section;
#[path = "../views.rs"]
mod views;
#[path = "../visibility.rs"]
mod visibility;
