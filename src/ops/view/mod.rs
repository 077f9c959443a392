//! Views of a shape (OPERATIONS.md §13.5–§13.6): projection maps ([`View`]), the
//! certified contour (outline) of a parametric surface ([`contour_surface`]) and the
//! visibility of a surface point ([`visibility_point_surface`]).
//!
//! * Projection maps (§13.6): frontal, horizontal, profile, isometric, dimetric,
//!   oblique (cabinet/cavalier), the general parallel view along a direction and the
//!   central view from an eye point; every map is one formula over [`crate::num::Real`].
//! * Contour (§13.5): `I(u, v) = n·d = 0` (parallel) or `n·(E − s) = 0` (central), a
//!   curve in the parameter domain. The float scan finds its components; each is
//!   covered by a chain of boxes in each of which it is proven to be one smooth arc
//!   (an interval gradient of full rank, the parametric Krawczyk test of
//!   [`crate::certify::graph`]); `complete` is proven by solving the contour on the
//!   domain's faces and seams and the height-critical system over the domain with the
//!   complete solver. Self-crossings of the contour (`∇I = 0`) are not resolved: the
//!   answer is then `undecided` with the place named.
//! * Visibility (§13.5): a point is hidden when the ray from it toward the viewer
//!   meets the surface (or another given surface) again, proven by the complete solver
//!   on `G(P + t·w) = 0` in `t` for surfaces with an implicit form (hits checked on the
//!   patch) and on the ray–surface system otherwise; `on_contour` when a contour point
//!   is proven within a small parameter box around it.

mod chain;
mod complete;
mod contour;
mod front;
mod projection;
mod ray;
mod system;
mod trace;
mod types;
mod visibility;

pub use contour::{
    contour_surface, contour_surface_of, Contour, ContourBound, ContourCurve, ContourEnd,
    ContourOptions, ContourVertex,
};
pub use front::{contour, curves_answer, visibility, visibility_answer};
pub use projection::{picture_axes, Rays, View};
pub(crate) use ray::covers;
pub use system::ContourFn;
pub use visibility::{
    visibility_point_surface, visibility_point_surface_of, Visibility, VisibilityAnswer,
};
