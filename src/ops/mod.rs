//! Operations on shapes (ARCHITECTURE.md layer `ops/`): each operation's float solver
//! and its certificate live together here.

pub mod algebraic;
pub mod certified;
pub mod classify;
pub mod closed_surface;
pub mod float;
pub mod intersect;
pub mod nearest;
pub mod polyhedron;
pub mod project;
pub mod space_curves;
pub mod surface_surface;

pub use classify::{classify_point_polyhedron, ShellPoint, Side};
pub use polyhedron::Polyhedron;
