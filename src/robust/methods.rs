//! Each method of the robustness table run on one [`Case`]: the truth (geocert's
//! `_exact` procedures in rationals), plain f64 (`_f64`), geocert certified, and CGAL's
//! Epick (feature `cgal`).

use nalgebra::Vector3;
use rug::Rational;

use super::answer::{self, Answer};
use super::case::{q, same, Case, Linear2In, LinearIn, PlaneIn, P3};
use crate::certificate::{Arithmetic, Certified};
use crate::geom::line_plane::{
    intersect_line_plane, intersect_line_plane_exact, intersect_line_plane_f64,
};
use crate::geom::lines2::{
    intersect_line2_line2, intersect_line2_line2_exact, intersect_line2_line2_f64,
};
use crate::geom::plane_plane::{
    intersect_plane_plane, intersect_plane_plane_exact, intersect_plane_plane_f64,
};
use crate::geom::project::{
    project_point_line, project_point_line_exact, project_point_line_f64, project_point_plane,
    project_point_plane_exact, project_point_plane_f64,
};
use crate::geom::three_planes::{
    intersect_three_planes, intersect_three_planes_exact, intersect_three_planes_f64,
};
use crate::geom::{Line, Linear};
use crate::num::round::Rounded;

/// The truth, the plain f64 answer and the certified one (with its arithmetic) for a
/// case. `None` only if geocert refuses an object ([`Case::is_valid`] rules that out).
pub struct Answers {
    pub truth: Answer<Rational>,
    pub plain: Answer<f64>,
    pub certified: Answer<Rounded>,
    pub arithmetic: Arithmetic,
}

fn v3<T: Clone + PartialEq + std::fmt::Debug + 'static>(
    p: &[f64; 3],
    f: impl Fn(f64) -> T,
) -> Vector3<T> {
    Vector3::new(f(p[0]), f(p[1]), f(p[2]))
}

fn cert<T>(c: Certified<T>, f: impl FnOnce(T) -> Answer<Rounded>) -> (Answer<Rounded>, Arithmetic) {
    let a = c.arithmetic;
    (f(c.value), a)
}

/// Run geocert's three paths on `case`.
pub fn geocert(case: &Case) -> Option<Answers> {
    let (truth, plain, (certified, arithmetic)) = match case {
        Case::ThreePlanes(ps) => three_planes(ps)?,
        Case::LinePlane(l, p) => line_plane(l, p)?,
        Case::PlanePlane(a, b) => plane_plane(a, b)?,
        Case::ProjectLine(p, o, d) => project_line(p, o, d)?,
        Case::ProjectPlane(p, pl) => project_plane(p, pl)?,
        Case::Linear2(a, b) => linear2(a, b)?,
    };
    Some(Answers {
        truth,
        plain,
        certified,
        arithmetic,
    })
}

/// The truth, the plain answer, and the certified answer with its arithmetic.
type Paths = (Answer<Rational>, Answer<f64>, (Answer<Rounded>, Arithmetic));

/// Three planes.
fn three_planes(ps: &[PlaneIn; 3]) -> Option<Paths> {
    let f = [
        ps[0].object(same).ok()?,
        ps[1].object(same).ok()?,
        ps[2].object(same).ok()?,
    ];
    let e = [
        ps[0].object(q).ok()?,
        ps[1].object(q).ok()?,
        ps[2].object(q).ok()?,
    ];
    Some((
        answer::three_planes(intersect_three_planes_exact(&e)),
        answer::three_planes(intersect_three_planes_f64(&f)),
        cert(intersect_three_planes(&f), answer::three_planes),
    ))
}

/// Line or segment ∩ plane.
fn line_plane(l: &LinearIn, p: &PlaneIn) -> Option<Paths> {
    let seg = matches!(l, LinearIn::Segment { .. });
    let (lf, le) = (l.object(same).ok()?, l.object(q).ok()?);
    let (pf, pe) = (p.object(same).ok()?, p.object(q).ok()?);
    Some((
        answer::line_plane(intersect_line_plane_exact(le.linear(), &pe), seg),
        answer::line_plane(intersect_line_plane_f64(lf.linear(), &pf), seg),
        cert(intersect_line_plane(lf.linear(), &pf), |r| {
            answer::line_plane(r, seg)
        }),
    ))
}

