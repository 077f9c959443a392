//! The filter tier of the linear kernel (CERTIFICATION.md "Escalation", first stage):
//! a formula is evaluated in double-double ([`Dd`]) and its absolute error is bounded by
//! a static constant `ε` (derived with [`crate::num::error_bound::ErrorBound`]) times the
//! scale `M = Π m_g^{d_g}` of its inputs, where `m_g` is the largest magnitude in input
//! group `g` (a plane's spanning vectors, a line's direction, all positions, ...) and
//! `d_g` the formula's degree in that group. Signs and correct roundings are accepted
//! only when the bound decides them; otherwise the caller falls through to the exact tier.
//!
//! Safe range: every group maximum must be at most [`SCALE_MAX`] = 2¹⁰⁰ (else the filter
//! is skipped: no overflow is possible below it, since formulas have degree ≤ 9 and
//! constants below 2¹⁰), and is clamped up to [`SCALE_MIN`] = 2⁻¹⁰⁰ (which bounds the
//! effect of underflow by `3u²` per product in scaled units, see `error_bound`). NaN or ∞
//! anywhere makes every test fail, so the exact tier answers.

// `!(a <= b)` is deliberate throughout: it is true for NaN, which must fail every test.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use std::cmp::Ordering;

use super::dd::{fast_two_sum, Dd, ProductMode, ETA, U};
use super::ring::Ring;
use super::round::{next_down, next_up, Rounded};

/// Largest group maximum the filter accepts: 2¹⁰⁰.
pub const SCALE_MAX: f64 = 1.2676506002282294e30;
/// Group maxima are clamped up to 2⁻¹⁰⁰.
pub const SCALE_MIN: f64 = 7.888609052210118e-31;

/// The scale of an input group: `max |x|`, clamped up to [`SCALE_MIN`]; `None` when it
/// exceeds [`SCALE_MAX`] or is not finite.
#[inline(always)]
pub fn group_scale(values: &[f64]) -> Option<f64> {
    let mut m = SCALE_MIN;
    for &x in values {
        let a = x.abs();
        if !(a <= SCALE_MAX) {
            return None;
        }
        if a > m {
            m = a;
        }
    }
    Some(m)
}

/// `max(a, b)` of two group scales rounded up where a quotient enters: a number that
/// belongs to group `g·h` (an implicit plane's `d`, in the units of normal × position)
/// extends the position scale by `|d| / m_normal`, rounded up.
#[inline(always)]
pub fn extend_scale(scale: Option<f64>, numerator: f64, divisor: f64) -> Option<f64> {
    let q = next_up(numerator.abs() / divisor);
    match scale {
        Some(m) if q <= SCALE_MAX => Some(m.max(q)),
        _ => None,
    }
}

/// The absolute error bound `ε · Π factors`, rounded up: the product of at most 10
/// factors in `[2⁻¹⁰⁰, 2¹⁰⁰]` neither overflows nor underflows, each rounding loses at
/// most a factor `(1 − u)`, and `(1 + 16u)` covers them.
#[inline(always)]
pub fn bound(eps: f64, factors: &[f64]) -> f64 {
    let mut m = eps;
    for &f in factors {
        m *= f;
    }
    m * (1.0 + 16.0 * U)
}

/// `x + y` rounded up for non-negative `x`, `y` (a safe upper bound).
#[inline(always)]
fn add_up(x: f64, y: f64) -> f64 {
    (x + y) * (1.0 + 4.0 * U) + 2.0 * ETA
}

/// The sign of the exact value of which `x` is an approximation with absolute error at
/// most `e`, if the bound decides it.
#[inline(always)]
pub fn sign_of<M: ProductMode>(x: &Dd<M>, e: f64) -> Option<Ordering> {
    if x.h.abs() > add_up(x.l.abs(), e) {
        x.h.partial_cmp(&0.0)
    } else if x.h == 0.0 && e == 0.0 {
        Some(Ordering::Equal)
    } else {
        None
    }
}

