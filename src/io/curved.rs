//! Solving cases with curved objects (OPERATIONS.md §3–§7 on curves and surfaces):
//! point → curve / surface projections (all feet, nearest, along a direction), plane
//! curve ∩ plane curve, curve ∩ surface, three surfaces, and a point against a closed
//! sphere, ellipsoid or torus. Initial guesses come from the walks of §2; every answer
//! is certified by [`crate::ops::certified`] (or decided exactly for `classify`).

use super::case::{Case, Op};
use super::number::Num;
use super::objects::{LineSpec, ObjectSpec, SegmentSpec};
use super::result::{Bounds, CaseResult, PointOut};
use super::shapes::surface::SurfaceSpec;
use super::shapes::PlaneShape;
use crate::certificate::{Certified, Status};
use crate::curve::any::AnyCurve3;
use crate::curve::lines::{Line, Segment};
use crate::curve::Curve;
use crate::error::GeomError;
use crate::num::Interval;
use crate::ops::certified::{CertifiedPoint, Options};
use crate::ops::classify::Side;
use crate::ops::closed_surface::{classify_point_surface, sphere_feet, ClosedSurface};
use crate::ops::float::Precision;
use crate::ops::nearest::{self, Nearest, NearestChoice};
use crate::ops::{intersect, project};
use crate::surface::any::AnySurface;
use crate::surface::Surface;
use crate::walk::surface::{SurfaceWalk, SurfaceWalkOptions};
use crate::walk::{CurveWalk, WalkOptions};
use std::f64::consts::PI;

/// `Some(result)` when the case involves a curved object, `None` for the linear kernel.
pub fn solve_curved(case: &Case) -> Option<Result<CaseResult, GeomError>> {
    let curved = |o: &ObjectSpec| {
        matches!(
            o,
            ObjectSpec::Curve3(_) | ObjectSpec::Curve2(_) | ObjectSpec::Surface(_)
        )
    };
    let any = case.objects.iter().any(curved)
        || case.onto.as_ref().is_some_and(curved)
        || case.shell.as_ref().is_some_and(curved);
    any.then(|| solve(case))
}

fn solve(case: &Case) -> Result<CaseResult, GeomError> {
    let precision = precision(case)?;
    let opts = Options {
        max_boxes: case.options.max_boxes.map_or(20_000, |b| b as usize),
        // 512, not CERTIFICATION.md's 4096: a tangency escalates to the cap before its
        // singular certificate, and at 4096 bits that costs ~100× more (measured).
        max_bits: case.options.max_bits.unwrap_or(512),
        min_width: 0.0,
    };
    match case.op {
        Op::Project => project_case(case, &precision, &opts),
        Op::Intersect => match super::exact_curved::try_exact(case) {
            Some(exact) => exact,
            None => intersect_case(case, &precision, &opts),
        },
        Op::Classify => classify_case(case, &precision, &opts),
        other => Err(unsupported(
            "op",
            format!("`{}` is not implemented for curved objects", other.as_str()),
        )),
    }
}

fn unsupported(field: &str, reason: String) -> GeomError {
    GeomError::Unsupported {
        field: field.into(),
        reason,
    }
}

fn precision(case: &Case) -> Result<Precision, GeomError> {
    let mut p = Precision::default();
    if let Some(eps) = &case.options.tolerance {
        p.eps = eps.0;
    }
    if let Some(delta) = &case.options.equal_tolerance {
        p.delta = delta.0;
    }
    let valid = |x: f64| x > 0.0 && x < 1.0;
    if !valid(p.eps) || !valid(p.delta) {
        return Err(GeomError::InvalidValue {
            field: "options.tolerance".into(),
            reason: format!(
                "tolerances must lie in (0, 1), found ε = {}, δ = {}",
                p.eps, p.delta
            ),
        });
    }
    Ok(p)
}

