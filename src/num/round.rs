//! Correctly rounded doubles with a proven enclosure (docs/CERTIFICATES.md level `exact`:
//! the reported coordinates are the exact values correctly rounded to the nearest double).
//!
//! Accuracy policy: `nearest` is the exact value rounded to nearest, ties to even, with
//! IEEE-754 binary64 subnormals and overflow (a value at or beyond
//! `f64::MAX + ulp(f64::MAX)/2` has no finite rounding; see [`Rounded::overflowed`]).
//! The enclosure is tight: `lo == hi == nearest` when the value is a double, otherwise
//! `lo < value < hi` with `lo`, `hi` adjacent doubles (open interval).
//!
//! Conversions from `rug::Rational` go through MPFR (`rug::Float`) at 53 bits, rounded to
//! nearest, in the normal range (where doubles have exactly 53 bits), and through integer
//! rounding of `x·2¹⁰⁷⁴` below it. (rug 1.19's `Rational::to_f64` truncates towards zero,
//! and its `subnormalize_ieee_round` ignores values below the smallest subnormal; neither
//! is used for results.)

use rug::float::Round;
use rug::{Float, Rational};
use std::cmp::Ordering;

/// An exact real value, correctly rounded to nearest, with a proven enclosure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rounded {
    /// The value rounded to nearest (ties to even). ±∞ when the value is beyond the
    /// double range ([`Rounded::overflowed`]).
    pub nearest: f64,
    /// Lower end of the enclosure (see the module documentation).
    pub lo: f64,
    /// Upper end of the enclosure.
    pub hi: f64,
}

impl Rounded {
    /// A value that is exactly the double `x`.
    pub fn exact(x: f64) -> Rounded {
        Rounded {
            nearest: x,
            lo: x,
            hi: x,
        }
    }

    /// `x` is the nearest double and the value lies strictly between `x` and its
    /// neighbour on the side given by `side` (`Greater`: the value is above `x`).
    #[inline]
    pub fn inexact(x: f64, side: Ordering) -> Rounded {
        match side {
            Ordering::Greater => Rounded {
                nearest: x,
                lo: x,
                hi: next_up(x),
            },
            Ordering::Less => Rounded {
                nearest: x,
                lo: next_down(x),
                hi: x,
            },
            Ordering::Equal => Rounded::exact(x),
        }
    }

    /// True when the value is exactly the double `nearest`.
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }

    /// True when the value lies beyond the double range (its rounding to nearest is
    /// ±∞; the enclosure is then `[f64::MAX, +∞]` or `[−∞, −f64::MAX]`). Callers report
    /// such a value as out of range; it is never printed as a number.
    pub fn overflowed(&self) -> bool {
        self.nearest.is_infinite()
    }

    /// Exact comparison of the value with a double, decided from the tight enclosure.
    pub fn compare_f64(&self, x: f64) -> Ordering {
        if self.is_exact() {
            return self.nearest.partial_cmp(&x).unwrap_or(Ordering::Equal);
        }
        // lo < value < hi with lo, hi adjacent: no double lies strictly inside.
        if x <= self.lo {
            Ordering::Greater
        } else {
            Ordering::Less
        }
    }

    /// The value's sign (exact).
    pub fn sign(&self) -> Ordering {
        self.compare_f64(0.0)
    }
}

/// The next double above `x` (`f64::next_up`, written out for the crate's MSRV 1.80).
#[inline]
pub fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let b = x.to_bits();
    f64::from_bits(if x > 0.0 { b + 1 } else { b - 1 })
}

/// The next double below `x`.
#[inline]
pub fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// Round an exact rational to the nearest double, with its enclosure.
pub fn round_rational(x: &Rational) -> Rounded {
    if x.cmp0() == Ordering::Equal {
        return Rounded::exact(0.0);
    }
    let min_normal = Rational::from_f64(f64::MIN_POSITIVE).unwrap_or_default();
    if Rational::from(x.abs_ref()) < min_normal {
        return round_subnormal(x);
    }
    let (f, dir) = Float::with_val_round(53, x, Round::Nearest);
    from_rounded_float(&f, dir)
}

/// Below 2⁻¹⁰²² the doubles are the multiples of 2⁻¹⁰⁷⁴: round `x·2¹⁰⁷⁴` to the nearest
/// integer, ties to even, in integers. (MPFR's `subnormalize` through rug 1.19 leaves
/// values below the smallest subnormal untouched, so it is not used.)
fn round_subnormal(x: &Rational) -> Rounded {
    let y = Rational::from(x << 1074u32);
    let (fl, frac) = {
        let f = Rational::from(y.floor_ref());
        let r = Rational::from(&y - &f);
        (f, r)
    };
    let half = Rational::from((1, 2));
    let k = match frac.cmp(&half) {
        Ordering::Less => fl.clone(),
        Ordering::Greater => fl.clone() + 1u32,
        Ordering::Equal => {
            if fl.numer().is_even() {
                fl.clone()
            } else {
                fl.clone() + 1u32
            }
        }
    };
    let c = k.to_f64() * f64::from_bits(1); // |k| ≤ 2^52: both steps exact
    let side = y.cmp(&k);
    Rounded::inexact(c, side)
}

