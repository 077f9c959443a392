//! The numbers of exact plane sections (OPERATIONS.md §13.2): quadratic surds
//! `p + q√r` (`p, q, r` rational, `r ≥ 0` fixed by the conic: the discriminant of its
//! eigenvalue equation) and the reported values `s·√S` built from them (a semi-axis
//! `√(κ/λ)`, a coordinate of a unit axis `yᵢ/√(yᵀGy)`).
//!
//! Signs and equalities are decided exactly (`p + q√r` against zero compares `p²` with
//! `q²r`). A reported value is the exact rational when it is one, else it is irrational
//! (a square root of a non-square rational, or of a surd with `q ≠ 0` and `r` not a
//! square) and is correctly rounded by Ziv's strategy
//! (`ops::algebraic::correctly_rounded`): its MPFR interval enclosure (outward
//! rounded at every operation) is refined until it lies between two consecutive
//! midpoints of doubles. An irrational number is never a double or a midpoint, so this
//! ends; the precision cap still bounds it, and past it the value keeps its enclosure
//! and is marked not correctly rounded.

use rug::{Integer, Rational};
use std::cmp::Ordering;

use crate::num::round::{round_rational, sqrt_rational};
use crate::num::MpfrInterval;
use crate::ops::rational::{correctly_rounded, PRECISION_CAP};

/// `p + q√r`, normalised so that `q ≠ 0` implies `r` is not the square of a rational.
#[derive(Debug, Clone, PartialEq)]
pub struct Surd {
    pub p: Rational,
    pub q: Rational,
    pub r: Rational,
}

/// Whether `x ≥ 0` is the square of a rational, and its root then.
pub(crate) fn rational_sqrt(x: &Rational) -> Option<Rational> {
    if x.cmp0() == Ordering::Less {
        return None;
    }
    let (n, d) = (x.numer(), x.denom());
    if n.is_perfect_square() && d.is_perfect_square() {
        Some(Rational::from((
            Integer::from(n.sqrt_ref()),
            Integer::from(d.sqrt_ref()),
        )))
    } else {
        None
    }
}

impl Surd {
    /// The rational `p`.
    pub fn rational(p: Rational) -> Surd {
        Surd {
            p,
            q: Rational::new(),
            r: Rational::new(),
        }
    }

    /// `p + q√r` (`r ≥ 0`), folding `√r` in when `r` is a square.
    pub fn new(p: Rational, q: Rational, r: Rational) -> Surd {
        match rational_sqrt(&r) {
            Some(s) => Surd::rational(p + q * s),
            None if q.cmp0() == Ordering::Equal => Surd::rational(p),
            None => Surd { p, q, r },
        }
    }

    /// The value when it is rational.
    pub fn as_rational(&self) -> Option<&Rational> {
        (self.q.cmp0() == Ordering::Equal).then_some(&self.p)
    }

    /// The exact sign.
    pub fn sign(&self) -> Ordering {
        let (sp, sq) = (self.p.cmp0(), self.q.cmp0());
        if sq == Ordering::Equal || sp == sq {
            return if sp == Ordering::Equal { sq } else { sp };
        }
        if sp == Ordering::Equal {
            return sq;
        }
        // Opposite signs: the larger of p² and q²r wins.
        let pp = Rational::from(&self.p * &self.p);
        let qqr = Rational::from(&self.q * &self.q) * &self.r;
        match pp.cmp(&qqr) {
            Ordering::Greater => sp,
            Ordering::Less => sq,
            Ordering::Equal => Ordering::Equal,
        }
    }

    fn field(&self, other: &Surd) -> Rational {
        if self.q.cmp0() != Ordering::Equal {
            self.r.clone()
        } else {
            other.r.clone()
        }
    }

    pub fn add(&self, o: &Surd) -> Surd {
        let r = self.field(o);
        Surd::new(
            Rational::from(&self.p + &o.p),
            Rational::from(&self.q + &o.q),
            r,
        )
    }

    pub fn neg(&self) -> Surd {
        Surd::new(-self.p.clone(), -self.q.clone(), self.r.clone())
    }

    pub fn sub(&self, o: &Surd) -> Surd {
        self.add(&o.neg())
    }

    /// The product (both in the same field `Q(√r)`, or one rational).
    pub fn mul(&self, o: &Surd) -> Surd {
        let r = self.field(o);
        let p = Rational::from(&self.p * &o.p) + Rational::from(&self.q * &o.q) * &r;
        let q = Rational::from(&self.p * &o.q) + Rational::from(&self.q * &o.p);
        Surd::new(p, q, r)
    }

    pub fn scale(&self, k: &Rational) -> Surd {
        Surd::new(
            Rational::from(&self.p * k),
            Rational::from(&self.q * k),
            self.r.clone(),
        )
    }

    /// The quotient; `None` when `o` is zero.
    pub fn div(&self, o: &Surd) -> Option<Surd> {
        // 1/(P + Q√r) = (P − Q√r)/(P² − Q²r); the norm is 0 only for o = 0 (r no square).
        let norm = Rational::from(&o.p * &o.p) - Rational::from(&o.q * &o.q) * &o.r;
        if norm.cmp0() == Ordering::Equal {
            return None;
        }
        let conj = Surd::new(o.p.clone(), -o.q.clone(), o.r.clone());
        Some(self.mul(&conj).scale(&norm.recip()))
    }

