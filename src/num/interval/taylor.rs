//! Fast proven enclosures of `sin x`, `cos x` and `exp x` at a double `x`: argument
//! reduction and a Taylor polynomial with its Lagrange remainder, all evaluated in
//! [`Interval`] arithmetic (outward rounding), so that every rounding error and every
//! constant's representation error is inside the result by construction; the only
//! mathematical inputs are the reduction identities and the remainder bounds below.
//! The enclosures are a few ulps wide (not tightest); the callers fall back to MPFR
//! outside the stated argument ranges.
//!
//! Constants are exact doubles with their defining property checked by the tests
//! against MPFR (`taylor_constants_are_what_they_claim`): `P1`, `P2` are the first two
//! 33-bit pieces of π/2, `[P3_LO, P3_HI]` encloses `π/2 − P1 − P2`; `L1` is `ln 2`
//! truncated to 32 bits and `[L2_LO, L2_HI]` encloses `ln 2 − L1`; `INV_FACT_LO[n]` is
//! `1/n!` rounded down, and `1/n!` lies in `[INV_FACT_LO[n], next_up(INV_FACT_LO[n])]`.

use super::arith::Sign;
use super::directed::{mul_up, next_up};
use super::Interval;

/// |x| ≤ 2^19 for the trigonometric fast path: `k = round(2x/π)` has at most 19 bits,
/// so `k·P1` and `k·P2` (33-bit constants) are exact doubles.
pub(crate) const TRIG_FAST_MAX: f64 = 524_288.0;
/// |x| ≤ 700 for the exponential fast path: `|k| ≤ 1010`, so `2^k` and
/// `2^k · exp(r)` (with `exp(r) ∈ [0.7, 1.5]`) are normal doubles and scaling is exact.
pub(crate) const EXP_FAST_MAX: f64 = 700.0;

const P1: f64 = 1.570_796_326_734_125_6; // 0x3ff921fb54400000
const P2: f64 = 6.077_100_506_303_966e-11; // 0x3dd0b4611a600000
const P3_LO: u64 = 0x3ba3198a2e037073;
const L1: f64 = 0.693_147_180_369_123_8; // 0x3fe62e42fee00000
const L2_LO: u64 = 0x3dea39ef35793c76;
const INV_FACT_LO: [u64; 21] = [
    0x3ff0000000000000,
    0x3ff0000000000000,
    0x3fe0000000000000,
    0x3fc5555555555555,
    0x3fa5555555555555,
    0x3f81111111111111,
    0x3f56c16c16c16c16,
    0x3f2a01a01a01a01a,
    0x3efa01a01a01a01a,
    0x3ec71de3a556c733,
    0x3e927e4fb7789f5c,
    0x3e5ae64567f544e3,
    0x3e21eed8eff8d897,
    0x3de6124613a86d09,
    0x3da93974a8c07c9d,
    0x3d6ae7f3e733b81f,
    0x3d2ae7f3e733b81f,
    0x3ce952c77030ad4a,
    0x3ca6827863b97d97,
    0x3c62f49b46814157,
    0x3c1e542ba4020225,
];

/// An enclosure of `1/n!` (exact for n ≤ 2).
#[inline]
pub(crate) fn inv_fact(n: usize) -> Interval {
    let lo = f64::from_bits(INV_FACT_LO[n]);
    if n <= 2 {
        Interval::point(lo)
    } else {
        Interval::from_neg_lo_hi(-lo, next_up(lo))
    }
}

/// `(−1)^i / n!` as an interval.
#[inline]
fn signed_inv_fact(n: usize, negative: bool) -> Interval {
    let c = inv_fact(n);
    if negative {
        c.neg()
    } else {
        c
    }
}

/// An enclosure of `π/2 − P1 − P2`.
#[inline]
fn p3() -> Interval {
    let lo = f64::from_bits(P3_LO);
    Interval::from_neg_lo_hi(-lo, next_up(lo))
}

/// An enclosure of `ln 2 − L1`.
#[inline]
fn l2() -> Interval {
    let lo = f64::from_bits(L2_LO);
    Interval::from_neg_lo_hi(-lo, next_up(lo))
}

/// `x = k·π/2 + r` for `|x| ≤ TRIG_FAST_MAX`: the integer `k = round(x·2/π)` (any
/// integer would keep the identity exact; this one gives `|r| ≤ π/4 + 2^-30`) and an
/// enclosure of `r = ((x − k·P1) − k·P2) − k·(π/2 − P1 − P2)`.
#[inline]
pub(crate) fn reduce_half_pi(x: f64) -> (i64, Interval) {
    let k = (x * std::f64::consts::FRAC_2_PI).round();
    if k == 0.0 {
        return (0, Interval::point(x));
    }
    // k·P1 and k·P2 are exact (|k| < 2^19, 33-bit constants).
    let r = Interval::point(x)
        .sub(&Interval::point(k * P1))
        .sub(&Interval::point(k * P2))
        .sub(&Interval::point(k).mul(&p3()));
    (k as i64, r)
}

