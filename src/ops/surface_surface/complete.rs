//! The completeness proof of surface ∩ surface (CERTIFICATION.md "Completeness").
//!
//! Let `D` be the search box of `[u, v, a, b]` (periodic parameters glued) and `V` the
//! union of the singular boxes (their interiors are holes: `D' = D \ int V`). Every
//! connected component `C` of the intersection `S ∩ D'` is either an arc whose ends lie
//! on `∂D'` — a face of the domain or of a singular box — or a closed loop in the interior
//! of `D'`. An arc's end is a root of a *face system*: the iso-curve of the face against
//! the other surface (§5.2, [`CurveSurfaceSystem`]), three equations in three unknowns. A
//! loop is compact, so the height `h = d·p` has a maximum on it, a root of the
//! height-critical system ([`CriticalSystem`]); so is a point where the curve is not
//! regular. Both kinds of roots are found — all of them, or the proof is incomplete — by
//! the complete certified solver ([`certify_roots`], subdivision with exclusion; the
//! critical system over the whole domain). Each root must lie in a box of a certified
//! chain, or (not for a root on a singular box's face) in a singular box: then its
//! component is that chain's, or it is not outside the holes. A root that matches
//! nothing is a point of a component not yet traced: the caller traces from it and tries
//! again. At a contact the critical system has a double root, which the solver encloses
//! in a `verified_singular` box; the caller grows the singular box to hold it.

use super::chain::ChainContext;
use super::equations::CriticalSystem;
use crate::certificate::Status;
use crate::curve::Curve;
use crate::error::GeomError;
use crate::num::Interval;
use crate::ops::certified::{
    certify_roots, curve_unknowns, surface_unknowns, CertifiedRoot, Unknowns,
};
use crate::ops::intersect::curve_surface::CurveSurfaceSystem;
use crate::ops::project::IsoCurve;
use crate::surface::Surface;

/// Where a root was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RootKind {
    /// On a face of the domain.
    DomainFace,
    /// On a face of a singular box.
    SingularFace,
    /// A height-critical point (or a non-regular point) of the curve.
    Critical,
}

/// A root of a completeness system, in `[u, v, a, b]`.
#[derive(Debug, Clone)]
pub struct RootBox {
    pub params: [Interval; 4],
    pub estimate: [f64; 4],
    pub status: Status,
    pub kind: RootKind,
}

/// The roots of all completeness systems and whether the solves were complete.
#[derive(Debug, Clone, Default)]
pub struct Roots {
    pub roots: Vec<RootBox>,
    pub complete: bool,
    pub reasons: Vec<String>,
    pub bits: u32,
}

impl Roots {
    fn absorb(
        &mut self,
        c: crate::Certified<Vec<CertifiedRoot>>,
        map: impl Fn(&CertifiedRoot) -> RootBox,
        what: &str,
    ) {
        self.bits = self.bits.max(c.bits);
        if !c.complete {
            self.complete = false;
            self.reasons.push(format!(
                "{what}: {}",
                c.reason.unwrap_or_else(|| "incomplete".into())
            ));
        }
        self.roots.extend(c.value.iter().map(map));
    }
}

/// Height directions for the critical system, tried in turn (a curve lying in a plane
/// normal to one of them makes its roots non-isolated).
pub const DIRECTIONS: [[f64; 3]; 3] = [[2.0, 3.0, 6.0], [-6.0, 2.0, 3.0], [3.0, -6.0, 2.0]];

/// Roots of the face systems of the domain's bounded faces and of the singular boxes'
/// faces (those inside the domain).
pub fn face_roots<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    holes: &[[Interval; 4]],
    opts: &crate::certify::Options,
) -> Result<Roots, GeomError> {
    let pair = ctx.pair;
    let mut out = Roots {
        complete: true,
        bits: 53,
        ..Roots::default()
    };
    for k in 0..4 {
        if pair.coords[k].periodic {
            continue;
        }
        for bound in ctx.search[k] {
            let c = face_solve(ctx, k, bound, None, opts)?;
            out.absorb(
                c,
                |r| root_box(k, bound, r, RootKind::DomainFace),
                "domain face",
            );
        }
    }
    for hole in holes {
        for k in 0..4 {
            if covers_period(ctx, k, &hole[k]) {
                continue;
            }
            for bound in [hole[k].lo(), hole[k].hi()] {
                let c = face_solve(ctx, k, bound, Some(hole), opts)?;
                out.absorb(
                    c,
                    |r| root_box(k, bound, r, RootKind::SingularFace),
                    "singular box face",
                );
            }
        }
    }
    Ok(out)
}

