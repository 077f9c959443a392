//! Exact univariate roots (issue 4, singular roots (a)): multiplicities from the
//! square-free decomposition, Sturm isolation, end points, and correct rounding,
//! checked against independent truths — closed forms, IEEE-754 correctly rounded
//! operations (`/`, `sqrt`, decimal parsing) and MPFR interval evaluation at 300 bits.

use std::cmp::Ordering;

use geocert::certify::univariate::{
    count_real_roots, count_real_roots_in, real_roots, real_roots_in, Polynomial, RealRoot,
    RootCount,
};
use geocert::num::round::{next_down, next_up};
use geocert::num::MpfrInterval;
use proptest::prelude::*;
use rug::{Integer, Rational};

const PREC: u32 = 300;

fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

fn exact(x: f64) -> Rational {
    Rational::from_f64(x).unwrap()
}

/// `p(x)` in MPFR interval arithmetic at 300 bits; `x` and the coefficients enter as
/// enclosures of the exact rationals.
fn mpfr_eval(p: &Polynomial, x: &Rational) -> MpfrInterval {
    let xi = MpfrInterval::from_rational(x, PREC);
    let mut acc = MpfrInterval::point(0.0, PREC);
    for c in p.coeffs().iter().rev() {
        acc = acc.mul(&xi).add(&MpfrInterval::from_rational(c, PREC));
    }
    acc
}

/// The sign of `p(x)` proven by the MPFR enclosure (panics if 300 bits cannot decide).
fn mpfr_sign(p: &Polynomial, x: &Rational) -> Ordering {
    let v = mpfr_eval(p, x);
    if *v.lo() > 0 {
        Ordering::Greater
    } else if *v.hi() < 0 {
        Ordering::Less
    } else {
        panic!("300-bit MPFR cannot decide the sign of p at {x}: {v:?}")
    }
}

/// The midpoints between `d` and its two neighbouring doubles: the rounding
/// boundaries of `d`.
fn rounding_boundaries(d: f64) -> (Rational, Rational) {
    let lo = (exact(next_down(d)) + exact(d)) / 2u32;
    let hi = (exact(d) + exact(next_up(d))) / 2u32;
    (lo, hi)
}

/// A simple root rounds to `d` iff `p` changes sign between `d`'s rounding boundaries
/// (given that no other root lies there): checked with MPFR, independently of the code.
fn assert_rounds_correctly(p: &Polynomial, root: &RealRoot) {
    assert_eq!(
        root.multiplicity() % 2,
        1,
        "sign test needs an odd multiplicity"
    );
    let d = root.nearest();
    let (lo, hi) = rounding_boundaries(d);
    assert_ne!(
        mpfr_sign(p, &lo),
        mpfr_sign(p, &hi),
        "no sign change around the rounded value {d:e}"
    );
}

fn ten_pow(k: u32) -> Rational {
    Rational::from(Integer::from(Integer::u_pow_u(10, k)))
}

#[test]
fn double_root_against_two_roots_1e_minus_10_apart() {
    let eps = Rational::from(1) / ten_pow(10); // exactly 1e-10
    let one = q(1, 1);
    let three = q(3, 1);
    let double = Polynomial::from_roots(&[(one.clone(), 2), (three.clone(), 1)]);
    let near = Polynomial::from_roots(&[
        (one.clone(), 1),
        (Rational::from(&one + &eps), 1),
        (three.clone(), 1),
    ]);
    let r = real_roots(&double).unwrap();
    assert_eq!(r.len(), 2);
    assert_eq!((r[0].exact(), r[0].multiplicity()), (Some(&one), 2));
    assert_eq!((r[1].exact(), r[1].multiplicity()), (Some(&three), 1));
    assert_eq!((r[0].nearest(), r[1].nearest()), (1.0, 3.0));

    let r = real_roots(&near).unwrap();
    assert_eq!(r.len(), 3);
    assert!(r.iter().all(|x| x.multiplicity() == 1 && x.is_rational()));
    assert_eq!(r[1].exact(), Some(&Rational::from(&one + &eps)));
    // Rust's decimal parser rounds correctly: an independent nearest double.
    assert_eq!(r[1].nearest(), "1.0000000001".parse::<f64>().unwrap());

    // The same with irrational roots 1 ± √2·1e-10: x² − 2x + 1 − 2e-20.
    let delta2 = Rational::from(2) / ten_pow(20);
    let irr = Polynomial::from_coeffs(vec![Rational::from(1) - delta2, q(-2, 1), q(1, 1)]);
    let r = real_roots(&irr).unwrap();
    assert_eq!(r.len(), 2);
    assert!(r.iter().all(|x| x.multiplicity() == 1 && !x.is_rational()));
    let (_, hi0) = r[0].interval();
    let (lo1, _) = r[1].interval();
    assert!(hi0 <= lo1, "the two intervals are disjoint");
    for x in &r {
        assert_rounds_correctly(&irr, x);
    }
    // 1 ± √2·1e-10 (f64 arithmetic is accurate enough at this size).
    let d = 2f64.sqrt() * 1e-10;
    assert!((r[0].nearest() - (1.0 - d)).abs() < 1e-15);
    assert!((r[1].nearest() - (1.0 + d)).abs() < 1e-15);
    assert_eq!(
        count_real_roots(&double).unwrap(),
        RootCount {
            distinct: 2,
            with_multiplicity: 3
        }
    );
    assert_eq!(count_real_roots(&near).unwrap().with_multiplicity, 3);
    assert_eq!(count_real_roots(&near).unwrap().distinct, 3);
}

