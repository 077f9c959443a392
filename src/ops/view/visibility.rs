//! Visibility of a surface point in a view (OPERATIONS.md §13.5, (13.11) extended to
//! real occlusion): the point `P = s(u, v)` is hidden exactly when the ray
//! `P + t·w`, `t > 0`, toward the viewer (`w = d`, or `w = E − P` with `t < 1` for a
//! central view) meets the surface — or another given surface — again.
//!
//! Per surface, what the ray meets is proven by module `ray`: for a surface with an
//! implicit form `G`, the univariate `G(P + t·w) = 0` over `t ∈ [−τ, T]` (each root
//! `t > 0` then checked on the patch with the ray–surface system in a small `t`
//! interval, unless the patch is the whole closed surface); otherwise, or when that
//! univariate solve is not complete, the ray–surface system `P + t·w − s(a, b) = 0`
//! (unknowns `t, a, b`) over `t ∈ [−τ, T]` and the surface's domain. Both are solved
//! with the complete solver ([`crate::certify::solve`]); `P = s(u, v)` is evaluated
//! inside each system in its number type, so an interval evaluation encloses the exact
//! point. `T` is where the ray leaves the interval bounding
//! box of the surface (no point of the surface lies beyond) or the eye. The point
//! itself is the root `t = 0`; `visible` needs it verified (one root in its box) and
//! every other root proven to have `t < 0` (or, on the implicit route, proven off the
//! patch), with nothing undecided; `hidden` needs a verified root with `t > 0` (and
//! `t < 1` for a central view). A point where `I` (13.10) is not proven non-zero is
//! reported `on_contour` when a contour point is proven within a parameter distance of
//! `10⁻⁹` around it.

use super::projection::View;
use super::ray::{by_implicit, ray_reach, Judged, Ray};
use super::system::{ContourFn, EdgeSystem};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::certify::{solve, Options};
use crate::error::GeomError;
use crate::num::Interval;
use crate::ops::surface_surface::SurfaceOperand;
use crate::surface::whole_box::surface_box;
use crate::surface::{AnySurface, Surface};

pub use crate::ops::answer::Visibility;

/// The answer of [`visibility_point_surface`].
#[derive(Debug, Clone, PartialEq)]
pub struct VisibilityAnswer {
    pub visibility: Visibility,
    /// `s(u, v)`.
    pub xyz: [f64; 3],
    /// An enclosure of `I(u, v)` (13.10) at the point (its sign is the potential
    /// visibility of (13.11) when the normal points outward).
    pub contour_value: Interval,
    /// For `hidden`: the occluding surface (0 = the surface itself, `k` = `others[k−1]`)
    /// and the enclosure `[t, a, b]` of the proven hit.
    pub blocker: Option<(usize, [Interval; 3])>,
}

/// Visibility of the point `s(params)` of `surface` in `view`, occluded by the surface
/// itself and by `others` (module doc).
///
/// Not generic, so it is compiled once, in this library (surfaces of another type:
/// [`visibility_point_surface_of`]).
///
/// Errors: `params` not finite or outside the domain (field `params`); invalid options.
#[inline(never)]
pub fn visibility_point_surface(
    surface: &AnySurface,
    params: [f64; 2],
    view: &View,
    others: &[&AnySurface],
    opts: &Options,
) -> Result<Certified<VisibilityAnswer>, GeomError> {
    visibility_point_surface_of(surface, params, view, others, opts)
}

