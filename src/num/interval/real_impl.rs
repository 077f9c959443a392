//! [`Real`] and [`IntervalLike`] for [`Interval`], and the `num_traits` identities that
//! nalgebra's matrix products need.

use super::mpfr_eval::{PI_DOWN, PI_UP};
use super::Interval;
use crate::num::interval::ops::forward_to_inherent;
use crate::num::real::Arith;
use crate::num::{IntervalLike, Real};

impl Arith for Interval {
    /// The point interval `[v, v]` (exact).
    fn lift(&self, v: f64) -> Self {
        Interval::point(v)
    }
}

impl Real for Interval {
    forward_to_inherent!(Interval; unary: sqr, sqrt, sin, cos, tan, exp, ln, sinh, cosh;
        binary: atan2 -> Self; predicates: );
    /// `[π↓, π↑]`, one ulp wide.
    fn pi_like(&self) -> Self {
        Interval::from_neg_lo_hi(-PI_DOWN, PI_UP)
    }
    fn powi(&self, n: i32) -> Self {
        Interval::powi(self, n)
    }
    fn mid(&self) -> f64 {
        self.midpoint()
    }
    fn bounds(&self) -> (f64, f64) {
        (self.lo(), self.hi())
    }
    fn hull_with(&self, other: &Self) -> Self {
        self.hull(other)
    }
    /// `[lo, hi]` as stored (exact).
    fn as_f64_interval(&self) -> Option<[f64; 2]> {
        Some([self.lo(), self.hi()])
    }
    /// The interval `[lo, hi]` itself (exact; `lo > hi` is the empty set).
    fn from_f64_interval([lo, hi]: [f64; 2], _args: &[&Self]) -> Option<Self> {
        Some(if lo > hi {
            Interval::EMPTY
        } else {
            Interval::from_bounds(lo, hi)
        })
    }
    /// Exact: the bounds are doubles, so the intersection needs no rounding.
    fn restrict_to(&self, lo: f64, hi: f64) -> Self {
        if lo > hi || lo.is_nan() || hi.is_nan() {
            return Interval::EMPTY;
        }
        self.intersection(&Interval::from_bounds(lo, hi))
    }
}

impl IntervalLike for Interval {
    forward_to_inherent!(Interval; unary: abs;
        binary: is_subset -> bool, is_interior_subset -> bool, hull -> Self, intersection -> Self;
        predicates: contains_zero, is_empty, is_entire);
    fn bisect(&self) -> (Self, Self) {
        Interval::bisect(self)
    }
    fn with_bounds(&self, lo: f64, hi: f64) -> Self {
        Interval::from_bounds(lo, hi)
    }
    fn empty_like(&self) -> Self {
        Interval::EMPTY
    }
    fn entire_like(&self) -> Self {
        Interval::ENTIRE
    }
    fn inf(&self) -> f64 {
        self.lo()
    }
    fn sup(&self) -> f64 {
        self.hi()
    }
    fn mid_interval(&self) -> Self {
        if self.is_empty() {
            Interval::EMPTY
        } else {
            Interval::point(self.midpoint())
        }
    }
    fn wid(&self) -> f64 {
        self.width()
    }
    fn rad(&self) -> f64 {
        self.radius()
    }
    fn mag(&self) -> f64 {
        Interval::mag(self)
    }
    fn mig(&self) -> f64 {
        Interval::mig(self)
    }
    fn contains_value(&self, x: f64) -> bool {
        self.contains(x)
    }
    fn precision_bits(&self) -> u32 {
        53
    }
}

impl num_traits::Zero for Interval {
    fn zero() -> Self {
        Interval::ZERO
    }
    fn is_zero(&self) -> bool {
        *self == Interval::ZERO
    }
}

impl num_traits::One for Interval {
    fn one() -> Self {
        Interval::ONE
    }
}
