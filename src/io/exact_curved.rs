//! Curved intersections that are algebraic, decided exactly on the command line
//! (spec/CERTIFICATION.md `exact`; issue 6: tangential points `exact` where the problem
//! is algebraic): a `line` or `segment` against a `sphere`, an `ellipsoid` (any frame)
//! or a ring `torus` (OPERATIONS.md §5.2 with §1.6), and in the plane a `line2` /
//! `segment2` or a conic against `circle2`, `ellipse2` or `conic2` (§6.3–§6.4), through
//! [`crate::ops::algebraic`]. Shapes whose implicit form is not rational from the
//! doubles given, that carry a `domain`, or a spindle or horn
//! torus (whose §1.6 domain cuts the implicit surface) go to the numeric certifier.
//!
//! The exact solver works on the implicit equations and reports points; the
//! parameters of the parametric curves and surfaces are enclosed by interval inverses
//! of their parametrisations (`atan2` with a proven enclosure) over each point's
//! enclosure, so every reported `param_box` contains the exact parameters.

use rug::Rational;

use super::case::Case;
use super::number::Num;
use super::objects::{Line2Spec, LineSpec, ObjectSpec, Segment2Spec, SegmentSpec};
use super::result::{CaseResult, ExactOut, PointOut};
use super::shapes::curve::Curve2Spec;
use super::shapes::surface::SurfaceSpec;
use crate::certificate::Certified;
use crate::certify::univariate::RealRoot;
use crate::error::GeomError;
use crate::num::parse::parse_rational;
use crate::num::{Interval, Real};
use crate::ops::algebraic::{
    intersect_conic_conic, intersect_line_quadric_exact, intersect_line_torus_exact, ConicCut,
    LineCut, LineHit, QuadricForm, TorusData,
};
use crate::surface::frame::Frame;
use std::cmp::Ordering;

/// `Some(result)` when the intersect case is algebraic in the sense of the module doc.
pub fn try_exact(case: &Case) -> Option<Result<CaseResult, GeomError>> {
    match case.objects.as_slice() {
        [a, b] => {
            if let Some(r) = line_and_surface(case, a, b, false) {
                return Some(r);
            }
            if let Some(r) = line_and_surface(case, b, a, true) {
                return Some(r);
            }
            plane_pair(case, a, b)
        }
        _ => None,
    }
}

/// An exact line `o + t·d` with the parameter range it is restricted to.
struct ExactLine<const D: usize> {
    o: [Rational; D],
    d: [Rational; D],
    range: Option<[Rational; 2]>,
}

impl<const D: usize> ExactLine<D> {
    /// `(1 − t)·a + t·b`, `t ∈ range`.
    fn segment(a: [Rational; D], b: [Rational; D], range: [Rational; 2]) -> Self {
        ExactLine {
            d: std::array::from_fn(|i| Rational::from(&b[i] - &a[i])),
            o: a,
            range: Some(range),
        }
    }

    fn valid(self) -> Option<Self> {
        self.d
            .iter()
            .any(|x| x.cmp0() != Ordering::Equal)
            .then_some(self)
    }
}

/// A number of a linear object, exactly (`"p/q"` strings included); `None` sends the
/// case to the numeric path, which reports the error.
fn num(x: &Num) -> Option<Rational> {
    match x {
        Num::Double(v) => Rational::from_f64(*v),
        Num::Text(t) => parse_rational("", t).ok(),
    }
}

fn nums<const D: usize>(xs: &[Num]) -> Option<[Rational; D]> {
    let v: Vec<Rational> = xs.iter().map(num).collect::<Option<_>>()?;
    v.try_into().ok()
}

fn exact<const D: usize>(x: &[f64]) -> Option<[Rational; D]> {
    let v: Vec<Rational> = x
        .iter()
        .map(|&v| Rational::from_f64(v))
        .collect::<Option<_>>()?;
    v.try_into().ok()
}

fn unit() -> [Rational; 2] {
    [Rational::new(), Rational::from(1)]
}

fn line3(spec: &ObjectSpec) -> Option<ExactLine<3>> {
    match spec {
        ObjectSpec::Line(LineSpec { origin, dir, range }) => ExactLine {
            o: nums(origin)?,
            d: nums(dir)?,
            range: match range {
                Some(r) => Some(nums(r)?),
                None => None,
            },
        },
        ObjectSpec::Segment(SegmentSpec { a, b }) => ExactLine::segment(nums(a)?, nums(b)?, unit()),
        _ => return None,
    }
    .valid()
}

