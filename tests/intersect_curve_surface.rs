//! Curve ∩ surface, float path (OPERATIONS.md §5.2), against the worked example §16.4
//! and closed forms.

use geocert::ops::float::Precision;
use geocert::ops::intersect::intersect_curve_surface_f64;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

mod ops_support;
use ops_support::{nodes, samples, Line3, Torus};

fn sphere(radius: f64) -> Torus {
    Torus {
        major: 0.0,
        minor: radius,
        v_range: [-FRAC_PI_2, FRAC_PI_2],
    }
}

#[test]
fn a_line_crosses_the_sphere_of_16_4_twice() {
    let line = Line3 {
        origin: [-3.0, 0.5, 0.2],
        dir: [1.0, 0.0, 0.0],
        range: [-10.0, 10.0],
    };
    let s = sphere(2.0);
    let pts = intersect_curve_surface_f64(
        &s,
        &line,
        &samples(&line, 1),
        &nodes(&s, 16),
        PI / 10.0,
        &Precision::default(),
    );
    assert_eq!(pts.len(), 2, "{pts:?}");
    let expected = [
        (1.0738639716, [2.8876114213, 0.1001674212]),
        (4.9261360284, [0.2539812323, 0.1001674212]),
    ];
    for (p, (t, uv)) in pts.iter().zip(expected) {
        assert!((p.t - t).abs() < 1e-9 && !p.tangent, "{p:?}");
        assert!((p.surface_params[0] - uv[0]).abs() < 1e-9);
        assert!((p.surface_params[1] - uv[1]).abs() < 1e-9);
    }
    // Closed form: t = 3 ± √(4 − 0.25 − 0.04).
    let h = (4.0f64 - 0.25 - 0.04).sqrt();
    assert!((pts[0].t - (3.0 - h)).abs() < 1e-13 && (pts[1].t - (3.0 + h)).abs() < 1e-13);
}

#[test]
fn the_tangent_line_of_16_4_touches_once() {
    let line = Line3 {
        origin: [-3.0, 2.0, 0.0],
        dir: [1.0, 0.0, 0.0],
        range: [-10.0, 10.0],
    };
    let s = sphere(2.0);
    let pts = intersect_curve_surface_f64(
        &s,
        &line,
        &samples(&line, 1),
        &nodes(&s, 16),
        PI / 10.0,
        &Precision::default(),
    );
    assert_eq!(pts.len(), 1, "{pts:?}");
    let p = &pts[0];
    assert!(p.tangent);
    // The tangency is located only to about √ε (§5.2).
    assert!((p.t - 3.0).abs() < 1e-5, "{p:?}");
    assert!((p.surface_params[0] - FRAC_PI_2).abs() < 1e-5 && p.surface_params[1].abs() < 1e-5);
}

#[test]
fn a_line_through_a_torus_hits_it_four_times() {
    // The x axis through the torus R = 3, r = 1: x = ±2, ±4.
    let line = Line3 {
        origin: [-5.0, 0.0, 0.0],
        dir: [1.0, 0.0, 0.0],
        range: [0.0, 10.0],
    };
    let torus = Torus {
        major: 3.0,
        minor: 1.0,
        v_range: [0.0, TAU],
    };
    let pts = intersect_curve_surface_f64(
        &torus,
        &line,
        &samples(&line, 1),
        &nodes(&torus, 24),
        PI / 10.0,
        &Precision::default(),
    );
    let ts: Vec<f64> = pts.iter().map(|p| p.t).collect();
    assert_eq!(ts.len(), 4, "{pts:?}");
    for (t, x) in ts.iter().zip([1.0, 3.0, 7.0, 9.0]) {
        assert!((t - x).abs() < 1e-12, "{ts:?}");
    }
    assert!(pts.iter().all(|p| !p.tangent));
}

