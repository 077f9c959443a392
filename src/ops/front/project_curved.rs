//! Projections onto curved shapes (OPERATIONS.md §3.2, §3.4, §3.5): every foot of a
//! perpendicular (certified, complete when the search covered the domain), the nearest
//! point of the closed domain (proven against the feet and the domain's ends and
//! edges), and projection along a direction (a ray against the surface, §5.2).

use super::points::{self, bounds, distance, keep_nearest_hit};
use super::seeds::{curve_samples, reach, surface_box, surface_nodes, TURN};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::curve::any::AnyCurve3;
use crate::curve::lines::Line;
use crate::curve::Curve;
use crate::error::GeomError;
use crate::ops::algebraic::every_point_a_foot;
use crate::ops::algebraic::pairs::{ray_surface, sphere_params};
use crate::ops::algebraic::quadric_feet::project_point_quadric;
use crate::ops::answer::{Answer, Point};
use crate::ops::certified::CertifiedPoint;
use crate::ops::closed_surface::{is_closed_shell, sphere_feet};
use crate::ops::intersect::intersect_curve_surface;
use crate::ops::nearest::{self, Nearest, NearestChoice};
use crate::ops::options::Options;
use crate::ops::project::{project_point_curve, project_point_surface};
use crate::surface::AnySurface;

/// Point → surface: the feet, the nearest point, or the hits along `direction`.
pub(crate) fn onto_surface(
    s: &AnySurface,
    p: [f64; 3],
    nearest: bool,
    direction: Option<[f64; 3]>,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    if let Some(d) = direction {
        return along(s, p, d, nearest, opts);
    }
    if let Some(r) = onto_sphere(s, &p, nearest) {
        return Ok(r);
    }
    if let Some(r) = project_point_quadric(p, s, nearest) {
        return Ok(r);
    }
    let nodes = surface_nodes(s, opts)?;
    let c = project_point_surface(s, &p, &nodes, &opts.precision, &opts.certify())?;
    let n = nearest.then(|| nearest::nearest_point_surface(s, &p, &c));
    Ok(with_nearest(c, &[2], &p, n))
}

/// Point → curve (2D or 3D): the feet, or the nearest point.
pub(crate) fn onto_curve<C: Curve<D>, const D: usize>(
    c: &C,
    p: [f64; D],
    nearest: bool,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let feet = project_point_curve(
        c,
        &p,
        &curve_samples(c, opts)?,
        &opts.precision,
        &opts.certify(),
    )?;
    let n = nearest.then(|| nearest::nearest_point_curve(c, &p, &feet));
    Ok(with_nearest(feet, &[1], &p, n))
}

/// The projection's `direction` is not the zero vector (`zero_direction` on it).
pub(super) fn nonzero_direction(d: &[f64]) -> Result<(), GeomError> {
    if d.iter().all(|&x| x == 0.0) {
        return Err(GeomError::ZeroDirection {
            field: "direction".into(),
        });
    }
    Ok(())
}

/// Projection along a direction (§3.5): the ray's parameters that can meet the surface
/// at all (a certified box of the whole surface), so that `complete` covers every hit.
fn along(
    s: &AnySurface,
    p: [f64; 3],
    d: [f64; 3],
    nearest: bool,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    nonzero_direction(&d)?;
    if let Some(mut r) = ray_surface(p, d, s) {
        // Decided exactly through the implicit form (poles and apexes included).
        if let Answer::Points(points) = &mut r.value {
            for q in points.iter_mut() {
                q.distance = Some(distance(&q.xyz, &p));
            }
        }
        if nearest && matches!(r.value, Answer::Points(_)) {
            keep_nearest_hit(&mut r, 1);
        }
        return Ok(r);
    }
    let range = reach(&p, &d, &surface_box(s)).ok_or_else(|| GeomError::Unsupported {
        field: "onto".into(),
        reason: "projection along a direction needs a bounded surface".into(),
    })?;
    let line = AnyCurve3::Line(Line::new(p, d, Some(range))?);
    let c = intersect_curve_surface(
        s,
        &line,
        &curve_samples(&line, opts)?,
        &surface_nodes(s, opts)?,
        TURN,
        &opts.precision,
        &opts.certify(),
    )?;
    let mut r = points::points(c, &[2, 1], Some(&p));
    if nearest && matches!(r.value, Answer::Points(_)) {
        keep_nearest_hit(&mut r, 1);
    }
    Ok(r)
}

