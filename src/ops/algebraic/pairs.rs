//! The algebraic pairs of the front door, decided exactly (docs/CERTIFICATES.md `exact`):
//! a line or segment against a whole sphere, ellipsoid (any frame) or ring torus
//! (OPERATIONS.md §5.2 with §1.6), and in the plane a 2D line or segment or a conic
//! against a whole `circle2`, `ellipse2` or a `conic2` (§6.3–§6.4). Shapes whose implicit
//! form is not rational from the doubles given, that are trimmed to a sub-domain, or a
//! spindle or horn torus (whose §1.6 domain cuts the implicit surface) are left to the
//! numeric certifier (`None`).
//!
//! The exact solver works on the implicit equations and reports points; the parameters
//! of the parametric curves and surfaces are enclosed by interval inverses of their
//! parametrisations (`atan2` with a proven enclosure) over each point's enclosure, so
//! every reported `param_box` contains the exact parameters.

use rug::Rational;
use std::cmp::Ordering;

pub(super) use super::exact_line::{angle, param, ExactLine};
use super::exact_spline::ExactCurve;
use super::params::{line_hit_params, ClosedFrame, Ellipse2, Param};
use super::{intersect_line_quadric_exact, intersect_line_torus_exact};
use super::{ConicCut, ConicHit, LineCut, LineHit, QuadricForm, TorusData};
use crate::certificate::{Certified, Status};
use crate::certify::univariate::RealRoot;
use crate::curve::analytic::Shape as CurveShape;
use crate::curve::{AnyCurve2, Curve};
use crate::error::GeomError;
use crate::num::round::round_rational;
use crate::num::Interval;
use crate::ops::answer::{Answer, ExactPoint, LineAnswer, ParamLine, Point, SegmentAnswer};
use crate::ops::closed_surface::is_closed_shell;
use crate::ops::rational::exact::compare_root as compare;
use crate::ops::rational::rounding::PRECISION_CAP;
use crate::ops::shape::{Linear, LinearObject, Shape};
use crate::surface::frame::Frame;
use crate::surface::AnySurface;

fn unit() -> [Rational; 2] {
    [Rational::new(), Rational::from(1)]
}

fn arr<const D: usize>(v: impl Iterator<Item = Rational>) -> [Rational; D] {
    let v: Vec<Rational> = v.collect();
    v.try_into().expect("dimension checked by the shape")
}

/// A 3D line or segment, exactly; `None` for a ray too (an [`ExactLine`] has a closed
/// range or none, so a ray would be answered as its whole carrier: rays take the
/// curved path, which cuts them to a closed span, `Linear::to_curve3`).
pub(super) fn line3(shape: &Linear) -> Option<ExactLine<3>> {
    match shape.exact() {
        LinearObject::Line(l) if l.is_ray() => None,
        LinearObject::Line(l) => Some(ExactLine {
            o: arr(l.origin().iter().cloned()),
            d: arr(l.dir().iter().cloned()),
            range: l.range().cloned(),
        }),
        LinearObject::Segment(s) => Some(ExactLine {
            o: arr(s.a().iter().cloned()),
            d: arr((0..3).map(|i| Rational::from(&s.b()[i] - &s.a()[i]))),
            range: Some(unit()),
        }),
        _ => None,
    }
}

/// A 2D line or segment, exactly.
fn line2(shape: &Shape) -> Option<ExactLine<2>> {
    let Shape::Linear(linear) = shape else {
        return None;
    };
    match linear.exact() {
        LinearObject::Line2(l) if l.is_ray() => None,
        LinearObject::Line2(l) => Some(ExactLine {
            o: arr(l.origin().iter().cloned()),
            d: arr(l.dir().iter().cloned()),
            range: l.range().cloned(),
        }),
        LinearObject::Segment2(s) => Some(ExactLine {
            o: arr(s.a().iter().cloned()),
            d: arr((0..2).map(|i| Rational::from(&s.b()[i] - &s.a()[i]))),
            range: Some(unit()),
        }),
        _ => None,
    }
}

/// The exact implicit form of a closed surface, with what inverts its parametrisation.
pub(crate) enum Closed {
    /// Sphere or ellipsoid: local coordinates divided by the radii lie on the unit
    /// sphere, `u = atan2(y, x)`, `v = atan2(z, ρ)`.
    Quadric(QuadricForm<3>, Frame, [f64; 3]),
    /// Ring torus `R > r`: `u = atan2(y, x)`, `v = atan2(z, ρ − R)`.
    Torus(TorusData, Frame, f64),
}

