//! `intersect` with `options.method = bisection`: a curve (or line, segment) against a
//! surface that has an implicit form `F` (a named quadric, the torus, or an
//! implicit `quadric`), by bisection on `g(σ) = F(x(σ))` (OPERATIONS.md §13.4,
//! [`crate::ops::bisection`]), certified like every other float answer.
//!
//! The roots of `g` are the points of the curve on the whole implicit surface. When the
//! object is that whole surface (an implicit `quadric`; a closed sphere, ellipsoid or
//! ring torus: [`crate::ops::view::covers`]) every root is an answer, and the surface
//! reports no parameters (as an implicit plane). Otherwise the object is a patch of the
//! implicit surface (a cylinder's `height`, a `domain`): each root is decided on the
//! patch by the curve–surface system (5.2) with `t` restricted to a small interval
//! around the root's box — a verified root there proves the point on the patch and
//! gives its `(u, v)`; a complete search without one proves that the implicit
//! surface's point is off the patch; anything else leaves the root `undecided`.

use super::intersect_curved::{curve3, field};
use super::points::point;
use super::seeds::{curve_samples, surface_box};
use crate::certificate::{Certified, Status};
use crate::curve::AnyCurve3;
use crate::error::GeomError;
use crate::ops::answer::Answer;
use crate::ops::bisection::{
    intersect_curve_implicit_bisection, intersect_curve_implicit_bisection_f64,
};
use crate::ops::certified::{certify_roots, surface_unknowns, CertifiedPoint, Unknowns};
use crate::ops::intersect::curve_surface::CurveSurfaceSystem;
use crate::ops::options::Options;
use crate::ops::shape::Shape;
use crate::surface::{AnyImplicit, AnySurface};

/// The curve, the implicit form and the patch (when the object is a parametric
/// surface) of a case, and where the curve is in the input.
struct Pair<'a> {
    curve: AnyCurve3,
    g: AnyImplicit,
    patch: Option<&'a AnySurface>,
    curve_at: usize,
}

fn refuse(field: &str, reason: &str) -> GeomError {
    GeomError::Unsupported {
        field: field.into(),
        reason: reason.into(),
    }
}

const NEEDS: &str = "`method: bisection` takes two objects: a curve, line or segment, and a \
                     surface with an implicit form (sphere, ellipsoid, hyperboloids, \
                     paraboloids, cylinder, cone, torus, or an implicit `quadric`)";

/// The pair of a bisection case (module doc); errors name `options.method` for shapes
/// the method does not take and `objects[i]` for a bad object.
fn pair(shapes: &[Shape]) -> Result<Pair<'_>, GeomError> {
    let [a, b] = shapes else {
        return Err(refuse("options.method", NEEDS));
    };
    let (curve_at, surface) = match (a, b) {
        (Shape::Surface(_) | Shape::Quadric(_), _) => (1, a),
        (_, Shape::Surface(_) | Shape::Quadric(_)) => (0, b),
        _ => return Err(refuse("options.method", NEEDS)),
    };
    let (g, patch, bound) = match surface {
        Shape::Surface(s) => {
            let g = s.implicit().ok_or_else(|| {
                refuse(
                    &format!("{}.type", field(1 - curve_at)),
                    "this surface has no implicit form for `method: bisection`",
                )
            })?;
            (g, Some(s), Some(surface_box(s)))
        }
        Shape::Quadric(q) => (AnyImplicit::Quadric(q.clone()), None, None),
        _ => unreachable!("matched above"),
    };
    let curve = curve3(&shapes[curve_at], bound.as_ref())
        .map_err(|e| e.at(&field(curve_at)))?
        .ok_or_else(|| refuse("options.method", NEEDS))?;
    Ok(Pair {
        curve,
        g,
        patch,
        curve_at,
    })
}

/// The bisection roots of the float path alone, increasing (proves nothing; for
/// comparing the float path with truths and the certified answer).
pub fn float_roots(shapes: &[Shape], opts: &Options) -> Result<Vec<f64>, GeomError> {
    let p = pair(shapes)?;
    let samples = curve_samples(&p.curve, opts).map_err(|e| e.at(&field(p.curve_at)))?;
    Ok(intersect_curve_implicit_bisection_f64(
        &p.curve,
        &p.g,
        &samples,
        &opts.precision,
    ))
}

