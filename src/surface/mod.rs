//! Parametric and implicit surfaces (OPERATIONS.md §1.3–§1.4, §1.6; docs/FORMAT.md
//! surface types).
//!
//! Like curves, a surface supplies only its value and derivatives, generic over the
//! number type ([`Real`]), so that one formula serves the float kernel and the
//! certifier. Evaluated on interval parameters, [`Surface::jet`] encloses every value
//! and derivative over the parameter box.

pub mod any;
pub mod basis;
pub mod bezier;
pub mod bilinear;
pub mod composite;
pub mod degenerate;
pub mod differential;
pub mod frame;
pub mod implicit;
pub mod motion;
pub mod nurbs;
mod patch_hull;
pub mod pencil;
pub mod plane;
pub mod quadrics;
pub mod repole;
mod rotational;
pub mod sets;
mod taylor;
mod taylor_fast;
mod tensor;
pub mod torus;
pub mod validate;
pub mod whole_box;

pub use crate::curve::implicit::{Implicit, ImplicitJet};
pub use any::{AnyImplicit, AnySurface};
pub use differential::FundamentalForms;

use crate::num::Real;

/// How the walk of OPERATIONS.md §2.2 chooses the step in one parameter direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepRule {
    /// (2.2): the normal curvature of the coordinate line, `Δ = Δα·√g_ii/|b_ii|`.
    Curvature,
    /// (2.1) applied to the coordinate line as a space curve (the generatrix of
    /// extrusions, revolutions and ruled surfaces).
    CoordinateCurve,
    /// An angular parameter: `Δ = Δα` (sphere, ellipsoid, torus; `u` of cylinders,
    /// cones and revolutions).
    Angle,
    /// The coordinate lines are straight: one step covers the range (planes; `v` of
    /// cylinders, cones, extrusions and ruled surfaces, as §2.2 prescribes).
    WholeRange,
}

/// [`Surface::implicit_value`] of a surface by its [`Implicit`] form (used inside the
/// `impl Surface` blocks of the surfaces that have one).
macro_rules! implicit_value_by_form {
    () => {
        /// The implicit form (§1.6), which vanishes on the whole surface.
        fn implicit_value<T: Real>(&self, x: &[T; 3]) -> Option<T> {
            Some(<Self as crate::surface::Implicit<3>>::implicit_jet(self, x, 0).value)
        }
    };
}
pub(crate) use implicit_value_by_form;

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
    ///
    /// Default: per direction, either bound is the double nearest to a multiple of
    /// `π/2` ([`crate::curve::is_angle_bound`]).
    fn domain_rounded(&self) -> [bool; 2] {
        let (u, v) = self.domain();
        let rounded = |[lo, hi]: [f64; 2]| {
            crate::curve::is_angle_bound(lo) || crate::curve::is_angle_bound(hi)
        };
        [rounded(u), rounded(v)]
    }

    /// The `v = v_min` / `v = v_max` edges that collapse to one point, a pole
    /// (OPERATIONS.md §14.1: `u` is undefined there and `s_u ≡ 0` along the edge):
    /// a sphere's and an ellipsoid's `v = ±π/2`. Default: none.
    fn v_poles(&self) -> [bool; 2] {
        [false, false]
    }

    /// Value and partial derivatives up to `order` (0, 1 or 2) at `(u, v)`, in the
    /// order `[s, s_u, s_v, s_uu, s_uv, s_vv]` truncated to 1, 3 or 6 entries (§1.3).
    ///
    /// For interval `u`, `v`, every entry encloses the true value over the box.
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]>;

    /// The §2.2 step rule per direction `[u, v]` (its analytic shortcuts).
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Curvature, StepRule::Curvature]
    }

    /// The non-empty knot span `[a, b]` containing the parameter `t` in `direction`
    /// (0 = u, 1 = v), for the B-spline clamp of §2.1 (`Δ ≤ ½·span`); `None` for
    /// surfaces without knots.
    fn knot_span(&self, direction: usize, t: f64) -> Option<(f64, f64)> {
        let _ = (direction, t);
        None
    }

    /// Per direction, the parameters strictly inside the domain where the formula
    /// changes (distinct interior knots of a NURBS), ascending; the certifier solves
    /// each closed knot rectangle on its own with [`Surface::pinned_at`] (issue 21, as
    /// [`crate::curve::Curve::piece_breaks`]). Default: none.
    fn piece_breaks(&self) -> [Vec<f64>; 2] {
        [Vec::new(), Vec::new()]
    }

    /// The surface whose [`Surface::jet`] evaluates everywhere the formula of the knot
    /// rectangle containing `(u, v)` (a point strictly inside one), continued
    /// analytically; it agrees with `self` on that closed rectangle. `None` when the
    /// surface has no pieces.
    fn pinned_at(&self, _u: f64, _v: f64) -> Option<Self>
    where
        Self: Sized,
    {
        None
    }

    /// A function of space that vanishes at `s(u, v)` for every real `(u, v)` (the
    /// implicit form of §1.6, [`Implicit`]), at `x`: for interval `x` an enclosure of
    /// its values over the box; `None` for surfaces without one (patches, motion
    /// surfaces). Used as a necessary condition ([`crate::certify::System::implied`]).
    fn implicit_value<T: Real>(&self, x: &[T; 3]) -> Option<T> {
        let _ = x;
        None
    }

    /// The unit normal `n̂ = (s_u × s_v)/|s_u × s_v|` (1.6), with the §1.3 limit at
    /// points where a partial derivative vanishes identically
    /// ([`differential::unit_normal`]).
    fn normal<T: Real>(&self, u: &T, v: &T) -> [T; 3] {
        differential::unit_normal(&self.jet(u, v, 2))
    }

    /// The fundamental forms (1.7)–(1.8) at `(u, v)`.
    fn fundamental_forms<T: Real>(&self, u: &T, v: &T) -> FundamentalForms<T> {
        FundamentalForms::from_jet(&self.jet(u, v, 2))
    }

    /// The Gaussian curvature `K` (1.9).
    fn gaussian_curvature<T: Real>(&self, u: &T, v: &T) -> T {
        self.fundamental_forms(u, v).gaussian_curvature()
    }

    /// The mean curvature `H` (1.9), signed with respect to the normal (1.6).
    fn mean_curvature<T: Real>(&self, u: &T, v: &T) -> T {
        self.fundamental_forms(u, v).mean_curvature()
    }

    /// The principal curvatures `(k₁, k₂) = H ± √(H² − K)` (1.9).
    fn principal_curvatures<T: Real>(&self, u: &T, v: &T) -> (T, T) {
        self.fundamental_forms(u, v).principal_curvatures()
    }
}
