//! Solving one case of the command line (CASES.md "Cases"): validate its objects,
//! run the operation and write the result record.
//!
//! Linear objects run on doubles through the certified kernel (exact verdict, correctly
//! rounded output, [`crate::geom`]); a number written as a string that no double equals,
//! or `options.exact`, sends the case through the exact rational kernel instead, which
//! also reports the rationals as `"p/q"` strings.

use std::cell::Cell;
use std::time::Instant;

use nalgebra::Vector3;
use rug::Rational;

use super::build::{build, polyhedron, unreachable_rational, vec3, BuildError, FromNum, Object};
use super::case::{Case, Op, ReadCase};
use super::linear_out::{self as out, Len, Q};
use super::objects::ObjectSpec;
use super::result::{CaseResult, LineOut, ParamLineOut, SegmentOut};
use crate::certificate::{Arithmetic, Certified};
use crate::error::GeomError;
use crate::geom::line_plane::{self, LinePlane};
use crate::geom::lines2::{self, Intersection2};
use crate::geom::plane_plane::{self, dir_exponent, PlaneLine, PlanePlane};
use crate::geom::project::{self, LineFoot, LineProjection, PlaneProjection};
use crate::geom::three_planes::{self, ThreePlanes};
use crate::geom::{Coord, Linear, Linear2, Plane};
use crate::num::round::scale_pow2;

/// Solve one case read from the input. Errors (unreadable cases, invalid objects,
/// unsupported operations) become error records naming the field.
pub fn solve_case(read: ReadCase) -> CaseResult {
    let start = Instant::now();
    let case = match read.case {
        Ok(case) => case,
        Err(e) => return CaseResult::error(read.id, &e),
    };
    match solve(&case) {
        Ok(mut result) => {
            result.micros = Some(start.elapsed().as_micros() as u64);
            result
        }
        Err(e) => CaseResult::error(case.id.clone(), &e),
    }
}

fn solve(case: &Case) -> Result<CaseResult, GeomError> {
    if let Some(result) = super::curved::solve_curved(case) {
        return result;
    }
    if !case.options.exact {
        match solve_in::<f64>(case) {
            Err(BuildError::NeedsRational) => {}
            Ok(r) => return Ok(r),
            Err(BuildError::Geom(e)) => return Err(e),
        }
    }
    solve_in::<Rational>(case).map_err(|e| match e {
        BuildError::Geom(e) => e,
        BuildError::NeedsRational => unreachable_rational(),
    })
}

fn solve_in<T: Kernel>(case: &Case) -> Result<CaseResult, BuildError> {
    match case.op {
        Op::Intersect => intersect::<T>(case),
        Op::Project => project::<T>(case),
        Op::Classify => classify(case).map_err(BuildError::Geom),
        other => Err(GeomError::Unsupported {
            field: "op".into(),
            reason: format!("`{}` is not implemented in this build", other.as_str()),
        }
        .into()),
    }
}

fn unsupported(field: &str, reason: String) -> BuildError {
    GeomError::Unsupported {
        field: field.into(),
        reason,
    }
    .into()
}

