//! The four operations, negation, square, square root and reciprocal of [`Interval`]:
//! tightest results, computed on the stored
//! `(−lo, hi)` pair with the upward-rounded primitives of [`super::directed`].

#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
use super::directed::fma_detected;
use super::directed::{add_up, div_up_k, mul_up_k, sqrt_down_k, sqrt_up_k, STATIC_FMA};
use super::Interval;

/// Sign class of a non-empty interval other than `[0, 0]`, for the case tables.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Sign {
    /// `[0, 0]`.
    Zero,
    /// `lo ≥ 0 < hi`.
    Pos,
    /// `lo < 0 ≥ hi`.
    Neg,
    /// `lo < 0 < hi`.
    Mixed,
}

impl Interval {
    #[inline]
    pub(crate) fn sign_class(&self) -> Sign {
        let (lo, hi) = (self.lo(), self.hi());
        if lo >= 0.0 {
            if hi == 0.0 {
                Sign::Zero
            } else {
                Sign::Pos
            }
        } else if hi <= 0.0 {
            Sign::Neg
        } else {
            Sign::Mixed
        }
    }

    /// `self + rhs`, tightest: `−lo = RU(−a_lo + −b_lo)`, `hi = RU(a_hi + b_hi)`.
    #[inline]
    pub fn add(&self, rhs: &Interval) -> Interval {
        if self.is_empty() || rhs.is_empty() {
            return Interval::EMPTY;
        }
        Interval::from_neg_lo_hi(
            add_up(self.neg_lo(), rhs.neg_lo()),
            add_up(self.hi(), rhs.hi()),
        )
    }

    /// `self − rhs`, tightest: `−lo = RU(−a_lo + b_hi)`, `hi = RU(a_hi + −b_lo)`.
    #[inline]
    pub fn sub(&self, rhs: &Interval) -> Interval {
        if self.is_empty() || rhs.is_empty() {
            return Interval::EMPTY;
        }
        Interval::from_neg_lo_hi(
            add_up(self.neg_lo(), rhs.hi()),
            add_up(self.hi(), rhs.neg_lo()),
        )
    }