/// [`visibility_point_surface`] for any [`SurfaceOperand`] (compiled in the caller's
/// crate for its type).
pub fn visibility_point_surface_of<S: SurfaceOperand>(
    surface: &S,
    params: [f64; 2],
    view: &View,
    others: &[&S],
    opts: &Options,
) -> Result<Certified<VisibilityAnswer>, GeomError> {
    opts.check()?;
    crate::error::require_finite_all("params", &params)?;
    let (du, dv) = surface.domain();
    if !(du[0] <= params[0] && params[0] <= du[1] && dv[0] <= params[1] && params[1] <= dv[1]) {
        return Err(GeomError::InvalidValue {
            field: "params".into(),
            reason: format!("{params:?} is outside the domain {du:?} × {dv:?}"),
        });
    }
    let f = ContourFn {
        surface,
        implicit: surface.implicit_form(),
        view,
    };
    let (u, v) = (Interval::point(params[0]), Interval::point(params[1]));
    let i_val = f.value(&u, &v);
    let p_box = surface.jet(&u, &v, 0).swap_remove(0);
    let xyz = surface.jet(&params[0], &params[1], 0)[0];
    let answer = |visibility, blocker| VisibilityAnswer {
        visibility,
        xyz,
        contour_value: i_val,
        blocker,
    };
    let certified = |value, status, bits: u32, reason: Option<String>| Certified {
        value,
        status,
        complete: status != Status::Undecided,
        arithmetic: if bits > 53 {
            Arithmetic::Mpfr
        } else {
            Arithmetic::Interval
        },
        bits,
        reason,
        perturbation: None,
    };
    if i_val.contains_zero() {
        let proven = near_contour(&f, params, opts)?;
        let (status, reason) = if proven {
            (
                Status::Verified,
                "a contour point is proven within 1e-9 (parameters) of the point",
            )
        } else {
            (
                Status::Undecided,
                "I = 0 is not excluded at the point and no contour point is proven near it",
            )
        };
        return Ok(certified(
            answer(Visibility::OnContour, None),
            status,
            53,
            Some(reason.into()),
        ));
    }
    let mut bits = 53;
    let mut undecided = Vec::new();
    let all: Vec<&S> = std::iter::once(surface)
        .chain(others.iter().copied())
        .collect();
    let reach = all
        .iter()
        .map(|s| ray_reach(&surface_box(*s), &p_box, view.rays))
        .fold(0.0, f64::max);
    let tau = (1e-3 * reach).max(1e-6);
    for (k, s) in all.iter().enumerate() {
        let ray = Ray {
            origin: surface,
            at: params,
            rays: view.rays,
            range: [-tau, reach.max(tau)],
            own: (k == 0).then_some(params),
        };
        let quick = match s.implicit_form() {
            Some(g) => by_implicit(*s, &g, &ray, opts)?,
            None => None,
        };
        let (judged, b) = match quick {
            Some(j) => j,
            None => ray.solve_3d(*s, ray.range, opts)?,
        };
        bits = bits.max(b);
        match judged {
            Judged::Hit(r) => {
                return Ok(certified(
                    answer(Visibility::Hidden, Some((k, r))),
                    Status::Verified,
                    bits,
                    None,
                ))
            }
            Judged::Clear => {}
            Judged::Unsure(why) => undecided.push(format!("surface {k}: {why}")),
        }
    }
    if undecided.is_empty() {
        Ok(certified(
            answer(Visibility::Visible, None),
            Status::Verified,
            bits,
            None,
        ))
    } else {
        Ok(certified(
            answer(Visibility::Visible, None),
            Status::Undecided,
            bits,
            Some(undecided.join("; ")),
        ))
    }
}

/// A contour point is proven within `10⁻⁹` (relative) of the point, along either
/// parameter line through it.
fn near_contour<S: Surface>(
    f: &ContourFn<'_, S>,
    x: [f64; 2],
    opts: &Options,
) -> Result<bool, GeomError> {
    for fixed in 0..2 {
        let other = 1 - fixed;
        let eps = 1e-9 * x[other].abs().max(1.0);
        let sys = EdgeSystem {
            f,
            fixed,
            at: x[fixed],
        };
        let sol = solve(&sys, &[[x[other] - eps, x[other] + eps]], opts)?;
        if sol.value.roots.iter().any(|r| r.status == Status::Verified) {
            return Ok(true);
        }
    }
    Ok(false)
}
