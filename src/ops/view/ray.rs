//! The ray toward the viewer and what it meets (OPERATIONS.md §13.5, (13.11) extended to
//! real occlusion), for [`super::visibility`].
//!
//! The ray from `P` is `P + t·w`, `w = d` (parallel) or `w = E − P` (central, `t < 1`).
//! `P = s(u, v)` is evaluated inside every system below in the number type of the
//! evaluation, at the double parameters lifted as constants: an interval evaluation
//! encloses the exact point (tighter at higher precision), and it stays a smooth
//! constant for the certifier. (A hull of a fixed enclosure, built with
//! [`Real::hull_with`], is marked non-smooth by the certifier's `Guarded` — the join of
//! two pieces — so no Krawczyk test could pass and every solve spent its box budget:
//! the `undecided` and minute-long visibility of issue 17.)
//!
//! * [`RaySystem`]: `P + t·w − s(a, b) = 0` in `(t, a, b)`, any parametric surface.
//! * The implicit route ([`by_implicit`]): for a surface with an implicit form `G`
//!   (§1.4, vanishing exactly on the surface: the frame is the exact orthonormal frame
//!   of the double inputs), every point of the patch on the ray is a root of the
//!   univariate `g(t) = G(P + t·w)` — a quadratic for a quadric, a quartic for a torus —
//!   solved completely over `t` by [`crate::certify::solve`] in one dimension instead
//!   of three. A root `t > 0` is a point of the patch when the patch is the whole
//!   implicit surface (a closed sphere, ellipsoid or ring torus: [`covers`]); otherwise
//!   the three-dimensional system is solved with `t` restricted to a small interval
//!   around that root, which proves the hit on the patch or that there is none.

use super::projection::Rays;
use crate::certificate::Status;
use crate::certify::{solve, Options, Solutions, System};
use crate::error::GeomError;
use crate::num::vector::{add, scale, sub};
use crate::num::{Interval, Real};
use crate::surface::{AnyImplicit, Implicit, Surface};

/// `P + t·w(P) − s(a, b)` (module doc).
struct RaySystem<'r, 'a, S> {
    surface: &'r S,
    ray: &'r Ray<'a, S>,
}

impl<S: Surface> System for RaySystem<'_, '_, S> {
    fn dim(&self) -> usize {
        3
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let s = self.surface.jet(&x[1], &x[2], 0).swap_remove(0);
        sub(&self.ray.point(&x[0]), &s).to_vec()
    }
}

/// `g(t) = G(P + t·w(P))` (module doc).
struct ImplicitRay<'r, 'a, S> {
    g: &'r AnyImplicit,
    ray: &'r Ray<'a, S>,
}

impl<S: Surface> System for ImplicitRay<'_, '_, S> {
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let q = self.ray.point(&x[0]);
        vec![self.g.implicit_jet(&q, 0).value]
    }
}

/// The largest `t` at which `P + t·w` can still meet a surface inside `bx` (central:
/// the eye, `t = 1`).
pub fn ray_reach(bx: &[Interval; 3], p: &[Interval; 3], rays: Rays) -> f64 {
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

/// What the ray does with one surface.
pub enum Judged {
    /// A proven point of the surface on the ray at `t > 0` (before the eye): `[t, a, b]`.
    Hit([Interval; 3]),
    /// Proven: no point of the surface on the ray at `t > 0` but the point itself.
    Clear,
    Unsure(String),
}

/// The ray and what it may meet: the point `origin(at)`, the rays, the `t` range
/// `[−τ, T]` searched, and `own`: the point's parameters when the surface is the
/// point's own.
pub struct Ray<'a, S> {
    pub origin: &'a S,
    pub at: [f64; 2],
    pub rays: Rays,
    pub range: [f64; 2],
    pub own: Option<[f64; 2]>,
}

impl<S: Surface> Ray<'_, S> {
    /// `P + t·w(P)`, `P = origin(at)` in the number type of `t` (module doc).
    fn point<T: Real>(&self, t: &T) -> [T; 3] {
        let p = self
            .origin
            .jet(&t.lift(self.at[0]), &t.lift(self.at[1]), 0)
            .swap_remove(0);
        let w: [T; 3] = match self.rays {
            Rays::Parallel(d) => d.map(|c| t.lift(c)),
            Rays::Central(e) => sub(&e.map(|c| t.lift(c)), &p),
        };
        add(&p, &scale(t, &w))
    }

    /// A `t` enclosure that proves a hit: after `0`, and before the eye for a central
    /// view (`t = 1`; a parallel view has no far end).
    fn ahead(&self, t: &Interval) -> bool {
        t.lo() > 0.0 && (matches!(self.rays, Rays::Parallel(_)) || t.hi() < 1.0)
    }

    /// What the roots of the three-dimensional system say (module doc).
    pub fn judge(&self, sol: &Solutions) -> Judged {
        let is_own = |e: &[Interval]| {
            self.own
                .is_some_and(|[u, v]| e[0].contains(0.0) && e[1].contains(u) && e[2].contains(v))
        };
        let mut unsure = None;
        let mut own_found = self.own.is_none();
        for r in sol.roots.iter().chain(&sol.boundary_roots) {
            let e = &r.enclosure;
            if r.status == Status::Verified && self.ahead(&e[0]) {
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
            (None, false) => {
                Judged::Unsure("the point itself is not verified as a ray root".into())
            }
            (None, true) => Judged::Clear,
        }
    }

    /// The three-dimensional system over `t ∈ t_range` and the whole domain.
    pub fn solve_3d(
        &self,
        s: &S,
        t_range: [f64; 2],
        opts: &Options,
    ) -> Result<(Judged, u32), GeomError> {
        let sys = RaySystem {
            surface: s,
            ray: self,
        };
        let (a, b) = s.domain();
        let sol = solve(&sys, &[t_range, a, b], opts)?;
        Ok((self.judge(&sol.value), sol.bits))
    }
}

