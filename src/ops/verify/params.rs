//! Claimed parameters → the claimed point on each shape, as a [`Region`] that holds
//! the exact image: linear shapes in exact rationals (`origin + t·dir`,
//! `(1 − t)·a + t·b`, `origin + u·u + v·v`, OPERATIONS.md §1.5 and §3.3), curves and
//! surfaces by interval evaluation of their parametrisation (§1.1, §1.3) at the
//! tightest interval around each claimed rational ([`Interval::from_rational`]); the
//! interval formulas enclose the true value (outward rounding, see
//! [`crate::num::interval`]), so the exact image lies in the region.

use nalgebra::SVector;
use rug::Rational;

use super::region::Region;
use crate::curve::Curve;
use crate::geom::Plane;
use crate::num::round::{next_down, next_up};
use crate::num::Interval;
use crate::ops::shape::{LinearObject, Shape};
use crate::surface::{AnySurface, Surface};

/// The point the parameters `params` give on `shape`: `Ok(None)` when `params` is
/// empty (the claim gives no parameters on this shape), `Err` with the reason when the
/// parameters do not name a point of the shape (wrong count, a shape without
/// parameters, a parameter outside a non-periodic domain).
pub fn image(shape: &Shape, params: &[Rational]) -> Result<Option<Region>, String> {
    if params.is_empty() {
        return Ok(None);
    }
    let region = match shape {
        Shape::Linear(l) => linear(&l.exact(), params)?,
        Shape::Curve(c) => curve::<3, _>(c, params)?,
        Shape::Curve2(c) => curve::<2, _>(c, params)?,
        Shape::Surface(s) => surface(s, params)?,
        Shape::Conic2(_) | Shape::Polyhedron(_) | Shape::Quadric(_) => {
            return Err("the object has no parameters".into());
        }
    };
    Ok(Some(region))
}

fn count(params: &[Rational], n: usize) -> Result<(), String> {
    if params.len() == n {
        Ok(())
    } else {
        Err(format!(
            "the object has {n} parameter(s), the claim gives {}",
            params.len()
        ))
    }
}

/// `origin + Σ tᵢ·dirᵢ`, exactly.
fn affine<const D: usize>(
    origin: &SVector<Rational, D>,
    terms: &[(&Rational, SVector<Rational, D>)],
) -> Region {
    let v: Vec<Rational> = (0..D)
        .map(|k| {
            let mut x = origin[k].clone();
            for (t, dir) in terms {
                x += Rational::from(*t * &dir[k]);
            }
            x
        })
        .collect();
    Region::point(&v)
}

/// Linear shapes, exactly; a parameter beyond a range or segment names a point of the
/// extended line, which is still an exact point to compare.
fn linear(o: &LinearObject<Rational>, p: &[Rational]) -> Result<Region, String> {
    Ok(match o {
        LinearObject::Line(l) => {
            count(p, 1)?;
            affine(l.origin(), &[(&p[0], l.dir().clone())])
        }
        LinearObject::Segment(s) => {
            count(p, 1)?;
            affine(s.a(), &[(&p[0], s.b() - s.a())])
        }
        LinearObject::Line2(l) => {
            count(p, 1)?;
            affine(l.origin(), &[(&p[0], l.dir().clone())])
        }
        LinearObject::Segment2(s) => {
            count(p, 1)?;
            affine(s.a(), &[(&p[0], s.b() - s.a())])
        }
        LinearObject::Plane(Plane::Parametric { origin, u, v }) => {
            count(p, 2)?;
            affine(origin, &[(&p[0], u.clone()), (&p[1], v.clone())])
        }
        LinearObject::Plane(Plane::Implicit { .. }) => {
            return Err("an implicit plane has no parameters".into());
        }
    })
}

/// The region of an interval point; `Err` when an enclosure is empty or unbounded.
fn region_of(v: &[Interval]) -> Result<Region, String> {
    if v.iter().any(|x| x.is_empty() || !x.is_bounded()) {
        return Err("the parametrisation cannot be bounded at the claimed parameters".into());
    }
    let end = |x: f64| Rational::from_f64(x);
    Ok(Region::from_ends(
        v.iter().map(|x| end(x.lo())).collect(),
        v.iter().map(|x| end(x.hi())).collect(),
    ))
}

/// Whether `t` lies in `[lo, hi]` (exactly); a `rounded` domain (its ends the doubles
/// nearest to irrational ends, `π/2`, `2π`) is widened by one ulp on each side, as the
/// certifier covers it.
fn within(t: &Rational, lo: f64, hi: f64, rounded: bool) -> bool {
    let (lo, hi) = if rounded {
        (next_down(lo), next_up(hi))
    } else {
        (lo, hi)
    };
    let above = Rational::from_f64(lo).is_none_or(|l| *t >= l);
    let below = Rational::from_f64(hi).is_none_or(|h| *t <= h);
    above && below
}

fn outside(name: &str, lo: f64, hi: f64) -> String {
    format!("the claimed parameter `{name}` lies outside the object's domain [{lo}, {hi}]")
}

fn curve<const D: usize, C: Curve<D>>(c: &C, p: &[Rational]) -> Result<Region, String> {
    count(p, 1)?;
    let (lo, hi) = c.domain();
    if !c.is_periodic() && !within(&p[0], lo, hi, c.domain_rounded()) {
        return Err(outside("t", lo, hi));
    }
    region_of(&c.point(&Interval::from_rational(&p[0])))
}

/// Whether the surface's formula in the closed direction `k` is an angle's (valid for
/// every value of the parameter, the same point modulo the period): the analytic
/// surfaces, the rotation angle of a revolution, and a motion surface's profile
/// direction when the profile is periodic (a circle).
fn angular(s: &AnySurface, k: usize) -> bool {
    match s {
        AnySurface::Bezier(_) | AnySurface::Nurbs(_) | AnySurface::Bilinear(_) => false,
        AnySurface::Revolution(r) => k == 0 || r.profile().is_periodic(),
        AnySurface::Extrusion(e) => k == 0 && e.profile().is_periodic(),
        // Guides reparametrised to [0, 1]: a parameter past 1 is not a turn of the circle.
        AnySurface::Ruled(_) => false,
        _ => true,
    }
}

fn surface(s: &AnySurface, p: &[Rational]) -> Result<Region, String> {
    count(p, 2)?;
    let (u, v) = s.domain();
    let closed = s.is_closed();
    let rounded = s.domain_rounded();
    for (k, (name, [lo, hi])) in [("u", u), ("v", v)].into_iter().enumerate() {
        let periodic = closed[k] && angular(s, k);
        if !periodic && !within(&p[k], lo, hi, rounded[k]) {
            return Err(outside(name, lo, hi));
        }
    }
    let (iu, iv) = (
        Interval::from_rational(&p[0]),
        Interval::from_rational(&p[1]),
    );
    region_of(&s.jet(&iu, &iv, 0)[0])
}
