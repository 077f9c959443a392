//! Visibility of a surface point in a view (OPERATIONS.md §13.5, (13.11) extended to
//! real occlusion): the point `P = s(u, v)` is hidden exactly when the ray
//! `P + t·w`, `t > 0`, toward the viewer (`w = d`, or `w = E − P` with `t < 1` for a
//! central view) meets the surface — or another given surface — again.
//!
//! The ray–surface system `P + t·w − s(a, b) = 0` (unknowns `t, a, b`) is solved with
//! the complete solver ([`crate::certify::solve`]) over `t ∈ [−τ, T]` and the surface's
//! domain; `P` enters as the interval hull of its enclosure (a family of systems: each
//! proof holds for every point of the hull, so for the exact `s(u, v)`). `T` is where
//! the ray leaves the interval bounding box of the surface (no point of the surface lies
//! beyond). The point itself is the root `(0, u, v)`; `visible` needs it verified (one
//! root in its box) and every other root proven to have `t < 0`, with nothing
//! undecided; `hidden` needs a verified root with `t > 0`. A point where `I` (13.10)
//! is not proven non-zero is reported `on_contour` when a contour point is proven
//! within a parameter distance of `10⁻⁹` around it.

use super::projection::{Rays, View};
use super::system::{ContourFn, EdgeSystem};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::certify::{solve, Options, Solutions, System};
use crate::error::GeomError;
use crate::num::vector::{add, scale, sub};
use crate::num::{Interval, Real};
use crate::ops::surface_surface::SurfaceOperand;
use crate::surface::Surface;

/// The verdict.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Visibility {
    Visible,
    Hidden,
    OnContour,
}

impl Visibility {
    /// The name the case format uses.
    pub fn as_str(self) -> &'static str {
        match self {
            Visibility::Visible => "visible",
            Visibility::Hidden => "hidden",
            Visibility::OnContour => "on_contour",
        }
    }
}

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

/// `P + t·w(P) − s(a, b)` with `P` an interval hull (module doc).
struct RaySystem<'a, S> {
    surface: &'a S,
    p: [[f64; 2]; 3],
    rays: Rays,
}

impl<S: Surface> System for RaySystem<'_, S> {
    fn dim(&self) -> usize {
        3
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let p: [T; 3] =
            std::array::from_fn(|i| x[0].lift(self.p[i][0]).hull_with(&x[0].lift(self.p[i][1])));
        let w: [T; 3] = match self.rays {
            Rays::Parallel(d) => d.map(|c| x[0].lift(c)),
            Rays::Central(e) => sub(&e.map(|c| x[0].lift(c)), &p),
        };
        let s = self.surface.jet(&x[1], &x[2], 0).swap_remove(0);
        sub(&add(&p, &scale(&x[0], &w)), &s).to_vec()
    }
}

/// An interval box enclosing the whole surface (16 × 16 interval patches).
fn bounding_box<S: Surface>(s: &S) -> [Interval; 3] {
    let (du, dv) = s.domain();
    let cell = |r: [f64; 2], i: usize| {
        let w = (r[1] - r[0]) / 16.0;
        Interval::from_bounds(
            r[0] + w * i as f64,
            if i == 15 {
                r[1]
            } else {
                r[0] + w * (i + 1) as f64
            },
        )
        .hull(&Interval::point(r[0] + w * i as f64))
    };
    let mut b: Option<[Interval; 3]> = None;
    for i in 0..16 {
        for j in 0..16 {
            let q = s.jet(&cell(du, i), &cell(dv, j), 0).swap_remove(0);
            b = Some(match b {
                None => q,
                Some(b) => std::array::from_fn(|k| b[k].hull(&q[k])),
            });
        }
    }
    b.unwrap_or([Interval::ENTIRE; 3])
}

/// The largest `t` at which `P + t·w` can still meet a surface inside `bx`.
fn ray_reach(bx: &[Interval; 3], p: &[Interval; 3], rays: Rays) -> f64 {
    match rays {
        Rays::Parallel(d) => {
            let w = d.map(Interval::point);
            let ww = crate::num::vector::dot(&w, &w);
            let top = (0..3).fold(Interval::point(0.0), |acc, i| acc + (bx[i] - p[i]) * w[i]);
            (top / ww).hi().max(0.0)
        }
        Rays::Central(_) => 1.0,
    }
}

/// Visibility of the point `s(params)` of `surface` in `view`, occluded by the surface
/// itself and by `others` (module doc).
///
/// Errors: `params` not finite or outside the domain (field `params`); invalid options.
pub fn visibility_point_surface<S: SurfaceOperand>(
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
    let p: [[f64; 2]; 3] = p_box.map(|c| [c.lo(), c.hi()]);
    let mut bits = 53;
    let mut undecided = Vec::new();
    let all: Vec<&S> = std::iter::once(surface)
        .chain(others.iter().copied())
        .collect();
    let reach = all
        .iter()
        .map(|s| ray_reach(&bounding_box(*s), &p_box, view.rays))
        .fold(0.0, f64::max);
    let tau = (1e-3 * reach).max(1e-6);
    for (k, s) in all.iter().enumerate() {
        let sys = RaySystem {
            surface: *s,
            p,
            rays: view.rays,
        };
        let (a, b) = s.domain();
        let sol = solve(&sys, &[[-tau, reach.max(tau)], a, b], opts)?;
        bits = bits.max(sol.bits);
        let own = (k == 0).then_some(params);
        match judge(&sol.value, own) {
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

enum Judged {
    Hit([Interval; 3]),
    Clear,
    Unsure(String),
}

/// What the roots of one ray system say (module doc); `own`: the point's parameters
/// when the surface is the point's own.
fn judge(sol: &Solutions, own: Option<[f64; 2]>) -> Judged {
    let is_own = |e: &[Interval]| {
        own.is_some_and(|[u, v]| e[0].contains(0.0) && e[1].contains(u) && e[2].contains(v))
    };
    let mut unsure = None;
    let mut own_found = own.is_none();
    for r in sol.roots.iter().chain(&sol.boundary_roots) {
        let e = &r.enclosure;
        if r.status == Status::Verified && e[0].lo() > 0.0 {
            return Judged::Hit([e[0], e[1], e[2]]);
        }
        if is_own(e) && r.status == Status::Verified {
            own_found = true;
        } else if e[0].hi() >= 0.0 {
            unsure = Some(format!(
                "a root box at t ∈ [{:e}, {:e}] is {:?}",
                e[0].lo(),
                e[0].hi(),
                r.status
            ));
        }
    }
    if let Some(u) = sol.undecided.first() {
        return Judged::Unsure(format!(
            "{} undecided box(es), first: {}",
            sol.undecided.len(),
            u.reason
        ));
    }
    match (unsure, own_found) {
        (Some(w), _) => Judged::Unsure(w),
        (None, false) => Judged::Unsure("the point itself is not verified as a ray root".into()),
        (None, true) => Judged::Clear,
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
