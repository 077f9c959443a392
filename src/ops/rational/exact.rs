//! Exact helpers of the algebraic operations: input validation into rationals, closed
//! rational intervals, and the correct rounding of a rational affine image of an
//! algebraic root.

use std::cmp::Ordering;

use rug::Rational;

use crate::certify::univariate::{Polynomial, RealRoot};
use crate::error::GeomError;
use crate::num::parse::rational_from_f64;
use crate::num::round::{round_rational, Rounded};

/// The exact values of a vector of doubles; a NaN or infinity is rejected naming
/// `field[i]`.
pub(crate) fn exact_vec<const D: usize>(
    field: &str,
    v: &[f64; D],
) -> Result<[Rational; D], GeomError> {
    let mut out: [Rational; D] = std::array::from_fn(|_| Rational::new());
    for (i, (o, &x)) in out.iter_mut().zip(v).enumerate() {
        *o = rational_from_f64(&format!("{field}[{i}]"), x)?;
    }
    Ok(out)
}

/// The exact value of a double that must be finite and positive.
pub(crate) fn positive(field: &str, x: f64) -> Result<Rational, GeomError> {
    let q = rational_from_f64(field, x)?;
    if q.cmp0() != Ordering::Greater {
        return Err(GeomError::InvalidValue {
            field: field.into(),
            reason: format!("{x} must be positive"),
        });
    }
    Ok(q)
}

/// A line `o + t·d` with exact rational data; `d ≠ 0`.
pub(crate) fn exact_line<const D: usize>(
    origin: &[f64; D],
    direction: &[f64; D],
) -> Result<([Rational; D], [Rational; D]), GeomError> {
    let o = exact_vec("line.origin", origin)?;
    let d = exact_vec("line.direction", direction)?;
    if d.iter().all(|x| x.cmp0() == Ordering::Equal) {
        return Err(GeomError::ZeroDirection {
            field: "line.direction".into(),
        });
    }
    Ok((o, d))
}

pub(crate) fn dot<const D: usize>(a: &[Rational; D], b: &[Rational; D]) -> Rational {
    let mut s = Rational::new();
    for (x, y) in a.iter().zip(b) {
        s += Rational::from(x * y);
    }
    s
}

/// A closed interval `[lo, hi]` of rationals, with exact (hence enclosing) arithmetic:
/// every operation returns the exact range of the operation over its operands' boxes
/// for `+`, `−`, scaling, and a superset for products of dependent operands (Horner
/// evaluation), so every result encloses the true value.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RatInterval {
    pub(crate) lo: Rational,
    pub(crate) hi: Rational,
}

impl RatInterval {
    pub(crate) fn point(x: Rational) -> RatInterval {
        RatInterval {
            lo: x.clone(),
            hi: x,
        }
    }

    pub(crate) fn from_root(r: &RealRoot) -> RatInterval {
        let (lo, hi) = r.interval();
        RatInterval { lo, hi }
    }

    pub(crate) fn is_point(&self) -> bool {
        self.lo == self.hi
    }

    pub(crate) fn add(&self, o: &RatInterval) -> RatInterval {
        RatInterval {
            lo: Rational::from(&self.lo + &o.lo),
            hi: Rational::from(&self.hi + &o.hi),
        }
    }

    pub(crate) fn scale(&self, c: &Rational) -> RatInterval {
        let a = Rational::from(&self.lo * c);
        let b = Rational::from(&self.hi * c);
        if a <= b {
            RatInterval { lo: a, hi: b }
        } else {
            RatInterval { lo: b, hi: a }
        }
    }

    pub(crate) fn mul(&self, o: &RatInterval) -> RatInterval {
        let p = [
            Rational::from(&self.lo * &o.lo),
            Rational::from(&self.lo * &o.hi),
            Rational::from(&self.hi * &o.lo),
            Rational::from(&self.hi * &o.hi),
        ];
        let lo = p.iter().min().cloned().unwrap_or_default();
        let hi = p.iter().max().cloned().unwrap_or_default();
        RatInterval { lo, hi }
    }

