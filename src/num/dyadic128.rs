//! 128-bit exact dyadic numbers `±m·2^e` (`m < 2¹²⁸`): the first, cheapest attempt of
//! the integer tier of the linear kernel (`Arithmetic::Integer`; see [`super::dyadic`]
//! for the principle and the wider fallback). Each operation is a few native 128-bit
//! integer instructions: a product is `checked_mul` of the integers, a sum shifts the
//! operand with the larger exponent left when the result provably stays below 2¹²⁸.
//! Exactly degenerate configurations given by short dyadic data (small integers,
//! `k/8`, powers of two) stay far inside 128 bits even in the degree-11 tests of the
//! kernel; anything that would not fit poisons ([`Poison`]) instead of wrapping, and
//! the tier escalates. Canonical like [`Dyadic`]: `m` odd, zero as `(0, 0, +)`.

use std::cmp::Ordering;

use super::dyadic::{round_quotient_parts, scale, top, Dyadic};
use super::expansion::Poison;
use super::ring::Ring;
use super::round::Rounded;

/// An exact dyadic number `(−1)^neg · mag · 2^exp` with a 128-bit integer, stored as
/// two 64-bit halves (8-byte alignment keeps the value at 24 bytes; see `mag`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dyadic128 {
    lo: u64,
    hi: u64,
    exp: i32,
    neg: bool,
}

/// Exponents are kept within `±2³⁰` (far beyond any formula of the kernel: the degree
/// is at most 13 and input exponents are at least −1074), so no `i32` overflows.
const EXP_LIMIT: i64 = 1 << 30;

impl Dyadic128 {
    /// Zero.
    pub const ZERO: Self = Dyadic128 {
        lo: 0,
        hi: 0,
        exp: 0,
        neg: false,
    };

    /// The integer.
    #[inline(always)]
    fn mag(&self) -> u128 {
        u128::from(self.lo) | (u128::from(self.hi) << 64)
    }

    #[inline(always)]
    fn is_zero(&self) -> bool {
        self.lo | self.hi == 0
    }

    #[cold]
    fn overflow() -> Self {
        Poison::set();
        Self::ZERO
    }

    /// The double `x`, exactly (a non-finite `x` poisons).
    #[inline(always)]
    pub fn from_f64(x: f64) -> Self {
        let d = Dyadic::<2>::from_f64(x);
        let (neg, exp, m) = d.parts();
        Dyadic128 {
            lo: m.first().copied().unwrap_or(0),
            hi: 0,
            exp: exp as i32,
            neg,
        }
    }

