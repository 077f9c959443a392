//! `classify`: a point against a closed shell (OPERATIONS.md §4) — a polyhedron, or a
//! whole sphere, ellipsoid or torus — decided exactly, with the shell's nearest point
//! when it is proven.

use super::points::bounds;
use super::seeds::surface_nodes;
use crate::certificate::{Certified, Status};
use crate::error::GeomError;
use crate::ops::algebraic::implicit_quadric::classify_point_quadric;
use crate::ops::answer::{Answer, Point};
use crate::ops::certified::CertifiedPoint;
use crate::ops::classify::Side;
use crate::ops::closed_surface::{classify_point_surface, sphere_feet};
use crate::ops::linear;
use crate::ops::nearest::{self, NearestChoice};
use crate::ops::options::Options;
use crate::ops::project::project_point_surface;
use crate::ops::shape::{Position, Shape};
use crate::surface::{AnySurface, Surface};

/// The side of `point` relative to the closed `shell` (`inside`, `on`, `outside`),
/// with the nearest point of the shell when it is proven (else the certificate's
/// `reason` says why not).
pub fn classify(
    point: &Position,
    shell: &Shape,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let not_closed = |what: &str| GeomError::Unsupported {
        field: "shell.type".into(),
        reason: format!("`{what}` is not a closed shell (sphere, ellipsoid, torus or polyhedron)"),
    };
    match shell {
        Shape::Polyhedron(p) => linear::classify_polyhedron(point, p, opts),
        Shape::Quadric(q) => {
            if let Position::Double(v) = point {
                for (i, &x) in v.iter().enumerate() {
                    crate::error::require_finite(&format!("point[{i}]"), x)?;
                }
            }
            let p: [rug::Rational; 3] =
                point
                    .exact()
                    .try_into()
                    .map_err(|v: Vec<_>| GeomError::CountMismatch {
                        field: "point".into(),
                        expected: "3 coordinates".into(),
                        found: v.len().to_string(),
                    })?;
            classify_point_quadric(&p, q).ok_or_else(|| not_closed("quadric"))
        }
        Shape::Surface(s) => {
            let p = point.doubles::<3>("point")?;
            let c = classify_point_surface(&p, s).ok_or_else(|| not_closed(surface_name(s)))?;
            closed_surface(s, p, c, opts)
        }
        _ => Err(GeomError::Unsupported {
            field: "shell".into(),
            reason: "expected a polyhedron, sphere, ellipsoid or torus".into(),
        }),
    }
}

fn surface_name(s: &AnySurface) -> &'static str {
    match s {
        AnySurface::Plane(_) => "plane",
        AnySurface::Sphere(_) => "sphere",
        AnySurface::Ellipsoid(_) => "ellipsoid",
        AnySurface::Hyperboloid(_) => "hyperboloid",
        AnySurface::Paraboloid(_) => "paraboloid",
        AnySurface::ParaboloidRect(_) => "paraboloid",
        AnySurface::Cylinder(_) => "cylinder",
        AnySurface::Cone(_) => "cone",
        AnySurface::Torus(_) => "torus",
        AnySurface::Bilinear(_) => "bilinear",
        AnySurface::Bezier(_) => "bezier_surface",
        AnySurface::Nurbs(_) => "nurbs_surface",
        AnySurface::Extrusion(_) => "extrusion",
        AnySurface::Revolution(_) => "revolution",
        AnySurface::Ruled(_) => "ruled",
    }
}

/// §4: the verdict comes with the nearest point of the shell, when it is proven.
fn closed_surface(
    s: &AnySurface,
    p: [f64; 3],
    side: Certified<Side>,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let nearest = match (&side.value, s) {
        (Side::On, _) => Ok(exact_point(p)),
        (_, AnySurface::Sphere(sphere)) => {
            nearest_on_sphere(&p, sphere.frame().origin(), sphere.radius())
        }
        _ => {
            let feet = project_point_surface(
                s,
                &p,
                &surface_nodes(s, opts)?,
                &opts.precision,
                &opts.certify(),
            )?;
            nearest_foot(s, &p, &feet)
        }
    };
    let mut r = side.clone_with(Answer::Side(side.value, None));
    match nearest {
        Ok(mut point) => {
            point.nearest = Some(true);
            r.value = Answer::Side(side.value, Some(point));
        }
        Err(why) => r.reason = Some(format!("the nearest point is not proven: {why}")),
    }
    Ok(r)
}

/// The query point itself, on the shell: its own nearest point at distance 0.
fn exact_point(p: [f64; 3]) -> Point {
    Point {
        xyz: p.to_vec(),
        xyz_box: p.iter().map(|&x| [x, x]).collect(),
        multiplicity: 1,
        distance: Some(0.0),
        ..Default::default()
    }
}

/// The nearest point of a sphere ([`sphere_feet`]), unique unless `p` is the centre.
fn nearest_on_sphere(p: &[f64; 3], center: [f64; 3], radius: f64) -> Result<Point, String> {
    let [(b, distance), _] = sphere_feet(p, &center, radius)
        .ok_or("the point is the centre: every point of the sphere is nearest")?;
    Ok(Point {
        xyz: b.iter().map(|x| x.midpoint()).collect(),
        xyz_box: bounds(&b),
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
) -> Result<Point, String> {
    let n = nearest::nearest_point_surface(s, p, feet).ok_or("no foot was found")?;
    if n.status == Status::Undecided {
        return Err(n.reason.unwrap_or_default());
    }
    let NearestChoice::Foot(i) = n.choice else {
        return Err("the nearest point is not a foot".into());
    };
    let f = &feet.value[i];
    Ok(Point {
        xyz: f.point.to_vec(),
        xyz_box: bounds(&f.point_box),
        params: vec![f.root.params.clone()],
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
