//! A ray against a bounded curve or surface, for the exact pairs. The exact algebraic
//! solver takes lines with a closed range or none (`ops::algebraic::pairs`: a ray
//! would be answered as its whole carrier), so a ray took the numeric path, where a
//! ray starting on the other object is a root on a domain end it cannot decide
//! (issue 16: rays against curves and surfaces). Past the other shape's certified box
//! no point is common, so the ray is the same question as its piece from the start to
//! a parameter beyond that box: [`cut`] gives that piece, with the ray's own
//! parametrisation (same origin, direction and start), so every answer is the ray's.

use super::seeds::{curve_box, reach, surface_box};
use crate::geom::{Line, ParamRange};
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
