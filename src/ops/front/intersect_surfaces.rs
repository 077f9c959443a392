//! Surface ∩ surface at the front door (OPERATIONS.md §9, §10): two surfaces, or a
//! plane of the linear kernel and a surface, through
//! [`crate::ops::surface_surface::intersect_surface_surface`]; its certified curves,
//! singular points and isolated contacts become an [`Answer::Curves`].
//!
//! An unbounded plane is cut to a rectangle whose image holds the other surface's
//! certified bounding box with a margin, so no intersection point reaches the
//! rectangle's edges (every point of the other surface lies in the box, and the box
//! projects into the rectangle's interior).

use super::seeds::surface_box;
use crate::certificate::{Certified, Status};
use crate::error::GeomError;
use crate::geom::Plane as LinearPlane;
use crate::num::Interval;
use crate::ops::answer::{
    Answer, CurveAnswer, CurveEnd, CurveVertex, CurvesAnswer, Point, SingularPointAnswer,
};
use crate::ops::options::Options;
use crate::ops::shape::{Linear, LinearObject, Shape};
use crate::ops::surface_surface::{
    self as ss, CertifiedCurve, CertifiedSingularPoint, SurfaceIntersection,
};
use crate::surface::plane::Plane;
use crate::surface::AnySurface;

/// One operand: the surface and whether its parameters are reported (an implicit
/// plane has none).
pub(crate) struct Operand {
    pub(crate) surface: AnySurface,
    pub(crate) params: bool,
}

/// Two shapes of which each is a surface or a plane and at least one a surface;
/// `None` for other pairs.
pub(crate) fn pair(
    a: &Shape,
    b: &Shape,
    opts: &Options,
) -> Option<Result<Certified<Answer>, GeomError>> {
    let other_box = match (a, b) {
        (Shape::Surface(s), _) | (_, Shape::Surface(s)) => surface_box(s),
        _ => return None,
    };
    let ra = operand(a, &other_box, 0)?;
    let rb = operand(b, &other_box, 1)?;
    Some(ra.and_then(|ra| rb.and_then(|rb| intersect(&ra, &rb, opts))))
}

fn operand(shape: &Shape, bound: &[Interval; 3], i: usize) -> Option<Result<Operand, GeomError>> {
    match shape {
        Shape::Surface(s) => Some(Ok(Operand {
            surface: s.clone(),
            params: true,
        })),
        Shape::Linear(l) if l.type_name() == "plane" => {
            Some(bounded_plane(l, bound).map_err(|e| e.at(&format!("objects[{i}]"))))
        }
        _ => None,
    }
}

/// The options of the surface operation from the front door's.
pub(crate) fn surface_options(opts: &Options) -> ss::Options {
    ss::Options {
        precision: opts.precision,
        chord_tolerance: opts.chord_tolerance,
        certify: opts.certify(),
        ..ss::Options::default()
    }
}

fn intersect(a: &Operand, b: &Operand, opts: &Options) -> Result<Certified<Answer>, GeomError> {
    let c = ss::intersect_surface_surface(&a.surface, &b.surface, &surface_options(opts))?;
    Ok(answer(c, [a.params, b.params]))
}

/// The plane cut to a rectangle around `bound` (module doc); the parameters are those
/// of a parametric plane's own `u`, `v`, or of an exact frame of an implicit one
/// ([`implicit_plane`]).
pub(crate) fn bounded_plane(l: &Linear, bound: &[Interval; 3]) -> Result<Operand, GeomError> {
    let LinearObject::Plane(p) = l.doubles()? else {
        return Err(GeomError::Unsupported {
            field: "type".into(),
            reason: "expected a plane".into(),
        });
    };
    let (surface, params) = match p {
        LinearPlane::Parametric { origin, u, v } => {
            (Plane::new(arr(&origin), arr(&u), arr(&v))?, true)
        }
        LinearPlane::Implicit { normal, d } => (implicit_plane(&arr(&normal), d)?, false),
    };
    let (origin, u, v) = (surface.origin(), surface.vectors().0, surface.vectors().1);
    let domain = cover(&origin, &u, &v, bound).ok_or_else(|| GeomError::Unsupported {
        field: "domain".into(),
        reason: "the other surface is unbounded: a plane needs a domain here".into(),
    })?;
    Ok(Operand {
        surface: AnySurface::Plane(surface.with_domain(domain)?),
        params,
    })
}

