//! Double-double ("double-word") arithmetic built from error-free transformations, the
//! evaluation type of the filter tier of the linear kernel.
//!
//! A [`Dd`] holds an unevaluated sum `h + l`. It is *not* renormalised after each
//! operation (the low part may exceed `ulp(h)`, e.g. after cancellation): the error
//! analysis bounds `|h|` and `|l|` separately in terms of the operands' bounds, which is
//! what [`crate::num::error_bound::ErrorBound`] propagates through a formula to derive a
//! filter constant. Skipping the renormalisation halves the cost of an addition. The
//! bounds assume no overflow and count underflow separately (`η = 2⁻¹⁰⁷⁴` per rounded
//! product); the callers' range guards make both hold (`num::filter`).
//!
//! * `two_sum(a, b)` (Knuth, 6 flops) and `fast_two_sum` (Dekker, 3 flops, needs
//!   `exponent(a) ≥ exponent(b)` or `a = 0`) are exact.
//! * `two_prod(a, b)` is exact: with FMA `e = fma(a, b, −p)`; without, Dekker's product
//!   with Veltkamp splitting (exact for `|a|, |b| < 2⁹⁹⁵` and `e_a + e_b ≥ −969`; otherwise
//!   its error is at most `η`).
//! * add: `(s, t) = two_sum(a.h, b.h)`, result `(s, (t + a.l) + b.l)`. Only the low part
//!   is rounded, twice: `|err| ≤ u|t + a.l| + u|v|` with `|t| ≤ u|s|`,
//!   `|s| ≤ (1+u)(|a.h| + |b.h|)`, `|v| ≤ (1+u)²(u|s| + |a.l| + |b.l|)`. Additions never
//!   underflow (sums of doubles that are subnormal are exact).
//! * mul: `(p, e) = two_prod(a.h, b.h)`, `e' = e + a.h·b.l`, `e'' = e' + a.l·b.h` (one
//!   rounding each with FMA, two without), `a.l·b.l` dropped, result `(p, e'')`:
//!   `|err| ≤ u|a.h b.l| + u|e'| + u|a.l b.h| + u|e''| + |a.l b.l| + 3η` with
//!   `|e'| ≤ (1+u)²(u|p| + |a.h b.l|)`, `|e''| ≤ (1+u)²(|e'| + |a.l b.h|)`.

use std::marker::PhantomData;

use super::lane::Lane;
use super::ring::Ring;

/// u = 2⁻⁵³, the unit roundoff of binary64.
pub const U: f64 = f64::EPSILON / 2.0;
/// η = 2⁻¹⁰⁷⁴, the smallest subnormal: the absolute error of an underflowing product.
pub const ETA: f64 = 5e-324;

/// How a double product is made error-free: with a fused multiply-add or with
/// Dekker's algorithm. A type parameter so that each instantiation is compiled
/// straight-line; the FMA one is called from `#[target_feature(enable = "fma")]`
/// functions on x86-64 (`geom::filter::fma_available`). Generic over the [`Lane`]
/// type: one `f64` or four lanes, each lane computing what the scalar code computes.
pub trait ProductMode: Copy + std::fmt::Debug + PartialEq + 'static {
    /// `(p, e)` with `p = fl(ab)` and `p + e = ab` exactly.
    fn two_prod<F: Lane>(a: F, b: F) -> (F, F);
    /// `a·b + c` with one or two roundings.
    fn mul_add<F: Lane>(a: F, b: F, c: F) -> F;
    /// `p − c·q` with one rounding, provided `fl(c·q)` lies within a factor 2 of `p`
    /// (then `p − fl(c·q)` is exact by Sterbenz's lemma and only the final subtraction
    /// of the product's error rounds; with FMA it is one fused operation).
    fn residual<F: Lane>(p: F, c: F, q: F) -> F;
}

/// Products through `f64::mul_add` (an instruction where the caller enables FMA).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WithFma;
/// Products through Dekker's algorithm (no FMA needed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WithoutFma;

impl ProductMode for WithFma {
    #[inline(always)]
    fn two_prod<F: Lane>(a: F, b: F) -> (F, F) {
        let p = a * b;
        (p, a.fused_mul_add(b, -p))
    }
    #[inline(always)]
    fn mul_add<F: Lane>(a: F, b: F, c: F) -> F {
        a.fused_mul_add(b, c)
    }
    #[inline(always)]
    fn residual<F: Lane>(p: F, c: F, q: F) -> F {
        (-c).fused_mul_add(q, p)
    }
}

impl ProductMode for WithoutFma {
    #[inline(always)]
    fn two_prod<F: Lane>(a: F, b: F) -> (F, F) {
        let p = a * b;
        let (ah, al) = split(a);
        let (bh, bl) = split(b);
        let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
        (p, e)
    }
    #[inline(always)]
    fn mul_add<F: Lane>(a: F, b: F, c: F) -> F {
        a * b + c
    }
    #[inline(always)]
    fn residual<F: Lane>(p: F, c: F, q: F) -> F {
        let (m, e) = Self::two_prod(c, q);
        (p - m) - e
    }
}

/// Veltkamp's split of `a` into two 26-bit halves, `a = h + l` exactly.
#[inline(always)]
fn split<F: Lane>(a: F) -> (F, F) {
    let t = F::splat(134217729.0) * a; // 2^27 + 1
    let h = t - (t - a);
    (h, a - h)
}

/// `(s, t)` with `s = fl(a + b)` and `s + t = a + b` exactly (Knuth).
#[inline(always)]
pub fn two_sum<F: Lane>(a: F, b: F) -> (F, F) {
    let s = a + b;
    let bb = s - a;
    let t = (a - (s - bb)) + (b - bb);
    (s, t)
}

