//! The last tier: the exact decision procedure of an operation run in `rug::Rational` on
//! the exact values of the double inputs, its results correctly rounded
//! ([`crate::num::round`]). `Certified::bits` reports the bit length of the largest
//! numerator or denominator rounded.

use rug::Rational;

use crate::certificate::{Arithmetic, Certified};
use crate::num::expansion::{round_quotient, Expansion, Poison};
use crate::num::ratio::Ratio;
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

/// Rounds results of the expansion tier; a value it cannot round (out of range)
/// marks the whole answer for the rational tier.
#[derive(Debug)]
pub(crate) struct ExpansionRounder {
    ok: bool,
    len: usize,
}

impl ExpansionRounder {
    /// `x` correctly rounded (a placeholder NaN when it cannot be: see `ok`).
    pub(crate) fn round(&mut self, x: Ratio<Expansion>) -> Rounded {
        let den = x.denominator();
        self.len = self.len.max(x.num.len()).max(den.len());
        round_quotient(&x.num, &den).unwrap_or_else(|| {
            self.ok = false;
            Rounded::exact(f64::NAN)
        })
    }
    /// A direction component: only unscaled directions (exponent 0, see
    /// `plane_plane::PlaneLine`) are handled here; the largest component's estimate must
    /// lie well inside `[2⁻¹⁰⁰⁰, 2¹⁰⁰⁰)`.
    pub(crate) fn check_unscaled(&mut self, dir: &[Ratio<Expansion>]) {
        let big = dir
            .iter()
            .map(|x| (x.num.estimate() / x.denominator().estimate()).abs())
            .fold(0.0, f64::max);
        if !(big >= 2f64.powi(-999) && big < 2f64.powi(999)) {
            self.ok = false;
        }
    }
}

/// Run the expansion tier: `None` when it lost exactness (poison) or could not round.
pub(crate) fn expansion_tier<T>(
    f: impl FnOnce(&mut ExpansionRounder) -> T,
) -> Option<Certified<T>> {
    Poison::reset();
    let mut r = ExpansionRounder { ok: true, len: 1 };
    let value = f(&mut r);
    if Poison::is_set() || !r.ok {
        return None;
    }
    Some(Certified::exact(
        value,
        Arithmetic::Expansion,
        53 * r.len as u32,
    ))
}

/// The certificate of an answer decided by the double-double filter.
pub(crate) fn filter_certified<T>(value: T) -> Certified<T> {
    Certified::exact(value, Arithmetic::Filter, 106)
}