fn wilkinson(n: i64) -> Polynomial {
    Polynomial::from_roots(&(1..=n).map(|k| (q(k, 1), 1)).collect::<Vec<_>>())
}

#[test]
fn wilkinson_polynomials() {
    let w = wilkinson(20);
    let r = real_roots(&w).unwrap();
    assert_eq!(r.len(), 20);
    for (k, root) in r.iter().enumerate() {
        assert_eq!(root.exact(), Some(&q(k as i64 + 1, 1)));
        assert_eq!(root.multiplicity(), 1);
    }
    // Wilkinson's perturbation: W(x) − 2⁻²³x¹⁹ has ten real roots (Wilkinson 1963, p. 43).
    let mut c = w.coeffs().to_vec();
    c[19] -= Rational::from(1) >> 23u32;
    let pw = Polynomial::from_coeffs(c);
    let r = real_roots(&pw).unwrap();
    let expected = [
        1.0,
        2.0,
        3.0,
        4.0,
        4.999999928,
        6.000006944,
        6.999697234,
        8.007267603,
        8.917250249,
        20.846908101,
    ];
    assert_eq!(r.len(), expected.len());
    for (root, want) in r.iter().zip(expected) {
        assert!(
            (root.nearest() - want).abs() < 1e-8 * want,
            "{} vs {want}",
            root.nearest()
        );
        assert!(!root.is_rational());
        assert_rounds_correctly(&pw, root);
    }
    // A double root inside: (x − 1)…(x − 10)·(x − 5).
    let wd = &wilkinson(10) * &Polynomial::from_roots(&[(q(5, 1), 1)]);
    let r = real_roots(&wd).unwrap();
    assert_eq!(r.len(), 10);
    assert_eq!(
        r.iter().map(|x| x.multiplicity()).collect::<Vec<_>>(),
        [1, 1, 1, 1, 2, 1, 1, 1, 1, 1]
    );
}

/// Mignotte's polynomial `xⁿ − 2(ax − 1)²` has two roots `1/a ± ~a^{-n/2-1}/√2` closer
/// than any other pair of its kind.
#[test]
fn mignotte_close_roots() {
    let (n, a) = (10usize, 100i64);
    let mut p = Polynomial::from_coeffs(vec![q(-2, 1), q(4 * a, 1), q(-2 * a * a, 1)]);
    p = &p
        + &Polynomial::from_coeffs({
            let mut v = vec![Rational::new(); n + 1];
            v[n] = q(1, 1);
            v
        });
    let r = real_roots(&p).unwrap();
    // x⁵ = ±√2(100x − 1): three real roots of the + branch, one of the − branch.
    assert_eq!(r.len(), 4);
    let near: Vec<&RealRoot> = r
        .iter()
        .filter(|x| (x.nearest() - 0.01).abs() < 1e-6)
        .collect();
    assert_eq!(near.len(), 2);
    let sep = 0.01f64.powi(5) / (100.0 * 2f64.sqrt()); // ≈ 7.07e-13
    assert!((near[0].nearest() - (0.01 - sep)).abs() < 1e-3 * sep);
    assert!((near[1].nearest() - (0.01 + sep)).abs() < 1e-3 * sep);
    for x in &r {
        assert_eq!(x.multiplicity(), 1);
        assert_rounds_correctly(&p, x);
    }
    let c = count_real_roots_in(&p, &exact(0.0099), &exact(0.0101)).unwrap();
    assert_eq!(c.distinct, 2);
}

