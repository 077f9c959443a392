//! Fixed-width exact dyadic numbers `±m·2^e` (`m` an integer of at most `N` 64-bit
//! limbs, `e` a shared binary exponent): the integer tier of the linear kernel
//! (`Arithmetic::Integer`, between the double-double filter and the expansions).
//!
//! Why it is exact and cheap. A finite double is `m·2^e` with an integer `|m| < 2⁵³`, so
//! every polynomial in doubles is a dyadic number; a product multiplies the integers and
//! adds the exponents, a sum shifts the operand with the larger exponent left by the
//! exponent difference and adds the integers. All of this is exact integer arithmetic
//! as long as the integers fit `N` limbs, which holds while the exponent spread of the
//! data is moderate: a formula of degree `d` over doubles whose values lie within
//! `[2^lo, 2^hi]` and whose lowest set bits lie at or above `2^b` has integers of at most
//! `d·(hi − b) + log₂(#terms)` bits. Each value is stored canonically (`m` odd, no zero
//! top limb, zero as the empty integer), so equal values have equal representations.
//!
//! Overflow of the width (a formula whose integers need more than `64·N` bits, e.g. the
//! mixed magnitudes 1e±150, whose sums need ~1000-bit shifts) is never silent: it
//! poisons the computation ([`Poison`], shared with the expansion tier) and yields 0;
//! the caller discards the result and escalates. No operation allocates.
//!
//! [`round_quotient`] rounds a quotient of two such numbers correctly (to nearest, ties
//! to even) with exact residual tests, also without allocation.

use std::cmp::Ordering;

use super::expansion::Poison;
use super::limbs::{bit_len, cmp_scaled, mul_into, shr_in_place, signed_sum, trailing_zeros};
use super::ring::Ring;
use super::round::{next_down, next_up, Rounded};

/// The widest instance the rounding's scratch buffers are sized for.
pub const MAX_LIMBS: usize = 16;
/// Scratch for the rounding residual `P − c·Q` of the widest instance (`N + 1` limbs for
/// `c·Q`, aligned against `P`: at most `2N + 2` limbs, see [`round_quotient`]).
pub(crate) const SCRATCH: usize = 2 * MAX_LIMBS + 4;

/// An exact dyadic number `(−1)^neg · mag · 2^exp` of at most `N` limbs (canonical:
/// `mag` odd and normalised, zero with `len = 0`, `exp = 0`, `neg = false`).
#[derive(Clone, Copy)]
pub struct Dyadic<const N: usize> {
    mag: [u64; N],
    len: u32,
    neg: bool,
    exp: i32,
}

impl<const N: usize> std::fmt::Debug for Dyadic<N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "Dyadic({}{:x?}·2^{})",
            if self.neg { "-" } else { "" },
            self.limbs(),
            self.exp
        )
    }
}

/// Value equality (the representation is canonical).
impl<const N: usize> PartialEq for Dyadic<N> {
    #[inline(always)]
    fn eq(&self, o: &Self) -> bool {
        self.len == o.len && self.neg == o.neg && self.exp == o.exp && self.limbs() == o.limbs()
    }
}

impl<const N: usize> Dyadic<N> {
    const OK: () = assert!(N >= 2 && N <= MAX_LIMBS);

    /// Zero.
    pub const ZERO: Self = Dyadic {
        mag: [0; N],
        len: 0,
        neg: false,
        exp: 0,
    };

    #[cold]
    fn overflow() -> Self {
        Poison::set();
        Self::ZERO
    }

    /// The limbs of the magnitude (normalised).
    #[inline(always)]
    fn limbs(&self) -> &[u64] {
        &self.mag[..self.len as usize]
    }

    /// Build from a sign, an exponent and `mag[..len]` (normalised, non-canonical):
    /// strips the trailing zero bits into the exponent.
    #[inline(always)]
    fn canonical(mut mag: [u64; N], len: usize, neg: bool, exp: i64) -> Self {
        if len == 0 {
            return Self::ZERO;
        }
        let tz = trailing_zeros(&mag[..len]);
        let len = if tz == 0 {
            len
        } else {
            shr_in_place(&mut mag, len, tz)
        };
        let exp = exp + tz as i64;
        if exp.unsigned_abs() > i32::MAX as u64 / 2 {
            return Self::overflow();
        }
        Dyadic {
            mag,
            len: len as u32,
            neg,
            exp: exp as i32,
        }
    }