fn doubles<const D: usize>(xs: &[Num], field: &str) -> Result<[f64; D], GeomError> {
    if xs.len() != D {
        return Err(GeomError::CountMismatch {
            field: field.into(),
            expected: format!("{D} coordinates"),
            found: xs.len().to_string(),
        });
    }
    let mut out = [0.0; D];
    for (i, x) in xs.iter().enumerate() {
        let f = format!("{field}[{i}]");
        out[i] = x.as_double().ok_or_else(|| {
            unsupported(
                &f,
                "curved operations take doubles, not exact strings".into(),
            )
        })?;
        crate::error::require_finite(&f, out[i])?;
    }
    Ok(out)
}

fn curve_samples<const D: usize, C: Curve<D>>(c: &C) -> Result<Vec<(f64, f64)>, GeomError> {
    Ok(CurveWalk::new(c, WalkOptions::default())?
        .map(|s| (s.t, s.step))
        .collect())
}

fn surface_nodes<S: Surface>(s: &S) -> Result<Vec<[f64; 4]>, GeomError> {
    Ok(SurfaceWalk::new(s, SurfaceWalkOptions::new(PI / 10.0))?
        .map(|n| [n.u, n.v, n.du, n.dv])
        .collect())
}

fn at<T>(r: Result<T, GeomError>, field: &str) -> Result<T, GeomError> {
    r.map_err(|e| e.at(field))
}

fn build_surface(spec: &ObjectSpec, field: &str) -> Result<Option<AnySurface>, GeomError> {
    match spec {
        ObjectSpec::Surface(s) => at(s.build(), field).map(Some),
        _ => Ok(None),
    }
}

/// A space curve from a curved spec, or from a `line` / `segment`; a line without a
/// range is cut to the part that can meet `bound` (a certified box of a surface).
fn build_curve3(
    spec: &ObjectSpec,
    field: &str,
    bound: Option<&[Interval; 3]>,
) -> Result<Option<AnyCurve3>, GeomError> {
    Ok(Some(match spec {
        ObjectSpec::Curve3(c) => at(c.build(), field)?,
        ObjectSpec::Segment(SegmentSpec { a, b }) => {
            let (a, b) = (
                doubles::<3>(a, &format!("{field}.a"))?,
                doubles::<3>(b, &format!("{field}.b"))?,
            );
            AnyCurve3::Segment(at(Segment::new(a, b, None), field)?)
        }
        ObjectSpec::Line(LineSpec { origin, dir, range }) => {
            let o = doubles::<3>(origin, &format!("{field}.origin"))?;
            let d = doubles::<3>(dir, &format!("{field}.dir"))?;
            let range = match range {
                Some(r) => {
                    let r = doubles::<2>(r, &format!("{field}.range"))?;
                    (r[0], r[1])
                }
                None => reach(&o, &d, bound).ok_or_else(|| {
                    unsupported(
                        &format!("{field}.range"),
                        "the line needs a `range` here: the other object is unbounded".into(),
                    )
                })?,
            };
            AnyCurve3::Line(at(Line::new(o, d, Some(range)), field)?)
        }
        _ => return Ok(None),
    }))
}

/// The parameters of `o + t·d` inside the box `bound` (slab method), widened outward so
/// that rounding cannot cut a hit off: every point of the line in the box has its `t`
/// in the range. `Some((0, 0))`-like tiny ranges for a miss are fine (the solver then
/// proves there is nothing).
fn reach(o: &[f64; 3], d: &[f64; 3], bound: Option<&[Interval; 3]>) -> Option<(f64, f64)> {
    let b = bound?;
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..3 {
        if !(b[i].lo().is_finite() && b[i].hi().is_finite()) {
            return None;
        }
        if d[i] == 0.0 {
            continue;
        }
        let di = Interval::point(d[i]);
        let t1 = (Interval::point(b[i].lo()) - Interval::point(o[i])) / di;
        let t2 = (Interval::point(b[i].hi()) - Interval::point(o[i])) / di;
        let span = t1.hull(&t2);
        lo = lo.max(span.lo());
        hi = hi.min(span.hi());
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return None;
    }
    let pad = 1e-9 * (hi - lo).abs().max(lo.abs()).max(hi.abs()).max(1.0);
    Some(if lo <= hi {
        (lo - pad, hi + pad)
    } else {
        (lo - pad, lo + pad)
    })
}

