//! The front door: one entry point per operation, taking typed [`Shape`]s and
//! returning a [`Certified`] [`Answer`]. Inside each, one ladder decided here —
//! the linear kernel, then the exact algebraic solver, then the numeric certifier —
//! and the seeding of the numeric path (walks, clipping of unbounded lines), so
//! callers never pass raw seeds.
//!
//! [`Shape`]: crate::ops::Shape
//! [`Certified`]: crate::Certified
//! [`Answer`]: crate::ops::Answer

mod classify;
mod intersect;
mod intersect_curved;
mod intersect_surfaces;
mod points;
mod project;
mod project_curved;
mod seeds;

pub use classify::classify;
pub use intersect::intersect;
pub use project::project;
