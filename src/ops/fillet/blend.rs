//! The blend surfaces as surfaces of the model (OPERATIONS.md §11.4, §11.5), written
//! once over [`Real`] ([`BlendFormula::point`]); their derivatives for
//! [`Surface::jet`] come from the same formula by forward-mode dual numbers
//! ([`Dual`], nested for second order), so over intervals every value and derivative
//! encloses the exact one.
//!
//! * [`FilletSurface`] `f(t, z)` (11.7): the rational quadratic arc from `p₁(t)` to
//!   `p₂(t)` with middle point `p_m` (11.6) and weight `w = cos(φ/2)` (11.5), a
//!   circular arc of radius `ρ` about the ball centre `c(t)`; its end tangents
//!   `2w(p_m − p₁)`, `2w(p₂ − p_m)` lie in the faces' tangent planes (G1 with both).
//! * [`ChamferSurface`] `f(t, z) = (1 − z)·c₁(t) + z·c₂(t)` (11.8) between the lines
//!   of contact `cᵢ = q − dᵢτᵢ` on two planes.

use super::centre::CentreCurve;
use crate::certify::dual::Dual;
use crate::num::vector::{add, add_scaled, cross, dot, norm_sq, scale, sub};
use crate::num::Real;
use crate::ops::blend_law::Law;
use crate::surface::Surface;

/// A blend written as one formula `f(t, z)` over any [`Real`].
pub trait BlendFormula {
    /// The point `f(t, z)`.
    fn point<T: Real>(&self, t: &T, z: &T) -> [T; 3];
    /// The domain `([t₀, t₁], [0, 1])`.
    fn range(&self) -> [f64; 2];
}

/// `[f, f_t, f_z, f_tt, f_tz, f_zz]` truncated to `order` by dual numbers.
fn formula_jet<F: BlendFormula, T: Real>(f: &F, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
    if order == 0 {
        return vec![f.point(u, v)];
    }
    if order == 1 {
        let (du, dv) = (
            Dual::variable(u.clone(), 0, 2),
            Dual::variable(v.clone(), 1, 2),
        );
        let p = f.point(&du, &dv);
        return vec![
            p.clone().map(|c| c.value),
            p.clone().map(|c| c.partial(0)),
            p.map(|c| c.partial(1)),
        ];
    }
    let (zero, one) = (u.zero_like(), u.one_like());
    let seed = |x: &T, i: usize| {
        let mut grad = vec![Dual::constant(zero.clone()), Dual::constant(zero.clone())];
        grad[i] = Dual::constant(one.clone());
        Dual {
            value: Dual::variable(x.clone(), i, 2),
            grad,
        }
    };
    let p = f.point(&seed(u, 0), &seed(v, 1));
    vec![
        p.clone().map(|c| c.value.value),
        p.clone().map(|c| c.value.partial(0)),
        p.clone().map(|c| c.value.partial(1)),
        p.clone().map(|c| c.partial(0).partial(0)),
        p.clone().map(|c| c.partial(0).partial(1)),
        p.map(|c| c.partial(1).partial(1)),
    ]
}

/// The rolling-ball fillet surface of one centre curve (module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct FilletSurface {
    pub centre: CentreCurve,
}

impl BlendFormula for FilletSurface {
    fn point<T: Real>(&self, t: &T, z: &T) -> [T; 3] {
        let st = self.centre.station(t);
        let [d1, d2] = self.centre.offsets(t);
        let one = t.one_like();
        let opc = one.clone() + &st.cos_phi;
        // (11.6) p_m = c − (d₁m + d₂n)/(1 + cos φ)
        let pull = add(&scale(&d1, &st.normal[0]), &scale(&d2, &st.normal[1]));
        let pm = sub(&st.centre, &pull.map(|c| c / &opc));
        // (11.5) w = √((1 + cos φ)/2)
        let w = (opc / t.lift(2.0)).sqrt();
        let y = one - z;
        let (a, b, c) = (y.sqr(), t.lift(2.0) * z * &y * &w, z.sqr());
        let num = add(
            &add(&scale(&a, &st.contact[0]), &scale(&b, &pm)),
            &scale(&c, &st.contact[1]),
        );
        let den = a + b + c;
        num.map(|x| x / &den)
    }
    fn range(&self) -> [f64; 2] {
        self.centre.range
    }
}

impl Surface for FilletSurface {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        (self.range(), [0.0, 1.0])
    }
    fn is_closed(&self) -> [bool; 2] {
        [self.centre.closed, false]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        formula_jet(self, u, v, order)
    }
}

/// The chamfer between two planes (§11.5): `edge` is the line of the planes (a
/// [`CentreCurve`] with zero offsets, `t` its arc length `ℓ`), the signed legs are
/// `dᵢ(ℓ) = signs[i]·legs[i](ℓ)` (constant legs (11.10), or laws of `ℓ` (11.11)).
#[derive(Debug, Clone, PartialEq)]
pub struct ChamferSurface {
    pub edge: CentreCurve,
    /// The sign of each leg's offset (±1).
    pub signs: [f64; 2],
    pub legs: [Law; 2],
}

impl ChamferSurface {
    /// The signed legs `d₁(t)`, `d₂(t)`.
    pub fn offsets<T: Real>(&self, t: &T) -> [T; 2] {
        [0, 1].map(|k| t.lift(self.signs[k]) * &self.legs[k].at(t))
    }

    /// The lines of contact `cᵢ(t) = q(t) − dᵢ(t)τᵢ` with the transversals (11.9)
    /// `τ₁ = m × t̂_e`, `τ₂ = t̂_e × n`, `t̂_e = (m × n)/|m × n|`, so that
    /// `c₁ + d₁τ₁ = c₂ + d₂τ₂ = q` (11.10), (11.11); `cᵢ − q ⟂ t̂_e`, the station plane.
    pub fn contacts<T: Real>(&self, t: &T) -> [[T; 3]; 2] {
        let st = self.edge.station(t);
        let (m, n) = (&st.normal[0], &st.normal[1]);
        let e = cross(m, n);
        let len = norm_sq(&e).sqrt();
        let te = e.map(|c| c / &len);
        let tau = [cross(m, &te), cross(&te, n)];
        let d = self.offsets(t);
        [0, 1].map(|k| add_scaled(&st.centre, &-d[k].clone(), &tau[k]))
    }
}

impl BlendFormula for ChamferSurface {
    fn point<T: Real>(&self, t: &T, z: &T) -> [T; 3] {
        let [c1, c2] = self.contacts(t);
        let y = t.one_like() - z;
        add(&scale(&y, &c1), &scale(z, &c2))
    }
    fn range(&self) -> [f64; 2] {
        self.edge.range
    }
}

impl Surface for ChamferSurface {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        (self.range(), [0.0, 1.0])
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        formula_jet(self, u, v, order)
    }
}

/// `(p_m − p₁)·m` and `(p₂ − p_m)·n` of a fillet station: zero by (11.6) (the arc's end
/// tangents lie in the faces' tangent planes); over intervals an enclosure of them.
pub fn end_tangency<T: Real>(f: &FilletSurface, t: &T) -> [T; 2] {
    let jet = f.jet(t, &t.zero_like(), 1);
    let end = f.jet(t, &t.one_like(), 1);
    let st = f.centre.station(t);
    [dot(&jet[2], &st.normal[0]), dot(&end[2], &st.normal[1])]
}
