//! The precision levels of the escalation (docs/CERTIFICATES.md "Escalation": f64 intervals,
//! then MPFR intervals at 128, 256, 512, … bits up to a cap) and what the generic
//! certifier needs from an interval type beyond [`IntervalLike`]: conversions between
//! levels and an approximate inverse for preconditioning.
//!
//! Boxes travel between levels as MPFR intervals: an f64 interval converts exactly, and a
//! `p`-bit interval converts exactly to any precision `≥ p`; going down (to report a box in
//! doubles) rounds outward.

use super::linalg;
use crate::certificate::Arithmetic;
use crate::num::{Interval, IntervalLike, MpfrInterval};

/// An interval type the certifier runs in (implemented by [`Interval`] and
/// [`MpfrInterval`]).
pub trait CertInterval: IntervalLike {
    /// How a result decided in this type is labelled.
    const ARITHMETIC: Arithmetic;
    /// `x` at `bits` bits of precision (exact when `bits ≥ x`'s precision, else outward).
    fn from_mpfr(x: &MpfrInterval, bits: u32) -> Self;
    /// The same set as an MPFR interval (exact).
    fn to_mpfr(&self) -> MpfrInterval;
    /// The tightest f64 interval containing `self` (outward).
    fn to_f64_interval(&self) -> Interval;
    /// An approximate inverse of the point matrix `a` (entries are point intervals), as
    /// point intervals of the same precision; `None` if numerically singular. Only the
    /// quality of a Krawczyk preconditioner depends on it, never a proof.
    fn approx_inverse(a: &[Vec<Self>]) -> Option<Vec<Vec<Self>>>;
}

impl CertInterval for Interval {
    const ARITHMETIC: Arithmetic = Arithmetic::Interval;
    fn from_mpfr(x: &MpfrInterval, _bits: u32) -> Self {
        x.to_interval()
    }
    fn to_mpfr(&self) -> MpfrInterval {
        MpfrInterval::from_interval(self, 53)
    }
    fn to_f64_interval(&self) -> Interval {
        *self
    }
    fn approx_inverse(a: &[Vec<Self>]) -> Option<Vec<Vec<Self>>> {
        let mid: Vec<Vec<f64>> = a
            .iter()
            .map(|r| r.iter().map(|x| x.midpoint()).collect())
            .collect();
        let inv = linalg::inverse_f64(&mid)?;
        Some(
            inv.into_iter()
                .map(|r| r.into_iter().map(Interval::point).collect())
                .collect(),
        )
    }
}

impl CertInterval for MpfrInterval {
    const ARITHMETIC: Arithmetic = Arithmetic::Mpfr;
    fn from_mpfr(x: &MpfrInterval, bits: u32) -> Self {
        x.with_prec(bits)
    }
    fn to_mpfr(&self) -> MpfrInterval {
        self.clone()
    }
    fn to_f64_interval(&self) -> Interval {
        self.to_interval()
    }
    fn approx_inverse(a: &[Vec<Self>]) -> Option<Vec<Vec<Self>>> {
        linalg::inverse_gauss_jordan(a)
    }
}

/// The precisions tried, in order, up to the cap `max_bits`: 53 (f64 intervals), then
/// 128, 256, 512, … (doubling) while `≤ max_bits`.
pub fn levels(max_bits: u32) -> Vec<u32> {
    let mut out = vec![53];
    let mut b = 128u32;
    while b <= max_bits {
        out.push(b);
        match b.checked_mul(2) {
            Some(next) => b = next,
            None => break,
        }
    }
    out
}

/// The box `x` at `bits` bits (exactly if it fits).
pub fn box_at<I: CertInterval>(x: &[MpfrInterval], bits: u32) -> Vec<I> {
    x.iter().map(|v| I::from_mpfr(v, bits)).collect()
}

/// The box `x` as MPFR intervals (exact).
pub fn box_to_mpfr<I: CertInterval>(x: &[I]) -> Vec<MpfrInterval> {
    x.iter().map(|v| v.to_mpfr()).collect()
}

/// The box `x` as f64 intervals (outward).
pub fn box_to_f64<I: CertInterval>(x: &[I]) -> Vec<Interval> {
    x.iter().map(|v| v.to_f64_interval()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_double_up_to_the_cap() {
        assert_eq!(levels(53), vec![53]);
        assert_eq!(levels(127), vec![53]);
        assert_eq!(levels(512), vec![53, 128, 256, 512]);
        assert_eq!(levels(1000), vec![53, 128, 256, 512]);
        assert_eq!(levels(4096), vec![53, 128, 256, 512, 1024, 2048, 4096]);
    }

    #[test]
    fn conversions_are_exact_upward_and_outward_downward() {
        let x = Interval::from_bounds(0.1, 0.3);
        let m = x.to_mpfr();
        assert_eq!(<Interval as CertInterval>::from_mpfr(&m, 53), x);
        let third = MpfrInterval::point(1.0, 200) / MpfrInterval::point(3.0, 200);
        let down = third.to_f64_interval();
        // f64(1/3) lies below 1/3: it is the lower bound, its successor the upper
        assert_eq!(down.lo(), 1.0 / 3.0);
        assert_eq!(
            down.hi(),
            crate::num::interval::directed::next_up(1.0 / 3.0)
        );
        let back = MpfrInterval::from_interval(&down, 200);
        assert!(third.is_subset(&back), "{third:?} {down:?} {back:?}");
        assert_eq!(third.with_prec(400).with_prec(200), third);
    }
}
