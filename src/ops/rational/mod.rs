//! The exact rational core shared by the exact algebraic operations
//! ([`crate::ops::algebraic`]) and the exact plane sections ([`crate::ops::section`]):
//! rational vectors and interval arithmetic over rationals (`exact`), the implicit
//! quadratic form `xᵀAx + 2bᵀx + c` of a quadric or conic (OPERATIONS.md §1.6–§1.7,
//! `quadric`), Ziv rounding of transcendental parameters (`rounding`), numbers of
//! `Q(√d)` (`surd`), exact planes and their frames (§13.1–§13.2, `plane`) and the exact
//! plane section of a quadric (§13.2, `conic`).
//!
//! It sits below [`crate::ops::answer`]: nothing here builds an answer, so the modules
//! that do (algebraic, section) can both use it without importing each other in a cycle.

pub mod conic;
pub(crate) mod exact;
pub mod plane;
mod quadric;
pub(crate) mod rounding;
pub mod surd;

pub use conic::Section;
pub(crate) use quadric::{diagonal, framed, identity, inv_sq, zero};
pub use quadric::{Conic, QuadricForm};
pub(crate) use rounding::{correctly_rounded, PRECISION_CAP};
