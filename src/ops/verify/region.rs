//! Boxes of exact rationals ([`Region`]) and the exact bounds of the distance between
//! two of them, the two tests of docs/CERTIFICATES.md "Verifying another program's
//! answer": a claim is within the tolerance of a solution when the *largest* distance
//! between the claim's region and the solution's box is at most the tolerance, and
//! beyond it when the *smallest* distance exceeds it.
//!
//! Every bound is computed exactly in rationals from the boxes' f64 ends (no rounding
//! at all), so both tests are proofs: the true claimed point lies in its region and the
//! true solution in its certified box.

use rug::Rational;
use std::cmp::Ordering;

/// An axis-aligned box with rational ends; `None` is an unbounded end (a certified
/// bound beyond the double range, `±∞`).
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    lo: Vec<Option<Rational>>,
    hi: Vec<Option<Rational>>,
}

/// `a − b` of two ends, `None` when either is unbounded.
fn diff(a: &Option<Rational>, b: &Option<Rational>) -> Option<Rational> {
    Some(Rational::from(a.as_ref()? - b.as_ref()?))
}

impl Region {
    /// The one point `v`.
    pub fn point(v: &[Rational]) -> Region {
        let ends: Vec<Option<Rational>> = v.iter().cloned().map(Some).collect();
        Region {
            lo: ends.clone(),
            hi: ends,
        }
    }

    /// The box of certified enclosures `[lo, hi]` (doubles, converted exactly). An
    /// infinite end is unbounded; a NaN end (never produced by a certified answer) is
    /// taken as unbounded too, which only weakens the conclusions drawn from it.
    pub fn from_bounds(bounds: &[[f64; 2]]) -> Region {
        let end = |x: f64| Rational::from_f64(x);
        Region {
            lo: bounds.iter().map(|b| end(b[0])).collect(),
            hi: bounds.iter().map(|b| end(b[1])).collect(),
        }
    }

    /// The box with the given exact ends (`None`: unbounded).
    pub fn from_ends(lo: Vec<Option<Rational>>, hi: Vec<Option<Rational>>) -> Region {
        debug_assert_eq!(lo.len(), hi.len());
        Region { lo, hi }
    }

    /// Number of coordinates.
    pub fn dim(&self) -> usize {
        self.lo.len()
    }

    /// A point of the region (the middle of each bounded coordinate, a bounded end
    /// otherwise, 0 for a coordinate unbounded both ways): an estimate for messages.
    pub fn center(&self) -> Vec<Rational> {
        self.lo
            .iter()
            .zip(&self.hi)
            .map(|(l, h)| match (l, h) {
                (Some(l), Some(h)) => Rational::from(l + h) / 2u32,
                (Some(x), None) | (None, Some(x)) => x.clone(),
                (None, None) => Rational::new(),
            })
            .collect()
    }

    /// The exact squared distance between the nearest points of two regions of the
    /// same dimension: per coordinate the gap `max(0, a.lo − b.hi, b.lo − a.hi)`, an
    /// unbounded end leaving no gap on its side.
    pub fn min_distance2(&self, other: &Region) -> Rational {
        let mut total = Rational::new();
        for k in 0..self.dim().min(other.dim()) {
            let gap = [
                diff(&self.lo[k], &other.hi[k]),
                diff(&other.lo[k], &self.hi[k]),
            ]
            .into_iter()
            .flatten()
            .filter(|g| g.cmp0() == Ordering::Greater)
            .max();
            if let Some(g) = gap {
                total += g.clone() * &g;
            }
        }
        total
    }

    /// The exact squared distance between the farthest points of two regions of the
    /// same dimension: per coordinate `max(a.hi − b.lo, b.hi − a.lo)`; `None` when an
    /// end is unbounded (the distance is not bounded).
    pub fn max_distance2(&self, other: &Region) -> Option<Rational> {
        let mut total = Rational::new();
        for k in 0..self.dim().min(other.dim()) {
            let a = diff(&self.hi[k], &other.lo[k])?;
            let b = diff(&other.hi[k], &self.lo[k])?;
            let span = a.max(b);
            total += span.clone() * &span;
        }
        Some(total)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(x: f64) -> Rational {
        Rational::from_f64(x).unwrap()
    }

    #[test]
    fn distances_between_boxes_are_exact() {
        let b = Region::from_bounds(&[[1.0, 2.0], [0.0, 1.0]]);
        let p = Region::point(&[q(4.0), q(0.5)]);
        // Nearest: (2, 0.5) at 2; farthest: (1, 0) or (1, 1) at √(9 + 0.25).
        assert_eq!(p.min_distance2(&b), q(4.0));
        assert_eq!(p.max_distance2(&b), Some(q(9.25)));
        // A point inside the box: no gap.
        let inside = Region::point(&[q(1.5), q(0.25)]);
        assert_eq!(inside.min_distance2(&b), 0);
        // An unbounded end: no upper bound, and no gap on that side.
        let open = Region::from_bounds(&[[f64::MAX, f64::INFINITY], [0.0, 0.0]]);
        let far = Region::point(&[q(f64::MAX) * 4u32, q(0.0)]);
        assert_eq!(far.min_distance2(&open), 0);
        assert_eq!(far.max_distance2(&open), None);
        let below = Region::point(&[q(0.0), q(0.0)]);
        assert_eq!(below.min_distance2(&open), q(f64::MAX) * q(f64::MAX));
        assert_eq!(open.center()[0], q(f64::MAX));
    }
}
