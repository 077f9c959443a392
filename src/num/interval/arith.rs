//! The four operations, negation, square, square root, reciprocal and integer powers
//! of [`Interval`]: tightest results (powi: see its note), computed on the stored
//! `(−lo, hi)` pair with the upward-rounded primitives of [`super::directed`].

#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
use super::directed::fma_detected;
use super::directed::{
    add_up, div_up, div_up_k, mul_up, mul_up_k, sqrt_down_k, sqrt_up_k, STATIC_FMA,
};
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

    /// `self^n` for an integer `n` (IEEE 1788 `pown`; `x^0 = 1`, negative `n` divides,
    /// dropping `x = 0`: `[0, 0]^-1` is EMPTY, `[-1, 1]^-1` is the whole line).
    /// Monotonicity: even `n > 0` gives `[mig^n, mag^n]`, odd `n > 0` is increasing,
    /// `n < 0` even gives `[mag^n, mig^n]`, odd is decreasing on each side of 0.
    /// Exponents 0, ±1, 2 are tightest; otherwise each endpoint power is computed by
    /// `directed_pow`: binary powering with every product rounded in the direction
    /// that keeps the bound (and one directed division for `n < 0`) — within about
    /// `2|n|` ulps, NOT tightest — or MPFR (tightest) when an intermediate could leave
    /// the normal range.
    pub fn powi(&self, n: i32) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        match n {
            0 => return Interval::ONE,
            1 => return *self,
            2 => return self.sqr(),
            -1 => return self.recip(),
            _ => {}
        }
        let (lo, hi) = (self.lo(), self.hi());
        let class = self.sign_class();
        let (lo_b, hi_b) = if n > 0 {
            if n % 2 == 0 {
                (
                    directed_pow(self.mig(), n, false),
                    directed_pow(self.mag(), n, true),
                )
            } else {
                (directed_pow(lo, n, false), directed_pow(hi, n, true))
            }
        } else if class == Sign::Zero {
            return Interval::EMPTY;
        } else if n % 2 == 0 {
            (
                directed_pow(self.mag(), n, false),
                directed_pow(self.mig(), n, true),
            )
        } else {
            match class {
                Sign::Mixed => return Interval::ENTIRE,
                Sign::Pos => {
                    let hi_b = if lo == 0.0 {
                        f64::INFINITY
                    } else {
                        directed_pow(lo, n, true)
                    };
                    (directed_pow(hi, n, false), hi_b)
                }
                _ => {
                    let lo_b = if hi == 0.0 {
                        f64::NEG_INFINITY
                    } else {
                        directed_pow(hi, n, false)
                    };
                    (lo_b, directed_pow(lo, n, true))
                }
            }
        };
        Interval::from_neg_lo_hi(-lo_b, hi_b)
    }
}

/// `x^n` rounded up (`up`) or down to a double, for `|n| ≥ 2` (for `n < 0`, `x ≠ 0`).
/// Fast path when `x` is normal and `(|e| + 1)·|n| ≤ 960` (`e` its binary exponent), so
/// every intermediate power stays in the normal range: `|x|^|n|` by binary powering with
/// each product of non-negative factors rounded in one direction (a bound in that
/// direction), the sign `sign(x)^n` and, for `n < 0`, one directed division `1/·` with
/// the opposite-direction power. Otherwise MPFR's correctly rounded `pow` (with its
/// IEEE special values for 0 and ∞).
pub(crate) fn directed_pow(x: f64, n: i32, up: bool) -> f64 {
    let m = n.unsigned_abs();
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i64;
    let e = (biased - 1023).unsigned_abs();
    if biased == 0 || biased == 0x7ff || (e + 1) * u64::from(m) > 960 {
        let mut f = rug::Float::with_val(53, x);
        let round = if up {
            rug::float::Round::Up
        } else {
            rug::float::Round::Down
        };
        rug::ops::PowAssignRound::pow_assign_round(&mut f, n, round);
        return f.to_f64_round(round);
    }
    let negative = x < 0.0 && m % 2 == 1;
    // Direction for |x|^n: if the result is negative, its upper bound needs |·| rounded down.
    let abs_up = up != negative;
    let a = x.abs();
    let mag = if n > 0 {
        if abs_up {
            pow_up_abs(a, m)
        } else {
            -pow_up_neg(a, m)
        }
    } else if abs_up {
        div_up(1.0, -pow_up_neg(a, m))
    } else {
        -div_up(-1.0, pow_up_abs(a, m))
    };
    if negative {
        -mag
    } else {
        mag
    }
}

/// `x^m` rounded up for `x ≥ 0` (binary powering; every product of non-negative factors
/// rounded up, so the result bounds the exact power from above).
fn pow_up_abs(x: f64, m: u32) -> f64 {
    let mut result = 1.0;
    let mut base = x;
    let mut e = m;
    while e > 0 {
        if e & 1 == 1 {
            result = mul_up(result, base);
        }
        e >>= 1;
        if e > 0 {
            base = mul_up(base, base);
        }
    }
    result
}

/// `−(x^m rounded down)` for `x ≥ 0`: binary powering with every product rounded down
/// (`RD(p·q) = −RU(−p·q)`), negated at the end.
fn pow_up_neg(x: f64, m: u32) -> f64 {
    let mut result = 1.0;
    let mut base = x;
    let mut e = m;
    while e > 0 {
        if e & 1 == 1 {
            result = -mul_up(-result, base);
        }
        e >>= 1;
        if e > 0 {
            base = -mul_up(-base, base);
        }
    }
    -result
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