pub(super) fn closed(surface: &AnySurface) -> Option<Closed> {
    if !is_closed_shell(surface) {
        return None;
    }
    match surface {
        AnySurface::Sphere(s) => Some(Closed::Quadric(
            QuadricForm::of_surface(surface)?,
            s.frame().clone(),
            [s.radius(); 3],
        )),
        AnySurface::Ellipsoid(e) => Some(Closed::Quadric(
            QuadricForm::of_surface(surface)?,
            e.frame().clone(),
            e.semi_axes(),
        )),
        AnySurface::Torus(t) if t.minor() < t.major() => Some(Closed::Torus(
            TorusData::of_torus(t).ok()?,
            t.frame().clone(),
            t.major(),
        )),
        _ => None,
    }
}

pub(super) fn point_box<const D: usize>(h: &LineHit<D>) -> [Interval; D] {
    std::array::from_fn(|i| Interval::from_bounds(h.point[i].lo, h.point[i].hi))
}

/// `(u, v)` (estimate, enclosure) of the points of the box `b` on a whole sphere;
/// `None` for other surfaces.
pub(crate) fn sphere_params(
    surface: &AnySurface,
    b: &[Interval; 3],
) -> Option<Vec<(f64, [f64; 2])>> {
    match surface {
        AnySurface::Sphere(_) => closed(surface).map(|shape| surface_params(&shape, b)),
        _ => None,
    }
}