    /// `self / o`; `None` when `o` contains zero.
    pub(crate) fn div(&self, o: &RatInterval) -> Option<RatInterval> {
        if o.lo.cmp0() != Ordering::Greater && o.hi.cmp0() != Ordering::Less {
            return None;
        }
        let inv = RatInterval {
            lo: Rational::from(o.hi.recip_ref()),
            hi: Rational::from(o.lo.recip_ref()),
        };
        Some(self.mul(&inv))
    }

    /// `p(self)` by Horner: encloses `{p(x) : x ∈ self}`.
    pub(crate) fn eval(&self, p: &Polynomial) -> RatInterval {
        let mut acc = RatInterval::point(Rational::new());
        for c in p.coeffs().iter().rev() {
            acc = acc.mul(self).add(&RatInterval::point(c.clone()));
        }
        acc
    }

    /// True when the two closed intervals meet.
    pub(crate) fn meets(&self, o: &RatInterval) -> bool {
        self.lo <= o.hi && o.lo <= self.hi
    }
}

/// `o + d·t` correctly rounded, for a root `t`. A rational root is rounded directly.
/// An isolated root is irrational (decided by the root finder), so for `d ≠ 0` the
/// image is irrational too: never a double nor a tie, so refining `t` until both ends
/// of the image round to the same double, lying outside the image, terminates.
pub(crate) fn round_affine(t: &mut RealRoot, o: &Rational, d: &Rational) -> Rounded {
    if d.cmp0() == Ordering::Equal {
        return round_rational(o);
    }
    loop {
        let image = RatInterval::from_root(t)
            .scale(d)
            .add(&RatInterval::point(o.clone()));
        if let Some(r) = round_enclosure(&image) {
            return r;
        }
        t.refine();
    }
}

/// The correct rounding of the value enclosed by `x` when the enclosure decides it:
/// `x` a point, or both ends rounding to one double that lies outside the open
/// enclosure (the value is then not that double, and on a known side of it).
pub(crate) fn round_enclosure(x: &RatInterval) -> Option<Rounded> {
    if x.is_point() {
        return Some(round_rational(&x.lo));
    }
    // Cheap test first: both ends can round alike only when the enclosure is about one
    // ulp wide (width·2⁵² ≤ max |end|, or width ≤ 2⁻¹⁰⁷⁴).
    let w = Rational::from(&x.hi - &x.lo);
    let m = if x.lo.cmp_abs(&x.hi) == Ordering::Greater {
        &x.lo
    } else {
        &x.hi
    };
    if Rational::from(&w << 52u32).cmp_abs(m) == Ordering::Greater
        && w > (Rational::from(1) >> 1074u32)
    {
        return None;
    }
    let (rl, rh) = (round_rational(&x.lo), round_rational(&x.hi));
    if rl.nearest != rh.nearest || rl.nearest.to_bits() != rh.nearest.to_bits() {
        return None;
    }
    if rl.overflowed() {
        return Some(rl);
    }
    let d = Rational::from_f64(rl.nearest)?;
    if d <= x.lo {
        Some(Rounded::inexact(rl.nearest, Ordering::Greater))
    } else if d >= x.hi {
        Some(Rounded::inexact(rl.nearest, Ordering::Less))
    } else {
        None
    }
}

/// The exact sign of `p` at a root `t`: zero when `t` is a root of `p`; otherwise `t`
/// is refined until the Horner enclosure of `p` over its interval excludes zero (it
/// converges to the non-zero value `p(t)`).
pub(crate) fn sign_at_root(t: &mut RealRoot, p: &Polynomial) -> Ordering {
    if t.is_root_of(p) {
        return Ordering::Equal;
    }
    loop {
        let v = RatInterval::from_root(t).eval(p);
        if v.lo.cmp0() == Ordering::Greater {
            return Ordering::Greater;
        }
        if v.hi.cmp0() == Ordering::Less {
            return Ordering::Less;
        }
        t.refine();
    }
}

/// Compare the root `t` with the rational `a`, exactly (refining an irrational root's
/// isolating interval until `a` lies outside it).
pub(crate) fn compare_root(t: &mut RealRoot, a: &Rational) -> Ordering {
    loop {
        let (lo, hi) = t.interval();
        if lo == hi {
            return lo.cmp(a);
        }
        if lo >= *a {
            return Ordering::Greater;
        }
        if hi <= *a {
            return Ordering::Less;
        }
        t.refine();
    }
}
