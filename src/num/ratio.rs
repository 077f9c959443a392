//! Quotients of exact ring elements, unreduced: the field the exact decision procedures
//! run in when the ring has no division (floating-point expansions). `a/b` is kept as
//! the pair; signs and comparisons are exact (`sign(a/b) = sign(a)·sign(b)`). Used over
//! fixed-width dyadic integers ([`Dyadic`]) and floating-point expansions.

use nalgebra::Scalar;
use std::cmp::Ordering;

use super::dyadic::Dyadic;
use super::dyadic128::Dyadic128;
use super::expansion::Expansion;
use super::ring::{Field, Ring};

/// An exact ring with an exact sign.
pub trait SignedRing: Ring + Scalar {
    fn sign_of(&self) -> Ordering;
    fn exact_f64(x: f64) -> Self;
}

impl<const N: usize> SignedRing for Dyadic<N> {
    #[inline]
    fn sign_of(&self) -> Ordering {
        self.sign()
    }
    #[inline]
    fn exact_f64(x: f64) -> Self {
        Dyadic::from_f64(x)
    }
}

impl SignedRing for Dyadic128 {
    #[inline(always)]
    fn sign_of(&self) -> Ordering {
        self.sign()
    }
    #[inline(always)]
    fn exact_f64(x: f64) -> Self {
        Dyadic128::from_f64(x)
    }
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
    #[inline]
    fn whole(num: E) -> Self {
        Ratio { num, den: None }
    }
    /// `self ± r` (`sub`: minus): over a shared denominator (both whole, or structurally
    /// equal denominators) without products.
    #[inline(always)]
    fn add(&self, r: &Self, sub: bool) -> Self {
        let op = |a: &E, b: &E| if sub { a.minus(b) } else { a.plus(b) };
        match (&self.den, &r.den) {
            (None, None) => Self::whole(op(&self.num, &r.num)),
            (Some(a), Some(b)) if a == b => Ratio {
                num: op(&self.num, &r.num),
                den: self.den.clone(),
            },
            _ => Ratio {
                num: op(&scale_opt(&self.num, &r.den), &scale_opt(&r.num, &self.den)),
                den: mul_opt(&self.den, &r.den),
            },
        }
    }
    /// The denominator (1 for whole values).
    pub fn denominator(&self) -> E {
        self.den.clone().unwrap_or_else(E::one)
    }
}

/// `a·b` where `None` is 1.
#[inline]
fn mul_opt<E: SignedRing>(a: &Option<E>, b: &Option<E>) -> Option<E> {
    match (a, b) {
        (None, None) => None,
        (Some(x), None) | (None, Some(x)) => Some(x.clone()),
        (Some(x), Some(y)) => Some(x.times(y)),
    }
}

/// `x·d` where `d = None` is 1.
#[inline]
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
    #[inline]
    fn plus(&self, r: &Self) -> Self {
        self.add(r, false)
    }
    #[inline]
    fn minus(&self, r: &Self) -> Self {
        self.add(r, true)
    }
    #[inline]
    fn times(&self, r: &Self) -> Self {
        Ratio {
            num: self.num.times(&r.num),
            den: mul_opt(&self.den, &r.den),
        }
    }
    #[inline]
    fn negate(&self) -> Self {
        Ratio {
            num: self.num.negate(),
            den: self.den.clone(),
        }
    }
}

impl<E: SignedRing> Field for Ratio<E> {
    #[inline]
    fn divide(&self, r: &Self) -> Self {
        Ratio {
            num: scale_opt(&self.num, &r.den),
            den: Some(scale_opt(&r.num, &self.den)),
        }
    }
    #[inline]
    fn sign(&self) -> Ordering {
        let a = self.num.sign_of();
        match &self.den {
            Some(d) if d.sign_of() == Ordering::Less => a.reverse(),
            _ => a,
        }
    }
    #[inline]
    fn from_f64(x: f64) -> Self {
        Self::whole(E::exact_f64(x))
    }
}
