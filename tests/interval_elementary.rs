//! Elementary functions of `Interval` and `MpfrInterval` on random intervals against an
//! independent truth: the exact range computed with 2000-bit MPFR from the endpoints and
//! every critical point (multiples of π/2 found by high-precision division, not by the
//! library's analysis), rounded outward to the tightest f64 interval.
//! `MpfrInterval` at 53 bits must equal the truth (it is tightest); `Interval` must
//! contain it and be at most a few ulps wider (Taylor path) or equal (MPFR path).

use geocert::num::{Interval, MpfrInterval};
use rug::float::{Constant, Round};
use rug::{Float, Integer};

const PREC: u32 = 2000;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

#[derive(Clone, Copy, Debug)]
enum Fun {
    Sin,
    Cos,
    Tan,
}

fn eval(f: Fun, x: f64) -> Float {
    let v = Float::with_val(PREC, x);
    match f {
        Fun::Sin => v.sin(),
        Fun::Cos => v.cos(),
        Fun::Tan => v.tan(),
    }
}

/// The tightest f64 interval of `f([a, b])`, by brute force: endpoint values and the
/// values at every `m·π/2 ∈ [a, b]` (extrema ±1, or a pole of tan).
fn truth(f: Fun, a: f64, b: f64) -> Interval {
    let half_pi = Float::with_val(PREC, Constant::Pi) / 2u32;
    let m_lo = Float::with_val(PREC, a / &half_pi)
        .ceil()
        .to_integer()
        .unwrap();
    let m_hi = Float::with_val(PREC, b / &half_pi)
        .floor()
        .to_integer()
        .unwrap();
    let mut vals = vec![eval(f, a), eval(f, b)];
    let mut m = m_lo.clone();
    let mut count = 0;
    while m <= m_hi && count < 8 {
        let r = m.mod_u(4);
        match f {
            Fun::Sin if r % 2 == 1 => vals.push(Float::with_val(PREC, if r == 1 { 1 } else { -1 })),
            Fun::Cos if r.is_multiple_of(2) => {
                vals.push(Float::with_val(PREC, if r == 0 { 1 } else { -1 }))
            }
            Fun::Tan if r % 2 == 1 => return Interval::ENTIRE,
            _ => {}
        }
        m += 1;
        count += 1;
    }
    let min = vals
        .iter()
        .min_by(|x, y| x.partial_cmp(y).unwrap())
        .unwrap();
    let max = vals
        .iter()
        .max_by(|x, y| x.partial_cmp(y).unwrap())
        .unwrap();
    Interval::from_bounds(min.to_f64_round(Round::Down), max.to_f64_round(Round::Up))
}

fn ulps_apart(x: f64, y: f64) -> u64 {
    let key = |v: f64| {
        let b = v.to_bits() as i64;
        if b < 0 {
            i64::MIN - b
        } else {
            b
        }
    };
    (key(x) - key(y)).unsigned_abs()
}

fn random_trig_interval(rng: &mut Rng, i: usize) -> (f64, f64) {
    let center = match i % 5 {
        0 => rng.range(-8.0, 8.0),
        1 => rng.range(-1000.0, 1000.0),
        2 => rng.range(-524_288.0, 524_288.0),
        3 => rng.range(-1e6, 1e6) * 10f64.powi((rng.next() % 290) as i32),
        // Right next to a multiple of π/2.
        _ => (rng.range(-50.0, 50.0).round()) * std::f64::consts::FRAC_PI_2,
    };
    let width = match rng.next() % 4 {
        0 => 0.0,
        1 => center.abs() * 1e-15 * rng.unit(),
        2 => rng.range(0.0, 0.1),
        _ => rng.range(0.0, 8.0),
    };
    (center, center + width)
}

