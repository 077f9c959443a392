//! Every curve primitive's analytic derivatives (OPERATIONS.md §1.5, (1.12), the
//! quotient rule) against central finite differences computed in 200-bit MPFR
//! intervals, at many random parameters: `(c⁽ᵏ⁾(t+h) − c⁽ᵏ⁾(t−h))/2h = c⁽ᵏ⁺¹⁾(t) + O(h²)`
//! with `h = 2⁻⁶⁴`, so a wrong derivative formula shows as an error of order 1 while
//! the truncation and rounding errors stay below 1e-30.

mod curve_support;

use curve_support::*;
use geocert::curve::Curve;
use geocert::num::{Arith, IntervalLike, MpfrInterval};
use rug::Float;

const SAMPLES: usize = 40;

fn check<const D: usize>(name: &str, curve: &impl Curve<D>, breaks: &[f64], seed: u64) {
    let mut rng = Rng::new(seed);
    let (lo, hi) = curve.domain();
    let h = Float::with_val(200, Float::i_exp(1, -64));
    let two_h = mp(&Float::with_val(200, &h * 2u32));
    for _ in 0..SAMPLES {
        let t = sample_away(&mut rng, (lo, hi), breaks, 1e-6);
        let tf = Float::with_val(200, t);
        let at = curve.jet(&mp(&tf), 3);
        let plus = curve.jet(&mp(&Float::with_val(200, &tf + &h)), 3);
        let minus = curve.jet(&mp(&Float::with_val(200, &tf - &h)), 3);
        for k in 0..3 {
            for i in 0..D {
                let fd = (plus[k][i].clone() - &minus[k][i]) / &two_h;
                let err = fd - &at[k + 1][i];
                let scale = 1.0 + at[k + 1][i].mag();
                assert!(
                    err.mag() <= 1e-28 * scale,
                    "{name}: derivative {} component {i} at t = {t}: finite difference differs by {}",
                    k + 1,
                    err.mag()
                );
            }
        }
        // The f64 evaluation is the same formula: it agrees to rounding.
        let f = curve.jet(&t, 3);
        for k in 0..=3 {
            for i in 0..D {
                let scale = 1.0 + at[k][i].mag();
                let e = (at[k][i].clone() - at[k][i].lift(f[k][i])).mag();
                assert!(
                    e <= 1e-12 * scale,
                    "{name}: f64 jet[{k}][{i}] at {t} off by {e}"
                );
            }
        }
        assert_eq!(MpfrInterval::precision_bits(&at[0][0]), 200);
    }
}

#[test]
fn space_curve_derivatives_match_finite_differences() {
    for (seed, (name, c)) in space_curves().into_iter().enumerate() {
        check(name, &c, &breaks3(&c), seed as u64 + 1);
    }
    for (seed, (name, c)) in arcs().into_iter().enumerate() {
        check(name, &c, &[], seed as u64 + 100);
    }
}

#[test]
fn plane_curve_derivatives_match_finite_differences() {
    for (seed, (name, c)) in plane_curves().into_iter().enumerate() {
        check(name, &c, &breaks2(&c), seed as u64 + 200);
    }
}