/// `(u, v)` of a point of a closed surface (module doc).
pub(super) fn surface_params(shape: &Closed, p: &[Interval; 3]) -> Vec<(f64, [f64; 2])> {
    let (frame, scale, major) = match shape {
        Closed::Quadric(_, f, r) => (f, *r, 0.0),
        Closed::Torus(_, f, major) => (f, [1.0; 3], *major),
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

fn in_range(t: &RealRoot, range: &Option<[Rational; 2]>) -> bool {
    let Some([a, b]) = range else {
        return true;
    };
    let mut t = t.clone();
    compare(&mut t, a) != Ordering::Less && compare(&mut t, b) != Ordering::Greater
}

/// The exact values of a hit at a rational parameter.
fn exact_point<const D: usize>(
    line: &ExactLine<D>,
    t: &RealRoot,
    line_first: bool,
) -> Option<ExactPoint> {
    let t = t.exact()?;
    let xyz = (0..D)
        .map(|i| &line.o[i] + Rational::from(&line.d[i] * t))
        .collect();
    let params = if line_first {
        vec![vec![t.clone()], vec![]]
    } else {
        vec![vec![], vec![t.clone()]]
    };
    Some(ExactPoint {
        xyz,
        params,
        distance_squared: None,
    })
}

/// A line lying on the curve or surface: the line itself, or for a segment or a
/// ranged line its end points (kind `segment`), with their parameters on the line.
fn contained<const D: usize>(line: &ExactLine<D>, line_first: bool) -> Answer {
    let nearest = |x: &Rational| round_rational(x).nearest;
    let order = |mine: Vec<f64>| {
        if line_first {
            vec![mine, vec![]]
        } else {
            vec![vec![], mine]
        }
    };
    let Some(range) = &line.range else {
        let params = vec![Some(ParamLine {
            origin: vec![0.0],
            dir: vec![1.0],
        })];
        let mut params = params;
        params.insert(usize::from(line_first), None);
        return Answer::Line(LineAnswer {
            point: line.o.iter().map(nearest).collect(),
            dir: line.d.iter().map(nearest).collect(),
            params,
            exact: None,
        });
    };
    let end = |t: &Rational| {
        let xyz: Vec<Rational> = (0..D)
            .map(|i| Rational::from(&line.d[i] * t) + &line.o[i])
            .collect();
        let r: Vec<_> = xyz.iter().map(round_rational).collect();
        let tr = round_rational(t);
        let bounds = |v: Vec<f64>, b: Vec<[f64; 2]>| (v, b);
        let (params, param_box) = bounds(vec![tr.nearest], vec![[tr.lo, tr.hi]]);
        Point {
            xyz: r.iter().map(|x| x.nearest).collect(),
            xyz_box: r.iter().map(|x| [x.lo, x.hi]).collect(),
            params: order(params),
            param_box: Some(if line_first {
                vec![param_box, vec![]]
            } else {
                vec![vec![], param_box]
            }),
            multiplicity: 1,
            ..Default::default()
        }
    };
    Answer::Segment(SegmentAnswer {
        a: end(&range[0]),
        b: end(&range[1]),
    })
}

/// The answer of a line cut, the line's parameter first or second as in the input.
pub(super) fn line_cut_answer<const D: usize>(
    line: &ExactLine<D>,
    mut cut: Certified<LineCut<D>>,
    other_params: impl Fn(&LineHit<D>, &[Interval; D]) -> Rounding,
    line_first: bool,
) -> Certified<Answer> {
    if matches!(cut.value, LineCut::Contained) {
        return cut.clone_with(contained(line, line_first));
    }
    if let LineCut::Points(hits) = &mut cut.value {
        hits.retain(|h| in_range(&h.t, &line.range));
    }
    let mut all_rounded = true;
    let points: Vec<Point> = cut
        .value
        .points()
        .iter()
        .map(|h| {
            let b = point_box(h);
            let t = h.t.rounded();
            let line_params = (vec![t.nearest], vec![[t.lo, t.hi]]);
            let (other, rounded) = other_params(h, &b);
            all_rounded &= rounded;
            let other_params = (
                other.iter().map(|p| p.0).collect::<Vec<_>>(),
                other.iter().map(|p| p.1).collect::<Vec<_>>(),
            );
            let (first, second) = if line_first {
                (line_params, other_params)
            } else {
                (other_params, line_params)
            };
            Point {
                xyz: h.nearest().to_vec(),
                xyz_box: b.iter().map(|x| [x.lo(), x.hi()]).collect(),
                params: vec![first.0, second.0],
                param_box: Some(vec![first.1, second.1]),
                multiplicity: h.multiplicity,
                tangent: h.is_tangent(),
                exact: exact_point(line, &h.t, line_first),
                ..Default::default()
            }
        })
        .collect();
    let mut r = cut.clone_with(Answer::from_points(points));
    if !all_rounded {
        not_correctly_rounded(&mut r);
    }
    r
}

/// Parameters of a hit, and whether they are correctly rounded (else their boxes still
/// hold the exact values, from interval inverses).
type Rounding = (Vec<Param>, bool);

/// An exact answer with a parameter that Ziv's loop could not round within its cap:
/// every number is still enclosed, but `exact` promises correct rounding.
pub(super) fn not_correctly_rounded(r: &mut Certified<Answer>) {
    r.status = r.status.weakest(Status::Verified);
    r.reason = Some(format!(
        "a parameter could not be correctly rounded within {PRECISION_CAP} bits; its box holds the exact value"
    ));
}

/// A line or segment against a whole sphere, ellipsoid or ring torus; `None` when the
/// pair is not one of these.
pub(crate) fn line_surface(
    line: &Linear,
    surface: &AnySurface,
    line_first: bool,
) -> Option<Certified<Answer>> {
    let line = line3(line)?;
    line_surface_exact(&line, surface, line_first)
}

/// The line `p + t·d` (doubles taken exactly, `d ≠ 0`) against a surface, as
/// [`line_surface_exact`] with the surface's parameters first: the hits of a
/// projection along a direction (§3.5).
pub(crate) fn ray_surface(
    p: [f64; 3],
    d: [f64; 3],
    surface: &AnySurface,
) -> Option<Certified<Answer>> {
    let (o, d) = crate::ops::rational::exact::exact_line(&p, &d).ok()?;
    line_surface_exact(&ExactLine { o, d, range: None }, surface, false)
}

/// [`line_surface`] on an exact line; also a whole-turn cone or paraboloid through its
/// implicit form ([`super::apex_line`]), which decides lines through the apex.
pub(super) fn line_surface_exact(
    line: &ExactLine<3>,
    surface: &AnySurface,
    line_first: bool,
) -> Option<Certified<Answer>> {
    if let Some(r) = super::apex_line::line_apex_surface(line, surface, line_first) {
        return Some(r);
    }
    let shape = closed(surface)?;
    let cut = match &shape {
        Closed::Quadric(q, _, _) => intersect_line_quadric_exact(&line.o, &line.d, q),
        Closed::Torus(t, _, _) => intersect_line_torus_exact(&line.o, &line.d, t),
    };
    let frame = frame_of(&shape);
    let params =
        |h: &LineHit<3>, b: &[Interval; 3]| match line_hit_params(&frame, &line.o, &line.d, &h.t) {
            Some(p) => (p, true),
            None => (surface_params(&shape, b), false),
        };
    Some(line_cut_answer(line, cut, params, line_first))
}

/// A space curve against a plane of the linear kernel, exactly where the restriction
/// is algebraic: the framed conics ([`super::conic_plane`]); `None` for other pairs,
/// and for a Bézier or NURBS curve whose rounding is still refining at `deadline`.
/// Against a line, ray or segment of space: the framed conics
/// ([`super::line_conic3`]).
pub(crate) fn curve_plane(
    plane: &Linear,
    curve: &crate::curve::AnyCurve3,
    curve_first: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let Some(plane) = super::conic_plane::exact_plane(plane) else {
        return match curve {
            crate::curve::AnyCurve3::Analytic(c) => {
                super::line_conic3::line_conic(plane, c, curve_first)
            }
            _ => None,
        };
    };
    match curve {
        crate::curve::AnyCurve3::Analytic(c) => {
            super::conic_plane::conic_plane(c, &plane, curve_first)
        }
        crate::curve::AnyCurve3::Bezier(b) => {
            super::bezier_plane::spline_plane(&ExactCurve::bezier(b), &plane, curve_first, deadline)
        }
        crate::curve::AnyCurve3::Nurbs(b) => {
            super::bezier_plane::spline_plane(&ExactCurve::nurbs(b), &plane, curve_first, deadline)
        }
        _ => None,
    }
}

/// A plane conic with the inverse of its parametrisation (`None`: implicit).
pub(super) struct PlaneConic {
    pub(super) form: QuadricForm<2>,
    /// Centre and semi-axes of `circle2` / `ellipse2`: `t = atan2((y−c_y)/b, (x−c_x)/a)`.
    pub(super) param: Option<Ellipse2>,
}

impl PlaneConic {
    /// The parameter of a hit of a line, correctly rounded where it can be.
    fn line_hit(&self, line: &ExactLine<2>, h: &LineHit<2>, b: &[Interval; 2]) -> Rounding {
        match self.param.map(|e| e.line_hit(&line.o, &line.d, &h.t)) {
            None => (vec![], true),
            Some(Some(t)) => (vec![t], true),
            Some(None) => (self.params(b), false),
        }
    }

    /// The parameter of a point with algebraic coordinates, correctly rounded where it
    /// can be.
    pub(super) fn point(&self, h: &ConicHit, b: &[Interval; 2]) -> Rounding {
        match self.param.map(|e| e.point(&h.x, &h.y)) {
            None => (vec![], true),
            Some(Some(t)) => (vec![t], true),
            Some(None) => (self.params(b), false),
        }
    }

    /// Interval inverses of the parametrisation over a box (not correctly rounded).
    fn params(&self, p: &[Interval; 2]) -> Vec<(f64, [f64; 2])> {
        let Some(Ellipse2 { center: c, axes: r }) = self.param else {
            return Vec::new();
        };
        let local: [Interval; 2] =
            std::array::from_fn(|i| (p[i] - Interval::point(c[i])) / Interval::point(r[i]));
        vec![param(angle(&local[1], &local[0]))]
    }
}

pub(super) fn plane_conic(shape: &Shape) -> Option<PlaneConic> {
    match shape {
        Shape::Curve2(AnyCurve2::Analytic(c)) if c.is_closed() => {
            let (form, axes) = match c.shape() {
                CurveShape::Circle { radius } => {
                    (QuadricForm::circle(c.center(), radius).ok()?, [radius; 2])
                }
                CurveShape::Ellipse { a, b } => {
                    let axes = [[1.0, 0.0], [0.0, 1.0]];
                    (QuadricForm::ellipse(c.center(), axes, a, b).ok()??, [a, b])
                }
                _ => return None,
            };
            Some(PlaneConic {
                form,
                param: Some(Ellipse2 {
                    center: c.center(),
                    axes,
                }),
            })
        }
        Shape::Conic2(c) => Some(PlaneConic {
            form: QuadricForm::conic(c.coeffs()).ok()?,
            param: None,
        }),
        _ => None,
    }
}

/// Two plane shapes of which one is a conic and the other a 2D line, segment or
/// conic; `None` for other pairs. Past `deadline` a Bézier curve is left to the
/// numeric path and two conics are `undecided` ("time limit reached").
pub(crate) fn plane_pair(
    a: &Shape,
    b: &Shape,
    deadline: Option<std::time::Instant>,
) -> Option<Result<Certified<Answer>, GeomError>> {
    if let Some(r) = spline_pair(a, b, deadline) {
        return Some(Ok(r));
    }
    if let (Some(line), Some(conic)) = (line2(a), plane_conic(b)) {
        let cut = intersect_line_quadric_exact(&line.o, &line.d, &conic.form);
        let params = |h: &LineHit<2>, b: &[Interval; 2]| conic.line_hit(&line, h, b);
        return Some(Ok(line_cut_answer(&line, cut, params, true)));
    }
    if let (Some(conic), Some(line)) = (plane_conic(a), line2(b)) {
        let cut = intersect_line_quadric_exact(&line.o, &line.d, &conic.form);
        let params = |h: &LineHit<2>, b: &[Interval; 2]| conic.line_hit(&line, h, b);
        return Some(Ok(line_cut_answer(&line, cut, params, false)));
    }
    let (ca, cb) = (plane_conic(a)?, plane_conic(b)?);
    Some(
        super::conic_conic::intersect_conic_conic_until(&ca.form, &cb.form, deadline)
            .map(|cut| conics_answer(&ca, &cb, cut)),
    )
}

/// A 2D line or segment ([`super::bezier_line2`]), a whole conic
/// ([`super::bezier_conic2`]) or a spline of conic arcs ([`super::conic_arcs`]) against
/// a Bézier or NURBS curve, in either order; `None`
/// for other pairs or when not decided exactly (or not before `deadline`).
fn spline_pair(
    a: &Shape,
    b: &Shape,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let exact = |c: &AnyCurve2| match c {
        AnyCurve2::Bezier(c) => Some(ExactCurve::bezier(c)),
        AnyCurve2::Nurbs(c) => Some(ExactCurve::nurbs(c)),
        _ => None,
    };
    let as_curve = |s: &Shape| match s {
        Shape::Curve2(c) => exact(c),
        _ => None,
    };
    let (curve, other, curve_first) = match as_curve(a) {
        Some(c) => (c, b, true),
        None => (as_curve(b)?, a, false),
    };
    if let Some(arcs) = as_curve(other) {
        return super::conic_arcs::spline_conic_arcs(&curve, &arcs, curve_first, deadline).or_else(
            || super::conic_arcs::spline_conic_arcs(&arcs, &curve, !curve_first, deadline),
        );
    }
    if let Some(line) = line2(other) {
        return super::bezier_line2::spline_line2(
            &curve,
            &line.o,
            &line.d,
            line.range.as_ref(),
            curve_first,
            deadline,
        );
    }
    let conic = plane_conic(other)?;
    super::bezier_conic2::spline_conic2(&curve, &conic.form, conic.param, curve_first, deadline)
}

fn conics_answer(a: &PlaneConic, b: &PlaneConic, cut: Certified<ConicCut>) -> Certified<Answer> {
    let mut all_rounded = true;
    let value = match &cut.value {
        ConicCut::Coincident => Answer::Coincident,
        ConicCut::CommonComponent => Answer::CommonComponent,
        ConicCut::Points(hits) => Answer::from_points(
            hits.iter()
                .map(|h| {
                    let pt: [Interval; 2] = std::array::from_fn(|i| {
                        Interval::from_bounds(h.point[i].lo, h.point[i].hi)
                    });
                    let ((pa, ra), (pb, rb)) = (a.point(h, &pt), b.point(h, &pt));
                    all_rounded &= ra && rb;
                    Point {
                        xyz: h.nearest().to_vec(),
                        xyz_box: pt.iter().map(|x| [x.lo(), x.hi()]).collect(),
                        params: vec![
                            pa.iter().map(|p| p.0).collect(),
                            pb.iter().map(|p| p.0).collect(),
                        ],
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
        ),
    };
    let mut r = cut.clone_with(value);
    if !all_rounded {
        not_correctly_rounded(&mut r);
    }
    r
}

/// The frame that inverts a closed surface's parametrisation.
pub(super) fn frame_of(c: &Closed) -> ClosedFrame<'_> {
    match c {
        Closed::Quadric(_, f, r) => ClosedFrame {
            frame: f,
            scale: *r,
            major: None,
        },
        Closed::Torus(_, f, major) => ClosedFrame {
            frame: f,
            scale: [1.0; 3],
            major: Some(*major),
        },
    }
}
