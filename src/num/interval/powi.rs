//! Integer powers of [`Interval`] (IEEE 1788 `pown`): the monotonicity analysis and the
//! directed endpoint powers.

use super::arith::Sign;
use super::directed::{div_up, mul_up};
use super::Interval;

impl Interval {
    /// `self^n` for an integer `n` (IEEE 1788 `pown`; `x^0 = 1`, negative `n` divides,
    /// dropping `x = 0`: `[0, 0]^-1` is EMPTY, `[-1, 1]^-1` is the whole line).
    /// Monotonicity: even `n > 0` gives `[mig^n, mag^n]`, odd `n > 0` is increasing,
    /// `n < 0` even gives `[mag^n, mig^n]`, odd is decreasing on each side of 0.
    /// Exponents 0, ±1, 2 are tightest; otherwise each endpoint power is computed by
    /// `directed_pow`: binary powering with every product rounded in the direction
    /// that keeps the bound (and one directed division for `n < 0`) — within about
    /// `2|n|` ulps, NOT tightest — or MPFR (tightest) when an intermediate could leave
    /// the normal range.
    pub fn powi(&self, n: i32) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        match n {
            0 => return Interval::ONE,
            1 => return *self,
            2 => return self.sqr(),
            -1 => return self.recip(),
            _ => {}
        }
        let (lo, hi) = (self.lo(), self.hi());
        let class = self.sign_class();
        let (lo_b, hi_b) = if n > 0 {
            if n % 2 == 0 {
                (
                    directed_pow(self.mig(), n, false),
                    directed_pow(self.mag(), n, true),
                )
            } else {
                (directed_pow(lo, n, false), directed_pow(hi, n, true))
            }
        } else if class == Sign::Zero {
            return Interval::EMPTY;
        } else if n % 2 == 0 {
            (
                directed_pow(self.mag(), n, false),
                directed_pow(self.mig(), n, true),
            )
        } else {
            match class {
                Sign::Mixed => return Interval::ENTIRE,
                Sign::Pos => {
                    let hi_b = if lo == 0.0 {
                        f64::INFINITY
                    } else {
                        directed_pow(lo, n, true)
                    };
                    (directed_pow(hi, n, false), hi_b)
                }
                _ => {
                    let lo_b = if hi == 0.0 {
                        f64::NEG_INFINITY
                    } else {
                        directed_pow(hi, n, false)
                    };
                    (lo_b, directed_pow(lo, n, true))
                }
            }
        };
        Interval::from_neg_lo_hi(-lo_b, hi_b)
    }
}

/// `x^n` rounded up (`up`) or down to a double, for `|n| ≥ 2` (for `n < 0`, `x ≠ 0`).
/// Fast path when `x` is normal and `(|e| + 1)·|n| ≤ 960` (`e` its binary exponent), so
/// every intermediate power stays in the normal range: `|x|^|n|` by binary powering with
/// each product of non-negative factors rounded in one direction (a bound in that
/// direction), the sign `sign(x)^n` and, for `n < 0`, one directed division `1/·` with
/// the opposite-direction power. Otherwise MPFR's correctly rounded `pow` (with its
/// IEEE special values for 0 and ∞).
pub(crate) fn directed_pow(x: f64, n: i32, up: bool) -> f64 {
    let m = n.unsigned_abs();
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i64;
    let e = (biased - 1023).unsigned_abs();
    if biased == 0 || biased == 0x7ff || (e + 1) * u64::from(m) > 960 {
        let mut f = rug::Float::with_val(53, x);
        let round = if up {
            rug::float::Round::Up
        } else {
            rug::float::Round::Down
        };
        rug::ops::PowAssignRound::pow_assign_round(&mut f, n, round);
        return f.to_f64_round(round);
    }
    let negative = x < 0.0 && m % 2 == 1;
    // Direction for |x|^n: if the result is negative, its upper bound needs |·| rounded down.
    let abs_up = up != negative;
    let a = x.abs();
    let mag = if n > 0 {
        if abs_up {
            pow_up_abs(a, m)
        } else {
            -pow_up_neg(a, m)
        }
    } else if abs_up {
        div_up(1.0, -pow_up_neg(a, m))
    } else {
        -div_up(-1.0, pow_up_abs(a, m))
    };
    if negative {
        -mag
    } else {
        mag
    }
}

/// `x^m` rounded up for `x ≥ 0` (binary powering; every product of non-negative factors
/// rounded up, so the result bounds the exact power from above).
fn pow_up_abs(x: f64, m: u32) -> f64 {
    let mut result = 1.0;
    let mut base = x;
    let mut e = m;
    while e > 0 {
        if e & 1 == 1 {
            result = mul_up(result, base);
        }
        e >>= 1;
        if e > 0 {
            base = mul_up(base, base);
        }
    }
    result
}

/// `−(x^m rounded down)` for `x ≥ 0`: binary powering with every product rounded down
/// (`RD(p·q) = −RU(−p·q)`), negated at the end.
fn pow_up_neg(x: f64, m: u32) -> f64 {
    let mut result = 1.0;
    let mut base = x;
    let mut e = m;
    while e > 0 {
        if e & 1 == 1 {
            result = -mul_up(-result, base);
        }
        e >>= 1;
        if e > 0 {
            base = -mul_up(-base, base);
        }
    }
    -result
}
