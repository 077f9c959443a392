//! Intersections decided exactly where the problem is algebraic (issue 6;
//! docs/CERTIFICATES.md level `exact`): a line against a quadric or a torus (OPERATIONS.md
//! §5.2 with §1.6–§1.7), a line against a conic and conic against conic in the plane
//! (§6.3–§6.4), through polynomials of degree ≤ 4 with rational coefficients solved by
//! [`crate::certify::univariate`].
//!
//! Inputs are doubles taken as exact rationals; the surfaces are given by their exact
//! implicit data ([`QuadricForm`], [`TorusData`]), whose constructors return `None`
//! where a primitive's implicit form is not rational (then the caller certifies
//! numerically). Every result is `Certified` with `status: exact`,
//! `complete: true`, `arithmetic: rational`, `bits` the largest coefficient bit length:
//! points carry their correctly rounded coordinates (with enclosures), the exact or
//! isolated parameters, and their intersection multiplicity, so a tangency is a proven
//! double root and two close crossings are two proven simple ones. Magnitudes from
//! 1e-300 to 1e300 are handled exactly (nothing overflows in rationals).

mod apex_line;
mod bezier_conic2;
mod bezier_line2;
mod bezier_plane;
mod bivariate;
mod conic;
mod conic_arcs;
mod conic_conic;
mod conic_plane;
pub(crate) mod coplanar;
pub(crate) mod curve_on_surface;
pub(crate) mod curve_quadric;
pub(crate) mod exact_line;
mod exact_spline;
mod foot2;
mod foot3;
pub(crate) mod implicit_quadric;
mod kquad;
mod line;
mod line_conic3;
mod line_surface;
mod on_surface;
pub(crate) mod overlap;
pub(crate) mod pairs;
mod params;
pub(crate) mod quadric_feet;
pub(crate) mod section_answer;
pub(crate) mod space_conics;
pub(crate) mod spline_quadric;
pub(crate) mod three_spheres;

pub use crate::ops::rational::{Conic, QuadricForm};
pub use conic_conic::{intersect_conic_conic, intersect_conic_conic_until, ConicCut, ConicHit};
pub(crate) use foot2::{every_point_a_foot, project_point_conic2};
pub(crate) use foot3::project_point_conic3;
pub use line::{LineCut, LineHit};
pub use line_surface::{
    intersect_line_conic, intersect_line_quadric, intersect_line_quadric_exact,
    intersect_line_torus, intersect_line_torus_exact, TorusData,
};
