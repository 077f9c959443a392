//! The front door: one entry point per operation, taking typed [`Shape`]s and
//! returning a [`Certified`] [`Answer`]. Inside each, one ladder decided here —
//! the linear kernel, then the exact algebraic solver, then the numeric certifier —
//! and the seeding of the numeric path (walks, clipping of unbounded lines), so
//! callers never pass raw seeds.
//!
//! [`Shape`]: crate::ops::Shape
//! [`Certified`]: crate::Certified
//! [`Answer`]: crate::ops::Answer

mod bisection;
mod classify;
mod intersect;
mod intersect_curved;
mod intersect_surfaces;
mod points;
mod poles;
mod polylines;
mod project;
mod project_curved;
mod rays;
mod sections;
mod seeds;

use crate::certificate::Certified;
use crate::error::GeomError;
use crate::ops::answer::Answer;
use crate::ops::beyond_range::exact_beyond_range;
use crate::ops::options::{Options, ProjectOptions};
use crate::ops::promise;
use crate::ops::shape::{Position, Shape};
pub use bisection::float_roots as intersect_bisection_f64;

// Each entry point answers again with exact rationals when a number of its answer is
// beyond the double range ([`exact_beyond_range`]), so no value is ever lost, and
// enforces the promise on every reported number ([`promise::keep`]: no NaN, every
// estimate in its box, every parameter box in its object's domain).

/// Every common point (or line, segment, coincidence) of two or three shapes,
/// certified. Errors name the offending shape as `objects[i]`.
///
/// ```
/// use geocert::prelude::*;
///
/// // Two unit spheres whose centres are 1 apart meet in a circle of radius √3/2,
/// // in the plane x = 1/2 (decided exactly through the radical plane).
/// let a = Sphere::new([0.0, 0.0, 0.0], 1.0, None, None)?;
/// let b = Sphere::new([1.0, 0.0, 0.0], 1.0, None, None)?;
/// let answer = intersect(&[a.into(), b.into()], &Options::default())?;
/// assert_ne!(answer.status, Status::Undecided);
/// let Answer::Curves(curves) = &answer.value else { panic!("{answer:?}") };
/// let circle = curves.conic.as_ref().expect("the exact circle");
/// let centre = circle.center.as_ref().expect("its centre");
/// assert_eq!(centre[0], rug::Rational::from((1, 2)));
/// # Ok::<(), GeomError>(())
/// ```
pub fn intersect(shapes: &[Shape], opts: &Options) -> Result<Certified<Answer>, GeomError> {
    let mut r = exact_beyond_range(opts, |o| intersect::intersect(shapes, o))?;
    let domains: Vec<_> = shapes.iter().map(promise::domains).collect();
    promise::keep(&mut r, &domains);
    Ok(r)
}

/// The projections of `point` onto `onto`: every foot of a perpendicular (points where
/// the distance is stationary, docs/FORMAT.md "Projections"), or with `nearest` the nearest
/// point of the closed domain, or with `direction` the hits of the ray (§3.5).
///
/// ```
/// use geocert::prelude::*;
///
/// // The nearest point of the torus R = 2, r = 1 about z to (3, 0, 1): on the tube's
/// // circle about (2, 0, 0) in the plane y = 0, at distance √2 − 1.
/// let torus = Torus::new([0.0; 3], 2.0, 1.0, [0.0, 0.0, 1.0], None)?;
/// let point = Position::Double(vec![3.0, 0.0, 1.0]);
/// let how = ProjectOptions { nearest: true, ..Default::default() };
/// let answer = project(&point, &torus.into(), &how)?;
/// assert_ne!(answer.status, Status::Undecided);
/// let Answer::Points(feet) = &answer.value else { panic!("{answer:?}") };
/// let d = feet[0].distance.expect("a distance");
/// assert!((d - (2f64.sqrt() - 1.0)).abs() < 1e-15);
/// # Ok::<(), GeomError>(())
/// ```
pub fn project(
    point: &Position,
    onto: &Shape,
    how: &ProjectOptions,
) -> Result<Certified<Answer>, GeomError> {
    let mut r = exact_beyond_range(&how.options, |o| {
        let how = ProjectOptions {
            options: o.clone(),
            ..how.clone()
        };
        project::project(point, onto, &how)
    })?;
    promise::keep(&mut r, &[promise::domains(onto)]);
    Ok(r)
}

/// The side of `point` relative to the closed `shell` (`inside`, `on`, `outside`),
/// with the nearest point of the shell when it is proven (else the certificate's
/// `reason` says why not).
///
/// ```
/// use geocert::prelude::*;
///
/// let ball = Sphere::new([0.0; 3], 1.0, None, None)?;
/// let inside = classify(&Position::Double(vec![0.5, 0.5, 0.5]), &ball.into(), &Options::default())?;
/// assert_eq!(inside.status, Status::Exact);
/// assert!(matches!(inside.value, Answer::Side(Side::Inside, _)));
/// # Ok::<(), GeomError>(())
/// ```
pub fn classify(
    point: &Position,
    shell: &Shape,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let mut r = exact_beyond_range(opts, |o| classify::classify(point, shell, o))?;
    promise::keep(&mut r, &[promise::domains(shell)]);
    Ok(r)
}
