//! Elementary functions of [`Interval`]: every bound is a proven bound of the function
//! at an endpoint (or at an extremum), from one of two sources:
//! * MPFR evaluated with directed rounding ([`super::mpfr_eval`]): tightest;
//! * the Taylor path ([`super::taylor`]) for `sin`, `cos`, `tan` (`|x| ≤ 2^19`) and `exp`
//!   (`|x| ≤ 700`): argument reduction with error-free transformations, Horner in plain
//!   f64 and an a-priori bound on every rounding error and on the Lagrange remainder
//!   (derived in `taylor`), a few ulps wide, 40–100× faster than MPFR.
//!
//! Which endpoint gives which bound comes from the monotonicity of the function; for
//! sin/cos/tan, from which multiples of π/2 the argument may contain
//! (`cases::half_pi_multiples`), decided from rigorous enclosures of the
//! reduced arguments (never from a rounded comparison with an approximation of π).

use rug::float::Round;
use rug::Float;
use std::cmp::Ordering;

use super::cases::{
    atan2_plan, half_pi_multiples, reduce_half_pi_mpfr, Atan2Bound, Atan2Plan, COS_MAX, COS_MIN,
    SIN_MAX, SIN_MIN, TAN_POLE,
};
use super::mpfr_eval::{atan2_f64, eval_f64, HALF_PI_DOWN, HALF_PI_UP, PI_DOWN, PI_UP};
use super::taylor::{
    exp_point, reduce_half_pi, sin_cos_reduced, tan_reduced, EXP_FAST_MAX, TRIG_FAST_MAX,
};
use super::Interval;

/// A bound of `f` at `x` in direction `round`, by MPFR.
type MpfrFn = fn(&mut Float, Round) -> Ordering;

/// The position of an endpoint relative to the multiples of π/2: `x = kπ/2 + r`.
struct Reduced {
    /// Fast path: `k`, `r` and `ε_r ≥ |r − r_true|` ([`super::taylor::reduce_half_pi`]).
    fast: Option<(i64, f64, f64)>,
    /// `k` for the span computation when it came from MPFR (may exceed `i64`).
    k_big: Option<rug::Integer>,
    k_mod4: u32,
    r_may_be_le0: bool,
    r_may_be_ge0: bool,
}

fn reduce(x: f64) -> Reduced {
    if x.abs() <= TRIG_FAST_MAX {
        let (k, r, er) = reduce_half_pi(x);
        if r.abs() <= 0.8 {
            return Reduced {
                fast: Some((k, r, er)),
                k_big: None,
                k_mod4: k.rem_euclid(4) as u32,
                r_may_be_le0: r <= er,
                r_may_be_ge0: r >= -er,
            };
        }
    }
    let red = reduce_half_pi_mpfr(&Float::with_val(53, x));
    Reduced {
        fast: None,
        k_big: Some(red.k),
        k_mod4: red.k_mod4,
        r_may_be_le0: red.r_may_be_le0,
        r_may_be_ge0: red.r_may_be_ge0,
    }
}

/// The multiples-of-π/2 mask for `[a, b]`.
fn mask(ra: &Reduced, rb: &Reduced) -> u8 {
    let span = match (ra.fast, rb.fast) {
        (Some((ka, _, _)), Some((kb, _, _))) => (kb - ka).max(0) as u64,
        _ => {
            let big = |r: &Reduced| match (&r.k_big, r.fast) {
                (Some(k), _) => k.clone(),
                (None, Some((k, _, _))) => rug::Integer::from(k),
                (None, None) => rug::Integer::new(),
            };
            let d = big(rb) - big(ra);
            d.to_u64().unwrap_or(if d < 0 { 0 } else { u64::MAX })
        }
    };
    half_pi_multiples(ra.k_mod4, span, ra.r_may_be_le0, rb.r_may_be_ge0)
}

/// An enclosure of sin (`cosine = false`) or cos at one endpoint: the Taylor path when
/// `red` has one, else MPFR in both directions.
fn endpoint(x: f64, red: &Reduced, cosine: bool, slow: MpfrFn) -> Interval {
    match red.fast {
        Some((k, r, er)) => sin_cos_reduced(k, r, er, cosine),
        None => Interval::from_bounds(eval_f64(x, Round::Down, slow), eval_f64(x, Round::Up, slow)),
    }
}

