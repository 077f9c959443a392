//! Differential geometry of a parametric surface from its second-order jet
//! (OPERATIONS.md §1.3): the normal (1.6), the fundamental forms (1.7)–(1.8), the
//! curvatures (1.9) and the Weingarten derivatives of the unit normal (1.10).
//!
//! Every formula is written once over [`Real`]. For interval jets every result encloses
//! the exact quantity over the box wherever it is defined (a quotient by an interval that
//! contains 0 is unbounded, never wrong).

use crate::num::vector::{add_scaled, cross, dot, neg, norm_sq, normalize, scale};
use crate::num::Real;

/// `true` if every component is exactly zero (f64 `0.0`, or the point interval `[0, 0]`).
fn identically_zero<T: Real>(a: &[T; 3]) -> bool {
    a.iter().all(|x| x.bounds() == (0.0, 0.0))
}

/// The unit normal `n̂ = N/|N|`, `N = s_u × s_v` (1.6), from a jet of order ≥ 1.
///
/// Where `N` is identically zero because one partial derivative vanishes identically
/// (sphere-like poles, a cone apex, a collapsed edge) and the jet has order 2, the §1.3
/// limit is used: `normalise(s_uv × s_v)` if `s_u ≡ 0`, `normalise(s_u × s_uv)` if
/// `s_v ≡ 0` (the limit approached from the side of increasing `v`, resp. `u`) (impl).
pub fn unit_normal<T: Real>(jet: &[[T; 3]]) -> [T; 3] {
    let n = cross(&jet[1], &jet[2]);
    if identically_zero(&n) && jet.len() >= 6 {
        if identically_zero(&jet[1]) {
            return normalize(&cross(&jet[4], &jet[2]));
        }
        if identically_zero(&jet[2]) {
            return normalize(&cross(&jet[1], &jet[4]));
        }
    }
    normalize(&n)
}

/// The first and second fundamental forms at one point (1.7)–(1.8), with the tangent
/// vectors and unit normal they were computed from.
#[derive(Debug, Clone, PartialEq)]
pub struct FundamentalForms<T> {
    pub s_u: [T; 3],
    pub s_v: [T; 3],
    /// The unit normal `n̂` (1.6).
    pub normal: [T; 3],
    pub g11: T,
    pub g12: T,
    pub g22: T,
    /// `g = g11 g22 − g12²`.
    pub g: T,
    pub b11: T,
    pub b12: T,
    pub b22: T,
}

impl<T: Real> FundamentalForms<T> {
    /// The forms from a jet of order 2 (`[s, s_u, s_v, s_uu, s_uv, s_vv]`).
    ///
    /// # Panics
    /// If the jet has fewer than 6 entries (a programming error, not bad input).
    pub fn from_jet(jet: &[[T; 3]]) -> Self {
        assert!(jet.len() >= 6, "fundamental forms need a jet of order 2");
        let (s_u, s_v) = (jet[1].clone(), jet[2].clone());
        let normal = unit_normal(jet);
        let g11 = norm_sq(&s_u);
        let g12 = dot(&s_u, &s_v);
        let g22 = norm_sq(&s_v);
        let g = g11.clone() * &g22 - g12.sqr();
        FundamentalForms {
            b11: dot(&normal, &jet[3]),
            b12: dot(&normal, &jet[4]),
            b22: dot(&normal, &jet[5]),
            s_u,
            s_v,
            normal,
            g11,
            g12,
            g22,
            g,
        }
    }

    /// The inverse metric `(g^11, g^12, g^22)` (1.7).
    pub fn inverse_metric(&self) -> (T, T, T) {
        (
            self.g22.clone() / &self.g,
            -(self.g12.clone() / &self.g),
            self.g11.clone() / &self.g,
        )
    }

    /// The normal curvature in the direction `du : dv` (1.9).
    pub fn normal_curvature(&self, du: &T, dv: &T) -> T {
        let two = du.lift(2.0);
        let b = self.b11.clone() * du.sqr()
            + two.clone() * &self.b12 * du * dv
            + self.b22.clone() * dv.sqr();
        let g =
            self.g11.clone() * du.sqr() + two * &self.g12 * du * dv + self.g22.clone() * dv.sqr();
        b / g
    }

    /// The Gaussian curvature `K = (b11 b22 − b12²)/g` (1.9).
    pub fn gaussian_curvature(&self) -> T {
        (self.b11.clone() * &self.b22 - self.b12.sqr()) / &self.g
    }

    /// The mean curvature `H = (g11 b22 − 2 g12 b12 + g22 b11)/(2g)` (1.9). Its sign
    /// follows the normal `n̂` of (1.6).
    pub fn mean_curvature(&self) -> T {
        let two = self.g.lift(2.0);
        (self.g11.clone() * &self.b22 - two.clone() * &self.g12 * &self.b12
            + self.g22.clone() * &self.b11)
            / (two * &self.g)
    }

    /// The principal curvatures `k₁,₂ = H ± √(H² − K)` (1.9), `k₁ ≥ k₂`.
    ///
    /// `H² − K ≥ 0` holds exactly; an f64 evaluation that rounds it below zero (at an
    /// umbilic such as any point of a sphere) is taken as 0. Intervals need no such care:
    /// `√` drops the negative part of an enclosure, which the true value is not in.
    pub fn principal_curvatures(&self) -> (T, T) {
        let h = self.mean_curvature();
        let mut d = h.sqr() - self.gaussian_curvature();
        let (lo, hi) = d.bounds();
        if lo <= hi && hi < 0.0 {
            d = d.zero_like();
        }
        let r = d.sqrt();
        (h.clone() + &r, h - r)
    }

    /// The derivatives of the unit normal (Weingarten, 1.10): `(n̂_u, n̂_v)`.
    pub fn normal_derivatives(&self) -> ([T; 3], [T; 3]) {
        let (g11i, g12i, g22i) = self.inverse_metric();
        let combine = |b1: &T, b2: &T| {
            let cu = b1.clone() * &g11i + b2.clone() * &g12i;
            let cv = b1.clone() * &g12i + b2.clone() * &g22i;
            neg(&add_scaled(&scale(&cu, &self.s_u), &cv, &self.s_v))
        };
        (combine(&self.b11, &self.b12), combine(&self.b12, &self.b22))
    }
}
