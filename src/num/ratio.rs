//! Quotients of exact ring elements, unreduced: the field the exact decision procedures
//! run in when the ring has no division (floating-point expansions). `a/b` is kept as
//! the pair; signs and comparisons are exact (`sign(a/b) = sign(a)·sign(b)`).

use nalgebra::Scalar;
use std::cmp::Ordering;

use super::expansion::Expansion;
use super::ring::{Field, Ring};

/// An exact ring with an exact sign.
pub trait SignedRing: Ring + Scalar {
    fn sign_of(&self) -> Ordering;
    fn exact_f64(x: f64) -> Self;
}

impl SignedRing for Expansion {
    fn sign_of(&self) -> Ordering {
        self.sign()
    }
    fn exact_f64(x: f64) -> Self {
        Expansion::from_f64(x)
    }
}

/// `num / den`, `den ≠ 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct Ratio<E> {
    pub num: E,
    pub den: E,
}

impl<E: SignedRing> Ratio<E> {
    fn whole(num: E) -> Self {
        Ratio { num, den: E::one() }
    }
    fn is_whole(&self) -> bool {
        // a structural test is enough: `one()` is what `whole` stores
        self.den == E::one()
    }
}

impl<E: SignedRing> Ring for Ratio<E> {
    fn zero() -> Self {
        Self::whole(E::zero())
    }
    fn one() -> Self {
        Self::whole(E::one())
    }
    fn plus(&self, r: &Self) -> Self {
        if self.is_whole() && r.is_whole() {
            return Self::whole(self.num.plus(&r.num));
        }
        if self.den == r.den {
            return Ratio {
                num: self.num.plus(&r.num),
                den: self.den.clone(),
            };
        }
        Ratio {
            num: self.num.times(&r.den).plus(&r.num.times(&self.den)),
            den: self.den.times(&r.den),
        }
    }
    fn minus(&self, r: &Self) -> Self {
        self.plus(&r.negate())
    }
    fn times(&self, r: &Self) -> Self {
        match (self.is_whole(), r.is_whole()) {
            (true, true) => Self::whole(self.num.times(&r.num)),
            (true, false) => Ratio {
                num: self.num.times(&r.num),
                den: r.den.clone(),
            },
            (false, true) => Ratio {
                num: self.num.times(&r.num),
                den: self.den.clone(),
            },
            (false, false) => Ratio {
                num: self.num.times(&r.num),
                den: self.den.times(&r.den),
            },
        }
    }
    fn negate(&self) -> Self {
        Ratio {
            num: self.num.negate(),
            den: self.den.clone(),
        }
    }
}

impl<E: SignedRing> Field for Ratio<E> {
    fn divide(&self, r: &Self) -> Self {
        let num = if r.is_whole() {
            self.num.clone()
        } else {
            self.num.times(&r.den)
        };
        let den = if self.is_whole() {
            r.num.clone()
        } else {
            self.den.times(&r.num)
        };
        Ratio { num, den }
    }
    fn sign(&self) -> Ordering {
        let (a, b) = (self.num.sign_of(), self.den.sign_of());
        if b == Ordering::Less {
            a.reverse()
        } else {
            a
        }
    }
    fn from_f64(x: f64) -> Self {
        Self::whole(E::exact_f64(x))
    }
}