#[test]
fn a_line_missing_the_sphere_has_no_points() {
    let line = Line3 {
        origin: [-3.0, 2.001, 0.0],
        dir: [1.0, 0.0, 0.0],
        range: [-10.0, 10.0],
    };
    let s = sphere(2.0);
    let pts = intersect_curve_surface_f64(
        &s,
        &line,
        &samples(&line, 1),
        &nodes(&s, 16),
        PI / 10.0,
        &Precision::default(),
    );
    assert!(pts.is_empty(), "{pts:?}");
}

#[test]
fn a_line_tangent_to_the_inner_equator_of_a_torus_crosses_twice_and_touches_once() {
    // y = 2 in the plane of the torus R = 3, r = 1 (annulus 2 ≤ ρ ≤ 4): crossings at
    // x = ±√12, a tangency at (0, 2, 0).
    let line = Line3 {
        origin: [-5.0, 2.0, 0.0],
        dir: [1.0, 0.0, 0.0],
        range: [0.0, 10.0],
    };
    let torus = Torus {
        major: 3.0,
        minor: 1.0,
        v_range: [0.0, TAU],
    };
    let pts = intersect_curve_surface_f64(
        &torus,
        &line,
        &samples(&line, 1),
        &nodes(&torus, 24),
        PI / 10.0,
        &Precision::default(),
    );
    assert_eq!(pts.len(), 3, "{pts:?}");
    let r12 = 12f64.sqrt();
    assert!((pts[0].t - (5.0 - r12)).abs() < 1e-12 && !pts[0].tangent);
    assert!((pts[1].t - 5.0).abs() < 1e-5 && pts[1].tangent);
    assert!((pts[2].t - (5.0 + r12)).abs() < 1e-12 && !pts[2].tangent);
}

fn certified(
    line: &Line3,
    s: &Torus,
) -> geocert::Certified<Vec<geocert::ops::certified::CertifiedPoint<3>>> {
    geocert::ops::intersect::intersect_curve_surface(
        s,
        line,
        &samples(line, 1),
        &nodes(s, 16),
        PI / 10.0,
        &Precision::default(),
        &Default::default(),
    )
    .expect("valid input")
}

fn contains(b: &geocert::num::Interval, x: &rug::Float) -> bool {
    b.lo() <= *x && *x <= b.hi()
}

#[test]
fn certified_crossings_of_16_4_contain_the_true_parameters() {
    use geocert::Status;
    let line = Line3 {
        origin: [-3.0, 0.5, 0.2],
        dir: [1.0, 0.0, 0.0],
        range: [-10.0, 10.0],
    };
    let r = certified(&line, &sphere(2.0));
    assert!(r.complete, "{:?}", r.reason);
    assert_eq!(r.status, Status::Verified);
    assert_eq!(r.value.len(), 2);
    // t = 3 ± √3.71 with the doubles 0.5 and 0.2 taken exactly.
    let prec = 300;
    let h2 = rug::Float::with_val(prec, 4)
        - rug::Float::with_val(prec, 0.5f64).square()
        - rug::Float::with_val(prec, 0.2f64).square();
    let h = h2.sqrt();
    let ts = [
        rug::Float::with_val(prec, 3) - &h,
        rug::Float::with_val(prec, 3) + &h,
    ];
    for (p, t) in r.value.iter().zip(ts) {
        assert!(
            contains(&p.root.enclosure[2], &t),
            "{:?} misses {t}",
            p.root.enclosure[2]
        );
        assert_eq!(p.root.status, Status::Verified);
    }
}

#[test]
fn certified_tangency_of_16_4_is_singular_and_encloses_the_touching_point() {
    use geocert::Status;
    let line = Line3 {
        origin: [-3.0, 2.0, 0.0],
        dir: [1.0, 0.0, 0.0],
        range: [-10.0, 10.0],
    };
    let r = certified(&line, &sphere(2.0));
    assert_eq!(r.value.len(), 1, "{r:?}");
    let p = &r.value[0];
    assert_eq!(p.root.status, Status::VerifiedSingular, "{p:?}");
    assert!(p.root.max_roots <= 2);
    let e = &p.root.enclosure;
    assert!(
        e[0].lo() <= std::f64::consts::FRAC_PI_2 && std::f64::consts::FRAC_PI_2 <= e[0].hi(),
        "{e:?}"
    );
    assert!(
        e[1].lo() <= 0.0 && 0.0 <= e[1].hi() && e[2].lo() <= 3.0 && 3.0 <= e[2].hi(),
        "{e:?}"
    );
}

