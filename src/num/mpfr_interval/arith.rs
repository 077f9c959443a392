//! Arithmetic of [`MpfrInterval`]: the same case tables as [`crate::num::Interval`]
//! (see [`crate::num::Interval::mul`] and [`crate::num::Interval::div`]), each bound one
//! MPFR operation rounded down (lower) or up (upper) at the result precision
//! `max(p_self, p_rhs)` — tightest.

use rug::ops::Pow;
use rug::Float;

use super::{rd, ru, MpfrInterval};
use crate::num::interval::Sign;

/// `x·y` rounded down/up, with `0·∞ = 0` (the interval convention; MPFR would give NaN).
fn mul_d(p: u32, x: &Float, y: &Float) -> Float {
    if x.is_zero() || y.is_zero() {
        Float::new(p)
    } else {
        rd(p, x * y)
    }
}
fn mul_u(p: u32, x: &Float, y: &Float) -> Float {
    if x.is_zero() || y.is_zero() {
        Float::new(p)
    } else {
        ru(p, x * y)
    }
}

fn inf(p: u32, positive: bool) -> Float {
    Float::with_val(
        p,
        if positive {
            f64::INFINITY
        } else {
            f64::NEG_INFINITY
        },
    )
}

impl MpfrInterval {
    pub(crate) fn sign_class(&self) -> Sign {
        if self.lo >= 0 {
            if self.hi == 0 {
                Sign::Zero
            } else {
                Sign::Pos
            }
        } else if self.hi <= 0 {
            Sign::Neg
        } else {
            Sign::Mixed
        }
    }

    fn result_prec(&self, rhs: &MpfrInterval) -> u32 {
        self.prec().max(rhs.prec())
    }

    /// `self + rhs`, tightest at the result precision.
    pub fn add(&self, rhs: &MpfrInterval) -> MpfrInterval {
        let p = self.result_prec(rhs);
        if self.is_empty() || rhs.is_empty() {
            return MpfrInterval::empty(p);
        }
        MpfrInterval::from_floats(rd(p, &self.lo + &rhs.lo), ru(p, &self.hi + &rhs.hi))
    }

    /// `self − rhs`, tightest at the result precision.
    pub fn sub(&self, rhs: &MpfrInterval) -> MpfrInterval {
        let p = self.result_prec(rhs);
        if self.is_empty() || rhs.is_empty() {
            return MpfrInterval::empty(p);
        }
        MpfrInterval::from_floats(rd(p, &self.lo - &rhs.hi), ru(p, &self.hi - &rhs.lo))
    }

    /// `−self` (exact).
    pub fn neg(&self) -> MpfrInterval {
        if self.is_empty() {
            return self.clone();
        }
        MpfrInterval::from_floats(
            Float::with_val(self.prec(), -&self.hi),
            Float::with_val(self.prec(), -&self.lo),
        )
    }

    /// `self · rhs`, tightest (table of [`crate::num::Interval::mul`]).
    pub fn mul(&self, rhs: &MpfrInterval) -> MpfrInterval {
        use Sign::*;
        let p = self.result_prec(rhs);
        if self.is_empty() || rhs.is_empty() {
            return MpfrInterval::empty(p);
        }
        let (a, b, c, d) = (&self.lo, &self.hi, &rhs.lo, &rhs.hi);
        let (lo, hi) = match (self.sign_class(), rhs.sign_class()) {
            (Zero, _) | (_, Zero) => (Float::new(p), Float::new(p)),
            (Pos, Pos) => (mul_d(p, a, c), mul_u(p, b, d)),
            (Pos, Mixed) => (mul_d(p, b, c), mul_u(p, b, d)),
            (Pos, Neg) => (mul_d(p, b, c), mul_u(p, a, d)),
            (Mixed, Pos) => (mul_d(p, a, d), mul_u(p, b, d)),
            (Mixed, Mixed) => (
                mul_d(p, a, d).min(&mul_d(p, b, c)),
                mul_u(p, a, c).max(&mul_u(p, b, d)),
            ),
            (Mixed, Neg) => (mul_d(p, b, c), mul_u(p, a, c)),
            (Neg, Pos) => (mul_d(p, a, d), mul_u(p, b, c)),
            (Neg, Mixed) => (mul_d(p, a, d), mul_u(p, a, c)),
            (Neg, Neg) => (mul_d(p, b, d), mul_u(p, a, c)),
        };
        MpfrInterval::from_floats(lo, hi)
    }

