//! f64 intervals with outward rounding (ARCHITECTURE.md "Numbers", docs/CERTIFICATES.md
//! "Escalation": the f64 interval stage).
//!
//! An [`Interval`] is a closed, connected set of reals `[lo, hi]` with double bounds
//! (`lo` may be −∞, `hi` may be +∞, and the empty set is an interval), with the set
//! semantics of IEEE 1788-2015: every operation returns an interval containing
//! `{ f(x) : x in the operands, f defined at x }`.
//!
//! # Accuracy policy
//!
//! Unless noted otherwise, operations return the **tightest** interval: the smallest
//! interval with double bounds containing the exact range (checked for equality against
//! the ITF1788 vectors in tests/itf1788.rs). This holds for `+ − × ÷`, `neg`, `sqr`,
//! `sqrt`, `recip`, `abs`, the set operations, and `ln sinh cosh atan2`, whose endpoint
//! values come from MPFR with directed rounding. Exceptions, noted at each function:
//! * `sin`, `cos`, `tan` (`|x| ≤ 2^19`) and `exp` (`|x| ≤ 700`) take the fast Taylor path
//!   (`taylor`: proven a-priori error bound, about 10× faster than MPFR): each endpoint
//!   bound is within a few ulps of the tightest (≤ 8 ulps wide for a point on the tests'
//!   samples); outside those ranges they use MPFR and are tightest;
//! * `powi(n)` for `|n| ≥ 3` is within about `2|n|` ulps (MPFR, tightest, when an
//!   intermediate power would leave the normal range).
//!
//! No operation depends on the FPU rounding mode or on target-cpu flags: directed
//! rounding comes from error-free transformations ([`directed`]); on x86-64 the hot
//! operations detect FMA at run time and use it when present.
//!
//! # Domain and emptiness (read this before writing a certifier)
//!
//! As in IEEE 1788, points where an operation is undefined are dropped: `sqrt([-4, 1]) =
//! [0, 1]`, `x / [0, 0]` and `sqrt([-2, -1])` are **empty**, `x / [-1, 1]` is the whole
//! line. An empty operand makes every result empty, and the empty set is a subset of
//! everything — so code that concludes "K(X) ⊆ X, hence a root exists" or "0 ∉ F(X),
//! hence no root" must first check [`Interval::is_empty`] on the values it tests.

mod arith;
mod cases;
pub mod directed;
mod elementary;
pub(crate) mod mpfr_eval;
pub(crate) mod ops;
mod powi;
mod real_impl;
mod set_ops;
mod taylor;
#[cfg(test)]
pub(crate) mod test_support;

pub(crate) use arith::Sign;
pub(crate) use cases::{
    atan2_plan, half_pi_multiples, reduce_half_pi_mpfr, Atan2Bound, Atan2Plan, COS_MAX, COS_MIN,
    SIN_MAX, SIN_MIN, TAN_POLE,
};

use rug::float::Round;
use rug::{Float, Rational};
use std::fmt;

use crate::error::GeomError;

/// A closed real interval with f64 bounds, outward rounded (module doc: accuracy policy,
/// emptiness).
#[derive(Clone, Copy, PartialEq)]
pub struct Interval {
    /// The NEGATED lower bound, `−lo`: storing `(−lo, hi)` lets both bounds be rounded
    /// up (`lo` rounded down is `−(−lo rounded up)`). Invariant for a non-empty
    /// interval: no NaN, `−neg_lo ≤ hi`, `neg_lo > −∞`, `hi > −∞`. The empty set is
    /// stored as `neg_lo = hi = −∞` (lo = +∞ > hi = −∞), so derived equality is set
    /// equality (`-0.0 == 0.0`).
    neg_lo: f64,
    hi: f64,
}

impl Interval {
    /// The empty set.
    pub const EMPTY: Interval = Interval {
        neg_lo: f64::NEG_INFINITY,
        hi: f64::NEG_INFINITY,
    };
    /// The whole real line `[−∞, +∞]`.
    pub const ENTIRE: Interval = Interval {
        neg_lo: f64::INFINITY,
        hi: f64::INFINITY,
    };
    /// `[0, 0]`.
    pub const ZERO: Interval = Interval {
        neg_lo: -0.0,
        hi: 0.0,
    };
    /// `[1, 1]`.
    pub const ONE: Interval = Interval {
        neg_lo: -1.0,
        hi: 1.0,
    };

    /// Build from stored fields (crate-internal; the caller keeps the invariant).
    #[inline]
    pub(crate) const fn from_neg_lo_hi(neg_lo: f64, hi: f64) -> Interval {
        Interval { neg_lo, hi }
    }

