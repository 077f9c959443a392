//! Results of the linear kernels → [`Answer`]s: each kind of result is written once,
//! for both kernels (their numbers are [`Q`]s).

use nalgebra::Vector3;
use rug::Rational;

use super::kernel::{Len, Q};
use crate::certificate::Certified;
use crate::geom::line_line::{LineLine, LineLineEmpty};
use crate::geom::line_plane::{LinePlane, LinePlanePoint};
use crate::geom::lines2::{Empty2, Intersection2};
use crate::geom::plane_plane::{ParamLine as KernelParamLine, PlaneLine, PlanePlane};
use crate::geom::project::{LineFoot, LineProjection, PlaneProjection};
use crate::geom::three_planes::ThreePlanes;
use crate::geom::{Coord, Linear, Linear2};
use crate::ops::answer::{
    Answer, ExactPoint, LineAnswer, ParamLine, Point, RayAnswer, SegmentAnswer,
};
use crate::ops::classify::ShellPoint;

/// The parameters of a point on each input shape (input order; `None`: the shape has
/// no parameters, as an implicit plane).
type Params<'a> = Vec<Option<&'a [Q]>>;

/// A point of the linear kernels.
pub(crate) fn point(xyz: &[Q], params: Params<'_>) -> Point {
    let exact = |v: &[Q]| v.iter().filter_map(|q| q.exact.clone()).collect::<Vec<_>>();
    let has_exact = xyz.iter().any(|q| q.exact.is_some());
    Point {
        xyz: xyz.iter().map(|q| q.r.nearest).collect(),
        xyz_box: xyz.iter().map(Q::bounds).collect(),
        params: params
            .iter()
            .map(|p| p.map_or(vec![], |p| p.iter().map(|q| q.r.nearest).collect()))
            .collect(),
        param_box: Some(
            params
                .iter()
                .map(|p| p.map_or(vec![], |p| p.iter().map(Q::bounds).collect()))
                .collect(),
        ),
        multiplicity: 1,
        tangent: false,
        exact: has_exact.then(|| ExactPoint {
            xyz: exact(xyz),
            params: params.iter().map(|p| p.map_or(vec![], exact)).collect(),
            distance_squared: None,
        }),
        ..Point::default()
    }
}

/// An empty answer with the reason the kernel found (`parallel`, ...).
fn empty<T>(c: &Certified<T>, reason: &str) -> Certified<Answer> {
    let mut out = c.clone_with(Answer::Empty);
    out.reason = Some(reason.to_string());
    out
}

/// Line ∩ plane; `line_first` says which of the two inputs is the line. A line lying
/// in the plane is the line itself (kind `line`), a ray its start and direction (kind
/// `ray`), a segment or a ranged line its end points (kind `segment`), with their
/// parameters on the line.
pub(crate) fn line_plane<T: Coord>(
    c: Certified<LinePlane<Q>>,
    l: Linear<'_, T>,
    line_first: bool,
    keep: bool,
) -> Certified<Answer> {
    match &c.value {
        LinePlane::Point(LinePlanePoint { point: p, t, uv }) => {
            let t = Some(std::slice::from_ref(t));
            let uv = uv.as_ref().map(|v| v.as_slice());
            let params = if line_first { vec![t, uv] } else { vec![uv, t] };
            c.clone_with(Answer::Points(vec![point(p.as_slice(), params)]))
        }
        LinePlane::Parallel => empty(&c, "parallel"),
        LinePlane::OutsideDomain(_) => empty(&c, "outside_domain"),
        LinePlane::Contained => c.clone_with(contained(l, line_first, keep)),
    }
}

/// The carrier `o + t·d` of a line, ray or segment in rationals, with the ends of its
/// domain (`None`: infinite).
struct ExactCarrier {
    o: Vector3<Rational>,
    d: Vector3<Rational>,
    ends: [Option<Rational>; 2],
}