    /// `(−1)^neg · v · 2^exp` for a 128-bit integer.
    #[inline(always)]
    fn from_u128(neg: bool, exp: i64, v: u128) -> Self {
        if v == 0 {
            return Self::ZERO;
        }
        let tz = v.trailing_zeros();
        let v = v >> tz;
        let mut mag = [0u64; N];
        mag[0] = v as u64;
        mag[1] = (v >> 64) as u64;
        let exp = exp + i64::from(tz);
        if exp.unsigned_abs() > i32::MAX as u64 / 2 {
            return Self::overflow();
        }
        Dyadic {
            mag,
            len: if mag[1] != 0 { 2 } else { 1 },
            neg,
            exp: exp as i32,
        }
    }

    /// The double `x`, exactly (a non-finite `x` poisons).
    #[inline(always)]
    pub fn from_f64(x: f64) -> Self {
        #[allow(clippy::let_unit_value)]
        let () = Self::OK;
        if x == 0.0 {
            return Self::ZERO;
        }
        if !x.is_finite() {
            return Self::overflow();
        }
        let bits = x.to_bits();
        let biased = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1u64 << 52) - 1);
        let (m, e) = if biased == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), biased - 1075)
        };
        let tz = m.trailing_zeros();
        let mut mag = [0u64; N];
        mag[0] = m >> tz;
        Dyadic {
            mag,
            len: 1,
            neg: x < 0.0,
            exp: (e + i64::from(tz)) as i32,
        }
    }

    /// The parts `(negative, exponent, magnitude limbs)`.
    #[inline(always)]
    pub(crate) fn parts(&self) -> Parts<'_> {
        (self.neg, i64::from(self.exp), self.limbs())
    }

    /// The exact sign.
    #[inline(always)]
    pub fn sign(&self) -> Ordering {
        if self.len == 0 {
            Ordering::Equal
        } else if self.neg {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }

    /// The bit length of the integer `m`.
    pub fn bit_len(&self) -> u32 {
        bit_len(self.limbs()) as u32
    }

    /// An approximation of the value (relative error below 2⁻⁵²; 0 or ±∞ beyond the
    /// double range).
    pub fn estimate(&self) -> f64 {
        if self.len == 0 {
            return 0.0;
        }
        let (f, k) = top(self.limbs());
        let v = scale(f, k + i64::from(self.exp));
        if self.neg {
            -v
        } else {
            v
        }
    }

    /// `self ± b` (`flip`: subtract).
    #[inline(always)]
    fn add_signed(&self, b: &Self, flip: bool) -> Self {
        let bneg = b.neg ^ flip;
        if b.len == 0 {
            return *self;
        }
        if self.len == 0 {
            let mut r = *b;
            r.neg = bneg;
            return r;
        }
        let (x, xneg, y, yneg) = if self.exp >= b.exp {
            (self, self.neg, b, bneg)
        } else {
            (b, bneg, self, self.neg)
        };
        let d = (i64::from(x.exp) - i64::from(y.exp)) as u64;
        if x.len == 1 && y.len == 1 && d < 64 {
            // Both fit 128 bits after the shift: x·2^d < 2^127, y < 2^64.
            let xv = u128::from(x.mag[0]) << d;
            let yv = u128::from(y.mag[0]);
            let (neg, v) = if xneg == yneg {
                (xneg, xv + yv)
            } else if xv >= yv {
                (xneg, xv - yv)
            } else {
                (yneg, yv - xv)
            };
            return Self::from_u128(neg, i64::from(y.exp), v);
        }
        let mut mag = [0u64; N];
        match signed_sum(
            x.limbs(),
            i64::from(x.exp) - i64::from(y.exp),
            xneg != yneg,
            y.limbs(),
            0,
            &mut mag,
        ) {
            Some((neg, _, len)) => Self::canonical(mag, len, neg ^ xneg, i64::from(y.exp)),
            None => Self::overflow(),
        }
    }
}