fn intersect<T: Kernel>(case: &Case) -> Result<CaseResult, BuildError> {
    let objects: Vec<Object<T>> = case
        .objects
        .iter()
        .enumerate()
        .map(|(i, s)| build::<T>(s, &format!("objects[{i}]")))
        .collect::<Result<_, _>>()?;
    let keep = case.options.exact;
    let id = &case.id;
    let names = || {
        case.objects
            .iter()
            .map(|o| o.type_name())
            .collect::<Vec<_>>()
            .join(" and ")
    };
    match objects.as_slice() {
        [a, b] => {
            if let (Some(l), Some(p)) = (a.linear(), b.plane()) {
                return Ok(intersect_line_plane(id, l, p, true, keep));
            }
            if let (Some(p), Some(l)) = (a.plane(), b.linear()) {
                return Ok(intersect_line_plane(id, l, p, false, keep));
            }
            if let (Some(p), Some(q)) = (a.plane(), b.plane()) {
                return Ok(out::plane_plane(id, T::plane_plane(p, q, keep)));
            }
            if let (Some(l), Some(m)) = (a.linear2(), b.linear2()) {
                let carrier = || carrier2(l);
                return Ok(out::lines2(id, T::lines2(l, m, keep), carrier));
            }
            Err(unsupported(
                "objects",
                format!("intersect of {} is not implemented in this build", names()),
            ))
        }
        [a, b, c] => match (a.plane(), b.plane(), c.plane()) {
            (Some(p), Some(q), Some(r)) => {
                let planes = [p.clone(), q.clone(), r.clone()];
                Ok(out::three_planes(id, T::three_planes(&planes, keep)))
            }
            _ => Err(unsupported(
                "objects",
                format!("intersect of {} is not implemented in this build", names()),
            )),
        },
        other => Err(GeomError::InvalidValue {
            field: "objects".into(),
            reason: format!("intersect takes 2 or 3 objects, found {}", other.len()),
        }
        .into()),
    }
}

fn intersect_line_plane<T: Kernel>(
    id: &serde_json::Value,
    l: Linear<'_, T>,
    p: &Plane<T>,
    line_first: bool,
    keep: bool,
) -> CaseResult {
    out::line_plane(id, T::line_plane(l, p, keep), line_first, |r| {
        contained(r, l, line_first, keep)
    })
}

/// A line lying in the plane: the line itself (kind `line`), or for a segment or a
/// ranged line its end points (kind `segment`), with their parameters on the line.
fn contained<T: Coord>(r: &mut CaseResult, l: Linear<'_, T>, line_first: bool, keep: bool) {
    let q = |x: &T| Q::rational(&x.to_rational(), keep);
    let (o, d, range) = match l {
        Linear::Line(line) => (
            line.origin().map(|x| x.to_rational()),
            line.dir().map(|x| x.to_rational()),
            line.range()
                .map(|[a, b]| [a.to_rational(), b.to_rational()]),
        ),
        Linear::Segment(s) => {
            let a = s.a().map(|x| x.to_rational());
            let d = s.b().map(|x| x.to_rational()) - &a;
            (a, d, Some([Rational::from(0), Rational::from(1)]))
        }
    };
    let Some(range) = range else {
        if let Linear::Line(line) = l {
            let param = ParamLineOut {
                origin: vec![0.0],
                dir: vec![1.0],
            };
            let mut params = vec![Some(param), None];
            if !line_first {
                params.reverse();
            }
            r.line = Some(LineOut {
                point: line.origin().iter().map(|x| q(x).r.nearest).collect(),
                dir: line.dir().iter().map(|x| q(x).r.nearest).collect(),
                params,
                exact: None,
            });
        }
        return;
    };
    let end = |t: &Rational| {
        let xyz: Vec<Q> = (0..3)
            .map(|i| Q::rational(&(o[i].clone() + d[i].clone() * t), keep))
            .collect();
        let t = [Q::rational(t, keep)];
        let params = if line_first {
            vec![Some(&t[..]), None]
        } else {
            vec![None, Some(&t[..])]
        };
        out::point_out(&xyz, params)
    };
    r.kind = Some("segment");
    r.segment = Some(SegmentOut {
        a: end(&range[0]),
        b: end(&range[1]),
    });
}

/// The common carrier of two coincident 2D lines (the first one).
fn carrier2<T: Coord>(l: Linear2<'_, T>) -> LineOut {
    let n = |x: &T| Q::rational(&x.to_rational(), false).r.nearest;
    match l {
        Linear2::Line(line) => LineOut {
            point: line.origin().iter().map(n).collect(),
            dir: line.dir().iter().map(n).collect(),
            params: vec![],
            exact: None,
        },
        Linear2::Segment(s) => LineOut {
            point: s.a().iter().map(n).collect(),
            dir: (0..2)
                .map(|i| {
                    Q::rational(&(s.b()[i].to_rational() - s.a()[i].to_rational()), false)
                        .r
                        .nearest
                })
                .collect(),
            params: vec![],
            exact: None,
        },
    }
}