/// A certified box of the whole surface (its point over the whole parameter domain).
fn surface_box<S: Surface>(s: &S) -> [Interval; 3] {
    let ([u0, u1], [v0, v1]) = s.domain();
    let mut b = s.jet(
        &Interval::from_bounds(u0, u1),
        &Interval::from_bounds(v0, v1),
        0,
    );
    b.swap_remove(0)
}

/// A certified box of a whole curve.
fn curve_box<C: Curve<3>>(c: &C) -> [Interval; 3] {
    let (lo, hi) = c.domain();
    c.jet(&Interval::from_bounds(lo, hi), 0).swap_remove(0)
}

fn bounds<const D: usize>(b: &[Interval; D]) -> Vec<Bounds> {
    b.iter().map(|x| [x.lo(), x.hi()]).collect()
}

/// The result record of certified points; `params` splits each root's parameters by
/// object (`sizes`).
fn points_result<const D: usize>(
    case: &Case,
    kind_if_any: &'static str,
    c: Certified<Vec<CertifiedPoint<D>>>,
    sizes: &[usize],
    distance_to: Option<[f64; D]>,
) -> CaseResult {
    let kind = if c.value.is_empty() {
        "empty"
    } else {
        kind_if_any
    };
    let mut r = CaseResult::certified(case.id.clone(), kind, &c);
    let points = c
        .value
        .iter()
        .map(|p| {
            let mut params = Vec::new();
            let mut param_box = Vec::new();
            let mut k = 0;
            for &n in sizes {
                params.push(p.root.params[k..k + n].to_vec());
                param_box.push(
                    p.root.enclosure[k..k + n]
                        .iter()
                        .map(|x| [x.lo(), x.hi()])
                        .collect(),
                );
                k += n;
            }
            let singular = p.root.status == Status::VerifiedSingular;
            PointOut {
                xyz: p.point.to_vec(),
                params,
                bounds: bounds(&p.point_box),
                param_box: Some(param_box),
                multiplicity: if singular { 2 } else { 1 },
                tangent: singular,
                distance: distance_to.map(|q| {
                    p.point
                        .iter()
                        .zip(q)
                        .map(|(a, b)| (a - b) * (a - b))
                        .sum::<f64>()
                        .sqrt()
                }),
                ..Default::default()
            }
        })
        .collect();
    r.points = Some(points);
    r
}

fn project_case(
    case: &Case,
    precision: &Precision,
    opts: &Options,
) -> Result<CaseResult, GeomError> {
    let onto = case.onto.as_ref().ok_or_else(|| GeomError::Format {
        field: "onto".into(),
        message: "missing field `onto`".into(),
    })?;
    let point = case.point.as_ref().ok_or_else(|| GeomError::Format {
        field: "point".into(),
        message: "missing field `point`".into(),
    })?;
    match onto {
        ObjectSpec::Surface(spec) => {
            let s = at(spec.build(), "onto")?;
            let p = doubles::<3>(point, "point")?;
            let nodes = surface_nodes(&s)?;
            if let Some(dir) = &case.direction {
                let d = doubles::<3>(dir, "direction")?;
                if d.iter().all(|&x| x == 0.0) {
                    return Err(GeomError::ZeroDirection {
                        field: "direction".into(),
                    });
                }
                // The ray's parameters that can meet the surface at all (a certified
                // box of the whole surface), so that `complete` covers every hit.
                let range = reach(&p, &d, Some(&surface_box(&s))).ok_or_else(|| {
                    unsupported(
                        "onto",
                        "projection along a direction needs a bounded surface".into(),
                    )
                })?;
                let line = AnyCurve3::Line(Line::new(p, d, Some(range))?);
                let samples = curve_samples(&line)?;
                let c = intersect::intersect_curve_surface(
                    &s,
                    &line,
                    &samples,
                    &nodes,
                    PI / 10.0,
                    precision,
                    opts,
                )?;
                let mut r = points_result(case, "points", c, &[2, 1], Some(p));
                if case.nearest {
                    keep_nearest_hit(&mut r);
                }
                Ok(r)
            } else if let Some(r) = sphere_projection(case, spec, &p) {
                Ok(r)
            } else {
                let c = project::project_point_surface(&s, &p, &nodes, precision, opts)?;
                let nearest = case
                    .nearest
                    .then(|| nearest::nearest_point_surface(&s, &p, &c));
                Ok(projection_result(case, c, &[2], p, nearest))
            }
        }
        ObjectSpec::Curve3(spec) => {
            let c3 = at(spec.build(), "onto")?;
            let p = doubles::<3>(point, "point")?;
            let c = project::project_point_curve(&c3, &p, &curve_samples(&c3)?, precision, opts)?;
            let nearest = case
                .nearest
                .then(|| nearest::nearest_point_curve(&c3, &p, &c));
            Ok(projection_result(case, c, &[1], p, nearest))
        }
        ObjectSpec::Curve2(spec) => {
            let PlaneShape::Curve(c2) = at(spec.build(), "onto")? else {
                return Err(unsupported(
                    "onto",
                    "projection onto an implicit `conic2` is not implemented".into(),
                ));
            };
            let p = doubles::<2>(point, "point")?;
            let c = project::project_point_curve(&c2, &p, &curve_samples(&c2)?, precision, opts)?;
            let nearest = case
                .nearest
                .then(|| nearest::nearest_point_curve(&c2, &p, &c));
            Ok(projection_result(case, c, &[1], p, nearest))
        }
        _ => Err(unsupported("onto", "expected a curved object".into())),
    }
}