/// [`two_sum`] when `exponent(a) ≥ exponent(b)` or `a = 0` (Dekker).
#[inline(always)]
pub fn fast_two_sum<F: Lane>(a: F, b: F) -> (F, F) {
    let s = a + b;
    (s, b - (s - a))
}

/// A double-double `h + l` (not necessarily normalised); with `F = F4`, four of them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dd<M: ProductMode, F: Lane = f64> {
    pub h: F,
    pub l: F,
    mode: PhantomData<M>,
}

impl<M: ProductMode> Dd<M> {
    /// The double `x`, exactly.
    #[inline(always)]
    pub fn from_f64(x: f64) -> Self {
        Dd::exact(x)
    }
}

impl<M: ProductMode, F: Lane> Dd<M, F> {
    /// The double (or lanes) `x`, exactly.
    #[inline(always)]
    pub fn exact(x: F) -> Self {
        Dd::new(x, F::splat(0.0))
    }
    /// `if m { a } else { b }`, lane by lane (exact: both parts are taken as they are).
    #[inline(always)]
    pub fn select(m: F::Mask, a: &Self, b: &Self) -> Self {
        Dd::new(F::select(m, a.h, b.h), F::select(m, a.l, b.l))
    }
    /// `h + l` from its parts.
    #[inline(always)]
    pub fn from_parts(h: F, l: F) -> Self {
        Dd::new(h, l)
    }
    /// The same value renormalised (`|l| ≤ ulp(h)/2`), exactly.
    #[inline(always)]
    pub fn normalized(&self) -> Self {
        let (h, l) = two_sum(self.h, self.l);
        Dd::new(h, l)
    }
    #[inline(always)]
    fn new(h: F, l: F) -> Self {
        Dd {
            h,
            l,
            mode: PhantomData,
        }
    }
}

impl<M: ProductMode> Dd<M> {
    /// True when every part is finite (an overflow makes a part infinite or NaN).
    #[inline(always)]
    pub fn is_finite(&self) -> bool {
        (self.h + self.l).is_finite()
    }
}

impl<M: ProductMode, F: Lane> Ring for Dd<M, F> {
    #[inline(always)]
    fn zero() -> Self {
        Self::exact(F::splat(0.0))
    }
    #[inline(always)]
    fn one() -> Self {
        Self::exact(F::splat(1.0))
    }
    #[inline(always)]
    fn plus(&self, b: &Self) -> Self {
        let (s, t) = two_sum(self.h, b.h);
        Dd::new(s, (t + self.l) + b.l)
    }
    #[inline(always)]
    fn minus(&self, b: &Self) -> Self {
        self.plus(&b.negate())
    }
    #[inline(always)]
    fn times(&self, b: &Self) -> Self {
        let (p, e) = M::two_prod(self.h, b.h);
        let e = M::mul_add(self.h, b.l, e);
        let e = M::mul_add(self.l, b.h, e);
        Dd::new(p, e)
    }
    #[inline(always)]
    fn negate(&self) -> Self {
        Dd::new(-self.h, -self.l)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;

    fn exact<M: ProductMode>(x: &Dd<M>) -> Rational {
        Rational::from_f64(x.h).unwrap() + Rational::from_f64(x.l).unwrap()
    }

    fn check_ops<M: ProductMode>() {
        let mut seed = 0x2545F4914F6CDD1Du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for _ in 0..2000 {
            let a = Dd::<M>::from_f64(next()).times(&Dd::from_f64(next()));
            let b = Dd::<M>::from_f64(next())
                .plus(&Dd::from_f64(next() * 1e-3))
                .normalized();
            let u2 = Rational::from_f64(U * U).unwrap();
            let mag = |x: &Dd<M>| Rational::from_f64(x.h.abs()).unwrap();
            // Operands with |l| ≤ u|h| (as products of doubles are): then
            // add: |err| ≤ 5u²(|a.h| + |b.h|), mul: |err| ≤ 8u²|a.h||b.h| (no underflow here).
            let s = a.plus(&b);
            let err = (exact(&s) - exact(&a) - exact(&b)).abs();
            assert!(err <= Rational::from(&u2 * 5u32) * (mag(&a) + mag(&b)));
            let p = a.times(&b);
            let err = (exact(&p) - exact(&a) * exact(&b)).abs();
            assert!(err <= Rational::from(&u2 * 8u32) * mag(&a) * mag(&b));
        }
    }

    #[test]
    fn operations_meet_their_documented_bounds() {
        check_ops::<WithFma>();
        check_ops::<WithoutFma>();
    }

    #[test]
    fn products_are_error_free() {
        let (a, b) = (1.0 + f64::EPSILON, 1.0 - f64::EPSILON);
        for (p, e) in [WithFma::two_prod(a, b), WithoutFma::two_prod(a, b)] {
            let exact = Rational::from_f64(a).unwrap() * Rational::from_f64(b).unwrap();
            assert_eq!(
                Rational::from_f64(p).unwrap() + Rational::from_f64(e).unwrap(),
                exact
            );
        }
        let (s, t) = two_sum(1e16, 1.0 + f64::EPSILON * 4.0);
        assert_eq!(
            Rational::from_f64(s).unwrap() + Rational::from_f64(t).unwrap(),
            Rational::from_f64(1e16).unwrap()
                + Rational::from_f64(1.0 + f64::EPSILON * 4.0).unwrap()
        );
    }
}
