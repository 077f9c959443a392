//! Elementary functions of [`MpfrInterval`]: each bound is the MPFR function (correctly
//! rounded) at an endpoint, rounded down for `lo` and up for `hi` at the interval's
//! precision, with the endpoint chosen by the function's monotonicity; for sin, cos and
//! tan by which multiples of π/2 the argument may contain
//! ([`crate::num::interval`] `cases`), decided from a rigorous reduction
//! ([`reduce_half_pi_mpfr`]); for atan2 by the shared corner analysis.

use rug::float::{Constant, Round};
use rug::{Float, Integer};
use std::cmp::Ordering;

use super::MpfrInterval;
use crate::num::interval::{
    atan2_plan, half_pi_multiples, reduce_half_pi_mpfr, Atan2Bound, Atan2Plan, COS_MAX, COS_MIN,
    SIN_MAX, SIN_MIN, TAN_POLE,
};

/// `f(x)` at precision `p` rounded in direction `round`.
fn at(p: u32, x: &Float, round: Round, f: fn(&mut Float, Round) -> Ordering) -> Float {
    let mut t = Float::with_val(p, x);
    f(&mut t, round);
    t
}

fn unit(p: u32) -> MpfrInterval {
    MpfrInterval::from_floats(Float::with_val(p, -1), Float::with_val(p, 1))
}

impl MpfrInterval {
    /// The multiples-of-π/2 mask of the (bounded, non-empty) argument.
    fn half_pi_mask(&self) -> u8 {
        let ra = reduce_half_pi_mpfr(&self.lo);
        let rb = reduce_half_pi_mpfr(&self.hi);
        let d = Integer::from(&rb.k - &ra.k);
        let span = d.to_u64().unwrap_or(if d < 0 { 0 } else { u64::MAX });
        half_pi_multiples(ra.k_mod4, span, ra.r_may_be_le0, rb.r_may_be_ge0)
    }

    fn sin_or_cos(
        &self,
        max_bit: u8,
        min_bit: u8,
        f: fn(&mut Float, Round) -> Ordering,
    ) -> MpfrInterval {
        let p = self.prec();
        if self.is_empty() {
            return self.clone();
        }
        if !self.is_bounded() || self.width() >= 7 {
            return unit(p);
        }
        let m = self.half_pi_mask();
        if m & max_bit != 0 && m & min_bit != 0 {
            return unit(p);
        }
        let lo = if m & min_bit != 0 {
            Float::with_val(p, -1)
        } else {
            at(p, &self.lo, Round::Down, f).min(&at(p, &self.hi, Round::Down, f))
        };
        let hi = if m & max_bit != 0 {
            Float::with_val(p, 1)
        } else {
            at(p, &self.lo, Round::Up, f).max(&at(p, &self.hi, Round::Up, f))
        };
        MpfrInterval::from_floats(lo, hi)
    }

    /// `sin`, tightest: ±1 where the argument may contain `±π/2 + 2jπ`, else the
    /// endpoint values rounded outward (sin is monotone between extrema).
    pub fn sin(&self) -> MpfrInterval {
        self.sin_or_cos(SIN_MAX, SIN_MIN, |t, r| t.sin_round(r))
    }

    /// `cos`, tightest: ±1 where the argument may contain `2jπ` / `π + 2jπ`.
    pub fn cos(&self) -> MpfrInterval {
        self.sin_or_cos(COS_MAX, COS_MIN, |t, r| t.cos_round(r))
    }

    /// `tan`, tightest: the whole line if the argument may contain a pole
    /// `π/2 + jπ` (or is unbounded), else `[tan(lo)↓, tan(hi)↑]` (increasing).
    pub fn tan(&self) -> MpfrInterval {
        let p = self.prec();
        if self.is_empty() {
            return self.clone();
        }
        if !self.is_bounded() || self.width() >= 4 || self.half_pi_mask() & TAN_POLE != 0 {
            return MpfrInterval::entire(p);
        }
        MpfrInterval::from_floats(
            at(p, &self.lo, Round::Down, |t, r| t.tan_round(r)),
            at(p, &self.hi, Round::Up, |t, r| t.tan_round(r)),
        )
    }

