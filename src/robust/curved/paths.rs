//! One curved case through geocert's two paths, graded against [`super::truth`]:
//! - the float path: the `_f64` solvers ([`intersect_curve_surface_f64`],
//!   [`intersect_curve_curve_f64`]) seeded by the float walks of OPERATIONS.md §2, as the
//!   front door seeds them (no proof);
//! - the certified front door [`crate::ops::intersect()`].

use nalgebra::Vector3;
use rug::Float;
use std::f64::consts::PI;

use super::truth::{truth, Truth, PREC};
use super::{CurvedCase, Data};
use crate::certificate::{Arithmetic, Status};
use crate::curve::{
    Analytic, Analytic2, AnyCurve2, AnyCurve3, Curve, Frame, NurbsCurve, Shape as Conic,
};
use crate::error::GeomError;
use crate::geom::Line as KernelLine;
use crate::ops::float::Precision;
use crate::ops::intersect::{intersect_curve_curve_f64, intersect_curve_surface_f64};
use crate::ops::{intersect, Answer, Options, Shape};
use crate::surface::quadrics::Sphere;
use crate::surface::torus::Torus;
use crate::surface::Surface;
use crate::walk::surface::{SurfaceWalk, SurfaceWalkOptions};
use crate::walk::{CurveWalk, WalkOptions};

/// A float point is "off" when it is farther than `TOLERANCE·scale` from every true
/// point (scale: [`CurvedCase::scale`]); `√ε ≈ 1.5·10⁻⁸` is the accuracy a double
/// root allows in doubles, so this asks for a little better than that.
pub const TOLERANCE: f64 = 1e-9;

/// The turning angle of the seeding walks: the front door's (`π/10`, §2.3).
const TURN: f64 = PI / 10.0;

/// How one case went.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Outcome {
    /// The true number of distinct common points.
    pub truth_count: usize,
    /// The float path found another number of points.
    pub float_wrong_count: bool,
    /// The right number, but a point more than the tolerance from the truth.
    pub float_off: bool,
    /// The certified answer claims something false: a simple box (of a status other
    /// than `undecided`) not holding exactly one true point, a singular box holding more
    /// than two (with multiplicity), or with `complete` a true point outside every box,
    /// or an `exact`/`verified` count or tangency that is not the truth's, or two simple
    /// boxes on one true point (a solution reported twice, e.g. once per side of a seam).
    pub certified_wrong: bool,
    /// `undecided`, or not `complete`, or an error from the front door.
    pub certified_undecided: bool,
    /// The arithmetic and precision that decided the certified answer.
    pub arithmetic: Option<Arithmetic>,
    pub bits: u32,
}

/// Run and grade `case`. Errors only if a shape is refused (the generators make valid
/// shapes; the caller counts it as undecided).
pub fn run(case: &CurvedCase) -> Outcome {
    let truth = truth(case);
    let mut out = Outcome {
        truth_count: truth.count(),
        ..Outcome::default()
    };
    let tol = TOLERANCE * case.scale();
    match float_points(&case.data) {
        Ok(points) => {
            if points.len() != truth.count() {
                out.float_wrong_count = true;
            } else {
                out.float_off = !matches(&points, &truth, tol);
            }
        }
        Err(_) => out.float_wrong_count = truth.count() != 0,
    }
    match certified(&case.data) {
        Ok(c) => {
            out.arithmetic = Some(c.arithmetic);
            out.bits = c.bits;
            out.certified_undecided = c.status == Status::Undecided || !c.complete;
            out.certified_wrong = !holds(&c, &truth, &case.data, case.scale());
        }
        Err(_) => out.certified_undecided = true,
    }
    out
}

fn dist2(p: &[f64], t: &[Float]) -> f64 {
    p.iter()
        .zip(t)
        .map(|(x, y)| (Float::with_val(PREC, y - *x).to_f64()).powi(2))
        .sum()
}

/// Each float point near a true point and each true point near a float point.
fn matches(points: &[Vec<f64>], truth: &Truth, tol: f64) -> bool {
    let near = |p: &Vec<f64>, t: &[Float]| dist2(p, t).sqrt() <= tol;
    points
        .iter()
        .all(|p| truth.points.iter().any(|t| near(p, &t.xyz)))
        && truth
            .points
            .iter()
            .all(|t| points.iter().any(|p| near(p, &t.xyz)))
}

/// The slack of the box test, relative to the case's scale: the 300-bit truth is a few
/// correctly rounded operations on numbers below 2¹⁰ away from the exact point (error
/// far below 2⁻²⁸⁰·scale), so a box is judged wrong only when the true point lies
/// outside it by more than 2⁻²⁵⁰·scale: a wrong verdict is then certain, and a box that
/// misses the truth by less is not caught (none can be that close to a double edge
/// without holding it for these data).
const SLACK: f64 = 5.527147875260445e-76; // 2⁻²⁵⁰

