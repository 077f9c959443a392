//! The completeness proof of surface ∩ surface (CERTIFICATION.md "Completeness").
//!
//! Let `D` be the search box of `[u, v, a, b]` (periodic parameters glued) and `V` the
//! union of the singular regions (boxes where the intersection is not resolved; their
//! interiors are holes: `D' = D \ int V`). Every connected component `C` of the
//! intersection `S ∩ D'` is either an arc whose ends lie on `∂D'` — on a face of the
//! domain outside `int V`, or on a face of a singular region inside `D` — or a closed loop
//! in the interior of `D'`. An arc's end is a root of a *face system*: the iso-curve of
//! the face against the other surface (§5.2, [`CurveSurfaceSystem`]), three equations in
//! three unknowns. A loop is compact, so the height `h = d·p` has a maximum on it, a root
//! of the height-critical system ([`CriticalSystem`]) outside `V`; so is a point where
//! the curve is not regular. Both kinds of roots are found by the complete certified
//! solver ([`solve`], subdivision with exclusion); boxes it leaves undecided are harmless
//! only inside `V`. Each root must lie in a box of a certified chain, or (a critical root,
//! or one on a domain face) in `V`: then its component is that chain's, or it is not a
//! point of `D'`. A root that matches nothing is a point of a component not yet traced:
//! the caller traces from it and tries again.
//!
//! A face decided exactly ([`super::ends`]) is not solved: it holds no point of the
//! intersection, or one where the curve touches it from inside the domain — such a
//! point is not an end of any arc, and its component is a loop found by the critical
//! system or an arc with ends on other faces.

use super::chain::ChainContext;
use super::equations::CriticalSystem;
use crate::certificate::Status;
use crate::certify::{solve, Root, System};
use crate::curve::Curve;
use crate::error::GeomError;
use crate::num::Interval;
use crate::ops::intersect::curve_surface::CurveSurfaceSystem;
use crate::ops::project::IsoCurve;
use crate::surface::Surface;

/// Where a root was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RootKind {
    /// On a face of the domain.
    DomainFace,
    /// On a face of a singular region.
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

/// What the solves of one kind proved: roots (existence proven), the boxes left
/// undecided (any other root lies in one of them) and why.
#[derive(Debug, Clone, Default)]
pub struct Solved {
    pub roots: Vec<RootBox>,
    pub undecided: Vec<([Interval; 4], RootKind)>,
    pub reasons: Vec<String>,
    pub bits: u32,
}

impl Solved {
    fn absorb(
        &mut self,
        c: crate::Certified<crate::certify::Solutions>,
        lift: impl Fn(&[Interval]) -> [Interval; 4],
        kind: RootKind,
    ) {
        self.bits = self.bits.max(c.bits);
        let v = c.value;
        for r in v.roots.iter().chain(&v.boundary_roots) {
            self.roots.push(root_box(r, &lift, kind));
        }
        for u in &v.undecided {
            self.undecided.push((lift(&u.enclosure), kind));
        }
        if let Some(first) = v.undecided.first() {
            self.reasons.push(format!("{kind:?}: {}", first.reason));
        }
    }

    pub fn extend(&mut self, other: Solved) {
        self.roots.extend(other.roots);
        self.undecided.extend(other.undecided);
        self.reasons.extend(other.reasons);
        self.bits = self.bits.max(other.bits);
    }
}

fn root_box(r: &Root, lift: &impl Fn(&[Interval]) -> [Interval; 4], kind: RootKind) -> RootBox {
    let points: Vec<Interval> = r.estimate.iter().map(|&x| Interval::point(x)).collect();
    let est = lift(&points);
    RootBox {
        params: lift(&r.enclosure),
        estimate: est.map(|x| x.midpoint()),
        status: r.status,
        kind,
    }
}

/// Height directions for the critical system, tried in turn (a curve lying in a plane
/// normal to one of them makes its roots non-isolated).
pub const DIRECTIONS: [[f64; 3]; 3] = [[2.0, 3.0, 6.0], [-6.0, 2.0, 3.0], [3.0, -6.0, 2.0]];

/// The roots of the height-critical system with direction `d` over the search box.
pub fn critical_roots<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    d: [f64; 3],
    opts: &crate::certify::Options,
) -> Result<Solved, GeomError> {
    let sys = CriticalSystem {
        r: ctx.pair.r,
        s: ctx.pair.s,
        direction: d,
    };
    let mut out = Solved {
        bits: 53,
        ..Solved::default()
    };
    let c = solve(&sys, &ctx.search, opts)?;
    out.absorb(c, |x| std::array::from_fn(|k| x[k]), RootKind::Critical);
    Ok(out)
}

