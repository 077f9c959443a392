//! What generic certification code (Krawczyk, subdivision, escalation — docs/CERTIFICATES.md)
//! needs from an interval type, on top of [`Real`]: implemented by
//! [`crate::num::Interval`] and [`crate::num::MpfrInterval`], so that the certifier is
//! written once and runs at f64 precision and at any MPFR precision.
//!
//! Conventions: f64 results that bound something are rounded outward (`inf` down,
//! `sup`/`wid`/`rad`/`mag` up, `mig` down); intervals created from a template (`*_like`)
//! have the template's precision. The empty set follows IEEE 1788: it is a subset and
//! an interior subset of everything, and arithmetic on it gives it back — a certifier
//! must test [`IntervalLike::is_empty`] before concluding from an inclusion
//! (see [`crate::num::interval`] "Domain and emptiness").

use super::Real;

/// An interval number type (see the module documentation).
pub trait IntervalLike: Real {
    /// `[lo, hi]` in the number system and precision of `self`, rounded outward if the
    /// bounds are not representable. Precondition `lo ≤ hi` (a violation gives the whole
    /// line, never a wrong enclosure).
    fn with_bounds(&self, lo: f64, hi: f64) -> Self;
    /// The empty set, in the precision of `self`.
    fn empty_like(&self) -> Self;
    /// The whole line, in the precision of `self`.
    fn entire_like(&self) -> Self;
    /// The lower bound rounded down to a double (`+∞` if empty).
    fn inf(&self) -> f64;
    /// The upper bound rounded up to a double (`−∞` if empty).
    fn sup(&self) -> f64;
    /// A point of the interval (its midpoint, rounded to nearest at the interval's
    /// precision) as a point interval `[m, m]` of the same type — the `m` of Krawczyk.
    /// Empty in, empty out.
    fn mid_interval(&self) -> Self;
    /// The width `hi − lo`, rounded up (NaN if empty).
    fn wid(&self) -> f64;
    /// An upper bound of the radius about `mid_interval` (NaN if empty).
    fn rad(&self) -> f64;
    /// `max |x|` rounded up (NaN if empty).
    fn mag(&self) -> f64;
    /// `min |x|` rounded down (NaN if empty).
    fn mig(&self) -> f64;
    /// `0 ∈ self`.
    fn contains_zero(&self) -> bool;
    /// `x ∈ self` for a double `x`.
    fn contains_value(&self, x: f64) -> bool;
    /// `self ⊆ other`.
    fn is_subset(&self, other: &Self) -> bool;
    /// `self ⊆ interior(other)` (for a bounded `other`: strictly inside on both sides).
    fn is_interior_subset(&self, other: &Self) -> bool;
    /// `|self|` (tightest).
    fn abs(&self) -> Self;
    /// The convex hull of the union.
    fn hull(&self, other: &Self) -> Self;
    /// The intersection (possibly empty).
    fn intersection(&self, other: &Self) -> Self;
    /// Two halves whose union is `self`, split at `mid_interval`.
    fn bisect(&self) -> (Self, Self);
    /// The precision of the bounds in bits (53 for f64 intervals).
    fn precision_bits(&self) -> u32;
    /// True for the empty set.
    fn is_empty(&self) -> bool;
    /// True for the whole line.
    fn is_entire(&self) -> bool;
}