fn exact_carrier<T: Coord>(l: Linear<'_, T>) -> ExactCarrier {
    match l {
        Linear::Line(line) => {
            let (lo, hi) = line.bounds();
            ExactCarrier {
                o: line.origin().map(|x| x.to_rational()),
                d: line.dir().map(|x| x.to_rational()),
                ends: [lo.map(Coord::to_rational), hi.map(Coord::to_rational)],
            }
        }
        Linear::Segment(s) => {
            let a = s.a().map(|x| x.to_rational());
            ExactCarrier {
                d: s.b().map(|x| x.to_rational()) - &a,
                o: a,
                ends: [Some(Rational::from(0)), Some(Rational::from(1))],
            }
        }
    }
}

/// The inputs' slots of a one-parameter shape's value (`line_first`: it is the first
/// of the two inputs, the other has no parameter to report).
fn slots<X>(mine: X, line_first: bool) -> Vec<Option<X>> {
    if line_first {
        vec![Some(mine), None]
    } else {
        vec![None, Some(mine)]
    }
}

/// A ray of an answer from its start, along `d` or (`forward` false) `−d`, with the
/// inputs' parameter directions.
fn ray(
    start: Point,
    d: &Vector3<Rational>,
    forward: bool,
    increasing: Vec<Option<bool>>,
    keep: bool,
) -> Answer {
    let dir: Vec<Rational> = d
        .iter()
        .map(|x| {
            if forward {
                x.clone()
            } else {
                Rational::from(-x)
            }
        })
        .collect();
    Answer::Ray(RayAnswer {
        start,
        dir: dir
            .iter()
            .map(|x| Q::rational(x, false).r.nearest)
            .collect(),
        increasing,
        exact_dir: keep.then_some(dir),
    })
}

/// A line, ray or segment lying in the plane (see [`line_plane`]).
fn contained<T: Coord>(l: Linear<'_, T>, line_first: bool, keep: bool) -> Answer {
    let q = |x: &Rational| Q::rational(x, keep);
    let ExactCarrier { o, d, ends } = exact_carrier(l);
    let end = |t: &Rational| {
        let xyz: Vec<Q> = (0..3)
            .map(|i| Q::rational(&(o[i].clone() + d[i].clone() * t), keep))
            .collect();
        let t = [Q::rational(t, keep)];
        let params = slots(&t[..], line_first);
        point(&xyz, params)
    };
    match ends {
        [None, None] => Answer::Line(LineAnswer {
            point: o.iter().map(|x| q(x).r.nearest).collect(),
            dir: d.iter().map(|x| q(x).r.nearest).collect(),
            params: slots(
                ParamLine {
                    origin: vec![0.0],
                    dir: vec![1.0],
                },
                line_first,
            ),
            exact: None,
        }),
        [Some(lo), None] => ray(end(&lo), &d, true, slots(true, line_first), keep),
        [None, Some(hi)] => ray(end(&hi), &d, false, slots(false, line_first), keep),
        [Some(lo), Some(hi)] => Answer::Segment(SegmentAnswer {
            a: end(&lo),
            b: end(&hi),
        }),
    }
}

fn param_line(p: &Option<KernelParamLine<Q>>) -> Option<ParamLine> {
    p.as_ref().map(|p| ParamLine {
        origin: p.origin.iter().map(|q| q.r.nearest).collect(),
        dir: p.dir.iter().map(|q| q.r.nearest).collect(),
    })
}

fn line(l: &PlaneLine<Q>, params: Vec<Option<ParamLine>>) -> LineAnswer {
    let exact = |v: &[Q]| v.iter().filter_map(|q| q.exact.clone()).collect::<Vec<_>>();
    LineAnswer {
        point: l.point.iter().map(|q| q.r.nearest).collect(),
        dir: l.dir.iter().map(|q| q.r.nearest).collect(),
        params,
        exact: l.point[0]
            .exact
            .is_some()
            .then(|| (exact(l.point.as_slice()), exact(l.dir.as_slice()))),
    }
}

/// Plane ∩ plane.
pub(crate) fn plane_plane(c: Certified<PlanePlane<Q>>) -> Certified<Answer> {
    match &c.value {
        PlanePlane::Line(l) => c.clone_with(Answer::Line(line(
            l,
            vec![param_line(&l.on_a), param_line(&l.on_b)],
        ))),
        PlanePlane::Parallel => empty(&c, "parallel"),
        PlanePlane::Coincident => c.clone_with(Answer::Coincident),
    }
}