/// The patch is all of its implicit surface: a sphere or ellipsoid closed in `u` with
/// both poles, a ring torus closed in both directions (their implicit forms vanish on
/// that closed surface only).
pub fn covers<S: Surface>(s: &S, g: &AnyImplicit) -> bool {
    match g {
        AnyImplicit::Sphere(_) | AnyImplicit::Ellipsoid(_) => {
            s.is_closed()[0] && s.v_poles() == [true, true]
        }
        AnyImplicit::Torus(_) => s.is_closed() == [true, true],
        _ => false,
    }
}

/// The implicit route (module doc). `None` when the univariate solve leaves part of the
/// `t` range undecided (the caller then solves the three-dimensional system).
pub fn by_implicit<S: Surface>(
    s: &S,
    g: &AnyImplicit,
    ray: &Ray<'_, S>,
    opts: &Options,
) -> Result<Option<(Judged, u32)>, GeomError> {
    let sys = ImplicitRay { g, ray };
    let sol = solve(&sys, &[ray.range], opts)?;
    if !sol.value.undecided.is_empty() {
        return Ok(None);
    }
    let mut bits = sol.bits;
    let mut own_found = ray.own.is_none();
    let mut unsure = Vec::new();
    let whole = covers(s, g);
    for r in sol.value.roots.iter().chain(&sol.value.boundary_roots) {
        let t = r.enclosure[0];
        let verified = r.status == Status::Verified;
        if t.hi() < 0.0 {
            continue;
        }
        if ray.own.is_some() && verified && t.contains(0.0) {
            // the point itself: `g(0) = 0` for the exact point, one root in the box
            own_found = true;
            continue;
        }
        if !(verified && ray.ahead(&t)) {
            unsure.push(format!(
                "a root of G on the ray at t ∈ [{:e}, {:e}] is {:?}",
                t.lo(),
                t.hi(),
                r.status
            ));
            continue;
        }
        let (judged, b) = on_patch(s, ray, &t, opts)?;
        bits = bits.max(b);
        match judged {
            Judged::Hit(e) => return Ok(Some((Judged::Hit(e), bits))),
            // the patch is the whole implicit surface: the root is a hit; only its
            // parameters are not enclosed more tightly than the domain
            _ if whole => {
                let (a, b) = s.domain();
                let e = [
                    t,
                    Interval::from_bounds(a[0], a[1]),
                    Interval::from_bounds(b[0], b[1]),
                ];
                return Ok(Some((Judged::Hit(e), bits)));
            }
            Judged::Clear => {}
            Judged::Unsure(why) => unsure.push(why),
        }
    }
    let judged = if !own_found {
        Judged::Unsure("the point itself is not verified as a root of G on the ray".into())
    } else if let Some(w) = unsure.first() {
        Judged::Unsure(w.clone())
    } else {
        Judged::Clear
    };
    Ok(Some((judged, bits)))
}

/// The three-dimensional system with `t` in a small interval around the root box `t`
/// of `g` (`t > 0`): a verified root proves the hit on the patch; none (complete)
/// proves that the point of the implicit surface there is off the patch. The interval
/// may hold other roots of `g`: each of its verified roots is a hit all the same.
fn on_patch<S: Surface>(
    s: &S,
    ray: &Ray<'_, S>,
    t: &Interval,
    opts: &Options,
) -> Result<(Judged, u32), GeomError> {
    let grow = t.width().max(1e-7 * t.mag().max(1.0));
    let lo = (t.lo() - grow).max(0.5 * t.lo());
    let hi = t.hi() + grow;
    let hi = if matches!(ray.rays, Rays::Central(_)) {
        hi.min(ray.range[1]).max(t.hi())
    } else {
        hi
    };
    let probe = Ray { own: None, ..*ray };
    probe.solve_3d(s, [lo, hi], opts)
}
