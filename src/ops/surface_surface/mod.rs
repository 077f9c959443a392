//! Surface ∩ surface with certified topology (OPERATIONS.md §1.9, §9, §10;
//! spec/CERTIFICATION.md).
//!
//! The unknowns are `x = [u, v, a, b]`, the parameters of the first surface `r` and of the
//! second `s`; the intersection is the solution set of (9.1) `r(u, v) − s(a, b) = 0`, a
//! curve where the 3 × 4 Jacobian `[r_u r_v −s_a −s_b]` has rank 3.
//!
//! * Float path ([`intersect_surface_surface_f64`]): start points on the iso-lines
//!   (§9.2), then tracing in both directions from each by marching (§9.3, with the guard
//!   of §9.3/§16.16), Dragilev's integration (§10.5, forms (10.4), (10.9), (10.5)–(10.6))
//!   or stepping without an ODE (§10.6); closure, boundary ends and covered start points
//!   (§9.4); contact points located and crossed (§9.5); the intermediate point of §9.6
//!   ([`intersection_point_at`]).
//! * Certified path ([`intersect_surface_surface`]): every traced curve is covered by a
//!   chain of boxes, in each of which the curve is proven to be a single smooth arc (a
//!   graph over one parameter, [`crate::certify::graph`]); consecutive boxes are proven
//!   to hold the same arc; every vertex gets a proven distance to the curve. Singular
//!   points get a box with a proven common normal along which the surfaces touch up to a
//!   reported perturbation (`verified_singular`). `complete` is proven by solving the
//!   boundary systems (iso-curves of the domain edges against the other surface, §5.2)
//!   and the height-critical system over the whole domain with the complete solver
//!   ([`crate::certify::solve`]): every component of the intersection either reaches
//!   the boundary or, being a closed loop, has a highest point; each such root must lie
//!   in a box of a certified chain (else it starts a new trace).

mod certified;
mod chain;
mod complete;
mod contact;
mod corrector;
mod ends;
mod equations;
mod float;
mod frame;
mod operand;
mod options;
mod singular;
mod start;
mod step;
mod trace;
mod types;

pub use equations::{CommonNormalSystem, CriticalSystem, PairJet, PairSystem};
pub use operand::SurfaceOperand;
pub use options::{DragilevForm, Method, Options};
pub use types::{
    CertifiedCurve, CertifiedSingularPoint, ChainBox, CurveEnd, CurvePoint, IntersectionCurve,
    SingularKind, SingularPoint, SurfaceIntersection, SurfaceIntersectionF64, VertexBound,
};

use crate::certificate::Certified;
use crate::error::GeomError;
use crate::surface::AnySurface;
use operand::Pair;

/// Every intersection curve and singular point of `a` and `b` (§9), float only: no proof,
/// and closed loops smaller than the iso-line spacing may be missed (§9.2 "Limitation").
///
/// Errors: a surface with an unbounded parameter domain (`objects[0].domain`, `objects[1].domain`), invalid
/// options (`options.*`).
///
/// Not generic, so it is compiled once, in this library: a caller's crate does not
/// compile the tracer and certifier again for [`AnySurface`] (surfaces of another type,
/// or your own [`SurfaceOperand`]: [`intersect_surface_surface_f64_of`]).
#[inline(never)]
pub fn intersect_surface_surface_f64(
    a: &AnySurface,
    b: &AnySurface,
    options: &Options,
) -> Result<SurfaceIntersectionF64, GeomError> {
    intersect_surface_surface_f64_of(a, b, options)
}

/// [`intersect_surface_surface_f64`] for any [`SurfaceOperand`]s (compiled in the caller's crate for their
/// types).
pub fn intersect_surface_surface_f64_of<A: SurfaceOperand, B: SurfaceOperand>(
    a: &A,
    b: &B,
    options: &Options,
) -> Result<SurfaceIntersectionF64, GeomError> {
    let pair = Pair::new(a, b, options)?;
    Ok(float::trace_all(&pair))
}

/// The branch through (a point near) `start = [u, v, a, b]`, float: the start is first
/// moved onto the curve by (10.13), then traced both ways (§9.3–§9.5). Returns the curve
/// and the singular points met on it.
///
/// Errors: `start` not finite, or no intersection point found near it (field `start`);
/// those of [`intersect_surface_surface_f64`].
///
/// Not generic, so it is compiled once, in this library: a caller's crate does not
/// compile the tracer and certifier again for [`AnySurface`] (surfaces of another type,
/// or your own [`SurfaceOperand`]: [`trace_surface_surface_f64_of`]).
#[inline(never)]
pub fn trace_surface_surface_f64(
    a: &AnySurface,
    b: &AnySurface,
    start: [f64; 4],
    options: &Options,
) -> Result<(IntersectionCurve, Vec<SingularPoint>), GeomError> {
    trace_surface_surface_f64_of(a, b, start, options)
}

