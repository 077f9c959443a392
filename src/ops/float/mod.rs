//! The common float machinery of every iterative operation (OPERATIONS.md §0.4, §12):
//! the tolerances ([`Precision`]), the Newton driver ([`mod@newton`]) and duplicate
//! merging ([`merge_duplicates`]). This is the fast path only: nothing here proves
//! anything; the certificates come from [`crate::certify`]-style interval methods.

pub mod merge;
pub mod newton;
pub mod precision;

pub use merge::merge_duplicates;
pub use newton::{newton, newton_with, Coordinate, NewtonOutcome};
pub use precision::Precision;
