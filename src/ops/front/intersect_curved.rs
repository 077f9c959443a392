//! The numeric certified intersections of curved shapes (OPERATIONS.md §5.2, §6.4,
//! §6.5, §7.2): plane curve ∩ plane curve, space curve ∩ space curve, curve ∩ surface
//! and three surfaces. Initial guesses come from the walks of §2 ([`super::seeds`]);
//! every answer is certified by [`crate::ops::certified`].

use super::points;
use super::seeds::{curve_box, curve_samples, reach, surface_box, surface_nodes, TURN};
use crate::certificate::{Certified, Status};
use crate::curve::{AnyCurve2, AnyCurve3};
use crate::error::GeomError;
use crate::geom::Plane as LinearPlane;
use crate::num::Interval;
use crate::ops::answer::Answer;
use crate::ops::bisection::intersect_curve_implicit_bisection;
use crate::ops::intersect::{
    intersect_curve2_curve2, intersect_curve_surface, intersect_three_surfaces,
};
use crate::ops::options::Options;
use crate::ops::shape::{Linear, LinearObject, Shape};
use crate::ops::space_curves::intersect_curve_curve;
use crate::surface::implicit::ImplicitPlane;
use crate::surface::AnySurface;

pub(super) fn field(i: usize) -> String {
    format!("objects[{i}]")
}

fn unsupported(field: &str, reason: &str) -> GeomError {
    GeomError::Unsupported {
        field: field.into(),
        reason: reason.into(),
    }
}

/// A space curve, or a line or segment as one; an unbounded line is cut to the part
/// that can meet `bound` (a certified box of the other shape). `Ok(None)`: not a space
/// curve.
pub(super) fn curve3(
    shape: &Shape,
    bound: Option<&[Interval; 3]>,
) -> Result<Option<AnyCurve3>, GeomError> {
    match shape {
        Shape::Curve(c) => Ok(Some(c.clone())),
        Shape::Linear(l) => l.to_curve3(|o, d| bound.and_then(|b| reach(o, d, b))),
        _ => Ok(None),
    }
}

/// A plane curve, or a 2D line or segment as one; an unbounded line is cut to the
/// part that can meet `bound` (a certified box of the other curve).
fn curve2(shape: &Shape, bound: Option<&[Interval; 2]>) -> Result<Option<AnyCurve2>, GeomError> {
    match shape {
        Shape::Curve2(c) => Ok(Some(c.clone())),
        Shape::Linear(l) => l.to_curve2(|o, d| bound.and_then(|b| reach(o, d, b))),
        _ => Ok(None),
    }
}

fn is_plane_shape(shape: &Shape) -> bool {
    matches!(shape, Shape::Curve2(_) | Shape::Conic2(_))
        || matches!(shape, Shape::Linear(l) if matches!(l.type_name(), "line2" | "segment2"))
}

/// Two shapes, at least one of them curved.
pub(crate) fn pair(a: &Shape, b: &Shape, opts: &Options) -> Result<Certified<Answer>, GeomError> {
    if let Some(i) = [a, b].iter().position(|s| matches!(s, Shape::Quadric(_))) {
        // Lines, segments and the framed conics were answered exactly before; a plane
        // is its exact section.
        if let Some(r) = super::sections::pair(a, b, opts) {
            return r;
        }
        return Err(unsupported(
            &format!("{}.type", field(i)),
            "an implicit `quadric` is intersected exactly with lines, segments, planes and \
             the framed conics (circle, ellipse, hyperbola, and a parabola whose frame is \
             rational) whose parameters round within the precision cap; against other \
             curves and surfaces give it by its named type (sphere, ellipsoid, cylinder, ...)",
        ));
    }
    if is_plane_shape(a) && is_plane_shape(b) {
        return plane_curves(a, b, opts);
    }
    if let Some(r) = super::sections::pair(a, b, opts) {
        return r;
    }
    if let Some(r) = super::intersect_surfaces::pair(a, b, opts) {
        return r;
    }
    match (a, b) {
        (Shape::Surface(s), other) => curve_surface(s, other, 1, true, true, opts),
        (other, Shape::Surface(s)) => curve_surface(s, other, 0, false, true, opts),
        (Shape::Linear(l), other) if l.type_name() == "plane" => {
            curve_plane(l, other, 1, true, opts)
        }
        (other, Shape::Linear(l)) if l.type_name() == "plane" => {
            curve_plane(l, other, 0, false, opts)
        }
        _ => space_curves(a, b, opts),
    }
}

