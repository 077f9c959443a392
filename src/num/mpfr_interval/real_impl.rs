//! [`Real`] and [`IntervalLike`] for [`MpfrInterval`], operators (via the shared macro),
//! and the `num_traits` identities that nalgebra's matrix products need.

use rug::float::{Constant, Round};
use rug::Float;

use super::MpfrInterval;
use crate::num::interval::ops::impl_interval_ops;
use crate::num::{IntervalLike, Real};

impl_interval_ops!(
    MpfrInterval,
    |t: &MpfrInterval, v: f64| MpfrInterval::point(v, t.prec())
);

impl Real for MpfrInterval {
    /// `[v, v]` at the precision of `self` (exact from 53 bits up).
    fn lift(&self, v: f64) -> Self {
        MpfrInterval::point(v, self.prec())
    }
    /// π rounded down and up at the precision of `self`.
    fn pi_like(&self) -> Self {
        let p = self.prec();
        MpfrInterval::from_floats(
            Float::with_val_round(p, Constant::Pi, Round::Down).0,
            Float::with_val_round(p, Constant::Pi, Round::Up).0,
        )
    }
    fn sqr(&self) -> Self {
        MpfrInterval::sqr(self)
    }
    fn sqrt(&self) -> Self {
        MpfrInterval::sqrt(self)
    }
    fn powi(&self, n: i32) -> Self {
        MpfrInterval::powi(self, n)
    }
    fn sin(&self) -> Self {
        MpfrInterval::sin(self)
    }
    fn cos(&self) -> Self {
        MpfrInterval::cos(self)
    }
    fn tan(&self) -> Self {
        MpfrInterval::tan(self)
    }
    fn exp(&self) -> Self {
        MpfrInterval::exp(self)
    }
    fn ln(&self) -> Self {
        MpfrInterval::ln(self)
    }
    fn sinh(&self) -> Self {
        MpfrInterval::sinh(self)
    }
    fn cosh(&self) -> Self {
        MpfrInterval::cosh(self)
    }
    fn atan2(&self, x: &Self) -> Self {
        MpfrInterval::atan2(self, x)
    }
    /// The midpoint rounded to the nearest double.
    fn mid(&self) -> f64 {
        self.midpoint().to_f64()
    }
    /// The bounds rounded outward to doubles.
    fn bounds(&self) -> (f64, f64) {
        (self.lo_f64(), self.hi_f64())
    }
}

impl IntervalLike for MpfrInterval {
    fn with_bounds(&self, lo: f64, hi: f64) -> Self {
        MpfrInterval::from_bounds(lo, hi, self.prec())
    }
    fn empty_like(&self) -> Self {
        MpfrInterval::empty(self.prec())
    }
    fn entire_like(&self) -> Self {
        MpfrInterval::entire(self.prec())
    }
    fn inf(&self) -> f64 {
        self.lo_f64()
    }
    fn sup(&self) -> f64 {
        self.hi_f64()
    }
    fn mid_interval(&self) -> Self {
        self.mid_point_interval()
    }
    fn wid(&self) -> f64 {
        self.width().to_f64_round(Round::Up)
    }
    fn rad(&self) -> f64 {
        self.radius().to_f64_round(Round::Up)
    }
    fn mag(&self) -> f64 {
        self.mag_float().to_f64_round(Round::Up)
    }
    fn mig(&self) -> f64 {
        self.mig_float().to_f64_round(Round::Down)
    }
    fn contains_zero(&self) -> bool {
        MpfrInterval::contains_zero(self)
    }
    fn contains_value(&self, x: f64) -> bool {
        self.contains(x)
    }
    fn is_subset(&self, other: &Self) -> bool {
        MpfrInterval::is_subset(self, other)
    }
    fn is_interior_subset(&self, other: &Self) -> bool {
        MpfrInterval::is_interior_subset(self, other)
    }
    fn abs(&self) -> Self {
        MpfrInterval::abs(self)
    }
    fn hull(&self, other: &Self) -> Self {
        MpfrInterval::hull(self, other)
    }
    fn intersection(&self, other: &Self) -> Self {
        MpfrInterval::intersection(self, other)
    }
    fn bisect(&self) -> (Self, Self) {
        MpfrInterval::bisect(self)
    }
    fn precision_bits(&self) -> u32 {
        self.prec()
    }
    fn is_empty(&self) -> bool {
        MpfrInterval::is_empty(self)
    }
    fn is_entire(&self) -> bool {
        MpfrInterval::is_entire(self)
    }
}

/// Exact 0 at 53 bits (no precision context; binary operations take the larger
/// precision, so this never lowers the precision of a computation at ≥ 53 bits).
impl num_traits::Zero for MpfrInterval {
    fn zero() -> Self {
        MpfrInterval::point(0.0, 53)
    }
    fn is_zero(&self) -> bool {
        self.lo().is_zero() && self.hi().is_zero()
    }
}

/// Exact 1 at 53 bits (see `Zero`).
impl num_traits::One for MpfrInterval {
    fn one() -> Self {
        MpfrInterval::point(1.0, 53)
    }
}