fn line2(spec: &ObjectSpec) -> Option<ExactLine<2>> {
    match spec {
        ObjectSpec::Line2(Line2Spec { origin, dir, range }) => ExactLine {
            o: nums(origin)?,
            d: nums(dir)?,
            range: match range {
                Some(r) => Some(nums(r)?),
                None => None,
            },
        },
        ObjectSpec::Segment2(Segment2Spec { a, b }) => {
            ExactLine::segment(nums(a)?, nums(b)?, unit())
        }
        ObjectSpec::Curve2(Curve2Spec::Line(l)) => ExactLine {
            o: exact(&l.origin)?,
            d: exact(&l.dir)?,
            range: match l.range {
                Some(r) => Some(exact(&r)?),
                None => None,
            },
        },
        ObjectSpec::Curve2(Curve2Spec::Segment(s)) => {
            let range = match s.domain {
                Some(r) => exact(&r)?,
                None => unit(),
            };
            ExactLine::segment(exact(&s.a)?, exact(&s.b)?, range)
        }
        _ => return None,
    }
    .valid()
}

/// The exact implicit form of a closed surface, with what inverts its parametrisation.
enum ClosedShape {
    /// Sphere or ellipsoid: local coordinates divided by the radii lie on the unit
    /// sphere, `u = atan2(y, x)`, `v = atan2(z, ρ)`.
    Quadric(QuadricForm<3>, Frame, [f64; 3]),
    /// Ring torus `R > r`: `u = atan2(y, x)`, `v = atan2(z, ρ − R)`.
    Torus(TorusData, Frame, f64),
}

fn closed_shape(spec: &SurfaceSpec) -> Option<ClosedShape> {
    let z = [0.0, 0.0, 1.0];
    match spec {
        SurfaceSpec::Sphere(s) if s.domain.is_none() => {
            let frame = Frame::new(s.center, s.axis.unwrap_or(z), s.reference).ok()?;
            let q = QuadricForm::sphere(s.center, s.radius).ok()?;
            Some(ClosedShape::Quadric(q, frame, [s.radius; 3]))
        }
        SurfaceSpec::Ellipsoid(e) if e.domain.is_none() => {
            let axis = e.axis.unwrap_or(z);
            let frame = Frame::new(e.center, axis, e.reference).ok()?;
            let q = QuadricForm::ellipsoid_in_frame(e.center, axis, e.reference, [e.a, e.b, e.c])
                .ok()?;
            Some(ClosedShape::Quadric(q, frame, [e.a, e.b, e.c]))
        }
        SurfaceSpec::Torus(t) if t.domain.is_none() && t.minor < t.major => {
            let frame = Frame::new(t.center, t.axis, t.reference).ok()?;
            let data = TorusData::new(t.center, t.axis, t.major, t.minor).ok()?;
            Some(ClosedShape::Torus(data, frame, t.major))
        }
        _ => None,
    }
}

/// The angle of `(x, y)` in `[0, 2π)`, enclosed: `atan2` or, near its branch cut on the
/// negative x-axis, `π + atan2(−y, −x)`, whichever is narrower; `[−π, 0)` shifted by
/// 2π. A box straddling the seam `t = 0` keeps its straddling enclosure.
fn angle(y: &Interval, x: &Interval) -> Interval {
    let pi = x.pi_like();
    let direct = y.atan2(x);
    let across = y.neg().atan2(&x.neg()) + pi;
    if across.width() < direct.width() {
        across
    } else if direct.hi() < 0.0 {
        direct + pi + pi
    } else {
        direct
    }
}

/// Estimate and enclosure of an angle parameter, the estimate in `[0, 2π)`; an empty
/// enclosure (the angle of the origin) stands for the whole circle.
fn param(b: Interval) -> (f64, [f64; 2]) {
    if b.is_empty() {
        // A point on the axis (a pole): every angle is its parameter.
        let two_pi = Interval::point(0.0).pi_like() * Interval::point(2.0);
        return (0.0, [0.0, two_pi.hi()]);
    }
    let mut m = b.midpoint();
    if m < 0.0 {
        m += 2.0 * std::f64::consts::PI;
    }
    (m, [b.lo(), b.hi()])
}

fn point_box<const D: usize>(h: &LineHit<D>) -> [Interval; D] {
    std::array::from_fn(|i| Interval::from_bounds(h.point[i].lo, h.point[i].hi))
}

/// `(u, v)` (estimate, enclosure) of the points of the box `b` on a sphere without a
/// `domain`; `None` for other shapes.
pub(super) fn sphere_params(spec: &SurfaceSpec, b: &[Interval; 3]) -> Option<Vec<(f64, [f64; 2])>> {
    match spec {
        SurfaceSpec::Sphere(_) => closed_shape(spec).map(|shape| surface_params(&shape, b)),
        _ => None,
    }
}