fn check_trig(f: Fun) {
    let mut rng = Rng(0x1234_5678_9abc_def1 + f as u64);
    for i in 0..3000 {
        let (a, b) = random_trig_interval(&mut rng, i);
        let x = Interval::from_bounds(a, b);
        let want = truth(f, a, b);
        let m = MpfrInterval::from_interval(&x, 53);
        let got_mpfr = match f {
            Fun::Sin => m.sin(),
            Fun::Cos => m.cos(),
            Fun::Tan => m.tan(),
        }
        .to_interval();
        assert_eq!(got_mpfr, want, "{f:?}([{a:e}, {b:e}]) in MPFR(53)");
        let got = match f {
            Fun::Sin => x.sin(),
            Fun::Cos => x.cos(),
            Fun::Tan => x.tan(),
        };
        assert!(
            want.is_subset(&got),
            "{f:?}([{a:e}, {b:e}]) = {got:?} misses {want:?}"
        );
        if want.is_bounded() {
            let (dl, dh) = (
                ulps_apart(got.lo(), want.lo()),
                ulps_apart(got.hi(), want.hi()),
            );
            assert!(
                dl <= 16 && dh <= 16,
                "{f:?}([{a:e}, {b:e}]) = {got:?}, tightest {want:?}"
            );
        } else {
            assert_eq!(got, want, "{f:?}([{a:e}, {b:e}])");
        }
    }
}

#[test]
fn sin_matches_brute_force_range() {
    check_trig(Fun::Sin);
}

#[test]
fn cos_matches_brute_force_range() {
    check_trig(Fun::Cos);
}

#[test]
fn tan_matches_brute_force_range() {
    check_trig(Fun::Tan);
}

#[test]
fn exp_ln_sinh_cosh_are_tight_enclosures_of_the_monotone_range() {
    let mut rng = Rng(99);
    for i in 0..3000 {
        let scale = [1.0, 10.0, 700.0, 750.0][i % 4];
        let a = rng.range(-scale, scale);
        let b = if i % 3 == 0 {
            a
        } else {
            a + rng.range(0.0, scale)
        };
        let x = Interval::from_bounds(a, b);
        let m = MpfrInterval::from_interval(&x, 53);
        let fa = Float::with_val(PREC, a);
        let fb = Float::with_val(PREC, b);
        let tight = |lo: &Float, hi: &Float| {
            Interval::from_bounds(lo.to_f64_round(Round::Down), hi.to_f64_round(Round::Up))
        };
        // exp: increasing.
        let want = tight(&fa.clone().exp(), &fb.clone().exp());
        assert_eq!(m.exp().to_interval(), want);
        let got = x.exp();
        assert!(
            want.is_subset(&got)
                && ulps_apart(got.lo(), want.lo()) <= 16
                && ulps_apart(got.hi(), want.hi()) <= 16,
            "exp {x:?}: {got:?} vs {want:?}"
        );
        // sinh: increasing; cosh: minimum 1 at 0 (tightest in both types).
        let want = tight(&fa.clone().sinh(), &fb.clone().sinh());
        assert_eq!(x.sinh(), want);
        assert_eq!(m.sinh().to_interval(), want);
        let (lo, hi) = if a <= 0.0 && b >= 0.0 {
            (
                Float::with_val(PREC, 1),
                fa.clone().cosh().max(&fb.clone().cosh()),
            )
        } else {
            let (c1, c2) = (fa.clone().cosh(), fb.clone().cosh());
            (c1.clone().min(&c2), c1.max(&c2))
        };
        assert_eq!(x.cosh(), tight(&lo, &hi), "cosh {x:?}");
        assert_eq!(m.cosh().to_interval(), tight(&lo, &hi));
        // ln on the positive part.
        if b > 0.0 {
            let lo = if a <= 0.0 {
                Float::with_val(PREC, f64::NEG_INFINITY)
            } else {
                fa.clone().ln()
            };
            let want = tight(&lo, &fb.clone().ln());
            assert_eq!(x.ln(), want, "ln {x:?}");
            assert_eq!(m.ln().to_interval(), want);
        } else {
            assert!(x.ln().is_empty() && m.ln().is_empty());
        }
    }
}

