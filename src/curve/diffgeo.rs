//! Differential geometry of a curve from its jet: the Frenet frame, curvature, torsion
//! and Darboux vector of OPERATIONS.md §1.1 (1.2)–(1.3), and the 2D normal and signed
//! curvature of §1.2 (1.4). Each formula is written once, generic over [`Real`]; for
//! interval jets it is a composition of enclosing operations, so the result encloses
//! the exact quantity over the parameter interval (an unbounded or empty interval
//! where a denominator can vanish: special points `c' = 0`, inflections `c'×c'' = 0`).

use super::Curve;
use crate::num::vector::{cross, cross2, cross_norm_sq, dot, norm_sq, scale};
use crate::num::Real;

/// `k = |c'×c''| / |c'|³` (1.3); in 2D `|x'y'' − y'x''| / |c'|³`.
pub fn curvature<T: Real, const D: usize>(d1: &[T; D], d2: &[T; D]) -> T {
    let speed_sq = norm_sq(d1);
    let speed = speed_sq.sqrt();
    cross_norm_sq(d1, d2).sqrt() / (speed_sq * speed)
}

/// `t̂ = c'/|c'|` (1.2).
pub fn unit_tangent<T: Real, const D: usize>(d1: &[T; D]) -> [T; D] {
    let inv = d1[0].one_like() / norm_sq(d1).sqrt();
    scale(&inv, d1)
}

/// `b̂ = (c'×c'')/|c'×c''|` (1.2).
pub fn binormal<T: Real>(d1: &[T; 3], d2: &[T; 3]) -> [T; 3] {
    let b = cross(d1, d2);
    let inv = d1[0].one_like() / norm_sq(&b).sqrt();
    scale(&inv, &b)
}

/// `n̂ = b̂ × t̂` (1.2).
pub fn principal_normal<T: Real>(d1: &[T; 3], d2: &[T; 3]) -> [T; 3] {
    cross(&binormal(d1, d2), &unit_tangent(d1))
}

/// `ϰ = ((c'×c'')·c''') / |c'×c''|²` (1.3).
pub fn torsion<T: Real>(d1: &[T; 3], d2: &[T; 3], d3: &[T; 3]) -> T {
    let b = cross(d1, d2);
    dot(&b, d3) / norm_sq(&b)
}

/// The Darboux vector `ω = ϰ t̂ + k b̂` (1.3).
pub fn darboux<T: Real>(d1: &[T; 3], d2: &[T; 3], d3: &[T; 3]) -> [T; 3] {
    let t = unit_tangent(d1);
    let b = binormal(d1, d2);
    let k = curvature(d1, d2);
    let tau = torsion(d1, d2, d3);
    std::array::from_fn(|i| tau.clone() * &t[i] + k.clone() * &b[i])
}

/// The 2D unit normal `n = (−y', x')/√(x'² + y'²)` (1.4): `t̂` turned by +90°.
pub fn normal2<T: Real>(d1: &[T; 2]) -> [T; 2] {
    let inv = d1[0].one_like() / norm_sq(d1).sqrt();
    [-(d1[1].clone() * &inv), d1[0].clone() * &inv]
}

/// The signed curvature `(x'y'' − y'x'')/|c'|³` (1.4), positive when the curve
/// turns counter-clockwise.
pub fn signed_curvature2<T: Real>(d1: &[T; 2], d2: &[T; 2]) -> T {
    let speed_sq = norm_sq(d1);
    let speed = speed_sq.sqrt();
    cross2(d1, d2) / (speed_sq * speed)
}