/// The certified answer (module doc).
pub(crate) fn intersect(shapes: &[Shape], opts: &Options) -> Result<Certified<Answer>, GeomError> {
    let p = pair(shapes)?;
    let samples = curve_samples(&p.curve, opts).map_err(|e| e.at(&field(p.curve_at)))?;
    let found = intersect_curve_implicit_bisection(
        &p.curve,
        &p.g,
        &samples,
        &opts.precision,
        &opts.certify(),
    )?;
    let whole = p.patch.is_none_or(|s| crate::ops::view::covers(s, &p.g));
    // Parameters in input order: the surface's (none for the whole surface), the curve's.
    let sizes = |n: usize| {
        if p.curve_at == 0 {
            vec![1, n]
        } else {
            vec![n, 1]
        }
    };
    let mut out = found.clone_with(Vec::new());
    let ts: Vec<_> = found.value.iter().map(|cp| cp.root.enclosure[0]).collect();
    for (i, cp) in found.value.into_iter().enumerate() {
        let decided = match p.patch {
            Some(s) if !whole => on_patch(s, &p.curve, cp, between(&ts, i), opts)?,
            _ => vec![(cp, 0)],
        };
        for (mut cp, n) in decided {
            if p.curve_at == 0 {
                cp.root.params.rotate_left(n);
                cp.root.enclosure.rotate_left(n);
            }
            if cp.root.status == Status::Undecided && out.reason.is_none() {
                out.reason.clone_from(&cp.root.reason);
            }
            out.status = out.status.weakest(cp.root.status);
            out.bits = out.bits.max(cp.root.bits);
            out.value.push(point(&cp, &sizes(n), None));
        }
    }
    Ok(out.map(Answer::from_points))
}

/// Where the patch search around root `i` may look: the curve's domain cut halfway
/// into the gaps to the neighbouring roots' enclosures (sorted, disjoint), so two
/// roots of `g` closer than the search's widening (a near-tangency) never find each
/// other's patch point — every point of the patch is a root of `g`, and the only
/// root of `g` in this window is root `i`. The window always holds root `i`'s own
/// enclosure, so its point is never cut off (overlapping enclosures are not cut).
fn between(ts: &[crate::num::Interval], i: usize) -> (f64, f64) {
    let mid = |a: f64, b: f64| if a < b { a + 0.5 * (b - a) } else { a };
    let mut order: Vec<usize> = (0..ts.len()).collect();
    order.sort_by(|&a, &b| ts[a].lo().total_cmp(&ts[b].lo()));
    let k = order.iter().position(|&j| j == i).expect("i is a root");
    // The window always holds root i's own enclosure (overlapping neighbours: no cut).
    let lo = k
        .checked_sub(1)
        .map(|j| mid(ts[order[j]].hi(), ts[i].lo()).min(ts[i].lo()));
    let hi = order
        .get(k + 1)
        .map(|&j| mid(ts[i].hi(), ts[j].lo()).max(ts[i].hi()));
    (lo.unwrap_or(f64::NEG_INFINITY), hi.unwrap_or(f64::INFINITY))
}

/// One root of `g` decided on the patch `s` (module doc): the points found, each with
/// the number of surface parameters in front of its curve parameter (2, or 0 when
/// undecided and given as the root of `g` alone).
fn on_patch(
    s: &AnySurface,
    curve: &AnyCurve3,
    cp: CertifiedPoint<3>,
    (lo, hi): (f64, f64),
    opts: &Options,
) -> Result<Vec<(CertifiedPoint<3>, usize)>, GeomError> {
    let t = cp.root.enclosure[0];
    let grow = t.width().max(1e-7 * t.mag().max(1.0));
    let (d_lo, d_hi) = crate::curve::Curve::domain(curve);
    let near = [
        (t.lo() - grow).max(lo).max(d_lo),
        (t.hi() + grow).min(hi).min(d_hi),
    ];
    let unknowns = Unknowns::concat(&[
        surface_unknowns(s),
        Unknowns {
            domain: vec![near],
            periodic: vec![false],
            rounded: vec![false],
        },
    ]);
    let sys = CurveSurfaceSystem { surface: s, curve };
    let roots = certify_roots(&sys, &unknowns, &[], &opts.certify())?;
    let proven = roots.complete && roots.status != Status::Undecided;
    if proven && roots.value.is_empty() {
        return Ok(Vec::new()); // the implicit surface's point is off the patch
    }
    if proven && roots.value.iter().all(|r| r.status != Status::Undecided) {
        return Ok(roots
            .value
            .into_iter()
            .map(|root| {
                let (point, point_box) =
                    crate::ops::certified::curve_point(curve, root.params[2], &root.enclosure[2]);
                let cp = CertifiedPoint {
                    root,
                    point,
                    point_box,
                };
                (cp, 2)
            })
            .collect());
    }
    let mut cp = cp;
    cp.root.status = Status::Undecided;
    cp.root.reason = Some(format!(
        "a point of the implicit surface on the curve at t ∈ [{:e}, {:e}] is not decided \
         on the patch",
        t.lo(),
        t.hi()
    ));
    Ok(vec![(cp, 0)])
}