impl<const N: usize> Ring for Dyadic<N> {
    #[inline(always)]
    fn zero() -> Self {
        Self::ZERO
    }
    #[inline(always)]
    fn one() -> Self {
        Self::from_f64(1.0)
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
        if self.len == 0 || b.len == 0 {
            return Self::ZERO;
        }
        let neg = self.neg != b.neg;
        let exp = i64::from(self.exp) + i64::from(b.exp);
        if self.len == 1 && b.len == 1 {
            return Self::from_u128(neg, exp, u128::from(self.mag[0]) * u128::from(b.mag[0]));
        }
        let mut mag = [0u64; N];
        match mul_into(self.limbs(), b.limbs(), &mut mag) {
            Some(len) => Self::canonical(mag, len, neg, exp),
            None => Self::overflow(),
        }
    }
    #[inline(always)]
    fn negate(&self) -> Self {
        let mut r = *self;
        r.neg = !r.neg && r.len != 0;
        r
    }
}

/// `(f, k)` with `a ≈ f·2^k`: `f` the top 64 bits of `a` (truncated) converted to a
/// double (rounded), so `|a − f·2^k| < (2⁻⁶³ + 2⁻⁵³)·a`.
#[inline(always)]
pub(crate) fn top(a: &[u64]) -> (f64, i64) {
    let n = a.len();
    if n == 1 {
        return (a[0] as f64, 0);
    }
    let lz = a[n - 1].leading_zeros();
    let hi = if lz == 0 {
        a[n - 1]
    } else {
        (a[n - 1] << lz) | (a[n - 2] >> (64 - lz))
    };
    (hi as f64, 64 * (n as i64 - 1) - i64::from(lz))
}

/// `x·2^k` for `x` in `[1, 2⁶⁴]`, saturating to 0 or ∞ outside the double range (used
/// for estimates only; exact in the normal range).
#[inline(always)]
pub(crate) fn scale(x: f64, k: i64) -> f64 {
    if k > 1100 {
        return f64::INFINITY;
    }
    if k < -1200 {
        return 0.0;
    }
    let mut v = x;
    let mut k = k;
    while k > 1000 {
        v *= 2f64.powi(1000);
        k -= 1000;
    }
    while k < -1000 {
        v *= 2f64.powi(-1000);
        k += 1000;
    }
    v * pow2(k as i32)
}

/// `2^k` for `k` in `[−1022, 1023]`, exactly.
#[inline(always)]
fn pow2(k: i32) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// Correctly rounded quotients are accepted in `[2⁻⁹⁶⁰, 2¹⁰⁰⁰]` (so that both
/// neighbours and the gaps between them are normal doubles); others are left to the
/// next tier.
const C_MIN: f64 = 1.0261342003245941e-289; // 2^-960
const C_MAX: f64 = 1.0715086071862673e301; // 2^1000

/// The quotient `p/q` correctly rounded to nearest (ties to even), decided exactly.
///
/// A candidate `c > 0` for `|p/q|` comes from the top 64 bits of both integers (relative
/// error below `2⁻⁵⁰`, i.e. a few ulps). Then, exactly: the residual `R = |p| − c·|q|`
/// (`c·|q|` has at most `N + 1` limbs, and aligned against `|p| ≈ c|q|` the difference
/// needs at most `max(bits p, bits q + 53) + 2` bits — inside the scratch); `R = 0`
/// means `|p/q| = c`. Otherwise the quotient lies on the side of `sign R`, and with `g`
/// the gap from `c` to its neighbour on that side, `2|R| < g·|q|` says it lies within
/// half a gap, so `c` is the rounding to nearest; equality is a tie (to even);
/// otherwise the neighbour is the next candidate. `None` when `q = 0`, when the value
/// is outside `[2⁻⁹⁶⁰, 2¹⁰⁰⁰]`, or (never for a candidate within a few ulps) after six
/// candidates.
pub fn round_quotient<const N: usize>(p: &Dyadic<N>, q: &Dyadic<N>) -> Option<Rounded> {
    round_quotient_parts::<SCRATCH>(p.parts(), q.parts())
}

/// A dyadic number given by its parts: `(negative, exponent, normalised magnitude)`.
pub(crate) type Parts<'a> = (bool, i64, &'a [u64]);