#[test]
fn near_misses_are_proven_and_close_crossings_separated() {
    use geocert::Status;
    let s = sphere(2.0);
    for gap in [1e-6, 1e-9, 1e-12] {
        let miss = Line3 {
            origin: [-3.0, 2.0 + gap, 0.0],
            dir: [1.0, 0.0, 0.0],
            range: [-10.0, 10.0],
        };
        let r = certified(&miss, &s);
        assert!(r.complete && r.value.is_empty(), "gap {gap}: {r:?}");
        let cross = Line3 {
            origin: [-3.0, 2.0 - gap, 0.0],
            dir: [1.0, 0.0, 0.0],
            range: [-10.0, 10.0],
        };
        let r = certified(&cross, &s);
        assert!(r.complete, "gap {gap}: {:?}", r.reason);
        assert_eq!(r.value.len(), 2, "gap {gap}: {r:?}");
        assert!(r.value.iter().all(|p| p.root.status == Status::Verified));
        // Disjoint boxes around t = 3 ∓ √(4 − (2 − gap)²).
        assert!(r.value[0].root.enclosure[2].hi() < r.value[1].root.enclosure[2].lo());
    }
}

mod properties {
    use super::*;
    use geocert::Status;
    use proptest::prelude::*;
    use rug::Float;

    const PREC: u32 = 1024;

    fn dyadic() -> impl Strategy<Value = f64> {
        (-4096i64..4096).prop_map(|m| m as f64 / 1024.0)
    }

    /// `CURVE_SURFACE_CASES` or 96.
    fn cases() -> u32 {
        std::env::var("CURVE_SURFACE_CASES")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(96)
    }

    /// The true crossings of the line `(−3 + t, y, z)` with the sphere of radius 2, as
    /// `(u, v, t)` at 1024 bits: `t = 3 ± √(4 − y² − z²)`, `u = atan2(y, x)` taken in
    /// `[0, 2π)`, `v = asin(z/2)`; and the closed-form least perturbation of one
    /// equation of (5.2) (a shift of the line along y or z) that makes it tangent.
    fn truth(y: f64, z: f64) -> (Vec<[Float; 3]>, Float) {
        let f = |x: f64| Float::with_val(PREC, x);
        let disc = f(4.0) - f(y).square() - f(z).square();
        let tau = Float::with_val(PREC, rug::float::Constant::Pi) * 2u32;
        let mut out = Vec::new();
        if disc >= 0 {
            let h = disc.clone().sqrt();
            for x in [-h.clone(), h] {
                let mut u = f(y).atan2(&x);
                if u < 0 {
                    u += &tau;
                }
                let v = (f(z) / 2u32).asin();
                out.push([u, v, x + 3u32]);
                if disc == 0 {
                    break;
                }
            }
        }
        let mut least = Float::with_val(PREC, rug::float::Special::Infinity);
        for (a, b) in [(y, z), (z, y)] {
            let h2 = f(4.0) - f(b).square();
            if h2 >= 0 {
                let e = (h2.sqrt() - f(a).abs()).abs();
                least = least.min(&e);
            }
        }
        (out, least)
    }

    fn holds(b: &geocert::num::Interval, x: &Float) -> bool {
        *x >= b.lo() && *x <= b.hi()
    }

