//! Implicit hypersurfaces `F(x) = 0` of `D` variables (OPERATIONS.md §1.4): the trait
//! that plane curves (`D = 2`, [`super::Conic2`]) and surfaces (`D = 3`, the quadrics
//! and analytic surfaces of `crate::surface::implicit`, which re-exports it as
//! `crate::surface::Implicit`) share, so that one formula serves both (as
//! [`super::frame`] does for frames).

use crate::num::Real;

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
