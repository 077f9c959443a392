//! Parametric curves (OPERATIONS.md §1.1–§1.2, §1.5; docs/FORMAT.md curve types).
//!
//! A curve supplies only its value and derivatives, generic over the number type
//! ([`Real`]: `f64`, [`crate::num::Interval`], [`crate::num::MpfrInterval`]), so that
//! one formula serves the float kernel and the certifier (ARCHITECTURE.md "Layers").
//! Evaluated on an interval parameter, [`Curve::jet`] encloses every value and
//! derivative over that interval.
//!
//! * [`frame`] — the local frame of analytic curves (docs/FORMAT.md frame rule);
//! * [`lines`] — line and segment (any dimension);
//! * [`analytic`] — circle, ellipse, hyperbola, parabola, helix, and the 2D circle and
//!   ellipse; circular and elliptic arcs;
//! * [`polyline`], [`bezier`] (rational Bézier, conic arc), [`nurbs`] (B-spline and
//!   NURBS curves over the basis of [`bspline`]);
//! * [`conic2`] — the implicit conic of the plane;
//! * [`derived`] — trimmed, reversed and reparametrised curves; [`offset`], [`composite`]
//!   and [`extended`] — the other derived curves of §1.2 and §1.5;
//! * [`any`] — [`AnyCurve3`] / [`AnyCurve2`], one enum over every curve;
//! * [`diffgeo`] — the frame quantities of (1.2)–(1.4) from a jet.

pub mod analytic;
pub mod any;
pub mod bezier;
pub mod bspline;
pub mod composite;
pub mod conic2;
pub mod derived;
pub mod diffgeo;
pub mod domain;
pub mod extended;
pub mod frame;
pub mod implicit;
pub mod lines;
pub mod nurbs;
pub mod offset;
pub mod polyline;
mod rational;
pub(crate) mod span_hull;
pub mod weight;

pub use analytic::{circular_arc, elliptic_arc, Analytic, Analytic2, Shape};
pub use any::{AnyCurve2, AnyCurve3};
pub use bezier::{conic_arc, Bezier};
pub use composite::Composite;
pub use conic2::{Conic2, ConicKind};
pub use derived::Reparametrised;
pub use diffgeo::{PlaneCurve, SpaceCurve};
pub use domain::Domain;
pub use extended::Extended;
pub use frame::Frame;
pub use lines::{Line, Segment};
pub use nurbs::NurbsCurve;
pub use offset::{Offset2, Offset3};
pub use polyline::Polyline;

use crate::num::Real;

/// A parametric curve `c(t)`, `t ∈ [t_min, t_max]`, in `D` dimensions (2 or 3).
///
/// Not object-safe (the evaluation is generic); heterogeneous collections use an
/// enum over the primitives ([`AnyCurve3`], [`AnyCurve2`]).
pub trait Curve<const D: usize> {
    /// The parameter domain `[t_min, t_max]` (§1.1), `t_min < t_max`. Only a line
    /// without a range has an unbounded domain.
    fn domain(&self) -> (f64, f64);

    /// `c(t_min) = c(t_max)` (§1.1 `closed` flag).
    fn is_closed(&self) -> bool {
        false
    }

    /// The curve is periodic with period `t_max − t_min` (derivatives also match
    /// at the ends), so a parameter may wrap around: [`Curve::jet`] of a periodic
    /// curve accepts any parameter and evaluates it modulo the period.
    fn is_periodic(&self) -> bool {
        false
    }

    /// The domain's bounds are the nearest doubles to irrational values (`2π`, an arc's
    /// angle), not the exact ends: the certifier then covers them outward by one ulp,
    /// so that no solution between the double and the exact end is missed.
    ///
    /// Default: either bound is the double nearest to a multiple `kπ/2`
    /// (`0 < |k| ≤ 4`), the ends of angular parameters.
    fn domain_rounded(&self) -> bool {
        let (lo, hi) = self.domain();
        is_angle_bound(lo) || is_angle_bound(hi)
    }

