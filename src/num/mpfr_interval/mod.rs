//! Intervals over `rug::Float` (MPFR) at any precision (ARCHITECTURE.md "Numbers",
//! docs/CERTIFICATES.md "Escalation": 128, 256, 512, … bits).
//!
//! An [`MpfrInterval`] is `[lo, hi]` with both bounds MPFR numbers of one precision `p`,
//! with the same IEEE 1788 set semantics as [`crate::num::Interval`] (dropped domain
//! points, EMPTY, the whole line — read "Domain and emptiness" there).
//!
//! # Accuracy policy
//!
//! Every bound is computed by one correctly rounded MPFR operation with `Round::Down`
//! for `lo` and `Round::Up` for `hi` (MPFR guarantees correct rounding for `+ − × ÷ √`,
//! `exp ln sin cos tan sinh cosh atan2` and `pow` with an integer exponent), from exact
//! endpoints chosen by the same monotonicity/extremum analysis as the f64 type
//! ([`crate::num::interval`] `cases`). So unless noted, results are the **tightest**
//! intervals with `p`-bit bounds. Exception: where the analysis of sin/cos/tan cannot
//! decide on which side of a multiple of π/2 an endpoint lies (an endpoint within about
//! `2^-(2p+60)` of it) it includes the extremum or pole: wider, never wrong.
//! MPFR's exponent range is huge, so bounds do not overflow or underflow where doubles
//! would; [`MpfrInterval::to_interval`] rounds outward to doubles.
//!
//! Precision: binary operations return the larger precision of their operands;
//! constants from [`crate::num::Arith::lift`] take the precision of their template, and
//! the context-free `Zero`/`One` of `num_traits` (nalgebra) are exact at 53 bits.

mod arith;
mod elementary;
mod real_impl;
mod set_ops;

pub(crate) use crate::num::interval::mpfr_eval::{rd, ru};

use rug::float::Round;
use rug::ops::AssignRound;
use rug::{Float, Rational};
use std::fmt;

use crate::error::GeomError;
use crate::num::Interval;

/// A closed interval with MPFR bounds of one precision (module doc: accuracy policy).
#[derive(Clone, PartialEq)]
pub struct MpfrInterval {
    /// Lower bound, always rounded toward −∞ when computed. Invariant: non-empty ⇒
    /// `lo ≤ hi`, no NaN, `lo < +∞`, `hi > −∞`; the empty set is `lo = +∞, hi = −∞`
    /// (derived equality is then set equality).
    lo: Float,
    /// Upper bound, always rounded toward +∞ when computed.
    hi: Float,
}

/// The precision actually used: rug accepts `[prec_min, prec_max]`; below 2 bits is
/// raised to 2.
#[inline]
pub(crate) fn clamp_prec(prec: u32) -> u32 {
    prec.clamp(2.max(rug::float::prec_min()), rug::float::prec_max())
}

impl MpfrInterval {
    /// Build from bounds (crate-internal: the caller keeps the invariant).
    #[inline]
    pub(crate) fn from_floats(lo: Float, hi: Float) -> MpfrInterval {
        MpfrInterval { lo, hi }
    }

    /// The empty set at `prec` bits.
    pub fn empty(prec: u32) -> MpfrInterval {
        let p = clamp_prec(prec);
        MpfrInterval {
            lo: Float::with_val(p, f64::INFINITY),
            hi: Float::with_val(p, f64::NEG_INFINITY),
        }
    }

    /// The whole line at `prec` bits.
    pub fn entire(prec: u32) -> MpfrInterval {
        let p = clamp_prec(prec);
        MpfrInterval {
            lo: Float::with_val(p, f64::NEG_INFINITY),
            hi: Float::with_val(p, f64::INFINITY),
        }
    }

    /// `[lo, hi]` from user data at `prec` bits (outward rounded below 53 bits): NaN,
    /// `lo > hi`, `lo = +∞` or `hi = −∞` is a typed error naming `field`.
    pub fn new(field: &str, lo: f64, hi: f64, prec: u32) -> Result<MpfrInterval, GeomError> {
        let x = Interval::new(field, lo, hi)?;
        Ok(MpfrInterval::from_interval(&x, prec))
    }

    /// `[lo, hi]` for bounds the program computed itself, outward rounded to `prec`
    /// bits; a NaN bound or `lo > hi` (caught by a debug assertion) gives the whole line,
    /// `lo = +∞` is read as `f64::MAX`, `hi = −∞` as `−f64::MAX` (as
    /// [`Interval::from_bounds`]).
    pub fn from_bounds(lo: f64, hi: f64, prec: u32) -> MpfrInterval {
        MpfrInterval::from_interval(&Interval::from_bounds(lo, hi), prec)
    }