/// Horner evaluation `c_0 + z·(c_1 + z·(…))` of the even/odd Taylor parts, with
/// `coef(i)` the interval coefficient of `z^i`.
#[inline]
fn horner(z: &Interval, terms: usize, coef: impl Fn(usize) -> Interval) -> Interval {
    let mut acc = coef(terms - 1);
    for i in (0..terms - 1).rev() {
        acc = coef(i).add(&z.mul(&acc));
    }
    acc
}

/// `[−e, e]`.
#[inline]
fn symmetric(e: f64) -> Interval {
    Interval::from_neg_lo_hi(e, e)
}

/// `mag(r)^n / n!` rounded up: the Lagrange remainder bound of a Taylor polynomial of
/// degree `n − 1` for a function whose n-th derivative is bounded by 1.
#[inline]
fn remainder(r: &Interval, n: usize) -> f64 {
    let m = r.mag();
    let mut p = 1.0;
    for _ in 0..n {
        p = mul_up(p, m);
    }
    mul_up(p, next_up(f64::from_bits(INV_FACT_LO[n])))
}

/// `sin r` for `|r| ≤ 0.8`: `Σ_{i=0}^{8} (−1)^i r^{2i+1}/(2i+1)!` (degree 17, the degree-18
/// term is 0) plus `[−R, R]`, `R = |r|^19/19!` (Lagrange; |sin^{(19)}| ≤ 1).
#[inline]
pub(crate) fn sin_small(r: &Interval) -> Interval {
    let z = r.sqr();
    let p = horner(&z, 9, |i| signed_inv_fact(2 * i + 1, i % 2 == 1));
    r.mul(&p).add(&symmetric(remainder(r, 19)))
}

/// `cos r` for `|r| ≤ 0.8`: `Σ_{i=0}^{9} (−1)^i r^{2i}/(2i)!` (degree 18, the degree-19
/// term is 0) plus `[−R, R]`, `R = |r|^20/20!`.
#[inline]
pub(crate) fn cos_small(r: &Interval) -> Interval {
    let z = r.sqr();
    horner(&z, 10, |i| signed_inv_fact(2 * i, i % 2 == 1)).add(&symmetric(remainder(r, 20)))
}

/// `[−1, 1] ∩ x`: sin and cos never leave [−1, 1].
#[inline]
fn clamp_unit(x: Interval) -> Interval {
    x.intersection(&Interval::from_neg_lo_hi(1.0, 1.0))
}

/// An enclosure of `sin x` for `|x| ≤ TRIG_FAST_MAX`: with `x = kπ/2 + r`,
/// `sin x = sin r, cos r, −sin r, −cos r` for `k ≡ 0, 1, 2, 3 (mod 4)`.
pub(crate) fn sin_point(k: i64, r: &Interval) -> Interval {
    clamp_unit(match k.rem_euclid(4) {
        0 => sin_small(r),
        1 => cos_small(r),
        2 => sin_small(r).neg(),
        _ => cos_small(r).neg(),
    })
}

/// An enclosure of `cos x` for `|x| ≤ TRIG_FAST_MAX`: `cos x = cos r, −sin r, −cos r,
/// sin r` for `k ≡ 0, 1, 2, 3 (mod 4)`.
pub(crate) fn cos_point(k: i64, r: &Interval) -> Interval {
    clamp_unit(match k.rem_euclid(4) {
        0 => cos_small(r),
        1 => sin_small(r).neg(),
        2 => cos_small(r).neg(),
        _ => sin_small(r),
    })
}

/// An enclosure of `tan x` for `|x| ≤ TRIG_FAST_MAX` as `sin x / cos x`, or `None` when
/// the cosine enclosure contains 0 (next to a pole; the caller uses MPFR).
pub(crate) fn tan_point(k: i64, r: &Interval) -> Option<Interval> {
    let c = cos_point(k, r);
    if c.sign_class() == Sign::Mixed || c.contains_zero() {
        None
    } else {
        Some(sin_point(k, r).div(&c))
    }
}

/// An enclosure of `exp x` for `|x| ≤ EXP_FAST_MAX`: `x = k·ln 2 + r` with
/// `k = round(x/ln 2)`, `r = (x − k·L1) − k·(ln 2 − L1)` (`k·L1` exact: `|k| ≤ 1010`, 32-bit
/// `L1`), `|r| ≤ 0.35`; `exp r = Σ_{n=0}^{15} r^n/n! + R` with
/// `|R| ≤ e^{|r|}|r|^16/16! ≤ 1.5·|r|^16/16!` (Lagrange; `e^{0.35} < 1.5`); then
/// `exp x = 2^k · exp r`, an exact scaling in the normal range.
pub(crate) fn exp_point(x: f64) -> Interval {
    let k = (x * std::f64::consts::LOG2_E).round();
    let r = Interval::point(x)
        .sub(&Interval::point(k * L1))
        .sub(&Interval::point(k).mul(&l2()));
    let p = horner(&r, 16, inv_fact);
    let e = p.add(&symmetric(mul_up(1.5, remainder(&r, 16))));
    // 2^k as a double (k + 1023 ∈ [13, 2033]: normal).
    let scale = f64::from_bits(((k as i64 + 1023) as u64) << 52);
    Interval::from_neg_lo_hi(e.neg_lo() * scale, e.hi() * scale)
}
