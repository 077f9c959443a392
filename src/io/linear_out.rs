//! Results of the linear kernel → result records (CASES.md "Results").
//!
//! Both paths (certified on doubles, exact on rationals) are mapped into [`Q`], a
//! correctly rounded number with its enclosure and, on request, its exact `"p/q"`
//! text, so that each kind of result is written once.

use nalgebra::{Vector2, Vector3};
use rug::Rational;

use super::result::{Bounds, CaseResult, ExactLineOut, ExactOut, LineOut, ParamLineOut, PointOut};
use crate::certificate::Certified;
use crate::geom::line_plane::{LinePlane, LinePlanePoint};
use crate::geom::lines2::{Empty2, Intersection2};
use crate::geom::plane_plane::{ParamLine, PlaneLine, PlanePlane};
use crate::geom::project::{ExactLength, LineFoot, LineProjection, PlaneProjection};
use crate::geom::three_planes::ThreePlanes;
use crate::num::round::{round_rational, Rounded};

/// An output number: the correctly rounded value with its enclosure, and the exact
/// rational as text when the case asked for it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Q {
    pub r: Rounded,
    pub text: Option<String>,
}

impl From<Rounded> for Q {
    fn from(r: Rounded) -> Q {
        Q { r, text: None }
    }
}

impl Q {
    /// An exact rational, rounded; its text kept when `keep`.
    pub fn rational(q: &Rational, keep: bool) -> Q {
        Q {
            r: round_rational(q),
            text: keep.then(|| q.to_string()),
        }
    }
    fn bounds(&self) -> Bounds {
        [self.r.lo, self.r.hi]
    }
}

/// A distance: correctly rounded, and the exact square on request.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Len {
    pub value: Rounded,
    pub squared: Option<String>,
}

impl From<Rounded> for Len {
    fn from(value: Rounded) -> Len {
        Len {
            value,
            squared: None,
        }
    }
}

impl Len {
    pub fn exact(l: ExactLength, keep: bool) -> Len {
        Len {
            value: l.rounded,
            squared: keep.then(|| l.squared.to_string()),
        }
    }
}

/// The parameters of a point on each input object (input order; `None`: the object
/// has no parameters, as an implicit plane).
pub(crate) type Params<'a> = Vec<Option<&'a [Q]>>;

pub(crate) fn point_out(xyz: &[Q], params: Params<'_>) -> PointOut {
    let texts = |v: &[Q]| v.iter().filter_map(|q| q.text.clone()).collect::<Vec<_>>();
    let has_text = xyz.iter().any(|q| q.text.is_some());
    PointOut {
        xyz: xyz.iter().map(|q| q.r.nearest).collect(),
        params: params
            .iter()
            .map(|p| p.map_or(vec![], |p| p.iter().map(|q| q.r.nearest).collect()))
            .collect(),
        bounds: xyz.iter().map(Q::bounds).collect(),
        param_box: Some(
            params
                .iter()
                .map(|p| p.map_or(vec![], |p| p.iter().map(Q::bounds).collect()))
                .collect(),
        ),
        multiplicity: 1,
        tangent: false,
        exact: has_text.then(|| ExactOut {
            xyz: texts(xyz),
            params: params.iter().map(|p| p.map_or(vec![], texts)).collect(),
            distance_squared: None,
        }),
        ..PointOut::default()
    }
}

fn with_kind<T>(id: &serde_json::Value, kind: &'static str, c: &Certified<T>) -> CaseResult {
    CaseResult::certified(id.clone(), kind, c)
}

fn empty<T>(id: &serde_json::Value, c: &Certified<T>, reason: &str) -> CaseResult {
    let mut out = with_kind(id, "empty", c);
    out.reason = Some(reason.to_string());
    out
}

fn points<T>(id: &serde_json::Value, c: &Certified<T>, pts: Vec<PointOut>) -> CaseResult {
    let mut out = with_kind(id, "points", c);
    out.points = Some(pts);
    out
}

/// Line ∩ plane; `line_first` says which of the two input objects is the line.
pub(crate) fn line_plane(
    id: &serde_json::Value,
    c: Certified<LinePlane<Q>>,
    line_first: bool,
    contained: impl FnOnce(&mut CaseResult),
) -> CaseResult {
    match &c.value {
        LinePlane::Point(LinePlanePoint { point, t, uv }) => {
            let t = Some(std::slice::from_ref(t));
            let uv = uv.as_ref().map(|v| v.as_slice());
            let params = if line_first { vec![t, uv] } else { vec![uv, t] };
            let p = point_out(point.as_slice(), params);
            points(id, &c, vec![p])
        }
        LinePlane::Parallel => empty(id, &c, "parallel"),
        LinePlane::OutsideDomain(_) => empty(id, &c, "outside_domain"),
        LinePlane::Contained => {
            let mut out = with_kind(id, "line", &c);
            contained(&mut out);
            out
        }
    }
}

fn param_line(p: &Option<ParamLine<Q>>) -> Option<ParamLineOut> {
    p.as_ref().map(|p| ParamLineOut {
        origin: p.origin.iter().map(|q| q.r.nearest).collect(),
        dir: p.dir.iter().map(|q| q.r.nearest).collect(),
    })
}

fn line_out(l: &PlaneLine<Q>, params: Vec<Option<ParamLineOut>>) -> LineOut {
    let texts = |v: &Vector3<Q>| v.iter().filter_map(|q| q.text.clone()).collect::<Vec<_>>();
    LineOut {
        point: l.point.iter().map(|q| q.r.nearest).collect(),
        dir: l.dir.iter().map(|q| q.r.nearest).collect(),
        params,
        exact: l.point[0].text.is_some().then(|| ExactLineOut {
            point: texts(&l.point),
            dir: texts(&l.dir),
        }),
    }
}

