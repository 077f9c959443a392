//! Unit tests of the f64 interval: directed rounding checked exactly with rationals,
//! arithmetic checked against exact rational ranges, the Taylor paths against 200-bit
//! MPFR. (The ITF1788 vectors are in tests/itf1788.rs.)

use super::directed::*;
use super::test_support::*;
use super::*;
use rug::ops::Pow;
use rug::{Float, Rational};

const N: usize = 20_000;

#[test]
fn next_up_and_down_step_one_double() {
    assert_eq!(next_up(0.0), f64::from_bits(1));
    assert_eq!(next_up(-0.0), f64::from_bits(1));
    assert_eq!(next_up(-f64::from_bits(1)), 0.0);
    assert_eq!(next_up(1.0), 1.0 + f64::EPSILON);
    assert_eq!(next_up(f64::MAX), f64::INFINITY);
    assert_eq!(next_up(f64::NEG_INFINITY), -f64::MAX);
    assert_eq!(next_down(1.0), 1.0 - f64::EPSILON / 2.0);
    assert_eq!(next_down(f64::from_bits(1)), 0.0);
}

#[test]
fn add_mul_div_round_up_exactly_over_the_whole_range() {
    let mut rng = Rng::new(1);
    for i in 0..N {
        // Alternate full-range operands with operands of similar size (cancellation).
        let a = rng.double(-1074, 1023);
        let b = if i % 3 == 0 {
            a * rng.range(-1.5, 1.5)
        } else {
            rng.double(-1074, 1023)
        };
        let b = if b.is_finite() { b } else { 1.0 };
        let (ea, eb) = (exact(a), exact(b));
        let s = add_up(a, b);
        assert!(
            is_rounded_up(s, &Rational::from(&ea + &eb)),
            "add_up({a:e}, {b:e}) = {s:e}"
        );
        assert!(is_rounded_down(add_down(a, b), &Rational::from(&ea + &eb)));
        let p = mul_up(a, b);
        assert!(
            is_rounded_up(p, &Rational::from(&ea * &eb)),
            "mul_up({a:e}, {b:e}) = {p:e}"
        );
        assert!(is_rounded_down(mul_down(a, b), &Rational::from(&ea * &eb)));
        if b != 0.0 {
            let q = div_up(a, b);
            assert_eq!((div_up_k::<true>(a, b), div_up_k::<false>(a, b)), (q, q));
            assert!(
                is_rounded_up(q, &Rational::from(&ea / &eb)),
                "div_up({a:e}, {b:e}) = {q:e}"
            );
            assert!(is_rounded_down(div_down(a, b), &Rational::from(&ea / &eb)));
        }
    }
}

#[test]
fn products_near_the_fast_path_limits_round_up_exactly() {
    // Products around 2^-969 (two_prod exactness limit), 2^1020 and the split limit.
    let mut rng = Rng::new(2);
    for _ in 0..N {
        let ea = rng.range(-1074.0, 1023.0) as i32;
        let target = if rng.unit() < 0.5 { -969 } else { 1021 };
        let eb = (target - ea).clamp(-1074, 1023);
        let a = rng.double(ea, ea);
        let b = rng.double(eb, eb);
        let exact_p = Rational::from(&exact(a) * &exact(b));
        assert!(
            is_rounded_up(mul_up(a, b), &exact_p),
            "mul_up({a:e}, {b:e})"
        );
        if b != 0.0 {
            let exact_q = Rational::from(&exact(a) / &exact(b));
            assert!(
                is_rounded_up(div_up(a, b), &exact_q),
                "div_up({a:e}, {b:e})"
            );
        }
    }
}

#[test]
fn dekker_error_term_is_exact() {
    // Independent of the target: Dekker's two_prod against the exact product.
    let mut rng = Rng::new(3);
    for _ in 0..N {
        let a = rng.double(-400, 400);
        let b = rng.double(-400, 400);
        let p = a * b;
        if !(1e-288..=1e307).contains(&p.abs()) || a.abs() > 1e299 || b.abs() > 1e299 {
            continue; // outside the documented validity range
        }
        let e = dekker_err(a, b, p);
        assert_eq!(
            Rational::from(&exact(p) + &exact(e)),
            Rational::from(&exact(a) * &exact(b))
        );
    }
}