/// [`round_quotient`] on the parts of two dyadic numbers, with scratch buffers of `S`
/// limbs: `S ≥ 2·max(len p, len q) + 4` always suffices (see [`round_quotient`]); a
/// smaller `S` only makes more quotients fall through (`None`), never a wrong one.
pub(crate) fn round_quotient_parts<const S: usize>(p: Parts<'_>, q: Parts<'_>) -> Option<Rounded> {
    let ((pneg, ep, pm), (qneg, eq, qm)) = (p, q);
    if qm.is_empty() {
        return None;
    }
    if pm.is_empty() {
        return Some(Rounded::exact(0.0));
    }
    let neg = pneg != qneg;
    let (fp, kp) = top(pm);
    let (fq, kq) = top(qm);
    // fp/fq lies in [2⁻⁶⁴, 2⁶⁴]; keep the scaling within the normal range.
    let k = kp + ep - kq - eq;
    if !(-950..=950).contains(&k) {
        return None;
    }
    let mut c = (fp / fq) * pow2(k as i32);
    let mut prod = [0u64; S];
    let mut res = [0u64; S];
    for _ in 0..6 {
        if !(C_MIN..=C_MAX).contains(&c) {
            return None;
        }
        // c = mc·2^ec with mc < 2⁵³ odd.
        let bits = c.to_bits();
        let mant = (bits & ((1u64 << 52) - 1)) | (1u64 << 52);
        let tz = mant.trailing_zeros();
        let (mc, ec) = (
            mant >> tz,
            ((bits >> 52) & 0x7ff) as i64 - 1075 + i64::from(tz),
        );
        let pl = mul_into(qm, &[mc], &mut prod)?;
        let (rneg, er, rl) = signed_sum(pm, ep, true, &prod[..pl], ec + eq, &mut res)?;
        if rl == 0 {
            return Some(signed(Rounded::exact(c), neg));
        }
        let side = if rneg {
            Ordering::Less
        } else {
            Ordering::Greater
        };
        let nb = if rneg { next_down(c) } else { next_up(c) };
        let gap = (nb - c).abs(); // a power of two, exactly
        let g = ((gap.to_bits() >> 52) & 0x7ff) as i64 - 1023;
        match cmp_scaled(&res[..rl], er + 1, qm, eq + g, &mut prod)? {
            Ordering::Less => return Some(signed(Rounded::inexact(c, side), neg)),
            Ordering::Equal => {
                let even = if c.to_bits() & 1 == 0 { c } else { nb };
                let (lo, hi) = if c < nb { (c, nb) } else { (nb, c) };
                return Some(signed(
                    Rounded {
                        nearest: even,
                        lo,
                        hi,
                    },
                    neg,
                ));
            }
            Ordering::Greater => c = nb,
        }
    }
    None
}