/// A space curve against a plane of the linear kernel, numerically (the pairs the exact
/// solver does not take, such as the helix): the plane is cut to a rectangle whose image
/// holds the curve's certified box with a margin
/// ([`super::intersect_surfaces::bounded_plane`]), so every common point lies inside it
/// and `complete` keeps its meaning; an implicit plane is enclosed exactly there (its
/// origin a one-ulp box where `−d/n_k` is not a double) and reports no parameters.
/// An implicit plane `n·x + d = 0` is first solved as the one equation `n·c(t) + d = 0`
/// in the curve's parameter (§13.4, [`intersect_curve_implicit_bisection`]), its
/// doubles exact in every evaluation: that decides near-tangencies within an ulp of the
/// plane, which the enclosed origin cannot.
fn curve_plane(
    plane: &Linear,
    curve_shape: &Shape,
    curve_at: usize,
    plane_first: bool,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let curve = curve3(curve_shape, None)
        .map_err(|e| e.at(&field(curve_at)))?
        .ok_or_else(|| unsupported(&field(curve_at), "expected a space curve"))?;
    let plane_at = 1 - curve_at;
    if let LinearObject::Plane(LinearPlane::Implicit { normal, d }) =
        plane.doubles().map_err(|e| e.at(&field(plane_at)))?
    {
        let g = ImplicitPlane::new([normal[0], normal[1], normal[2]], d)
            .map_err(|e| e.at(&field(plane_at)))?;
        let c = intersect_curve_implicit_bisection(
            &curve,
            &g,
            &curve_samples(&curve, opts)?,
            &opts.precision,
            &opts.certify(),
        )?;
        // Decided and complete: done (the plane has no parameters of its own). Else (a
        // root at a kink of a composite curve, where g' jumps): the plane route below.
        if c.status != Status::Undecided && c.complete {
            let sizes: &[usize] = if plane_first { &[0, 1] } else { &[1, 0] };
            return Ok(points::points(c, sizes, None));
        }
    }
    let op = super::intersect_surfaces::bounded_plane(plane, &curve_box(&curve))
        .map_err(|e| e.at(&field(plane_at)))?;
    curve_surface(
        &op.surface,
        curve_shape,
        curve_at,
        plane_first,
        op.params,
        opts,
    )
}

fn plane_curves(a: &Shape, b: &Shape, opts: &Options) -> Result<Certified<Answer>, GeomError> {
    // A line without a range is cut to the other curve's box.
    let (ca, cb) = match (curve2(a, None), curve2(b, None)) {
        (Ok(ca), Ok(cb)) => (ca, cb),
        (Ok(Some(ca)), Err(_)) => {
            let cb = curve2(b, Some(&curve_box(&ca))).map_err(|e| e.at(&field(1)))?;
            (Some(ca), cb)
        }
        (Err(_), Ok(Some(cb))) => {
            let ca = curve2(a, Some(&curve_box(&cb))).map_err(|e| e.at(&field(0)))?;
            (ca, Some(cb))
        }
        (Err(e), _) => return Err(e.at(&field(0))),
        (_, Err(e)) => return Err(e.at(&field(1))),
    };
    let (Some(ca), Some(cb)) = (ca, cb) else {
        return Err(unsupported(
            "objects",
            "intersections with an implicit `conic2` are not implemented for the command line yet",
        ));
    };
    let c = intersect_curve2_curve2(
        &ca,
        &cb,
        &curve_samples(&ca, opts)?,
        &curve_samples(&cb, opts)?,
        &opts.precision,
        &opts.certify(),
    )?;
    Ok(points::points(c, &[1, 1], None))
}