#[test]
fn sqrt_rounds_both_ways_exactly() {
    let mut rng = Rng::new(4);
    for _ in 0..N {
        let x = rng.double(-1074, 1023).abs();
        let (lo, hi) = (sqrt_down(x), sqrt_up(x));
        assert_eq!((sqrt_down_k::<true>(x), sqrt_up_k::<true>(x)), (lo, hi));
        assert_eq!((sqrt_down_k::<false>(x), sqrt_up_k::<false>(x)), (lo, hi));
        let ex = exact(x);
        // hi ≥ √x ⇔ hi² ≥ x; the double below hi is < √x.
        assert!(
            Rational::from(&exact(hi) * &exact(hi)) >= ex,
            "sqrt_up({x:e})"
        );
        let below = next_down(hi);
        assert!(below < 0.0 || Rational::from(&exact(below) * &exact(below)) < ex);
        assert!(
            Rational::from(&exact(lo) * &exact(lo)) <= ex,
            "sqrt_down({x:e})"
        );
        let above = next_up(lo);
        assert!(Rational::from(&exact(above) * &exact(above)) > ex);
    }
}

/// The tightest interval of the exact range of `op` over the corners (valid for
/// + − × on bounded operands, where the extremes are at corners).
fn exact_corner_range(
    x: &Interval,
    y: &Interval,
    op: fn(&Rational, &Rational) -> Rational,
) -> Interval {
    let mut vals = vec![];
    for a in [x.lo(), x.hi()] {
        for b in [y.lo(), y.hi()] {
            vals.push(op(&exact(a), &exact(b)));
        }
    }
    let min = vals.iter().min().unwrap();
    let max = vals.iter().max().unwrap();
    Interval::from_rational(min).hull(&Interval::from_rational(max))
}

#[test]
fn add_sub_mul_are_tightest_on_random_bounded_intervals() {
    let mut rng = Rng::new(5);
    for _ in 0..N / 4 {
        let x = random_interval(&mut rng, -1074, 1023);
        let y = random_interval(&mut rng, -1074, 1023);
        assert_eq!(
            x.add(&y),
            exact_corner_range(&x, &y, |a, b| Rational::from(a + b)),
            "{x:?}+{y:?}"
        );
        assert_eq!(
            x.sub(&y),
            exact_corner_range(&x, &y, |a, b| Rational::from(a - b)),
            "{x:?}-{y:?}"
        );
        assert_eq!(
            x.mul(&y),
            exact_corner_range(&x, &y, |a, b| Rational::from(a * b)),
            "{x:?}*{y:?}"
        );
        if !y.contains_zero() {
            let q = exact_corner_range(&x, &y, |a, b| Rational::from(a / b));
            assert_eq!(x.div(&y), q, "{x:?}/{y:?}");
        }
    }
}

#[test]
fn division_by_intervals_containing_zero_follows_set_semantics() {
    let x = Interval::from_bounds(1.0, 2.0);
    assert!(x.div(&Interval::ZERO).is_empty());
    assert_eq!(x.div(&Interval::from_bounds(-1.0, 1.0)), Interval::ENTIRE);
    assert_eq!(
        x.div(&Interval::from_bounds(0.0, 4.0)),
        Interval::from_bounds(0.25, f64::INFINITY)
    );
    assert_eq!(
        x.div(&Interval::from_bounds(-4.0, 0.0)),
        Interval::from_bounds(f64::NEG_INFINITY, -0.25)
    );
    assert_eq!(
        Interval::ZERO.div(&Interval::from_bounds(-1.0, 1.0)),
        Interval::ZERO
    );
    assert_eq!(
        Interval::from_bounds(-1.0, 2.0).div(&Interval::from_bounds(0.0, 1.0)),
        Interval::ENTIRE
    );
}

#[test]
fn rational_construction_is_tight_and_exact_for_doubles() {
    let third = Rational::from((1, 3));
    let t = Interval::from_rational(&third);
    assert_eq!(next_up(t.lo()), t.hi());
    assert!(exact(t.lo()) < third && third < exact(t.hi()));
    assert_eq!(Interval::from_rational(&exact(0.1)), Interval::point(0.1));
    let huge = Rational::from(rug::Integer::from(10).pow(400));
    assert_eq!(
        Interval::from_rational(&huge),
        Interval::from_bounds(f64::MAX, f64::INFINITY)
    );
    let tiny = Rational::from((1, rug::Integer::from(10).pow(400)));
    assert_eq!(
        Interval::from_rational(&tiny),
        Interval::from_bounds(0.0, f64::from_bits(1))
    );
}

