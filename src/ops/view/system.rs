//! The contour function of OPERATIONS.md §13.5 and the systems its certificate solves,
//! written once over [`Real`].
//!
//! `I(u, v) = n(u, v)·w(u, v)`, `w = d` for a parallel view and `w = E − s(u, v)` for a
//! central one (13.10). The normal `n` is `∇G(s(u, v))` when the surface has an
//! implicit form `G` (§1.4): it does not vanish at the poles of a sphere's or an
//! ellipsoid's net, where `s_u × s_v` does (and would make the whole pole edge part of
//! `I = 0`); otherwise `n = s_u × s_v` (1.6). Both are normals of the surface, so the
//! zero set is the same contour.

use super::projection::View;
use crate::certify::dual::value_and_jacobian;
use crate::certify::graph::CurveSystem;
use crate::certify::System;
use crate::num::vector::{cross, dot, lift};
use crate::num::Real;
use crate::surface::{AnyImplicit, Implicit, Surface};

/// `I(u, v)` for a surface and a view.
pub struct ContourFn<'a, S> {
    pub surface: &'a S,
    pub implicit: Option<AnyImplicit>,
    pub view: &'a View,
}

impl<S: Surface> ContourFn<'_, S> {
    /// The point `s(u, v)` and the normal used (module doc).
    pub fn point_normal<T: Real>(&self, u: &T, v: &T) -> ([T; 3], [T; 3]) {
        match &self.implicit {
            Some(g) => {
                let p = self.surface.jet(u, v, 0).swap_remove(0);
                let grad = g.implicit_jet(&p, 1).gradient;
                let n = grad.unwrap_or_else(|| lift(u, &[0.0; 3]));
                (p, n)
            }
            None => {
                let j = self.surface.jet(u, v, 1);
                (j[0].clone(), cross(&j[1], &j[2]))
            }
        }
    }

    /// (13.10): `I = n·d`, or `n·(E − s)` for a central view.
    pub fn value<T: Real>(&self, u: &T, v: &T) -> T {
        let (p, n) = self.point_normal(u, v);
        dot(&n, &self.view.toward_viewer(&p))
    }

    /// `I` and its gradient `(I_u, I_v)` (dual numbers).
    pub fn with_gradient<T: Real>(&self, u: &T, v: &T) -> (T, [T; 2]) {
        let (val, jac) =
            value_and_jacobian(&[u.clone(), v.clone()], |x| vec![self.value(&x[0], &x[1])]);
        let row = &jac[0];
        (val[0].clone(), [row[0].clone(), row[1].clone()])
    }
}

/// `I(u, v) = 0` as a curve system (one equation in `[u, v]`).
impl<S: Surface> CurveSystem for ContourFn<'_, S> {
    fn equations(&self) -> usize {
        1
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        vec![self.value(&x[0], &x[1])]
    }
}

/// The height-critical system of the completeness proof: `I = 0` and
/// `∂I/∂x_{1−k} = 0`, whose roots are the points of the contour where the height `x_k`
/// is stationary along it (the tangent `(I_v, −I_u)` has a zero `k`-component) and its
/// singular points (`∇I = 0`).
pub struct CriticalSystem<'c, 'a, S> {
    pub f: &'c ContourFn<'a, S>,
    /// The height coordinate `k` (0 = u, 1 = v).
    pub height: usize,
}

impl<S: Surface> System for CriticalSystem<'_, '_, S> {
    fn dim(&self) -> usize {
        2
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let (i, g) = self.f.with_gradient(&x[0], &x[1]);
        vec![i, g[1 - self.height].clone()]
    }
}

/// `I` on the line `x_k = at` of the parameter plane, a function of the other
/// coordinate (the edge systems of the completeness proof).
pub struct EdgeSystem<'c, 'a, S> {
    pub f: &'c ContourFn<'a, S>,
    pub fixed: usize,
    pub at: f64,
}

impl<S: Surface> System for EdgeSystem<'_, '_, S> {
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let c = x[0].lift(self.at);
        let (u, v) = if self.fixed == 0 {
            (c, x[0].clone())
        } else {
            (x[0].clone(), c)
        };
        vec![self.f.value(&u, &v)]
    }
}
