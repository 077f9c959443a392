//! Test helpers: a deterministic generator of doubles over the whole range (subnormals,
//! huge, tiny, special), and exact checks of directed rounding with `rug::Rational`.

use rug::{Float, Rational};

/// xorshift64*: deterministic, no dependency.
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64) -> Rng {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    pub(crate) fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in [0, 1).
    pub(crate) fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    pub(crate) fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// A finite double with a random sign, a random exponent in [emin, emax] (binary
    /// exponents; below −1022 gives subnormals) and random mantissa bits; one call in 16
    /// returns a special value (0, ±MIN_POSITIVE, ±smallest subnormal, ±MAX, ±1).
    pub(crate) fn double(&mut self, emin: i32, emax: i32) -> f64 {
        let r = self.next_u64();
        if r.is_multiple_of(16) {
            let specials = [
                0.0,
                f64::MIN_POSITIVE,
                f64::from_bits(1),
                f64::MAX,
                1.0,
                0.5,
            ];
            let v = specials[(r >> 8) as usize % specials.len()];
            return if r & 0x10000 != 0 { -v } else { v };
        }
        let e = emin + (self.next_u64() % (emax - emin + 1) as u64) as i32;
        let m = 1.0 + (self.next_u64() >> 12) as f64 / (1u64 << 52) as f64;
        let v = Float::with_val(64, m) << e;
        let v = v.to_f64();
        if r & 2 != 0 {
            -v
        } else {
            v
        }
    }
}

/// The exact value of a finite double.
pub(crate) fn exact(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

/// `r` is `x` rounded toward +∞ to a double: `r ≥ x` and the double below `r` is `< x`.
pub(crate) fn is_rounded_up(r: f64, x: &Rational) -> bool {
    let below = super::directed::next_down(r);
    let ge = r == f64::INFINITY || (r.is_finite() && exact(r) >= *x);
    let below_lt = below == f64::NEG_INFINITY || (below.is_finite() && exact(below) < *x);
    ge && below_lt
}

/// `r` is `x` rounded toward −∞.
pub(crate) fn is_rounded_down(r: f64, x: &Rational) -> bool {
    is_rounded_up(-r, &Rational::from(-x))
}

/// `lo ≤ v ≤ hi` for an MPFR value and double bounds, compared exactly.
pub(crate) fn encloses(lo: f64, hi: f64, v: &Float) -> bool {
    *v >= lo && *v <= hi
}

/// A random interval: two random doubles (`Rng::double`) as bounds; a point in 30% of
/// the draws.
pub(crate) fn random_interval(rng: &mut Rng, emin: i32, emax: i32) -> super::Interval {
    let a = rng.double(emin, emax);
    let b = if rng.unit() < 0.3 {
        a
    } else {
        rng.double(emin, emax)
    };
    super::Interval::from_bounds(a.min(b), a.max(b))
}