#[test]
fn atan2_contains_sampled_angles_and_reaches_the_corner_values() {
    let mut rng = Rng(7);
    for i in 0..2000 {
        let s = [1.0, 1e-3, 1e10][i % 3];
        let (c, d) = {
            let u = rng.range(-s, s);
            (u, u + rng.range(0.0, s))
        };
        let (a, b) = {
            let u = rng.range(-s, s);
            (u, u + rng.range(0.0, s))
        };
        let y = Interval::from_bounds(c, d);
        let x = Interval::from_bounds(a, b);
        let got = y.atan2(&x);
        let got_mpfr =
            MpfrInterval::from_interval(&y, 53).atan2(&MpfrInterval::from_interval(&x, 53));
        assert_eq!(got_mpfr.to_interval(), got, "atan2 tightest in both types");
        let mut seen_min = Float::with_val(PREC, 10);
        let mut seen_max = Float::with_val(PREC, -10);
        for k in 0..64 {
            // Corners, edges and interior points.
            let (ty, tx) = if k < 4 {
                ((k & 1) as f64, (k >> 1) as f64)
            } else {
                (rng.unit(), rng.unit())
            };
            let py = c + (d - c) * ty;
            let px = a + (b - a) * tx;
            if !(c..=d).contains(&py) || !(a..=b).contains(&px) || (px == 0.0 && py == 0.0) {
                continue;
            }
            let v = Float::with_val(PREC, if py == 0.0 { 0.0 } else { py })
                .atan2(&Float::with_val(PREC, px));
            assert!(
                got.lo() <= v && v <= got.hi(),
                "atan2({y:?}, {x:?}) = {got:?} misses the angle of ({px}, {py})"
            );
            if v < seen_min {
                seen_min = v.clone();
            }
            if v > seen_max {
                seen_max = v;
            }
        }
        // The box does not meet the negative x-axis: the extremes are at corners, so the
        // sampled corners reach the bounds (tightness of the case analysis).
        if !(c <= 0.0 && d >= 0.0 && a < 0.0) && !(a <= 0.0 && b >= 0.0 && c <= 0.0 && d >= 0.0) {
            assert_eq!(
                got.lo(),
                seen_min.to_f64_round(Round::Down),
                "atan2({y:?}, {x:?}) lower bound"
            );
            assert_eq!(
                got.hi(),
                seen_max.to_f64_round(Round::Up),
                "atan2({y:?}, {x:?}) upper bound"
            );
        }
    }
}

#[test]
fn huge_arguments_use_a_correct_reduction() {
    // 2^1000 ≈ 1.07e301: the reduction needs ~1100 bits of π (Payne–Hanek territory).
    let x = 2f64.powi(1000);
    let got = Interval::point(x).sin();
    let v = Float::with_val(PREC, x).sin();
    assert!(got.lo() <= v && v <= got.hi());
    assert_eq!(
        geocert::num::interval::directed::next_up(got.lo()),
        got.hi()
    );
    // An interval of two consecutive doubles around a huge multiple of π/2 still gets the
    // extremum right (checked against the brute-force truth).
    let k = Integer::from(Integer::u_pow_u(10, 40));
    let m = Float::with_val(PREC, Constant::Pi) * Float::with_val(PREC, &k);
    let c = m.to_f64();
    let (a, b) = (
        geocert::num::interval::directed::next_down(c),
        geocert::num::interval::directed::next_up(c),
    );
    for f in [Fun::Sin, Fun::Cos] {
        let want = truth(f, a, b);
        let x = Interval::from_bounds(a, b);
        let got = match f {
            Fun::Sin => x.sin(),
            _ => x.cos(),
        };
        assert_eq!(got, want, "{f:?} near 10^40·π");
    }
}
