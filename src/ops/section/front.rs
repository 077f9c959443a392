//! Plane ∩ quadric at the front door's `intersect` (OPERATIONS.md §13.2): for a plane
//! of the linear kernel and a whole sphere or ellipsoid (whose exact conic is the
//! whole intersection, no domain trims it) the section is decided exactly first. An
//! empty section is the answer (`exact`, complete); otherwise the numeric tracer
//! ([`crate::ops::surface_surface`]) still gives the polylines with their surface
//! parameters, and the exact conic is attached to its curves answer. Trimmed quadrics
//! (cylinders, hyperboloids and paraboloids with a height or range) stay with the
//! tracer, whose answers respect the domain.

use super::{conic_answer, exact_plane, is_whole, quadric_of_surface, section_plane_quadric};
use crate::certificate::Certified;
use crate::error::GeomError;
use crate::ops::answer::Answer;
use crate::ops::shape::Shape;

type Tracer<'a> = dyn FnOnce() -> Option<Result<Certified<Answer>, GeomError>> + 'a;

/// `Some` answer when one shape is a plane and the other a whole sphere or ellipsoid
/// with an exact form; `tracer` gives the numeric answer it refines.
pub(crate) fn intersect_plane_quadric(
    a: &Shape,
    b: &Shape,
    tracer: Box<Tracer<'_>>,
) -> Option<Result<Certified<Answer>, GeomError>> {
    let (plane, surface) = match (a, b) {
        (Shape::Linear(l), Shape::Surface(s)) | (Shape::Surface(s), Shape::Linear(l))
            if l.type_name() == "plane" =>
        {
            (exact_plane(&Shape::Linear(l.clone()), "plane").ok()?, s)
        }
        _ => return None,
    };
    if !is_whole(surface) {
        return None;
    }
    let form = quadric_of_surface(surface)?;
    let section = section_plane_quadric(&plane, &form);
    let exact = conic_answer(section);
    let Answer::Curves(curves) = &exact.value else {
        // Empty (a plane cannot lie in a sphere or an ellipsoid).
        return Some(Ok(exact));
    };
    let conic = curves.conic.clone();
    Some(tracer()?.map(|mut c| {
        if let Answer::Curves(traced) = &mut c.value {
            traced.conic = conic;
        }
        c
    }))
}
