//! Plane ∩ quadric at the front door's `intersect` (OPERATIONS.md §13.2): for a plane
//! of the linear kernel and a whole sphere or ellipsoid (whose exact conic is the
//! whole intersection, no domain trims it) the section is decided exactly first. An
//! empty section is the answer (`exact`, complete); otherwise the numeric tracer
//! ([`crate::ops::surface_surface`]) still gives the polylines with their surface
//! parameters, and the exact conic is attached to its curves answer. Trimmed quadrics
//! (cylinders, hyperboloids and paraboloids with a height or range) stay with the
//! tracer, whose answers respect the domain.
//!
//! Two whole quadrics whose quadratic parts are proportional (`A₁ = λA₂`, e.g. two
//! spheres) meet exactly where their *radical plane* `F₁ − λF₂ = 0` meets the first
//! one: a point of both satisfies both equations, and a point of the plane and `F₁ = 0`
//! has `λF₂ = F₁ − (F₁ − λF₂) = 0`. So sphere ∩ sphere is a plane section, decided
//! exactly the same way (issue 16): disjoint spheres are an exact `empty`, equal ones
//! `coincident`, and a circle comes with its exact centre and radius.

use super::{
    conic_answer, exact_plane, is_whole, quadric_of_surface, section_plane_quadric, ConicType,
    ExactPlane,
};
use crate::certificate::Certified;
use crate::error::GeomError;
use crate::ops::answer::Answer;
use crate::ops::rational::QuadricForm;
use crate::ops::shape::Shape;
use rug::Rational;

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
    Some(exact_then_traced(&plane, &form, tracer))
}

/// `Some` answer when both shapes are whole quadrics with exact forms whose quadratic
/// parts are proportional (module documentation); `tracer` as above.
pub(crate) fn intersect_proportional_quadrics(
    a: &Shape,
    b: &Shape,
    tracer: Box<Tracer<'_>>,
) -> Option<Result<Certified<Answer>, GeomError>> {
    let (Shape::Surface(s1), Shape::Surface(s2)) = (a, b) else {
        return None;
    };
    if !(is_whole(s1) && is_whole(s2)) {
        return None;
    }
    let (f1, f2) = (quadric_of_surface(s1)?, quadric_of_surface(s2)?);
    let plane = radical_plane(&f1, &f2)?;
    match plane {
        Radical::Plane(plane) => Some(exact_then_traced(&plane, &f1, tracer)),
        Radical::Same => Some(Ok(Certified::exact(
            Answer::Coincident,
            crate::certificate::Arithmetic::Rational,
            0,
        ))),
        Radical::Disjoint => Some(Ok(Certified::exact(
            Answer::Empty,
            crate::certificate::Arithmetic::Rational,
            0,
        ))),
    }
}

/// What `F₁ − λF₂` is when `A₁ = λA₂`.
enum Radical {
    Plane(ExactPlane),
    /// `F₁ = λF₂`: the same quadric.
    Same,
    /// A non-zero constant: no common point.
    Disjoint,
}

/// `F₁ − λF₂ = 2(b₁ − λb₂)·x + (c₁ − λc₂)` when `A₁ = λA₂` exactly (`None` otherwise).
fn radical_plane(f1: &QuadricForm<3>, f2: &QuadricForm<3>) -> Option<Radical> {
    let (a1, a2) = (f1.matrix(), f2.matrix());
    let (i, j) = (0..3)
        .flat_map(|i| (0..3).map(move |j| (i, j)))
        .find(|&(i, j)| a2[i][j] != 0)?;
    let lambda = Rational::from(&a1[i][j] / &a2[i][j]);
    if lambda == 0 {
        return None;
    }
    let proportional =
        (0..3).all(|i| (0..3).all(|j| a1[i][j] == Rational::from(&lambda * &a2[i][j])));
    if !proportional {
        return None;
    }
    let normal: [Rational; 3] =
        std::array::from_fn(|k| &f1.linear()[k] - Rational::from(&lambda * &f2.linear()[k]));
    let d = (f1.constant() - Rational::from(&lambda * f2.constant())) / 2u32;
    Some(if normal.iter().all(|x| *x == 0) {
        if d == 0 {
            Radical::Same
        } else {
            Radical::Disjoint
        }
    } else {
        Radical::Plane(ExactPlane { normal, d })
    })
}

/// The exact section of `form` by `plane`; when it is not empty, the tracer's curves
/// with the exact conic attached.
fn exact_then_traced(
    plane: &ExactPlane,
    form: &QuadricForm<3>,
    tracer: Box<Tracer<'_>>,
) -> Result<Certified<Answer>, GeomError> {
    let section = section_plane_quadric(plane, form);
    let exact = conic_answer(section);
    let Answer::Curves(curves) = &exact.value else {
        // Empty (a plane cannot lie in a sphere or an ellipsoid).
        return Ok(exact);
    };
    let conic = curves.conic.clone();
    // The tracer's polylines when it traced curves; otherwise (nothing, an error, or
    // points where the exact section is a curve, e.g. a circle of radius 1e-8) the
    // exact section alone is the answer.
    let touching = matches!(curves.conic, Some(ref s) if s.kind == ConicType::Point);
    match tracer() {
        // A touching point: the tracer's proven point (with its surface parameters).
        Some(Ok(c)) if touching && matches!(&c.value, Answer::Points(p) if !p.is_empty()) => Ok(c),
        Some(Ok(mut c)) if matches!(c.value, Answer::Curves(_)) => {
            if let Answer::Curves(traced) = &mut c.value {
                traced.conic = conic;
            }
            Ok(c)
        }
        _ => Ok(exact),
    }
}
