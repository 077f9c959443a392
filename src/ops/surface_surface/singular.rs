//! Certified singular points (OPERATIONS.md §9.5; CERTIFICATION.md `verified_singular`).
//!
//! A singular point of the float path gets a region `V` of `[u, v, a, b]` (a box about
//! `ρ L` across in space, `ρ` from [`REGION_SIZE`] up, grown where its faces cannot be
//! decided; a parameter whose derivative vanishes there — the angle at a cone's apex —
//! spans its whole period). Inside `V` the intersection is not resolved: chains end in
//! its interior, and the completeness proof treats it as a hole whose faces are
//! boundary. What is proven in `V`, in a tight box of its own, is a contact of a
//! perturbed input:
//!
//! * the common-normal system ([`CommonNormalSystem`]) has a verified root `(x*, λ*)` with
//!   `x* ∈ V`: moving `s` by `λ* N_s(a*, b*)`, of length at most the reported
//!   perturbation, makes the surfaces touch at `x*`; if the enclosure of `λ*` excludes 0
//!   the surfaces are proven not to touch there, and the point is `undecided` (a near
//!   contact whose topology is not resolved);
//! * failing that (a surface's normal vanishes, as at a cone's apex), when the other
//!   surface has an implicit form `G`: a verified critical point of `φ = G(q(u, v))` in
//!   `V`, with `φ` enclosed there: the level set `G = φ*` (the implicit surface offset by
//!   at most the reported perturbation, in units of `G`) meets `q` in a singular point.

use super::chain::{distance_bound, ChainContext};
use super::equations::CommonNormalSystem;
use super::types::SingularPoint;
use crate::certificate::Status;
use crate::certify::{certify_root, System};
use crate::num::vector::{cross, norm_f64, norm_sq};
use crate::num::{Interval, Real};
use crate::surface::{AnyImplicit, Implicit, Surface};

/// The first space size of a singular region, relative to `L`.
pub const REGION_SIZE: f64 = 1e-3;

/// A certified singular point.
#[derive(Debug, Clone)]
pub struct SingularBox {
    /// The tight box of the proof (the region when there is no proof).
    pub params: [Interval; 4],
    pub xyz: [Interval; 3],
    /// The region `V` in which the intersection is not resolved.
    pub region: [Interval; 4],
    pub region_xyz: [Interval; 3],
    /// The region's size relative to `L` (grown by the caller).
    pub size: f64,
    pub status: Status,
    pub perturbation: Option<f64>,
    pub reason: Option<String>,
}

/// `∇φ = (∇G(q)·q_u, ∇G(q)·q_v)` of `φ(u, v) = G(q(u, v))`, unknowns `(u, v)`.
pub struct ImplicitCriticalSystem<'a, Q> {
    pub q: &'a Q,
    pub g: &'a AnyImplicit,
}

impl<Q: Surface> System for ImplicitCriticalSystem<'_, Q> {
    fn dim(&self) -> usize {
        2
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let j = self.q.jet(&x[0], &x[1], 1);
        match self.g.implicit_jet(&j[0], 1).gradient {
            Some(grad) => vec![
                crate::num::vector::dot(&grad, &j[1]),
                crate::num::vector::dot(&grad, &j[2]),
            ],
            None => Vec::new(),
        }
    }
}

/// The region `V` of space size `size·L` around the singular point `p` (module doc).
pub fn singular_region<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    p: &SingularPoint,
    size: f64,
) -> [Interval; 4] {
    let pair = ctx.pair;
    let x = p.params;
    let jr = pair.r.jet(&x[0], &x[1], 1);
    let js = pair.s.jet(&x[2], &x[3], 1);
    let speed = [
        norm_f64(&jr[1]),
        norm_f64(&jr[2]),
        norm_f64(&js[1]),
        norm_f64(&js[2]),
    ];
    let top = speed.iter().copied().fold(0.0, f64::max);
    let rho = size * pair.length;
    std::array::from_fn(|k| {
        let c = &pair.coords[k];
        if speed[k] <= 1e-9 * top {
            if c.periodic {
                let quarter = 0.25 * (c.hi - c.lo);
                Interval::from_bounds(c.lo - quarter, c.hi + quarter)
            } else {
                Interval::from_bounds(ctx.search[k][0], ctx.search[k][1])
            }
        } else {
            let w = rho / speed[k];
            Interval::from_bounds(x[k] - w, x[k] + w)
        }
    })
}

