//! The last tier: the exact decision procedure of an operation run in `rug::Rational` on
//! the exact values of the double inputs, its results correctly rounded
//! ([`crate::num::round`]). `Certified::bits` reports the bit length of the largest
//! numerator or denominator rounded.

use rug::Rational;

use crate::certificate::{Arithmetic, Certified};
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

/// The certificate of an answer decided by the double-double filter.
pub(crate) fn filter_certified<T>(value: T) -> Certified<T> {
    Certified::exact(value, Arithmetic::Filter, 106)
}
