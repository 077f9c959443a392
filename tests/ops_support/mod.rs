//! Test-local shapes for the operation tests, implemented on the Curve/Surface traits
//! only, and the uniform samples standing in for the walks.
#![allow(dead_code)]

use geocert::curve::Curve;
use geocert::num::Real;
use geocert::surface::Surface;
use std::f64::consts::TAU;

/// `(a cos t, b sin t)`, t ∈ [0, 2π], closed (test-local, so this test depends only on
/// the Curve trait).
pub struct Ellipse2 {
    pub a: f64,
    pub b: f64,
}

impl Curve<2> for Ellipse2 {
    fn domain(&self) -> (f64, f64) {
        (0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn domain_rounded(&self) -> bool {
        true // [0, 2π]
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 2]> {
        let (c, s) = (t.cos(), t.sin());
        let (a, b) = (t.lift(self.a), t.lift(self.b));
        let rot = [
            [c.clone(), s.clone()],
            [-s.clone(), c.clone()],
            [-c.clone(), -s.clone()],
            [s, -c],
        ];
        rot[..=order]
            .iter()
            .map(|[x, y]| [a.clone() * x, b.clone() * y])
            .collect()
    }
}

/// Torus `((R + r cos v) cos u, (R + r cos v) sin u, r sin v)` on `[0, 2π]²`; with
/// `r_major = 0` and `v ∈ [−π/2, π/2]` it is the sphere of §1.6.
pub struct Torus {
    pub major: f64,
    pub minor: f64,
    pub v_range: [f64; 2],
}

impl Surface for Torus {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        ([0.0, TAU], self.v_range)
    }
    fn is_closed(&self) -> [bool; 2] {
        [true, self.v_range == [0.0, TAU]]
    }
    fn domain_rounded(&self) -> [bool; 2] {
        [true, true] // 2π, ±π/2
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (cu, su, cv, sv) = (u.cos(), u.sin(), v.cos(), v.sin());
        let (big, r) = (u.lift(self.major), u.lift(self.minor));
        let w = big + r.clone() * &cv; // R + r cos v
        let z = u.zero_like();
        let all = vec![
            [w.clone() * &cu, w.clone() * &su, r.clone() * &sv],
            [-(w.clone() * &su), w.clone() * &cu, z.clone()],
            [
                -(r.clone() * &sv * &cu),
                -(r.clone() * &sv * &su),
                r.clone() * &cv,
            ],
            [-(w.clone() * &cu), -(w * &su), z.clone()],
            [r.clone() * &sv * &su, -(r.clone() * &sv * &cu), z],
            [
                -(r.clone() * &cv * &cu),
                -(r.clone() * &cv * &su),
                -(r * &sv),
            ],
        ];
        all.into_iter().take([1, 3, 6][order.min(2)]).collect()
    }
}

/// The unit square `(u, v, 0)`, `[0, 1]²`, open in both directions.
pub struct Square;

impl Surface for Square {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        ([0.0, 1.0], [0.0, 1.0])
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (z, o) = (u.zero_like(), u.one_like());
        let all = vec![
            [u.clone(), v.clone(), z.clone()],
            [o.clone(), z.clone(), z.clone()],
            [z.clone(), o, z.clone()],
            [z.clone(), z.clone(), z.clone()],
            [z.clone(), z.clone(), z.clone()],
            [z.clone(), z.clone(), z],
        ];
        all.into_iter().take([1, 3, 6][order.min(2)]).collect()
    }
}

/// The line `origin + t·dir`, `t ∈ range`.
pub struct Line3 {
    pub origin: [f64; 3],
    pub dir: [f64; 3],
    pub range: [f64; 2],
}

impl Curve<3> for Line3 {
    fn domain(&self) -> (f64, f64) {
        (self.range[0], self.range[1])
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let p = std::array::from_fn(|i| t.lift(self.origin[i]) + t.lift(self.dir[i]) * t);
        let d = std::array::from_fn(|i| t.lift(self.dir[i]));
        let z = std::array::from_fn(|_| t.zero_like());
        let mut out = vec![p, d, z.clone(), z];
        out.truncate(order + 1);
        out
    }
}

/// `n` uniform samples `(t, Δt)` over a curve's domain, the last one at its end.
pub fn samples<const D: usize>(c: &impl Curve<D>, n: usize) -> Vec<(f64, f64)> {
    let (lo, hi) = c.domain();
    let dt = (hi - lo) / n as f64;
    (0..=n).map(|i| (lo + i as f64 * dt, dt)).collect()
}

/// `(n + 1)²` uniform nodes `(u, v, Δu, Δv)` over a surface's domain.
pub fn nodes(s: &impl Surface, n: usize) -> Vec<[f64; 4]> {
    let ([u0, u1], [v0, v1]) = s.domain();
    let (du, dv) = ((u1 - u0) / n as f64, (v1 - v0) / n as f64);
    let mut out = Vec::new();
    for i in 0..=n {
        for j in 0..=n {
            out.push([u0 + i as f64 * du, v0 + j as f64 * dv, du, dv]);
        }
    }
    out
}
