//! Answers of the front door → result records (docs/FORMAT.md "Results"): a field-for-field
//! translation; exact rationals are written as `"p/q"` strings.
//!
//! A number with no finite double (beyond the f64 range) is written `"inf"` or `"-inf"`
//! ([`super::result`]), and the point or line holding it always carries its exact
//! rationals ([`crate::ops::beyond_range`]), so no value is lost (docs/FORMAT.md
//! "Numbers beyond the double range").

use rug::Rational;

use super::blend_law::law_json;
use super::result::{
    BlendOut, CaseResult, ComponentOut, CurveEndOut, CurveOut, CurveVertexOut, ExactLineOut,
    ExactOut, ExactRayOut, GridOut, LineOut, ParamLineOut, PointOut, RayOut, SegmentOut,
    SingularPointOut,
};
use crate::certificate::Certified;
use crate::ops::{
    Answer, BlendAnswer, BlendComponent, BlendKind, CurveAnswer, CurveEnd, LineAnswer, Point,
    SingularPointAnswer,
};

fn texts(v: &[Rational]) -> Vec<String> {
    v.iter().map(Rational::to_string).collect()
}

/// One point of an answer.
pub(crate) fn point(p: &Point) -> PointOut {
    PointOut {
        xyz: p.xyz.clone(),
        params: p.params.clone(),
        bounds: p.xyz_box.clone(),
        param_box: p.param_box.clone(),
        multiplicity: p.multiplicity,
        tangent: p.tangent,
        distance: p.distance,
        signed_distance: p.signed_distance,
        nearest: p.nearest,
        exact: p.exact.as_ref().map(|e| ExactOut {
            xyz: texts(&e.xyz),
            params: e.params.iter().map(|p| texts(p)).collect(),
            distance_squared: e.distance_squared.as_ref().map(Rational::to_string),
        }),
        region: p.region.clone(),
    }
}

fn line(l: &LineAnswer) -> LineOut {
    LineOut {
        point: l.point.clone(),
        dir: l.dir.clone(),
        params: l
            .params
            .iter()
            .map(|p| {
                p.as_ref().map(|p| ParamLineOut {
                    origin: p.origin.clone(),
                    dir: p.dir.clone(),
                })
            })
            .collect(),
        exact: l.exact.as_ref().map(|(p, d)| ExactLineOut {
            point: texts(p),
            dir: texts(d),
        }),
    }
}

fn curve(c: &CurveAnswer, singular: &[SingularPointOut]) -> CurveOut {
    let end = |e: CurveEnd| CurveEndOut {
        kind: e.as_str(),
        index: match e {
            CurveEnd::Singular(i) => Some(i),
            _ => None,
        },
    };
    CurveOut {
        closed: c.closed,
        points: c
            .points
            .iter()
            .map(|v| CurveVertexOut {
                xyz: v.xyz.clone(),
                params: v.params.clone(),
                exact: v.exact.as_ref().map(|e| texts(e)),
            })
            .collect(),
        singular_points: {
            let mut at: Vec<usize> = c
                .ends
                .iter()
                .filter_map(|e| match e {
                    CurveEnd::Singular(i) => Some(*i),
                    _ => None,
                })
                .collect();
            at.dedup();
            at.iter()
                .filter_map(|&i| singular.get(i).cloned())
                .collect()
        },
        ends: c.ends.map(end),
        status: c.status.as_str(),
        distance_bound: c.distance_bound,
        reason: c.reason.clone(),
    }
}

fn singular_point(p: &SingularPointAnswer) -> SingularPointOut {
    SingularPointOut {
        point: point(&p.point),
        status: p.status.as_str(),
        perturbation: p.perturbation,
        branches: p.branches,
    }
}

fn component(c: &BlendComponent) -> ComponentOut {
    ComponentOut {
        contacts: [0, 1].map(|k| c.contacts[k].iter().map(point).collect()),
        grid: GridOut {
            t: c.grid.t.clone(),
            z: c.grid.z.clone(),
            points: c.grid.points.clone(),
            boxes: c.grid.boxes.clone(),
        },
        status: c.spine.status.as_str(),
        reason: c.spine.reason.clone(),
    }
}

/// The record field of a blend (`fillet`, `chamfer`).
fn blend(b: &BlendAnswer) -> BlendOut {
    let (kind, radius, legs) = match &b.kind {
        BlendKind::Fillet { radius } => ("fillet", Some(law_json(radius)), None),
        BlendKind::Chamfer { legs } => ("chamfer", None, Some(legs.each_ref().map(law_json))),
    };
    BlendOut {
        kind,
        radius,
        legs,
        sector: b.sector,
        components: b.components.iter().map(component).collect(),
    }
}

/// The result record of an answer.
pub fn result(id: serde_json::Value, c: &Certified<Answer>) -> CaseResult {
    let mut r = CaseResult::certified(id, c.value.kind(), c);
    match &c.value {
        Answer::Empty => r.points = Some(vec![]),
        Answer::Points(p) => r.points = Some(p.iter().map(point).collect()),
        Answer::Line(l) => r.line = Some(line(l)),
        Answer::Segment(s) => {
            r.segment = Some(SegmentOut {
                a: point(&s.a),
                b: point(&s.b),
            })
        }
        Answer::Arc(s) => {
            r.arc = Some(SegmentOut {
                a: point(&s.a),
                b: point(&s.b),
            })
        }
        Answer::Ray(ray) => {
            r.ray = Some(RayOut {
                start: point(&ray.start),
                dir: ray.dir.clone(),
                increasing: ray.increasing.clone(),
                exact: ray
                    .exact_dir
                    .as_ref()
                    .map(|d| ExactRayOut { dir: texts(d) }),
            })
        }
        Answer::Side(_, nearest) => r.points = nearest.as_ref().map(|p| vec![point(p)]),
        Answer::Visibility(v) => {
            r.points = Some(vec![point(&v.point)]);
            r.blocker = v.blocker;
        }
        Answer::Curves(c) => {
            let singular: Vec<SingularPointOut> =
                c.singular_points.iter().map(singular_point).collect();
            r.curves = Some(c.curves.iter().map(|k| curve(k, &singular)).collect());
            r.singular_points = Some(singular);
            r.conic = c.conic.as_ref().map(super::section_out::conic);
            if !c.points.is_empty() {
                r.points = Some(c.points.iter().map(point).collect());
            }
        }
        Answer::Blend(b) if b.components.is_empty() => r.points = Some(vec![]),
        Answer::Blend(b) => {
            r.curves = Some(b.components.iter().map(|k| curve(&k.spine, &[])).collect());
            r.blend = Some(blend(b));
        }
        Answer::Plane | Answer::Coincident | Answer::CommonComponent => {}
    }
    r
}
