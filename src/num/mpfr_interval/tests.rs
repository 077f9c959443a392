//! Unit tests of the MPFR interval: precision handling (escalation 128 → 4096 bits),
//! tightness against exact rationals, conversions to and from f64 intervals.

use super::*;
use crate::num::interval::test_support::{random_interval, Rng};
use crate::num::{Arith, IntervalLike};
use rug::float::Constant;
use rug::ops::Pow;
use rug::Integer;

fn ulp_width(x: &MpfrInterval) -> Float {
    // Width measured in units of 2^(exponent(hi) − prec).
    let e = x.hi().get_exp().unwrap_or(0);
    Float::with_val(64, x.width()) >> (e - x.prec() as i32)
}

#[test]
fn rational_enclosures_are_one_ulp_wide_at_every_precision() {
    let third = Rational::from((1, 3));
    for prec in [53, 128, 256, 512, 1024, 4096] {
        let x = MpfrInterval::from_rational(&third, prec);
        assert_eq!(x.prec(), prec);
        assert!(x.lo().to_rational().unwrap() < third);
        assert!(x.hi().to_rational().unwrap() > third);
        let mut next = x.lo().clone();
        next.next_up();
        assert_eq!(next, *x.hi(), "one ulp at {prec} bits");
    }
    // A double is exact from 53 bits up.
    let x = MpfrInterval::from_rational(&Rational::from_f64(0.1).unwrap(), 53);
    assert_eq!(x.lo(), x.hi());
}

#[test]
fn escalation_shrinks_the_enclosure_of_a_cancelling_formula() {
    // (1 + 2^-200) − 1 − 2^-200 = 0 exactly; 1/3·3 − 1 = 0. At p bits the enclosure
    // width is about 2^-p: each doubling of the precision must shrink it.
    let mut last = Float::with_val(64, f64::INFINITY);
    for prec in [128, 256, 512, 1024, 2048, 4096] {
        let one = MpfrInterval::point(1.0, prec);
        let three = one.lift(3.0);
        let t = &one / &three * &three - &one;
        assert!(t.contains_zero(), "{prec}: {t:?}");
        let w = t.width();
        assert!(
            w < Float::with_val(64, &last >> 100),
            "{prec}: width {w} after {last}"
        );
        assert!(
            w <= Float::with_val(64, 1) >> (prec - 2),
            "{prec}: width {w}"
        );
        last = w;
    }
}

#[test]
fn elementary_functions_enclose_higher_precision_values_within_one_ulp() {
    let mut rng = Rng::new(11);
    for prec in [64, 128, 300, 1000] {
        for _ in 0..200 {
            let x = rng.range(-20.0, 20.0);
            let xi = MpfrInterval::point(x, prec);
            let truth_prec = prec + 200;
            let hp = |f: fn(Float) -> Float| f(Float::with_val(truth_prec, x));
            let cases: [(MpfrInterval, Float); 7] = [
                (xi.sin(), hp(|v| v.sin())),
                (xi.cos(), hp(|v| v.cos())),
                (xi.tan(), hp(|v| v.tan())),
                (xi.exp(), hp(|v| v.exp())),
                (xi.sinh(), hp(|v| v.sinh())),
                (xi.cosh(), hp(|v| v.cosh())),
                (xi.abs().ln(), hp(|v| v.abs().ln())),
            ];
            for (k, (enc, v)) in cases.iter().enumerate() {
                assert_eq!(enc.prec(), prec);
                assert!(
                    enc.contains_float(v),
                    "case {k} at {x} ({prec} bits): {enc:?} ∌ {v}"
                );
                assert!(
                    ulp_width(enc) <= 1,
                    "case {k} at {x} ({prec} bits) not tightest: {enc:?}"
                );
            }
        }
    }
}

#[test]
fn sin_at_4096_bits_of_a_point_near_a_multiple_of_pi() {
    // x = 355/113 is 2.7e-7 away from π: sin x ≈ −2.7e-7, relative accuracy kept.
    let x = MpfrInterval::from_rational(&Rational::from((355, 113)), 4096);
    let s = x.sin();
    let truth = Float::with_val(5000, Rational::from((355, 113))).sin();
    assert!(s.contains_float(&truth));
    assert!(s.hi() < &0, "{s:?}");
    // |sin'| ≤ 1: the width is at most the input's (one ulp of π at 4096 bits, about
    // 2^-4094) plus the two outward roundings (2^-22 relative magnitude, 2^-4118).
    let allowed = Float::with_val(64, x.width()) + (Float::with_val(64, 1) >> 4116);
    assert!(s.width() <= allowed, "{s:?}");
    // An interval [π − 2^-3000, π + 2^-3000] contains the zero of sin and not its extrema.
    let pi = Float::with_val(5000, Constant::Pi);
    let eps = Float::with_val(64, 1) >> 3000;
    let around = MpfrInterval::from_float_bounds(
        &Float::with_val(5000, &pi - &eps),
        &Float::with_val(5000, &pi + &eps),
        4096,
    );
    let s = around.sin();
    assert!(s.contains_zero() && s.mag_float() < (Float::with_val(64, 1) >> 2990));
    let c = around.cos();
    assert_eq!(*c.lo(), -1, "cos reaches −1 at π");
    assert!(*c.hi() < -0.99);
}