/// Two space curves: a line without a range is cut to the other's box.
fn space_curves(a: &Shape, b: &Shape, opts: &Options) -> Result<Certified<Answer>, GeomError> {
    let bounded = |s: &Shape, i: usize, bound: Option<&[Interval; 3]>| {
        curve3(s, bound)
            .map_err(|e| e.at(&field(i)))?
            .ok_or_else(|| unsupported(&field(i), "expected a space curve"))
    };
    let (ca, cb) = match (curve3(a, None), curve3(b, None)) {
        (Ok(Some(ca)), Ok(Some(cb))) => (ca, cb),
        (Ok(Some(ca)), Err(_)) => {
            let cb = bounded(b, 1, Some(&curve_box(&ca)))?;
            (ca, cb)
        }
        (Err(_), Ok(Some(cb))) => (bounded(a, 0, Some(&curve_box(&cb)))?, cb),
        (Err(e), _) => return Err(e.at(&field(0))),
        (_, Err(e)) => return Err(e.at(&field(1))),
        _ => {
            return Err(unsupported(
                "objects",
                "intersect of these curved objects is not implemented",
            ))
        }
    };
    let c = intersect_curve_curve(&ca, &cb, &opts.certify());
    Ok(points::points(c, &[1, 1], None))
}

/// A curve (or line, segment) against a surface; `curve_at` is the curve's place in
/// the input, `surface_first` whether the surface comes first.
fn curve_surface(
    s: &AnySurface,
    curve_shape: &Shape,
    curve_at: usize,
    surface_first: bool,
    surface_params: bool,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    if matches!(curve_shape, Shape::Surface(_)) {
        return Err(unsupported(
            "objects",
            "intersect of these curved objects is not implemented",
        ));
    }
    let curve = curve3(curve_shape, Some(&surface_box(s)))
        .map_err(|e| e.at(&field(curve_at)))?
        .ok_or_else(|| unsupported(&field(curve_at), "expected a space curve"))?;
    // Near a pole of a sphere or ellipsoid: on a chart with new poles (§14).
    let c = match super::poles::curve_near_poles(s, &curve, opts) {
        Some(c) => c?,
        None => intersect_curve_surface(
            s,
            &curve,
            &curve_samples(&curve, opts)?,
            &surface_nodes(s, opts)?,
            TURN,
            &opts.precision,
            &opts.certify(),
        )?,
    };
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
    let mut r = points::points(c, sizes, None);
    if !surface_params {
        // An implicit plane has no parameters of its own.
        let at = usize::from(!surface_first);
        if let Answer::Points(ps) = &mut r.value {
            for p in ps {
                p.params[at].clear();
                if let Some(b) = &mut p.param_box {
                    b[at].clear();
                }
            }
        }
    }
    Ok(r)
}

/// Three surfaces (§7.2).
pub(crate) fn three(
    a: &Shape,
    b: &Shape,
    c: &Shape,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let (Shape::Surface(r), Shape::Surface(s), Shape::Surface(q)) = (a, b, c) else {
        return Err(unsupported(
            "objects",
            "three-object intersections take three surfaces (or three planes)",
        ));
    };
    if let Some(exact) = crate::ops::algebraic::three_spheres::intersect_three_spheres([r, s, q]) {
        return Ok(exact);
    }
    let (nr, ns, nq) = (
        surface_nodes(r, opts)?,
        surface_nodes(s, opts)?,
        surface_nodes(q, opts)?,
    );
    let c = intersect_three_surfaces((r, s, q), [&nr, &ns, &nq], &opts.precision, &opts.certify())?;
    Ok(points::points(c, &[2, 2, 2], None))
}