/// The roots of the face systems of the domain's bounded faces outside the holes.
pub fn domain_face_roots<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    holes: &[[Interval; 4]],
    opts: &crate::certify::Options,
) -> Result<Solved, GeomError> {
    let pair = ctx.pair;
    let mut out = Solved {
        bits: 53,
        ..Solved::default()
    };
    for k in 0..4 {
        if pair.coords[k].periodic {
            continue;
        }
        for bound in ctx.search[k] {
            // decided exactly (`super::ends`): no point, or one where the curve only
            // touches the face from inside, which every loop through it covers
            if pair.decided.iter().any(|d| d.k == k && d.bound == bound) {
                continue;
            }
            let face: [[f64; 2]; 4] = std::array::from_fn(|i| {
                if i == k {
                    [bound, bound]
                } else {
                    ctx.search[i]
                }
            });
            let mut pieces = vec![face];
            for h in holes.iter().filter(|h| h[k].contains(bound)) {
                pieces = pieces.iter().flat_map(|p| subtract(p, h, k)).collect();
            }
            for p in pieces {
                face_solve(ctx, k, &p, RootKind::DomainFace, opts, &mut out)?;
            }
        }
    }
    Ok(out)
}

/// The roots of the face systems of one hole's faces inside the domain (a hole spanning a
/// whole period of a periodic coordinate has no faces in it).
pub fn hole_face_roots<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    h: &[Interval; 4],
    opts: &crate::certify::Options,
) -> Result<Solved, GeomError> {
    let pair = ctx.pair;
    let mut out = Solved {
        bits: 53,
        ..Solved::default()
    };
    {
        for k in 0..4 {
            if covers_period(ctx, k, &h[k]) {
                continue;
            }
            for bound in [h[k].lo(), h[k].hi()] {
                let c = &pair.coords[k];
                if !(c.periodic || ctx.search[k][0] < bound && bound < ctx.search[k][1]) {
                    continue;
                }
                let face: Option<Vec<[f64; 2]>> = (0..4)
                    .map(|i| {
                        if i == k {
                            return Some([bound, bound]);
                        }
                        let (lo, hi) = (h[i].lo(), h[i].hi());
                        if pair.coords[i].periodic {
                            Some([lo, hi])
                        } else {
                            let [a, b] = ctx.search[i];
                            (lo.max(a) <= hi.min(b)).then_some([lo.max(a), hi.min(b)])
                        }
                    })
                    .collect();
                if let Some(f) = face {
                    let f: [[f64; 2]; 4] = std::array::from_fn(|i| f[i]);
                    face_solve(ctx, k, &f, RootKind::SingularFace, opts, &mut out)?;
                }
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

/// The face box `f` (coordinate `k` fixed) minus the hole's interior, in the other three
/// coordinates: up to six boxes.
fn subtract(f: &[[f64; 2]; 4], h: &[Interval; 4], k: usize) -> Vec<[[f64; 2]; 4]> {
    let others = (0..4).filter(|&i| i != k);
    let disjoint = others
        .clone()
        .any(|i| h[i].hi() <= f[i][0] || h[i].lo() >= f[i][1]);
    if disjoint {
        return vec![*f];
    }
    let mut out = Vec::new();
    let mut rest = *f;
    for i in others {
        let [lo, hi] = rest[i];
        if h[i].lo() > lo {
            let mut piece = rest;
            piece[i] = [lo, h[i].lo()];
            out.push(piece);
        }
        if h[i].hi() < hi {
            let mut piece = rest;
            piece[i] = [h[i].hi(), hi];
            out.push(piece);
        }
        rest[i] = [lo.max(h[i].lo()), hi.min(h[i].hi())];
    }
    out
}

/// Solve the face `x_k = f[k]` over the box `f`: the iso-curve of the surface owning `x_k`
/// (running in that surface's other parameter) against the other surface.
fn face_solve<R: Surface, S: Surface>(
    ctx: &ChainContext<'_, '_, R, S>,
    k: usize,
    f: &[[f64; 2]; 4],
    kind: RootKind,
    opts: &crate::certify::Options,
    out: &mut Solved,
) -> Result<(), GeomError> {
    let pair = ctx.pair;
    let bound = f[k][0];
    let (own, other) = if k < 2 { (0, 2) } else { (2, 0) };
    let running = own + (1 - (k % 2));
    let domain = [f[other], f[other + 1], f[running]];
    let lift = |x: &[Interval]| -> [Interval; 4] {
        let mut p = [Interval::point(bound); 4];
        p[other] = x[0];
        p[other + 1] = x[1];
        p[running] = x[2];
        p
    };
    let direction = 1 - (k % 2);
    let c = if k < 2 {
        let curve = IsoCurve {
            surface: pair.r,
            direction,
            fixed: bound,
        };
        solve_face(pair.s, &curve, &domain, opts)?
    } else {
        let curve = IsoCurve {
            surface: pair.s,
            direction,
            fixed: bound,
        };
        solve_face(pair.r, &curve, &domain, opts)?
    };
    out.absorb(c, lift, kind);
    Ok(())
}

fn solve_face<Q: Surface, C: Curve<3>>(
    surface: &Q,
    curve: &C,
    domain: &[[f64; 2]; 3],
    opts: &crate::certify::Options,
) -> Result<crate::Certified<crate::certify::Solutions>, GeomError> {
    let sys = CurveSurfaceSystem { surface, curve };
    debug_assert_eq!(sys.dim(), 3);
    solve(&sys, domain, opts)
}
