//! The linear shapes through the linear kernel (OPERATIONS.md §3.1, §3.3, §5.1,
//! §6.1–6.2, §7.1, §8): certified on doubles, or — when a number is not a double, or
//! the caller asks for the exact rationals — the same decision procedure on exact
//! rationals. Every answer is `exact`.

mod answer;
mod kernel;

use nalgebra::Vector3;
use rug::Rational;

use self::kernel::Kernel;
use super::answer::Answer;
use super::options::Options;
use super::shape::{Linear, LinearObject, Position};
use crate::certificate::Certified;
use crate::error::GeomError;
use crate::geom::line_plane::LinePlane;
use crate::geom::{Coord, Line, Linear as LinearRef, Plane};

/// The objects in one coordinate type: doubles when every object is on doubles and
/// exact rationals were not asked for, else rationals.
enum Objects {
    Double(Vec<LinearObject<f64>>),
    Exact(Vec<LinearObject<Rational>>),
}

fn objects(shapes: &[&Linear], exact: bool) -> Objects {
    let doubles: Option<Vec<LinearObject<f64>>> = (!exact)
        .then(|| {
            shapes
                .iter()
                .map(|s| match s {
                    Linear::Double(o) => Some(o.clone()),
                    Linear::Exact(_) => None,
                })
                .collect()
        })
        .flatten();
    match doubles {
        Some(d) => Objects::Double(d),
        None => Objects::Exact(shapes.iter().map(|s| s.exact()).collect()),
    }
}

/// Intersect two or three linear shapes.
pub(crate) fn intersect(
    shapes: &[&Linear],
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    match objects(shapes, opts.exact) {
        Objects::Double(o) => intersect_in(&o, opts.exact),
        Objects::Exact(o) => intersect_in(&o, opts.exact),
    }
}

fn unsupported_pair<T: Coord>(objects: &[LinearObject<T>]) -> GeomError {
    let names: Vec<&str> = objects.iter().map(|o| o.type_name()).collect();
    GeomError::Unsupported {
        field: "objects".into(),
        reason: format!(
            "intersect of {} is not implemented in this build",
            names.join(" and ")
        ),
    }
}

fn intersect_in<T: Kernel>(
    objects: &[LinearObject<T>],
    keep: bool,
) -> Result<Certified<Answer>, GeomError> {
    match objects {
        [a, b] => {
            if let (Some(l), Some(p)) = (a.linear(), b.plane()) {
                return Ok(answer::line_plane(T::line_plane(l, p, keep), l, true, keep));
            }
            if let (Some(p), Some(l)) = (a.plane(), b.linear()) {
                return Ok(answer::line_plane(
                    T::line_plane(l, p, keep),
                    l,
                    false,
                    keep,
                ));
            }
            if let (Some(l), Some(m)) = (a.linear(), b.linear()) {
                return Ok(answer::line_line(T::line_line(l, m, keep), l, keep));
            }
            if let (Some(p), Some(q)) = (a.plane(), b.plane()) {
                return Ok(answer::plane_plane(T::plane_plane(p, q, keep)));
            }
            if let (Some(l), Some(m)) = (a.linear2(), b.linear2()) {
                // The 2D kernel reads closed ranges only: a pair with a ray is decided
                // in space, in the plane z = 0 (an exact embedding: same parameters,
                // same decision, coordinates with z = 0 dropped after).
                if [l, m].iter().any(is_ray2) {
                    let (x, y) = (in_space(a)?, in_space(b)?);
                    let (Some(lx), Some(ly)) = (x.linear(), y.linear()) else {
                        return Err(unsupported_pair(objects));
                    };
                    let r = answer::line_line(T::line_line(lx, ly, keep), lx, keep);
                    return Ok(answer::in_plane(r));
                }
                return Ok(answer::lines2(T::lines2(l, m, keep), l));
            }
            Err(unsupported_pair(objects))
        }
        [a, b, c] => match (a.plane(), b.plane(), c.plane()) {
            (Some(p), Some(q), Some(r)) => {
                let planes = [p.clone(), q.clone(), r.clone()];
                Ok(answer::three_planes(T::three_planes(&planes, keep)))
            }
            _ => Err(unsupported_pair(objects)),
        },
        other => Err(GeomError::InvalidValue {
            field: "objects".into(),
            reason: format!("intersect takes 2 or 3 objects, found {}", other.len()),
        }),
    }
}