/// Three planes.
pub(crate) fn three_planes(c: Certified<ThreePlanes<Q>>) -> Certified<Answer> {
    match &c.value {
        ThreePlanes::Point { point: p, params } => {
            let ps = params
                .iter()
                .map(|p| p.as_ref().map(|v| v.as_slice()))
                .collect();
            c.clone_with(Answer::Points(vec![point(p.as_slice(), ps)]))
        }
        ThreePlanes::Line { line: l, pair } => {
            let mut params = vec![None, None, None];
            params[pair.0] = param_line(&l.on_a);
            params[pair.1] = param_line(&l.on_b);
            c.clone_with(Answer::Line(line(l, params)))
        }
        ThreePlanes::Plane => c.clone_with(Answer::Plane),
        ThreePlanes::Empty => empty(&c, "no_common_point"),
    }
}

fn point2(p: &[Q], t1: &Q, t2: &Q) -> Point {
    point(
        p,
        vec![
            Some(std::slice::from_ref(t1)),
            Some(std::slice::from_ref(t2)),
        ],
    )
}

/// Two 2D lines or segments; coincident lines are reported as the first one.
pub(crate) fn lines2<T: Coord>(
    c: Certified<Intersection2<Q>>,
    first: Linear2<'_, T>,
) -> Certified<Answer> {
    match &c.value {
        Intersection2::Point { point, t1, t2 } => {
            c.clone_with(Answer::Points(vec![point2(point.as_slice(), t1, t2)]))
        }
        Intersection2::Segment {
            a,
            b,
            a_params,
            b_params,
        } => c.clone_with(Answer::Segment(SegmentAnswer {
            a: point2(a.as_slice(), &a_params[0], &a_params[1]),
            b: point2(b.as_slice(), &b_params[0], &b_params[1]),
        })),
        Intersection2::Line => c.clone_with(Answer::Line(carrier2(first))),
        Intersection2::Empty(Empty2::Parallel) => empty(&c, "parallel"),
        Intersection2::Empty(Empty2::CollinearDisjoint) => empty(&c, "collinear_disjoint"),
        Intersection2::Empty(Empty2::OutsideDomain { .. }) => empty(&c, "extensions_meet"),
    }
}

/// Two 3D lines, rays, ranged lines or segments (OPERATIONS.md §6.1–6.2 in space,
/// [`crate::geom::line_line`]): a crossing (`points`), a collinear overlap (`segment`),
/// two identical unbounded lines (`coincident`), or `empty` with the kernel's reason
/// (`parallel`, `skew`, `collinear_disjoint`, `extensions_meet`). A collinear overlap
/// that is a ray (a ray against a collinear line, or two collinear rays going the same
/// way) is kind `ray`: its start, and the direction of the first object (`first`) or
/// its opposite.
pub(crate) fn line_line<T: Coord>(
    c: Certified<LineLine<Q>>,
    first: Linear<'_, T>,
    keep: bool,
) -> Certified<Answer> {
    match &c.value {
        LineLine::Point(p) => c.clone_with(Answer::Points(vec![point2(
            p.point.as_slice(),
            &p.t1,
            &p.t2,
        )])),
        LineLine::Segment {
            a,
            b,
            a_params,
            b_params,
        } => c.clone_with(Answer::Segment(SegmentAnswer {
            a: point2(a.as_slice(), &a_params[0], &a_params[1]),
            b: point2(b.as_slice(), &b_params[0], &b_params[1]),
        })),
        LineLine::Line => {
            let mut r = c.clone_with(Answer::Coincident);
            r.reason = Some("the two lines coincide".into());
            r
        }
        LineLine::Ray {
            a,
            a_params,
            increasing,
        } => c.clone_with(ray(
            point2(a.as_slice(), &a_params[0], &a_params[1]),
            &exact_carrier(first).d,
            increasing[0],
            increasing.iter().map(|&i| Some(i)).collect(),
            keep,
        )),
        LineLine::Empty(LineLineEmpty::Parallel) => empty(&c, "parallel"),
        LineLine::Empty(LineLineEmpty::Skew) => empty(&c, "skew"),
        LineLine::Empty(LineLineEmpty::CollinearDisjoint) => empty(&c, "collinear_disjoint"),
        LineLine::Empty(LineLineEmpty::OutsideDomain(_)) => empty(&c, "extensions_meet"),
    }
}