#[test]
fn roots_at_interval_end_points() {
    let f = Polynomial::from_roots(&[(q(1, 1), 1), (q(2, 1), 1), (q(1, 3), 1)]);
    let r = real_roots_in(&f, &q(1, 1), &q(2, 1)).unwrap();
    assert_eq!(
        r.iter().map(|x| x.exact().cloned()).collect::<Vec<_>>(),
        [Some(q(1, 1)), Some(q(2, 1))]
    );
    let r = real_roots_in(&f, &q(1, 3), &q(1, 3)).unwrap();
    assert_eq!(r.len(), 1);
    assert_eq!(r[0].exact(), Some(&q(1, 3)));
    assert_eq!(r[0].nearest(), 1.0 / 3.0);
    assert_eq!(real_roots_in(&f, &q(1, 2), &q(9, 10)).unwrap().len(), 0);
    let c = count_real_roots_in(&f, &q(1, 3), &q(1, 1)).unwrap();
    assert_eq!(c.distinct, 2);

    // √2 lies below the double 1.4142135623730951 and above its predecessor.
    let s = Polynomial::from_i64s(&[-2, 0, 1]);
    let above = std::f64::consts::SQRT_2;
    assert!(exact(above) * exact(above) > 2);
    assert_eq!(real_roots_in(&s, &q(0, 1), &exact(above)).unwrap().len(), 1);
    assert_eq!(
        real_roots_in(&s, &q(0, 1), &exact(next_down(above)))
            .unwrap()
            .len(),
        0
    );
    assert_eq!(
        count_real_roots_in(&s, &exact(next_down(above)), &exact(above))
            .unwrap()
            .distinct,
        1
    );
    let double = Polynomial::from_roots(&[(q(1, 1), 2), (q(3, 1), 1)]);
    assert_eq!(
        count_real_roots_in(&double, &q(1, 1), &q(3, 1)).unwrap(),
        RootCount {
            distinct: 2,
            with_multiplicity: 3
        }
    );
    assert_eq!(
        count_real_roots_in(&double, &q(3, 2), &q(3, 1)).unwrap(),
        RootCount {
            distinct: 1,
            with_multiplicity: 1
        }
    );
    // Bad input: an inverted interval and the zero polynomial are typed errors.
    let e = real_roots_in(&f, &q(2, 1), &q(1, 1)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("empty_domain", "interval"));
    let e = real_roots(&Polynomial::zero()).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("invalid_value", "poly"));
    assert!(real_roots(&Polynomial::from_i64s(&[5])).unwrap().is_empty());
}

#[test]
fn rounding_of_hard_cases() {
    // Ties and near-ties: the root 1 + 2⁻⁵³ is the midpoint between 1 and 1 + 2⁻⁵²
    // (ties to even: 1); 1 + 2⁻⁵³ + 2⁻¹⁰⁰ rounds up.
    let tie = Rational::from(1) + (Rational::from(1) >> 53u32);
    let r = real_roots(&Polynomial::from_roots(&[(tie.clone(), 1)])).unwrap();
    assert_eq!(r[0].nearest(), 1.0);
    let above = tie + (Rational::from(1) >> 100u32);
    let p = &Polynomial::from_roots(&[(above, 1)]) * &Polynomial::from_i64s(&[-3, 0, 1]);
    let r = real_roots(&p).unwrap();
    assert_eq!(r[1].nearest(), 1.0 + f64::EPSILON);
    // The two irrational roots ±√3 agree with IEEE's correctly rounded sqrt.
    assert_eq!(r[0].nearest(), -(3f64.sqrt()));
    assert_eq!(r[2].nearest(), 3f64.sqrt());
    // Cubics without rational roots: x³ − 3x + 1 (roots 2cos(2πk/9)) and x⁵ − x − 1.
    for p in [
        Polynomial::from_i64s(&[1, -3, 0, 1]),
        Polynomial::from_i64s(&[-1, -1, 0, 0, 0, 1]),
    ] {
        for x in real_roots(&p).unwrap() {
            assert!(!x.is_rational());
            assert_rounds_correctly(&p, &x);
        }
    }
    // A rational root inside a square-free factor of degree 4: (7x − 3)(x³ − 2·10¹⁰⁰).
    let cube = Polynomial::from_coeffs(vec![
        Rational::from(-2) * ten_pow(100),
        q(0, 1),
        q(0, 1),
        q(1, 1),
    ]);
    let p = &Polynomial::from_i64s(&[-3, 7]) * &cube;
    let r = real_roots(&p).unwrap();
    assert_eq!(r.len(), 2);
    assert_eq!(r[0].exact(), Some(&q(3, 7)));
    assert_eq!(r[0].nearest(), 3.0 / 7.0);
    assert!(!r[1].is_rational());
    assert_rounds_correctly(&p, &r[1]);
    // Huge and tiny: x² − 2·10³⁰⁰ and 10³⁰⁰x² − 2.
    let huge = Polynomial::from_coeffs(vec![Rational::from(-2) * ten_pow(300), q(0, 1), q(1, 1)]);
    let tiny = Polynomial::from_coeffs(vec![q(-2, 1), q(0, 1), ten_pow(300)]);
    for p in [huge, tiny] {
        let r = real_roots(&p).unwrap();
        assert_eq!(r.len(), 2);
        for x in &r {
            assert_rounds_correctly(&p, x);
        }
    }
    // Beyond the double range: the root 2¹⁰³⁰ rounds to +∞ (reported as overflowed).
    let r = real_roots(&Polynomial::from_roots(&[(
        Rational::from(1) << 1030u32,
        1,
    )]))
    .unwrap();
    assert!(r[0].rounded().overflowed());
}

