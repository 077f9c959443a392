//! Line (ranged line, segment) ∩ plane, OPERATIONS.md §5.1.
//!
//! With `N` the plane's unnormalised normal and `f(x) = N·(x − o)` (or `n·x + d`), the
//! carrier `c(t) = c₀ + t c'` meets the plane where `f(c₀) + t N·c' = 0`, i.e. eq. (5.1)
//! with the normalisation of `n̂` cancelled:
//! `t = −f(c₀)/(N·c')`, `p = (c₀ (N·c') − f(c₀) c')/(N·c')`. The plane parameters follow
//! from Cramer's rule on `u·s₁ + v·s₂ − t c' = c₀ − s₀` (equivalent to (3.7)–(3.8) for a
//! point of the plane, with a lower degree): `u = det(w, s₂, c')/(N·c')`,
//! `v = det(s₁, w, c')/(N·c')`, `w = c₀ − s₀`, since `det(s₁, s₂, c') = N·c'`.
//! `N·c' = 0` exactly: `Contained` if `f(c₀) = 0`, else `Parallel`.

mod exact;
mod filter;
mod lanes;
#[cfg(test)]
mod tests;

#[cfg(test)]
pub(crate) use lanes::assert_four_lane_run_equals_scalar;
pub use lanes::{intersect_line_plane_batch, LinePlaneCase};

use nalgebra::{Scalar, Vector2, Vector3};
use rug::Rational;

use super::data::{Linear, PlaneData};
use super::exact_tier::filter_certified;
use super::objects::Plane;
use crate::certificate::Certified;
use crate::num::dd::ProductMode;
use crate::num::filter::dispatch_fma;
use crate::num::round::Rounded;
use exact::{core, exact_tiers};
use filter::fast;

/// Where a line meets a plane: the point, the line parameter `t` and, for a parametric
/// plane, the plane parameters `(u, v)`.
#[derive(Debug, Clone, PartialEq)]
pub struct LinePlanePoint<S> {
    pub point: Vector3<S>,
    pub t: S,
    pub uv: Option<Vector2<S>>,
}

/// The result of line ∩ plane.
#[derive(Debug, Clone, PartialEq)]
pub enum LinePlane<S> {
    /// One point, inside the line's domain.
    Point(LinePlanePoint<S>),
    /// The carrier is parallel to the plane and off it: empty.
    Parallel,
    /// The whole line (segment, ranged line) lies in the plane.
    Contained,
    /// Empty: the carrier meets the plane at this point, outside the line's domain.
    OutsideDomain(LinePlanePoint<S>),
}

impl<S: Scalar> LinePlanePoint<S> {
    fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> LinePlanePoint<T> {
        LinePlanePoint {
            point: self.point.map(&mut f),
            t: f(self.t),
            uv: self.uv.map(|uv| uv.map(&mut f)),
        }
    }
}

impl<S: Scalar> LinePlane<S> {
    /// Apply `f` to every number of the result.
    pub fn map<T: Scalar>(self, f: impl FnMut(S) -> T) -> LinePlane<T> {
        match self {
            LinePlane::Point(p) => LinePlane::Point(p.map(f)),
            LinePlane::OutsideDomain(p) => LinePlane::OutsideDomain(p.map(f)),
            LinePlane::Parallel => LinePlane::Parallel,
            LinePlane::Contained => LinePlane::Contained,
        }
    }
}

/// Plain f64 (uncertified; `N·c' == 0.0` decides parallelism).
pub fn intersect_line_plane_f64(line: Linear<f64>, plane: &Plane<f64>) -> LinePlane<f64> {
    core::<f64>(&line.data(), &PlaneData::new(plane))
}

/// Exact, on rational inputs.
pub fn intersect_line_plane_exact(
    line: Linear<Rational>,
    plane: &Plane<Rational>,
) -> LinePlane<Rational> {
    core::<Rational>(&line.data(), &PlaneData::new(plane))
}

/// Certified: the exact verdict for the double inputs, coordinates correctly rounded
/// with enclosures. Tiers: the double-double filter (generic input), fixed-width
/// integers, expansions, rationals.
pub fn intersect_line_plane(
    line: Linear<f64>,
    plane: &Plane<f64>,
) -> Certified<LinePlane<Rounded>> {
    dispatch_fma!(certified(line: Linear<f64>, plane: &Plane<f64>) -> Certified<LinePlane<Rounded>>)
}

/// The filter, then the exact tiers (instantiated once per product mode, so that the
/// answer is built in place).
#[inline(always)]
fn certified<M: ProductMode>(
    line: Linear<f64>,
    plane: &Plane<f64>,
) -> Certified<LinePlane<Rounded>> {
    match fast::<M>(line, plane) {
        Some(r) => filter_certified(r),
        None => exact_tiers(line, plane),
    }
}
