//! Parametric curves (OPERATIONS.md §1.1–§1.2, §1.5; spec/CASES.md curve types).
//!
//! A curve supplies only its value and derivatives, generic over the number type
//! ([`Real`]: `f64`, [`crate::num::Interval`], [`crate::num::MpfrInterval`]), so that
//! one formula serves the float kernel and the certifier (ARCHITECTURE.md "Layers").
//! Evaluated on an interval parameter, [`Curve::jet`] encloses every value and
//! derivative over that interval.

use crate::num::Real;

/// A parametric curve `c(t)`, `t ∈ [t_min, t_max]`, in `D` dimensions (2 or 3).
///
/// Not object-safe (the evaluation is generic); heterogeneous collections use an
/// enum over the primitives.
pub trait Curve<const D: usize> {
    /// The parameter domain `[t_min, t_max]` (§1.1), `t_min < t_max`.
    fn domain(&self) -> (f64, f64);

    /// `c(t_min) = c(t_max)` (§1.1 `closed` flag).
    fn is_closed(&self) -> bool {
        false
    }

    /// The curve is periodic with period `t_max − t_min` (derivatives also match
    /// at the ends), so a parameter may wrap around.
    fn is_periodic(&self) -> bool {
        false
    }

    /// The domain's bounds are the nearest doubles to irrational values (`2π`, an arc's
    /// angle), not the exact ends: the certifier then covers them outward by one ulp,
    /// so that no solution between the double and the exact end is missed.
    fn domain_rounded(&self) -> bool {
        false
    }

    /// The value and derivatives up to `order` (at most 3) at `t`:
    /// `jet[k] = dᵏc/dtᵏ`, so `jet.len() == order + 1`.
    ///
    /// For an interval `t`, every entry encloses the true value for every parameter
    /// in `t` (restricted to the domain where the formula is only defined there).
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]>;
}
