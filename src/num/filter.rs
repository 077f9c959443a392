//! The filter tier of the linear kernel (docs/CERTIFICATES.md "Escalation", first stage):
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

use super::dd::{fast_two_sum, two_sum, Dd, ProductMode, ETA, U};
use super::lane::{Lane, Wide, MAX_LANES};
use super::round::Rounded;

/// Largest group maximum the filter accepts: 2¹⁰⁰.
pub const SCALE_MAX: f64 = 1.2676506002282294e30;
/// Group maxima are clamped up to 2⁻¹⁰⁰.
pub const SCALE_MIN: f64 = 7.888609052210118e-31;

/// The scale of an input group: `max |x|`, clamped up to [`SCALE_MIN`]; `None` when it
/// exceeds [`SCALE_MAX`] or is not finite ([`scale_of`] for one `f64`, its poison as
/// `None`).
#[inline(always)]
pub fn group_scale(values: &[f64]) -> Option<f64> {
    accepted(scale_of(values))
}

/// A scale from [`scale_of`] or [`extend_scale_of`], `None` when it is the poison `+∞`.
#[inline(always)]
pub fn accepted(scale: f64) -> Option<f64> {
    (scale < f64::INFINITY).then_some(scale)
}

/// [`group_scale`] for any [`Lane`] type: `max |x|` clamped up to [`SCALE_MIN`], and
/// `+∞` (in place of `None`) when it exceeds [`SCALE_MAX`] or a value is not finite.
/// An infinite scale poisons every bound built from it (`ε·∞ = ∞`), so every acceptance
/// test of the filter (`bound < value`) fails and the case goes to the exact tiers;
/// scales are never NaN, so [`Lane::max`] of scales keeps the poison.
#[allow(clippy::eq_op)] // `x − x` is 0 for finite x and NaN otherwise: the point
#[inline(always)]
pub fn scale_of<F: Lane>(values: &[F]) -> F {
    let mut m = F::splat(SCALE_MIN);
    let mut z = F::splat(0.0); // 0, or NaN once a value is ±∞ or NaN (x − x)
    for &x in values {
        m = m.max(x.abs());
        z = z + (x - x);
    }
    let ok = m.less_eq(F::splat(SCALE_MAX)) & z.equal(F::splat(0.0));
    F::select(ok, m, F::splat(f64::INFINITY))
}

/// The position scale `m` extended by a number of group `g·h` (an implicit plane's `d`,
/// in the units of normal × position): `max(m, q)` with `q ≥ |d|/divisor`, `+∞`
/// beyond [`SCALE_MAX`] (as in [`scale_of`]). `q = fl(fl(|d|/divisor)·(1 + 4u))`: where
/// it matters (`q ≥ m ≥ 2⁻¹⁰⁰`, no underflow) `q ≥ (|d|/divisor)(1 − u)²(1 + 4u) ≥
/// |d|/divisor`; a NaN quotient (∞/∞: a poisoned divisor) fails the range test.
#[inline(always)]
pub fn extend_scale_of<F: Lane>(m: F, d: F, divisor: F) -> F {
    let q = d.abs() / divisor * F::splat(1.0 + 4.0 * U);
    F::select(
        q.less_eq(F::splat(SCALE_MAX)),
        m.max(q),
        F::splat(f64::INFINITY),
    )
}

