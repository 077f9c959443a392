//! Set operations on enclosures for generic code over [`Real`], which has none: the
//! hull (union) and intersection of two enclosures of the same quantity, for the
//! interval types of this crate (found by downcasting; [`Real`] is `'static`).
//!
//! For `f64` (point evaluation, which proves nothing) the first argument is returned.

use std::any::Any;

use crate::num::{Interval, IntervalLike, MpfrInterval, Real};

fn combine<T: Real>(
    a: &T,
    b: &T,
    f64_op: fn(&Interval, &Interval) -> Interval,
    mpfr_op: fn(&MpfrInterval, &MpfrInterval) -> MpfrInterval,
) -> T {
    let mut out = a.clone();
    let any_out: &mut dyn Any = &mut out;
    if let Some(x) = any_out.downcast_mut::<Interval>() {
        if let Some(y) = (b as &dyn Any).downcast_ref::<Interval>() {
            *x = f64_op(x, y);
        }
    } else if let Some(x) = any_out.downcast_mut::<MpfrInterval>() {
        if let Some(y) = (b as &dyn Any).downcast_ref::<MpfrInterval>() {
            *x = mpfr_op(x, y);
        }
    } else if !any_out.is::<f64>() {
        panic!("surface::sets: unsupported number type");
    }
    out
}

/// An enclosure of the union of two enclosures (the interval hull).
///
/// # Panics
/// For a [`Real`] type other than `f64`, [`Interval`] and [`MpfrInterval`] (add it
/// here; no user input reaches this).
pub fn hull<T: Real>(a: &T, b: &T) -> T {
    combine(a, b, IntervalLike::hull, IntervalLike::hull)
}

/// The intersection of two enclosures of the same quantity (an enclosure of it). Empty
/// only if one of them was wrong — never for correct enclosures.
///
/// # Panics
/// As [`hull`].
pub fn meet<T: Real>(a: &T, b: &T) -> T {
    combine(a, b, IntervalLike::intersection, IntervalLike::intersection)
}
