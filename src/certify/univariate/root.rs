//! One real root of a polynomial: exact when rational, else an isolating interval that
//! can be refined without end, with its multiplicity and its correctly rounded double.
//!
//! Rationality is decided exactly before rounding, so that every non-exact root is a
//! proven irrational: then no affine image of it with a non-zero rational slope is a
//! double or a midpoint between doubles, and every rounding loop downstream
//! (`ops::algebraic`) terminates. The test: a rational root `a/b` of a primitive
//! integer polynomial `g` has `b | lc(g)` (rational root theorem), so `lc(g)·x` is an
//! integer; once the bracket is narrower than `1/lc(g)` it holds at most one such
//! candidate, which is tested exactly. Degrees 1 and 2 are decided in closed form
//! (a quadratic has rational roots iff its discriminant is a square). A factor that a
//! small prime proves to have no rational root (`modular`) skips the test.
//!
//! Correct rounding: nearest rounding is monotone, so when both ends of the bracket
//! round to the same double `d` and `d` lies outside the bracket, the root rounds to
//! `d` and lies on the known side of it. An irrational root is never a double or a
//! tie, so refinement reaches that state; a rational root is rounded directly.

use std::cmp::Ordering;

use rug::{Integer, Rational};

use super::bracket::Bracket;
use super::int_poly::{At, IntPoly};
use super::poly::Polynomial;
use crate::num::round::{round_rational, Rounded};

#[derive(Debug, Clone)]
enum Location {
    Exact(Rational),
    Isolated(Bracket),
}

/// A real root, exact or isolated (see the module documentation).
#[derive(Debug, Clone)]
pub struct RealRoot {
    location: Location,
    multiplicity: u32,
    rounded: Rounded,
    /// The square-free factor of the input of which this is a simple root
    /// (primitive, positive leading coefficient).
    factor: IntPoly,
}

impl RealRoot {
    /// Build from an isolated root of `factor` and decide rationality and rounding.
    pub(crate) fn new_exact(x: Rational, multiplicity: u32, factor: IntPoly) -> RealRoot {
        RealRoot {
            rounded: round_rational(&x),
            location: Location::Exact(x),
            multiplicity,
            factor,
        }
    }

    /// Build from a bracket of `factor` (ends not roots of `factor`, one root inside)
    /// and decide rationality (skipped when `irrational` is already proven) and
    /// rounding.
    pub(crate) fn new_isolated(
        bracket: Bracket,
        multiplicity: u32,
        factor: IntPoly,
        irrational: bool,
    ) -> RealRoot {
        let mut root = RealRoot {
            location: Location::Isolated(bracket),
            multiplicity,
            rounded: Rounded::exact(f64::NAN),
            factor,
        };
        if !irrational {
            root.decide_rationality();
        }
        root.decide_rounding();
        root
    }

    /// The exact value when the root is rational (and only then).
    pub fn exact(&self) -> Option<&Rational> {
        match &self.location {
            Location::Exact(x) => Some(x),
            Location::Isolated(_) => None,
        }
    }

    /// True when the root is rational; otherwise it is proven irrational.
    pub fn is_rational(&self) -> bool {
        matches!(self.location, Location::Exact(_))
    }

    /// `[lo, hi]` holding the root and no other root of the input polynomial;
    /// `lo = hi` for a rational root, else `lo < root < hi`.
    pub fn interval(&self) -> (Rational, Rational) {
        match &self.location {
            Location::Exact(x) => (x.clone(), x.clone()),
            Location::Isolated(b) => (b.lo_rational(), b.hi_rational()),
        }
    }

    /// The width of [`RealRoot::interval`].
    pub fn width(&self) -> Rational {
        match &self.location {
            Location::Exact(_) => Rational::new(),
            Location::Isolated(b) => b.width(),
        }
    }

    /// The multiplicity of the root in the input polynomial.
    pub fn multiplicity(&self) -> u32 {
        self.multiplicity
    }

    /// The root correctly rounded to the nearest double (ties to even).
    pub fn nearest(&self) -> f64 {
        self.rounded.nearest
    }

    /// The rounding with its tight enclosure (`lo == hi` iff the root is a double).
    pub fn rounded(&self) -> Rounded {
        self.rounded
    }

    /// The square-free factor of the input of which this is a simple root (primitive
    /// integer coefficients).
    pub fn factor(&self) -> Polynomial {
        self.factor.to_polynomial()
    }

    /// Shrink the interval: at least halve it (a no-op on rational roots).
    pub fn refine(&mut self) {
        if let Location::Isolated(b) = &mut self.location {
            if let Some(x) = b.step(&self.factor) {
                self.location = Location::Exact(x);
            }
        }
    }

