//! Projection of a point onto curves and surfaces (OPERATIONS.md §3): every foot of a
//! perpendicular, and the nearest point.

pub mod curve;
pub mod direction;
pub mod equations;
pub mod pole;
pub mod surface;

pub use curve::{
    foot_equation, project_point_curve, project_point_curve_f64, CurveFeet, CurveFoot,
};
pub use direction::{project_point_surface_along_f64, Ray};
pub use equations::surface_foot_equations;
pub use surface::{
    project_point_surface, project_point_surface_f64, IsoCurve, SurfaceFeet, SurfaceFoot,
};