/// Plane ∩ plane.
pub(crate) fn plane_plane(id: &serde_json::Value, c: Certified<PlanePlane<Q>>) -> CaseResult {
    match &c.value {
        PlanePlane::Line(l) => {
            let mut out = with_kind(id, "line", &c);
            out.line = Some(line_out(l, vec![param_line(&l.on_a), param_line(&l.on_b)]));
            out
        }
        PlanePlane::Parallel => empty(id, &c, "parallel"),
        PlanePlane::Coincident => with_kind(id, "coincident", &c),
    }
}

/// Three planes.
pub(crate) fn three_planes(id: &serde_json::Value, c: Certified<ThreePlanes<Q>>) -> CaseResult {
    match &c.value {
        ThreePlanes::Point { point, params } => {
            let ps = params
                .iter()
                .map(|p| p.as_ref().map(|v| v.as_slice()))
                .collect();
            points(id, &c, vec![point_out(point.as_slice(), ps)])
        }
        ThreePlanes::Line { line, pair } => {
            let mut params = vec![None, None, None];
            params[pair.0] = param_line(&line.on_a);
            params[pair.1] = param_line(&line.on_b);
            let mut out = with_kind(id, "line", &c);
            out.line = Some(line_out(line, params));
            out
        }
        ThreePlanes::Plane => with_kind(id, "plane", &c),
        ThreePlanes::Empty => empty(id, &c, "no_common_point"),
    }
}

fn point2_out(p: &Vector2<Q>, t1: &Q, t2: &Q) -> PointOut {
    point_out(
        p.as_slice(),
        vec![
            Some(std::slice::from_ref(t1)),
            Some(std::slice::from_ref(t2)),
        ],
    )
}

/// Two 2D lines or segments.
pub(crate) fn lines2(
    id: &serde_json::Value,
    c: Certified<Intersection2<Q>>,
    carrier: impl FnOnce() -> LineOut,
) -> CaseResult {
    match &c.value {
        Intersection2::Point { point, t1, t2 } => points(id, &c, vec![point2_out(point, t1, t2)]),
        Intersection2::Segment {
            a,
            b,
            a_params,
            b_params,
        } => {
            let mut out = with_kind(id, "segment", &c);
            out.segment = Some(super::result::SegmentOut {
                a: point2_out(a, &a_params[0], &a_params[1]),
                b: point2_out(b, &b_params[0], &b_params[1]),
            });
            out
        }
        Intersection2::Line => {
            let mut out = with_kind(id, "line", &c);
            out.line = Some(carrier());
            out
        }
        Intersection2::Empty(Empty2::Parallel) => empty(id, &c, "parallel"),
        Intersection2::Empty(Empty2::CollinearDisjoint) => empty(id, &c, "collinear_disjoint"),
        Intersection2::Empty(Empty2::OutsideDomain { .. }) => empty(id, &c, "extensions_meet"),
    }
}

fn foot_out(f: &LineFoot<Q, Len>, nearest: bool) -> PointOut {
    let mut p = point_out(f.foot.as_slice(), vec![Some(std::slice::from_ref(&f.t))]);
    p.distance = Some(f.distance.value.nearest);
    p.nearest = Some(nearest);
    if let (Some(exact), Some(sq)) = (p.exact.as_mut(), &f.distance.squared) {
        exact.distance_squared = Some(sq.clone());
    }
    p
}

/// Point → line / segment: all stationary feet, or the nearest point.
pub(crate) fn project_line(
    id: &serde_json::Value,
    c: Certified<LineProjection<Q, Len>>,
    nearest_only: bool,
) -> CaseResult {
    let v = &c.value;
    if nearest_only {
        return points(id, &c, vec![foot_out(&v.nearest, true)]);
    }
    match &v.stationary {
        Some(f) => points(id, &c, vec![foot_out(f, f.t == v.nearest.t)]),
        None => empty(id, &c, "foot_outside_domain"),
    }
}

/// Point → plane.
pub(crate) fn project_plane(
    id: &serde_json::Value,
    c: Certified<PlaneProjection<Q, Len>>,
) -> CaseResult {
    let v = &c.value;
    let mut p = point_out(
        v.foot.as_slice(),
        vec![v.uv.as_ref().map(|uv| uv.as_slice())],
    );
    p.signed_distance = Some(v.distance.value.nearest);
    p.distance = Some(v.distance.value.nearest.abs());
    p.nearest = Some(true);
    if let (Some(exact), Some(sq)) = (p.exact.as_mut(), &v.distance.squared) {
        exact.distance_squared = Some(sq.clone());
    }
    points(id, &c, vec![p])
}

/// Point against a shell: the side, and the nearest shell point with its distance.
pub(crate) fn shell_point(
    id: &serde_json::Value,
    c: Certified<crate::ops::ShellPoint>,
    keep: bool,
) -> CaseResult {
    let v = &c.value;
    let xyz: Vec<Q> = v.nearest.iter().map(|x| Q::rational(x, keep)).collect();
    let mut p = point_out(&xyz, vec![]);
    p.distance = Some(crate::num::round::sqrt_rational(&v.distance_squared).nearest);
    p.nearest = Some(true);
    if let Some(exact) = p.exact.as_mut() {
        exact.distance_squared = Some(v.distance_squared.to_string());
    }
    let mut out = with_kind(id, v.side.as_str(), &c);
    out.points = Some(vec![p]);
    out
}