    /// The value and derivatives up to `order` (at most 3) at `t`:
    /// `jet[k] = dᵏc/dtᵏ`, so `jet.len() == order + 1`.
    ///
    /// For an interval `t`, every entry encloses the true value for every parameter
    /// in `t` (restricted to the domain where the formula is only defined there).
    /// Where a piecewise curve (polyline, B-spline) is only C⁰ or C¹ at a knot, an
    /// interval straddling the knot encloses the one-sided derivatives of both pieces.
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]>;

    /// The point `c(t)`.
    fn point<T: Real>(&self, t: &T) -> [T; D] {
        self.jet(t, 0).swap_remove(0)
    }

    /// The curvature `k = |c'×c''| / |c'|³` of (1.3) (in 2D the absolute value of
    /// (1.4)); NaN or an unbounded interval at a special point (`c' = 0`).
    fn curvature<T: Real>(&self, t: &T) -> T {
        let jet = self.jet(t, 2);
        diffgeo::curvature(&jet[1], &jet[2])
    }

    /// The parameters where `c'` may jump (a polyline's inner vertices, the knots of
    /// multiplicity ≥ p of a B-spline; for a periodic curve also its seam), ascending,
    /// each as an interval of doubles `(lo, hi)` containing it (`lo = hi` when the
    /// parameter is a double). The tangent turns there by an angle that no derivative
    /// bound sees, so proven steps (OPERATIONS.md §2) stop at them. Default: none.
    fn tangent_breaks(&self) -> Vec<(f64, f64)> {
        Vec::new()
    }

    /// The parameters strictly inside the domain where the curve's formula changes (the
    /// distinct interior knots of a NURBS), ascending: on each closed piece between
    /// them the curve is one rational (polynomial) map, the one [`Curve::pinned_at`]
    /// continues. The certifier solves piece by piece (issue 21: a box straddling a knot
    /// is never smooth, so a root on or at a knot could not be proven). Default: none.
    fn piece_breaks(&self) -> Vec<f64> {
        Vec::new()
    }

    /// The curve whose [`Curve::jet`] evaluates, at every parameter, the formula of the
    /// piece containing `t` (a point strictly inside a piece of
    /// [`Curve::piece_breaks`]), continued analytically beyond that piece; it agrees
    /// with `self` on the closed piece. `None` when the curve has no pieces.
    fn pinned_at(&self, _t: f64) -> Option<Self>
    where
        Self: Sized,
    {
        None
    }

    /// How the walk of OPERATIONS.md §2.1 chooses its step at `t` (see [`StepHint`]).
    /// The default is the general rule (2.1) with no extra clamp.
    fn step_hint(&self, _t: f64) -> StepHint {
        StepHint::Adaptive { max_step: None }
    }
}

/// A curve's rule for the walking step of OPERATIONS.md §2.1 at a parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepHint {
    /// The general rule (2.1) `Δt = Δα|c'|²/|c'×c''|` with the clamps of §2.1, and
    /// `max_step` as an additional upper clamp (½ of the current knot span for
    /// B-splines and NURBS, of the current segment for polylines).
    Adaptive { max_step: Option<f64> },
    /// Analytic shortcut for an angular parameter (circle, arc, ellipse, helix):
    /// `Δt = Δα / rate`, `rate` the angle swept per unit of parameter (1 for the
    /// primitives; the scale factor for reparametrised ones).
    Angular { rate: f64 },
    /// One step covers the whole domain (line, segment: `Δt = t_max − t_min`).
    Whole,
}

/// `x` is the double nearest to `kπ/2` for some `0 < |k| ≤ 4` (`±π/2`, `±π`, `±3π/2`,
/// `±2π`): a domain bound that stands for an irrational end.
pub fn is_angle_bound(x: f64) -> bool {
    (1..=4).any(|k| x.abs() == k as f64 * std::f64::consts::FRAC_PI_2 && x != 0.0)
}