#[test]
fn constructors_reject_bad_bounds_with_typed_errors() {
    assert_eq!(
        Interval::new("t", 2.0, 1.0).unwrap_err().kind(),
        "empty_domain"
    );
    assert_eq!(
        Interval::new("t", f64::NAN, 1.0).unwrap_err().kind(),
        "non_finite"
    );
    assert_eq!(
        Interval::new("box[0]", f64::INFINITY, f64::INFINITY)
            .unwrap_err()
            .field(),
        "box[0]"
    );
    assert_eq!(
        Interval::new("t", f64::NEG_INFINITY, 1.0).unwrap().lo(),
        f64::NEG_INFINITY
    );
    assert_eq!(Interval::point(f64::NAN), Interval::ENTIRE);
    assert_eq!(
        Interval::point(f64::INFINITY),
        Interval::from_bounds(f64::MAX, f64::INFINITY)
    );
}

#[test]
fn set_operations() {
    let a = Interval::from_bounds(1.0, 3.0);
    let b = Interval::from_bounds(2.0, 5.0);
    assert_eq!(a.hull(&b), Interval::from_bounds(1.0, 5.0));
    assert_eq!(a.intersection(&b), Interval::from_bounds(2.0, 3.0));
    assert!(a.intersection(&Interval::from_bounds(4.0, 5.0)).is_empty());
    assert_eq!(a.hull(&Interval::EMPTY), a);
    assert!(Interval::from_bounds(1.5, 2.5).is_interior_subset(&a));
    assert!(!Interval::from_bounds(1.0, 2.5).is_interior_subset(&a));
    assert!(Interval::from_bounds(1.0, 2.5).is_subset(&a));
    assert_eq!(
        a.bisect(),
        (
            Interval::from_bounds(1.0, 2.0),
            Interval::from_bounds(2.0, 3.0)
        )
    );
    assert_eq!(Interval::from_bounds(-4.0, 2.0).mag(), 4.0);
    assert_eq!(Interval::from_bounds(-4.0, 2.0).mig(), 0.0);
    assert_eq!(Interval::from_bounds(-4.0, -2.0).mig(), 2.0);
    // Width rounds up: [0, 1] + tiny.
    let w = Interval::from_bounds(-f64::from_bits(1), 1.0).width();
    assert!(is_rounded_up(
        w,
        &Rational::from(&exact(1.0) + &exact(f64::from_bits(1)))
    ));
    let r = Interval::from_bounds(0.0, 0.1).radius();
    let m = Interval::from_bounds(0.0, 0.1).midpoint();
    assert!(exact(m) + exact(r) >= exact(0.1) && exact(m) - exact(r) <= 0);
}

#[test]
fn powi_encloses_exact_powers_and_is_tight_for_small_exponents() {
    // (Within 2|n| + 2 ulps of the tightest: mpfr_interval's tests, against MPFR.)
    let mut rng = Rng::new(6);
    for _ in 0..2000 {
        let x = random_interval(&mut rng, -30, 30);
        for n in [-5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 7, 12] {
            let y = x.powi(n);
            // Exact powers at the endpoints and at 0 (when inside) lie in the result.
            for v in [x.lo(), x.hi()] {
                if v != 0.0 || n >= 0 {
                    let p = Float::with_val(4000, v).pow(n);
                    assert!(encloses(y.lo(), y.hi(), &p), "{x:?}^{n} = {y:?} misses {p}");
                }
            }
        }
    }
    // Small exponents are tightest.
    let x = Interval::from_bounds(-3.0, 0.1);
    assert_eq!(x.powi(2), Interval::from_bounds(0.0, 9.0));
    assert_eq!(Interval::from_bounds(0.0, 0.0).powi(-2), Interval::EMPTY);
    assert_eq!(Interval::from_bounds(-1.0, 1.0).powi(-1), Interval::ENTIRE);
}

/// Taylor paths: enclosure of the 200-bit MPFR value, at most `max_ulps` wide.
fn check_taylor(
    name: &str,
    xs: impl Iterator<Item = f64>,
    f: fn(f64) -> Interval,
    exact_f: fn(&mut Float),
    max_ulps: u64,
) -> u64 {
    let mut widest = 0;
    for x in xs {
        let y = f(x);
        let mut v = Float::with_val(200, x);
        exact_f(&mut v);
        assert!(
            encloses(y.lo(), y.hi(), &v),
            "{name}({x:e}) = {y:?} misses {v}"
        );
        let ulps = if y.lo().signum() == y.hi().signum() || y.lo() == 0.0 {
            (y.hi().to_bits() as i64 - y.lo().to_bits() as i64).unsigned_abs()
        } else {
            2 * y.hi().to_bits().min((-y.lo()).to_bits())
        };
        assert!(
            ulps <= max_ulps || y.width() < 1e-300,
            "{name}({x:e}) = {y:?}: {ulps} ulps wide"
        );
        if y.width() >= 1e-300 {
            widest = widest.max(ulps);
        }
    }
    println!("{name}: widest enclosure {widest} ulps");
    widest
}