/// The absolute error bound `ε · Π factors`, rounded up: the product of at most 10
/// factors in `[2⁻¹⁰⁰, 2¹⁰⁰]` neither overflows nor underflows, each rounding loses at
/// most a factor `(1 − u)`, and `(1 + 16u)` covers them. Lane-wise for [`F4`](super::lane::F4).
#[inline(always)]
pub fn bound<F: Lane>(eps: f64, factors: &[F]) -> F {
    let mut m = F::splat(eps);
    for &f in factors {
        m = m * f;
    }
    m * F::splat(1.0 + 16.0 * U)
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

/// A denominator prepared once for several [`round_over`] calls: its sign decided, its
/// reciprocal (for candidates only) and the two factors of [`round_over`]'s error bound
/// that depend on it alone. With `F = F4`, four denominators; `ok` says which lanes
/// were accepted.
#[derive(Debug, Clone, Copy)]
pub struct Denominator<M: ProductMode, F: Lane = f64> {
    q: Dd<M, F>,
    eq: F,
    inv: F,
    /// `|q.l|`.
    ql: F,
    /// An upper bound on `1/|Q|`.
    inv_lo: F,
    /// An upper bound on `|1/Q − inv|`.
    k: F,
}

impl<M: ProductMode> Denominator<M> {
    /// `None` when `q` is out of the accepted range or its sign is not decided by `eq`
    /// (see [`Denominator::prepare`]).
    #[inline(always)]
    pub fn new(q: &Dd<M>, eq: f64) -> Option<Self> {
        let (ok, d) = Self::prepare(q, eq);
        ok.then_some(d)
    }
}

impl<M: ProductMode, F: Lane> Denominator<M, F> {
    /// The prepared denominator and whether it is accepted (lane-wise): rejected when
    /// `q` is out of the accepted range or its sign is not decided by `eq`.
    ///
    /// `q` is used as it is (not renormalised: that would delay the reciprocal by a
    /// `two_sum`; the bounds below hold for any split `q = q.h + q.l`). With
    /// `inv = fl(1/q.h)`, `1/|q.h| ≤ |inv|/(1 − u) ≤ |inv|(1 + 2u)`, so
    /// `x = (|q.l| + eq)·|inv|·(1 + 8u) ≥ (|q.l| + eq)/|q.h|` (three roundings and the
    /// reciprocal's: `(1 − u)⁴(1 + 8u) ≥ 1`). Since
    /// `|Q| ≥ |q.h| − |q.l| − eq ≥ |q.h|(1 − x)`, `x ≤ 1/2` decides the sign of `Q` (that
    /// of `q.h`) and, with `1/(1 − x) ≤ 1 + 2x`, `inv_lo = |inv|(1 + 2x)(1 + 8u) ≥ 1/|Q|`
    /// (no second division; `1/|Q| ≤ |inv|(1 + 2u)(1 + 2x)`, and the three roundings of
    /// `inv_lo` lose at most `(1 − u)³`: `(1 − u)³(1 + 8u) ≥ 1 + 2u`). `k ≥ |1/Q − inv|`:
    /// `|1/Q − 1/q.h| ≤ |Q − q.h|/(|Q||q.h|) ≤ (|q.l| + eq)·inv_lo·|inv|(1 + 2u)` and
    /// `|1/q.h − inv| ≤ u/|q.h| ≤ u|inv|(1 + 2u)`; `k = ((|q.l| + eq)·inv_lo + u)·|inv|·
    /// (1 + 8u)` covers both and its own four roundings (`(1 − u)⁵(1 + 8u) ≥ 1 + 2u`).
    #[inline(always)]
    pub fn prepare(q: &Dd<M, F>, eq: F) -> (F::Mask, Self) {
        let qa = q.h.abs();
        let in_range =
            F::splat(TINY).less_eq(qa) & qa.less_eq(F::splat(C_MAX)) & eq.less_eq(F::splat(C_MAX));
        let inv = F::splat(1.0) / q.h;
        let ia = inv.abs();
        let ql = q.l.abs();
        let x = (ql + eq) * ia * F::splat(1.0 + 8.0 * U);
        let ok = in_range & x.less_eq(F::splat(0.5));
        let inv_lo = ia * (F::splat(1.0) + F::splat(2.0) * x) * F::splat(1.0 + 8.0 * U);
        let k = ((ql + eq) * inv_lo + F::splat(U)) * ia * F::splat(1.0 + 8.0 * U);
        (
            ok,
            Denominator {
                q: *q,
                eq,
                inv,
                ql,
                inv_lo,
                k,
            },
        )
    }
}

const TINY: f64 = 1.1830521861667747e-271; // 2^-900
const C_MIN: f64 = 1.0261342003245941e-289; // 2^-960
const C_MAX: f64 = 1.0715086071862673e301; // 2^1000

/// Half the smaller of the two gaps next to the double `c` (`|c|` in `[2⁻⁹⁶⁰, 2¹⁰⁰⁰]`):
/// half an ulp, or a quarter of an ulp at a power of two (where the gap below is half
/// the gap above). A power of two, computed exactly from the exponent bits.
#[inline(always)]
fn half_gap<F: Lane>(c: F) -> F {
    // 2^e with 2^e ≤ |c| < 2^(e+1): the exponent field alone (exact, no rounding).
    let p = c.exponent_power();
    let half_ulp = p * F::splat(U); // 2^(e−53), exact (normal)
    F::select(p.equal(c.abs()), half_ulp * F::splat(0.5), half_ulp)
}

/// A correct rounding decided by the filter, lane-wise: where `ok`, the exact value lies
/// strictly between `c` and its neighbour on the side of the sign of `t`
/// ([`Decided::rounded`] builds the [`Rounded`]).
#[derive(Debug, Clone, Copy)]
pub struct Decided<F: Lane> {
    pub ok: F::Mask,
    pub c: F,
    pub t: F,
}

impl<F: Lane> Decided<F> {
    /// The enclosure `(lo, hi)`: `c` and its neighbour on the side of `t` (meaningful
    /// where `ok`, i.e. for `|c|` in `[2⁻⁹⁶⁰, 2¹⁰⁰⁰]`, a normal double).
    ///
    /// With `p = 2^e ≤ |c| < 2^(e+1)` (the exponent bits, exact), the doubles next to
    /// `c` are `ulp = p·2⁻⁵²` away, except below `|c|` when `|c| = p` (then `ulp/2`).
    /// `s = ±ulp` with the sign of `t`; `c + s` is a double (`c` shifted by one unit of
    /// its last place, or, towards zero at a power of two, `p(1 − 2⁻⁵²)`, which has 52
    /// significant bits), so the sum is exact; it is the neighbour unless it moved
    /// towards zero from `|c| = p`, where the neighbour is `c + s/2 = ±p(1 − 2⁻⁵³)`, also
    /// exact.
    #[inline(always)]
    pub fn enclosure(&self) -> (F, F) {
        let (c, zero) = (self.c, F::splat(0.0));
        let p = c.exponent_power();
        let ulp = p * F::splat(2.0 * U);
        let up = zero.less(self.t);
        let s = F::select(up, ulp, -ulp);
        let nb = c + s;
        let half = nb.abs().less(c.abs()) & p.equal(c.abs());
        let nb = F::select(half, c + s * F::splat(0.5), nb);
        (F::select(up, c, nb), F::select(up, nb, c))
    }
}

impl Decided<f64> {
    /// The rounding, when decided.
    #[inline(always)]
    pub fn rounded(self) -> Option<Rounded> {
        self.ok.then(|| self.value())
    }
    /// The rounding (meaningful where `ok`).
    #[inline(always)]
    pub fn value(self) -> Rounded {
        let (lo, hi) = self.enclosure();
        Rounded {
            nearest: self.c,
            lo,
            hi,
        }
    }
}

/// Decided roundings of several lanes unpacked for building answers lane by lane.
#[derive(Debug, Clone, Copy)]
pub struct RoundedLanes {
    nearest: [f64; MAX_LANES],
    lo: [f64; MAX_LANES],
    hi: [f64; MAX_LANES],
}

impl RoundedLanes {
    /// The rounding of lane `i` (meaningful where that lane was decided).
    #[inline(always)]
    pub fn get(&self, i: usize) -> Rounded {
        Rounded {
            nearest: self.nearest[i],
            lo: self.lo[i],
            hi: self.hi[i],
        }
    }
}

impl<F: Wide> Decided<F> {
    /// The roundings of every lane (enclosures computed in lanes).
    #[inline(always)]
    pub fn lanes(&self) -> RoundedLanes {
        let (lo, hi) = self.enclosure();
        let mut r = RoundedLanes {
            nearest: [0.0; MAX_LANES],
            lo: [0.0; MAX_LANES],
            hi: [0.0; MAX_LANES],
        };
        self.c.store(&mut r.nearest);
        lo.store(&mut r.lo);
        hi.store(&mut r.hi);
        r
    }
}

/// The exact quotient `P/Q` correctly rounded, where `p` approximates `P` with
/// absolute error at most `ep` and `d` is prepared from `Q` ([`Denominator::new`]) — if
/// the bounds decide the rounding and `P/Q` is provably not a double (a value that may
/// be a double goes to the exact tiers, which report `lo = hi`).
///
/// Method (one candidate, one residual, no second product): `c₀ = p.h·inv`; the
/// residual `R = P − c₀Q` is approximated by `r = r₁ + r₂` with `r₁ = p.h − c₀·q.h`
/// (FMA: one rounding; without FMA: `(m, e)` Dekker's exact product, `p.h − m` exact
/// by Sterbenz's lemma since `c₀ = fl(p.h·fl(1/q.h))` makes `m = fl(c₀q.h)` lie within
/// a factor `1 ± 4u` of `p.h`, then one rounding; should `c₀q.h` underflow, `e` loses at
/// most `η`, covered below) and `r₂ = p.l − c₀·q.l` (FMA: one rounding; without: the
/// product's, at most `u|c₀q.l|`, and the sum's). Then
///
/// `|R − r| ≤ E = ep + |c₀|·eq + u(|r₁| + |c₀||q.l| + |r₂| + |r|)`
///
/// (the inputs' errors, `|c₀ (Q − q)|`, and the four roundings). With `δ = fl(r·inv)`
/// and `P/Q = c₀ + R/Q`: `|R/Q − δ| ≤ E/|Q| + |r|·|1/Q − inv| + u|δ|
/// ≤ ε = E·inv_lo + |r|·k + u|δ|` (see [`Denominator::new`]). `(c, t) =
/// fast_two_sum(c₀, δ)` is exact when `|δ| ≤ |c₀|` (checked), so `P/Q − c = t + ρ`
/// with `|ρ| ≤ ε`. If `ε < |t|` and `|t| + ε` is below half the smaller gap next to `c`,
/// then `P/Q` lies strictly inside the rounding cell of `c`, on the side of `t`.
/// The bound is evaluated with `(1 + 16u)` for its own roundings (a tree of depth at
/// most ten over non-negative terms: `(1 − u)¹⁰(1 + 16u) ≥ 1`) and `8η` on each side of
/// the division for underflows: of `r₁`, `r₂`, `r` and the bound's products in the
/// residual's units (added to `E`), of `δ` and the bound's products in the quotient's.
/// Accepted only for `|c| ∈ [2⁻⁹⁶⁰, 2¹⁰⁰⁰]` (so the gap is a normal double); overflow
/// gives ∞ or NaN somewhere, and every comparison with NaN fails.
#[inline(always)]
pub fn round_over<M: ProductMode>(p: &Dd<M>, ep: f64, d: &Denominator<M>) -> Option<Rounded> {
    decide_over(p, ep, d).rounded()
}

/// [`round_over`] for any [`Lane`] type, the decision as a mask (the method and its
/// proof are those of [`round_over`], lane by lane).
#[inline(always)]
pub fn decide_over<M: ProductMode, F: Lane>(
    p: &Dd<M, F>,
    ep: F,
    d: &Denominator<M, F>,
) -> Decided<F> {
    let c0 = p.h * d.inv;
    let r1 = M::residual(p.h, c0, d.q.h);
    let r2 = M::mul_add(-c0, d.q.l, p.l);
    let r = r1 + r2;
    let delta = r * d.inv;
    let ca = c0.abs();
    let eta8 = F::splat(8.0 * ETA);
    let e_r = ep + ca * d.eq + F::splat(U) * (r1.abs() + ca * d.ql + r2.abs() + r.abs()) + eta8;
    let eps = (e_r * d.inv_lo + r.abs() * d.k + F::splat(U) * delta.abs())
        * F::splat(1.0 + 16.0 * U)
        + eta8;
    let (c, t) = fast_two_sum(c0, delta);
    let (ta, cabs) = (t.abs(), c.abs());
    let ok = delta.abs().less_eq(ca)
        & eps.less(ta)
        & F::splat(C_MIN).less_eq(cabs)
        & cabs.less_eq(F::splat(C_MAX))
        & ((ta + eps) * F::splat(1.0 + 4.0 * U)).less(half_gap(c));
    Decided { ok, c, t }
}

/// The exact quotient `P/Q` correctly rounded (see [`round_over`], which does the work
/// once the denominator is prepared by [`Denominator::new`]).
#[inline(always)]
pub fn round_ratio<M: ProductMode>(p: &Dd<M>, ep: f64, q: &Dd<M>, eq: f64) -> Option<Rounded> {
    round_over(p, ep, &Denominator::new(q, eq)?)
}

/// A polynomial value `P` correctly rounded, from `p` with `|P − p| ≤ ep`: `(c, t) =
/// two_sum(p.h, p.l)` is exact, so `P − c = t + ρ`, `|ρ| ≤ ep`; accepted when
/// `ep < |t|` and `|t| + ep` (rounded up by `(1 + 4u)`) is below half the smaller gap
/// next to `c`, for `|c| ∈ [2⁻⁹⁶⁰, 2¹⁰⁰⁰]`. (A value that may be a double is left to
/// the exact tiers, as in [`round_over`].)
#[inline(always)]
pub fn round_value<M: ProductMode>(p: &Dd<M>, ep: f64) -> Option<Rounded> {
    decide_value(p, ep).rounded()
}

/// [`round_value`] for any [`Lane`] type, the decision as a mask.
#[inline(always)]
pub fn decide_value<M: ProductMode, F: Lane>(p: &Dd<M, F>, ep: F) -> Decided<F> {
    let (c, t) = two_sum(p.h, p.l);
    let (ta, ca) = (t.abs(), c.abs());
    let ok = ep.less(ta)
        & F::splat(C_MIN).less_eq(ca)
        & ca.less_eq(F::splat(C_MAX))
        & ((ta + ep) * F::splat(1.0 + 4.0 * U)).less(half_gap(c));
    Decided { ok, c, t }
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
        corners::<WithFma>();
        corners::<WithoutFma>();
    }

    fn q(x: f64) -> Rational {
        Rational::from_f64(x).unwrap()
    }

    /// Soundness at the extremes of the error bounds: whenever a rounding is accepted for
    /// `p ± ep` over `q ± eq`, it is the rounding of every corner quotient; and with
    /// exact data nearly every quotient is decided (the test is not vacuous).
    fn corners<M: ProductMode>() {
        let mut seed = 0x0DDB_1A5E_5BAD_5EEDu64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let (mut decided_exact, mut decided_loose) = (0, 0);
        for i in 0..4000 {
            let scale = 2f64.powi((i % 61) - 30);
            let ph = next() * scale;
            let p = Dd::<M>::from_parts(ph, ph * next() * 1e-16);
            let qh = next() + 0.75 * next().signum();
            let q_dd = Dd::<M>::from_parts(qh, qh * next() * 1e-16);
            let (pv, qv) = (q(p.h) + q(p.l), q(q_dd.h) + q(q_dd.l));
            if let Some(r) = round_ratio(&p, 0.0, &q_dd, 0.0) {
                decided_exact += 1;
                assert_eq!(r, round_rational(&(pv.clone() / &qv)));
            }
            // Error bounds of a few hundredths of an ulp of the quotient: accepted or not,
            // an accepted rounding must hold at all four corners.
            let ulp = (ph / qh).abs() * f64::EPSILON;
            let (ep, eq) = (
                ulp * qh.abs() * 0.03 * (next() + 0.5),
                1e-18 * (next() + 0.5),
            );
            if let Some(r) = round_ratio(&p, ep, &q_dd, eq) {
                decided_loose += 1;
                for (dp, dq) in [(ep, eq), (ep, -eq), (-ep, eq), (-ep, -eq)] {
                    let corner = (pv.clone() + q(dp)) / (qv.clone() + q(dq));
                    assert_eq!(r, round_rational(&corner), "{i}");
                }
            }
        }
        assert!(decided_exact > 3990, "{decided_exact}");
        assert!(decided_loose > 3000, "{decided_loose}");
        // Values: (1 + 2^-60) rounds down to 1, just above; 1/3 as a double-double.
        let v = Dd::<M>::from_parts(1.0, 2f64.powi(-60));
        assert_eq!(
            round_value(&v, 0.0),
            Some(Rounded::inexact(1.0, Ordering::Greater))
        );
        assert_eq!(round_value(&v, 2f64.powi(-59)), None);
        let third = Dd::<M>::from_parts(1.0 / 3.0, 1.850371707708594e-17);
        let truth = round_rational(&(q(third.h) + q(third.l)));
        assert_eq!(round_value(&third, 1e-30), Some(truth));
        assert_eq!(round_value(&Dd::<M>::from_f64(3.0), 0.0), None);
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
