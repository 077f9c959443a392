//! Intervals that remember whether every operation was smooth on its operands: the
//! certifier's guard against systems defined only on part of a box (a `sqrt` or `ln`
//! of something that may be negative, a division by something that may vanish).
//!
//! The interval types follow IEEE 1788 set semantics (`crate::num::interval`, "Domain
//! and emptiness"): `√[-4, 1] = [0, 1]` silently drops the points where the operation is
//! undefined. That is the right enclosure of the *image*, and it keeps exclusion sound
//! (an image that misses 0, or is empty, proves there is no root where the system is
//! defined), but the Krawczyk and count theorems need the system to be `C¹` (`C²`) on the
//! whole box. [`Guarded`] carries that proof obligation: `smooth` is true only if every
//! operation that produced the value was applied to operands lying in an open set on which
//! the operation is `C^∞` — `√` and `ln` on `(0, ∞)`, division by a divisor that excludes
//! 0, `tan` away from its poles (its operand's cosine excludes 0), `atan2` off its branch
//! cut and the origin, negative powers away from 0 — and no value was empty. Then every
//! function evaluated this way is `C^∞` on the box (a composition of maps, each smooth on
//! an enclosure of its argument's range), and with [`super::dual::Dual`] on top its
//! derivatives are enclosed as well.

use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::num::{Arith, IntervalLike, Real};

/// An interval value and whether it was computed by smooth operations only (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Guarded<I> {
    /// The enclosure.
    pub value: I,
    /// Every operation was `C^∞` on (a neighbourhood of) its operands, and nothing was empty.
    pub smooth: bool,
}

impl<I: IntervalLike> Guarded<I> {
    /// An input value (smooth unless empty).
    pub fn new(value: I) -> Self {
        let smooth = !value.is_empty();
        Guarded { value, smooth }
    }

    fn make(value: I, smooth: bool) -> Self {
        let smooth = smooth && !value.is_empty();
        Guarded { value, smooth }
    }

    /// An operation smooth everywhere: only emptiness can spoil it.
    fn unary(&self, value: I) -> Self {
        Guarded::make(value, self.smooth)
    }

    /// An operation smooth on the open set `cond` says the operand lies in.
    fn unary_if(&self, value: I, cond: bool) -> Self {
        Guarded::make(value, self.smooth && cond)
    }
}

/// The interval lies in `(0, ∞)` (its lower bound, rounded down, is ≥ 0 and 0 is excluded).
fn positive<I: IntervalLike>(x: &I) -> bool {
    !x.is_empty() && !x.contains_zero() && x.inf() >= 0.0
}

/// Every `&Vec<Guarded<I>>` check of a system's output: all smooth.
pub fn all_smooth<I>(values: &[Guarded<I>]) -> bool {
    values.iter().all(|v| v.smooth)
}

macro_rules! binary {
    ($($Tr:ident $m:ident $cond:expr),*) => {$(
        impl<I: IntervalLike> $Tr<&Guarded<I>> for Guarded<I> {
            type Output = Guarded<I>;
            fn $m(self, rhs: &Guarded<I>) -> Guarded<I> {
                let cond: fn(&I) -> bool = $cond;
                let ok = self.smooth && rhs.smooth && cond(&rhs.value);
                Guarded::make($Tr::$m(self.value, &rhs.value), ok)
            }
        }
        impl<I: IntervalLike> $Tr<Guarded<I>> for Guarded<I> {
            type Output = Guarded<I>;
            fn $m(self, rhs: Guarded<I>) -> Guarded<I> {
                $Tr::$m(self, &rhs)
            }
        }
    )*};
}
binary!(
    Add add |_| true,
    Sub sub |_| true,
    Mul mul |_| true,
    Div div |d| !d.contains_zero()
);

impl<I: IntervalLike> Neg for Guarded<I> {
    type Output = Guarded<I>;
    fn neg(self) -> Guarded<I> {
        Guarded {
            value: -self.value,
            smooth: self.smooth,
        }
    }
}

impl<I: IntervalLike> Arith for Guarded<I> {
    fn lift(&self, v: f64) -> Self {
        Guarded::new(self.value.lift(v))
    }
}