/// Certify the singular point `p` (module doc) with the region `v` (from
/// [`singular_region`] of size `size`, possibly grown).
pub fn certify_singular<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    p: &SingularPoint,
    v: [Interval; 4],
    size: f64,
    opts: &crate::certify::Options,
) -> SingularBox {
    let pair = ctx.pair;
    let (region_xyz, _) = distance_bound(pair, &v, &p.xyz);
    let found = |w: [Interval; 4], e: f64, reason: Option<String>| SingularBox {
        params: w,
        xyz: distance_bound(pair, &w, &p.xyz).0,
        region: v,
        region_xyz,
        size,
        status: Status::VerifiedSingular,
        perturbation: Some(e),
        reason,
    };
    let undecided = |reason: String| SingularBox {
        params: v,
        xyz: region_xyz,
        region: v,
        region_xyz,
        size,
        status: Status::Undecided,
        perturbation: None,
        reason: Some(reason),
    };
    match common_normal_proof(ctx, p, &v, opts) {
        Proof::Touch(w, e) => found(w, e, None),
        Proof::Apart(gap) => undecided(format!(
            "near contact: the surfaces are proven not to touch at the common normal in the box \
             (gap enclosed in [{:e}, {:e}]); the curve's topology near it is not resolved",
            gap.lo(),
            gap.hi()
        )),
        Proof::None => match implicit_proof(ctx, p, &v, opts) {
            Proof::Touch(w, e) => found(
                w,
                e,
                Some(
                    "a singular point of the implicit surface offset by at most the perturbation \
                     (in units of its implicit function)"
                        .into(),
                ),
            ),
            Proof::Apart(gap) => undecided(format!(
                "near singular: the critical value of the implicit function is proven non-zero \
                 ([{:e}, {:e}]); the curve's topology near it is not resolved",
                gap.lo(),
                gap.hi()
            )),
            Proof::None => undecided("no proof of a contact in the box".into()),
        },
    }
}

enum Proof {
    /// A contact of an input perturbed by at most this much, in this box.
    Touch([Interval; 4], f64),
    /// Proven apart: the gap's enclosure.
    Apart(Interval),
    None,
}

fn common_normal_proof<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    p: &SingularPoint,
    v: &[Interval; 4],
    opts: &crate::certify::Options,
) -> Proof {
    let pair = ctx.pair;
    let sys = CommonNormalSystem {
        r: pair.r,
        s: pair.s,
    };
    let x = p.params;
    let js = pair.s.jet(&x[2], &x[3], 1);
    let ns = cross(&js[1], &js[2]);
    let nn = norm_sq(&ns);
    if nn.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Proof::None;
    }
    let d = crate::num::vector::sub(&pair.r.jet(&x[0], &x[1], 0)[0], &js[0]);
    let lambda = crate::num::vector::dot(&d, &ns) / nn;
    let Ok(c) = certify_root(&sys, &[x[0], x[1], x[2], x[3], lambda], opts) else {
        return Proof::None;
    };
    if c.status != Status::Verified {
        return Proof::None;
    }
    let e = &c.value.enclosure;
    let w: [Interval; 4] = std::array::from_fn(|k| e[k]);
    if !ctx.shifted_inside(&w, v, true) {
        return Proof::None;
    }
    let lam = e[4];
    if !lam.contains_zero() {
        return Proof::Apart(lam);
    }
    let jw = pair.s.jet(&w[2], &w[3], 1);
    let n = norm_sq(&cross(&jw[1], &jw[2])).sqrt();
    Proof::Touch(w, (lam.abs() * n).hi())
}

fn implicit_proof<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    p: &SingularPoint,
    v: &[Interval; 4],
    opts: &crate::certify::Options,
) -> Proof {
    let pair = ctx.pair;
    let x = p.params;
    // the proof is about the parametric surface's two parameters; the other pair of the
    // box is the region's
    if let Some(g) = &pair.implicit[1] {
        match critical_proof(pair.r, g, [x[0], x[1]], [v[0], v[1]], opts) {
            Proof::Touch([a, b, ..], e) => Proof::Touch([a, b, v[2], v[3]], e),
            other => other,
        }
    } else if let Some(g) = &pair.implicit[0] {
        match critical_proof(pair.s, g, [x[2], x[3]], [v[2], v[3]], opts) {
            Proof::Touch([a, b, ..], e) => Proof::Touch([v[0], v[1], a, b], e),
            other => other,
        }
    } else {
        Proof::None
    }
}

fn critical_proof<Q: Surface>(
    q: &Q,
    g: &AnyImplicit,
    at: [f64; 2],
    within: [Interval; 2],
    opts: &crate::certify::Options,
) -> Proof {
    let sys = ImplicitCriticalSystem { q, g };
    let Ok(c) = certify_root(&sys, &at, opts) else {
        return Proof::None;
    };
    let e = &c.value.enclosure;
    if c.status != Status::Verified || !(e[0].is_subset(&within[0]) && e[1].is_subset(&within[1])) {
        return Proof::None;
    }
    let point = q.jet(&e[0], &e[1], 0).swap_remove(0);
    let phi = g.implicit_jet(&point, 0).value;
    if phi.contains_zero() {
        Proof::Touch([e[0], e[1], e[0], e[1]], phi.mag())
    } else {
        Proof::Apart(phi)
    }
}