fn sin_at(x: f64) -> Interval {
    let (k, r, er) = taylor::reduce_half_pi(x);
    taylor::sin_cos_reduced(k, r, er, false)
}
fn cos_at(x: f64) -> Interval {
    let (k, r, er) = taylor::reduce_half_pi(x);
    taylor::sin_cos_reduced(k, r, er, true)
}

#[test]
fn taylor_sin_cos_exp_enclose_200_bit_values_within_a_few_ulps() {
    let mut rng = Rng::new(7);
    let trig_args: Vec<f64> = (0..N)
        .map(|i| match i % 4 {
            0 => rng.range(-7.0, 7.0),
            1 => rng.range(-taylor::TRIG_FAST_MAX, taylor::TRIG_FAST_MAX),
            2 => rng
                .double(-1074, 18)
                .clamp(-taylor::TRIG_FAST_MAX, taylor::TRIG_FAST_MAX),
            // Near multiples of π/2, where the reduced argument is tiny.
            _ => rng.range(-1000.0, 1000.0).round() * std::f64::consts::FRAC_PI_2,
        })
        .collect();
    check_taylor(
        "sin",
        trig_args.iter().copied(),
        sin_at,
        |v| {
            v.sin_mut();
        },
        8,
    );
    check_taylor(
        "cos",
        trig_args.iter().copied(),
        cos_at,
        |v| {
            v.cos_mut();
        },
        8,
    );
    let exp_args = (0..N).map(|i| {
        if i % 2 == 0 {
            rng.range(-700.0, 700.0)
        } else {
            rng.double(-1074, 0).clamp(-1.0, 1.0)
        }
    });
    check_taylor(
        "exp",
        exp_args,
        taylor::exp_point,
        |v| {
            v.exp_mut();
        },
        8,
    );
}

#[test]
fn taylor_constants_are_what_they_claim() {
    use rug::float::Constant;
    use taylor::*;
    let half_pi = Float::with_val(400, Constant::Pi) / 2u32;
    // P1, P2: the first two 33-bit pieces of π/2 (truncated), with at most 32 significant
    // bits, so that k·P1 and k·P2 are exact for |k| < 2^19.
    let p1 = Float::with_val(400, &half_pi * (1u64 << 32)).floor() / (1u64 << 32);
    assert_eq!(p1, P1);
    assert_eq!(P1.to_bits(), 0x3ff921fb54400000);
    let rest = Float::with_val(400, &half_pi - &p1);
    let p2 = Float::with_val(400, &rest * (1u128 << 66)).floor() / (1u128 << 66);
    assert_eq!(p2, P2);
    for c in [P1, P2, L1] {
        assert!(
            c.to_bits().trailing_zeros() >= 21,
            "at most 32 significant bits"
        );
    }
    let p3 = Float::with_val(400, &rest - &p2);
    assert_eq!(p3.to_f64(), P3, "P3 is the nearest double");
    assert_eq!(D3, 2f64.powi(-121));
    assert!(Float::with_val(400, &p3 - P3).abs() <= D3);
    let ln2 = Float::with_val(400, Constant::Log2);
    let l1 = Float::with_val(400, &ln2 * (1u64 << 32)).floor() / (1u64 << 32);
    assert_eq!(l1, L1);
    let l2 = Float::with_val(400, &ln2 - &l1);
    assert_eq!(l2.to_f64(), L2);
    assert_eq!(D2, 2f64.powi(-85));
    assert!(Float::with_val(400, &l2 - L2).abs() <= D2);
    // Coefficients: nearest doubles to ±1/n!, so within u relative.
    let u = Rational::from((1, rug::Integer::from(1) << 53));
    let check = |c: f64, n: u32, negative: bool| {
        let fact = rug::Integer::from(rug::Integer::factorial(n));
        let a = Rational::from((if negative { -1 } else { 1 }, fact));
        assert_eq!(
            Float::with_val(53, &a).to_f64(),
            c,
            "nearest double to ±1/{n}!"
        );
        let err = Rational::from(&exact(c) - &a).abs();
        assert!(err <= Rational::from(&u * &a).abs(), "1/{n}!");
    };
    for (i, &c) in SIN_C.iter().enumerate() {
        check(c, 2 * i as u32 + 3, i % 2 == 0);
    }
    for (i, &c) in COS_C.iter().enumerate() {
        check(c, 2 * i as u32 + 2, i % 2 == 0);
    }
    for (i, &c) in EXP_C.iter().enumerate() {
        check(c, i as u32 + 1, false);
    }
}