/// Projection onto a whole sphere in closed form ([`sphere_feet`]): both feet, complete
/// (the parametric search cannot finish there: every pole is a continuum of `(u, v)`
/// roots). At a pole `u` is any angle and its box is the whole circle. `None` for other
/// surfaces, and for the centre (left to the search, which says `undecided`).
fn sphere_projection(case: &Case, spec: &SurfaceSpec, p: &[f64; 3]) -> Option<CaseResult> {
    let SurfaceSpec::Sphere(s) = spec else {
        return None;
    };
    if s.domain.is_some() {
        return None;
    }
    let feet = sphere_feet(p, &s.center, s.radius)?;
    let keep = if case.nearest { 1 } else { 2 };
    let points = feet[..keep]
        .iter()
        .map(|(b, d)| {
            let uv = super::exact_curved::sphere_params(spec, b).unwrap_or_default();
            PointOut {
                xyz: b.iter().map(|x| x.midpoint()).collect(),
                params: vec![uv.iter().map(|x| x.0).collect()],
                bounds: bounds(b),
                param_box: Some(vec![uv.iter().map(|x| x.1).collect()]),
                multiplicity: 1,
                distance: Some(d.midpoint()),
                nearest: case.nearest.then_some(true),
                ..Default::default()
            }
        })
        .collect();
    let proof = Certified {
        value: (),
        status: Status::Verified,
        complete: true,
        arithmetic: crate::certificate::Arithmetic::Interval,
        bits: 53,
        reason: None,
        perturbation: None,
    };
    let mut r = CaseResult::certified(case.id.clone(), "points", &proof);
    r.points = Some(points);
    Some(r)
}