#[test]
fn mixed_precision_takes_the_larger() {
    let a = MpfrInterval::point(1.0, 64);
    let b = MpfrInterval::from_rational(&Rational::from((1, 3)), 256);
    assert_eq!((&a + &b).prec(), 256);
    assert_eq!((&b * &a).prec(), 256);
    assert_eq!(a.atan2(&b).prec(), 256);
    assert_eq!(a.hull(&b).prec(), 256);
    // Zero/One (nalgebra) are exact at 53 bits and do not lower a precision.
    use num_traits::{One, Zero};
    assert_eq!((MpfrInterval::zero() + &b).prec(), 256);
    assert_eq!(MpfrInterval::one() * b.clone(), b);
}

#[test]
fn conversion_to_f64_intervals_is_outward_and_tight() {
    // 1/3 at 128 bits → the two doubles around 1/3.
    let x = MpfrInterval::from_rational(&Rational::from((1, 3)), 128).to_interval();
    assert_eq!(
        x,
        crate::num::Interval::from_rational(&Rational::from((1, 3)))
    );
    // Beyond the double range: 10^400 → [MAX, +∞]; 10^-400 → [0, smallest subnormal].
    let big = Rational::from(Integer::from(10).pow(400u32));
    assert_eq!(
        MpfrInterval::from_rational(&big, 128).to_interval(),
        crate::num::Interval::from_bounds(f64::MAX, f64::INFINITY)
    );
    let tiny = Rational::from((1, Integer::from(10).pow(400u32)));
    assert_eq!(
        MpfrInterval::from_rational(&tiny, 128).to_interval(),
        crate::num::Interval::from_bounds(0.0, f64::from_bits(1))
    );
    // exp(1000) does not overflow in MPFR; its f64 image is [MAX, ∞].
    let e = MpfrInterval::point(1000.0, 128).exp();
    assert!(e.is_bounded());
    assert_eq!(
        e.to_interval(),
        crate::num::Interval::from_bounds(f64::MAX, f64::INFINITY)
    );
    // Below 53 bits, f64 bounds are rounded outward.
    let t = MpfrInterval::point(0.1, 10);
    assert!(t.contains(0.1) && t.lo() < &0.1 && t.hi() > &0.1);
}

#[test]
fn set_operations_and_emptiness() {
    let p = 128;
    let a = MpfrInterval::from_bounds(1.0, 3.0, p);
    let b = MpfrInterval::from_bounds(2.0, 5.0, p);
    assert_eq!(a.intersection(&b), MpfrInterval::from_bounds(2.0, 3.0, p));
    assert_eq!(a.hull(&b), MpfrInterval::from_bounds(1.0, 5.0, p));
    assert!(a
        .intersection(&MpfrInterval::from_bounds(4.0, 5.0, p))
        .is_empty());
    assert!(MpfrInterval::from_bounds(-2.0, -1.0, p).sqrt().is_empty());
    assert!(a.div(&MpfrInterval::point(0.0, p)).is_empty());
    assert!(a.div(&MpfrInterval::from_bounds(-1.0, 1.0, p)).is_entire());
    let (l, r) = a.bisect();
    assert_eq!(l, MpfrInterval::from_bounds(1.0, 2.0, p));
    assert_eq!(r, MpfrInterval::from_bounds(2.0, 3.0, p));
    assert!(MpfrInterval::from_bounds(1.5, 2.5, p).is_interior_subset(&a));
    assert!(!a.is_interior_subset(&a));
    assert_eq!(a.mid_interval(), MpfrInterval::point(2.0, p));
    assert_eq!(MpfrInterval::entire(p).midpoint(), 0);
    assert_eq!(
        MpfrInterval::new("x", 3.0, 1.0, p).unwrap_err().kind(),
        "empty_domain"
    );
}

/// The f64 interval's `powi` is within `2|n| + 2` ulps of the tightest result, MPFR's at
/// 53 bits (tightest by design), and contains it.
#[test]
fn f64_interval_powi_is_within_2n_ulps_of_the_tightest() {
    let mut rng = Rng::new(6);
    for _ in 0..2000 {
        let x = random_interval(&mut rng, -30, 30);
        for n in [-5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 7, 12] {
            let y = x.powi(n);
            let t = MpfrInterval::from_interval(&x, 53).powi(n).to_interval();
            assert!(t.is_subset(&y));
            if y.is_bounded() && t.is_bounded() && t.lo() != 0.0 {
                let ulps =
                    |u: f64, v: f64| (u.to_bits() as i64 - v.to_bits() as i64).unsigned_abs();
                let k = 2 * n.unsigned_abs() as u64 + 2;
                assert!(
                    ulps(y.lo().abs(), t.lo().abs()) <= k && ulps(y.hi().abs(), t.hi().abs()) <= k,
                    "{x:?}^{n}: {y:?} vs tightest {t:?}"
                );
            }
        }
    }
}
