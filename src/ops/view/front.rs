//! The front door of views (OPERATIONS.md §13.5): [`contour`] and [`visibility`] take
//! the typed shapes of [`crate::ops`] and answer in its [`Answer`] form, so that the
//! command line only translates.

use super::contour::{contour_surface, Contour, ContourOptions};
use super::projection::View;
use super::visibility::{visibility_point_surface, VisibilityAnswer};
use crate::certificate::Certified;
use crate::error::GeomError;
use crate::num::Interval;
use crate::ops::answer::{
    Answer, CurveAnswer, CurveEnd, CurveVertex, CurvesAnswer, Point, VisibilityPoint,
};
use crate::ops::{Options, Shape};
use crate::surface::AnySurface;
use crate::surface::Surface;

fn surface<'s>(s: &'s Shape, field: &str) -> Result<&'s AnySurface, GeomError> {
    match s {
        Shape::Surface(s) => Ok(s),
        _ => Err(GeomError::Unsupported {
            field: field.into(),
            reason: "views are defined for parametric surfaces".into(),
        }),
    }
}

/// The contour (outline) of a surface in a view, certified (§13.5; answer kind
/// `curves`: polylines with `xyz` and the surface's `[u, v]`, each vertex with its
/// proven distance bound; `complete` when no other component exists).
///
/// Errors: a shape that is not a parametric surface (field `objects[0]`); those of
/// [`contour_surface`].
pub fn contour(
    shape: &Shape,
    view: &View,
    options: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let s = surface(shape, "objects[0]")?;
    let opts = options.started();
    let c = contour_surface(
        s,
        view,
        &ContourOptions {
            certify: opts.certify(),
            ..ContourOptions::default()
        },
    )?;
    Ok(map_certified(c, |v| Answer::Curves(curves_answer(&v))))
}

/// The visibility of the point `s(params)` of the surface `shape` in `view`, occluded
/// by the surface itself and by `others` (§13.5, module `visibility`).
///
/// Errors: shapes that are not parametric surfaces (fields `objects[k]`); those of
/// [`visibility_point_surface`].
///
/// `verified` `visible`/`hidden` is proven (tests/visibility.rs checks it against the
/// closed-form truth at 300 bits); `undecided` where the point lies on (or within
/// rounding of) the contour and no contour point is proven near it, or where a ray
/// grazes a surface too closely for the solver's budget.
pub fn visibility(
    shape: &Shape,
    params: [f64; 2],
    view: &View,
    others: &[Shape],
    options: &Options,
) -> Result<Certified<VisibilityAnswer>, GeomError> {
    let s = surface(shape, "objects[0]")?;
    let rest = others
        .iter()
        .enumerate()
        .map(|(k, o)| surface(o, &format!("objects[{}]", k + 1)))
        .collect::<Result<Vec<_>, _>>()?;
    let opts = options.started();
    visibility_point_surface(s, params, view, &rest, &opts.certify())
}

/// `visibility` at the front door: [`visibility`] of `s(params)` on `shapes[0]`, occluded
/// by `shapes[1..]`, as an [`Answer::Visibility`] whose point carries `s(params)` with a
/// certified box (the surface evaluated in f64 interval arithmetic at the exact doubles
/// `params`, which encloses the true point), the parameters on `shapes[0]` (empty lists
/// for the others), and the index among `shapes` of the surface that hides it.
///
/// Errors: no shape (field `objects`); those of [`visibility`].
pub fn visibility_answer(
    shapes: &[Shape],
    params: [f64; 2],
    view: &View,
    options: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let (first, others) = shapes
        .split_first()
        .ok_or_else(|| GeomError::CountMismatch {
            field: "objects".into(),
            expected: "the surface, then any surfaces that may hide it".into(),
            found: "0".into(),
        })?;
    let c = visibility(first, params, view, others, options)?;
    let s = surface(first, "objects[0]")?;
    let [u, v] = params.map(Interval::point);
    let b = s.jet(&u, &v, 0).swap_remove(0);
    let mut params_out = vec![Vec::new(); shapes.len()];
    params_out[0] = params.to_vec();
    let mut param_box = vec![Vec::new(); shapes.len()];
    param_box[0] = params.iter().map(|&x| [x, x]).collect();
    let point = Point {
        xyz: c.value.xyz.to_vec(),
        xyz_box: b.iter().map(|i| [i.lo(), i.hi()]).collect(),
        params: params_out,
        param_box: Some(param_box),
        multiplicity: 1,
        ..Point::default()
    };
    let blocker = c.value.blocker.as_ref().map(|(k, _)| *k);
    Ok(map_certified(c, |v| {
        Answer::Visibility(VisibilityPoint {
            visibility: v.visibility,
            point,
            blocker,
        })
    }))
}

fn map_certified<T, U>(c: Certified<T>, f: impl FnOnce(T) -> U) -> Certified<U> {
    Certified {
        value: f(c.value),
        status: c.status,
        complete: c.complete,
        arithmetic: c.arithmetic,
        bits: c.bits,
        reason: c.reason,
        perturbation: c.perturbation,
    }
}

/// The contour in the `curves` form of surface ∩ surface.
pub fn curves_answer(c: &Contour) -> CurvesAnswer {
    let curves = c
        .curves
        .iter()
        .map(|k| {
            let points: Vec<CurveVertex> = k
                .points
                .iter()
                .map(|p| CurveVertex {
                    xyz: p.xyz.to_vec(),
                    params: vec![p.params.to_vec()],
                    bound: p.bound.as_ref().map(|b| b.distance),
                    exact: None,
                })
                .collect();
            let distance_bound = points
                .iter()
                .map(|p| p.bound)
                .try_fold(0.0f64, |m, b| b.map(|b| m.max(b)));
            let end = if k.closed {
                CurveEnd::Closed
            } else {
                CurveEnd::Boundary
            };
            CurveAnswer {
                points,
                closed: k.closed,
                ends: [end; 2],
                distance_bound,
                status: k.status,
                reason: k.reason.clone(),
            }
        })
        .collect();
    CurvesAnswer {
        curves,
        ..CurvesAnswer::default()
    }
}
