//! The filter tier of the linear kernel (CERTIFICATION.md "Escalation", first stage):
//! a formula is evaluated in double-double ([`Dd`]) and its absolute error is bounded by
//! a static constant `ε` (derived with [`crate::num::error_bound::ErrorBound`]) times the
//! scale `M = Π m_g^{d_g}` of its inputs, where `m_g` is the largest magnitude in input
//! group `g` (a plane's spanning vectors, a line's direction, all positions, ...) and
//! `d_g` the formula's degree in that group. Signs and correct roundings are accepted
//! only when the bound decides them; otherwise the caller falls through to the exact tier.
//!
//! Safe range: every group maximum must be at most [`SCALE_MAX`] = 2¹⁰⁰ (else the filter
//! is skipped: formulas have degree ≤ 9, so every intermediate is at most `b·2⁹⁰⁰` with
//! `b` the derived magnitude bound — a few thousand — far below the 2⁹⁹⁵ that Veltkamp's
//! split and the double range allow), and is clamped up to [`SCALE_MIN`] = 2⁻¹⁰⁰ (which
//! bounds the effect of underflow by `3u²` per product in scaled units, see
//! `error_bound`). NaN or ∞ anywhere makes every test fail, so the exact tier answers.
//!
//! This is the semi-static filter of the kernel, evaluated in double-double rather than
//! plain f64: the same pass decides the verdict (the sign of a denominator) and the
//! correct rounding of every output, so a plain-f64 pre-filter would only add work on
//! generic input.

// `!(a <= b)` is deliberate throughout: it is true for NaN, which must fail every test.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::manual_range_contains)]

use std::cmp::Ordering;

use super::dd::{two_sum, Dd, ProductMode, ETA, U};
use super::round::{next_up, Rounded};

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
/// most `e`, if the bound decides it (`|h| > |l| + e`; no normalisation needed).
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

/// A denominator prepared once for several [`round_ratio`] calls: normalised, with a
/// lower bound on its exact magnitude and its reciprocal (for the candidate only).
#[derive(Debug, Clone, Copy)]
pub struct Denominator<M: ProductMode> {
    q: Dd<M>,
    eq: f64,
    q_lo: f64,
    inv: f64,
}

impl<M: ProductMode> Denominator<M> {
    /// `None` when `q` is out of the accepted range or its sign is not decided by `eq`.
    #[inline(always)]
    pub fn new(q: &Dd<M>, eq: f64) -> Option<Self> {
        let q = q.normalized();
        let qa = q.h.abs();
        if !(qa >= TINY && qa <= C_MAX && eq <= C_MAX) {
            return None;
        }
        let q_lo = (qa - add_up(q.l.abs(), eq)) * (1.0 - 4.0 * U);
        if !(q_lo > 0.0) {
            return None;
        }
        Some(Denominator {
            q,
            eq,
            q_lo,
            inv: 1.0 / q.h,
        })
    }
}

const TINY: f64 = 1.1830521861667747e-271; // 2^-900
const C_MIN: f64 = 1.0261342003245941e-289; // 2^-960
const C_MAX: f64 = 1.0715086071862673e301; // 2^1000

