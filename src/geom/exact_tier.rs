//! The exact tiers after the filter: the exact decision procedure of an operation run
//! on the exact values of the double inputs in an exact ring — fixed-width dyadic
//! integers ([`SmallInteger`], then [`WideInteger`]; `Arithmetic::Integer`), then
//! floating-point expansions (`Arithmetic::Expansion`), each as unreduced quotients
//! ([`Ratio`]), each giving up (poison) when its range or width is exceeded — and last
//! in `rug::Rational`, which always answers. Results are correctly rounded
//! ([`crate::num::round`]).
//! `Certified::bits` reports the bit length of the largest numerator or denominator
//! rounded (for expansions, 53 × the largest number of components).

use std::marker::PhantomData;

use rug::Rational;

use crate::certificate::{Arithmetic, Certified};
use crate::num::dyadic::{round_quotient as round_dyadic_quotient, Dyadic};
use crate::num::dyadic128::Dyadic128;
use crate::num::expansion::{round_quotient as round_expansion_quotient, Expansion, Poison};
use crate::num::ratio::{Ratio, SignedRing};
use crate::num::round::{round_rational, round_rational_scaled, sqrt_rational, Rounded};

/// Rounds exact results and remembers the largest bit length seen.
#[derive(Debug, Default)]
pub(crate) struct Rounder {
    bits: u32,
}

impl Rounder {
    fn see(&mut self, q: &Rational) {
        let b = q
            .numer()
            .significant_bits()
            .max(q.denom().significant_bits());
        self.bits = self.bits.max(b);
    }
    /// `q` correctly rounded.
    pub(crate) fn round(&mut self, q: Rational) -> Rounded {
        self.see(&q);
        round_rational(&q)
    }
    /// `q · 2^k` correctly rounded (directions scaled into range).
    pub(crate) fn round_scaled(&mut self, q: Rational, k: i32) -> Rounded {
        self.see(&q);
        round_rational_scaled(&q, k)
    }
    /// `√q` correctly rounded, `q ≥ 0`.
    pub(crate) fn sqrt(&mut self, q: &Rational) -> Rounded {
        self.see(q);
        sqrt_rational(q)
    }
    /// The certificate of an answer decided in rationals.
    pub(crate) fn certify<T>(&self, value: T) -> Certified<T> {
        Certified::exact(value, Arithmetic::Rational, self.bits.max(1))
    }
}

/// An exact ring that can serve as a tier between the filter and rationals: exact
/// signs, correctly rounded quotients, and a size to report. Its operations signal a
/// loss of exactness (range or width) through [`Poison`].
pub(crate) trait ExactRing: SignedRing {
    /// The arithmetic reported in the certificate.
    const ARITHMETIC: Arithmetic;
    /// `p/q` correctly rounded, or `None` when this ring cannot round it.
    fn round_quotient(p: &Self, q: &Self) -> Option<Rounded>;
    /// An approximation of the value (used only for range checks: 0, ∞ or NaN fail them).
    fn estimate(&self) -> f64;
    /// The size reported as `Certified::bits`.
    fn bits(&self) -> u32;
}

impl ExactRing for Expansion {
    const ARITHMETIC: Arithmetic = Arithmetic::Expansion;
    fn round_quotient(p: &Self, q: &Self) -> Option<Rounded> {
        round_expansion_quotient(p, q)
    }
    fn estimate(&self) -> f64 {
        Expansion::estimate(self)
    }
    fn bits(&self) -> u32 {
        53 * self.len() as u32
    }
}

/// The first attempt of the integer tier: 128-bit integers in native arithmetic, enough
/// for exactly degenerate configurations on short dyadic data (the common degenerate
/// input: small integers, grid coordinates), even in the degree-11 line test.
pub(crate) type SmallInteger = Dyadic128;

/// The second attempt: 12 limbs (768-bit integers). The degree-11 formulas (the
/// three-plane line test) of full 53-bit data fit while the exponent spread of the data
/// stays below ~15 bits, the degree-7 point formulas below ~55 bits; others overflow
/// and escalate to expansions.
pub(crate) type WideInteger = Dyadic<12>;

impl ExactRing for Dyadic128 {
    const ARITHMETIC: Arithmetic = Arithmetic::Integer;
    #[inline]
    fn round_quotient(p: &Self, q: &Self) -> Option<Rounded> {
        Dyadic128::round_quotient(p, q)
    }
    fn estimate(&self) -> f64 {
        Dyadic128::estimate(self)
    }
    fn bits(&self) -> u32 {
        self.bit_len()
    }
}

impl<const N: usize> ExactRing for Dyadic<N> {
    const ARITHMETIC: Arithmetic = Arithmetic::Integer;
    #[inline]
    fn round_quotient(p: &Self, q: &Self) -> Option<Rounded> {
        round_dyadic_quotient(p, q)
    }
    fn estimate(&self) -> f64 {
        Dyadic::estimate(self)
    }
    fn bits(&self) -> u32 {
        self.bit_len()
    }
}

/// Rounds results of an exact-ring tier; a value it cannot round (out of range)
/// marks the whole answer for the next tier.
#[derive(Debug)]
pub(crate) struct RingRounder<E> {
    ok: bool,
    bits: u32,
    ring: PhantomData<E>,
}

impl<E: ExactRing> RingRounder<E> {
    /// `x` correctly rounded (a placeholder NaN when it cannot be: see `ok`).
    #[inline]
    pub(crate) fn round(&mut self, x: Ratio<E>) -> Rounded {
        let one = E::one();
        let den = x.den.as_ref().unwrap_or(&one);
        self.bits = self.bits.max(x.num.bits()).max(den.bits());
        E::round_quotient(&x.num, den).unwrap_or_else(|| {
            self.ok = false;
            Rounded::exact(f64::NAN)
        })
    }
    /// A direction component: only unscaled directions (exponent 0, see
    /// `plane_plane::PlaneLine`) are handled here; the largest component's estimate must
    /// lie well inside `[2⁻¹⁰⁰⁰, 2¹⁰⁰⁰)`.
    pub(crate) fn check_unscaled(&mut self, dir: &[Ratio<E>]) {
        let big = dir
            .iter()
            .map(|x| match &x.den {
                None => x.num.estimate().abs(),
                Some(d) => (x.num.estimate() / d.estimate()).abs(),
            })
            .fold(0.0, f64::max);
        if !(big >= 2f64.powi(-999) && big < 2f64.powi(999)) {
            self.ok = false;
        }
    }
}

/// Run an exact-ring tier: `None` when it lost exactness (poison) or could not round.
#[inline]
pub(crate) fn ring_tier<E: ExactRing, T>(
    f: impl FnOnce(&mut RingRounder<E>) -> T,
) -> Option<Certified<T>> {
    Poison::reset();
    let mut r = RingRounder {
        ok: true,
        bits: E::one().bits(),
        ring: PhantomData,
    };
    let value = f(&mut r);
    if Poison::is_set() || !r.ok {
        return None;
    }
    Some(Certified::exact(value, E::ARITHMETIC, r.bits))
}

/// The certificate of an answer decided by the double-double filter.
pub(crate) fn filter_certified<T>(value: T) -> Certified<T> {
    Certified::exact(value, Arithmetic::Filter, 106)
}