    /// `exp`, increasing, tightest.
    pub fn exp(&self) -> MpfrInterval {
        self.increasing(|t, r| t.exp_round(r))
    }

    /// `sinh`, increasing, tightest.
    pub fn sinh(&self) -> MpfrInterval {
        self.increasing(|t, r| t.sinh_round(r))
    }

    fn increasing(&self, f: fn(&mut Float, Round) -> Ordering) -> MpfrInterval {
        if self.is_empty() {
            return self.clone();
        }
        let p = self.prec();
        MpfrInterval::from_floats(
            at(p, &self.lo, Round::Down, f),
            at(p, &self.hi, Round::Up, f),
        )
    }

    /// `cosh`, tightest: `[cosh(mig)↓, cosh(mag)↑]` (minimum 1 at 0).
    pub fn cosh(&self) -> MpfrInterval {
        if self.is_empty() {
            return self.clone();
        }
        let p = self.prec();
        let f: fn(&mut Float, Round) -> Ordering = |t, r| t.cosh_round(r);
        MpfrInterval::from_floats(
            at(p, &self.mig_float(), Round::Down, f),
            at(p, &self.mag_float(), Round::Up, f),
        )
    }

    /// Natural logarithm, tightest; the part `≤ 0` is dropped (`ln [−2, 0]` is EMPTY,
    /// `ln [0, 1] = [−∞, 0]`).
    pub fn ln(&self) -> MpfrInterval {
        let p = self.prec();
        if self.is_empty() || self.hi <= 0 {
            return MpfrInterval::empty(p);
        }
        let f: fn(&mut Float, Round) -> Ordering = |t, r| t.ln_round(r);
        let lo = if self.lo <= 0 {
            Float::with_val(p, f64::NEG_INFINITY)
        } else {
            at(p, &self.lo, Round::Down, f)
        };
        MpfrInterval::from_floats(lo, at(p, &self.hi, Round::Up, f))
    }

    /// `atan2(self, x)` over the box `x × self` minus the origin, in `(−π, π]`,
    /// tightest at the larger precision: the corner analysis of
    /// [`crate::num::Interval::atan2`], corners by MPFR `atan2` rounded outward, the
    /// constants ±π, ±π/2 rounded outward.
    pub fn atan2(&self, x: &MpfrInterval) -> MpfrInterval {
        let p = self.prec().max(x.prec());
        if self.is_empty() || x.is_empty() {
            return MpfrInterval::empty(p);
        }
        let sign = |v: &Float| v.cmp0().unwrap_or(Ordering::Equal);
        let (c, d, a, b) = (&self.lo, &self.hi, &x.lo, &x.hi);
        let bound = |bd: Atan2Bound, round: Round| -> Float {
            let pi = |r: Round| Float::with_val_round(p, Constant::Pi, r).0;
            let neg = |v: Float| -v;
            let down = round == Round::Down;
            let opposite = if down { Round::Up } else { Round::Down };
            match bd {
                Atan2Bound::Corner { y_hi, x_hi } => {
                    let mut t = Float::with_val(p, if y_hi { d } else { c });
                    t.atan2_round(if x_hi { b } else { a }, round);
                    t
                }
                Atan2Bound::NegPi => neg(pi(opposite)),
                Atan2Bound::NegHalfPi => neg(pi(opposite)) / 2u32,
                Atan2Bound::Zero => Float::new(p),
                Atan2Bound::HalfPi => pi(round) / 2u32,
                Atan2Bound::Pi => pi(round),
            }
        };
        match atan2_plan(sign(c), sign(d), sign(a), sign(b)) {
            Atan2Plan::Empty => MpfrInterval::empty(p),
            Atan2Plan::Range(lo, hi) => {
                MpfrInterval::from_floats(bound(lo, Round::Down), bound(hi, Round::Up))
            }
        }
    }
}
