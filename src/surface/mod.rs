//! Parametric and implicit surfaces (OPERATIONS.md §1.3–§1.4, §1.6; spec/CASES.md
//! surface types).
//!
//! Like curves, a surface supplies only its value and derivatives, generic over the
//! number type ([`Real`]), so that one formula serves the float kernel and the
//! certifier. Evaluated on interval parameters, [`Surface::jet`] encloses every value
//! and derivative over the parameter box.

use crate::num::Real;

/// A parametric surface `s(u, v)` on a rectangle `[u_min, u_max] × [v_min, v_max]`.
pub trait Surface {
    /// `([u_min, u_max], [v_min, v_max])`, each non-empty.
    fn domain(&self) -> ([f64; 2], [f64; 2]);

    /// Closed in `u` / in `v` (`s(u_min, v) = s(u_max, v)`, resp. in `v`).
    fn is_closed(&self) -> [bool; 2] {
        [false, false]
    }

    /// Per direction: the domain's bounds are the nearest doubles to irrational values
    /// (`2π`, `±π/2`, the `v`-range of a torus with `r > R`), not the exact ends; the
    /// certifier then covers them outward by one ulp (a sphere's pole is at the exact
    /// `π/2`, beyond the double `1.5707963267948966`).
    fn domain_rounded(&self) -> [bool; 2] {
        [false, false]
    }

    /// Value and partial derivatives up to `order` (0, 1 or 2) at `(u, v)`, in the
    /// order `[s, s_u, s_v, s_uu, s_uv, s_vv]` truncated to 1, 3 or 6 entries (§1.3).
    ///
    /// For interval `u`, `v`, every entry encloses the true value over the box.
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]>;
}

/// An implicit hypersurface `F(x) = 0` in `D` dimensions: an implicit surface for
/// `D = 3` (§1.4), an implicit plane curve (`conic2`) for `D = 2`.
///
/// Side convention of §1.4: `F > 0` outside, `F < 0` inside.
pub trait Implicit<const D: usize> {
    /// `F(x)`; with `order ≥ 1` also the gradient, with `order ≥ 2` the Hessian.
    fn implicit_jet<T: Real>(&self, x: &[T; D], order: usize) -> ImplicitJet<T, D>;
}

/// The value of an implicit function and, when requested, its gradient and Hessian.
#[derive(Debug, Clone, PartialEq)]
pub struct ImplicitJet<T, const D: usize> {
    /// `F(x)`.
    pub value: T,
    /// `∇F(x)` (present when `order ≥ 1`).
    pub gradient: Option<[T; D]>,
    /// The Hessian `∂²F/∂xᵢ∂xⱼ` (present when `order ≥ 2`).
    pub hessian: Option<[[T; D]; D]>,
}