    /// `self / rhs`, tightest, with the set semantics and table of
    /// [`crate::num::Interval::div`] (`x / [0, 0]` is EMPTY, a divisor with 0 inside
    /// gives the whole line).
    pub fn div(&self, rhs: &MpfrInterval) -> MpfrInterval {
        use Sign::*;
        let p = self.result_prec(rhs);
        if self.is_empty() || rhs.is_empty() || rhs.sign_class() == Zero {
            return MpfrInterval::empty(p);
        }
        let x = self.sign_class();
        if x == Zero {
            return MpfrInterval::from_floats(Float::new(p), Float::new(p));
        }
        let (a, b, c, d) = (&self.lo, &self.hi, &rhs.lo, &rhs.hi);
        let dd = |u: &Float, v: &Float| rd(p, u / v);
        let du = |u: &Float, v: &Float| ru(p, u / v);
        let (lo, hi) = if *c > 0 {
            match x {
                Pos => (dd(a, d), du(b, c)),
                Mixed => (dd(a, c), du(b, c)),
                _ => (dd(a, c), du(b, d)),
            }
        } else if *d < 0 {
            match x {
                Pos => (dd(b, d), du(a, c)),
                Mixed => (dd(b, d), du(a, d)),
                _ => (dd(b, c), du(a, d)),
            }
        } else if c.is_zero() {
            match x {
                Pos => (dd(a, d), inf(p, true)),
                Mixed => return MpfrInterval::entire(p),
                _ => (inf(p, false), du(b, d)),
            }
        } else if d.is_zero() {
            match x {
                Pos => (inf(p, false), du(a, c)),
                Mixed => return MpfrInterval::entire(p),
                _ => (dd(b, c), inf(p, true)),
            }
        } else {
            return MpfrInterval::entire(p);
        };
        MpfrInterval::from_floats(lo, hi)
    }

    /// `1 / self` (set semantics of [`MpfrInterval::div`]).
    pub fn recip(&self) -> MpfrInterval {
        MpfrInterval::point(1.0, self.prec()).div(self)
    }

    /// `self²`, tightest: `[mig², mag²]`.
    pub fn sqr(&self) -> MpfrInterval {
        let p = self.prec();
        if self.is_empty() {
            return self.clone();
        }
        let (a, b) = (&self.lo, &self.hi);
        match self.sign_class() {
            Sign::Zero => MpfrInterval::from_floats(Float::new(p), Float::new(p)),
            Sign::Pos => MpfrInterval::from_floats(rd(p, a.square_ref()), ru(p, b.square_ref())),
            Sign::Neg => MpfrInterval::from_floats(rd(p, b.square_ref()), ru(p, a.square_ref())),
            Sign::Mixed => {
                let m = if -a.clone() > *b { a } else { b };
                MpfrInterval::from_floats(Float::new(p), ru(p, m.square_ref()))
            }
        }
    }

    /// `√self`, tightest; the part below 0 is dropped (entirely below 0: EMPTY).
    pub fn sqrt(&self) -> MpfrInterval {
        let p = self.prec();
        if self.is_empty() || self.hi < 0 {
            return MpfrInterval::empty(p);
        }
        let lo = if self.lo <= 0 {
            Float::new(p)
        } else {
            rd(p, self.lo.sqrt_ref())
        };
        MpfrInterval::from_floats(lo, ru(p, self.hi.sqrt_ref()))
    }

    /// `|self|` (exact).
    pub fn abs(&self) -> MpfrInterval {
        let p = self.prec();
        match self.sign_class() {
            _ if self.is_empty() => self.clone(),
            Sign::Zero | Sign::Pos => self.clone(),
            Sign::Neg => self.neg(),
            Sign::Mixed => MpfrInterval::from_floats(Float::new(p), self.mag_float()),
        }
    }

    /// `self^n` (IEEE 1788 `pown`, semantics of [`crate::num::Interval::powi`]),
    /// tightest: each bound is one MPFR `pow` with an integer exponent, rounded
    /// outward, at an endpoint chosen by monotonicity (even `n`: of `|x|`).
    pub fn powi(&self, n: i32) -> MpfrInterval {
        let p = self.prec();
        if self.is_empty() {
            return self.clone();
        }
        let pd = |x: &Float| rd(p, x.pow(n));
        let pu = |x: &Float| ru(p, x.pow(n));
        let class = self.sign_class();
        if n == 0 {
            return MpfrInterval::point(1.0, p);
        }
        if n > 0 {
            return if n % 2 == 0 {
                MpfrInterval::from_floats(pd(&self.mig_float()), pu(&self.mag_float()))
            } else {
                MpfrInterval::from_floats(pd(&self.lo), pu(&self.hi))
            };
        }
        if class == Sign::Zero {
            return MpfrInterval::empty(p);
        }
        if n % 2 == 0 {
            // 1/|x|^|n|: decreasing in |x| (mig = 0 gives +∞).
            return MpfrInterval::from_floats(pd(&self.mag_float()), pu(&self.mig_float()));
        }
        match class {
            Sign::Mixed => MpfrInterval::entire(p),
            Sign::Pos => {
                let hi = if self.lo.is_zero() {
                    inf(p, true)
                } else {
                    pu(&self.lo)
                };
                MpfrInterval::from_floats(pd(&self.hi), hi)
            }
            _ => {
                let lo = if self.hi.is_zero() {
                    inf(p, false)
                } else {
                    pd(&self.hi)
                };
                MpfrInterval::from_floats(lo, pu(&self.lo))
            }
        }
    }
}