/// The interval spans a whole period of periodic coordinate `k`.
pub fn covers_period<R, S>(ctx: &ChainContext<'_, '_, R, S>, k: usize, x: &Interval) -> bool {
    let c = &ctx.pair.coords[k];
    c.periodic && x.lo() <= c.lo && x.hi() >= c.hi
}

/// The face `x_k = bound`: the iso-curve of the surface owning `x_k` against the other
/// surface, over the search box (or over the hole's extent).
fn face_solve<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    k: usize,
    bound: f64,
    hole: Option<&[Interval; 4]>,
    opts: &crate::certify::Options,
) -> Result<crate::Certified<Vec<CertifiedRoot>>, GeomError> {
    let pair = ctx.pair;
    // The iso-curve's running parameter is the other parameter of the same surface.
    let direction = 1 - (k % 2);
    if k < 2 {
        let iso = IsoCurve {
            surface: pair.r,
            direction,
            fixed: bound,
        };
        solve_face(pair.s, &iso, hole.map(|h| [h[2], h[3], h[1 - k]]), opts)
    } else {
        let iso = IsoCurve {
            surface: pair.s,
            direction,
            fixed: bound,
        };
        solve_face(
            pair.r,
            &iso,
            hole.map(|h| [h[0], h[1], h[2 + 1 - (k - 2)]]),
            opts,
        )
    }
}

fn solve_face<Q: Surface, C: Curve<3>>(
    surface: &Q,
    curve: &C,
    within: Option<[Interval; 3]>,
    opts: &crate::certify::Options,
) -> Result<crate::Certified<Vec<CertifiedRoot>>, GeomError> {
    let sys = CurveSurfaceSystem { surface, curve };
    let unknowns = match within {
        None => Unknowns::concat(&[surface_unknowns(surface), curve_unknowns(curve)]),
        Some(w) => Unknowns {
            domain: w.iter().map(|x| [x.lo(), x.hi()]).collect(),
            periodic: vec![false; 3],
            rounded: vec![false; 3],
        },
    };
    certify_roots(&sys, &unknowns, &[], opts)
}

/// A face root `(p, q, t)` (surface parameters, then the iso-curve's) in `[u, v, a, b]`.
fn root_box(k: usize, bound: f64, r: &CertifiedRoot, kind: RootKind) -> RootBox {
    let (e, x) = (&r.enclosure, &r.params);
    // the owning surface's pair: (fixed k, running t); the other surface: (e0, e1)
    let mut params = [Interval::ZERO; 4];
    let mut estimate = [0.0; 4];
    let (own, other) = if k < 2 { (0, 2) } else { (2, 0) };
    params[other] = e[0];
    params[other + 1] = e[1];
    estimate[other] = x[0];
    estimate[other + 1] = x[1];
    let running = own + (1 - (k % 2));
    params[k] = Interval::point(bound);
    estimate[k] = bound;
    params[running] = e[2];
    estimate[running] = x[2];
    RootBox {
        params,
        estimate,
        status: r.status,
        kind,
    }
}

/// Roots of the height-critical system over the search box, with the first direction of
/// [`DIRECTIONS`] whose solve is complete.
pub fn critical_roots<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    opts: &crate::certify::Options,
) -> Result<Roots, GeomError> {
    let mut last = Roots::default();
    for d in DIRECTIONS {
        let sys = CriticalSystem {
            r: ctx.pair.r,
            s: ctx.pair.s,
            direction: d,
        };
        let mut out = Roots {
            complete: true,
            bits: 53,
            ..Roots::default()
        };
        let unknowns = Unknowns {
            domain: ctx.search.to_vec(),
            periodic: ctx.pair.coords.iter().map(|c| c.periodic).collect(),
            rounded: vec![false; 4],
        };
        let c = certify_roots(&sys, &unknowns, &[], opts)?;
        out.absorb(c, critical_box, "height-critical system");
        if out.complete {
            return Ok(out);
        }
        last = out;
    }
    Ok(last)
}

fn critical_box(r: &CertifiedRoot) -> RootBox {
    RootBox {
        params: std::array::from_fn(|k| r.enclosure[k]),
        estimate: std::array::from_fn(|k| r.params[k]),
        status: r.status,
        kind: RootKind::Critical,
    }
}