    /// `−self` (exact).
    #[inline]
    pub fn neg(&self) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        Interval::from_neg_lo_hi(self.hi(), self.neg_lo())
    }

    /// `self · rhs`, tightest. Sign-case table for `[a, b]·[c, d]` (P: `a ≥ 0`,
    /// N: `b ≤ 0`, M: `a < 0 < b`, Z: `[0, 0]`; Z times anything non-empty is `[0, 0]`):
    ///
    /// | × | P | M | N |
    /// |---|---|---|---|
    /// | P | `[ac, bd]` | `[bc, bd]` | `[bc, ad]` |
    /// | M | `[ad, bd]` | `[min(ad, bc), max(ac, bd)]` | `[bc, ac]` |
    /// | N | `[ad, bc]` | `[ad, ac]` | `[bd, ac]` |
    ///
    /// Each lower product `xy` is rounded down as `−RU((−x)·y)`; no entry multiplies a
    /// zero bound by an infinite one (and `mul_up` returns 0 for `0·∞` anyway).
    #[inline]
    pub fn mul(&self, rhs: &Interval) -> Interval {
        #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
        if fma_detected() {
            // SAFETY: the CPU supports FMA (run-time detection).
            return unsafe { mul_fma(self, rhs) };
        }
        self.mul_impl::<STATIC_FMA>(rhs)
    }

    #[inline(always)]
    pub(crate) fn mul_impl<const FMA: bool>(&self, rhs: &Interval) -> Interval {
        use Sign::*;
        if self.is_empty() || rhs.is_empty() {
            return Interval::EMPTY;
        }
        let (na, b) = (self.neg_lo(), self.hi());
        let (nc, d) = (rhs.neg_lo(), rhs.hi());
        let (a, c) = (-na, -nc);
        let (neg_lo, hi) = match (self.sign_class(), rhs.sign_class()) {
            (Zero, _) | (_, Zero) => return Interval::ZERO,
            (Pos, Pos) => (mul_up_k::<FMA>(na, c), mul_up_k::<FMA>(b, d)),
            (Pos, Mixed) => (mul_up_k::<FMA>(b, nc), mul_up_k::<FMA>(b, d)),
            (Pos, Neg) => (mul_up_k::<FMA>(b, nc), mul_up_k::<FMA>(a, d)),
            (Mixed, Pos) => (mul_up_k::<FMA>(na, d), mul_up_k::<FMA>(b, d)),
            (Mixed, Mixed) => (
                mul_up_k::<FMA>(na, d).max(mul_up_k::<FMA>(b, nc)),
                mul_up_k::<FMA>(na, nc).max(mul_up_k::<FMA>(b, d)),
            ),
            (Mixed, Neg) => (mul_up_k::<FMA>(b, nc), mul_up_k::<FMA>(na, nc)),
            (Neg, Pos) => (mul_up_k::<FMA>(na, d), mul_up_k::<FMA>(b, c)),
            (Neg, Mixed) => (mul_up_k::<FMA>(na, d), mul_up_k::<FMA>(na, nc)),
            (Neg, Neg) => (mul_up_k::<FMA>(-b, d), mul_up_k::<FMA>(na, nc)),
        };
        Interval::from_neg_lo_hi(neg_lo, hi)
    }

    /// `self / rhs`, tightest, with IEEE 1788 set semantics: the result encloses
    /// `{x/y : x ∈ self, y ∈ rhs, y ≠ 0}`. Hence `x / [0, 0]` is EMPTY, a divisor with 0
    /// in its interior gives the whole line (unless `self = [0, 0]`), and a divisor
    /// `[0, d]` or `[c, 0]` gives a half-line. Case table for `[a, b]/[c, d]`
    /// (classes as in [`Interval::mul`]):
    ///
    /// | ÷ | `c > 0` | `d < 0` | `[0, d]` | `[c, 0]` | `c < 0 < d` |
    /// |---|---|---|---|---|---|
    /// | P | `[a/d, b/c]` | `[b/d, a/c]` | `[a/d, +∞]` | `[−∞, a/c]` | ℝ |
    /// | M | `[a/c, b/c]` | `[b/d, a/d]` | ℝ | ℝ | ℝ |
    /// | N | `[a/c, b/d]` | `[b/c, a/d]` | `[−∞, b/d]` | `[b/c, +∞]` | ℝ |
    ///
    /// (`a/d` with `a = 0` is 0; no entry divides ∞ by ∞.) A certifier must treat a
    /// divisor that contains 0 as "undecided": the dropped points are poles.
    #[inline]
    pub fn div(&self, rhs: &Interval) -> Interval {
        #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
        if fma_detected() {
            // SAFETY: the CPU supports FMA (run-time detection).
            return unsafe { div_fma(self, rhs) };
        }
        self.div_impl::<STATIC_FMA>(rhs)
    }

    #[inline(always)]
    pub(crate) fn div_impl<const FMA: bool>(&self, rhs: &Interval) -> Interval {
        use Sign::*;
        if self.is_empty() || rhs.is_empty() {
            return Interval::EMPTY;
        }
        let (na, b) = (self.neg_lo(), self.hi());
        let (nc, d) = (rhs.neg_lo(), rhs.hi());
        let (a, c) = (-na, -nc);
        let x = self.sign_class();
        if rhs.sign_class() == Zero {
            return Interval::EMPTY;
        }
        if x == Zero {
            return Interval::ZERO;
        }
        let up = div_up_k::<FMA>;
        // Lower bounds are stored negated: RD(p/q) = −RU((−p)/q).
        let (neg_lo, hi) = if c > 0.0 {
            match x {
                Pos => (up(na, d), up(b, c)),
                Mixed => (up(na, c), up(b, c)),
                _ => (up(na, c), up(b, d)),
            }
        } else if d < 0.0 {
            match x {
                Pos => (up(-b, d), up(a, c)),
                Mixed => (up(-b, d), up(a, d)),
                _ => (up(-b, c), up(a, d)),
            }
        } else if c == 0.0 {
            // rhs = [0, d], d > 0.
            match x {
                Pos => (up(na, d), f64::INFINITY),
                Mixed => return Interval::ENTIRE,
                _ => (f64::INFINITY, up(b, d)),
            }
        } else if d == 0.0 {
            // rhs = [c, 0], c < 0.
            match x {
                Pos => (f64::INFINITY, up(a, c)),
                Mixed => return Interval::ENTIRE,
                _ => (up(-b, c), f64::INFINITY),
            }
        } else {
            return Interval::ENTIRE;
        };
        Interval::from_neg_lo_hi(neg_lo, hi)
    }

    /// `1 / self`, tightest, with the set semantics of [`Interval::div`].
    #[inline]
    pub fn recip(&self) -> Interval {
        Interval::ONE.div(self)
    }

    /// `self²`, tightest: `[mig², mag²]` (tighter than `self · self` when 0 ∈ self).
    #[inline]
    pub fn sqr(&self) -> Interval {
        #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
        if fma_detected() {
            // SAFETY: the CPU supports FMA (run-time detection).
            return unsafe { sqr_fma(self) };
        }
        self.sqr_impl::<STATIC_FMA>()
    }

    #[inline(always)]
    pub(crate) fn sqr_impl<const FMA: bool>(&self) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        let (na, b) = (self.neg_lo(), self.hi());
        match self.sign_class() {
            Sign::Zero => Interval::ZERO,
            Sign::Pos => Interval::from_neg_lo_hi(mul_up_k::<FMA>(na, -na), mul_up_k::<FMA>(b, b)),
            Sign::Neg => Interval::from_neg_lo_hi(mul_up_k::<FMA>(-b, b), mul_up_k::<FMA>(na, na)),
            Sign::Mixed => {
                Interval::from_neg_lo_hi(-0.0, mul_up_k::<FMA>(na, na).max(mul_up_k::<FMA>(b, b)))
            }
        }
    }

    /// `√self`, tightest; the part of `self` below 0 is dropped (IEEE 1788), so an
    /// interval entirely below 0 gives EMPTY. Bounds by [`super::directed::sqrt_down`] /
    /// [`super::directed::sqrt_up`].
    #[inline]
    pub fn sqrt(&self) -> Interval {
        #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
        if fma_detected() {
            // SAFETY: the CPU supports FMA (run-time detection).
            return unsafe { sqrt_fma(self) };
        }
        self.sqrt_impl::<STATIC_FMA>()
    }

    #[inline(always)]
    pub(crate) fn sqrt_impl<const FMA: bool>(&self) -> Interval {
        if self.is_empty() || self.hi() < 0.0 {
            return Interval::EMPTY;
        }
        let lo = self.lo();
        let neg_lo = if lo <= 0.0 {
            -0.0
        } else {
            -sqrt_down_k::<FMA>(lo)
        };
        Interval::from_neg_lo_hi(neg_lo, sqrt_up_k::<FMA>(self.hi()))
    }

    /// `|self|`, tightest (exact).
    pub fn abs(&self) -> Interval {
        match self.sign_class() {
            _ if self.is_empty() => Interval::EMPTY,
            Sign::Zero | Sign::Pos => *self,
            Sign::Neg => self.neg(),
            Sign::Mixed => Interval::from_neg_lo_hi(-0.0, self.neg_lo().max(self.hi())),
        }
    }
}

/// FMA-compiled copies of the hot operations, run when the CPU has FMA but the build
/// does not assume it (x86-64 without `+fma`): the same code with the one-instruction
/// error term.
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
mod fma_copies {
    use super::Interval;

    #[target_feature(enable = "fma")]
    pub(super) unsafe fn mul_fma(x: &Interval, y: &Interval) -> Interval {
        x.mul_impl::<true>(y)
    }
    #[target_feature(enable = "fma")]
    pub(super) unsafe fn div_fma(x: &Interval, y: &Interval) -> Interval {
        x.div_impl::<true>(y)
    }
    #[target_feature(enable = "fma")]
    pub(super) unsafe fn sqr_fma(x: &Interval) -> Interval {
        x.sqr_impl::<true>()
    }
    #[target_feature(enable = "fma")]
    pub(super) unsafe fn sqrt_fma(x: &Interval) -> Interval {
        x.sqrt_impl::<true>()
    }
}
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
use fma_copies::{div_fma, mul_fma, sqr_fma, sqrt_fma};
