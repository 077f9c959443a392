//! Linear objects and their exact, filtered constructions (ARCHITECTURE.md layer `geom/`;
//! OPERATIONS.md §3.1, §3.3, §5.1, §6.1–6.2, §7.1, §8).
//!
//! Every operation has three entry points side by side: `*_f64` (plain doubles, no
//! proof: the benchmark floor), the certified one on double inputs (exact verdict,
//! correctly rounded coordinates with enclosures, [`crate::Certified`]), and `*_exact`
//! on rational inputs (exact rationals). One decision procedure (`core`), generic over
//! [`crate::num::ring::Field`], serves the plain and the exact paths; the certified path
//! runs the same formulas in double-double with a static error bound first
//! ([`crate::num::filter`]; no allocation) and falls back to the same `core` in exact
//! rings of rising cost: 128-bit and 768-bit dyadic integers ([`crate::num::dyadic128`],
//! [`crate::num::dyadic`]; no allocation), floating-point expansions, rationals.

mod batch;
pub mod data;
mod exact_tier;
pub mod line_line;
pub mod line_plane;
pub mod lines2;
pub mod objects;
pub mod plane_plane;
pub mod project;
mod raw;
pub mod three_planes;

pub use data::{Linear, Linear2};
pub use objects::{Coord, Line, Line2, ParamRange, Plane, Segment, Segment2};