/// Build a [`Rounded`] from a 53-bit MPFR float in the normal range, whose ternary
/// value `dir` compares it with the exact value.
fn from_rounded_float(f: &Float, dir: Ordering) -> Rounded {
    // 2^1024: the first power of two beyond the double range.
    let limit = Float::with_val(53, Float::u_exp(1, 1024));
    if f.clone().abs() >= limit {
        return if f.is_sign_positive() {
            Rounded {
                nearest: f64::INFINITY,
                lo: f64::MAX,
                hi: f64::INFINITY,
            }
        } else {
            Rounded {
                nearest: f64::NEG_INFINITY,
                lo: f64::NEG_INFINITY,
                hi: -f64::MAX,
            }
        };
    }
    let d = f.to_f64();
    // dir compares the rounded value with the exact one: Less means rounded < exact.
    Rounded::inexact(d, dir.reverse())
}

/// `x · 2^k`, exactly, then rounded: used to report directions scaled into range.
pub fn round_rational_scaled(x: &Rational, k: i32) -> Rounded {
    round_rational(&scale_pow2(x, k))
}

/// `x · 2^k` exactly.
pub fn scale_pow2(x: &Rational, k: i32) -> Rational {
    let mut r = x.clone();
    if k >= 0 {
        r <<= k as u32;
    } else {
        r >>= k.unsigned_abs();
    }
    r
}

/// The exponent `e` with `2^e ≤ |x| < 2^(e+1)` of a non-zero rational.
pub fn exponent_of(x: &Rational) -> Option<i64> {
    if x.cmp0() == Ordering::Equal {
        return None;
    }
    let f = Float::with_val_round(64, x, Round::Down).0.abs();
    // Rounding down at 64 bits keeps the power of two: 2^e ≤ f ≤ |x| < 2^(e+1).
    f.get_exp().map(|e| i64::from(e) - 1)
}

/// The correctly rounded square root of a non-negative rational, Ziv-style:
/// MPFR square roots rounded down and up at rising precision until both round to the
/// same double and the side is known; the cases where that never happens are decided
/// by exact tests first (the root is a double, or the midpoint between two doubles).
pub fn sqrt_rational(q: &Rational) -> Rounded {
    if q.cmp0() != Ordering::Greater {
        return Rounded::exact(0.0);
    }
    let mut prec = 64u32;
    loop {
        let mut lo = Float::with_val_round(prec, q, Round::Down).0;
        lo.sqrt_round(Round::Down);
        let mut hi = Float::with_val_round(prec, q, Round::Up).0;
        hi.sqrt_round(Round::Up);
        let (a, a_dir) = round_float_to_f64(&lo);
        let (b, _) = round_float_to_f64(&hi);
        if a == b {
            if a.is_infinite() {
                return from_rounded_float(&Float::with_val(53, Float::u_exp(1, 1024)), a_dir);
            }
            let c = Float::with_val(53, a);
            if c < lo {
                return Rounded::inexact(a, Ordering::Greater);
            }
            if c > hi {
                return Rounded::inexact(a, Ordering::Less);
            }
            // lo ≤ a ≤ hi: the root may be exactly a.
            if Rational::from_f64(a).map(|r| Rational::from(&r * &r) == *q) == Some(true) {
                return Rounded::exact(a);
            }
        } else if b == next_up(a) {
            // The root may be the midpoint m of a and b: then it is a tie.
            let m = (Rational::from_f64(a).unwrap_or_default()
                + Rational::from_f64(b).unwrap_or_default())
                / 2u32;
            if Rational::from(&m * &m) == *q {
                let even = if a.to_bits() & 1 == 0 { a } else { b };
                return Rounded {
                    nearest: even,
                    lo: a,
                    hi: b,
                };
            }
        }
        prec *= 2;
    }
}

