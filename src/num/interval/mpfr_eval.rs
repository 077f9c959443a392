//! Correctly rounded endpoint evaluation through MPFR for [`super::Interval`]'s
//! elementary functions: `f(x)` rounded at 53 bits in a direction, then converted to a
//! double in the same direction. MPFR's functions are correctly rounded (its
//! documented guarantee), and two roundings in one direction compose to the directed
//! rounding onto the coarser set (the doubles, including subnormals and overflow to
//! ±∞ / ±f64::MAX), so the result is the tightest double bound of `f(x)`.
//! A thread-local scratch number avoids an allocation per call.

use rug::float::Round;
use rug::Float;
use std::cell::RefCell;
use std::cmp::Ordering;

thread_local! {
    static SCRATCH: RefCell<(Float, Float)> = RefCell::new((Float::new(53), Float::new(53)));
}

/// `f(x)` rounded in direction `round` to a double; `f` applies the MPFR function in
/// place with the given rounding.
pub(crate) fn eval_f64(x: f64, round: Round, f: impl FnOnce(&mut Float, Round) -> Ordering) -> f64 {
    SCRATCH.with(|s| {
        let mut s = s.borrow_mut();
        let t = &mut s.0;
        // 53 bits hold a double exactly.
        t.assign_f64_exact(x);
        f(t, round);
        t.to_f64_round(round)
    })
}

/// `atan2(y, x)` rounded in direction `round` to a double.
pub(crate) fn atan2_f64(y: f64, x: f64, round: Round) -> f64 {
    SCRATCH.with(|s| {
        let mut s = s.borrow_mut();
        let (t, u) = &mut *s;
        t.assign_f64_exact(y);
        u.assign_f64_exact(x);
        t.atan2_round(u, round);
        t.to_f64_round(round)
    })
}

/// π rounded down / up to doubles.
pub(crate) const PI_DOWN: f64 = std::f64::consts::PI;
pub(crate) const PI_UP: f64 = 3.141_592_653_589_793_6;
/// π/2 rounded down / up to doubles.
pub(crate) const HALF_PI_DOWN: f64 = std::f64::consts::FRAC_PI_2;
pub(crate) const HALF_PI_UP: f64 = 1.570_796_326_794_896_8;

trait AssignExact {
    fn assign_f64_exact(&mut self, x: f64);
}

impl AssignExact for Float {
    #[inline]
    fn assign_f64_exact(&mut self, x: f64) {
        use rug::Assign;
        debug_assert!(self.prec() >= 53);
        self.assign(x);
    }
}

/// `v` rounded down at `prec` bits.
#[inline]
pub(crate) fn rd<T>(prec: u32, v: T) -> Float
where
    Float: rug::ops::AssignRound<T, Round = Round, Ordering = std::cmp::Ordering>,
{
    Float::with_val_round(prec, v, Round::Down).0
}

/// `v` rounded up at `prec` bits.
#[inline]
pub(crate) fn ru<T>(prec: u32, v: T) -> Float
where
    Float: rug::ops::AssignRound<T, Round = Round, Ordering = std::cmp::Ordering>,
{
    Float::with_val_round(prec, v, Round::Up).0
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::float::Constant;

    #[test]
    fn pi_constants_bracket_pi_tightly() {
        let pi = Float::with_val(300, Constant::Pi);
        assert!(Float::with_val(300, PI_DOWN) < pi && pi < Float::with_val(300, PI_UP));
        assert_eq!(super::super::directed::next_up(PI_DOWN), PI_UP);
        let half = Float::with_val(300, &pi / 2u32);
        assert!(Float::with_val(300, HALF_PI_DOWN) < half);
        assert!(half < Float::with_val(300, HALF_PI_UP));
        assert_eq!(super::super::directed::next_up(HALF_PI_DOWN), HALF_PI_UP);
    }

    #[test]
    fn directed_evaluation_brackets_and_is_one_ulp_wide() {
        for &x in &[0.5, 1.0, 2.0, 10.0, -3.0] {
            let lo = eval_f64(x, Round::Down, |t, r| t.exp_round(r));
            let hi = eval_f64(x, Round::Up, |t, r| t.exp_round(r));
            let exact = Float::with_val(300, x).exp();
            assert!(Float::with_val(53, lo) <= exact && exact <= Float::with_val(53, hi));
            assert_eq!(super::super::directed::next_up(lo), hi);
        }
        // Overflow: exp(1000) lies above f64::MAX.
        assert_eq!(
            eval_f64(1000.0, Round::Down, |t, r| t.exp_round(r)),
            f64::MAX
        );
        assert_eq!(
            eval_f64(1000.0, Round::Up, |t, r| t.exp_round(r)),
            f64::INFINITY
        );
        // Underflow to subnormals: exp(-740) ≈ 4.2e-322, rounded to the subnormal grid.
        let lo = eval_f64(-740.0, Round::Down, |t, r| t.exp_round(r));
        let hi = eval_f64(-740.0, Round::Up, |t, r| t.exp_round(r));
        assert!(lo > 0.0 && lo < f64::MIN_POSITIVE);
        assert_eq!(hi.to_bits(), lo.to_bits() + 1);
        assert_eq!(
            atan2_f64(1.0, -1.0, Round::Up),
            atan2_f64(1.0, -1.0, Round::Down).next_up_bits()
        );
    }

    trait NextUpBits {
        fn next_up_bits(self) -> f64;
    }
    impl NextUpBits for f64 {
        fn next_up_bits(self) -> f64 {
            super::super::directed::next_up(self)
        }
    }
}