/// Whether the box `b` holds the 300-bit point `t`, up to `slack`.
fn inside(b: &[[f64; 2]], t: &[Float], slack: f64) -> bool {
    b.len() == t.len()
        && b.iter().zip(t).all(|(&[lo, hi], x)| {
            let below = Float::with_val(PREC, lo - x);
            let above = Float::with_val(PREC, x - hi);
            below <= slack && above <= slack
        })
}

/// Whether the certified answer's claims hold for the truth (see [`Outcome`]).
fn holds(c: &crate::Certified<Answer>, truth: &Truth, data: &Data, scale: f64) -> bool {
    if c.status == Status::Undecided {
        return true;
    }
    let points: &[crate::ops::Point] = match &c.value {
        Answer::Empty => &[],
        Answer::Points(ps) => ps,
        _ => return false,
    };
    let slack = SLACK * scale;
    let boxed = |p: &crate::ops::Point, t: &[Float]| inside(&p.xyz_box, t, slack);
    // A simple box (multiplicity 1) holds exactly one true point; a singular box of a
    // `verified_singular` answer holds at most two counted with multiplicity, possibly
    // none (CERTIFICATION.md: a double root of a perturbed input).
    let singular = c.status == Status::VerifiedSingular;
    let box_holds = |p: &crate::ops::Point| {
        let inside: Vec<u32> = truth
            .points
            .iter()
            .filter(|t| boxed(p, &t.xyz))
            .map(|t| t.multiplicity)
            .collect();
        if singular && p.multiplicity > 1 {
            inside.iter().sum::<u32>() <= 2
        } else {
            inside.len() == 1
        }
    };
    if !points.iter().all(box_holds) {
        return false;
    }
    // Each true point a box holds has its parameters in the point's parameter boxes.
    let params_hold = |p: &crate::ops::Point| {
        truth
            .points
            .iter()
            .filter(|t| boxed(p, &t.xyz))
            .all(|t| params_in(p, &t.xyz, data, scale))
    };
    if !points.iter().all(params_hold) {
        return false;
    }
    // Two simple boxes on one true point: a solution reported twice (a seam copy).
    let simple = |p: &&crate::ops::Point| p.multiplicity == 1 && !p.tangent;
    let twice = truth.points.iter().any(|t| {
        points
            .iter()
            .filter(simple)
            .filter(|p| boxed(p, &t.xyz))
            .count()
            > 1
    });
    if twice {
        return false;
    }
    if !c.complete {
        return true;
    }
    if !truth
        .points
        .iter()
        .all(|t| points.iter().any(|p| boxed(p, &t.xyz)))
    {
        return false;
    }
    match c.status {
        Status::Exact | Status::Verified => {
            points.len() == truth.count()
                && points.iter().all(|p| {
                    let t = truth.points.iter().find(|t| boxed(p, &t.xyz));
                    t.is_some_and(|t| (t.multiplicity > 1) == (p.multiplicity > 1))
                })
        }
        _ => true,
    }
}

/// The true parameters of the point `x` on each shape of `data`, in input order, at
/// [`PREC`] bits, from closed forms of the parametrisations (not the solvers'):
/// `None` where no closed form is used here (space circles and NURBS curves, whose
/// parameters depend on their frames and knots) or where a parameter is undefined (the
/// longitude at a sphere's pole); `Some(period)` marks an angle, compared modulo `2π`.
fn true_params(data: &Data, x: &[Float]) -> Vec<Vec<Option<(Float, bool)>>> {
    let sub = |a: &Float, b: f64| Float::with_val(PREC, a - b);
    let atan2 = |y: Float, x: Float| Some((y.atan2(&x), true));
    // `t` on `o + t·d`: `(x − o)·d / |d|²`.
    let line_t = |o: &[f64], d: &[f64]| {
        let mut num = Float::with_val(PREC, 0);
        let mut den = Float::with_val(PREC, 0);
        for i in 0..o.len() {
            num += sub(&x[i], o[i]) * d[i];
            den += Float::with_val(PREC, d[i] * d[i]);
        }
        vec![Some((num / den, false))]
    };
    let circle_t = |c: &[f64]| vec![atan2(sub(&x[1], c[1]), sub(&x[0], c[0]))];
    // Sphere about +z, reference +x: u the longitude (undefined on the axis), v the
    // latitude.
    let sphere_uv = |c: &[f64]| {
        let (dx, dy, dz) = (sub(&x[0], c[0]), sub(&x[1], c[1]), sub(&x[2], c[2]));
        let rho = Float::with_val(PREC, dx.hypot_ref(&dy));
        let on_axis = rho.is_zero();
        let v = Some((dz.atan2(&rho), false));
        let u = if on_axis { None } else { atan2(dy, dx) };
        vec![u, v]
    };
    match data {
        Data::LineSphere { o, d, c, .. } => vec![line_t(o, d), sphere_uv(c)],
        Data::LineTorus { o, d, c, major, .. } => {
            let (dx, dy, dz) = (sub(&x[0], c[0]), sub(&x[1], c[1]), sub(&x[2], c[2]));
            let rho = Float::with_val(PREC, dx.hypot_ref(&dy));
            let v = atan2(dz, rho - *major);
            vec![line_t(o, d), vec![atan2(dy, dx), v]]
        }
        Data::Circles2 { c1, c2, .. } => vec![circle_t(c1), circle_t(c2)],
        Data::CircleEllipse2 { c, e, a, b, .. } => {
            let t = atan2(sub(&x[1], e[1]) / *b, sub(&x[0], e[0]) / *a);
            vec![circle_t(c), vec![t]]
        }
        Data::CircleSphere { c, .. } | Data::NurbsCircleSphere { c, .. } => {
            vec![vec![None], sphere_uv(c)]
        }
    }
}

