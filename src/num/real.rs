//! The one numeric trait that f64, the f64 interval and the MPFR interval implement
//! (ARCHITECTURE.md "Numbers"), so that a formula — a curve's point, a Jacobian — is
//! written once and evaluated in any of them.
//!
//! Contract for implementors that are enclosures (intervals): every operation returns
//! a set that contains the exact result of the operation applied to every point of the
//! operands. For `f64` the operations are the ordinary (rounded) ones and prove nothing.
//! The interval types follow IEEE 1788 set semantics: points where an operation is
//! undefined are dropped (`√[-4, 1] = [0, 1]`; `x / [0, 0]` is empty; a divisor with 0
//! inside gives the whole line), so an interval result can be EMPTY — generic
//! certification code checks [`crate::num::IntervalLike::is_empty`] before concluding
//! anything from an inclusion (see [`crate::num::interval`] "Domain and emptiness").
//!
//! Constants enter a formula through [`Arith::lift`] (the arithmetic supertrait of [`Real`]), which produces the exact value in
//! the number system (and precision) of an existing number, so MPFR intervals keep
//! their precision through a generic formula without a global context.

use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The arithmetic of a polynomial or rational formula, without elementary functions:
/// what the basis recursions of `surface::basis` need. Every [`Real`] is one; so is
/// [`crate::num::midrad::MidRad`], the cheap enclosure of the fast surface path.
pub trait Arith:
    Clone
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
{
    /// The exact value `v` in the same number system and precision as `self`.
    fn lift(&self, v: f64) -> Self;
}

/// A number type a formula can be evaluated in: `f64`, [`crate::num::Interval`] or
/// [`crate::num::MpfrInterval`].
pub trait Real: Arith + Debug + PartialEq + 'static {
    /// π (an enclosure of it for interval types).
    fn pi_like(&self) -> Self;
    /// `self²` (tighter than `self * self` for intervals that contain 0).
    fn sqr(&self) -> Self;
    /// `√self`; for intervals, the part of the operand below 0 is ignored
    /// (an operand entirely below 0 gives an empty or NaN result).
    fn sqrt(&self) -> Self;
    /// `self^n` for an integer `n` (n < 0 divides).
    fn powi(&self, n: i32) -> Self;
    fn sin(&self) -> Self;
    fn cos(&self) -> Self;
    fn tan(&self) -> Self;
    fn exp(&self) -> Self;
    /// Natural logarithm.
    fn ln(&self) -> Self;
    fn sinh(&self) -> Self;
    fn cosh(&self) -> Self;
    /// `atan2(self, x)`: the angle of the point `(x, self)`, in `(-π, π]`.
    fn atan2(&self, x: &Self) -> Self;
    /// A representative double (the value for f64, a midpoint for intervals).
    fn mid(&self) -> f64;
    /// Lower and upper f64 bounds of the value (rounded outward for MPFR intervals;
    /// `(x, x)` for f64).
    fn bounds(&self) -> (f64, f64);

    /// 0 in the number system of `self`.
    fn zero_like(&self) -> Self {
        self.lift(0.0)
    }
    /// 1 in the number system of `self`.
    fn one_like(&self) -> Self {
        self.lift(1.0)
    }

    /// The convex hull of `self` and `other`, for evaluating a formula piecewise over
    /// an interval parameter (a B-spline over the knot spans it straddles) and
    /// joining the pieces. Enclosures: contains both operands (an empty operand gives
    /// the other). `f64` (a point, which generic code that splits by [`Real::bounds`]
    /// never needs to join): `self`.
    fn hull_with(&self, other: &Self) -> Self;

    /// `self ∩ [lo, hi]` (`lo` may be `−∞`, `hi` may be `+∞`), for restricting an
    /// interval parameter to one piece of a piecewise formula. Enclosures: the
    /// intersection, possibly empty. `f64`: `self` clamped into `[lo, hi]`.
    fn restrict_to(&self, lo: f64, hi: f64) -> Self;

    /// `true` for `f64` only: plain floating point, which proves nothing, so a formula
    /// may reuse an f64 value it computed once (the cached axes of
    /// `curve::frame::Frame::axes`) where every other type evaluates the formula to
    /// enclose the exact value.
    const IS_F64: bool = false;

    /// Hook of the fast paths written for f64 intervals (`surface::taylor_fast`), the
    /// way in: `[lo, hi]` when this number is an f64 interval — [`crate::num::Interval`]
    /// itself, or a wrapper that adds bookkeeping to one (the certifier's
    /// `Guarded<Interval>`) — as [`crate::num::Interval::lo`] and `hi` give them
    /// (`[+∞, −∞]` for the empty set). `None` (the default) for every other type, which
    /// then takes the generic path.
    fn as_f64_interval(&self) -> Option<[f64; 2]> {
        None
    }

    /// The same hook, the way out: the number of this type whose value is the f64
    /// interval `[lo, hi]` (`lo > hi`: empty), which a fast path computed from `args`
    /// (each [`Real::as_f64_interval`]) by a function that is `C^∞` on a neighbourhood
    /// of their box (a polynomial, or a quotient whose denominator it proved nonzero).
    /// A wrapper keeps its bookkeeping: `Guarded` is smooth exactly when every argument
    /// is and the value is not empty. `Some` exactly for the types whose
    /// [`Real::as_f64_interval`] is `Some`; the bounds are taken as they are (no rounding).
    fn from_f64_interval(bounds: [f64; 2], args: &[&Self]) -> Option<Self> {
        let _ = (bounds, args);
        None
    }
}