/// Projection onto a whole sphere in closed form ([`sphere_feet`]): both feet, complete
/// (the parametric search cannot finish there: every pole is a continuum of `(u, v)`
/// roots). At a pole `u` is any angle and its box is the whole circle. `None` for other
/// surfaces, and for the centre (left to the search, which says `undecided`).
fn onto_sphere(s: &AnySurface, p: &[f64; 3], nearest: bool) -> Option<Certified<Answer>> {
    let AnySurface::Sphere(sphere) = s else {
        return None;
    };
    let centre = sphere.frame().origin();
    if *p == centre {
        // Every point of the sphere (or of its part) is at the distance r.
        let r2 = rug::Rational::from_f64(sphere.radius())?.square();
        return Some(every_point_a_foot("sphere", &r2));
    }
    if !is_closed_shell(s) {
        return None;
    }
    let feet = sphere_feet(p, &sphere.frame().origin(), sphere.radius())?;
    let keep = if nearest { 1 } else { 2 };
    let pts = feet[..keep]
        .iter()
        .map(|(b, d)| {
            let uv = sphere_params(s, b).unwrap_or_default();
            Point {
                xyz: b.iter().map(|x| x.midpoint()).collect(),
                xyz_box: bounds(b),
                params: vec![uv.iter().map(|x| x.0).collect()],
                param_box: Some(vec![uv.iter().map(|x| x.1).collect()]),
                multiplicity: 1,
                distance: Some(d.midpoint()),
                nearest: nearest.then_some(true),
                ..Default::default()
            }
        })
        .collect();
    Some(Certified {
        value: Answer::Points(pts),
        status: Status::Verified,
        complete: true,
        arithmetic: Arithmetic::Interval,
        bits: 53,
        reason: None,
        perturbation: None,
    })
}

/// The feet of a projection, or with `nearest` the one nearest point and whether it
/// is proven ([`nearest`]).
fn with_nearest<const D: usize>(
    feet: Certified<Vec<CertifiedPoint<D>>>,
    sizes: &[usize],
    p: &[f64; D],
    nearest: Option<Option<Nearest<D>>>,
) -> Certified<Answer> {
    let Some(nearest) = nearest else {
        return points::points(feet, sizes, Some(p));
    };
    let mut r = points::points(feet.clone(), sizes, Some(p));
    let Some(n) = nearest else {
        // No foot and no end: the nearest point lies on a surface's edge.
        r.status = Status::Undecided;
        r.value = Answer::Empty;
        r.reason = Some(if feet.complete {
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
            r.status = feet.value[*i].root.status;
            points::point(&feet.value[*i], sizes, Some(p))
        }
        NearestChoice::End {
            t,
            t_box,
            point,
            point_box,
        } => {
            r.status = Status::Verified;
            Point {
                xyz: point.to_vec(),
                xyz_box: bounds(point_box),
                params: vec![vec![*t]],
                param_box: Some(vec![vec![[t_box.lo(), t_box.hi()]]]),
                multiplicity: 1,
                distance: Some(distance(point, p)),
                ..Default::default()
            }
        }
    };
    point.nearest = Some(true);
    r.value = Answer::Points(vec![point]);
    if n.status == Status::Undecided {
        r.status = Status::Undecided;
        r.reason = n.reason;
    } else {
        // The nearest point is proven: the answer (one point) is complete.
        r.complete = true;
        r.reason = None;
    }
    r
}