/// Frame quantities of a space curve at a parameter (§1.1 (1.2)–(1.3)); implemented
/// for every [`Curve<3>`].
pub trait SpaceCurve: Curve<3> {
    /// `t̂` (1.2).
    fn unit_tangent_at<T: Real>(&self, t: &T) -> [T; 3] {
        unit_tangent(&self.jet(t, 1)[1])
    }
    /// `b̂` (1.2); undefined where `k = 0`.
    fn binormal_at<T: Real>(&self, t: &T) -> [T; 3] {
        let j = self.jet(t, 2);
        binormal(&j[1], &j[2])
    }
    /// `n̂ = b̂ × t̂` (1.2); undefined where `k = 0`.
    fn principal_normal_at<T: Real>(&self, t: &T) -> [T; 3] {
        let j = self.jet(t, 2);
        principal_normal(&j[1], &j[2])
    }
    /// `ϰ` (1.3); undefined where `k = 0`.
    fn torsion_at<T: Real>(&self, t: &T) -> T {
        let j = self.jet(t, 3);
        torsion(&j[1], &j[2], &j[3])
    }
    /// `ω = ϰ t̂ + k b̂` (1.3).
    fn darboux_at<T: Real>(&self, t: &T) -> [T; 3] {
        let j = self.jet(t, 3);
        darboux(&j[1], &j[2], &j[3])
    }
}

impl<C: Curve<3>> SpaceCurve for C {}

/// The normal and signed curvature of a plane curve (§1.2 (1.4)); implemented for
/// every [`Curve<2>`].
pub trait PlaneCurve: Curve<2> {
    /// `n = (−y', x')/|c'|` (1.4).
    fn unit_normal_at<T: Real>(&self, t: &T) -> [T; 2] {
        normal2(&self.jet(t, 1)[1])
    }
    /// `(x'y'' − y'x'')/|c'|³` (1.4).
    fn signed_curvature_at<T: Real>(&self, t: &T) -> T {
        let j = self.jet(t, 2);
        signed_curvature2(&j[1], &j[2])
    }
}

impl<C: Curve<2>> PlaneCurve for C {}

/// The derivatives of the unit tangent `t̂ = v/|v|` (1.2) from those of `v = c'`:
/// `v_jet[j] = v⁽ʲ⁾` (`j = 0..=k`) gives `t̂⁽ʲ⁾` for the same `j`. Written as Taylor
/// (Leibniz) arithmetic: `s = v·v`, `w = s^(−1/2)` with `2s w' + s' w = 0` differentiated
/// `m` times for `w⁽ᵐ⁺¹⁾`, and `t̂⁽ᵐ⁾ = Σ C(m,i) v⁽ⁱ⁾ w⁽ᵐ⁻ⁱ⁾`.
///
/// Every step is an enclosing [`Real`] operation, so for interval jets the result
/// encloses the exact derivatives wherever `v ≠ 0`; where the enclosure of `|v|²` holds
/// 0 (a cusp or stationary point) the divisions make the result unbounded (or, for
/// f64, NaN/∞) — never a wrong finite value.
pub fn unit_tangent_jet<T: Real, const D: usize>(v_jet: &[[T; D]]) -> Vec<[T; D]> {
    let k = v_jet.len();
    if k == 0 {
        return Vec::new();
    }
    let like = &v_jet[0][0];
    let binom = |m: usize, i: usize| -> T {
        let c = (0..i).fold(1.0, |c, j| c * (m - j) as f64 / (j + 1) as f64);
        like.lift(c)
    };
    let s: Vec<T> = (0..k)
        .map(|m| {
            (1..=m).fold(dot(&v_jet[0], &v_jet[m]), |acc, i| {
                acc + binom(m, i) * dot(&v_jet[i], &v_jet[m - i])
            })
        })
        .collect();
    let s0 = norm_sq(&v_jet[0]);
    let mut w = vec![like.one_like() / s0.sqrt()];
    let two_s0 = like.lift(2.0) * &s0;
    for m in 0..k - 1 {
        let mut acc = s[1].clone() * &w[m] * binom(m, 0);
        for i in 1..=m {
            acc = acc
                + like.lift(2.0) * binom(m, i) * &s[i] * &w[m + 1 - i]
                + binom(m, i) * &s[i + 1] * &w[m - i];
        }
        w.push(-acc / &two_s0);
    }
    (0..k)
        .map(|m| {
            std::array::from_fn(|d| {
                (0..=m).fold(like.zero_like(), |acc, i| {
                    acc + binom(m, i) * &v_jet[i][d] * &w[m - i]
                })
            })
        })
        .collect()
}