#[test]
fn trig_reduction_error_bound_holds() {
    // |r − (x − kπ/2)| ≤ ε_r, checked at 400 bits, including the hardest doubles near
    // multiples of π/2.
    use rug::float::Constant;
    let half_pi = Float::with_val(400, Constant::Pi) / 2u32;
    let mut rng = Rng::new(8);
    for i in 0..N {
        let x = if i % 2 == 0 {
            rng.range(-taylor::TRIG_FAST_MAX, taylor::TRIG_FAST_MAX)
        } else {
            (rng.range(-330_000.0, 330_000.0).round() * std::f64::consts::FRAC_PI_2)
                .clamp(-taylor::TRIG_FAST_MAX, taylor::TRIG_FAST_MAX)
        };
        let (k, r, er) = taylor::reduce_half_pi(x);
        let truth = Float::with_val(400, x) - Float::with_val(400, &half_pi * k);
        let err = Float::with_val(400, &truth - r).abs();
        assert!(err <= er, "x = {x:e}: error {err} > bound {er:e}");
        assert!(r.abs() <= 0.8);
    }
}

#[test]
fn fma_and_dekker_copies_of_the_operations_agree() {
    // The public operations pick one copy at run time; both must give the same (tightest)
    // result, so the copy not chosen on this machine is tested too.
    let mut rng = Rng::new(9);
    for _ in 0..N / 4 {
        let x = random_interval(&mut rng, -1074, 1023);
        let y = random_interval(&mut rng, -1074, 1023);
        let m = x.mul(&y);
        assert_eq!((x.mul_impl::<true>(&y), x.mul_impl::<false>(&y)), (m, m));
        let d = x.div(&y);
        assert_eq!((x.div_impl::<true>(&y), x.div_impl::<false>(&y)), (d, d));
        let s = x.sqr();
        assert_eq!((x.sqr_impl::<true>(), x.sqr_impl::<false>()), (s, s));
        let r = x.sqrt();
        assert_eq!((x.sqrt_impl::<true>(), x.sqrt_impl::<false>()), (r, r));
    }
}

// Re-derive, at 300 bits, the constants of the a-priori bounds in taylor.rs from their
// definitions (Higham's γ_k = ku/(1−ku) per term, coefficient errors ≤ u|a_i|, the
// z̃ = z(1+δ) perturbation, the Lagrange remainders) and check the code's constants are
// at least as large. Each bound B(t) is a polynomial in t = z̃ or |r| with non-negative
// coefficients (convex), and the code uses a linear bound c0 + c1·t, so checking both
// ends of the range proves it on the whole range.

/// The working precision of the re-derivations.
const P: u32 = 300;

/// `x` at the working precision.
fn f(x: f64) -> Float {
    Float::with_val(P, x)
}

/// The unit roundoff `u = 2⁻⁵³`.
fn unit() -> Float {
    f(1.0) >> 53
}

/// Higham's `γ_k = ku/(1 − ku)`.
fn gamma(k: u32) -> Float {
    let ku = Float::with_val(P, unit() * k);
    Float::with_val(P, &ku / (f(1.0) - &ku))
}

/// `1/n!`.
fn inv_fact(n: u32) -> Float {
    f(1.0) / Float::with_val(P, rug::Integer::from(rug::Integer::factorial(n)))
}

/// The propagated error `u(1+2u) (i+1)|a_i| (z(1+u))^i` of term `i` (sin, cos).
fn perturbation_term(i: usize, a: Float, z: f64) -> Float {
    let u = unit();
    let zp = Float::with_val(P, f(z) * (f(1.0) + &u)).pow(i as u32);
    Float::with_val(P, &u * (f(1.0) + Float::with_val(P, &u * 2u32))) * (i as u32 + 1) * a * zp
}