/// Round an MPFR float to the nearest double (IEEE subnormals and overflow included).
fn round_float_to_f64(x: &Float) -> (f64, Ordering) {
    let r = x
        .to_rational()
        .map(|q| round_rational(&q))
        .unwrap_or(Rounded::exact(f64::NAN));
    let dir = if r.is_exact() {
        Ordering::Equal
    } else if r.lo == r.nearest {
        Ordering::Less
    } else {
        Ordering::Greater
    };
    (r.nearest, dir)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rational_rounding_is_to_nearest_not_truncation() {
        // 1/3 rounds up in binary64? 0x3FD5555555555555 is below 1/3: nearest is it.
        let third = Rational::from((1, 3));
        let r = round_rational(&third);
        assert_eq!(r.nearest, 1.0 / 3.0);
        assert!(!r.is_exact());
        // 2/3 = 0x3FE5555555555555 + ...: division in f64 is correctly rounded.
        let r = round_rational(&Rational::from((2, 3)));
        assert_eq!(r.nearest, 2.0 / 3.0);
        // A value just above a midpoint rounds up where truncation would not.
        let one = Rational::from(1);
        let ulp = Rational::from_f64(f64::EPSILON).unwrap();
        let above_mid = &one + Rational::from(&ulp / 2u32) + Rational::from(&ulp / 1024u32);
        let r = round_rational(&above_mid);
        assert_eq!(r.nearest, 1.0 + f64::EPSILON);
        assert_eq!((r.lo, r.hi), (1.0, 1.0 + f64::EPSILON));
    }

    #[test]
    fn subnormals_overflow_and_ties() {
        let tiny = Rational::from_f64(f64::from_bits(1)).unwrap(); // 2^-1074
        let r = round_rational(&(&tiny * Rational::from((3, 2))));
        // 1.5 · 2^-1074 is a tie between 2^-1074 (odd) and 2^-1073 (even).
        assert_eq!(r.nearest, f64::from_bits(2));
        assert_eq!((r.lo, r.hi), (f64::from_bits(1), f64::from_bits(2)));
        let r = round_rational(&Rational::from(&tiny / 3u32));
        assert_eq!(r.nearest, 0.0);
        assert_eq!((r.lo, r.hi), (0.0, f64::from_bits(1)));
        let r = round_rational(&Rational::from(&tiny / -1024i32));
        assert_eq!((r.nearest, r.lo, r.hi), (0.0, -f64::from_bits(1), 0.0));
        // 0.5 · 2^-1074 is a tie between 0 (even) and 2^-1074.
        let r = round_rational(&Rational::from(&tiny / 2u32));
        assert_eq!((r.nearest, r.lo, r.hi), (0.0, 0.0, f64::from_bits(1)));
        let r = round_rational(&(Rational::from(&tiny * 3u32) / 4u32));
        assert_eq!(
            (r.nearest, r.lo, r.hi),
            (f64::from_bits(1), 0.0, f64::from_bits(1))
        );
        // just below 2^-1022 rounds up to it
        let below = Rational::from_f64(f64::MIN_POSITIVE).unwrap() - Rational::from(&tiny / 4u32);
        assert_eq!(round_rational(&below).nearest, f64::MIN_POSITIVE);
        let max = Rational::from_f64(f64::MAX).unwrap();
        let r = round_rational(&Rational::from(&max * 2u32));
        assert!(r.overflowed() && r.lo == f64::MAX);
        let r = round_rational(&max);
        assert!(r.is_exact() && r.nearest == f64::MAX);
    }

    #[test]
    fn square_roots_are_correctly_rounded() {
        let r = sqrt_rational(&Rational::from(4));
        assert!(r.is_exact() && r.nearest == 2.0);
        let r = sqrt_rational(&Rational::from(2));
        assert_eq!(r.nearest, std::f64::consts::SQRT_2);
        assert!(r.lo < r.nearest || r.hi > r.nearest);
        // (1 + 2^-53)^2: the root is the midpoint between 1 and 1 + 2^-52: ties to even (1).
        let m = Rational::from(1) + Rational::from_f64(f64::EPSILON / 2.0).unwrap();
        let r = sqrt_rational(&Rational::from(&m * &m));
        assert_eq!((r.nearest, r.lo, r.hi), (1.0, 1.0, 1.0 + f64::EPSILON));
        // 2/3 = (2/√6)²: §16.2's distance.
        let r = sqrt_rational(&Rational::from((2, 3)));
        assert_eq!(r.nearest, 0.816496580927726);
    }

    #[test]
    fn neighbours() {
        assert_eq!(next_up(1.0), 1.0 + f64::EPSILON);
        assert_eq!(next_down(1.0), 1.0 - f64::EPSILON / 2.0);
        assert_eq!(next_up(-0.0), f64::from_bits(1));
        assert_eq!(next_down(0.0), -f64::from_bits(1));
        assert_eq!(next_up(-f64::from_bits(1)), 0.0);
        assert_eq!(next_up(f64::MAX), f64::INFINITY);
        assert_eq!(next_down(f64::NEG_INFINITY), f64::NEG_INFINITY);
    }

    #[test]
    fn exponent_and_scaling() {
        assert_eq!(exponent_of(&Rational::from(5)), Some(2));
        assert_eq!(exponent_of(&Rational::from((1, 3))), Some(-2));
        assert_eq!(exponent_of(&Rational::from(4)), Some(2));
        assert_eq!(scale_pow2(&Rational::from(3), -2), Rational::from((3, 4)));
        let r = Rounded::inexact(1.0, Ordering::Greater);
        assert_eq!(r.compare_f64(1.0), Ordering::Greater);
        assert_eq!(r.compare_f64(1.0 + f64::EPSILON), Ordering::Less);
    }
}