/// A 2D line (ray, ranged line) or segment as the same object in the plane `z = 0`.
fn in_space<T: Coord>(o: &LinearObject<T>) -> Result<LinearObject<T>, GeomError> {
    let lift = |v: &nalgebra::Vector2<T>| Vector3::new(v[0].clone(), v[1].clone(), T::zero_coord());
    Ok(match o {
        LinearObject::Line2(l) => LinearObject::Line(crate::geom::Line::with_param_range(
            lift(l.origin()),
            lift(l.dir()),
            l.param_range().cloned(),
        )?),
        LinearObject::Segment2(s) => {
            LinearObject::Segment(crate::geom::Segment::new(lift(s.a()), lift(s.b()))?)
        }
        other => other.clone(),
    })
}

fn is_ray2<T: Coord>(l: &crate::geom::Linear2<'_, T>) -> bool {
    matches!(l, crate::geom::Linear2::Line(l) if l.is_ray())
}

/// A query point as a 3D vector (`field`: its name in messages).
fn vec3<T: Clone>(v: &[T], field: &str) -> Result<Vector3<T>, GeomError> {
    match v {
        [x, y, z] => Ok(Vector3::new(x.clone(), y.clone(), z.clone())),
        _ => Err(GeomError::Format {
            field: field.into(),
            message: format!("expected 3 coordinates, found {}", v.len()),
        }),
    }
}

/// Project a point onto a linear shape: the foot on a line or segment (or the nearest
/// point with `nearest`), the foot on a plane, or along `direction` onto a plane
/// (§3.5).
pub(crate) fn project(
    point: &Position,
    onto: &Linear,
    nearest: bool,
    direction: Option<&Position>,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let doubles = !opts.exact
        && !matches!(direction, Some(Position::Exact(_)))
        && matches!(point, Position::Double(_));
    if let (true, Position::Double(p), Linear::Double(o)) = (doubles, point, onto) {
        let dir = match direction {
            Some(Position::Double(d)) => Some(vec3(d, "direction")?),
            _ => None,
        };
        return project_in(&vec3(p, "point")?, o, nearest, dir, false);
    }
    let p = vec3(&point.exact(), "point")?;
    let dir = direction
        .map(|d| vec3(&d.exact(), "direction"))
        .transpose()?;
    project_in(&p, &onto.exact(), nearest, dir, opts.exact)
}

fn project_in<T: Kernel>(
    p: &Vector3<T>,
    onto: &LinearObject<T>,
    nearest: bool,
    direction: Option<Vector3<T>>,
    keep: bool,
) -> Result<Certified<Answer>, GeomError> {
    if let Some(dir) = direction {
        let Some(plane) = onto.plane() else {
            return Err(GeomError::Unsupported {
                field: "direction".into(),
                reason: format!(
                    "projection along a direction onto a {} is not implemented in this build",
                    onto.type_name()
                ),
            });
        };
        let line = Line::new(p.clone(), dir).map_err(|e| match e {
            GeomError::ZeroDirection { .. } => GeomError::ZeroDirection {
                field: "direction".into(),
            },
            other => other,
        })?;
        return Ok(along(p, LinearRef::Line(&line), plane, keep));
    }
    if let Some(l) = onto.linear() {
        return Ok(answer::project_line(T::project_line(p, l, keep), nearest));
    }
    if let Some(plane) = onto.plane() {
        return Ok(answer::project_plane(T::project_plane(p, plane, keep)));
    }
    Err(GeomError::Unsupported {
        field: "onto".into(),
        reason: format!(
            "projection onto a {} is not implemented in this build",
            onto.type_name()
        ),
    })
}

/// Projection along a direction onto a plane (OPERATIONS.md §3.5): the line through
/// the point along the direction meets the plane; a point on the plane is its own
/// projection whatever the direction.
fn along<T: Kernel>(
    p: &Vector3<T>,
    line: LinearRef<'_, T>,
    plane: &Plane<T>,
    keep: bool,
) -> Certified<Answer> {
    let c = T::line_plane(line, plane, keep);
    if matches!(c.value, LinePlane::Contained) {
        return answer::project_plane(T::project_plane(p, plane, keep));
    }
    let mut r = answer::line_plane(c, line, true, keep);
    // The case has one shape (`onto`): drop the parameter of the auxiliary line.
    if let Answer::Points(points) = &mut r.value {
        for pt in points {
            pt.params.remove(0);
            if let Some(b) = pt.param_box.as_mut() {
                b.remove(0);
            }
            if let Some(e) = pt.exact.as_mut() {
                e.params.remove(0);
            }
        }
    }
    r
}

/// A point against a polyhedral shell, exactly (OPERATIONS.md §4).
pub(crate) fn classify_polyhedron(
    point: &Position,
    shell: &crate::ops::Polyhedron,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let p = vec3(&point.exact(), "point")?;
    let c =
        crate::ops::classify_point_polyhedron(&[p[0].clone(), p[1].clone(), p[2].clone()], shell);
    Ok(answer::shell_point(c, opts.exact))
}
