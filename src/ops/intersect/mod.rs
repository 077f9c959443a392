//! Intersections of curves and surfaces (OPERATIONS.md §5.2, §6.4–6.5, §7.2).

pub mod curve_curve;
pub mod curve_surface;
pub mod three_surfaces;

pub use curve_curve::{intersect_curve2_curve2, intersect_curve_curve_f64, CurveCurvePoint};
pub use curve_surface::{intersect_curve_surface, intersect_curve_surface_f64, CurveSurfacePoint};
pub use three_surfaces::{
    intersect_three_surfaces, intersect_three_surfaces_f64, ThreeSurfacePoint,
};