    /// An outward-rounded MPFR enclosure at `bits` bits.
    pub fn enclose(&self, bits: u32) -> MpfrInterval {
        let p = MpfrInterval::from_rational(&self.p, bits);
        if self.q.cmp0() == Ordering::Equal {
            return p;
        }
        let root = MpfrInterval::from_rational(&self.r, bits).sqrt();
        p.add(&MpfrInterval::from_rational(&self.q, bits).mul(&root))
    }
}

/// A reported real number: its double (correctly rounded when `rounded`), an enclosure,
/// and the exact rational when it is one.
#[derive(Debug, Clone, PartialEq)]
pub struct Value {
    pub value: f64,
    pub bounds: [f64; 2],
    pub exact: Option<Rational>,
    /// Whether `value` is the exact number correctly rounded (else only enclosed).
    pub rounded: bool,
}

impl Value {
    /// A rational, correctly rounded.
    pub fn rational(q: &Rational) -> Value {
        let r = round_rational(q);
        Value {
            value: r.nearest,
            bounds: [r.lo, r.hi],
            exact: Some(q.clone()),
            rounded: !r.overflowed(),
        }
    }

    /// A surd.
    pub fn surd(x: &Surd) -> Value {
        match x.as_rational() {
            Some(q) => Value::rational(q),
            None => ziv(|bits| x.enclose(bits)),
        }
    }

    /// `sign·√s` for a surd `s ≥ 0` (`sign` of `Ordering::Less` negates).
    pub fn signed_sqrt(sign: Ordering, s: &Surd) -> Value {
        if sign == Ordering::Equal || s.sign() == Ordering::Equal {
            return Value::rational(&Rational::new());
        }
        let neg = sign == Ordering::Less;
        if let Some(q) = s.as_rational() {
            if let Some(root) = rational_sqrt(q) {
                return Value::rational(&if neg { -root } else { root });
            }
            if !neg {
                let r = sqrt_rational(q);
                return Value {
                    value: r.nearest,
                    bounds: [r.lo, r.hi],
                    exact: None,
                    rounded: !r.overflowed(),
                };
            }
        }
        ziv(|bits| {
            let root = s.enclose(bits).sqrt();
            if neg {
                root.neg()
            } else {
                root
            }
        })
    }

    /// The value `x/√n` of a coordinate of the unit vector along a vector with the
    /// coordinate `x` and squared length `n > 0`.
    pub fn unit_component(x: &Surd, n: &Surd) -> Value {
        let sq = x
            .mul(x)
            .div(n)
            .unwrap_or_else(|| Surd::rational(Rational::new()));
        Value::signed_sqrt(x.sign(), &sq)
    }
}

/// Correct rounding of an irrational number from its enclosures; at the precision cap
/// the enclosure is kept and the value marked not correctly rounded.
fn ziv(enclose: impl Fn(u32) -> MpfrInterval) -> Value {
    match correctly_rounded(&enclose) {
        Some(r) => Value {
            value: r.nearest,
            bounds: [r.lo, r.hi],
            exact: None,
            rounded: true,
        },
        None => {
            let x = enclose(PRECISION_CAP);
            let (lo, hi) = (x.lo_f64(), x.hi_f64());
            Value {
                value: 0.5 * lo + 0.5 * hi,
                bounds: [lo, hi],
                exact: None,
                rounded: false,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    #[test]
    fn signs_and_arithmetic_are_exact() {
        let s = Surd::new(q(-7, 5), q(1, 1), q(2, 1)); // −1.4 + √2 > 0
        assert_eq!(s.sign(), Ordering::Greater);
        let t = Surd::new(q(-3, 2), q(1, 1), q(2, 1)); // −1.5 + √2 < 0
        assert_eq!(t.sign(), Ordering::Less);
        // (1 + √2)(1 − √2) = −1
        let a = Surd::new(q(1, 1), q(1, 1), q(2, 1));
        let b = Surd::new(q(1, 1), q(-1, 1), q(2, 1));
        assert_eq!(a.mul(&b).as_rational(), Some(&q(-1, 1)));
        assert_eq!(a.div(&a).unwrap().as_rational(), Some(&q(1, 1)));
        assert_eq!(
            Surd::new(q(1, 1), q(1, 1), q(9, 4)).as_rational(),
            Some(&q(5, 2))
        );
    }

    #[test]
    fn values_are_correctly_rounded() {
        let v = Value::signed_sqrt(Ordering::Greater, &Surd::rational(q(2, 1)));
        assert_eq!(v.value, 2f64.sqrt());
        assert!(v.rounded && v.exact.is_none());
        let v = Value::signed_sqrt(Ordering::Less, &Surd::rational(q(9, 4)));
        assert_eq!(v.exact, Some(q(-3, 2)));
        let golden = Value::surd(&Surd::new(q(1, 2), q(1, 2), q(5, 1)));
        assert_eq!(golden.value, (1.0 + 5f64.sqrt()) / 2.0);
        assert!(golden.bounds[0] <= golden.value && golden.value <= golden.bounds[1]);
        assert!(golden.bounds[0] < golden.bounds[1]);
    }
}
