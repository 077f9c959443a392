//! `intersect`: the front door of every intersection (OPERATIONS.md §5–§8), one ladder
//! for all shapes — the linear kernel when every shape is linear, the exact algebraic
//! solver where the pair is algebraic, the numeric certifier otherwise.

use super::intersect_curved;
use crate::certificate::{Arithmetic, Certified};
use crate::curve::AnyCurve3;
use crate::error::GeomError;
use crate::ops::algebraic::coplanar;
use crate::ops::algebraic::curve_on_surface as on_surface;
use crate::ops::algebraic::curve_quadric::curve_quadric;
use crate::ops::algebraic::implicit_quadric;
use crate::ops::algebraic::pairs;
use crate::ops::algebraic::space_conics;
use crate::ops::algebraic::spline_quadric::spline_quadric;
use crate::ops::answer::Answer;
use crate::ops::linear;
use crate::ops::options::{Method, Options};
use crate::ops::shape::{Linear, Shape};

/// Every common point (or line, segment, coincidence) of two or three shapes,
/// certified. Errors name the offending shape as `objects[i]`.
pub fn intersect(shapes: &[Shape], opts: &Options) -> Result<Certified<Answer>, GeomError> {
    if let Some(i) = shapes
        .iter()
        .position(|s| matches!(s, Shape::Polyhedron(_)))
    {
        return Err(GeomError::Unsupported {
            field: format!("objects[{i}].type"),
            reason: "a polyhedron is used as the `shell` of `classify` in this build".into(),
        });
    }
    let linear: Option<Vec<&Linear>> = shapes
        .iter()
        .map(|s| match s {
            Shape::Linear(l) => Some(l),
            _ => None,
        })
        .collect();
    if opts.method == Method::Bisection {
        // The float path of §13.4 instead of the ladder (the exact pairs included).
        return super::bisection::intersect(shapes, opts);
    }
    if let Some(linear) = linear {
        return linear::intersect(&linear, opts);
    }
    if let [a, b] = shapes {
        // A ray against an unbounded conic or quadric: the carrier, kept on the ray.
        for at in 0..2 {
            let (ray, other) = if at == 0 { (a, b) } else { (b, a) };
            let Some((line, range)) = super::rays::carrier(ray, other) else {
                continue;
            };
            let pair = if at == 0 {
                (&line, other)
            } else {
                (other, &line)
            };
            if let Some(Ok(r)) = algebraic(pair.0, pair.1, opts.deadline) {
                if let Some(r) = super::rays::keep_on_ray(r, at, &range) {
                    return Ok(r);
                }
            }
        }
        // A ray against a bounded shape is its piece up to that shape's box (`rays`).
        let cut = [super::rays::cut(a, b), super::rays::cut(b, a)];
        let (ca, cb) = (cut[0].as_ref().unwrap_or(a), cut[1].as_ref().unwrap_or(b));
        if let Some(r) = algebraic(ca, cb, opts.deadline) {
            return r;
        }
        if let Some(r) = identical_curves(a, b) {
            return Ok(r);
        }
        if let Some(r) = super::polylines::pair(a, b, opts) {
            return Ok(r);
        }
        if let Some(r) = crate::ops::algebraic::overlap::curve_overlap(a, b, opts.deadline) {
            return Ok(r);
        }
    }
    match shapes {
        [a, b] => intersect_curved::pair(a, b, opts),
        [a, b, c] => intersect_curved::three(a, b, c, opts),
        other => Err(GeomError::InvalidValue {
            field: "objects".into(),
            reason: format!("intersect takes 2 or 3 objects, found {}", other.len()),
        }),
    }
}

/// Two curves given by the same numbers (compared exactly as doubles): every point of
/// one is a point of the other, so the answer is `coincident`, exactly (CERTIFICATION.md
/// `exact`; docs/FORMAT.md "coincident"). Without this a curve against its copy has a
/// common point in every box and subdivision runs to its budget (issue 20; a copy with
/// collapsed control points, all equal, is one point and coincident the same way).
/// Asked after the exact pairs, which answer identical conics themselves.
fn identical_curves(a: &Shape, b: &Shape) -> Option<Certified<Answer>> {
    let curves = matches!(
        (a, b),
        (Shape::Curve(_), Shape::Curve(_)) | (Shape::Curve2(_), Shape::Curve2(_))
    );
    if !curves || a != b {
        return None;
    }
    let mut r = Certified::exact(Answer::Coincident, Arithmetic::Rational, 53);
    r.reason = Some("the two curves are identical".into());
    Some(r)
}

/// The exact algebraic pairs ([`pairs`]), in either order.
/// Past `deadline` the exact rounding loops give up (the numeric path then reports the
/// time limit) and conic pairs answer `undecided`.
fn algebraic(
    a: &Shape,
    b: &Shape,
    deadline: Option<std::time::Instant>,
) -> Option<Result<Certified<Answer>, GeomError>> {
    match (a, b) {
        (Shape::Linear(l), Shape::Surface(s)) => pairs::line_surface(l, s, true)
            .or_else(|| on_surface::line_on_surface(l, s, true))
            .map(Ok),
        (Shape::Surface(s), Shape::Linear(l)) => pairs::line_surface(l, s, false)
            .or_else(|| on_surface::line_on_surface(l, s, false))
            .map(Ok),
        (Shape::Curve(c), Shape::Surface(s)) => on_surface::curve_on_surface(c, s)
            .or_else(|| curve_quadric(c, s, false))
            .or_else(|| spline_quadric(c, s, false, deadline))
            .map(Ok),
        (Shape::Surface(s), Shape::Curve(c)) => on_surface::curve_on_surface(c, s)
            .or_else(|| curve_quadric(c, s, true))
            .or_else(|| spline_quadric(c, s, true, deadline))
            .map(Ok),
        (Shape::Linear(l), Shape::Quadric(q)) => implicit_quadric::line_quadric(l, q, true).map(Ok),
        (Shape::Quadric(q), Shape::Linear(l)) => {
            implicit_quadric::line_quadric(l, q, false).map(Ok)
        }
        (Shape::Linear(l), Shape::Curve(c)) => pairs::curve_plane(l, c, false, deadline).map(Ok),
        (Shape::Curve(c), Shape::Linear(l)) => pairs::curve_plane(l, c, true, deadline).map(Ok),
        (Shape::Curve(AnyCurve3::Analytic(c)), Shape::Curve(AnyCurve3::Analytic(d))) => {
            space_conics::conic_conic3(c, d, deadline).map(Ok)
        }
        (Shape::Curve(AnyCurve3::Analytic(c)), Shape::Quadric(q)) => {
            coplanar::conic_quadric(c, &implicit_quadric::form(q)?, true, deadline).map(Ok)
        }
        (Shape::Quadric(q), Shape::Curve(AnyCurve3::Analytic(c))) => {
            coplanar::conic_quadric(c, &implicit_quadric::form(q)?, false, deadline).map(Ok)
        }
        _ => pairs::plane_pair(a, b, deadline),
    }
}