impl<I: IntervalLike> Real for Guarded<I> {
    fn pi_like(&self) -> Self {
        Guarded::new(self.value.pi_like())
    }
    fn sqr(&self) -> Self {
        self.unary(self.value.sqr())
    }
    fn sqrt(&self) -> Self {
        self.unary_if(self.value.sqrt(), positive(&self.value))
    }
    fn powi(&self, n: i32) -> Self {
        self.unary_if(self.value.powi(n), n >= 0 || !self.value.contains_zero())
    }
    fn sin(&self) -> Self {
        self.unary(self.value.sin())
    }
    fn cos(&self) -> Self {
        self.unary(self.value.cos())
    }
    fn tan(&self) -> Self {
        let off_poles = !self.value.cos().contains_zero();
        self.unary_if(self.value.tan(), off_poles)
    }
    fn exp(&self) -> Self {
        self.unary(self.value.exp())
    }
    /// Joins pieces of a piecewise formula (B-spline spans, the seam of a periodic
    /// curve). Conservatively not smooth: across a knot a B-spline may be only `C⁰`,
    /// and the certifier's derivative-based conclusions must not rely on it.
    fn hull_with(&self, other: &Self) -> Self {
        Guarded::make(self.value.hull(&other.value), false)
    }
    /// Restricts to one piece's parameter range (smoothness unchanged).
    fn restrict_to(&self, lo: f64, hi: f64) -> Self {
        self.unary(self.value.restrict_to(lo, hi))
    }
    fn ln(&self) -> Self {
        self.unary_if(self.value.ln(), positive(&self.value))
    }
    fn sinh(&self) -> Self {
        self.unary(self.value.sinh())
    }
    fn cosh(&self) -> Self {
        self.unary(self.value.cosh())
    }
    fn atan2(&self, x: &Self) -> Self {
        // atan2(y, x) is C^∞ off {y = 0, x ≤ 0}: y excludes 0, or x lies in (0, ∞).
        let off_cut = !self.value.contains_zero() || positive(&x.value);
        Guarded::make(
            self.value.atan2(&x.value),
            self.smooth && x.smooth && off_cut,
        )
    }
    /// The wrapped interval's view (`None` unless it is an f64 interval).
    fn as_f64_interval(&self) -> Option<[f64; 2]> {
        self.value.as_f64_interval()
    }
    /// Smooth exactly when every argument is and the value is not empty (the fast
    /// path's function is `C^∞` on their box, [`Real::from_f64_interval`]). The wrapped
    /// type has no bookkeeping of its own to keep, so it is given no arguments.
    fn from_f64_interval(bounds: [f64; 2], args: &[&Self]) -> Option<Self> {
        let value = I::from_f64_interval(bounds, &[])?;
        Some(Guarded::make(value, args.iter().all(|a| a.smooth)))
    }
    fn mid(&self) -> f64 {
        self.value.mid()
    }
    fn bounds(&self) -> (f64, f64) {
        self.value.bounds()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Interval, MpfrInterval};

    fn g(lo: f64, hi: f64) -> Guarded<Interval> {
        Guarded::new(Interval::from_bounds(lo, hi))
    }

    #[test]
    fn partial_domains_are_not_smooth() {
        assert!(!g(-1.0, 4.0).sqrt().smooth);
        assert_eq!(g(-1.0, 4.0).sqrt().value, Interval::from_bounds(0.0, 2.0));
        assert!(!g(0.0, 4.0).sqrt().smooth, "√ is not differentiable at 0");
        assert!(g(1e-300, 4.0).sqrt().smooth);
        assert!(!g(-2.0, -1.0).sqrt().smooth, "empty image");
        assert!(!g(0.0, 1.0).ln().smooth);
        assert!(!(g(1.0, 2.0) / g(-1.0, 1.0)).smooth);
        assert!((g(1.0, 2.0) / g(0.5, 1.0)).smooth);
        assert!(!g(1.0, 2.0).tan().smooth, "π/2 inside");
        assert!(g(-1.0, 1.0).tan().smooth);
        assert!(!g(-1.0, 1.0).powi(-2).smooth);
        assert!(g(-1.0, 1.0).powi(3).smooth);
        // atan2's branch cut {y = 0, x ≤ 0} and the origin
        assert!(!g(-0.1, 0.1).atan2(&g(-2.0, -1.0)).smooth);
        assert!(!g(-0.1, 0.1).atan2(&g(0.0, 1.0)).smooth);
        assert!(g(-0.1, 0.1).atan2(&g(1.0, 2.0)).smooth);
        assert!(g(0.5, 1.0).atan2(&g(-2.0, -1.0)).smooth);
    }

    #[test]
    fn non_smoothness_propagates() {
        let bad = g(-1.0, 1.0).sqrt();
        let ok = g(2.0, 3.0);
        assert!(!(ok.clone() + &bad).smooth);
        assert!(!(bad.clone() * &ok).smooth);
        assert!(!bad.sin().smooth);
        assert!((ok.clone() * &ok.lift(2.0)).smooth);
        let m = Guarded::new(MpfrInterval::from_bounds(-1.0, 1.0, 128));
        assert!(!m.ln().smooth);
        assert!(m.exp().smooth);
    }

    /// Guarded f64 intervals take the surfaces' fast f64-interval path through the
    /// hook of [`Real::as_f64_interval`]: a NURBS jet on one span pair has exactly the
    /// f64 interval jet as values (the fast path's: `surface::nurbs`'s tests; the
    /// generic interval path gives other enclosures), smooth exactly when both
    /// parameters are.
    #[test]
    fn guarded_intervals_take_the_fast_surface_path() {
        use crate::surface::{nurbs::NurbsSurface, Surface};
        let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let points: Vec<Vec<[f64; 3]>> = (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| [j as f64, i as f64, ((i * j) % 3) as f64])
                    .collect()
            })
            .collect();
        let weights: Vec<Vec<f64>> = (0..4)
            .map(|i| (0..4).map(|j| 1.0 + ((i + j) % 3) as f64 * 0.25).collect())
            .collect();
        let s = NurbsSurface::new([3, 3], knots.clone(), knots, &points, Some(&weights)).unwrap();
        let (u, v) = (
            Interval::from_bounds(0.3, 0.31),
            Interval::from_bounds(0.6, 0.61),
        );
        let plain = s.jet(&u, &v, 2);
        let guarded = s.jet(&Guarded::new(u), &Guarded::new(v), 2);
        let values: Vec<[Interval; 3]> =
            guarded.iter().map(|e| e.clone().map(|g| g.value)).collect();
        assert_eq!(values, plain);
        assert!(guarded.iter().flatten().all(|g| g.smooth));
        let rough = Guarded {
            value: u,
            smooth: false,
        };
        let jet = s.jet(&rough, &Guarded::new(v), 2);
        assert!(jet.iter().flatten().all(|g| !g.smooth));
    }
}