/// An answer of two objects of the plane `z = 0` computed in space, with the third
/// coordinate (zero) dropped from every point, box and direction.
pub(crate) fn in_plane(mut c: Certified<Answer>) -> Certified<Answer> {
    fn flat(p: &mut Point) {
        p.xyz.truncate(2);
        p.xyz_box.truncate(2);
        if let Some(e) = p.exact.as_mut() {
            e.xyz.truncate(2);
        }
    }
    match &mut c.value {
        Answer::Points(ps) => ps.iter_mut().for_each(flat),
        Answer::Segment(s) | Answer::Arc(s) => {
            flat(&mut s.a);
            flat(&mut s.b);
        }
        Answer::Ray(r) => {
            flat(&mut r.start);
            r.dir.truncate(2);
            if let Some(d) = r.exact_dir.as_mut() {
                d.truncate(2);
            }
        }
        _ => {}
    }
    c
}

/// The carrier of a 2D line or segment.
fn carrier2<T: Coord>(l: Linear2<'_, T>) -> LineAnswer {
    let n = |x: Rational| Q::rational(&x, false).r.nearest;
    let (point, dir) = match l {
        Linear2::Line(line) => (
            line.origin().iter().map(|x| n(x.to_rational())).collect(),
            line.dir().iter().map(|x| n(x.to_rational())).collect(),
        ),
        Linear2::Segment(s) => (
            s.a().iter().map(|x| n(x.to_rational())).collect(),
            (0..2)
                .map(|i| n(s.b()[i].to_rational() - s.a()[i].to_rational()))
                .collect(),
        ),
    };
    LineAnswer {
        point,
        dir,
        params: vec![],
        exact: None,
    }
}

fn foot(f: &LineFoot<Q, Len>, nearest: bool) -> Point {
    let mut p = point(f.foot.as_slice(), vec![Some(std::slice::from_ref(&f.t))]);
    p.distance = Some(f.distance.value.nearest);
    p.nearest = Some(nearest);
    if let (Some(exact), Some(sq)) = (p.exact.as_mut(), &f.distance.squared) {
        exact.distance_squared = Some(sq.clone());
    }
    p
}

/// Point → line / segment: the stationary foot, or the nearest point.
pub(crate) fn project_line(
    c: Certified<LineProjection<Q, Len>>,
    nearest_only: bool,
) -> Certified<Answer> {
    let v = &c.value;
    if nearest_only {
        return c.clone_with(Answer::Points(vec![foot(&v.nearest, true)]));
    }
    match &v.stationary {
        Some(f) => c.clone_with(Answer::Points(vec![foot(f, f.t == v.nearest.t)])),
        None => empty(&c, "foot_outside_domain"),
    }
}

/// Point → plane.
pub(crate) fn project_plane(c: Certified<PlaneProjection<Q, Len>>) -> Certified<Answer> {
    let v = &c.value;
    let mut p = point(
        v.foot.as_slice(),
        vec![v.uv.as_ref().map(|uv| uv.as_slice())],
    );
    p.signed_distance = Some(v.distance.value.nearest);
    p.distance = Some(v.distance.value.nearest.abs());
    p.nearest = Some(true);
    if let (Some(exact), Some(sq)) = (p.exact.as_mut(), &v.distance.squared) {
        exact.distance_squared = Some(sq.clone());
    }
    c.clone_with(Answer::Points(vec![p]))
}

/// Point against a polyhedral shell: the side, and the nearest shell point with its
/// distance.
pub(crate) fn shell_point(c: Certified<ShellPoint>, keep: bool) -> Certified<Answer> {
    let v = &c.value;
    let xyz: Vec<Q> = v.nearest.iter().map(|x| Q::rational(x, keep)).collect();
    let mut p = point(&xyz, vec![]);
    p.distance = Some(crate::num::round::sqrt_rational(&v.distance_squared).nearest);
    p.nearest = Some(true);
    if let Some(exact) = p.exact.as_mut() {
        exact.distance_squared = Some(v.distance_squared.clone());
    }
    c.clone_with(Answer::Side(v.side, Some(p)))
}