#[test]
fn sin_error_bound_constants_rederived() {
    // B(z) = Σ γ_{2i+3}|c_i|z^i + u Σ|a_i| z^i + u(1+2u) Σ (i+1)|a_i| (z(1+u))^i.
    let u = unit();
    let sin_b = |z: f64| {
        let mut b = f(0.0);
        for (i, &c) in SIN_C_REF.iter().enumerate() {
            let zi = f(z).pow(i as u32);
            let a = inv_fact(2 * i as u32 + 3);
            b += gamma(2 * i as u32 + 3) * f(c.abs()) * &zi;
            b += Float::with_val(P, &u * &a) * &zi;
            b += perturbation_term(i, a, z);
        }
        Float::with_val(P, b / &u)
    };
    for z in [0.0, 0.7] {
        assert!(
            sin_b(z) <= f(0.84 + 0.18 * z),
            "sin constant at z = {z}: {}",
            sin_b(z)
        );
    }
}

#[test]
fn cos_error_bound_constants_rederived() {
    // B(z) = Σ γ_{2i+2}|c_i|z^i + u Σ_{i≥1}|a_i|z^i + u(1+2u) Σ (i+1)|a_i|(z(1+u))^i.
    let u = unit();
    let cos_b = |z: f64| {
        let mut b = f(0.0);
        for (i, &c) in COS_C_REF.iter().enumerate() {
            let zi = f(z).pow(i as u32);
            let a = inv_fact(2 * i as u32 + 2);
            b += gamma(2 * i as u32 + 2) * f(c.abs()) * &zi;
            if i >= 1 {
                b += Float::with_val(P, &u * &a) * &zi;
            }
            b += perturbation_term(i, a, z);
        }
        Float::with_val(P, b / &u)
    };
    for z in [0.0, 0.7] {
        assert!(
            cos_b(z) <= f(1.51 + 0.91 * z),
            "cos constant at z = {z}: {}",
            cos_b(z)
        );
    }
}

#[test]
fn exp_error_bound_constants_rederived() {
    // B(r) = Σ γ_{2i+2}|c_i|r^i + u Σ_{i≥2}|a_i| r^i.
    let u = unit();
    let exp_b = |r: f64| {
        let mut b = f(0.0);
        for (i, &c) in EXP_C_REF.iter().enumerate() {
            let ri = f(r).pow(i as u32);
            b += gamma(2 * i as u32 + 2) * f(c.abs()) * &ri;
            if i >= 2 {
                b += Float::with_val(P, &u * inv_fact(i as u32 + 1)) * &ri;
            }
        }
        Float::with_val(P, b / &u)
    };
    for r in [0.0, 0.35] {
        assert!(
            exp_b(r) <= f(2.001 + 2.97 * r),
            "exp constant at r = {r}: {}",
            exp_b(r)
        );
    }
}

#[test]
fn taylor_remainder_and_range_constants_rederived() {
    use rug::float::Constant;
    let u = unit();
    // The last addition: u/(1 − u) ≤ 1.0001u.
    assert!(Float::with_val(P, &u / (f(1.0) - &u)) <= Float::with_val(P, &u * f(1.0001)));
    // Remainders: |r|^19/19! with |r|^18 = z^9 ≤ z̃^9(1−u)^-9; z^10/20!; e^{0.3466}/16!.
    let corr = |k: i32| f(1.0) / Float::with_val(P, f(1.0) - &u).pow(k);
    assert!(Float::with_val(P, inv_fact(19) * corr(9)) <= f(8.23e-18));
    assert!(Float::with_val(P, inv_fact(20) * corr(10)) <= f(4.12e-19));
    let ln2_half = Float::with_val(P, Constant::Log2) / 2u32 + f(1e-9);
    assert!(Float::with_val(P, ln2_half.clone().exp() * inv_fact(16)) <= f(6.8e-14));
    // Reduced ranges: |r| ≤ π/4 + 2^-30 ≤ 0.8 gives z̃ ≤ 0.7; |r| ≤ ln2/2 + ε ≤ 0.35;
    // exp is 1.44-Lipschitz on |r| ≤ 0.36.
    assert!(Float::with_val(P, Constant::Pi) / 4u32 + f(1e-9) <= f(0.8));
    assert!(f(0.8) * f(0.8) * (f(1.0) + &u) <= f(0.7));
    assert!(ln2_half <= f(0.35));
    assert!(f(0.36).exp() <= f(1.44));
}

use taylor::{COS_C as COS_C_REF, EXP_C as EXP_C_REF, SIN_C as SIN_C_REF};
