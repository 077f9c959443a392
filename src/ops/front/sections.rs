//! Plane ∩ whole sphere or ellipsoid, and two whole quadrics with proportional quadratic
//! parts (two spheres), at the front door (OPERATIONS.md §13.2; issue 16): the exact
//! section ([`crate::ops::section::plane_quadric_section`],
//! [`crate::ops::section::proportional_quadrics_section`]) is the whole intersection,
//! so it decides the answer and its completeness:
//!
//! - empty, coincident: the exact answer;
//! - a touching point: the exact point with both shapes' parameters
//!   ([`crate::ops::algebraic::section_answer::touching_point`]), `exact` where they
//!   round correctly;
//! - a circle or an ellipse: the exact conic with a polyline sampled on it, every
//!   vertex proven within the curve's distance bound and carrying both shapes'
//!   parameters — never `undecided`, and no tracing (the numeric tracer of
//!   [`super::intersect_surfaces`] would only re-derive, slower and with a chance of
//!   failing near closure, a curve that is known exactly).

use crate::certificate::Certified;
use crate::error::GeomError;
use crate::ops::algebraic::section_answer::{
    sampled_answer, section_point, touching_point, ParamSource,
};
use crate::ops::answer::Answer;
use crate::ops::options::Options;
use crate::ops::section::{
    conic_answer, plane_quadric_section, proportional_quadrics_section, ExactSection,
};
use crate::ops::shape::Shape;

/// `Some` answer for the pairs of the module doc; `None` for other pairs.
pub(crate) fn pair(
    a: &Shape,
    b: &Shape,
    opts: &Options,
) -> Option<Result<Certified<Answer>, GeomError>> {
    let section =
        match plane_quadric_section(a, b).or_else(|| proportional_quadrics_section(a, b))? {
            ExactSection::Answer(c) => return Some(Ok(c)),
            ExactSection::Section(s) => s,
        };
    let shapes = [ParamSource::of(a), ParamSource::of(b)];
    let exact = conic_answer(section.clone());
    if !matches!(exact.value, Answer::Curves(_)) {
        return Some(Ok(exact)); // empty
    }
    if let Some(p) = section_point(&section) {
        return Some(Ok(touching_point(&p, &shapes, exact.bits)));
    }
    Some(Ok(sampled_answer(
        &exact,
        &section,
        &shapes,
        opts.chord_tolerance,
    )
    .unwrap_or(exact)))
}