    /// `[x, x]` (outward rounded below 53 bits; NaN gives the whole line, ±∞ a half-line
    /// beyond ±f64::MAX, as [`Interval::point`]).
    pub fn point(x: f64, prec: u32) -> MpfrInterval {
        MpfrInterval::from_interval(&Interval::point(x), prec)
    }

    /// The f64 interval `x`, exactly if `prec ≥ 53`, else rounded outward.
    pub fn from_interval(x: &Interval, prec: u32) -> MpfrInterval {
        let p = clamp_prec(prec);
        if x.is_empty() {
            return MpfrInterval::empty(p);
        }
        MpfrInterval {
            lo: rd(p, x.lo()),
            hi: ru(p, x.hi()),
        }
    }

    /// The tightest `prec`-bit interval containing the rational `q`.
    pub fn from_rational(q: &Rational, prec: u32) -> MpfrInterval {
        let p = clamp_prec(prec);
        MpfrInterval {
            lo: rd(p, q),
            hi: ru(p, q),
        }
    }

    /// The tightest `prec`-bit interval containing the MPFR number `x` (NaN: the whole
    /// line).
    pub fn from_float(x: &Float, prec: u32) -> MpfrInterval {
        MpfrInterval::from_float_bounds(x, x, prec)
    }

    /// `[lo, hi]` rounded outward to `prec` bits (NaN or `lo > hi`: the whole line, as
    /// [`MpfrInterval::from_bounds`]).
    pub fn from_float_bounds(lo: &Float, hi: &Float, prec: u32) -> MpfrInterval {
        let p = clamp_prec(prec);
        if lo.is_nan() || hi.is_nan() || lo > hi {
            debug_assert!(
                lo.is_nan() || hi.is_nan(),
                "MpfrInterval::from_float_bounds({lo}, {hi})"
            );
            return MpfrInterval::entire(p);
        }
        MpfrInterval {
            lo: rd(p, lo),
            hi: ru(p, hi),
        }
    }

    /// The same set rounded outward to `prec` bits (exact if `prec` is larger).
    pub fn with_prec(&self, prec: u32) -> MpfrInterval {
        if self.is_empty() {
            return MpfrInterval::empty(prec);
        }
        MpfrInterval::from_float_bounds(&self.lo, &self.hi, prec)
    }

    /// The tightest f64 interval containing `self` (bounds converted by MPFR with
    /// directed rounding: beyond the double range they become ±∞ or ±f64::MAX).
    pub fn to_interval(&self) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let lo = self.lo.to_f64_round(Round::Down);
        let hi = self.hi.to_f64_round(Round::Up);
        // A bound beyond ±f64::MAX keeps the set inside [lo, hi]: lo ≥ −∞, hi ≤ +∞.
        Interval::from_bounds(lo.min(f64::MAX), hi.max(-f64::MAX))
    }

    /// The precision of the bounds in bits.
    #[inline]
    pub fn prec(&self) -> u32 {
        self.lo.prec()
    }

    /// The lower bound (`+∞` if empty).
    #[inline]
    pub fn lo(&self) -> &Float {
        &self.lo
    }

    /// The upper bound (`−∞` if empty).
    #[inline]
    pub fn hi(&self) -> &Float {
        &self.hi
    }

    /// The lower bound rounded down to a double.
    #[inline]
    pub fn lo_f64(&self) -> f64 {
        self.lo.to_f64_round(Round::Down)
    }

    /// The upper bound rounded up to a double.
    #[inline]
    pub fn hi_f64(&self) -> f64 {
        self.hi.to_f64_round(Round::Up)
    }

    /// True for the empty set.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.lo.is_infinite() && self.lo.is_sign_positive()
    }

    /// True for the whole line.
    #[inline]
    pub fn is_entire(&self) -> bool {
        self.lo.is_infinite()
            && self.lo.is_sign_negative()
            && self.hi.is_infinite()
            && self.hi.is_sign_positive()
    }

    /// Both bounds finite (false for the empty set).
    #[inline]
    pub fn is_bounded(&self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// Replace the value by `x` keeping the precision (outward).
    pub fn assign_interval(&mut self, x: &Interval) {
        if x.is_empty() {
            *self = MpfrInterval::empty(self.prec());
        } else {
            self.lo.assign_round(x.lo(), Round::Down);
            self.hi.assign_round(x.hi(), Round::Up);
        }
    }
}

impl fmt::Debug for MpfrInterval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_empty() {
            write!(f, "[empty]@{}", self.prec())
        } else {
            write!(f, "[{:e}, {:e}]@{}", self.lo, self.hi, self.prec())
        }
    }
}

impl fmt::Display for MpfrInterval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

#[cfg(test)]
mod tests;