/// The exact quotient `P/Q` correctly rounded, where `p`, `q` approximate `P`, `Q` with
/// absolute errors at most `ep`, `eq` — if the bounds decide the rounding and `P/Q` is
/// provably not a double (a value that may be a double goes to the exact tier, which
/// reports `lo = hi`).
///
/// Method: a candidate `c ≈ p/q`, the residual `R = p − c·q` in double-double, and the
/// test `|R/Q| < min(gap below c, gap above c)/2`, i.e. `P/Q` lies strictly inside the
/// rounding cell of `c`. `R`'s error bound: the inputs' `ep + |c|·eq`; forming `c·q`
/// exactly up to `u|c·q.l| + u|e'|` (the rounding of `e' = e + c·q.l`, `two_prod` and
/// `fast_two_sum` being exact); the subtraction's `5u²(|p.h| + |cq.h|)`; `4η` for
/// underflow; summed with a `(1 + 16u)` margin for the rounding of the bound itself.
/// Accepted only for `|p.h|, |q.h| ≥ 2⁻⁹⁰⁰` and `2⁻¹⁰⁰⁰ ≤ |c| ≤ 2¹⁰⁰⁰`, so no quantity of
/// the test underflows or overflows.
#[inline(always)]
pub fn round_ratio<M: ProductMode>(p: &Dd<M>, ep: f64, q: &Dd<M>, eq: f64) -> Option<Rounded> {
    const TINY: f64 = 1.1830521861667747e-271; // 2^-900
    const C_MIN: f64 = 9.332636185032189e-302; // 2^-1000
    const C_MAX: f64 = 1.0715086071862673e301; // 2^1000
    let (pa, qa) = (p.h.abs(), q.h.abs());
    if !(pa >= TINY
        && qa >= TINY
        && ep.is_finite()
        && eq.is_finite()
        && p.is_finite()
        && q.is_finite())
    {
        return None;
    }
    let q_lo = (qa - add_up(q.l.abs(), eq)) * (1.0 - 4.0 * U);
    if !(q_lo > 0.0) {
        return None;
    }
    let c0 = p.h / q.h;
    let r0 = p.minus(&q.times(&Dd::from_f64(c0)));
    let c = c0 + r0.h / q.h;
    if !(c.abs() >= C_MIN && c.abs() <= C_MAX) {
        return None;
    }
    let (m, e) = M::two_prod(c, q.h);
    let e2 = M::mul_add(c, q.l, e);
    let (ch, cl) = fast_two_sum(m, e2);
    let cq = Dd::<M>::from_parts(ch, cl);
    let r = p.minus(&cq);
    let er = (ep
        + c.abs() * eq
        + U * (c.abs() * q.l.abs() + e2.abs())
        + 5.0 * U * U * (pa + cq.h.abs()))
        * (1.0 + 16.0 * U)
        + 4.0 * ETA;
    let gap = (c - next_down(c)).abs().min((next_up(c) - c).abs());
    let cell = (gap * 0.5) * q_lo * (1.0 - 2.0 * U);
    if !(add_up(r.h.abs(), add_up(r.l.abs(), er)) < cell) {
        return None;
    }
    // c is the nearest double; the side of P/Q relative to c is sign(R)·sign(Q).
    let side = sign_of(&r, er)?;
    if side == Ordering::Equal {
        return None;
    }
    let side = if q.h < 0.0 { side.reverse() } else { side };
    Some(Rounded::inexact(c, side))
}

/// A polynomial value correctly rounded (see [`round_ratio`] with `Q = 1`).
#[inline(always)]
pub fn round_value<M: ProductMode>(p: &Dd<M>, ep: f64) -> Option<Rounded> {
    round_ratio(p, ep, &Dd::from_f64(1.0), 0.0)
}

/// True when the FMA instruction can be used (runtime detection on x86-64; always on
/// AArch64, where it is part of the base instruction set).
#[inline(always)]
pub fn fma_available() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::is_x86_feature_detected!("fma")
    }
    #[cfg(target_arch = "aarch64")]
    {
        true
    }
    #[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
    {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::dd::{WithFma, WithoutFma};
    use crate::num::round::round_rational;
    use rug::Rational;

    fn check<M: ProductMode>() {
        // P/Q for P, Q given exactly as double-doubles: 1/3, 2/7, -5/9.
        for (a, b) in [(1.0, 3.0), (2.0, 7.0), (-5.0, 9.0), (1e200, 3e-50)] {
            let p = Dd::<M>::from_f64(a);
            let q = Dd::<M>::from_f64(b);
            let r = round_ratio(&p, 0.0, &q, 0.0).expect("decided");
            let truth = round_rational(&Rational::from(
                Rational::from_f64(a).unwrap() / Rational::from_f64(b).unwrap(),
            ));
            assert_eq!(r, truth);
        }
        // An exact double result is never accepted here (the exact tier reports lo = hi).
        let p = Dd::<M>::from_f64(6.0);
        assert_eq!(round_ratio(&p, 0.0, &Dd::from_f64(3.0), 0.0), None);
        // An error bound as large as the value decides nothing.
        assert_eq!(sign_of(&Dd::<M>::from_f64(1.0), 1.0), None);
        assert_eq!(sign_of(&Dd::<M>::from_f64(-1.0), 0.5), Some(Ordering::Less));
    }

    #[test]
    fn rounding_test_agrees_with_exact_rounding() {
        check::<WithFma>();
        check::<WithoutFma>();
    }

    #[test]
    fn scales_guard_the_range() {
        assert_eq!(group_scale(&[0.0, 0.0]), Some(SCALE_MIN));
        assert_eq!(group_scale(&[1e31]), None);
        assert_eq!(group_scale(&[f64::NAN]), None);
        assert_eq!(SCALE_MAX, 2f64.powi(100));
        assert_eq!(SCALE_MIN, 2f64.powi(-100));
        assert_eq!(1.1830521861667747e-271, 2f64.powi(-900));
        assert_eq!(9.332636185032189e-302, 2f64.powi(-1000));
        assert_eq!(1.0715086071862673e301, 2f64.powi(1000));
        assert_eq!(ETA, f64::from_bits(1));
    }
}
