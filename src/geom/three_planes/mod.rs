//! Three planes, OPERATIONS.md §7.1, with every degenerate outcome (CGAL's result kinds:
//! a point, a line, a plane, or nothing).
//!
//! With unnormalised normals `N_i` and `D = N₀·(N₁ × N₂)` (eq. (7.2)'s denominator with
//! the normalisations cancelled), a reference point `x_r` (the first parametric plane's
//! origin, else the coordinate origin) and `F_i = f_i(x_r)`:
//! `p = x_r − (F₀ N₁×N₂ + F₁ N₂×N₀ + F₂ N₀×N₁)/D` (Cramer on `N_i·(p − x_r) = −F_i`).
//! Parameters on a parametric plane `k` (with `i, j` the next two, cyclically) solve the
//! 2×2 system `f_i(o_k + u u_k + v v_k) = 0`, `f_j(...) = 0`, whose determinant is
//! `(N_i × N_j)·(u_k × v_k) = D`: `u = (F_j (N_i·v_k) − F_i (N_j·v_k))/D`,
//! `v = (F_i (N_j·u_k) − F_j (N_i·u_k))/D`, `F = f(o_k)`. This is (3.7)–(3.8) for the
//! point, of lower degree (§16.7's `(t, τ) = (−1, 2)` needs no orthogonal basis).
//!
//! `D = 0` exactly: if every `N_i × N_j = 0`, all normals are parallel: `Plane` when all
//! three coincide (plane 0 shares a point with each other, see
//! `plane_plane::coincide_parallel`), else `Empty`. Otherwise the first pair `(i, j)`
//! (in the order (0,1), (0,2), (1,2)) with `N_i × N_j ≠ 0` gives the line of §8; it is
//! the answer if it lies in the third plane (`f_k(p) = 0`; its direction is orthogonal to
//! `N_k` because `D = 0`), else `Empty`. This covers two coincident planes crossed by a
//! third, three planes through one line, two parallel planes and a third crossing them,
//! and the prism of three pairwise crossing planes with parallel lines.

mod exact;
mod filter;
mod lanes;
#[cfg(test)]
mod tests;

#[cfg(test)]
pub(crate) use lanes::assert_four_lane_run_equals_scalar;
pub use lanes::intersect_three_planes_batch;

use nalgebra::{Scalar, Vector2, Vector3};
use rug::Rational;

use super::data::PlaneData;
use super::exact_tier::filter_certified;
use super::objects::Plane;
use super::plane_plane::PlaneLine;
use crate::certificate::Certified;
use crate::num::dd::ProductMode;
use crate::num::filter::dispatch_fma;
use crate::num::round::Rounded;
use exact::{core, exact_tiers};
use filter::fast;

/// The result of three planes.
#[derive(Debug, Clone, PartialEq)]
pub enum ThreePlanes<S: Scalar> {
    /// One point, with its parameters on each parametric plane (input order).
    Point {
        point: Vector3<S>,
        params: [Option<Vector2<S>>; 3],
    },
    /// A common line (see [`PlaneLine`]; `pair` names the two planes it was computed
    /// from, whose parameter lines `on_a`, `on_b` it carries).
    Line {
        line: PlaneLine<S>,
        pair: (usize, usize),
    },
    /// All three planes coincide.
    Plane,
    /// No common point.
    Empty,
}

impl<S: Scalar> ThreePlanes<S> {
    /// Apply `f` to every number.
    pub fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> ThreePlanes<T> {
        match self {
            ThreePlanes::Point { point, params } => ThreePlanes::Point {
                point: point.map(&mut f),
                params: params.map(|p| p.map(|p| p.map(&mut f))),
            },
            ThreePlanes::Line { line, pair } => ThreePlanes::Line {
                line: line.map(f),
                pair,
            },
            ThreePlanes::Plane => ThreePlanes::Plane,
            ThreePlanes::Empty => ThreePlanes::Empty,
        }
    }
}

/// Plain f64 (uncertified; `D == 0.0` decides degeneracy, like CGAL's Epick).
pub fn intersect_three_planes_f64(p: &[Plane<f64>; 3]) -> ThreePlanes<f64> {
    core::<f64>(&[
        PlaneData::new(&p[0]),
        PlaneData::new(&p[1]),
        PlaneData::new(&p[2]),
    ])
}

/// Exact, on rational inputs.
pub fn intersect_three_planes_exact(p: &[Plane<Rational>; 3]) -> ThreePlanes<Rational> {
    core::<Rational>(&[
        PlaneData::new(&p[0]),
        PlaneData::new(&p[1]),
        PlaneData::new(&p[2]),
    ])
}

/// Certified: exact verdict, correctly rounded coordinates and parameters.
pub fn intersect_three_planes(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>> {
    dispatch_fma!(certified(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>>)
}

/// The filter, then the exact tiers (instantiated once per product mode, so that the
/// answer is built in place).
#[inline(always)]
fn certified<M: ProductMode>(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>> {
    match fast::<M>(p) {
        Some(r) => filter_certified(r),
        None => exact_tiers(p),
    }
}
