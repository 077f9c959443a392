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

use crate::certificate::Certified;
use crate::error::GeomError;
use crate::ops::answer::Answer;
use crate::ops::beyond_range::exact_beyond_range;
use crate::ops::options::{Options, ProjectOptions};
use crate::ops::shape::{Position, Shape};

// Each entry point answers again with exact rationals when a number of its answer is
// beyond the double range ([`exact_beyond_range`]), so no value is ever lost.

/// Every common point (or line, segment, coincidence) of two or three shapes,
/// certified. Errors name the offending shape as `objects[i]`.
pub fn intersect(shapes: &[Shape], opts: &Options) -> Result<Certified<Answer>, GeomError> {
    exact_beyond_range(opts, |o| intersect::intersect(shapes, o))
}

/// The projections of `point` onto `onto`: every foot of a perpendicular (points where
/// the distance is stationary, docs/FORMAT.md "Projections"), or with `nearest` the nearest
/// point of the closed domain, or with `direction` the hits of the ray (§3.5).
pub fn project(
    point: &Position,
    onto: &Shape,
    how: &ProjectOptions,
) -> Result<Certified<Answer>, GeomError> {
    exact_beyond_range(&how.options, |o| {
        let how = ProjectOptions {
            options: o.clone(),
            ..how.clone()
        };
        project::project(point, onto, &how)
    })
}

/// The side of `point` relative to the closed `shell` (`inside`, `on`, `outside`),
/// with the nearest point of the shell when it is proven (else the certificate's
/// `reason` says why not).
pub fn classify(
    point: &Position,
    shell: &Shape,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    exact_beyond_range(opts, |o| classify::classify(point, shell, o))
}