/// `(u, v)` of a point of a closed surface (module doc).
fn surface_params(shape: &ClosedShape, p: &[Interval; 3]) -> Vec<(f64, [f64; 2])> {
    let (frame, scale, major) = match shape {
        ClosedShape::Quadric(_, f, r) => (f, *r, 0.0),
        ClosedShape::Torus(_, f, major) => (f, [1.0; 3], *major),
    };
    let (q, _) = frame.to_local(p);
    let q: [Interval; 3] = std::array::from_fn(|i| q[i] / Interval::point(scale[i]));
    let rho = (q[0].sqr() + q[1].sqr()).sqrt();
    let u = angle(&q[1], &q[0]);
    let v = if major > 0.0 {
        param(angle(&q[2], &(rho - Interval::point(major))))
    } else {
        // The latitude, in [−π/2, π/2]: no wrapping.
        let v = q[2].atan2(&rho);
        (v.midpoint(), [v.lo(), v.hi()])
    };
    vec![param(u), v]
}

/// Compare the root `t` with the double `a`, exactly (refining an irrational root's
/// isolating interval until `a` lies outside it).
fn compare(t: &mut RealRoot, a: &Rational) -> Ordering {
    loop {
        let (lo, hi) = t.interval();
        if lo == hi {
            return lo.cmp(a);
        }
        if lo >= *a {
            return Ordering::Greater;
        }
        if hi <= *a {
            return Ordering::Less;
        }
        t.refine();
    }
}

fn in_range(t: &RealRoot, range: &Option<[Rational; 2]>) -> bool {
    let Some([a, b]) = range else {
        return true;
    };
    let mut t = t.clone();
    compare(&mut t, a) != Ordering::Less && compare(&mut t, b) != Ordering::Greater
}

/// The exact strings of a hit at a rational parameter.
fn exact_out<const D: usize>(
    line: &ExactLine<D>,
    t: &RealRoot,
    line_first: bool,
) -> Option<ExactOut> {
    let t = t.exact()?;
    let xyz = (0..D)
        .map(|i| (&line.o[i] + Rational::from(&line.d[i] * t)).to_string())
        .collect();
    let params = if line_first {
        vec![vec![t.to_string()], vec![]]
    } else {
        vec![vec![], vec![t.to_string()]]
    };
    Some(ExactOut {
        xyz,
        params,
        distance_squared: None,
    })
}

/// The result of a line cut, the line's parameter first or second as in the input.
fn line_cut_result<const D: usize>(
    case: &Case,
    line: &ExactLine<D>,
    mut cut: Certified<LineCut<D>>,
    other_params: impl Fn(&[Interval; D]) -> Vec<(f64, [f64; 2])>,
    line_first: bool,
) -> CaseResult {
    let contained = matches!(cut.value, LineCut::Contained);
    if let LineCut::Points(hits) = &mut cut.value {
        hits.retain(|h| in_range(&h.t, &line.range));
    }
    let points: Vec<PointOut> = cut
        .value
        .points()
        .iter()
        .map(|h| {
            let b = point_box(h);
            let t = h.t.rounded();
            let line_params = (vec![t.nearest], vec![[t.lo, t.hi]]);
            let other = other_params(&b);
            let other_params = (
                other.iter().map(|p| p.0).collect::<Vec<_>>(),
                other.iter().map(|p| p.1).collect::<Vec<_>>(),
            );
            let (first, second) = if line_first {
                (line_params, other_params)
            } else {
                (other_params, line_params)
            };
            PointOut {
                xyz: h.nearest().to_vec(),
                params: vec![first.0, second.0],
                bounds: b.iter().map(|x| [x.lo(), x.hi()]).collect(),
                param_box: Some(vec![first.1, second.1]),
                multiplicity: h.multiplicity,
                tangent: h.is_tangent(),
                exact: exact_out(line, &h.t, line_first),
                ..Default::default()
            }
        })
        .collect();
    let kind = if contained {
        "line"
    } else if points.is_empty() {
        "empty"
    } else {
        "points"
    };
    let mut r = CaseResult::certified(case.id.clone(), kind, &cut);
    if !contained {
        r.points = Some(points);
    }
    r
}

fn line_and_surface(
    case: &Case,
    line_spec: &ObjectSpec,
    surface_spec: &ObjectSpec,
    surface_first: bool,
) -> Option<Result<CaseResult, GeomError>> {
    let ObjectSpec::Surface(spec) = surface_spec else {
        return None;
    };
    let line = line3(line_spec)?;
    let shape = closed_shape(spec)?;
    let cut = match &shape {
        ClosedShape::Quadric(q, _, _) => intersect_line_quadric_exact(&line.o, &line.d, q),
        ClosedShape::Torus(t, _, _) => intersect_line_torus_exact(&line.o, &line.d, t),
    };
    Some(Ok(line_cut_result(
        case,
        &line,
        cut,
        |b| surface_params(&shape, b),
        !surface_first,
    )))
}