impl Arith for f64 {
    fn lift(&self, v: f64) -> Self {
        v
    }
}

impl Real for f64 {
    const IS_F64: bool = true;
    fn pi_like(&self) -> Self {
        std::f64::consts::PI
    }
    fn sqr(&self) -> Self {
        self * self
    }
    fn sqrt(&self) -> Self {
        f64::sqrt(*self)
    }
    fn powi(&self, n: i32) -> Self {
        f64::powi(*self, n)
    }
    fn sin(&self) -> Self {
        f64::sin(*self)
    }
    fn cos(&self) -> Self {
        f64::cos(*self)
    }
    fn tan(&self) -> Self {
        f64::tan(*self)
    }
    fn exp(&self) -> Self {
        f64::exp(*self)
    }
    fn ln(&self) -> Self {
        f64::ln(*self)
    }
    fn sinh(&self) -> Self {
        f64::sinh(*self)
    }
    fn cosh(&self) -> Self {
        f64::cosh(*self)
    }
    fn atan2(&self, x: &Self) -> Self {
        f64::atan2(*self, *x)
    }
    fn mid(&self) -> f64 {
        *self
    }
    fn bounds(&self) -> (f64, f64) {
        (*self, *self)
    }
    fn hull_with(&self, _other: &Self) -> Self {
        *self
    }
    fn restrict_to(&self, lo: f64, hi: f64) -> Self {
        self.max(lo).min(hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A generic formula, written once: the point of a circle of radius r at angle t.
    fn circle_point<T: Real>(r: f64, t: &T) -> (T, T) {
        let rr = t.lift(r);
        (rr.clone() * t.cos(), rr * t.sin())
    }

    #[test]
    fn f64_evaluates_generic_formulas() {
        let (x, y) = circle_point(2.0, &0.0f64);
        assert_eq!((x, y), (2.0, 0.0));
        assert_eq!(3.0f64.lift(0.5), 0.5);
        assert_eq!(Real::sqr(&-3.0f64), 9.0);
        assert_eq!(Real::bounds(&1.5f64), (1.5, 1.5));
        assert_eq!(2.5f64.restrict_to(0.0, 1.0), 1.0);
        assert_eq!((-2.5f64).restrict_to(f64::NEG_INFINITY, 1.0), -2.5);
        assert_eq!(2.5f64.hull_with(&7.0), 2.5);
    }
}