fn project<T: Kernel>(case: &Case) -> Result<CaseResult, BuildError> {
    let missing = |field: &str| GeomError::Format {
        field: field.into(),
        message: format!("`project` needs `{field}`"),
    };
    let point = case.point.as_ref().ok_or_else(|| missing("point"))?;
    let onto_spec = case.onto.as_ref().ok_or_else(|| missing("onto"))?;
    let p: Vector3<T> = vec3(point, "point")?;
    let onto: Object<T> = build(onto_spec, "onto")?;
    let keep = case.options.exact;
    let id = &case.id;
    if let Some(direction) = &case.direction {
        let dir: Vector3<T> = vec3(direction, "direction")?;
        let Some(plane) = onto.plane() else {
            return Err(unsupported(
                "direction",
                format!(
                    "projection along a direction onto a {} is not implemented in this build",
                    onto_spec.type_name()
                ),
            ));
        };
        let line = crate::geom::Line::new(p.clone(), dir).map_err(|e| match e {
            GeomError::ZeroDirection { .. } => GeomError::ZeroDirection {
                field: "direction".into(),
            },
            other => other,
        })?;
        return Ok(along(id, &p, Linear::Line(&line), plane, keep));
    }
    if let Some(l) = onto.linear() {
        return Ok(out::project_line(
            id,
            T::project_line(&p, l, keep),
            case.nearest,
        ));
    }
    if let Some(plane) = onto.plane() {
        return Ok(out::project_plane(id, T::project_plane(&p, plane, keep)));
    }
    Err(unsupported(
        "onto",
        format!(
            "projection onto a {} is not implemented in this build",
            onto_spec.type_name()
        ),
    ))
}

/// Projection along a direction onto a plane (OPERATIONS.md §3.5): the line through
/// the point along the direction meets the plane; a point on the plane is its own
/// projection whatever the direction.
fn along<T: Kernel>(
    id: &serde_json::Value,
    p: &Vector3<T>,
    line: Linear<'_, T>,
    plane: &Plane<T>,
    keep: bool,
) -> CaseResult {
    let c = T::line_plane(line, plane, keep);
    if matches!(c.value, LinePlane::Contained) {
        return out::project_plane(id, T::project_plane(p, plane, keep));
    }
    let mut r = out::line_plane(id, c, true, |_| {});
    // The case has one object (`onto`): drop the parameter of the auxiliary line.
    for pt in r.points.iter_mut().flatten() {
        pt.params.remove(0);
        if let Some(b) = pt.param_box.as_mut() {
            b.remove(0);
        }
        if let Some(e) = pt.exact.as_mut() {
            e.params.remove(0);
        }
    }
    r
}