/// The feet of a projection, or with `nearest` the one nearest point and whether it
/// is proven ([`nearest`]).
fn projection_result<const D: usize>(
    case: &Case,
    feet: Certified<Vec<CertifiedPoint<D>>>,
    sizes: &[usize],
    p: [f64; D],
    nearest: Option<Option<Nearest<D>>>,
) -> CaseResult {
    let Some(nearest) = nearest else {
        return points_result(case, "points", feet, sizes, Some(p));
    };
    let complete = feet.complete;
    let mut r = points_result(case, "points", feet.clone(), sizes, Some(p));
    let Some(n) = nearest else {
        // No foot and no end: the nearest point lies on a surface's edge.
        r.status = Status::Undecided.as_str();
        r.kind = Some("empty");
        r.reason = Some(if complete {
            "no foot in the interior: the nearest point lies on the surface's boundary, which is not searched".into()
        } else {
            feet.reason
                .clone()
                .unwrap_or_else(|| "the search is incomplete".into())
        });
        return r;
    };
    let mut point = match &n.choice {
        NearestChoice::Foot(i) => {
            let mut pts = r.points.take().unwrap_or_default();
            r.status = feet.value[*i].root.status.as_str();
            pts.swap_remove(*i)
        }
        NearestChoice::End {
            t,
            t_box,
            point,
            point_box,
        } => {
            r.kind = Some("points");
            r.status = Status::Verified.as_str();
            PointOut {
                xyz: point.to_vec(),
                params: vec![vec![*t]],
                bounds: bounds(point_box),
                param_box: Some(vec![vec![[t_box.lo(), t_box.hi()]]]),
                multiplicity: 1,
                distance: Some(
                    point
                        .iter()
                        .zip(p)
                        .map(|(a, b)| (a - b) * (a - b))
                        .sum::<f64>()
                        .sqrt(),
                ),
                ..Default::default()
            }
        }
    };
    point.nearest = Some(true);
    r.points = Some(vec![point]);
    if n.status == Status::Undecided {
        r.status = Status::Undecided.as_str();
        r.reason = n.reason;
    } else {
        // The nearest point is proven: the answer (one point) is complete.
        r.complete = Some(true);
        r.reason = None;
    }
    r
}

/// `nearest` along a direction: the hit of smallest distance; proven only when the
/// hits are complete and its distance enclosure lies below every other's.
fn keep_nearest_hit(r: &mut CaseResult) {
    let Some(points) = r.points.as_mut() else {
        return;
    };
    if points.is_empty() {
        return;
    }
    points.sort_by(|a, b| {
        a.distance
            .unwrap_or(f64::INFINITY)
            .total_cmp(&b.distance.unwrap_or(f64::INFINITY))
    });
    // |t| along the ray, enclosed by the certified parameter box of each hit.
    let t_abs = |q: &PointOut| {
        q.param_box
            .as_ref()
            .and_then(|b| b.get(1))
            .and_then(|t| t.first())
            .map(|&[lo, hi]| Interval::from_bounds(lo, hi).abs())
    };
    let separated = match t_abs(&points[0]) {
        Some(t0) => points[1..]
            .iter()
            .all(|q| t_abs(q).is_some_and(|t| t0.hi() < t.lo())),
        None => false,
    };
    points.truncate(1);
    points[0].nearest = Some(true);
    if !(separated && r.complete == Some(true)) {
        r.status = Status::Undecided.as_str();
        r.reason = Some(
            "the nearest hit is not proven: the search is incomplete or two hits are not separated"
                .into(),
        );
    }
}

