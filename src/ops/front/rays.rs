//! A ray against a bounded curve or surface, for the exact pairs. The exact algebraic
//! solver takes lines with a closed range or none (`ops::algebraic::pairs`: a ray
//! would be answered as its whole carrier), so a ray took the numeric path, where a
//! ray starting on the other object is a root on a domain end it cannot decide
//! (issue 16: rays against curves and surfaces). Past the other shape's certified box
//! no point is common, so the ray is the same question as its piece from the start to
//! a parameter beyond that box: [`cut`] gives that piece, with the ray's own
//! parametrisation (same origin, direction and start), so every answer is the ray's.
//! Against a shape without a box (a `conic2`, an implicit `quadric`) the exact pair is
//! asked for the ray's whole carrier and the answer kept where it lies on the ray
//! ([`carrier`], [`keep_on_ray`]).

use super::seeds::{curve_box, reach, surface_box};
use crate::certificate::{Certified, Status};
use crate::geom::{Line, ParamRange};
use crate::ops::answer::{Answer, Point};
use crate::ops::shape::{Linear, LinearObject, Shape};

/// `ray` as the line on `[start, T]` (`[T, start]` for a ray towards decreasing `t`)
/// when `other` is a curve or surface with a finite certified box, `T` past the box
/// ([`reach`], outward: every `t` beyond it puts a coordinate outside the box); `None`
/// for anything else (not a ray given in doubles, an unbounded or unboxed other).
pub(super) fn cut(ray: &Shape, other: &Shape) -> Option<Shape> {
    let Shape::Linear(Linear::Double(object)) = ray else {
        return None;
    };
    match object {
        LinearObject::Line(l) if l.is_ray() => {
            let bound = match other {
                Shape::Curve(c) => curve_box(c),
                Shape::Surface(s) => surface_box(s),
                _ => return None,
            };
            let (o, d) = (*l.origin(), *l.dir());
            let range = closed(l.param_range()?, reach(&o.into(), &d.into(), &bound)?)?;
            let line = Line::with_range(o, d, Some(range)).ok()?;
            Some(Shape::Linear(Linear::Double(LinearObject::Line(line))))
        }
        LinearObject::Line2(l) if l.is_ray() => {
            let Shape::Curve2(c) = other else {
                return None;
            };
            let (o, d) = (*l.origin(), *l.dir());
            let range = closed(
                l.param_range()?,
                reach(&o.into(), &d.into(), &curve_box(c))?,
            )?;
            let line = Line::with_range(o, d, Some(range)).ok()?;
            Some(Shape::Linear(Linear::Double(LinearObject::Line2(line))))
        }
        _ => None,
    }
}

/// The ray's range closed at the far end of `(a, b)`, the parameters that can meet the
/// box; a ray that does not reach the box keeps only its start.
fn closed(range: &ParamRange<f64>, (a, b): (f64, f64)) -> Option<[f64; 2]> {
    match *range {
        ParamRange::AtLeast(lo) => Some([lo, lo.max(b)]),
        ParamRange::AtMost(hi) => Some([hi.min(a), hi]),
        ParamRange::Closed(_) => None,
    }
}

/// A ray (doubles) against a shape without a certified box — a `conic2` or an implicit
/// `quadric`, unbounded in general: the ray's whole carrier (same origin and direction,
/// so the same parameter) and the ray's range. The exact pairs answer the carrier;
/// [`keep_on_ray`] keeps what lies on the ray. `None` for anything else.
pub(super) fn carrier(ray: &Shape, other: &Shape) -> Option<(Shape, ParamRange<f64>)> {
    if !matches!(other, Shape::Conic2(_) | Shape::Quadric(_)) {
        return None;
    }
    let Shape::Linear(Linear::Double(object)) = ray else {
        return None;
    };
    let line = match object {
        LinearObject::Line(l) if l.is_ray() => {
            LinearObject::Line(Line::with_param_range(*l.origin(), *l.dir(), None).ok()?)
        }
        LinearObject::Line2(l) if l.is_ray() => {
            LinearObject::Line2(Line::with_param_range(*l.origin(), *l.dir(), None).ok()?)
        }
        _ => return None,
    };
    let range = match object {
        LinearObject::Line(l) => l.param_range()?.clone(),
        LinearObject::Line2(l) => l.param_range()?.clone(),
        _ => return None,
    };
    Some((Shape::Linear(Linear::Double(line)), range))
}

/// The carrier's answer restricted to the ray of `range` (the ray is object `at`):
/// points whose ray parameter is proven outside the range (its box beyond the finite
/// end) are dropped, the others kept; a point whose box straddles the end (only a
/// parameter that is not correctly rounded can) makes the answer `undecided`. `None`
/// for an answer that is not points (a carrier lying on a degenerate conic is a whole
/// line, not the ray's piece of it).
pub(super) fn keep_on_ray(
    mut r: Certified<Answer>,
    at: usize,
    range: &ParamRange<f64>,
) -> Option<Certified<Answer>> {
    let points = match &mut r.value {
        Answer::Points(points) => points,
        Answer::Empty => return Some(r),
        _ => return None,
    };
    // 1: on the ray, 0: unresolved, −1: off it.
    let side = |q: &Point| -> i8 {
        let Some([lo, hi]) = q
            .param_box
            .as_ref()
            .and_then(|b| b.get(at)?.first().copied())
        else {
            return 0;
        };
        match *range {
            ParamRange::AtLeast(s) if lo >= s => 1,
            ParamRange::AtLeast(s) if hi < s => -1,
            ParamRange::AtMost(s) if hi <= s => 1,
            ParamRange::AtMost(s) if lo > s => -1,
            ParamRange::Closed([a, b]) if lo >= a && hi <= b => 1,
            ParamRange::Closed([a, b]) if hi < a || lo > b => -1,
            _ => 0,
        }
    };
    if points.iter().any(|q| side(q) == 0) {
        r.status = r.status.weakest(Status::Undecided);
        r.complete = false;
        r.reason = Some(
            "a common point's ray parameter is not proven on either side of the ray's start".into(),
        );
    }
    points.retain(|q| side(q) >= 0);
    Some(r)
}