/// The two kernels behind one interface: certified on doubles, exact on rationals.
/// Both return numbers as [`Q`] (rounded, with the exact text on request).
pub(crate) trait Kernel: FromNum {
    fn line_plane(l: Linear<'_, Self>, p: &Plane<Self>, keep: bool) -> Certified<LinePlane<Q>>;
    fn plane_plane(a: &Plane<Self>, b: &Plane<Self>, keep: bool) -> Certified<PlanePlane<Q>>;
    fn three_planes(p: &[Plane<Self>; 3], keep: bool) -> Certified<ThreePlanes<Q>>;
    fn lines2(
        a: Linear2<'_, Self>,
        b: Linear2<'_, Self>,
        keep: bool,
    ) -> Certified<Intersection2<Q>>;
    fn project_line(
        p: &Vector3<Self>,
        l: Linear<'_, Self>,
        keep: bool,
    ) -> Certified<LineProjection<Q, Len>>;
    fn project_plane(
        p: &Vector3<Self>,
        plane: &Plane<Self>,
        keep: bool,
    ) -> Certified<PlaneProjection<Q, Len>>;
}

fn map_line_projection<S: nalgebra::Scalar, L, S2: nalgebra::Scalar, L2>(
    v: LineProjection<S, L>,
    mut s: impl FnMut(S) -> S2,
    mut l: impl FnMut(L) -> L2,
) -> LineProjection<S2, L2> {
    let mut foot = |f: LineFoot<S, L>| LineFoot {
        foot: f.foot.map(&mut s),
        t: s(f.t),
        distance: l(f.distance),
    };
    LineProjection {
        stationary: v.stationary.map(&mut foot),
        nearest: foot(v.nearest),
    }
}

fn map_plane_projection<S: nalgebra::Scalar, L, S2: nalgebra::Scalar, L2>(
    v: PlaneProjection<S, L>,
    mut s: impl FnMut(S) -> S2,
    l: impl FnOnce(L) -> L2,
) -> PlaneProjection<S2, L2> {
    PlaneProjection {
        foot: v.foot.map(&mut s),
        uv: v.uv.map(|uv| uv.map(&mut s)),
        distance: l(v.distance),
    }
}

impl Kernel for f64 {
    fn line_plane(l: Linear<'_, f64>, p: &Plane<f64>, _: bool) -> Certified<LinePlane<Q>> {
        line_plane::intersect_line_plane(l, p).map(|v| v.map(Q::from))
    }
    fn plane_plane(a: &Plane<f64>, b: &Plane<f64>, _: bool) -> Certified<PlanePlane<Q>> {
        plane_plane::intersect_plane_plane(a, b).map(|v| v.map(Q::from))
    }
    fn three_planes(p: &[Plane<f64>; 3], _: bool) -> Certified<ThreePlanes<Q>> {
        three_planes::intersect_three_planes(p).map(|v| v.map(Q::from))
    }
    fn lines2(a: Linear2<'_, f64>, b: Linear2<'_, f64>, _: bool) -> Certified<Intersection2<Q>> {
        lines2::intersect_line2_line2(a, b).map(|v| v.map(Q::from))
    }
    fn project_line(
        p: &Vector3<f64>,
        l: Linear<'_, f64>,
        _: bool,
    ) -> Certified<LineProjection<Q, Len>> {
        project::project_point_line(p, l).map(|v| map_line_projection(v, Q::from, Len::from))
    }
    fn project_plane(
        p: &Vector3<f64>,
        plane: &Plane<f64>,
        _: bool,
    ) -> Certified<PlaneProjection<Q, Len>> {
        project::project_point_plane(p, plane).map(|v| map_plane_projection(v, Q::from, Len::from))
    }
}

/// Rounds exact results and records the largest bit length seen (the `bits` of a
/// rational answer: CERTIFICATION.md, "the bit length of the largest exact number").
struct ExactRounder {
    keep: bool,
    bits: Cell<u32>,
}

impl ExactRounder {
    fn new(keep: bool) -> Self {
        ExactRounder {
            keep,
            bits: Cell::new(53),
        }
    }
    fn q(&self, x: Rational) -> Q {
        let b = x
            .numer()
            .significant_bits()
            .max(x.denom().significant_bits());
        self.bits.set(self.bits.get().max(b));
        Q::rational(&x, self.keep)
    }
    fn done<T>(self, value: T) -> Certified<T> {
        Certified::exact(value, Arithmetic::Rational, self.bits.get())
    }
    /// A plane line whose direction (and parameter directions) are scaled by a power
    /// of two so that they round to finite normal doubles (as the certified path does).
    fn line(&self, l: PlaneLine<Rational>) -> PlaneLine<Q> {
        let k = dir_exponent(l.dir.as_slice());
        let scaled = |x: Rational| self.q(scale_pow2(&x, k));
        let param = |p: plane_plane::ParamLine<Rational>| plane_plane::ParamLine {
            origin: p.origin.map(|x| self.q(x)),
            dir: p.dir.map(scaled),
        };
        PlaneLine {
            point: l.point.map(|x| self.q(x)),
            dir: l.dir.map(scaled),
            dir_exponent: k,
            on_a: l.on_a.map(param),
            on_b: l.on_b.map(param),
        }
    }
}

impl Kernel for Rational {
    fn line_plane(
        l: Linear<'_, Rational>,
        p: &Plane<Rational>,
        keep: bool,
    ) -> Certified<LinePlane<Q>> {
        let r = ExactRounder::new(keep);
        let v = line_plane::intersect_line_plane_exact(l, p).map(|x| r.q(x));
        r.done(v)
    }
    fn plane_plane(
        a: &Plane<Rational>,
        b: &Plane<Rational>,
        keep: bool,
    ) -> Certified<PlanePlane<Q>> {
        let r = ExactRounder::new(keep);
        let v = match plane_plane::intersect_plane_plane_exact(a, b) {
            PlanePlane::Line(l) => PlanePlane::Line(r.line(l)),
            PlanePlane::Parallel => PlanePlane::Parallel,
            PlanePlane::Coincident => PlanePlane::Coincident,
        };
        r.done(v)
    }
    fn three_planes(p: &[Plane<Rational>; 3], keep: bool) -> Certified<ThreePlanes<Q>> {
        let r = ExactRounder::new(keep);
        let v = match three_planes::intersect_three_planes_exact(p) {
            ThreePlanes::Line { line, pair } => ThreePlanes::Line {
                line: r.line(line),
                pair,
            },
            other => other.map(|x| r.q(x)),
        };
        r.done(v)
    }
    fn lines2(
        a: Linear2<'_, Rational>,
        b: Linear2<'_, Rational>,
        keep: bool,
    ) -> Certified<Intersection2<Q>> {
        let r = ExactRounder::new(keep);
        let v = lines2::intersect_line2_line2_exact(a, b).map(|x| r.q(x));
        r.done(v)
    }
    fn project_line(
        p: &Vector3<Rational>,
        l: Linear<'_, Rational>,
        keep: bool,
    ) -> Certified<LineProjection<Q, Len>> {
        let r = ExactRounder::new(keep);
        let v = map_line_projection(
            project::project_point_line_exact(p, l),
            |x| r.q(x),
            |d| Len::exact(d, keep),
        );
        r.done(v)
    }
    fn project_plane(
        p: &Vector3<Rational>,
        plane: &Plane<Rational>,
        keep: bool,
    ) -> Certified<PlaneProjection<Q, Len>> {
        let r = ExactRounder::new(keep);
        let v = map_plane_projection(
            project::project_point_plane_exact(p, plane),
            |x| r.q(x),
            |d| Len::exact(d, keep),
        );
        r.done(v)
    }
}

/// `classify`: a point against a closed shell (OPERATIONS.md §4), exactly.
fn classify(case: &Case) -> Result<CaseResult, GeomError> {
    let missing = |field: &str| GeomError::Format {
        field: field.into(),
        message: format!("`classify` needs `{field}`"),
    };
    let point = case.point.as_ref().ok_or_else(|| missing("point"))?;
    let shell = case.shell.as_ref().ok_or_else(|| missing("shell"))?;
    let ObjectSpec::Polyhedron(spec) = shell else {
        return Err(GeomError::Unsupported {
            field: "shell.type".into(),
            reason: format!(
                "classify against a {} is not implemented in this build (polyhedron is)",
                shell.type_name()
            ),
        });
    };
    let p: Vector3<Rational> = vec3(point, "point").map_err(|e| match e {
        BuildError::Geom(g) => g,
        BuildError::NeedsRational => unreachable_rational(),
    })?;
    let shell = polyhedron(spec, "shell")?;
    let c =
        crate::ops::classify_point_polyhedron(&[p[0].clone(), p[1].clone(), p[2].clone()], &shell);
    Ok(out::shell_point(&case.id, c, case.options.exact))
}
