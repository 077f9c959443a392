//! [`Real`] and [`IntervalLike`] for [`Interval`], and the `num_traits` identities that
//! nalgebra's matrix products need.

use super::mpfr_eval::{PI_DOWN, PI_UP};
use super::Interval;
use crate::num::{IntervalLike, Real};

impl Real for Interval {
    /// The point interval `[v, v]` (exact).
    fn lift(&self, v: f64) -> Self {
        Interval::point(v)
    }
    /// `[π↓, π↑]`, one ulp wide.
    fn pi_like(&self) -> Self {
        Interval::from_neg_lo_hi(-PI_DOWN, PI_UP)
    }
    fn sqr(&self) -> Self {
        Interval::sqr(self)
    }
    fn sqrt(&self) -> Self {
        Interval::sqrt(self)
    }
    fn powi(&self, n: i32) -> Self {
        Interval::powi(self, n)
    }
    fn sin(&self) -> Self {
        Interval::sin(self)
    }
    fn cos(&self) -> Self {
        Interval::cos(self)
    }
    fn tan(&self) -> Self {
        Interval::tan(self)
    }
    fn exp(&self) -> Self {
        Interval::exp(self)
    }
    fn ln(&self) -> Self {
        Interval::ln(self)
    }
    fn sinh(&self) -> Self {
        Interval::sinh(self)
    }
    fn cosh(&self) -> Self {
        Interval::cosh(self)
    }
    fn atan2(&self, x: &Self) -> Self {
        Interval::atan2(self, x)
    }
    fn mid(&self) -> f64 {
        self.midpoint()
    }
    fn bounds(&self) -> (f64, f64) {
        (self.lo(), self.hi())
    }
}

impl IntervalLike for Interval {
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
    fn contains_zero(&self) -> bool {
        Interval::contains_zero(self)
    }
    fn contains_value(&self, x: f64) -> bool {
        self.contains(x)
    }
    fn is_subset(&self, other: &Self) -> bool {
        Interval::is_subset(self, other)
    }
    fn is_interior_subset(&self, other: &Self) -> bool {
        Interval::is_interior_subset(self, other)
    }
    fn abs(&self) -> Self {
        Interval::abs(self)
    }
    fn hull(&self, other: &Self) -> Self {
        Interval::hull(self, other)
    }
    fn intersection(&self, other: &Self) -> Self {
        Interval::intersection(self, other)
    }
    fn bisect(&self) -> (Self, Self) {
        Interval::bisect(self)
    }
    fn precision_bits(&self) -> u32 {
        53
    }
    fn is_empty(&self) -> bool {
        Interval::is_empty(self)
    }
    fn is_entire(&self) -> bool {
        Interval::is_entire(self)
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