fn sin_mpfr(t: &mut Float, r: Round) -> Ordering {
    t.sin_round(r)
}
fn cos_mpfr(t: &mut Float, r: Round) -> Ordering {
    t.cos_round(r)
}
fn tan_mpfr(t: &mut Float, r: Round) -> Ordering {
    t.tan_round(r)
}
fn exp_mpfr(t: &mut Float, r: Round) -> Ordering {
    t.exp_round(r)
}

impl Interval {
    /// Shared body of sin and cos: the bounds are ±1 where the argument may contain an
    /// extremum (`max_bit`/`min_bit` of the multiples mask), else the hull of the
    /// endpoint enclosures.
    fn sin_or_cos(&self, max_bit: u8, min_bit: u8, cosine: bool, slow: MpfrFn) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let (a, b) = (self.lo(), self.hi());
        if !self.is_bounded() || b - a >= 7.0 {
            return Interval::from_neg_lo_hi(1.0, 1.0);
        }
        let (ra, rb) = (reduce(a), reduce(b));
        let m = mask(&ra, &rb);
        if m & max_bit != 0 && m & min_bit != 0 {
            return Interval::from_neg_lo_hi(1.0, 1.0);
        }
        let ea = endpoint(a, &ra, cosine, slow);
        let eb = if a == b {
            ea
        } else {
            endpoint(b, &rb, cosine, slow)
        };
        let hull = ea.hull(&eb);
        let neg_lo = if m & min_bit != 0 { 1.0 } else { hull.neg_lo() };
        let hi = if m & max_bit != 0 { 1.0 } else { hull.hi() };
        Interval::from_neg_lo_hi(neg_lo, hi)
    }

    /// `sin`: extrema +1 at `π/2 + 2jπ`, −1 at `−π/2 + 2jπ` (inclusion decided by
    /// `cases::half_pi_multiples` from enclosures of the reduced endpoints),
    /// else the hull of the endpoint values. Endpoints: Taylor path for `|x| ≤ 2^19`
    /// (a few ulps wide), MPFR otherwise (tightest). Unbounded or width ≥ 7 > 2π:
    /// `[−1, 1]`.
    pub fn sin(&self) -> Interval {
        self.sin_or_cos(SIN_MAX, SIN_MIN, false, sin_mpfr)
    }

    /// `cos`: extrema +1 at `2jπ`, −1 at `π + 2jπ`; otherwise as [`Interval::sin`].
    pub fn cos(&self) -> Interval {
        self.sin_or_cos(COS_MAX, COS_MIN, true, cos_mpfr)
    }

    /// `tan`: the whole line if the argument may contain a pole `π/2 + jπ` (or is
    /// unbounded); else tan is increasing and the bounds are the endpoint enclosures
    /// (Taylor path `sin/cos` in interval arithmetic for `|x| ≤ 2^19` unless the cosine
    /// enclosure touches 0; MPFR otherwise, tightest).
    pub fn tan(&self) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let (a, b) = (self.lo(), self.hi());
        if !self.is_bounded() || b - a >= 4.0 {
            return Interval::ENTIRE;
        }
        let (ra, rb) = (reduce(a), reduce(b));
        if mask(&ra, &rb) & TAN_POLE != 0 {
            return Interval::ENTIRE;
        }
        let at = |x: f64, red: &Reduced| -> Interval {
            red.fast
                .and_then(|(k, r, er)| tan_reduced(k, r, er))
                .unwrap_or_else(|| {
                    Interval::from_bounds(
                        eval_f64(x, Round::Down, tan_mpfr),
                        eval_f64(x, Round::Up, tan_mpfr),
                    )
                })
        };
        let lo = at(a, &ra).lo();
        let hi = if a == b {
            at(a, &ra).hi()
        } else {
            at(b, &rb).hi()
        };
        Interval::from_neg_lo_hi(-lo, hi)
    }

    /// `exp`, increasing: `[exp(lo)↓, exp(hi)↑]`. Endpoints with `|x| ≤ 700` use the
    /// Taylor path (a few ulps wide), others MPFR (tightest; `exp(−∞) = 0`).
    pub fn exp(&self) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let at = |x: f64, round: Round| -> f64 {
            if x.abs() <= EXP_FAST_MAX {
                let e = exp_point(x);
                if round == Round::Down {
                    e.lo().max(0.0)
                } else {
                    e.hi()
                }
            } else {
                eval_f64(x, round, exp_mpfr)
            }
        };
        Interval::from_neg_lo_hi(-at(self.lo(), Round::Down), at(self.hi(), Round::Up))
    }

    /// Natural logarithm, increasing on `(0, ∞)`, tightest (MPFR). The part of the
    /// argument `≤ 0` is dropped (IEEE 1788): `ln([0, 1]) = [−∞, 0]`, `ln([−2, 0])` is
    /// EMPTY.
    pub fn ln(&self) -> Interval {
        if self.is_empty() || self.hi() <= 0.0 {
            return Interval::EMPTY;
        }
        let lo = if self.lo() <= 0.0 {
            f64::NEG_INFINITY
        } else {
            eval_f64(self.lo(), Round::Down, |t, r| t.ln_round(r))
        };
        let hi = eval_f64(self.hi(), Round::Up, |t, r| t.ln_round(r));
        Interval::from_neg_lo_hi(-lo, hi)
    }

    /// `sinh`, increasing, tightest (MPFR).
    pub fn sinh(&self) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let lo = eval_f64(self.lo(), Round::Down, |t, r| t.sinh_round(r));
        let hi = eval_f64(self.hi(), Round::Up, |t, r| t.sinh_round(r));
        Interval::from_neg_lo_hi(-lo, hi)
    }

    /// `cosh`, even, decreasing then increasing with its minimum 1 at 0:
    /// `[cosh(mig)↓, cosh(mag)↑]`, tightest (MPFR).
    pub fn cosh(&self) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let lo = eval_f64(self.mig(), Round::Down, |t, r| t.cosh_round(r));
        let hi = eval_f64(self.mag(), Round::Up, |t, r| t.cosh_round(r));
        Interval::from_neg_lo_hi(-lo, hi)
    }

    /// `atan2(self, x)`: the angle in `(−π, π]` of the points `(x, y)` of the box
    /// `x × self` other than the origin (IEEE 1788 `atan2`), tightest. The case
    /// analysis (`cases::atan2_plan`: branch cut on the negative x-axis, where
    /// the angle is π; the origin dropped) picks corners, evaluated by MPFR with
    /// directed rounding, or the constants ±π, ±π/2, 0 rounded outward. EMPTY if either
    /// operand is empty or the box is the origin.
    pub fn atan2(&self, x: &Interval) -> Interval {
        if self.is_empty() || x.is_empty() {
            return Interval::EMPTY;
        }
        let sign = |v: f64| v.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
        let (c, d, a, b) = (self.lo(), self.hi(), x.lo(), x.hi());
        let bound = |bd: Atan2Bound, round: Round| -> f64 {
            let up = round == Round::Up;
            match bd {
                Atan2Bound::Corner { y_hi, x_hi } => {
                    atan2_f64(if y_hi { d } else { c }, if x_hi { b } else { a }, round)
                }
                Atan2Bound::NegPi => {
                    if up {
                        -PI_DOWN
                    } else {
                        -PI_UP
                    }
                }
                Atan2Bound::NegHalfPi => {
                    if up {
                        -HALF_PI_DOWN
                    } else {
                        -HALF_PI_UP
                    }
                }
                Atan2Bound::Zero => 0.0,
                Atan2Bound::HalfPi => {
                    if up {
                        HALF_PI_UP
                    } else {
                        HALF_PI_DOWN
                    }
                }
                Atan2Bound::Pi => {
                    if up {
                        PI_UP
                    } else {
                        PI_DOWN
                    }
                }
            }
        };
        match atan2_plan(sign(c), sign(d), sign(a), sign(b)) {
            Atan2Plan::Empty => Interval::EMPTY,
            Atan2Plan::Range(lo, hi) => {
                Interval::from_neg_lo_hi(-bound(lo, Round::Down), bound(hi, Round::Up))
            }
        }
    }
}
