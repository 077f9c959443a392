//! `project`: the front door of every projection of a point (OPERATIONS.md §3).

use super::intersect::intersect;
use super::points::{distance, keep_nearest_hit};
use super::project_curved;
use crate::certificate::Certified;
use crate::curve::any::AnyCurve3;
use crate::error::GeomError;
use crate::geom::Line;
use crate::ops::algebraic::{project_point_conic2, project_point_conic3};
use crate::ops::answer::Answer;
use crate::ops::linear;
use crate::ops::options::{Options, ProjectOptions};
use crate::ops::shape::{Linear, LinearObject, Position, Shape};
use nalgebra::{Vector2, Vector3};

/// The projections of `point` onto `onto`: every foot of a perpendicular (points where
/// the distance is stationary, docs/FORMAT.md "Projections"), or with `nearest` the nearest
/// point of the closed domain, or with `direction` the hits of the ray (§3.5).
pub fn project(
    point: &Position,
    onto: &Shape,
    how: &ProjectOptions,
) -> Result<Certified<Answer>, GeomError> {
    let opts = &how.options;
    let direction = |field: &str| -> Result<Option<[f64; 3]>, GeomError> {
        how.direction
            .as_ref()
            .map(|d| d.doubles::<3>(field))
            .transpose()
    };
    match onto {
        Shape::Linear(l) => linear::project(point, l, how.nearest, how.direction.as_ref(), opts),
        Shape::Surface(s) => {
            let p = point.doubles::<3>("point")?;
            project_curved::onto_surface(s, p, how.nearest, direction("direction")?, opts)
        }
        Shape::Curve(_) if how.direction.is_some() => {
            let p = point.doubles::<3>("point")?;
            let d = direction("direction")?.unwrap_or_default();
            along_curve(onto, &p, &d, how.nearest, opts)
        }
        Shape::Curve2(_) | Shape::Conic2(_) if how.direction.is_some() => {
            let p = point.doubles::<2>("point")?;
            let d = how
                .direction
                .as_ref()
                .map_or(Ok([0.0; 2]), |d| d.doubles::<2>("direction"))?;
            along_curve(onto, &p, &d, how.nearest, opts)
        }
        Shape::Curve(c) => {
            let p = point.doubles::<3>("point")?;
            if let AnyCurve3::Analytic(a) = c {
                if let Some(r) = project_point_conic3(p, a, how.nearest, opts.deadline) {
                    return Ok(r);
                }
            }
            project_curved::onto_curve(c, p, how.nearest, opts)
        }
        Shape::Curve2(c) => {
            let p = point.doubles::<2>("point")?;
            match project_point_conic2(p, onto, how.nearest, opts.deadline) {
                Some(r) => Ok(r),
                None => project_curved::onto_curve(c, p, how.nearest, opts),
            }
        }
        Shape::Conic2(_) => {
            let p = point.doubles::<2>("point")?;
            project_point_conic2(p, onto, how.nearest, opts.deadline).ok_or_else(|| {
                GeomError::Unsupported {
                    field: "onto".into(),
                    reason: "projection onto a degenerate `conic2` (a line pair), or onto a \
                         conic from its centre, is not implemented"
                        .into(),
                }
            })
        }
        Shape::Polyhedron(_) => Err(GeomError::Unsupported {
            field: "onto.type".into(),
            reason: "a polyhedron is used as the `shell` of `classify` in this build".into(),
        }),
        Shape::Quadric(_) => Err(GeomError::Unsupported {
            field: "onto.type".into(),
            reason: "projection onto an implicit `quadric` is not implemented: the exact \
                     feet (OPERATIONS.md §3.4) are solved in the quadric's principal axes, \
                     which a general symmetric matrix has only with irrational directions; \
                     give the surface by its named type (`ellipsoid`, `paraboloid`, ...) to \
                     project onto it"
                .into(),
        }),
    }
}

/// Projection onto a curve along a direction (§3.5 as for surfaces): the hits of the ray
/// `point + t·direction`, `t ≥ 0`, on the curve, by the intersect front door (exact for
/// conics and lines, certified otherwise), each with its distance from `point`; with
/// `nearest` the hit nearest to `point` when its ray parameter is proven smallest
/// (a `conic2` is met by the ray's carrier, kept on the ray: `rays::keep_on_ray`).
/// Parameters: the curve's, then the ray's.
fn along_curve(
    onto: &Shape,
    p: &[f64],
    d: &[f64],
    nearest: bool,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    project_curved::nonzero_direction(d)?;
    let ray = if p.len() == 3 {
        LinearObject::Line(Line::ray(
            Vector3::from_column_slice(p),
            Vector3::from_column_slice(d),
        )?)
    } else {
        LinearObject::Line2(Line::ray(
            Vector2::from_column_slice(p),
            Vector2::from_column_slice(d),
        )?)
    };
    let shapes = [onto.clone(), Shape::Linear(Linear::Double(ray))];
    let mut r = intersect(&shapes, opts).map_err(|e| {
        e.renamed("objects[0]", "onto")
            .renamed("objects[1]", "direction")
    })?;
    if let Answer::Points(points) = &mut r.value {
        for q in points.iter_mut() {
            q.distance = Some(distance(&q.xyz, p));
        }
    }
    if nearest && matches!(&r.value, Answer::Points(v) if !v.is_empty()) {
        keep_nearest_hit(&mut r, 1);
    }
    Ok(r)
}
