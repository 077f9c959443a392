//! Plane ∩ plane, OPERATIONS.md §8 with the correction (8.3), unnormalised.
//!
//! With `N_a`, `N_b` the unnormalised normals (`u × v` or the given normal), the
//! direction is `n = N_a × N_b` (eq. (8.1) without the unit normals: its length is
//! `|N_a||N_b| sin θ`, not `sin θ`). The point is (8.3) generalised to any reference
//! point `x_r` (`b`'s origin when `b` is parametric — then it is exactly (8.3) — else
//! `a`'s origin, else the coordinate origin) with `F = f(x_r)` the planes' values there:
//! `p = x_r − (F_a (N_b × n) + F_b (n × N_a))/|n|²`, the projection of `x_r` onto the line.
//!
//! The parameter lines (8.4) on a parametric plane are `l(t) = (u_p, v_p) + t(du, dv)`
//! for the points `p + t n`. `(du, dv)` are the coordinates of `n` in the plane's basis,
//! which simplify exactly (`n × s₂ = N_a(N_b·s₂)`-type identities) to polynomials:
//! on `a`: `(du, dv) = (−N_b·a₂, N_b·a₁)`; on `b`: `(N_a·b₂, −N_a·b₁)`. `(u_p, v_p)` solves
//! `p = a₀ + u a₁ + v a₂` via the two conditions `f_b(p) = 0`, `n·(p − x_r) = 0`, whose
//! determinant is `|n|²`: `u = (e (n·a₂) − (N_b·a₂) g)/|n|²`, `v = ((N_b·a₁) g − e (n·a₁))/|n|²`
//! with `e = −f_b(a₀)`, `g = n·(x_r − a₀)`; on `b` the same with the roles swapped and
//! determinant `−|n|²`.
//!
//! `n = 0` exactly: `Coincident` if the planes share a point (`f_a(o_b) = 0`, or
//! `h_a N_b = h_b N_a` for two implicit planes `N·x = h`), else `Parallel`.

mod exact;
mod filter;
mod lanes;
#[cfg(test)]
mod tests;

pub use lanes::{intersect_plane_plane_batch, PlanePlaneCase};

pub(crate) use exact::{
    coincide_parallel, core, dir_exponent, finish, round_line, round_line_ring, terms_from,
};
#[cfg(test)]
pub(crate) use filter::bound_planes;
#[cfg(test)]
pub(crate) use lanes::assert_four_lane_run_equals_scalar;

use exact::exact_tiers;
use filter::fast;

use nalgebra::{Scalar, Vector2, Vector3};
use rug::Rational;

use super::data::PlaneData;
use super::exact_tier::filter_certified;
use super::objects::Plane;
use crate::certificate::Certified;
use crate::num::dd::ProductMode;
use crate::num::filter::dispatch_fma;
use crate::num::round::Rounded;

/// A line in a plane's parameter space: `l(t) = origin + t·dir` (OPERATIONS.md eq. (8.4)).
#[derive(Debug, Clone, PartialEq)]
pub struct ParamLine<S: Scalar> {
    pub origin: Vector2<S>,
    pub dir: Vector2<S>,
}

/// The intersection line `p(t) = point + t·dir` with its parameter lines on each
/// parametric plane (`on_a(t)`, `on_b(t)` are the parameters of `p(t)`).
///
/// `dir = 2^dir_exponent · (N_a × N_b)`, and the parameter-line directions are scaled
/// alike. `dir_exponent` is 0 unless the largest component of `N_a × N_b` lies outside
/// `[2⁻¹⁰⁰⁰, 2¹⁰⁰⁰)`; then it brings that component into `[1, 2)`, so that it rounds
/// to a finite normal double (certified path only: `_f64` and `_exact` use 0).
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneLine<S: Scalar> {
    pub point: Vector3<S>,
    pub dir: Vector3<S>,
    pub dir_exponent: i32,
    pub on_a: Option<ParamLine<S>>,
    pub on_b: Option<ParamLine<S>>,
}

/// The result of plane ∩ plane.
#[derive(Debug, Clone, PartialEq)]
pub enum PlanePlane<S: Scalar> {
    Line(PlaneLine<S>),
    /// Parallel and distinct: empty.
    Parallel,
    /// The same plane.
    Coincident,
}

impl<S: Scalar> ParamLine<S> {
    fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> ParamLine<T> {
        ParamLine {
            origin: self.origin.map(&mut f),
            dir: self.dir.map(&mut f),
        }
    }
}

impl<S: Scalar> PlaneLine<S> {
    /// Apply `f` to every number.
    pub fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> PlaneLine<T> {
        PlaneLine {
            point: self.point.map(&mut f),
            dir: self.dir.map(&mut f),
            dir_exponent: self.dir_exponent,
            on_a: self.on_a.map(|l| l.map(&mut f)),
            on_b: self.on_b.map(|l| l.map(&mut f)),
        }
    }
}

impl<S: Scalar> PlanePlane<S> {
    /// Apply `f` to every number.
    pub fn map<T: Scalar>(self, f: impl FnMut(S) -> T) -> PlanePlane<T> {
        match self {
            PlanePlane::Line(l) => PlanePlane::Line(l.map(f)),
            PlanePlane::Parallel => PlanePlane::Parallel,
            PlanePlane::Coincident => PlanePlane::Coincident,
        }
    }
}

/// Plain f64 (uncertified; `n == 0.0` decides parallelism).
pub fn intersect_plane_plane_f64(a: &Plane<f64>, b: &Plane<f64>) -> PlanePlane<f64> {
    core::<f64>(&PlaneData::new(a), &PlaneData::new(b))
}

/// Exact, on rational inputs.
pub fn intersect_plane_plane_exact(
    a: &Plane<Rational>,
    b: &Plane<Rational>,
) -> PlanePlane<Rational> {
    core::<Rational>(&PlaneData::new(a), &PlaneData::new(b))
}

/// Certified: exact verdict, correctly rounded point, direction and parameter lines.
pub fn intersect_plane_plane(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>> {
    dispatch_fma!(certified(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>>)
}

/// The filter, then the exact tiers (instantiated once per product mode, so that the
/// answer is built in place).
#[inline(always)]
fn certified<M: ProductMode>(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>> {
    match fast::<M>(a, b) {
        Some(l) => filter_certified(PlanePlane::Line(l)),
        None => exact_tiers(a, b),
    }
}
