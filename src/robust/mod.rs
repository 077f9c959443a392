//! Robustness: seeded case generators for the linear constructions and the
//! robustness table that runs them through plain f64, CGAL's Epick (feature `cgal`),
//! geocert's float-only filter and geocert certified, against the exact truth
//! (`geocert bench robustness`). The differential tests (tests/diff_*.rs) draw their
//! cases from the same generators and compare geocert with CGAL's Epeck.
//!
//! Everything here is deterministic from a seed: the same seed gives the same cases
//! and the same table.

pub mod answer;
pub mod case;
pub mod curved;
pub mod gen;
pub mod kettner;
pub mod line_line;
pub mod methods;
pub mod plot;
pub mod report;
pub mod table;

#[cfg(test)]
mod lane_tests;

/// The generators' random stream (it lives in `num`, below the layers whose tests use it).
pub use crate::num::rng;
pub use case::Case;
pub use gen::{case, Construction, Generator};
pub use report::Report;
pub use table::{robustness_table, Table};