/// Whether the parameter boxes of `p` hold the true parameters of the true point `x`
/// (angles modulo `2π`: a box may sit at either copy of a seam), up to an absolute
/// slack of `2⁻²⁵⁰` for angles and `2⁻²⁵⁰·max(scale, 1)` for line parameters — far
/// above the 300-bit truth's error, far below any double's spacing here.
fn params_in(p: &crate::ops::Point, x: &[Float], data: &Data, scale: f64) -> bool {
    let Some(boxes) = &p.param_box else {
        return true;
    };
    let truth = true_params(data, x);
    let two_pi = Float::with_val(PREC, rug::float::Constant::Pi) * 2u32;
    boxes.iter().zip(&truth).all(|(bs, ts)| {
        bs.len() != ts.len()
            || bs.iter().zip(ts).all(|(&[lo, hi], t)| {
                let Some((t, angle)) = t else { return true };
                let slack = if *angle {
                    SLACK
                } else {
                    SLACK * scale.max(1.0)
                };
                let within = |y: &Float| {
                    Float::with_val(PREC, lo - y) <= slack && Float::with_val(PREC, y - hi) <= slack
                };
                within(t)
                    || (*angle
                        && (within(&Float::with_val(PREC, t + &two_pi))
                            || within(&Float::with_val(PREC, t - &two_pi))))
            })
    })
}

fn sphere(c: &[f64; 3], r: f64) -> Result<Sphere, GeomError> {
    Sphere::new(*c, r, None, None)
}

fn torus(c: &[f64; 3], major: f64, minor: f64) -> Result<Torus, GeomError> {
    Torus::new(*c, major, minor, [0.0, 0.0, 1.0], None)
}

fn circle3(q: &[f64; 3], n: &[f64; 3], rho: f64) -> Result<Analytic, GeomError> {
    Analytic::new(
        Frame::new(*q, *n, None)?,
        Conic::Circle { radius: rho },
        None,
    )
}

/// The exact NURBS circle of [`super::seams::nurbs_circle`].
fn nurbs_circle(q: &[f64; 3], rho: f64, start: [i64; 3]) -> Result<NurbsCurve<3>, GeomError> {
    let (points, weights) = super::seams::nurbs_circle(q, rho, start);
    NurbsCurve::new(
        2,
        super::seams::NURBS_CIRCLE_KNOTS.to_vec(),
        points,
        Some(weights),
        None,
    )
}

fn circle2(c: &[f64; 2], r: f64) -> Result<Analytic2, GeomError> {
    Analytic2::new(*c, Conic::Circle { radius: r }, None)
}

fn ellipse2(e: &[f64; 2], a: f64, b: f64) -> Result<Analytic2, GeomError> {
    Analytic2::new(*e, Conic::Ellipse { a, b }, None)
}

/// The part of the line `o + t·d` within `reach` of `c` (a superset of the hits).
fn clipped_line(o: &[f64; 3], d: &[f64; 3], c: &[f64; 3], reach: f64) -> crate::curve::Line<3> {
    let dd: f64 = d.iter().map(|x| x * x).sum();
    let t0 = -(0..3).map(|i| d[i] * (o[i] - c[i])).sum::<f64>() / dd;
    let half = 1.5 * reach / dd.sqrt() + 1.0;
    crate::curve::Line::new(*o, *d, Some((t0 - half, t0 + half)))
        .expect("finite data, nonzero direction")
}