/// The implicit plane `n·x + d = 0` as a parametric one that is the same plane for
/// every enclosure ([`Plane::through_box`]): with `k` the largest component of `n` and
/// `i`, `j` the others, the spanning vectors `u = n_k e_i − n_i e_k`, `v = n_k e_j −
/// n_j e_k` are exactly perpendicular to `n` (their entries are `n`'s own, so
/// `n·u = n_i n_k − n_k n_i = 0`), scaled by a common power of two to unit size where
/// that is exact; the origin is `−d/n_k e_k`, and when that quotient is not a double,
/// the box of its two neighbours, which holds the exact quotient (the division is
/// correctly rounded). (A frame and origin rounded in f64 gave a shifted plane: a
/// torus touched by the exact plane was certified `empty`.)
fn implicit_plane(n: &[f64; 3], d: f64) -> Result<Plane, GeomError> {
    let k = (0..3)
        .max_by(|&i, &j| n[i].abs().total_cmp(&n[j].abs()))
        .unwrap_or(2);
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let mut u = [0.0; 3];
    let mut v = [0.0; 3];
    (u[i], u[k]) = (n[k], -n[i]);
    (v[j], v[k]) = (n[k], -n[j]);
    // A common power of two bringing |n_k| to [1, 2), kept only if exact for every entry.
    let scale = 2f64.powi(-n[k].abs().log2().floor().clamp(-1000.0, 1000.0) as i32);
    let exact = |x: &[f64; 3]| {
        x.iter()
            .all(|&c| (c * scale) / scale == c && (c * scale).is_finite())
    };
    if scale.is_finite() && scale > 0.0 && exact(&u) && exact(&v) {
        u = u.map(|c| c * scale);
        v = v.map(|c| c * scale);
    }
    let q = -d / n[k];
    let mut origin = [0.0; 3];
    origin[k] = q;
    if n[k].mul_add(q, d) == 0.0 {
        return Plane::new(origin, u, v);
    }
    let (mut lo, mut hi) = (origin, origin);
    (lo[k], hi[k]) = (q.next_down(), q.next_up());
    Plane::through_box(origin, [lo, hi], u, v)
}