/// Plane ∩ plane.
fn plane_plane(a: &PlaneIn, b: &PlaneIn) -> Option<Paths> {
    let (af, ae) = (a.object(same).ok()?, a.object(q).ok()?);
    let (bf, be) = (b.object(same).ok()?, b.object(q).ok()?);
    Some((
        answer::plane_plane(intersect_plane_plane_exact(&ae, &be)),
        answer::plane_plane(intersect_plane_plane_f64(&af, &bf)),
        cert(intersect_plane_plane(&af, &bf), answer::plane_plane),
    ))
}

/// A point projected onto a line.
fn project_line(p: &P3, o: &P3, d: &P3) -> Option<Paths> {
    let lf = Line::new(v3(o, same), v3(d, same)).ok()?;
    let le = Line::new(v3(o, q), v3(d, q)).ok()?;
    Some((
        answer::project_line(project_point_line_exact(&v3(p, q), Linear::Line(&le))),
        answer::project_line(project_point_line_f64(&v3(p, same), Linear::Line(&lf))),
        cert(
            project_point_line(&v3(p, same), Linear::Line(&lf)),
            answer::project_line,
        ),
    ))
}

/// A point projected onto a plane.
fn project_plane(p: &P3, pl: &PlaneIn) -> Option<Paths> {
    let (pf, pe) = (pl.object(same).ok()?, pl.object(q).ok()?);
    Some((
        answer::project_plane(project_point_plane_exact(&v3(p, q), &pe)),
        answer::project_plane(project_point_plane_f64(&v3(p, same), &pf)),
        cert(
            project_point_plane(&v3(p, same), &pf),
            answer::project_plane,
        ),
    ))
}

/// Two 2D lines or segments.
fn linear2(a: &Linear2In, b: &Linear2In) -> Option<Paths> {
    let (af, ae) = (a.object(same).ok()?, a.object(q).ok()?);
    let (bf, be) = (b.object(same).ok()?, b.object(q).ok()?);
    Some((
        answer::linear2(intersect_line2_line2_exact(ae.linear(), be.linear())),
        answer::linear2(intersect_line2_line2_f64(af.linear(), bf.linear())),
        cert(
            intersect_line2_line2(af.linear(), bf.linear()),
            answer::linear2,
        ),
    ))
}

/// Whether CGAL Epick can be asked `case` without killing the process. Epick builds
/// objects in doubles (plane coefficients `u × v` and `d`, lines of two planes, 2D line
/// coefficients); when one of them overflows to ±∞ or becomes NaN and a filtered
/// predicate then falls back to exact arithmetic, GMP's `mpq_set_d` raises SIGFPE
/// (observed: segment ∩ plane with coordinates near 1e150). This conservative window
/// keeps every nonzero input magnitude within `[2^-B, 2^B]`, `B = 60` in space (the
/// constructions chained before a predicate have degree ≤ 12) and `B = 200` in the
/// plane (degree ≤ 3); cases outside are not run.
pub fn epick_safe(case: &Case) -> bool {
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    let mut see = |v: &[f64]| {
        for x in v.iter().map(|x| x.abs()).filter(|&x| x != 0.0) {
            lo = lo.min(x);
            hi = hi.max(x);
        }
    };
    let planes = |p: &super::case::PlaneIn, see: &mut dyn FnMut(&[f64])| match p {
        super::case::PlaneIn::Parametric { origin, u, v } => {
            see(origin);
            see(u);
            see(v);
        }
        super::case::PlaneIn::Implicit { normal, d } => {
            see(normal);
            see(&[*d]);
        }
    };
    let b = match case {
        Case::ThreePlanes(ps) => {
            ps.iter().for_each(|p| planes(p, &mut see));
            60
        }
        Case::LinePlane(l, p) => {
            match l {
                LinearIn::Line { origin: a, dir: b } | LinearIn::Segment { a, b } => {
                    see(a);
                    see(b);
                }
            }
            planes(p, &mut see);
            60
        }
        Case::PlanePlane(a, b) => {
            planes(a, &mut see);
            planes(b, &mut see);
            60
        }
        Case::ProjectLine(p, o, d) => {
            see(p);
            see(o);
            see(d);
            60
        }
        Case::ProjectPlane(p, pl) => {
            see(p);
            planes(pl, &mut see);
            60
        }
        Case::Linear2(a, b) => {
            for l in [a, b] {
                match l {
                    Linear2In::Line { origin: a, dir: b } | Linear2In::Segment { a, b } => {
                        see(a);
                        see(b);
                    }
                }
            }
            200
        }
    };
    hi <= 2f64.powi(b) && (lo == f64::INFINITY || lo >= 2f64.powi(-b))
}

