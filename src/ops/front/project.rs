//! `project`: the front door of every projection of a point (OPERATIONS.md §3).

use super::project_curved;
use crate::certificate::Certified;
use crate::error::GeomError;
use crate::ops::algebraic::project_point_conic2;
use crate::ops::answer::Answer;
use crate::ops::linear;
use crate::ops::options::ProjectOptions;
use crate::ops::shape::{Position, Shape};

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
        Shape::Curve(c) => {
            let p = point.doubles::<3>("point")?;
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