fn arr(v: &nalgebra::Vector3<f64>) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The parameter rectangle of `origin + s·u + t·v` holding the projection (along
/// `u × v`) of the box's corners, widened by 10 % and by 1 on each side (so rounding
/// of the projection cannot bring a point of the box to the edge). `None`: an
/// unbounded box.
fn cover(
    origin: &[f64; 3],
    u: &[f64; 3],
    v: &[f64; 3],
    bound: &[Interval; 3],
) -> Option<([f64; 2], [f64; 2])> {
    if bound
        .iter()
        .any(|x| !(x.lo().is_finite() && x.hi().is_finite()))
    {
        return None;
    }
    let n = cross(u, v);
    let det = dot(&n, &n);
    let (mut s, mut t) = (
        [f64::INFINITY, f64::NEG_INFINITY],
        [f64::INFINITY, f64::NEG_INFINITY],
    );
    for corner in 0..8 {
        let p: [f64; 3] = std::array::from_fn(|k| {
            let x = &bound[k];
            (if corner >> k & 1 == 0 { x.lo() } else { x.hi() }) - origin[k]
        });
        // Cramer on [u v n]: s = (p × v)·n / |n|², t = (u × p)·n / |n|².
        let (a, b) = (dot(&cross(&p, v), &n) / det, dot(&cross(u, &p), &n) / det);
        s = [s[0].min(a), s[1].max(a)];
        t = [t[0].min(b), t[1].max(b)];
    }
    let widen = |[lo, hi]: [f64; 2]| {
        let m = 0.1 * (hi - lo) + 1.0 + 1e-6 * (lo.abs() + hi.abs());
        [lo - m, hi + m]
    };
    Some((widen(s), widen(t)))
}

/// The certified intersection as an answer: singular points that no branch meets become
/// isolated points; nothing at all becomes `Empty`.
fn answer(c: Certified<SurfaceIntersection>, params: [bool; 2]) -> Certified<Answer> {
    let mut out = CurvesAnswer::default();
    let mut index = vec![None; c.value.singular_points.len()];
    for (i, p) in c.value.singular_points.iter().enumerate() {
        // no branch meets it (a contact of two spheres, a plane touching a cone's apex)
        let isolated = p.branch_ends == 0 && !c.value.curves.iter().any(|k| meets(k, i));
        if isolated {
            out.points.push(singular(p, params).point);
        } else {
            index[i] = Some(out.singular_points.len());
            out.singular_points.push(singular(p, params));
        }
    }
    out.curves = c
        .value
        .curves
        .iter()
        .map(|k| curve(k, params, &index))
        .collect();
    let value = if out.curves.is_empty() && out.singular_points.is_empty() {
        Answer::from_points(out.points)
    } else {
        Answer::Curves(out)
    };
    c.clone_with(value)
}

fn meets(c: &CertifiedCurve, i: usize) -> bool {
    c.curve.ends.contains(&ss::CurveEnd::Singular(i))
        || c.curve.points.iter().any(|p| p.singular == Some(i))
}

fn split(x: &[f64; 4], params: [bool; 2]) -> Vec<Vec<f64>> {
    let part = |k: usize| {
        if params[k] {
            x[2 * k..2 * k + 2].to_vec()
        } else {
            Vec::new()
        }
    };
    vec![part(0), part(1)]
}

fn bounds(b: &[Interval]) -> Vec<[f64; 2]> {
    b.iter().map(|x| [x.lo(), x.hi()]).collect()
}

/// The point of the interval `b` nearest to `x`; its midpoint for `NaN`.
fn nearest_in(x: f64, b: &Interval) -> f64 {
    if b.is_empty() {
        x
    } else if x.is_nan() {
        b.midpoint()
    } else {
        x.clamp(b.lo(), b.hi())
    }
}

fn singular(p: &CertifiedSingularPoint, params: [bool; 2]) -> SingularPointAnswer {
    let b = &p.param_box;
    let param_box = [0, 1]
        .into_iter()
        .map(|k| {
            if params[k] {
                bounds(&b[2 * k..2 * k + 2])
            } else {
                Vec::new()
            }
        })
        .collect();
    // The float space point (1.21) of a singular point can lose every digit to
    // cancellation (a torus of minor radius 1.9e40: an estimate 5.9e23 against the
    // proven box [−6, −6], issue 14 item 5); the box is the proven statement, so an
    // estimate it excludes is replaced by the box's point nearest to it.
    let xyz = p
        .point
        .xyz
        .iter()
        .zip(&p.xyz_box)
        .map(|(&x, b)| nearest_in(x, b))
        .collect();
    SingularPointAnswer {
        point: Point {
            xyz,
            xyz_box: bounds(&p.xyz_box),
            params: split(&p.point.params, params),
            param_box: Some(param_box),
            multiplicity: 2,
            tangent: true,
            region: Some(bounds(&p.region_xyz)),
            ..Point::default()
        },
        status: p.status,
        perturbation: p.perturbation,
        branches: p.branch_ends,
    }
}

fn curve(c: &CertifiedCurve, params: [bool; 2], index: &[Option<usize>]) -> CurveAnswer {
    let certified = c.status == Status::Verified && c.bounds.len() == c.curve.points.len();
    let points = c
        .curve
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| CurveVertex {
            xyz: p.xyz.to_vec(),
            params: split(&p.params, params),
            bound: certified.then(|| c.bounds[i].distance),
            exact: None,
        })
        .collect();
    let end = |e: ss::CurveEnd| match e {
        ss::CurveEnd::Closed => CurveEnd::Closed,
        ss::CurveEnd::Boundary => CurveEnd::Boundary,
        ss::CurveEnd::Singular(i) => index
            .get(i)
            .copied()
            .flatten()
            .map_or(CurveEnd::Tangency, CurveEnd::Singular),
        ss::CurveEnd::Tangency => CurveEnd::Tangency,
        ss::CurveEnd::Unfinished => CurveEnd::Unfinished,
    };
    CurveAnswer {
        points,
        closed: c.curve.closed,
        ends: c.curve.ends.map(end),
        distance_bound: certified.then(|| c.bounds.iter().map(|b| b.distance).fold(0.0, f64::max)),
        status: if certified {
            Status::Verified
        } else {
            Status::Undecided
        },
        reason: c.reason.clone(),
    }
}