/// CGAL Epick's answer (an input it refuses is [`Kind::Error`](crate::robust::answer::Kind::Error)); `None` when the case
/// is outside [`epick_safe`]'s window.
#[cfg(feature = "cgal")]
pub fn epick(case: &Case) -> Option<Answer<f64>> {
    if !epick_safe(case) {
        return None;
    }
    Some(epick_unguarded(case))
}

#[cfg(feature = "cgal")]
fn epick_unguarded(case: &Case) -> Answer<f64> {
    use super::answer::Kind;
    use super::case::{line, line2, segment, segment2};
    use crate::oracle::{epick, Intersection, OracleError};
    fn from<const D: usize>(r: Result<Intersection<f64, D>, OracleError>) -> Answer<f64> {
        match r {
            Ok(Intersection::Empty) => Answer::kind(Kind::Empty),
            Ok(Intersection::Point(p)) => Answer {
                kind: Kind::Point,
                coords: p.to_vec(),
            },
            Ok(Intersection::Line { .. }) => Answer::kind(Kind::Line),
            Ok(Intersection::Segment { source, target }) => Answer {
                kind: Kind::Segment,
                coords: source.iter().chain(&target).copied().collect(),
            },
            // (no construction of the table gives a ray)
            Ok(Intersection::Ray { .. }) => Answer::kind(Kind::Error),
            Ok(Intersection::Plane(_)) => Answer::kind(Kind::Plane),
            Err(_) => Answer::kind(Kind::Error),
        }
    }
    let point = |r: Result<[f64; 3], OracleError>| from(r.map(Intersection::Point));
    match case {
        Case::ThreePlanes(p) => from(epick::intersect_three_planes(
            &p[0].oracle(),
            &p[1].oracle(),
            &p[2].oracle(),
        )),
        Case::LinePlane(LinearIn::Line { origin, dir }, p) => from(epick::intersect_line_plane(
            &line(*origin, *dir),
            &p.oracle(),
        )),
        Case::LinePlane(LinearIn::Segment { a, b }, p) => from(epick::intersect_segment_plane(
            &segment(*a, *b),
            &p.oracle(),
        )),
        Case::PlanePlane(a, b) => from(epick::intersect_plane_plane(&a.oracle(), &b.oracle())),
        Case::ProjectLine(p, o, d) => point(epick::project_point_line(p, &line(*o, *d))),
        Case::ProjectPlane(p, pl) => point(epick::project_point_plane(p, &pl.oracle())),
        Case::Linear2(
            Linear2In::Line {
                origin: o1,
                dir: d1,
            },
            Linear2In::Line {
                origin: o2,
                dir: d2,
            },
        ) => from(epick::intersect_line2_line2(
            &line2(*o1, *d1),
            &line2(*o2, *d2),
        )),
        Case::Linear2(Linear2In::Segment { a: a1, b: b1 }, Linear2In::Segment { a: a2, b: b2 }) => {
            from(epick::intersect_segment2_segment2(
                &segment2(*a1, *b1),
                &segment2(*a2, *b2),
            ))
        }
        // CGAL has no mixed line/segment intersection; the generators never mix them.
        Case::Linear2(..) => Answer::kind(Kind::Error),
    }
}
