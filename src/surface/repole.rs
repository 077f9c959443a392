//! A sphere-mapped surface with new poles (OPERATIONS.md §14.1–§14.2, issue 17):
//! `R̃(α, λ) = R(u(α, λ), v(α, λ))`, where `(u, v)` are the parameters (14.7) of the
//! unit-sphere point `X(α, λ)` of a [`PencilNet`].
//!
//! # Conventions
//!
//! The spec's sphere map (14.1) `S(ϑ, φ) = (sin ϑ cos φ, sin ϑ sin φ, cos ϑ)` with the
//! polar `ϑ = π u/u_p` is, in the library's parameters (docs/FORMAT.md: sphere
//! `center + r cos v (cos u X + sin u Y) + r sin v Z`), `φ = u ∈ [0, 2π]`,
//! `ϑ = π/2 − v`, `v ∈ [−π/2, π/2]`: the spec's `u`/`v` are the library's `v`/`u`
//! (swapped, and `v` counted from the equator). The new surface keeps the library's
//! convention: its `u` is the angle `α` along the circles, `[0, 2π]`, closed; its `v` is
//! the latitude `λ` of the circle (module doc of [`super::pencil`]), `v = π/2` the
//! first new pole `P₁` (the spec's `β = 0`), `v = −π/2` the second.
//!
//! # Composition without the way back
//!
//! A [`SphereMapped`] surface is an affine image of the sphere map,
//! `R(u, v) = c + A S(u, v)` (sphere: `A` = frame × `r`; ellipsoid: frame ×
//! `diag(a, b, c)`). Since `S(u(X), v(X)) = X` for `|X| = 1`,
//! `R̃ = c + A X(α, λ)` exactly, and its jet is `A` applied to the jet of `X` (the chain
//! rule through a linear map). This is smooth through the old poles and the old seam,
//! where `(u, v)(α, λ)` itself is not (`u` undefined at the old poles, a jump of `2π`
//! at the seam): §14.2's "evaluate `R` there by its pole value" holds by construction.
//! The way back (14.7) is [`Repole::original_params`], for reporting points.
//!
//! # Enclosures
//!
//! The jet of `X` encloses the exact one ([`super::pencil`]), and the surface's frame
//! does ([`super::frame::Frame::place_jet`]), so [`Surface::jet`] on interval parameters
//! encloses the exact jet of the exact re-parametrised surface over the box.

use super::frame::Frame;
use super::pencil::{PencilNet, Pole};
use super::quadrics::{Ellipsoid, Sphere};
use super::validate::FULL_TURN;
use super::Surface;
use crate::error::GeomError;
use crate::num::Real;

const HALF_PI: f64 = std::f64::consts::FRAC_PI_2;

/// A surface `R(u, v) = frame(diag(k) (cos v cos u, cos v sin u, sin v))` on the full
/// domain `[0, 2π] × [−π/2, π/2]`: one-to-one onto the unit sphere (14.1) except for
/// the seam and the poles.
pub trait SphereMapped: Surface + Clone {
    /// The frame placing the local point.
    fn sphere_frame(&self) -> &Frame;
    /// The scales `k` of the local axes.
    fn sphere_scales(&self) -> [f64; 3];
}

impl SphereMapped for Sphere {
    fn sphere_frame(&self) -> &Frame {
        &self.frame
    }
    fn sphere_scales(&self) -> [f64; 3] {
        [self.radius; 3]
    }
}

impl SphereMapped for Ellipsoid {
    fn sphere_frame(&self) -> &Frame {
        &self.frame
    }
    fn sphere_scales(&self) -> [f64; 3] {
        self.abc
    }
}

/// `R̃(α, λ)`: the sphere-mapped surface `R` with the net of new poles (module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct Repole<S> {
    surface: S,
    net: PencilNet,
}

impl<S: SphereMapped> Repole<S> {
    /// `surface` with new poles `pole1` (at `v = π/2`) and `pole2` (at `v = −π/2`),
    /// given in the surface's local frame ([`Pole::Params`] are the surface's own
    /// `(u, v)`). Errors: those of [`PencilNet::new`], and `invalid_value` on `domain`
    /// when the surface is restricted (the map (14.1) must cover the sphere).
    pub fn new(surface: S, pole1: Pole, pole2: Pole) -> Result<Repole<S>, GeomError> {
        if surface.domain() != (FULL_TURN, [-HALF_PI, HALF_PI]) {
            return Err(GeomError::InvalidValue {
                field: "domain".into(),
                reason: "new poles need the whole surface: domain [0, 2π] × [−π/2, π/2]".into(),
            });
        }
        let net = PencilNet::new(pole1, pole2)?;
        Ok(Repole { surface, net })
    }

    pub fn surface(&self) -> &S {
        &self.surface
    }

    pub fn net(&self) -> &PencilNet {
        &self.net
    }

    /// The parameters `(u, v)` of the original surface at `R̃(α, λ)`: (14.7) in the
    /// library's convention, `u = atan2(Y, X)` and `v = atan2(Z, √(X² + Y²))`
    /// (`= π/2 − arccos(Z/|X|)`, better conditioned near the poles) of the unit-sphere
    /// point. `u` is shifted into `[0, 2π)` when its value is surely negative (an
    /// enclosure straddling the seam stays in `(−π, π]`). At an old pole `u` is
    /// undefined: `f64` gives `0`, an enclosure whose `X`, `Y` contain 0 gives the
    /// whole turn `[−π, π]`.
    pub fn original_params<T: Real>(&self, alpha: &T, lambda: &T) -> (T, T) {
        let x = self.net.jet(alpha, lambda, 0).swap_remove(0);
        unit_params(&x)
    }
}

/// (14.7) for a unit-sphere point (doc of [`Repole::original_params`]).
pub fn unit_params<T: Real>(x: &[T; 3]) -> (T, T) {
    let u = x[1].atan2(&x[0]);
    let u = if u.bounds().1 < 0.0 {
        let turn = u.pi_like() * u.lift(2.0);
        u + turn
    } else {
        u
    };
    let rho = (x[0].sqr() + x[1].sqr()).sqrt();
    (u, x[2].atan2(&rho))
}

impl<S: SphereMapped> Surface for Repole<S> {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        (FULL_TURN, [-HALF_PI, HALF_PI])
    }
    fn is_closed(&self) -> [bool; 2] {
        [true, false]
    }
    fn v_poles(&self) -> [bool; 2] {
        [true, true]
    }
    /// The surface's own: `R̃(α, λ) = R(u, v)` is a point of it (module doc).
    fn implicit_value<T: Real>(&self, x: &[T; 3]) -> Option<T> {
        self.surface.implicit_value(x)
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let k = self.surface.sphere_scales();
        let local: Vec<[T; 3]> = self
            .net
            .jet(u, v, order.min(2))
            .into_iter()
            .map(|x| std::array::from_fn(|i| x[i].clone() * u.lift(k[i])))
            .collect();
        self.surface.sphere_frame().place_jet(&local)
    }
}