fn intersect_case(
    case: &Case,
    precision: &Precision,
    opts: &Options,
) -> Result<CaseResult, GeomError> {
    let field = |i: usize| format!("objects[{i}]");
    match case.objects.as_slice() {
        [ObjectSpec::Curve2(a), ObjectSpec::Curve2(b)] => {
            let (PlaneShape::Curve(ca), PlaneShape::Curve(cb)) =
                (at(a.build(), &field(0))?, at(b.build(), &field(1))?)
            else {
                return Err(unsupported("objects", "intersections with an implicit `conic2` are not implemented for the command line yet".into()));
            };
            let c = intersect::intersect_curve2_curve2(
                &ca,
                &cb,
                &curve_samples(&ca)?,
                &curve_samples(&cb)?,
                precision,
                opts,
            )?;
            Ok(points_result(case, "points", c, &[1, 1], None))
        }
        [a, b]
            if [a, b].iter().all(|o| {
                matches!(
                    o,
                    ObjectSpec::Curve3(_) | ObjectSpec::Line(_) | ObjectSpec::Segment(_)
                )
            }) =>
        {
            // Two space curves: a line without a range is cut to the other's box.
            let (ca, cb) = match (
                build_curve3(a, &field(0), None),
                build_curve3(b, &field(1), None),
            ) {
                (Ok(Some(ca)), Ok(Some(cb))) => (ca, cb),
                (Ok(Some(ca)), Err(_)) => {
                    let cb = build_curve3(b, &field(1), Some(&curve_box(&ca)))?;
                    (
                        ca,
                        cb.ok_or_else(|| unsupported(&field(1), "expected a space curve".into()))?,
                    )
                }
                (Err(_), Ok(Some(cb))) => {
                    let ca = build_curve3(a, &field(0), Some(&curve_box(&cb)))?;
                    (
                        ca.ok_or_else(|| unsupported(&field(0), "expected a space curve".into()))?,
                        cb,
                    )
                }
                (Err(e), _) | (_, Err(e)) => return Err(e),
                _ => return Err(unsupported("objects", "expected two space curves".into())),
            };
            let c = crate::ops::space_curves::intersect_curve_curve(&ca, &cb, opts);
            Ok(points_result(case, "points", c, &[1, 1], None))
        }
        [a, b] => {
            let (surface_first, s, curve_spec, cf) =
                match (build_surface(a, &field(0))?, build_surface(b, &field(1))?) {
                    (Some(s), None) => (true, s, b, field(1)),
                    (None, Some(s)) => (false, s, a, field(0)),
                    _ => {
                        return Err(unsupported(
                            "objects",
                            "intersect of these curved objects is not implemented".into(),
                        ))
                    }
                };
            let bound = surface_box(&s);
            let Some(curve) = build_curve3(curve_spec, &cf, Some(&bound))? else {
                return Err(unsupported(&cf, "expected a space curve".into()));
            };
            let nodes = surface_nodes(&s)?;
            let c = intersect::intersect_curve_surface(
                &s,
                &curve,
                &curve_samples(&curve)?,
                &nodes,
                PI / 10.0,
                precision,
                opts,
            )?;
            // Parameters in input order: the root is (u, v, t).
            let c = if surface_first {
                c
            } else {
                c.map(|ps| {
                    ps.into_iter()
                        .map(|mut p| {
                            p.root.params.rotate_right(1);
                            p.root.enclosure.rotate_right(1);
                            p
                        })
                        .collect()
                })
            };
            let sizes: &[usize] = if surface_first { &[2, 1] } else { &[1, 2] };
            Ok(points_result(case, "points", c, sizes, None))
        }
        [a, b, c] => {
            let (Some(r), Some(s), Some(q)) = (
                build_surface(a, &field(0))?,
                build_surface(b, &field(1))?,
                build_surface(c, &field(2))?,
            ) else {
                return Err(unsupported(
                    "objects",
                    "three-object intersections take three surfaces (or three planes)".into(),
                ));
            };
            let (nr, ns, nq) = (surface_nodes(&r)?, surface_nodes(&s)?, surface_nodes(&q)?);
            let c = intersect::intersect_three_surfaces(
                (&r, &s, &q),
                [&nr, &ns, &nq],
                precision,
                opts,
            )?;
            Ok(points_result(case, "points", c, &[2, 2, 2], None))
        }
        other => Err(GeomError::InvalidValue {
            field: "objects".into(),
            reason: format!("intersect takes 2 or 3 objects, found {}", other.len()),
        }),
    }
}

