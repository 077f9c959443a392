//! Set operations and numeric functions of [`Interval`] (IEEE 1788 §10.5.9–10.6):
//! bounds, midpoint, radius, width, magnitude, mignitude, containment, hull,
//! intersection, bisection.

use super::directed::{add_up, next_up};
use super::Interval;

impl Interval {
    /// The midpoint, rounded to nearest (IEEE 1788 `mid`): `0` for the whole line,
    /// `∓f64::MAX` for a half-line, `0.5·(lo + hi)` (or `0.5·lo + 0.5·hi` if the sum
    /// overflows) otherwise; always inside the interval. NaN for the empty set.
    pub fn midpoint(&self) -> f64 {
        let (lo, hi) = (self.lo(), self.hi());
        if self.is_empty() {
            f64::NAN
        } else if lo == f64::NEG_INFINITY {
            if hi == f64::INFINITY {
                0.0
            } else {
                -f64::MAX
            }
        } else if hi == f64::INFINITY {
            f64::MAX
        } else {
            let m = 0.5 * (lo + hi);
            if m.is_finite() {
                m
            } else {
                0.5 * lo + 0.5 * hi
            }
        }
    }

    /// The radius rounded up: the least double `r` with `[m − r, m + r] ⊇ self` for
    /// `m = self.midpoint()` (IEEE 1788 `rad`); `+∞` if unbounded, NaN if empty.
    pub fn radius(&self) -> f64 {
        if self.is_empty() {
            return f64::NAN;
        }
        let m = self.midpoint();
        add_up(m, self.neg_lo()).max(add_up(self.hi(), -m))
    }

    /// The width `hi − lo` rounded up (IEEE 1788 `wid`); `+∞` if unbounded, NaN if
    /// empty.
    pub fn width(&self) -> f64 {
        if self.is_empty() {
            return f64::NAN;
        }
        add_up(self.hi(), self.neg_lo())
    }

    /// The magnitude `max |x|` over the interval (exact); NaN if empty.
    pub fn mag(&self) -> f64 {
        if self.is_empty() {
            return f64::NAN;
        }
        self.neg_lo().max(self.hi())
    }

    /// The mignitude `min |x|` over the interval (exact): 0 if it contains 0; NaN if
    /// empty.
    pub fn mig(&self) -> f64 {
        if self.is_empty() {
            f64::NAN
        } else if self.lo() > 0.0 {
            self.lo()
        } else if self.hi() < 0.0 {
            -self.hi()
        } else {
            0.0
        }
    }

    /// True if the real `x` lies in the interval (false for NaN).
    #[inline]
    pub fn contains(&self, x: f64) -> bool {
        self.lo() <= x && x <= self.hi()
    }

    /// True if 0 lies in the interval.
    #[inline]
    pub fn contains_zero(&self) -> bool {
        self.neg_lo() >= 0.0 && self.hi() >= 0.0
    }

    /// `self ⊆ other` (the empty set is a subset of everything).
    #[inline]
    pub fn is_subset(&self, other: &Interval) -> bool {
        self.is_empty() || (other.neg_lo() >= self.neg_lo() && other.hi() >= self.hi())
    }

    /// `self ⊆ interior(other)` (IEEE 1788 `interior`: an infinite bound of `other`
    /// counts as interior, and the empty set is interior to everything). For a
    /// bounded `other` this is `other.lo < self.lo ∧ self.hi < other.hi`.
    #[inline]
    pub fn is_interior_subset(&self, other: &Interval) -> bool {
        self.is_empty()
            || ((other.neg_lo() > self.neg_lo() || other.neg_lo() == f64::INFINITY)
                && (other.hi() > self.hi() || other.hi() == f64::INFINITY))
    }

    /// True if the two sets do not meet.
    #[inline]
    pub fn is_disjoint(&self, other: &Interval) -> bool {
        self.intersection(other).is_empty()
    }

    /// The smallest interval containing both (IEEE 1788 `convexHull`).
    #[inline]
    pub fn hull(&self, other: &Interval) -> Interval {
        Interval::from_neg_lo_hi(self.neg_lo().max(other.neg_lo()), self.hi().max(other.hi()))
    }

    /// The intersection, possibly EMPTY.
    #[inline]
    pub fn intersection(&self, other: &Interval) -> Interval {
        let neg_lo = self.neg_lo().min(other.neg_lo());
        let hi = self.hi().min(other.hi());
        if -neg_lo > hi || self.is_empty() || other.is_empty() {
            Interval::EMPTY
        } else {
            Interval::from_neg_lo_hi(neg_lo, hi)
        }
    }

    /// Bisection at the midpoint: `([lo, m], [m, hi])`, whose union is `self`.
    /// For a point interval both halves are the point; the empty set gives two empties.
    pub fn bisect(&self) -> (Interval, Interval) {
        if self.is_empty() {
            return (Interval::EMPTY, Interval::EMPTY);
        }
        let m = self.midpoint();
        (
            Interval::from_neg_lo_hi(self.neg_lo(), m),
            Interval::from_neg_lo_hi(-m, self.hi()),
        )
    }

    /// The interval widened by one ulp on each side (a cheap inflation for
    /// ε-inflation in Krawczyk iterations); EMPTY stays EMPTY.
    pub fn inflate_ulp(&self) -> Interval {
        if self.is_empty() {
            return Interval::EMPTY;
        }
        Interval::from_neg_lo_hi(next_up(self.neg_lo()), next_up(self.hi()))
    }
}