/// The float path's points.
fn float_points(data: &Data) -> Result<Vec<Vec<f64>>, GeomError> {
    let p = Precision::default();
    match data {
        Data::LineSphere { o, d, c, r } => {
            let s = sphere(c, *r)?;
            let l = clipped_line(o, d, c, *r);
            curve_surface(&s, &l, &p)
        }
        Data::LineTorus {
            o,
            d,
            c,
            major,
            minor,
        } => {
            let s = torus(c, *major, *minor)?;
            let l = clipped_line(o, d, c, major + minor);
            curve_surface(&s, &l, &p)
        }
        Data::CircleSphere { q, n, rho, c, r } => {
            curve_surface(&sphere(c, *r)?, &circle3(q, n, *rho)?, &p)
        }
        Data::NurbsCircleSphere {
            q,
            start,
            rho,
            c,
            r,
        } => curve_surface(&sphere(c, *r)?, &nurbs_circle(q, *rho, *start)?, &p),
        Data::Circles2 { c1, r1, c2, r2 } => {
            let (a, b) = (circle2(c1, *r1)?, circle2(c2, *r2)?);
            let (sa, sb) = (walk(&a)?, walk(&b)?);
            Ok(point_list(intersect_curve_curve_f64(&a, &b, &sa, &sb, &p)))
        }
        Data::CircleEllipse2 { c, rho, e, a, b } => {
            let (x, y) = (circle2(c, *rho)?, ellipse2(e, *a, *b)?);
            let (sx, sy) = (walk(&x)?, walk(&y)?);
            Ok(point_list(intersect_curve_curve_f64(&x, &y, &sx, &sy, &p)))
        }
    }
}

fn point_list<const D: usize>(ps: Vec<crate::ops::intersect::CurveCurvePoint<D>>) -> Vec<Vec<f64>> {
    ps.into_iter().map(|p| p.point.to_vec()).collect()
}

fn walk<const D: usize, C: Curve<D>>(c: &C) -> Result<Vec<(f64, f64)>, GeomError> {
    Ok(CurveWalk::new(c, WalkOptions::default())?
        .map(|s| (s.t, s.step))
        .collect())
}

fn curve_surface<S: Surface, C: Curve<3>>(
    s: &S,
    c: &C,
    p: &Precision,
) -> Result<Vec<Vec<f64>>, GeomError> {
    let samples = walk(c)?;
    let nodes: Vec<[f64; 4]> = SurfaceWalk::new(s, SurfaceWalkOptions::new(TURN))?
        .map(|n| [n.u, n.v, n.du, n.dv])
        .collect();
    Ok(intersect_curve_surface_f64(s, c, &samples, &nodes, TURN, p)
        .into_iter()
        .map(|x| x.point.to_vec())
        .collect())
}

/// The certified front door's answer.
fn certified(data: &Data) -> Result<crate::Certified<Answer>, GeomError> {
    let v = |x: &[f64; 3]| Vector3::new(x[0], x[1], x[2]);
    let shapes: [Shape; 2] = match data {
        Data::LineSphere { o, d, c, r } => [
            KernelLine::new(v(o), v(d))?.into(),
            Shape::from(crate::surface::AnySurface::Sphere(sphere(c, *r)?)),
        ],
        Data::LineTorus {
            o,
            d,
            c,
            major,
            minor,
        } => [
            KernelLine::new(v(o), v(d))?.into(),
            Shape::from(crate::surface::AnySurface::Torus(torus(c, *major, *minor)?)),
        ],
        Data::Circles2 { c1, r1, c2, r2 } => [
            AnyCurve2::Analytic(circle2(c1, *r1)?).into(),
            AnyCurve2::Analytic(circle2(c2, *r2)?).into(),
        ],
        Data::CircleEllipse2 { c, rho, e, a, b } => [
            AnyCurve2::Analytic(circle2(c, *rho)?).into(),
            AnyCurve2::Analytic(ellipse2(e, *a, *b)?).into(),
        ],
        Data::CircleSphere { q, n, rho, c, r } => [
            AnyCurve3::Analytic(circle3(q, n, *rho)?).into(),
            Shape::from(crate::surface::AnySurface::Sphere(sphere(c, *r)?)),
        ],
        Data::NurbsCircleSphere {
            q,
            start,
            rho,
            c,
            r,
        } => [
            AnyCurve3::Nurbs(nurbs_circle(q, *rho, *start)?).into(),
            Shape::from(crate::surface::AnySurface::Sphere(sphere(c, *r)?)),
        ],
    };
    intersect(&shapes, &Options::default())
}
