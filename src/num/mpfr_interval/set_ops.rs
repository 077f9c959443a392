//! Set operations and numeric functions of [`MpfrInterval`] (as for
//! [`crate::num::Interval`], with MPFR bounds): midpoint, radius, width, magnitude,
//! mignitude, containment, hull, intersection, bisection.

use rug::Float;

use super::{rd, ru, MpfrInterval};

impl MpfrInterval {
    /// The midpoint, rounded to nearest at the interval's precision, always inside the
    /// interval: `(lo + hi)/2` if bounded; 0 for the whole line; for a half-line, the
    /// finite bound or ±f64::MAX, whichever lies inside. NaN if empty.
    pub fn midpoint(&self) -> Float {
        let p = self.prec();
        if self.is_empty() {
            return Float::with_val(p, f64::NAN);
        }
        let (lo, hi) = (&self.lo, &self.hi);
        match (lo.is_finite(), hi.is_finite()) {
            (true, true) => {
                let mut m = Float::with_val(p, lo + hi);
                m /= 2u32;
                m
            }
            (false, false) => Float::new(p),
            (false, true) => {
                if *hi >= -f64::MAX {
                    Float::with_val(p, -f64::MAX)
                } else {
                    hi.clone()
                }
            }
            (true, false) => {
                if *lo <= f64::MAX {
                    Float::with_val(p, f64::MAX)
                } else {
                    lo.clone()
                }
            }
        }
    }

    /// The point interval `[m, m]` at the midpoint (exact: `m` has the precision).
    pub fn mid_point_interval(&self) -> MpfrInterval {
        if self.is_empty() {
            return self.clone();
        }
        let m = self.midpoint();
        MpfrInterval::from_floats(m.clone(), m)
    }

    /// An upper bound of the radius about [`MpfrInterval::midpoint`]:
    /// `max(hi − m, m − lo)` rounded up (+∞ if unbounded, NaN if empty).
    pub fn radius(&self) -> Float {
        let p = self.prec();
        if self.is_empty() {
            return Float::with_val(p, f64::NAN);
        }
        let m = self.midpoint();
        let r1 = ru(p, &self.hi - &m);
        let r2 = ru(p, &m - &self.lo);
        r1.max(&r2)
    }

    /// The width `hi − lo` rounded up (+∞ if unbounded, NaN if empty).
    pub fn width(&self) -> Float {
        let p = self.prec();
        if self.is_empty() {
            return Float::with_val(p, f64::NAN);
        }
        ru(p, &self.hi - &self.lo)
    }

    /// `max |x|` (exact; NaN if empty).
    pub fn mag_float(&self) -> Float {
        let p = self.prec();
        if self.is_empty() {
            return Float::with_val(p, f64::NAN);
        }
        let neg_lo = Float::with_val(p, -&self.lo);
        neg_lo.max(&self.hi)
    }

    /// `min |x|` (exact; 0 if the interval contains 0, NaN if empty).
    pub fn mig_float(&self) -> Float {
        let p = self.prec();
        if self.is_empty() {
            Float::with_val(p, f64::NAN)
        } else if self.lo > 0 {
            self.lo.clone()
        } else if self.hi < 0 {
            Float::with_val(p, -&self.hi)
        } else {
            Float::new(p)
        }
    }

    /// `x ∈ self` for a double.
    pub fn contains(&self, x: f64) -> bool {
        self.lo <= x && self.hi >= x
    }

    /// `x ∈ self` for an MPFR number (false for NaN).
    pub fn contains_float(&self, x: &Float) -> bool {
        self.lo <= *x && self.hi >= *x
    }

    /// `0 ∈ self`.
    pub fn contains_zero(&self) -> bool {
        self.lo <= 0 && self.hi >= 0
    }

    /// `self ⊆ other` (the empty set is a subset of everything).
    pub fn is_subset(&self, other: &MpfrInterval) -> bool {
        self.is_empty() || (other.lo <= self.lo && self.hi <= other.hi)
    }

    /// `self ⊆ interior(other)` (IEEE 1788 `interior`; an infinite bound of `other`
    /// counts as interior).
    pub fn is_interior_subset(&self, other: &MpfrInterval) -> bool {
        self.is_empty()
            || ((other.lo < self.lo || (other.lo.is_infinite() && other.lo < 0))
                && (self.hi < other.hi || (other.hi.is_infinite() && other.hi > 0)))
    }

    /// The convex hull of the union, at the larger precision.
    pub fn hull(&self, other: &MpfrInterval) -> MpfrInterval {
        let p = self.prec().max(other.prec());
        if self.is_empty() {
            return other.with_prec(p);
        }
        if other.is_empty() {
            return self.with_prec(p);
        }
        let lo = if self.lo <= other.lo {
            &self.lo
        } else {
            &other.lo
        };
        let hi = if self.hi >= other.hi {
            &self.hi
        } else {
            &other.hi
        };
        MpfrInterval::from_floats(rd(p, lo), ru(p, hi))
    }

    /// The intersection (possibly empty), at the larger precision.
    pub fn intersection(&self, other: &MpfrInterval) -> MpfrInterval {
        let p = self.prec().max(other.prec());
        if self.is_empty() || other.is_empty() {
            return MpfrInterval::empty(p);
        }
        let lo = if self.lo >= other.lo {
            &self.lo
        } else {
            &other.lo
        };
        let hi = if self.hi <= other.hi {
            &self.hi
        } else {
            &other.hi
        };
        if lo > hi {
            return MpfrInterval::empty(p);
        }
        MpfrInterval::from_floats(rd(p, lo), ru(p, hi))
    }

    /// Bisection at the midpoint: `([lo, m], [m, hi])`.
    pub fn bisect(&self) -> (MpfrInterval, MpfrInterval) {
        if self.is_empty() {
            return (self.clone(), self.clone());
        }
        let m = self.midpoint();
        (
            MpfrInterval::from_floats(self.lo.clone(), m.clone()),
            MpfrInterval::from_floats(m, self.hi.clone()),
        )
    }
}
