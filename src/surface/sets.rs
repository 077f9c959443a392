//! Set operations on enclosures for generic code over [`Real`]: the hull (union) and
//! intersection of two enclosures of the same quantity, through [`Real::hull_with`]
//! and [`Real::restrict_to`], so they work for every number type (f64, intervals, and
//! the certifier's dual and smoothness-guarded wrappers).
//!
//! For `f64` (point evaluation, which proves nothing) they return a point.

use crate::num::Real;

/// An enclosure of the union of two enclosures (the interval hull).
pub fn hull<T: Real>(a: &T, b: &T) -> T {
    a.hull_with(b)
}

/// An enclosure of the intersection of two enclosures of the same quantity: `a`
/// restricted to the outward f64 bounds of `b` (a superset of `b`, so the result
/// still contains the quantity). Empty only if one of them was wrong.
pub fn meet<T: Real>(a: &T, b: &T) -> T {
    let (lo, hi) = b.bounds();
    a.restrict_to(lo, hi)
}