fn classify_case(
    case: &Case,
    precision: &Precision,
    opts: &Options,
) -> Result<CaseResult, GeomError> {
    let point = case.point.as_ref().ok_or_else(|| GeomError::Format {
        field: "point".into(),
        message: "missing field `point`".into(),
    })?;
    let p = doubles::<3>(point, "point")?;
    let Some(ObjectSpec::Surface(spec)) = &case.shell else {
        return Err(unsupported(
            "shell",
            "expected a polyhedron, sphere, ellipsoid or torus".into(),
        ));
    };
    // Validate through the surface builder (typed errors naming the field).
    let surface = at(spec.build(), "shell")?;
    use super::shapes::surface::SurfaceSpec as S;
    let closed = match spec {
        S::Sphere(s) => ClosedSurface::Sphere {
            center: s.center,
            radius: s.radius,
        },
        S::Ellipsoid(e) => ClosedSurface::Ellipsoid {
            center: e.center,
            radii: [e.a, e.b, e.c],
            axis: e.axis.unwrap_or([0.0, 0.0, 1.0]),
            reference: e.reference,
        },
        S::Torus(t) => ClosedSurface::Torus {
            center: t.center,
            major: t.major,
            minor: t.minor,
            axis: t.axis,
        },
        other => {
            return Err(unsupported(
                "shell.type",
                format!(
                    "`{}` is not a closed shell (sphere, ellipsoid, torus or polyhedron)",
                    other.type_name()
                ),
            ))
        }
    };
    let c = classify_point_surface(&p, &closed);
    let kind = c.value.as_str();
    let mut r = CaseResult::certified(case.id.clone(), kind, &c);
    // §4: the verdict comes with the nearest point of the shell, when it is proven.
    let nearest = match (&c.value, spec) {
        (Side::On, _) => Ok(exact_point(p)),
        (_, S::Sphere(s)) => nearest_on_sphere(&p, s.center, s.radius),
        _ => {
            let feet = project::project_point_surface(
                &surface,
                &p,
                &surface_nodes(&surface)?,
                precision,
                opts,
            )?;
            nearest_foot(&surface, &p, &feet)
        }
    };
    match nearest {
        Ok(mut point) => {
            point.nearest = Some(true);
            r.points = Some(vec![point]);
        }
        Err(why) => r.reason = Some(format!("the nearest point is not proven: {why}")),
    }
    Ok(r)
}

/// The query point itself, on the shell: its own nearest point at distance 0.
fn exact_point(p: [f64; 3]) -> PointOut {
    PointOut {
        xyz: p.to_vec(),
        bounds: p.iter().map(|&x| [x, x]).collect(),
        multiplicity: 1,
        distance: Some(0.0),
        ..Default::default()
    }
}

/// The nearest point of a sphere ([`sphere_feet`]), unique unless `p` is the centre.
fn nearest_on_sphere(p: &[f64; 3], center: [f64; 3], radius: f64) -> Result<PointOut, String> {
    let [(b, distance), _] = sphere_feet(p, &center, radius)
        .ok_or("the point is the centre: every point of the sphere is nearest")?;
    Ok(PointOut {
        xyz: b.iter().map(|x| x.midpoint()).collect(),
        bounds: bounds(&b),
        multiplicity: 1,
        distance: Some(distance.midpoint()),
        ..Default::default()
    })
}

/// The proven nearest of the certified feet ([`nearest::nearest_point_surface`]).
fn nearest_foot<S: Surface>(
    s: &S,
    p: &[f64; 3],
    feet: &Certified<Vec<CertifiedPoint<3>>>,
) -> Result<PointOut, String> {
    let n = nearest::nearest_point_surface(s, p, feet).ok_or("no foot was found")?;
    if n.status == Status::Undecided {
        return Err(n.reason.unwrap_or_default());
    }
    let NearestChoice::Foot(i) = n.choice else {
        return Err("the nearest point is not a foot".into());
    };
    let f = &feet.value[i];
    Ok(PointOut {
        xyz: f.point.to_vec(),
        params: vec![f.root.params.clone()],
        bounds: bounds(&f.point_box),
        param_box: Some(vec![f
            .root
            .enclosure
            .iter()
            .map(|x| [x.lo(), x.hi()])
            .collect()]),
        multiplicity: if f.root.is_singular() { 2 } else { 1 },
        distance: Some(n.distance.midpoint()),
        ..Default::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reach_of_a_line_covers_the_box() {
        let b = [Interval::from_bounds(-1.0, 1.0); 3];
        let (lo, hi) = reach(&[-5.0, 0.0, 0.0], &[2.0, 0.0, 0.0], Some(&b)).expect("bounded");
        assert!(lo <= 2.0 && hi >= 3.0 && hi - lo < 1.1);
        assert_eq!(reach(&[0.0; 3], &[1.0, 0.0, 0.0], None), None);
    }

    #[test]
    fn only_finite_boxes_bound_a_line() {
        let b = [
            Interval::from_bounds(f64::NEG_INFINITY, 1.0),
            Interval::from_bounds(0.0, 1.0),
            Interval::from_bounds(0.0, 1.0),
        ];
        assert_eq!(reach(&[0.0; 3], &[1.0, 0.0, 0.0], Some(&b)), None);
    }
}
