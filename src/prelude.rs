//! The names most programs need, in one `use geocert::prelude::*;`: the front door
//! (`intersect`, `project`, `classify`, `section`), its options and answers, the
//! certificate, typed errors, and the shapes to build (the linear kernel's lines,
//! segments and planes; analytic and spline curves; quadrics, tori and patches).
//! Every shape converts into an [`ops::Shape`](crate::ops::Shape) with `.into()`.
//!
//! ```
//! use geocert::prelude::*;
//!
//! // The unit sphere and the line x = 0.6, y = 0 (OPERATIONS.md §5.2): two points, exact.
//! let sphere = Sphere::new([0.0; 3], 1.0, None, None)?;
//! let line = Line::new(Vector3::new(0.6, 0.0, -2.0), Vector3::new(0.0, 0.0, 1.0))?;
//! let answer = intersect(&[line.into(), sphere.into()], &Options::default())?;
//! assert_eq!(answer.status, Status::Exact);
//! assert!(answer.complete);
//! let Answer::Points(points) = &answer.value else { panic!("{answer:?}") };
//! let mut z: Vec<f64> = points.iter().map(|p| p.xyz[2]).collect();
//! z.sort_by(f64::total_cmp);
//! assert_eq!(z, [-0.8, 0.8]); // 0.6² + 0.8² = 1: the rounding of ±4/5
//! # Ok::<(), GeomError>(())
//! ```

pub use crate::certificate::{Arithmetic, Certified, Status};
pub use crate::curve::{Analytic, Analytic2, AnyCurve2, AnyCurve3, Bezier, Conic2, Frame};
pub use crate::error::GeomError;
pub use crate::geom::{Line, Line2, Plane, Segment, Segment2};
pub use crate::ops::{
    classify, intersect, project, section, Answer, Options, Point, Position, ProjectOptions, Shape,
    Side,
};
pub use crate::surface::quadrics::{Cone, Cylinder, Ellipsoid, Hyperboloid, Paraboloid, Sphere};
pub use crate::surface::torus::Torus;
pub use crate::surface::{bezier::BezierSurface, nurbs::NurbsSurface, AnySurface};
pub use nalgebra::{Vector2, Vector3};
