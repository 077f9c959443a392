//! An isolating interval with dyadic end points and its refinement: bisection and
//! Abbott's quadratic interval refinement (QIR; J. Abbott, "Quadratic interval
//! refinement for real roots", 2006; Kerber & Sagraloff 2011).
//!
//! A bracket `(lo/2ᵉ, hi/2ᵉ)` holds exactly one root of a square-free integer
//! polynomial `g`, which is non-zero with opposite signs at the two ends. Every step
//! keeps that invariant by exact sign evaluation, so it never loses the root:
//!
//! * bisection tests the midpoint;
//! * QIR splits the bracket into `N = 2ⁿ` cells, takes the cell `k` nearest to the secant
//!   root `k = round(N·g(lo)/(g(lo) − g(hi)))` and tests the signs at the cell's two ends;
//!   if they differ, the bracket shrinks by `N` and `n` doubles (quadratic convergence
//!   near a simple root), else `n` halves and a bisection follows.
//!
//! Every step at least halves the bracket, or lands exactly on the root (returned as a
//! rational). All points are dyadic, so the numbers stay as short as the width asks.

use std::cmp::Ordering;

use rug::{Integer, Rational};

use super::int_poly::IntPoly;

/// QIR grid sizes stop growing at `2^MAX_QIR_BITS` cells per step.
const MAX_QIR_BITS: u32 = 1 << 14;

/// `(lo/2ᵉ, hi/2ᵉ)`, `lo < hi`, one root of the polynomial inside, none at the ends.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Bracket {
    pub(crate) lo: Integer,
    pub(crate) hi: Integer,
    pub(crate) e: u32,
    /// The sign of the polynomial at `lo` (never `Equal`); at `hi` it is the opposite.
    pub(crate) sign_lo: Ordering,
    /// log₂ of the QIR grid size.
    qir: u32,
    /// `(g(lo)·2^{e·deg g}, g(hi)·2^{e·deg g})` once computed, kept exact across steps
    /// (the points a step tests become the new ends).
    values: Option<(Integer, Integer)>,
}

/// The dyadic `m/2ᵉ` as a rational.
pub(crate) fn dyadic(m: &Integer, e: u32) -> Rational {
    Rational::from(m.clone()) >> e
}

impl Bracket {
    pub(crate) fn new(lo: Integer, hi: Integer, e: u32, sign_lo: Ordering) -> Bracket {
        let mut b = Bracket {
            lo,
            hi,
            e,
            sign_lo,
            qir: 2,
            values: None,
        };
        b.normalize(0);
        b
    }

    pub(crate) fn lo_rational(&self) -> Rational {
        dyadic(&self.lo, self.e)
    }

    pub(crate) fn hi_rational(&self) -> Rational {
        dyadic(&self.hi, self.e)
    }

    /// `hi − lo` as a rational.
    pub(crate) fn width(&self) -> Rational {
        dyadic(&Integer::from(&self.hi - &self.lo), self.e)
    }

    /// True when the bracket is at most about one double's spacing wide:
    /// `width·2⁵² ≤ max(|lo|, |hi|)`, or `width ≤ 2⁻¹⁰⁷⁴` (the subnormal spacing). Only
    /// then can both ends round to the same double, so rounding is tried no earlier.
    pub(crate) fn about_one_ulp(&self) -> bool {
        let w = Integer::from(&self.hi - &self.lo);
        let m = if self.lo.cmp_abs(&self.hi) == Ordering::Greater {
            &self.lo
        } else {
            &self.hi
        };
        Integer::from(&w << 52u32).cmp_abs(m) != Ordering::Greater
            || u64::from(w.significant_bits()) + 1074 <= u64::from(self.e)
    }

    /// Drop common factors of two from the end points; the cached values of the degree
    /// `deg` polynomial scale by `2^{−s·deg}` (exactly: each term has the factor).
    fn normalize(&mut self, deg: usize) {
        let tz = |x: &Integer| x.find_one(0).unwrap_or(u32::MAX);
        let s = tz(&self.lo).min(tz(&self.hi)).min(self.e);
        if s > 0 {
            self.lo >>= s;
            self.hi >>= s;
            self.e -= s;
            if let Some((a, b)) = &mut self.values {
                *a >>= s * deg as u32;
                *b >>= s * deg as u32;
            }
        }
    }

    /// The homogeneous values at the ends (computed if not cached).
    fn take_values(&mut self, g: &IntPoly) -> (Integer, Integer) {
        self.values.take().unwrap_or_else(|| {
            (
                g.eval_dyadic(&self.lo, self.e),
                g.eval_dyadic(&self.hi, self.e),
            )
        })
    }

    /// Replace the bracket by `(lo/2ᵉ, hi/2ᵉ)` with the values there.
    fn set(&mut self, ends: (Integer, Integer), e: u32, values: (Integer, Integer), deg: usize) {
        self.lo = ends.0;
        self.hi = ends.1;
        self.e = e;
        self.values = Some(values);
        self.normalize(deg);
    }

    /// One refinement step (see the module documentation). Returns the root when a
    /// tested point is exactly the root.
    pub(crate) fn step(&mut self, g: &IntPoly) -> Option<Rational> {
        if self.qir >= 2 {
            match self.qir_step(g) {
                Ok(found) => return found,
                Err(()) => self.qir /= 2,
            }
        } else {
            self.qir = 2;
        }
        self.bisect(g)
    }

