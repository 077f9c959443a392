//! [`Real`] and [`IntervalLike`] for [`MpfrInterval`], operators (via the shared macro),
//! and the `num_traits` identities that nalgebra's matrix products need.

use rug::float::{Constant, Round};
use rug::Float;

use super::MpfrInterval;
use crate::num::interval::ops::{forward_to_inherent, impl_interval_ops};
use crate::num::real::Arith;
use crate::num::{IntervalLike, Real};

impl_interval_ops!(
    MpfrInterval,
    |t: &MpfrInterval, v: f64| MpfrInterval::point(v, t.prec())
);

impl Arith for MpfrInterval {
    /// `[v, v]` at the precision of `self` (exact from 53 bits up).
    fn lift(&self, v: f64) -> Self {
        MpfrInterval::point(v, self.prec())
    }
}

impl Real for MpfrInterval {
    forward_to_inherent!(MpfrInterval; unary: sqr, sqrt, sin, cos, tan, exp, ln, sinh, cosh;
        binary: atan2 -> Self; predicates: );
    /// π rounded down and up at the precision of `self`.
    fn pi_like(&self) -> Self {
        let p = self.prec();
        MpfrInterval::from_floats(
            Float::with_val_round(p, Constant::Pi, Round::Down).0,
            Float::with_val_round(p, Constant::Pi, Round::Up).0,
        )
    }
    fn powi(&self, n: i32) -> Self {
        MpfrInterval::powi(self, n)
    }
    /// The midpoint rounded to the nearest double.
    fn mid(&self) -> f64 {
        self.midpoint().to_f64()
    }
    /// The bounds rounded outward to doubles.
    fn bounds(&self) -> (f64, f64) {
        (self.lo_f64(), self.hi_f64())
    }
    fn hull_with(&self, other: &Self) -> Self {
        self.hull(other)
    }
    /// Exact at 53 bits and more (the bounds are doubles).
    fn restrict_to(&self, lo: f64, hi: f64) -> Self {
        if lo > hi || lo.is_nan() || hi.is_nan() {
            return MpfrInterval::empty(self.prec());
        }
        self.intersection(&MpfrInterval::from_bounds(lo, hi, self.prec()))
    }
}

impl IntervalLike for MpfrInterval {
    forward_to_inherent!(MpfrInterval; unary: abs;
        binary: is_subset -> bool, is_interior_subset -> bool, hull -> Self, intersection -> Self;
        predicates: contains_zero, is_empty, is_entire);
    fn bisect(&self) -> (Self, Self) {
        MpfrInterval::bisect(self)
    }
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
    fn contains_value(&self, x: f64) -> bool {
        self.contains(x)
    }
    fn precision_bits(&self) -> u32 {
        self.prec()
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
