//! Plane ∩ quadric at the front door's `intersect` (OPERATIONS.md §13.2): for a plane
//! of the linear kernel and a whole sphere or ellipsoid, or an implicit `quadric` (whose
//! exact conic is the whole intersection, no domain trims it) the section is decided
//! exactly first; the
//! front door (`ops::front::sections`) turns it into the answer. Trimmed quadrics
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
    exact_plane, is_whole, quadric_of_surface, section_plane_quadric, ExactPlane, Section,
};
use crate::certificate::{Arithmetic, Certified};
use crate::ops::answer::Answer;
use crate::ops::rational::QuadricForm;
use crate::ops::shape::Shape;
use rug::Rational;

/// What the exact route decided: the section that is the whole intersection, or the
/// answer itself (equal spheres: `coincident`; concentric ones: `empty`).
pub(crate) enum ExactSection {
    Section(Section),
    Answer(Certified<Answer>),
}

/// The exact section when one shape is a plane and the other a whole sphere or
/// ellipsoid with an exact form; `None` for other pairs.
pub(crate) fn plane_quadric_section(a: &Shape, b: &Shape) -> Option<ExactSection> {
    let (plane, surface) = match (a, b) {
        (Shape::Linear(l), Shape::Surface(s)) | (Shape::Surface(s), Shape::Linear(l))
            if l.type_name() == "plane" =>
        {
            (exact_plane(&Shape::Linear(l.clone()), "plane").ok()?, s)
        }
        (Shape::Linear(l), Shape::Quadric(q)) | (Shape::Quadric(q), Shape::Linear(l))
            if l.type_name() == "plane" =>
        {
            // The implicit quadric is its whole zero set: no domain trims the section.
            let plane = exact_plane(&Shape::Linear(l.clone()), "plane").ok()?;
            let form = QuadricForm::of_implicit(q)?;
            return Some(ExactSection::Section(section_plane_quadric(&plane, &form)));
        }
        _ => return None,
    };
    if !is_whole(surface) {
        return None;
    }
    let form = quadric_of_surface(surface)?;
    Some(ExactSection::Section(section_plane_quadric(&plane, &form)))
}

/// The exact section when both shapes are whole quadrics with exact forms whose
/// quadratic parts are proportional (module documentation); `None` for other pairs.
pub(crate) fn proportional_quadrics_section(a: &Shape, b: &Shape) -> Option<ExactSection> {
    let (Shape::Surface(s1), Shape::Surface(s2)) = (a, b) else {
        return None;
    };
    if !(is_whole(s1) && is_whole(s2)) {
        return None;
    }
    let (f1, f2) = (quadric_of_surface(s1)?, quadric_of_surface(s2)?);
    let exact = |a: Answer| ExactSection::Answer(Certified::exact(a, Arithmetic::Rational, 0));
    Some(match radical_plane(&f1, &f2)? {
        Radical::Plane(plane) => ExactSection::Section(section_plane_quadric(&plane, &f1)),
        Radical::Same => exact(Answer::Coincident),
        Radical::Disjoint => exact(Answer::Empty),
    })
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