    /// The answer for the line at `(y, z)` against its truth: complete; every
    /// singular box states a perturbation of at least the closed-form least one; the
    /// true points one-to-one with verified boxes, or all in one singular box.
    fn check(y: f64, z: f64) -> Result<(), TestCaseError> {
        let line = Line3 {
            origin: [-3.0, y, z],
            dir: [1.0, 0.0, 0.0],
            range: [-10.0, 10.0],
        };
        let r = certified(&line, &sphere(2.0));
        let (truths, least) = truth(y, z);
        prop_assert!(r.complete, "({}, {}): {:?}", y, z, r);
        let inside = |p: &geocert::ops::certified::CertifiedPoint<3>, t: &[Float; 3]| {
            (0..3).all(|k| holds(&p.root.enclosure[k], &t[k]))
        };
        let singular = r
            .value
            .iter()
            .filter(|p| p.root.status == Status::VerifiedSingular)
            .count();
        for p in &r.value {
            let held = truths.iter().filter(|t| inside(p, t)).count();
            match p.root.status {
                Status::Verified => prop_assert_eq!(held, 1, "verified box {:?}", p.root),
                Status::VerifiedSingular => {
                    prop_assert!(held <= 2);
                    let e = p.root.perturbation.expect("perturbation");
                    prop_assert!(
                        least <= e,
                        "perturbation {:e} < least {:e}",
                        e,
                        least.to_f64()
                    );
                }
                other => prop_assert!(false, "status {:?} in a complete answer", other),
            }
        }
        for t in &truths {
            let k = r.value.iter().filter(|p| inside(p, t)).count();
            prop_assert_eq!(k, 1, "a true point in {} boxes: {:?}", k, r);
        }
        prop_assert!(
            (singular == 0 && r.value.len() == truths.len())
                || (singular == 1 && r.value.len() == 1),
            "{} boxes ({} singular) for {} points",
            r.value.len(),
            singular,
            truths.len()
        );
        if truths.len() == 2 && least > 1e-6 {
            prop_assert_eq!(singular, 0, "two simple points well apart: {:?}", r);
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(cases()))]

        /// Lines parallel to x at height (y, z) on a 1/1024 grid against the sphere of
        /// radius 2 (away from the seam u = 0 and the poles, which have tests of
        /// their own).
        #[test]
        fn certified_boxes_hold_the_true_roots_one_to_one(y in dyadic(), z in dyadic()) {
            prop_assume!(y.abs() >= 1.0 / 64.0 && z.abs() <= 1.75);
            check(y, z)?;
        }

        /// Near tangency on both sides: `y = ±√(4 − z²) ± 10^-k` (rounded), 3 ≤ k ≤
        /// 15, and ±1 ulp of the rounded tangent height.
        #[test]
        fn near_tangencies_on_both_sides(
            z in -1.5f64..1.5,
            k in 3i32..=16,
            outside in any::<bool>(),
            below in any::<bool>(),
        ) {
            let touch = (4.0 - z * z).sqrt();
            let y = match (k, outside) {
                (16, false) => f64::from_bits(touch.to_bits() - 1),
                (16, true) => f64::from_bits(touch.to_bits() + 1),
                (_, false) => touch - 10f64.powi(-k),
                (_, true) => touch + 10f64.powi(-k),
            };
            check(if below { -y } else { y }, z)?;
        }
    }

    #[test]
    fn exact_tangencies_are_singular_and_pole_tangencies_never_wrongly_decided() {
        for y in [2.0, -2.0] {
            let line = Line3 {
                origin: [-3.0, y, 0.0],
                dir: [1.0, 0.0, 0.0],
                range: [-10.0, 10.0],
            };
            let r = certified(&line, &sphere(2.0));
            assert_eq!(r.value.len(), 1, "{y}: {r:?}");
            assert_eq!(r.value[0].root.status, Status::VerifiedSingular);
            assert!(contains(
                &r.value[0].root.enclosure[2],
                &rug::Float::with_val(53, 3.0)
            ));
        }
        // Touching at a pole, v = π/2 exactly: every u is a solution of (5.2), a
        // continuum no isolating box can hold. The answer may not be decided, but it
        // must not claim a complete absence of points.
        for z in [2.0, -2.0] {
            let line = Line3 {
                origin: [-3.0, 0.0, z],
                dir: [1.0, 0.0, 0.0],
                range: [-10.0, 10.0],
            };
            let r = certified(&line, &sphere(2.0));
            assert!(!(r.complete && r.value.is_empty()), "{z}: {r:?}");
        }
    }
}
