//! Operations on shapes (ARCHITECTURE.md layer `ops/`): each operation's float solver
//! and its certificate live together here.
//!
//! # The front door
//!
//! [`intersect()`], [`project()`] and [`classify()`] take typed [`Shape`]s and return a
//! [`crate::Certified`] [`Answer`]; they choose the ladder (linear kernel → exact
//! algebraic → numeric certified) and seed the solvers. The command line's JSON
//! reader only translates into these types and back.
//!
//! # Naming scheme
//!
//! Operation functions are named `[operation]_[shape]_[shape]`: `intersect_line_plane`,
//! `intersect_plane_plane`, `intersect_three_planes`, `intersect_curve_surface`,
//! `intersect_curve2_curve2` (plane curves), `project_point_curve`,
//! `project_point_surface`, `classify_point_polyhedron`, `nearest_point_curve`.
//! Suffixes: `_f64` (plain doubles, no proof: the speed floor), `_exact` (exact
//! rationals in and out), `_batch` (many cases per call, same answers). The certified
//! entry point has no suffix.

pub mod algebraic;
pub mod answer;
pub mod beyond_range;
pub mod bisection;
pub mod blend_law;
pub mod certified;
pub mod classify;
pub mod closed_surface;
pub mod fillet;
pub mod float;
mod front;
pub mod intersect;
mod linear;
pub mod nearest;
pub mod options;
pub mod polyhedron;
pub mod project;
pub mod promise;
pub(crate) mod rational;
pub mod section;
pub mod shape;
pub mod space_curves;
pub mod surface_surface;
pub mod verify;
pub mod view;

pub use answer::{
    Answer, BlendAnswer, BlendComponent, BlendGrid, BlendKind, CurveAnswer, CurveEnd, CurveVertex,
    CurvesAnswer, ExactPoint, LineAnswer, ParamLine, Point, RayAnswer, SegmentAnswer,
    SingularPointAnswer,
};
pub use classify::{classify_point_polyhedron, ShellPoint, Side};
pub use fillet::{chamfer, fillet, BlendSpec};
pub use front::{classify, intersect, intersect_bisection_f64, project};
pub use options::{Method, Options, ProjectOptions};
pub use polyhedron::Polyhedron;
pub use section::section;
pub use shape::{Linear, LinearObject, Position, Shape};
pub use view::{contour, visibility, View};