/// [`trace_surface_surface_f64`] for any [`SurfaceOperand`]s (compiled in the caller's crate for their
/// types).
pub fn trace_surface_surface_f64_of<A: SurfaceOperand, B: SurfaceOperand>(
    a: &A,
    b: &B,
    start: [f64; 4],
    options: &Options,
) -> Result<(IntersectionCurve, Vec<SingularPoint>), GeomError> {
    let pair = Pair::new(a, b, options)?;
    let x = float::settle(&pair, start)?;
    let mut tracer = trace::Tracer::new(&pair);
    let curve = float::trace_branch(&mut tracer, x, &mut Vec::new());
    Ok((curve, tracer.singular))
}

/// §9.6: the point of a traced `curve` at the curve parameter `t` (its cumulative chord
/// length, `0 ≤ t ≤ t_max`), on both surfaces, float.
///
/// Errors: `t` outside the curve's range or not finite (field `t`); no convergence.
///
/// Not generic, so it is compiled once, in this library: a caller's crate does not
/// compile the tracer and certifier again for [`AnySurface`] (surfaces of another type,
/// or your own [`SurfaceOperand`]: [`intersection_point_at_of`]).
#[inline(never)]
pub fn intersection_point_at(
    a: &AnySurface,
    b: &AnySurface,
    curve: &IntersectionCurve,
    t: f64,
    options: &Options,
) -> Result<CurvePoint, GeomError> {
    intersection_point_at_of(a, b, curve, t, options)
}

/// [`intersection_point_at`] for any [`SurfaceOperand`]s (compiled in the caller's crate for their
/// types).
pub fn intersection_point_at_of<A: SurfaceOperand, B: SurfaceOperand>(
    a: &A,
    b: &B,
    curve: &IntersectionCurve,
    t: f64,
    options: &Options,
) -> Result<CurvePoint, GeomError> {
    let pair = Pair::new(a, b, options)?;
    float::point_at(&pair, curve, t)
}

/// Every component of `a ∩ b`, certified (module doc): curves covered by proven box
/// chains, singular points in `verified_singular` boxes, and `complete` when it is proven
/// that nothing else exists. What cannot be proven is reported `undecided` with the float
/// answer and the reason.
///
/// Errors: as [`intersect_surface_surface_f64`].
///
/// Not generic, so it is compiled once, in this library: a caller's crate does not
/// compile the tracer and certifier again for [`AnySurface`] (surfaces of another type,
/// or your own [`SurfaceOperand`]: [`intersect_surface_surface_of`]).
#[inline(never)]
pub fn intersect_surface_surface(
    a: &AnySurface,
    b: &AnySurface,
    options: &Options,
) -> Result<Certified<SurfaceIntersection>, GeomError> {
    intersect_surface_surface_of(a, b, options)
}

/// [`intersect_surface_surface`] for any [`SurfaceOperand`]s (compiled in the caller's crate for their
/// types).
pub fn intersect_surface_surface_of<A: SurfaceOperand, B: SurfaceOperand>(
    a: &A,
    b: &B,
    options: &Options,
) -> Result<Certified<SurfaceIntersection>, GeomError> {
    let pair = Pair::new(a, b, options)?;
    certified::intersect(&pair)
}

/// The branch through (a point near) `start`, certified: its box chain and vertex bounds
/// (`complete` is false: nothing is said about other branches).
///
/// Errors: as [`trace_surface_surface_f64`].
///
/// Not generic, so it is compiled once, in this library: a caller's crate does not
/// compile the tracer and certifier again for [`AnySurface`] (surfaces of another type,
/// or your own [`SurfaceOperand`]: [`trace_surface_surface_of`]).
#[inline(never)]
pub fn trace_surface_surface(
    a: &AnySurface,
    b: &AnySurface,
    start: [f64; 4],
    options: &Options,
) -> Result<Certified<SurfaceIntersection>, GeomError> {
    trace_surface_surface_of(a, b, start, options)
}

/// [`trace_surface_surface`] for any [`SurfaceOperand`]s (compiled in the caller's crate for their
/// types).
pub fn trace_surface_surface_of<A: SurfaceOperand, B: SurfaceOperand>(
    a: &A,
    b: &B,
    start: [f64; 4],
    options: &Options,
) -> Result<Certified<SurfaceIntersection>, GeomError> {
    let pair = Pair::new(a, b, options)?;
    let x = float::settle(&pair, start)?;
    certified::trace(&pair, x)
}