#[test]
fn refinement_to_a_width_keeps_the_root() {
    let p = Polynomial::from_i64s(&[-2, 0, 1]);
    let mut r = real_roots(&p).unwrap().pop().unwrap();
    let w = Rational::from(1) >> 400u32;
    r.refine_to_width(&w);
    let (lo, hi) = r.interval();
    assert!(Rational::from(&hi - &lo) <= w);
    // MPFR's √2 at 600 bits (an enclosure) lies inside.
    let s = MpfrInterval::point(2.0, 600).sqrt();
    assert!(*s.lo() > lo && *s.hi() < hi);
    assert_eq!(r.compare(&q(3, 2)), Ordering::Less);
    assert_eq!(r.compare(&q(7, 5)), Ordering::Greater);
}

/// Small rational roots `n/d` with multiplicities.
fn rational_roots() -> impl Strategy<Value = Vec<(i64, i64, u32)>> {
    prop::collection::vec((-30i64..=30, 1i64..=8, 1u32..=3), 1..=5)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A product of linear factors has exactly its roots, with their multiplicities,
    /// exact, and rounded as IEEE division rounds `n/d`.
    #[test]
    fn products_of_linear_factors(roots in rational_roots(), shift in -60i32..=60) {
        let mut want: Vec<(Rational, u32)> = Vec::new();
        for (n, d, m) in roots {
            let r = Rational::from((n, d)) << shift;
            match want.iter_mut().find(|(x, _)| *x == r) {
                Some(entry) => entry.1 += m,
                None => want.push((r, m)),
            }
        }
        want.sort_by(|a, b| a.0.cmp(&b.0));
        let p = Polynomial::from_roots(&want).scale(&q(-7, 3));
        let got = real_roots(&p).unwrap();
        prop_assert_eq!(got.len(), want.len());
        for (g, (r, m)) in got.iter().zip(&want) {
            prop_assert_eq!(g.exact(), Some(r));
            prop_assert_eq!(g.multiplicity(), *m);
            // n/d·2^shift: IEEE division of small integers is correctly rounded and
            // the power-of-two scaling is exact in this range.
            let unscaled = Rational::from(r >> shift);
            let f = unscaled.numer().to_f64() / unscaled.denom().to_f64();
            prop_assert_eq!(g.nearest(), f * 2f64.powi(shift));
        }
        let total: u32 = want.iter().map(|(_, m)| m).sum();
        prop_assert_eq!(count_real_roots(&p).unwrap().with_multiplicity, total as usize);
    }

    /// Quadratic factors `x² − k` (k not a square) give the irrational roots ±√k, rounded
    /// as IEEE's correctly rounded `sqrt`, next to rational roots and repeated factors.
    #[test]
    fn irrational_square_roots(ks in prop::collection::btree_set(2i64..60, 1..=3),
                               rational in -20i64..=20, m in 1u32..=3) {
        let ks: Vec<i64> = ks.into_iter().filter(|k| {
            let s = (*k as f64).sqrt() as i64;
            s * s != *k
        }).collect();
        let mut p = Polynomial::from_roots(&[(q(rational, 7), m)]);
        for k in &ks {
            p = &p * &Polynomial::from_i64s(&[-k, 0, 1]);
        }
        let got = real_roots(&p).unwrap();
        prop_assert_eq!(got.len(), 1 + 2 * ks.len());
        let mut want: Vec<f64> = ks.iter().flat_map(|&k| {
            let s = (k as f64).sqrt();
            [s, -s]
        }).collect();
        want.push(rational as f64 / 7.0);
        want.sort_by(|a, b| a.partial_cmp(b).unwrap());
        for (g, w) in got.iter().zip(&want) {
            prop_assert_eq!(g.nearest(), *w);
            let is_rational_root = *w == rational as f64 / 7.0;
            prop_assert_eq!(g.is_rational(), is_rational_root);
            prop_assert_eq!(g.multiplicity(), if is_rational_root { m } else { 1 });
        }
    }
}