    /// `[lo, hi]` from user data: NaN, `lo > hi`, `lo = +∞` or `hi = −∞` is a typed
    /// error naming `field`.
    pub fn new(field: &str, lo: f64, hi: f64) -> Result<Interval, GeomError> {
        if lo.is_nan() || hi.is_nan() {
            return Err(GeomError::NonFinite {
                field: field.to_string(),
                value: format!("[{lo}, {hi}]"),
            });
        }
        if lo > hi || lo == f64::INFINITY || hi == f64::NEG_INFINITY {
            return Err(GeomError::EmptyDomain {
                field: field.to_string(),
                lo: format!("{lo}"),
                hi: format!("{hi}"),
            });
        }
        Ok(Interval { neg_lo: -lo, hi })
    }

    /// `[lo, hi]` for bounds the program computed itself. Never produces a wrong
    /// enclosure: a NaN bound or `lo > hi` (a bug in the caller, caught by a debug
    /// assertion) gives the whole line; `lo = +∞` is read as `f64::MAX` and
    /// `hi = −∞` as `−f64::MAX`.
    #[inline]
    pub fn from_bounds(lo: f64, hi: f64) -> Interval {
        debug_assert!(lo <= hi, "Interval::from_bounds({lo}, {hi})");
        if lo <= hi {
            Interval {
                neg_lo: -lo.min(f64::MAX),
                hi: hi.max(-f64::MAX),
            }
        } else {
            Interval::ENTIRE
        }
    }

    /// The point interval `[x, x]`. A NaN gives the whole line (the value is unknown)
    /// and `±∞` gives `[f64::MAX, +∞]` / `[−∞, −f64::MAX]` (a finite value too large to
    /// represent), so the result always encloses the intended real.
    #[inline]
    pub fn point(x: f64) -> Interval {
        if x.is_finite() {
            Interval { neg_lo: -x, hi: x }
        } else if x == f64::INFINITY {
            Interval {
                neg_lo: -f64::MAX,
                hi: f64::INFINITY,
            }
        } else if x == f64::NEG_INFINITY {
            Interval {
                neg_lo: f64::INFINITY,
                hi: -f64::MAX,
            }
        } else {
            Interval::ENTIRE
        }
    }

    /// The tightest interval containing the rational `q`: its bounds are `q` rounded
    /// down and up to doubles by MPFR (correctly rounded conversion), `[f64::MAX, +∞]`
    /// beyond the double range. Equal bounds iff `q` is a double.
    pub fn from_rational(q: &Rational) -> Interval {
        let (lo, _) = Float::with_val_round(53, q, Round::Down);
        let (hi, _) = Float::with_val_round(53, q, Round::Up);
        Interval {
            neg_lo: -lo.to_f64_round(Round::Down),
            hi: hi.to_f64_round(Round::Up),
        }
    }

    /// The tightest interval containing the MPFR number `x` (exact if it is a double).
    pub fn from_float(x: &Float) -> Interval {
        if x.is_nan() {
            return Interval::ENTIRE;
        }
        Interval::from_bounds(x.to_f64_round(Round::Down), x.to_f64_round(Round::Up))
    }

    /// The lower bound (`+∞` for the empty set).
    #[inline]
    pub fn lo(&self) -> f64 {
        -self.neg_lo
    }

    /// The upper bound (`−∞` for the empty set).
    #[inline]
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// The negated lower bound `−lo`, as stored.
    #[inline]
    pub(crate) fn neg_lo(&self) -> f64 {
        self.neg_lo
    }

    /// True for the empty set.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.hi == f64::NEG_INFINITY
    }

    /// True for the whole line.
    #[inline]
    pub fn is_entire(&self) -> bool {
        self.neg_lo == f64::INFINITY && self.hi == f64::INFINITY
    }

    /// True if both bounds are finite (false for the empty set).
    #[inline]
    pub fn is_bounded(&self) -> bool {
        self.neg_lo.is_finite() && self.hi.is_finite()
    }

    /// True for a single point `[x, x]`.
    #[inline]
    pub fn is_point(&self) -> bool {
        -self.neg_lo == self.hi
    }
}

impl fmt::Debug for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_empty() {
            write!(f, "[empty]")
        } else {
            write!(f, "[{:e}, {:e}]", self.lo(), self.hi())
        }
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

impl Default for Interval {
    /// `[0, 0]`, the additive identity.
    fn default() -> Self {
        Interval::ZERO
    }
}

impl From<f64> for Interval {
    /// [`Interval::point`].
    fn from(x: f64) -> Self {
        Interval::point(x)
    }
}

#[cfg(test)]
mod tests;
