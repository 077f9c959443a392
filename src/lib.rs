//! geocert — a geometric kernel whose answers come with proofs.
//!
//! Operations are computed fast in f64 and certified by an interval and
//! multiprecision layer (docs/CERTIFICATES.md). Layers, each depending only on
//! the ones above it (ARCHITECTURE.md):
//!
//! * [`num`] — numbers: the generic [`num::Real`] trait, filters, intervals, MPFR, rationals;
//! * [`geom`] — linear objects and their exact, filtered predicates and constructions;
//! * [`curve`], [`surface`] — parametric curves and surfaces, implicit surfaces;
//! * [`certify`] — Krawczyk, subdivision, precision escalation, singular roots;
//! * [`io`] — the JSON case format (docs/FORMAT.md).

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
pub mod robust;
pub mod surface;
pub mod walk;

pub use certificate::{Arithmetic, Certified, Status};
pub use error::GeomError;
