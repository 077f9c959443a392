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

/// `num / den`, `den ≠ 0`; `den = None` stands for 1 (whole values skip the products).
#[derive(Debug, Clone, PartialEq)]
pub struct Ratio<E> {
    pub num: E,
    pub den: Option<E>,
}

impl<E: SignedRing> Ratio<E> {
    fn whole(num: E) -> Self {
        Ratio { num, den: None }
    }
    /// The denominator (1 for whole values).
    pub fn denominator(&self) -> E {
        self.den.clone().unwrap_or_else(E::one)
    }
}

/// `a·b` where `None` is 1.
fn mul_opt<E: SignedRing>(a: &Option<E>, b: &Option<E>) -> Option<E> {
    match (a, b) {
        (None, None) => None,
        (Some(x), None) | (None, Some(x)) => Some(x.clone()),
        (Some(x), Some(y)) => Some(x.times(y)),
    }
}

/// `x·d` where `d = None` is 1.
fn scale_opt<E: SignedRing>(x: &E, d: &Option<E>) -> E {
    match d {
        None => x.clone(),
        Some(d) => x.times(d),
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
        match (&self.den, &r.den) {
            (None, None) => Self::whole(self.num.plus(&r.num)),
            (Some(a), Some(b)) if a == b => Ratio {
                num: self.num.plus(&r.num),
                den: self.den.clone(),
            },
            _ => Ratio {
                num: scale_opt(&self.num, &r.den).plus(&scale_opt(&r.num, &self.den)),
                den: mul_opt(&self.den, &r.den),
            },
        }
    }
    fn minus(&self, r: &Self) -> Self {
        self.plus(&r.negate())
    }
    fn times(&self, r: &Self) -> Self {
        Ratio {
            num: self.num.times(&r.num),
            den: mul_opt(&self.den, &r.den),
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
        Ratio {
            num: scale_opt(&self.num, &r.den),
            den: Some(scale_opt(&r.num, &self.den)),
        }
    }
    fn sign(&self) -> Ordering {
        let a = self.num.sign_of();
        match &self.den {
            Some(d) if d.sign_of() == Ordering::Less => a.reverse(),
            _ => a,
        }
    }
    fn from_f64(x: f64) -> Self {
        Self::whole(E::exact_f64(x))
    }
}