    /// The exact sign.
    #[inline(always)]
    pub fn sign(&self) -> Ordering {
        if self.is_zero() {
            Ordering::Equal
        } else if self.neg {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }

    /// The bit length of the integer.
    pub fn bit_len(&self) -> u32 {
        128 - self.mag().leading_zeros()
    }

    /// The magnitude as normalised limbs.
    #[inline(always)]
    fn limbs(&self) -> ([u64; 2], usize) {
        let l = [self.lo, self.hi];
        let n = if l[1] != 0 { 2 } else { usize::from(l[0] != 0) };
        (l, n)
    }

    /// An approximation of the value (see [`Dyadic::estimate`]).
    pub fn estimate(&self) -> f64 {
        let (l, n) = self.limbs();
        if n == 0 {
            return 0.0;
        }
        let (f, k) = top(&l[..n]);
        let v = scale(f, k + i64::from(self.exp));
        if self.neg {
            -v
        } else {
            v
        }
    }

    /// `(−1)^neg · v · 2^exp`, canonical.
    #[inline(always)]
    fn make(neg: bool, exp: i64, v: u128) -> Self {
        if v == 0 {
            return Self::ZERO;
        }
        let tz = v.trailing_zeros();
        let m = v >> tz;
        Dyadic128 {
            lo: m as u64,
            hi: (m >> 64) as u64,
            exp: (exp + i64::from(tz)) as i32,
            neg,
        }
    }

    /// `self ± b` (`flip`: subtract). With `x` the operand of the larger exponent and
    /// `d` the exponent difference, the sum is `x·2^d ± y` at `y`'s exponent; both terms
    /// are required below 2¹²⁷, so the sum stays below 2¹²⁸.
    #[inline(always)]
    fn add_signed(&self, b: &Self, flip: bool) -> Self {
        let bneg = b.neg ^ flip;
        if b.is_zero() {
            return *self;
        }
        if self.is_zero() {
            return Dyadic128 { neg: bneg, ..*b };
        }
        let (x, xneg, y, yneg) = if self.exp >= b.exp {
            (self, self.neg, b, bneg)
        } else {
            (b, bneg, self, self.neg)
        };
        let d = i64::from(x.exp) - i64::from(y.exp);
        let (xm, ym) = (x.mag(), y.mag());
        if d >= i64::from(xm.leading_zeros()) || y.hi >> 63 != 0 {
            return Self::overflow();
        }
        let xv = xm << d;
        let yv = ym;
        let (neg, v) = if xneg == yneg {
            (xneg, xv + yv)
        } else if xv >= yv {
            (xneg, xv - yv)
        } else {
            (yneg, yv - xv)
        };
        Self::make(neg, i64::from(y.exp), v)
    }

    /// `p/q` correctly rounded (see [`super::dyadic::round_quotient`]). Fast path: a
    /// quotient by a power of two (`q`'s integer is 1, as for every whole value) with a
    /// numerator of at most 53 bits is the double `±m·2^(e_p − e_q)` when that lies in
    /// the normal range.
    #[inline]
    pub fn round_quotient(p: &Self, q: &Self) -> Option<Rounded> {
        if p.is_zero() {
            return if q.is_zero() {
                None
            } else {
                Some(Rounded::exact(0.0))
            };
        }
        if q.lo == 1 && q.hi == 0 && p.hi == 0 && p.lo < (1 << 53) {
            let e = i64::from(p.exp) - i64::from(q.exp);
            if (-1000..=900).contains(&e) {
                // m < 2⁵³ converts exactly; the power of two is exact and normal, and the
                // product lies in [2⁻¹⁰⁰⁰, 2⁹⁵³]: exact.
                let v = p.lo as f64 * f64::from_bits(((e + 1023) as u64) << 52);
                return Some(Rounded::exact(if p.neg != q.neg { -v } else { v }));
            }
        }
        let (pl, pn) = p.limbs();
        let (ql, qn) = q.limbs();
        // Two-limb operands: 8 limbs of scratch suffice (2·2 + 4).
        round_quotient_parts::<8>(
            (p.neg, i64::from(p.exp), &pl[..pn]),
            (q.neg, i64::from(q.exp), &ql[..qn]),
        )
    }
}

impl Ring for Dyadic128 {
    #[inline(always)]
    fn zero() -> Self {
        Self::ZERO
    }
    #[inline(always)]
    fn one() -> Self {
        Dyadic128 {
            lo: 1,
            hi: 0,
            exp: 0,
            neg: false,
        }
    }
    #[inline(always)]
    fn plus(&self, b: &Self) -> Self {
        self.add_signed(b, false)
    }
    #[inline(always)]
    fn minus(&self, b: &Self) -> Self {
        self.add_signed(b, true)
    }
    /// Exact: odd × odd is odd, so the product is canonical as computed.
    #[inline(always)]
    fn times(&self, b: &Self) -> Self {
        if self.is_zero() || b.is_zero() {
            return Self::ZERO;
        }
        let exp = i64::from(self.exp) + i64::from(b.exp);
        let v = if self.hi | b.hi == 0 {
            // 64 × 64 bits: never overflows 128.
            Some(u128::from(self.lo) * u128::from(b.lo))
        } else {
            self.mag().checked_mul(b.mag())
        };
        match v {
            Some(v) if exp.abs() < EXP_LIMIT => Dyadic128 {
                lo: v as u64,
                hi: (v >> 64) as u64,
                exp: exp as i32,
                neg: self.neg != b.neg,
            },
            _ => Self::overflow(),
        }
    }
    #[inline(always)]
    fn negate(&self) -> Self {
        Dyadic128 {
            neg: !self.neg && !self.is_zero(),
            ..*self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::round::round_rational;
    use rug::{Integer, Rational};

    fn exact(x: &Dyadic128) -> Rational {
        let mut r = Rational::from(Integer::from(x.mag()));
        if x.exp >= 0 {
            r <<= x.exp as u32;
        } else {
            r >>= x.exp.unsigned_abs();
        }
        if x.neg {
            -r
        } else {
            r
        }
    }

    #[test]
    fn exact_within_128_bits_and_poisoned_beyond() {
        Poison::reset();
        let mut seed = 0x5151_7A7A_0F0F_1234u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            // short dyadic data: k/8, |k| ≤ 64, scaled by 2^(−20..20)
            let k = (seed % 129) as f64 - 64.0;
            k / 8.0 * 2f64.powi(((seed >> 20) % 41) as i32 - 20)
        };
        for _ in 0..3000 {
            let v: Vec<f64> = (0..5).map(|_| next()).collect();
            let d: Vec<Dyadic128> = v.iter().map(|&x| Dyadic128::from_f64(x)).collect();
            let q: Vec<Rational> = v.iter().map(|&x| Rational::from_f64(x).unwrap()).collect();
            let x = d[0].times(&d[1]).minus(&d[2].times(&d[3])).plus(&d[4]);
            let t = q[0].clone() * &q[1] - q[2].clone() * &q[3] + &q[4];
            assert_eq!(exact(&x), t);
            assert_eq!(x.sign(), t.cmp0());
            assert_eq!(x, d[4].minus(&d[2].times(&d[3])).plus(&d[1].times(&d[0])));
            if !d[1].is_zero() {
                assert_eq!(
                    Dyadic128::round_quotient(&x, &d[1]),
                    Some(round_rational(&(t / &q[1])))
                );
            }
        }
        assert!(!Poison::is_set());
        // 2^100 + 2^-30: a 130-bit integer.
        let _ = Dyadic128::from_f64(2f64.powi(100)).plus(&Dyadic128::from_f64(2f64.powi(-30)));
        assert!(Poison::is_set());
        Poison::reset();
        let m = Dyadic128::from_f64((1u64 << 53) as f64 - 1.0);
        let m3 = m.times(&m);
        assert!(!Poison::is_set());
        let _ = m3.times(&m);
        assert!(Poison::is_set());
        Poison::reset();
    }
}
