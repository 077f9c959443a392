//! Exact plane sections (OPERATIONS.md §13.1–§13.3; issue 17): the plane through three
//! points with its true-size frame ([`plane`]), plane ∩ quadric classified and
//! described exactly ([`conic`]), and plane sections of closed polyhedra ([`polygon`]).
//!
//! [`section()`] is the front door of the `section` operation: a quadric surface (its
//! whole implicit quadric, [`form`]) or a polyhedron, cut by a plane.

pub mod form;
mod front;
// The exact conic, plane and surd arithmetic live below `answer` (ops::rational),
// which names the section type; they stay reachable here under their old paths.
pub use crate::ops::rational::{conic, plane, surd};
pub mod polygon;

use rug::Rational;

pub use conic::{section_plane_quadric, ConicAxis, ConicLine, ConicType, Section};
pub use form::{is_whole, quadric_of_surface};
pub(crate) use front::{plane_quadric_section, proportional_quadrics_section, ExactSection};
pub use plane::{plane_through_points, plane_through_points_exact, ExactPlane, PlaneFrame};
pub use polygon::{section_plane_polyhedron, SectionLoop};
pub use surd::{Surd, Value};

use crate::certificate::{Arithmetic, Certified, Status};
use crate::error::GeomError;
use crate::num::round::round_rational;
use crate::ops::answer::{Answer, CurveAnswer, CurveEnd, CurveVertex, CurvesAnswer};
use crate::ops::options::Options;
use crate::ops::shape::{LinearObject, Shape};

/// The exact plane of a shape (a plane of the linear kernel); errors name `field`.
pub fn exact_plane(shape: &Shape, field: &str) -> Result<ExactPlane, GeomError> {
    match shape {
        Shape::Linear(l) => match l.exact() {
            LinearObject::Plane(p) => Ok(ExactPlane::from_plane(&p)),
            _ => Err(not_a_plane(field)),
        },
        _ => Err(not_a_plane(field)),
    }
}

fn not_a_plane(field: &str) -> GeomError {
    GeomError::Unsupported {
        field: format!("{field}.type"),
        reason: "a section is cut by a plane".into(),
    }
}

/// `section`: `shape` (`objects[0]`) cut by `plane` (`objects[1]`).
pub fn section(
    shape: &Shape,
    plane: &Shape,
    _opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let cut = exact_plane(plane, "objects[1]")?;
    match shape {
        Shape::Surface(s) => {
            let form = quadric_of_surface(s).ok_or_else(|| GeomError::Unsupported {
                field: "objects[0].type".into(),
                reason: "sections are exact for quadrics with a rational implicit form \
                         (sphere, ellipsoid, hyperboloids, cylinders, paraboloids with a \
                         rational |axis|); a cone given by its half-angle has none"
                    .into(),
            })?;
            Ok(conic_answer(section_plane_quadric(&cut, &form)))
        }
        Shape::Polyhedron(p) => Ok(polygon_answer(&cut, &section_plane_polyhedron(&cut, p))),
        _ => Err(GeomError::Unsupported {
            field: "objects[0].type".into(),
            reason: "`section` cuts a quadric surface or a polyhedron".into(),
        }),
    }
}

/// Every value a section reports.
fn values(s: &Section) -> Vec<&Value> {
    let mut v: Vec<&Value> = vec![];
    for a in &s.axes {
        v.extend(a.dir.iter());
        v.push(&a.length);
    }
    for l in &s.lines {
        v.extend(l.point.iter().chain(l.dir.iter()));
    }
    if let Some(c) = &s.center_uv {
        v.extend(c.iter());
    }
    v
}

fn bits(q: &Rational) -> u32 {
    q.numer().significant_bits() + q.denom().significant_bits()
}

/// The answer of plane ∩ quadric: kind `empty`, `coincident` (the plane lies in the
/// quadric) or `curves` with the exact conic; status `exact` when every reported
/// number is exact or correctly rounded, else `verified` (enclosed).
pub fn conic_answer(s: Section) -> Certified<Answer> {
    let width = s
        .form
        .matrix()
        .iter()
        .flatten()
        .chain(s.form.linear())
        .chain(std::iter::once(s.form.constant()))
        .map(bits)
        .max()
        .unwrap_or(0);
    let rounded = values(&s).iter().all(|v| v.rounded);
    let value = match s.kind {
        ConicType::Empty => Answer::Empty,
        ConicType::Plane => Answer::Coincident,
        _ => Answer::Curves(CurvesAnswer {
            conic: Some(s),
            ..CurvesAnswer::default()
        }),
    };
    let mut c = Certified::exact(value, Arithmetic::Rational, width);
    if !rounded {
        c.status = Status::Verified;
        c.reason = Some(
            "a reported length or direction is enclosed but not correctly rounded \
                         (precision cap)"
                .into(),
        );
    }
    c
}

/// The answer of a polyhedron section: one closed polyline per loop (material loops
/// counter-clockwise seen from `+n`, holes clockwise), exact vertices.
pub fn polygon_answer(cut: &ExactPlane, loops: &[SectionLoop]) -> Certified<Answer> {
    let mut width = 0;
    let curves: Vec<CurveAnswer> = loops
        .iter()
        .map(|l| {
            let mut points: Vec<CurveVertex> = l
                .vertices
                .iter()
                .map(|v| {
                    width = width.max(v.iter().map(bits).max().unwrap_or(0));
                    CurveVertex {
                        xyz: v.iter().map(|x| round_rational(x).nearest).collect(),
                        params: vec![],
                        bound: Some(0.0),
                        exact: Some(v.to_vec()),
                    }
                })
                .collect();
            if let Some(first) = points.first().cloned() {
                points.push(first);
            }
            let _ = cut;
            CurveAnswer {
                points,
                closed: true,
                ends: [CurveEnd::Closed; 2],
                distance_bound: Some(0.0),
                status: Status::Exact,
                reason: None,
            }
        })
        .collect();
    let value = if curves.is_empty() {
        Answer::Empty
    } else {
        Answer::Curves(CurvesAnswer {
            curves,
            ..CurvesAnswer::default()
        })
    };
    Certified::exact(value, Arithmetic::Rational, width)
}