    fn bisect(&mut self, g: &IntPoly) -> Option<Rational> {
        let deg = g.degree();
        let (va, vb) = self.take_values(g);
        let (va, vb) = (va << deg as u32, vb << deg as u32);
        let m = Integer::from(&self.lo + &self.hi);
        let (lo, hi, e) = (
            Integer::from(&self.lo << 1),
            Integer::from(&self.hi << 1),
            self.e + 1,
        );
        let vm = g.eval_dyadic(&m, e);
        let s = vm.cmp0();
        if s == Ordering::Equal {
            return Some(dyadic(&m, e));
        }
        if s == self.sign_lo {
            self.set((m, hi), e, (vm, vb), deg);
        } else {
            self.set((lo, m), e, (va, vm), deg);
        }
        None
    }

    /// One QIR attempt: `Ok(None)` on success, `Ok(Some(root))` when a grid point is
    /// the root, `Err` on failure (the bracket may still have shrunk, validly).
    fn qir_step(&mut self, g: &IntPoly) -> Result<Option<Rational>, ()> {
        let n = self.qir;
        let deg = g.degree();
        let (va, vb) = self.take_values(g);
        let cells = Integer::from(1) << n;
        // va and vb have opposite signs, so va/(va − vb) ∈ (0, 1).
        let (k, _) = Integer::from(&va << n).div_rem_round(Integer::from(&va - &vb));
        let k = if k.cmp0() == Ordering::Less {
            Integer::new()
        } else if k > cells {
            cells.clone()
        } else {
            k
        };
        let w = Integer::from(&self.hi - &self.lo);
        // The grid at exponent e + n; values there scale by 2^{n·deg}.
        let lo = Integer::from(&self.lo << n);
        let hi = Integer::from(&self.hi << n);
        let e = self.e + n;
        let up = n * deg as u32;
        let (va, vb) = (va << up, vb << up);
        let point = |idx: &Integer| -> (Integer, Integer) {
            if idx.cmp0() == Ordering::Equal {
                (lo.clone(), va.clone())
            } else if *idx == cells {
                (hi.clone(), vb.clone())
            } else {
                let x: Integer = &lo + Integer::from(idx * &w);
                let v = g.eval_dyadic(&x, e);
                (x, v)
            }
        };
        let (m, vm) = point(&k);
        let sm = vm.cmp0();
        if sm == Ordering::Equal {
            return Ok(Some(dyadic(&m, e)));
        }
        let success = if sm == self.sign_lo {
            // The root lies right of m.
            let (m2, v2) = point(&Integer::from(&k + 1u32));
            let s2 = v2.cmp0();
            if s2 == Ordering::Equal {
                return Ok(Some(dyadic(&m2, e)));
            }
            if s2 != self.sign_lo {
                self.set((m, m2), e, (vm, v2), deg);
                true
            } else {
                self.set((m2, hi), e, (v2, vb), deg);
                false
            }
        } else {
            let (m0, v0) = point(&Integer::from(&k - 1u32));
            let s0 = v0.cmp0();
            if s0 == Ordering::Equal {
                return Ok(Some(dyadic(&m0, e)));
            }
            if s0 == self.sign_lo {
                self.set((m0, m), e, (v0, vm), deg);
                true
            } else {
                self.set((lo, m0), e, (va, v0), deg);
                false
            }
        };
        if success {
            self.qir = (2 * n).min(MAX_QIR_BITS);
            Ok(None)
        } else {
            Err(())
        }
    }

    /// The sign of `root − x` for a rational `x` (exact; `Equal` when `x` is the root).
    pub(crate) fn compare_root_with(&self, g: &IntPoly, x: &Rational) -> Ordering {
        if *x <= self.lo_rational() {
            return Ordering::Greater;
        }
        if *x >= self.hi_rational() {
            return Ordering::Less;
        }
        let s = g.eval_rational(x).cmp0();
        if s == Ordering::Equal {
            Ordering::Equal
        } else if s == self.sign_lo {
            Ordering::Greater
        } else {
            Ordering::Less
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refinement_keeps_the_root_and_shrinks() {
        // x² − 2 on (1, 2): √2 stays inside, the width falls below 2^-200 quickly.
        let g = IntPoly {
            c: vec![Integer::from(-2), Integer::new(), Integer::from(1)],
        };
        let mut b = Bracket::new(Integer::from(1), Integer::from(2), 0, Ordering::Less);
        let tiny = Rational::from(1) >> 200u32;
        let mut steps = 0;
        while b.width() > tiny {
            assert!(b.step(&g).is_none());
            steps += 1;
            let lo = b.lo_rational();
            let hi = b.hi_rational();
            assert!(Rational::from(&lo * &lo) < 2 && Rational::from(&hi * &hi) > 2);
        }
        // Bisection alone would need 200 steps.
        assert!(steps < 60, "{steps} steps");
    }

    #[test]
    fn exact_roots_are_landed_on() {
        // x − 3/4 on (0, 1): bisection hits 3/4.
        let g = IntPoly {
            c: vec![Integer::from(-3), Integer::from(4)],
        };
        let mut b = Bracket::new(Integer::new(), Integer::from(1), 0, Ordering::Less);
        let mut found = None;
        for _ in 0..10 {
            if let Some(r) = b.step(&g) {
                found = Some(r);
                break;
            }
        }
        assert_eq!(found, Some(Rational::from((3, 4))));
    }
}