    /// Refine until the interval is no wider than `width` (`width > 0`).
    pub fn refine_to_width(&mut self, width: &Rational) {
        if width.cmp0() != Ordering::Greater {
            return;
        }
        while self.width() > *width {
            self.refine();
        }
    }

    /// True when the root is also a root of `p` (exact): for an isolated root, `p`
    /// vanishes there iff `h = gcd(factor, p)` does; `h` divides the square-free factor,
    /// whose only root in the bracket is this one and whose ends are not roots, so that
    /// happens iff `h` changes sign across the bracket. The zero polynomial vanishes
    /// everywhere.
    pub fn is_root_of(&self, p: &Polynomial) -> bool {
        if p.is_zero() {
            return true;
        }
        match &self.location {
            Location::Exact(x) => p.eval(x).cmp0() == Ordering::Equal,
            Location::Isolated(b) => {
                let h = IntPoly::gcd(&self.factor, &IntPoly::from_polynomial(p));
                h.degree() > 0
                    && h.sign_at(At::Dyadic(&b.lo, b.e)) != h.sign_at(At::Dyadic(&b.hi, b.e))
            }
        }
    }

    /// The exact sign of `root − x`.
    pub fn compare(&self, x: &Rational) -> Ordering {
        match &self.location {
            Location::Exact(r) => r.cmp(x),
            Location::Isolated(b) => b.compare_root_with(&self.factor, x),
        }
    }

    fn decide_rationality(&mut self) {
        if let Location::Isolated(b) = &mut self.location {
            if let Some(x) = rational_root_in(b, &self.factor) {
                self.location = Location::Exact(x);
            }
        }
    }

    fn decide_rounding(&mut self) {
        loop {
            let b = match &self.location {
                Location::Exact(x) => {
                    self.rounded = round_rational(x);
                    return;
                }
                Location::Isolated(b) => b,
            };
            // The root is irrational, hence not zero: wait until the bracket has a sign,
            // and try rounding only once it is about one ulp wide (a cheap test).
            if (b.lo.cmp0() != Ordering::Less || b.hi.cmp0() != Ordering::Greater)
                && b.about_one_ulp()
            {
                let lo = b.lo_rational();
                let hi = b.hi_rational();
                let (rl, rh) = (round_rational(&lo), round_rational(&hi));
                if rl.nearest == rh.nearest {
                    if rl.overflowed() {
                        self.rounded = rl;
                        return;
                    }
                    let d = rl.nearest;
                    let dr = Rational::from_f64(d).unwrap_or_default();
                    if dr <= lo {
                        self.rounded = Rounded::inexact(d, Ordering::Greater);
                        return;
                    }
                    if dr >= hi {
                        self.rounded = Rounded::inexact(d, Ordering::Less);
                        return;
                    }
                }
            }
            self.refine();
        }
    }
}

/// The root of the square-free `g` in the bracket when it is rational (see the module
/// documentation); the bracket may be narrowed on the way.
fn rational_root_in(b: &mut Bracket, g: &IntPoly) -> Option<Rational> {
    match g.degree() {
        1 => Some(Rational::from((-g.c[0].clone(), g.c[1].clone()))),
        2 => {
            let (c0, c1, c2) = (&g.c[0], &g.c[1], &g.c[2]);
            let disc = Integer::from(c1 * c1) - Integer::from(c0 * c2) * 4u32;
            if !disc.is_perfect_square() {
                return None;
            }
            let s = disc.sqrt();
            let two_a = Integer::from(c2 * 2u32);
            let r1 = Rational::from((-Integer::from(c1 + &s), two_a.clone()));
            let r2 = Rational::from((Integer::from(&s - c1), two_a));
            // Both roots are rational; the bracket holds exactly one of them.
            Some(if b.lo_rational() < r1 && r1 < b.hi_rational() {
                r1
            } else {
                r2
            })
        }
        _ => {
            // Narrow to width < 1/lc, then test the one candidate k/lc.
            let lc = g.lc();
            while Integer::from(&b.hi - &b.lo) * &lc >= (Integer::from(1) << b.e) {
                if let Some(x) = b.step(g) {
                    return Some(x);
                }
            }
            let (k, _) = Integer::from(&b.lo * &lc).div_rem_ceil(Integer::from(1) << b.e);
            let x = Rational::from((k, lc));
            (x < b.hi_rational() && g.eval_rational(&x).cmp0() == Ordering::Equal).then_some(x)
        }
    }
}
