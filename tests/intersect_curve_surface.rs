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

    fn dyadic() -> impl Strategy<Value = f64> {
        (-4096i64..4096).prop_map(|m| m as f64 / 1024.0)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// Lines parallel to x at height (y, z) against the sphere of radius 2: every
        /// certified box holds a true root t = 3 ± √(4 − y² − z²) (300-bit), a complete
        /// answer has exactly the true count, and a verified box never holds a tangency.
        #[test]
        fn certified_boxes_hold_the_true_roots_and_complete_counts_are_right(y in dyadic(), z in dyadic()) {
            let line = Line3 { origin: [-3.0, y, z], dir: [1.0, 0.0, 0.0], range: [-10.0, 10.0] };
            let r = certified(&line, &sphere(2.0));
            let prec = 300;
            let d2 = rug::Float::with_val(prec, y).square() + rug::Float::with_val(prec, z).square();
            let disc = rug::Float::with_val(prec, 4) - d2;
            let truths: Vec<rug::Float> = if disc > 0 {
                let h = disc.clone().sqrt();
                vec![rug::Float::with_val(prec, 3) - &h, rug::Float::with_val(prec, 3) + &h]
            } else if disc == 0 {
                vec![rug::Float::with_val(prec, 3)]
            } else {
                vec![]
            };
            for p in &r.value {
                if p.root.status == Status::Undecided { continue; }
                let held = truths.iter().filter(|t| contains(&p.root.enclosure[2], t)).count();
                prop_assert!(held >= 1, "box {:?} holds no root", p.root.enclosure);
                if p.root.status == Status::Verified {
                    prop_assert!(disc != 0, "a tangency reported as a simple root");
                }
            }
            if r.complete {
                let multiplicity: u32 = r.value.iter().map(|p| if p.root.status == Status::Verified { 1 } else { 2 }).sum();
                prop_assert_eq!(multiplicity as usize, if disc == 0 { 2 } else { truths.len() }, "{:?}", r);
            }
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