/// `r` or `−r` (the enclosure mirrored).
#[inline(always)]
fn signed(r: Rounded, neg: bool) -> Rounded {
    if neg {
        Rounded {
            nearest: -r.nearest,
            lo: -r.hi,
            hi: -r.lo,
        }
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::round::round_rational;
    use rug::{Integer, Rational};

    type D = Dyadic<4>;

    fn exact<const N: usize>(x: &Dyadic<N>) -> Rational {
        let mut m = Integer::new();
        for &l in x.limbs().iter().rev() {
            m <<= 64;
            m += l;
        }
        let mut r = Rational::from(m);
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

    struct Gen(u64);
    impl Gen {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        /// Doubles of every shape: full or short significands, exponents within ±40.
        fn f(&mut self) -> f64 {
            let r = self.next();
            let m = if r.is_multiple_of(3) {
                (r >> 40) as f64
            } else {
                (r >> 11) as f64
            };
            let e = (self.next() % 81) as i32 - 40 - 52;
            let s = if r & 1 == 0 { 1.0 } else { -1.0 };
            s * m * 2f64.powi(e)
        }
    }

    #[test]
    fn ring_operations_are_exact_and_canonical() {
        Poison::reset();
        let mut g = Gen(0xDEAD_BEEF_1234_5678);
        for _ in 0..2000 {
            let (a, b, c) = (g.f(), g.f(), g.f());
            let (da, db, dc) = (D::from_f64(a), D::from_f64(b), D::from_f64(c));
            let qa = Rational::from_f64(a).unwrap();
            let qb = Rational::from_f64(b).unwrap();
            let qc = Rational::from_f64(c).unwrap();
            let x = da.times(&db).minus(&dc).plus(&da);
            assert_eq!(exact(&x), qa.clone() * &qb - &qc + &qa);
            assert_eq!(x.sign(), (qa.clone() * &qb - &qc + &qa).cmp0());
            // Canonical: the same value computed another way has the same representation.
            let y = da.plus(&da.times(&db)).minus(&dc);
            assert_eq!(x, y);
            assert!(x.len == 0 || x.mag[0] & 1 == 1);
            assert_eq!(da.minus(&da), D::ZERO);
            assert_eq!(da.negate().plus(&da), D::ZERO);
        }
        assert!(!Poison::is_set());
    }

    #[test]
    fn width_overflow_poisons_instead_of_truncating() {
        Poison::reset();
        // 1e150 + 1e-150: a shift of ~1000 bits does not fit 4 limbs.
        let x = D::from_f64(1e150).plus(&D::from_f64(1e-150));
        assert!(Poison::is_set());
        assert_eq!(x, D::ZERO);
        Poison::reset();
        // Full 53-bit significands: four factors (212 bits) fit 256 bits, five (265) do not.
        let f = D::from_f64(1.0 + f64::EPSILON);
        let mut p = f;
        for _ in 0..3 {
            p = p.times(&f);
        }
        assert!(!Poison::is_set());
        let _ = p.times(&f).times(&f);
        assert!(Poison::is_set());
        Poison::reset();
        // Extreme exponents are exact: (2^-1074)² needs no significand bits.
        let t = D::from_f64(f64::from_bits(1));
        let s = t.times(&t);
        assert!(!Poison::is_set());
        assert_eq!(exact(&s), Rational::from((1, 1)) >> 2148u32);
    }

    #[test]
    fn quotients_round_correctly_including_ties() {
        type D = Dyadic<8>;
        Poison::reset();
        let mut g = Gen(0x0123_4567_89AB_CDEF);
        for _ in 0..2000 {
            let (a, b, c, d) = (g.f(), g.f(), g.f(), g.f());
            if b == 0.0 || d == 0.0 {
                continue;
            }
            let p = D::from_f64(a).times(&D::from_f64(b)).plus(&D::from_f64(c));
            let q = D::from_f64(d).times(&D::from_f64(b));
            let truth = round_rational(&(exact(&p) / exact(&q)));
            assert_eq!(round_quotient(&p, &q), Some(truth), "{a} {b} {c} {d}");
        }
        let r = |a: f64, b: f64| round_quotient(&D::from_f64(a), &D::from_f64(b)).unwrap();
        assert_eq!(r(6.0, 3.0), Rounded::exact(2.0));
        assert_eq!(r(-1.0, 3.0), round_rational(&Rational::from((-1, 3))));
        assert_eq!(r(1.0, -1024.0), Rounded::exact(-1.0 / 1024.0));
        // (1 + 2^-53)·3 / 3: the midpoint between 1 and 1 + 2^-52, a tie to even (1).
        let p = D::from_f64(3.0).plus(&D::from_f64(3.0 * f64::EPSILON / 2.0));
        let t = round_quotient(&p, &D::from_f64(3.0)).unwrap();
        assert_eq!((t.nearest, t.lo, t.hi), (1.0, 1.0, 1.0 + f64::EPSILON));
        let t = round_quotient(&p.negate(), &D::from_f64(3.0)).unwrap();
        assert_eq!((t.nearest, t.lo, t.hi), (-1.0, -1.0 - f64::EPSILON, -1.0));
        // Out of the accepted range, or a zero denominator: left to the next tier.
        assert_eq!(
            round_quotient(&D::from_f64(1e-300), &D::from_f64(1e10)),
            None
        );
        assert_eq!(round_quotient(&D::from_f64(1.0), &D::ZERO), None);
        assert_eq!(
            round_quotient(&D::ZERO, &D::from_f64(3.0)),
            Some(Rounded::exact(0.0))
        );
        assert!(!Poison::is_set());
    }

    #[test]
    fn estimates() {
        let x = D::from_f64(3.0)
            .times(&D::from_f64(1e200))
            .times(&D::from_f64(1e200));
        assert_eq!(x.estimate(), f64::INFINITY);
        assert_eq!(D::from_f64(-0.375).estimate(), -0.375);
    }
}
