//! geocert — a geometric kernel whose answers come with proofs.
//!
//! Operations are computed fast in f64 and certified by an interval and
//! multiprecision layer (docs/CERTIFICATES.md). Layers, lowest first, each importing
//! only from the ones below it (docs/ARCHITECTURE.md; `tests/layers.rs` checks it, and
//! that no module's submodules import each other in a cycle):
//!
//! * [`certificate`], [`error`] — what is proven, and typed errors;
//! * [`num`] — numbers: the generic [`num::Real`] trait, filters, intervals, MPFR, rationals;
//! * [`geom`] — linear objects and their exact, filtered predicates and constructions;
//! * [`curve`], then [`surface`] — parametric curves and surfaces, implicit surfaces;
//! * [`walk`] — curvature-adaptive stepping over parameter domains;
//! * [`certify`] — Krawczyk, subdivision, precision escalation, singular roots;
//! * [`ops`] — every operation's front door (`ops::intersect`, `ops::project`,
//!   `ops::classify`); beside it `oracle`, the CGAL bridge (feature `cgal`);
//! * [`prelude`] — the names most programs need, in one `use geocert::prelude::*;`;
//! * [`io`] — the JSON case format (docs/FORMAT.md); beside it [`robust`], the
//!   robustness generators and table.

pub mod certificate;
pub mod certify;
pub mod curve;
pub mod error;
pub mod geom;
pub mod io;
pub mod num;
pub mod ops;
#[cfg(feature = "cgal")]
pub mod oracle;
pub mod prelude;
pub mod render;
pub mod robust;
pub mod surface;
pub mod walk;

pub use certificate::{Arithmetic, Certified, Status};

/// The README's library example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
pub use error::GeomError;