/// The exact quotient `P/Q` correctly rounded (`d` prepared from `Q`), where `p`, `q` approximate `P`, `Q` with
/// absolute errors at most `ep`, `eq` — if the bounds decide the rounding and `P/Q` is
/// provably not a double (a value that may be a double goes to the exact tier, which
/// reports `lo = hi`).
///
/// Method: a candidate `c ≈ p/q` (one division, one correction step), the residual
/// `R = p − c·q` in double-double, and the test `|R/Q| < min(gap below c, gap above c)/2`,
/// i.e. `P/Q` lies strictly inside the rounding cell of `c`. With `q` normalised,
/// `(m, e) = two_prod(c, q.h)` (exact), `e' = e + c·q.l` (error `≤ u|c q.l| + u|e'|`),
/// `(s, t) = two_sum(p.h, −m)` (exact), `r_l = (t + p.l) − e'` (error
/// `≤ u|t + p.l| + u|r_l|`) and `R̂ = s + r_l` (error `≤ u|R̂|`): so
/// `|R − R̂| ≤ ep + |c|·eq + u(|c q.l| + |e'| + |t + p.l| + |r_l|) + u|R̂|`, taken with a
/// `(1 + 16u)` margin for the (at most nine) roundings of the bound itself and `8η` for
/// underflow in the residual and in the bound.
/// Accepted only for `2⁻⁹⁰⁰ ≤ |p.h|, |q.h| ≤ 2¹⁰⁰⁰` and `2⁻⁹⁶⁰ ≤ |c| ≤ 2¹⁰⁰⁰`, so that no
/// quantity of the test underflows or overflows and half an ulp of `c` is a normal double.
#[inline(always)]
pub fn round_over<M: ProductMode>(p: &Dd<M>, ep: f64, d: &Denominator<M>) -> Option<Rounded> {
    let (q, eq, q_lo, inv) = (d.q, d.eq, d.q_lo, d.inv);
    // `p` is used as it is: the bound below is computed from the actual parts, so it
    // holds whether or not `p` is normalised (a poorly normalised `p` only spoils the
    // candidate, and then the test fails).
    let pa = p.h.abs();
    if !(pa >= TINY && pa <= C_MAX && ep <= C_MAX) {
        return None;
    }
    // Candidate: c₀ = p.h/q.h, corrected once by the residual (c need not be right:
    // a wrong candidate fails the test below).
    let c0 = p.h * inv;
    let rem = M::mul_add(-c0, q.h, p.h) + (p.l - c0 * q.l);
    let c = c0 + rem * inv;
    let ca = c.abs();
    if !(ca >= C_MIN && ca <= C_MAX) {
        return None;
    }
    let (m, e) = M::two_prod(c, q.h);
    let e2 = M::mul_add(c, q.l, e);
    let (s, t) = two_sum(p.h, -m);
    let tl = t + p.l;
    let rl = tl - e2;
    let r = s + rl;
    let er = (ep + ca * eq + U * (ca * q.l.abs() + e2.abs() + tl.abs() + rl.abs() + r.abs()))
        * (1.0 + 16.0 * U)
        + 8.0 * ETA;
    // Half the smaller gap next to c: half an ulp, or a quarter at a power of two.
    let bits = c.to_bits();
    let biased = (bits >> 52) & 0x7ff;
    let half_ulp = f64::from_bits((biased - 53) << 52);
    let half_gap = if bits & ((1u64 << 52) - 1) == 0 {
        half_ulp * 0.5
    } else {
        half_ulp
    };
    let cell = half_gap * q_lo * (1.0 - 4.0 * U);
    if !(add_up(r.abs(), er) < cell) {
        return None;
    }
    // c is the nearest double; P/Q − c = R/Q has the sign of R·Q.
    if !(r.abs() > er) {
        return None;
    }
    let above = (r > 0.0) == (q.h > 0.0);
    Some(Rounded::inexact(
        c,
        if above {
            Ordering::Greater
        } else {
            Ordering::Less
        },
    ))
}

/// The exact quotient `P/Q` correctly rounded (see [`round_over`], which does the work
/// once the denominator is prepared by [`Denominator::new`]).
#[inline(always)]
pub fn round_ratio<M: ProductMode>(p: &Dd<M>, ep: f64, q: &Dd<M>, eq: f64) -> Option<Rounded> {
    round_over(p, ep, &Denominator::new(q, eq)?)
}

/// A polynomial value correctly rounded (see [`round_ratio`] with `Q = 1`).
#[inline(always)]
pub fn round_value<M: ProductMode>(p: &Dd<M>, ep: f64) -> Option<Rounded> {
    round_ratio(p, ep, &Dd::from_f64(1.0), 0.0)
}

/// Call `$fast::<WithFma>` through a function compiled with FMA enabled when the CPU has
/// it (x86-64: runtime detection; AArch64: always), else `$fast::<WithoutFma>`. No
/// compile flag is needed: the FMA instance lives in a `#[target_feature]` function, and
/// the generic formulas are `#[inline(always)]` so that they are compiled inside it.
macro_rules! dispatch_fma {
    ($fast:ident($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty) => {{
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "fma")]
        unsafe fn with_fma($($arg: $ty),*) -> $ret {
            $fast::<$crate::num::dd::WithFma>($($arg),*)
        }
        #[cfg(target_arch = "x86_64")]
        let r = if $crate::num::filter::fma_available() {
            // SAFETY: the CPU supports FMA (checked at run time).
            unsafe { with_fma($($arg),*) }
        } else {
            $fast::<$crate::num::dd::WithoutFma>($($arg),*)
        };
        #[cfg(not(target_arch = "x86_64"))]
        let r = if $crate::num::filter::fma_available() {
            $fast::<$crate::num::dd::WithFma>($($arg),*)
        } else {
            $fast::<$crate::num::dd::WithoutFma>($($arg),*)
        };
        r
    }};
}
pub(crate) use dispatch_fma;

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
            let truth =
                round_rational(&(Rational::from_f64(a).unwrap() / Rational::from_f64(b).unwrap()));
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
        assert_eq!(1.0261342003245941e-289, 2f64.powi(-960));
        assert_eq!(1.0715086071862673e301, 2f64.powi(1000));
        assert_eq!(ETA, f64::from_bits(1));
    }
}