/// A plane conic with the inverse of its parametrisation (`None`: implicit).
struct PlaneConic {
    form: QuadricForm<2>,
    /// Centre and semi-axes of `circle2` / `ellipse2`: `t = atan2((y−c_y)/b, (x−c_x)/a)`.
    param: Option<([f64; 2], [f64; 2])>,
}

impl PlaneConic {
    fn params(&self, p: &[Interval; 2]) -> Vec<(f64, [f64; 2])> {
        let Some((c, r)) = self.param else {
            return Vec::new();
        };
        let local: [Interval; 2] =
            std::array::from_fn(|i| (p[i] - Interval::point(c[i])) / Interval::point(r[i]));
        vec![param(angle(&local[1], &local[0]))]
    }
}

fn plane_conic(spec: &ObjectSpec) -> Option<PlaneConic> {
    let ObjectSpec::Curve2(spec) = spec else {
        return None;
    };
    match spec {
        Curve2Spec::Circle(c) if c.domain.is_none() => {
            let r = c.radius?;
            Some(PlaneConic {
                form: QuadricForm::circle(c.center, r).ok()?,
                param: Some((c.center, [r, r])),
            })
        }
        Curve2Spec::Ellipse(e) if e.domain.is_none() => {
            let (a, b) = (e.a?, e.b?);
            let axes = [[1.0, 0.0], [0.0, 1.0]];
            Some(PlaneConic {
                form: QuadricForm::ellipse(e.center, axes, a, b).ok()??,
                param: Some((e.center, [a, b])),
            })
        }
        Curve2Spec::Conic(c) => Some(PlaneConic {
            form: QuadricForm::conic(c.coeffs).ok()?,
            param: None,
        }),
        _ => None,
    }
}

fn plane_pair(
    case: &Case,
    a: &ObjectSpec,
    b: &ObjectSpec,
) -> Option<Result<CaseResult, GeomError>> {
    // Validate the curved objects through their builders first (typed errors naming
    // the field).
    for (i, o) in [a, b].into_iter().enumerate() {
        if let ObjectSpec::Curve2(c) = o {
            if let Err(e) = c.build() {
                return Some(Err(e.at(&format!("objects[{i}]"))));
            }
        }
    }
    if let (Some(line), Some(conic)) = (line2(a), plane_conic(b)) {
        let cut = intersect_line_quadric_exact(&line.o, &line.d, &conic.form);
        return Some(Ok(line_cut_result(
            case,
            &line,
            cut,
            |p| conic.params(p),
            true,
        )));
    }
    if let (Some(conic), Some(line)) = (plane_conic(a), line2(b)) {
        let cut = intersect_line_quadric_exact(&line.o, &line.d, &conic.form);
        return Some(Ok(line_cut_result(
            case,
            &line,
            cut,
            |p| conic.params(p),
            false,
        )));
    }
    let (ca, cb) = (plane_conic(a)?, plane_conic(b)?);
    Some(intersect_conic_conic(&ca.form, &cb.form).map(|cut| conics_result(case, &ca, &cb, cut)))
}

fn conics_result(
    case: &Case,
    a: &PlaneConic,
    b: &PlaneConic,
    cut: Certified<ConicCut>,
) -> CaseResult {
    let kind = match &cut.value {
        ConicCut::Points(p) if p.is_empty() => "empty",
        ConicCut::Points(_) => "points",
        ConicCut::Coincident => "coincident",
        ConicCut::CommonComponent => "common_component",
    };
    let mut r = CaseResult::certified(case.id.clone(), kind, &cut);
    if let ConicCut::Points(hits) = &cut.value {
        r.points = Some(
            hits.iter()
                .map(|h| {
                    let pt: [Interval; 2] = std::array::from_fn(|i| {
                        Interval::from_bounds(h.point[i].lo, h.point[i].hi)
                    });
                    let (pa, pb) = (a.params(&pt), b.params(&pt));
                    PointOut {
                        xyz: h.nearest().to_vec(),
                        params: vec![
                            pa.iter().map(|p| p.0).collect(),
                            pb.iter().map(|p| p.0).collect(),
                        ],
                        bounds: pt.iter().map(|x| [x.lo(), x.hi()]).collect(),
                        param_box: Some(vec![
                            pa.iter().map(|p| p.1).collect(),
                            pb.iter().map(|p| p.1).collect(),
                        ]),
                        multiplicity: h.multiplicity,
                        tangent: h.multiplicity >= 2,
                        ..Default::default()
                    }
                })
                .collect(),
        );
    }
    r
}
