//! Operations on shapes (ARCHITECTURE.md layer `ops/`): each operation's float solver
//! and its certificate live together here.

pub mod algebraic;
pub mod classify;
pub mod polyhedron;

pub use classify::{classify_point_polyhedron, ShellPoint, Side};
pub use polyhedron::Polyhedron;
