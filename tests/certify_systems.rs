//! The certifier (src/certify, issue 4) on systems with known roots: circles meeting
//! transversally, tangent, nearly tangent and nearly missing; a line tangent to a
//! sphere; the 6×6 three-surface system of three spheres; systems defined on half a line.
//! Every truth is computed in closed form at 1100 bits (tests/certify_support).

mod certify_support;

use certify_support::*;
use geocert::certify::{certify_root, solve, Options, Solutions};
use geocert::{Certified, Status};
use rug::Float;

const CIRCLE_DOMAIN: [[f64; 2]; 2] = [[-3.0, 3.0], [-3.0, 3.0]];

fn solve_circles(c: &Circles) -> Certified<Solutions> {
    solve(c, &CIRCLE_DOMAIN, &Options::default()).unwrap()
}

/// Every reported root box holds the number of true roots its status allows, a
/// singular box states a perturbation of at least `least` (the closed-form least
/// perturbation that makes a double root), and when complete every true root lies in
/// exactly one reported box.
fn check_against_truth(r: &Certified<Solutions>, truth: &[Vec<Float>], least: &Float) {
    let s = &r.value;
    for root in s.roots.iter().chain(&s.boundary_roots) {
        let k = count_inside(root, truth);
        match root.status {
            Status::Verified => assert_eq!(k, 1, "a verified box must hold one root: {root:?}"),
            Status::VerifiedSingular => {
                assert!(k <= 2, "{root:?}");
                let e = root
                    .perturbation
                    .expect("a singular box states its perturbation");
                assert!(
                    *least <= e,
                    "perturbation {e:e} below the least {:e} that makes a double root",
                    least.to_f64()
                );
            }
            other => panic!("unexpected status {other:?}"),
        }
    }
    if r.complete {
        for t in truth {
            let covered = s
                .roots
                .iter()
                .chain(&s.boundary_roots)
                .filter(|root| encloses(root, t))
                .count();
            assert_eq!(
                covered, 1,
                "complete, but the root {t:?} is in {covered} reported boxes"
            );
        }
    }
}

#[test]
fn transversal_circles_two_verified_roots() {
    let c = Circles::unit_pair(1.0);
    let (truth, _) = c.truth();
    let r = solve_circles(&c);
    eprintln!(
        "{:?} boxes={} excluded={}",
        r.status, r.value.boxes, r.value.excluded_volume
    );
    assert!(r.complete);
    assert_eq!(r.status, Status::Verified);
    assert_eq!(r.bits, 53);
    assert_eq!(r.value.roots.len(), 2);
    let truth: Vec<Vec<Float>> = truth.iter().map(as_vec).collect();
    check_against_truth(&r, &truth, &c.least_perturbation());
    for root in &r.value.roots {
        assert!(root.enclosure.iter().all(|iv| iv.width() < 1e-12));
    }
}

#[test]
fn tangent_circles_one_singular_box() {
    let c = Circles::unit_pair(2.0);
    let r = solve_circles(&c);
    eprintln!("{r:#?}");
    assert!(r.complete);
    assert_eq!(r.status, Status::VerifiedSingular);
    assert_eq!(r.value.roots.len(), 1);
    let root = &r.value.roots[0];
    assert_eq!(root.max_roots, 2);
    assert!(encloses(root, &point(&[1.0, 0.0])));
    // the exact problem has its double root in the box: the perturbation is ~ rounding
    assert!(root.perturbation.unwrap() < 1e-12);
}

fn nearly_tangent(g: f64) {
    // centres 2 − g apart (the double nearest to it): two roots ±√(d/2·...) apart
    let c = Circles::unit_pair(2.0 - g);
    let (truth, h2) = c.truth();
    assert!(h2 > 0);
    let r = solve_circles(&c);
    eprintln!(
        "gap {g:e}: {:?} bits {} roots {:?}",
        r.status,
        r.bits,
        r.value
            .roots
            .iter()
            .map(|x| (x.status, x.bits))
            .collect::<Vec<_>>()
    );
    assert!(r.complete, "{:?}", r.value.undecided);
    let truth: Vec<Vec<Float>> = truth.iter().map(as_vec).collect();
    check_against_truth(&r, &truth, &c.least_perturbation());
    let verified = r
        .value
        .roots
        .iter()
        .filter(|x| x.status == Status::Verified)
        .count();
    let singular = r.value.roots.len() - verified;
    assert!(verified == 2 && singular == 0 || verified == 0 && singular == 1);
}

#[test]
fn nearly_tangent_circles_gap_1e_6() {
    nearly_tangent(1e-6);
}

#[test]
fn nearly_tangent_circles_gap_1e_12() {
    nearly_tangent(1e-12);
}

#[test]
fn nearly_tangent_circles_gap_1e_15() {
    nearly_tangent(1e-15);
}

#[test]
fn nearly_missing_circles_have_no_verified_root() {
    for g in [1e-3, 1e-6, 1e-9, 1e-12, 1e-15] {
        let c = Circles::unit_pair(2.0 + g);
        assert!(c.truth().0.is_empty());
        let r = solve_circles(&c);
        eprintln!("miss {g:e}: {:?} {:?}", r.status, r.value.roots);
        assert!(r.complete);
        // nothing, or one singular box whose perturbation covers the gap: moving one
        // circle's r² by e makes them touch only for |e| ≥ (2 + g − 1)² − 1 ≈ 2g
        assert!(r.value.roots.len() <= 1, "{:?}", r.value.roots);
        check_against_truth(&r, &[], &c.least_perturbation());
        let least = c.least_perturbation();
        let gap = (2.0 + g) - 2.0; // the gap of the rounded data (exact, Sterbenz)
        assert!(
            least > 1.9 * gap && least < 2.1 * gap,
            "closed form: {least}"
        );
    }
}

#[test]
fn roots_below_f64_resolution_need_mpfr() {
    // |x|² = 1 + 2⁻¹⁰⁰ and |x − (2, 0)|² = 1: roots at y = ±2^-50.5 (about 6e-16), x = 1 − 2⁻¹⁰²
    let c = Circles {
        ea: 2f64.powi(-100),
        ..Circles::unit_pair(2.0)
    };
    let (truth, _) = c.truth();
    let r = solve_circles(&c);
    eprintln!("{:?} bits {} {:#?}", r.status, r.bits, r.value.roots);
    assert!(r.complete);
    let truth: Vec<Vec<Float>> = truth.iter().map(as_vec).collect();
    check_against_truth(&r, &truth, &c.least_perturbation());
    assert_eq!(r.value.roots.len(), 2);
    assert!(r
        .value
        .roots
        .iter()
        .all(|x| x.status == Status::Verified && x.bits >= 128));
    assert!(r.bits >= 128);
}

#[test]
fn line_tangent_to_sphere() {
    let domain = [[-1.0, 1.0], [-1.0, 1.0], [-1.0, 1.0]];
    let r = solve(&LineSphere::tangent(), &domain, &Options::default()).unwrap();
    eprintln!("{r:#?}");
    assert!(r.complete);
    assert_eq!(r.value.roots.len(), 1);
    let root = &r.value.roots[0];
    assert_eq!(root.status, Status::VerifiedSingular);
    assert!(encloses(root, &point(&[0.0, 0.0, 0.0])));
}

#[test]
fn three_spheres_six_by_six() {
    let (sys, truth) = ThreeSpheres::unit_triple();
    let t: Vec<f64> = truth.iter().map(|v| v.to_f64()).collect();
    let guess: Vec<f64> = t
        .iter()
        .enumerate()
        .map(|(i, v)| v + 1e-3 * (i as f64 - 2.5))
        .collect();
    let r = certify_root(&sys, &guess, &Options::default()).unwrap();
    assert_eq!(r.status, Status::Verified);
    assert_eq!(r.bits, 53);
    assert!(encloses(&r.value, &truth));
    // all roots in a box of ±0.05 around the upper point: exactly that one
    let domain: Vec<[f64; 2]> = t.iter().map(|v| [v - 0.05, v + 0.05]).collect();
    let s = solve(&sys, &domain, &Options::default()).unwrap();
    eprintln!("6x6 boxes {}", s.value.boxes);
    assert!(s.complete);
    assert_eq!(s.value.roots.len(), 1);
    assert!(encloses(&s.value.roots[0], &truth));
}

#[test]
fn half_line_systems() {
    // √x = 1/2 on [−1, 1]: one root, 1/4
    let r = solve(&SqrtMinus(0.5), &[[-1.0, 1.0]], &Options::default()).unwrap();
    assert!(r.complete);
    assert_eq!(r.value.roots.len(), 1);
    assert!(encloses(&r.value.roots[0], &point(&[0.25])));
    // √x = −1: no root anywhere (the image is empty left of 0, ≥ 0 right of it)
    let r = solve(&SqrtMinus(-1.0), &[[-1.0, 1.0]], &Options::default()).unwrap();
    assert!(r.complete && r.value.roots.is_empty());
    // √x = 0: the root 0 sits where √ is not differentiable; nothing may be certified
    let r = solve(&SqrtMinus(0.0), &[[-1.0, 1.0]], &Options::default()).unwrap();
    assert!(!r.complete);
    assert!(r.value.roots.is_empty() && r.value.boundary_roots.is_empty());
    assert!(r
        .value
        .undecided
        .iter()
        .any(|u| in_box(&u.enclosure, &point(&[0.0]))));
}

#[test]
fn roots_on_a_bisection_plane_are_reported_once() {
    // unit circles at (∓1/2, 0) meet at (0, ±√3/2): x = 0 is the domain's first split
    let c = Circles {
        a: [-0.5, 0.0],
        ra2: 1.0,
        ea: 0.0,
        b: [0.5, 0.0],
        rb2: 1.0,
    };
    let (truth, _) = c.truth();
    let r = solve_circles(&c);
    assert!(r.complete);
    assert_eq!(r.value.roots.len(), 2);
    let truth: Vec<Vec<Float>> = truth.iter().map(as_vec).collect();
    check_against_truth(&r, &truth, &c.least_perturbation());
}

#[test]
fn line_crossing_a_sphere_twice() {
    // p(t) = (t, 0.3, 0.2): roots t = ±√0.87, u = atan2(0.3, t), v = asin 0.2
    let (sys, t) = LineSphere::crossing(0.3, 0.2);
    let p = TRUTH_BITS;
    let other = vec![
        Float::with_val(p, -&t[0]),
        Float::with_val(
            p,
            Float::with_val(p, 0.3).atan2_ref(&Float::with_val(p, -&t[0])),
        ),
        t[2].clone(),
    ];
    let domain = [[-2.0, 2.0], [-3.0, 3.0], [-1.4, 1.4]];
    let r = solve(&sys, &domain, &Options::default()).unwrap();
    eprintln!("line-sphere boxes {}", r.value.boxes);
    assert!(r.complete);
    assert_eq!(r.status, Status::Verified);
    assert_eq!(r.value.roots.len(), 2);
    check_against_truth(&r, &[t, other], &LineSphere::least_perturbation(0.3, 0.2));
}

#[test]
fn certify_root_escalates_and_falls_back_to_the_singular_test() {
    // roots 1.3e-15 apart: f64 intervals cannot separate them, 128 bits can
    let c = Circles {
        ea: 2f64.powi(-100),
        ..Circles::unit_pair(2.0)
    };
    let (truth, _) = c.truth();
    let t1: Vec<f64> = truth[0].iter().map(|v| v.to_f64()).collect();
    let r = certify_root(&c, &t1, &Options::default()).unwrap();
    assert_eq!(r.status, Status::Verified);
    assert!(r.bits >= 128);
    assert!(encloses(&r.value, &truth[0]) && !encloses(&r.value, &truth[1]));
    // with the cap at f64 it cannot be proven
    let capped = Options {
        max_bits: 53,
        ..Options::default()
    };
    let r = certify_root(&c, &t1, &capped).unwrap();
    assert_ne!(r.status, Status::Verified);
    // the tangent line: a double root, verified_singular
    let r = certify_root(
        &LineSphere::tangent(),
        &[1e-9, -2e-9, 1e-9],
        &Options::default(),
    )
    .unwrap();
    assert_eq!(r.status, Status::VerifiedSingular);
    assert_eq!(r.value.max_roots, 2);
    assert!(encloses(&r.value, &point(&[0.0, 0.0, 0.0])));
    // a near miss: proven to have no root near the estimate, so nothing is certified
    let r = certify_root(
        &Circles::unit_pair(2.0 + 1e-9),
        &[1.0, 0.0],
        &Options::default(),
    )
    .unwrap();
    assert_eq!(r.status, Status::Undecided);
    assert!(r.reason.unwrap().contains("no root"));
}

#[test]
fn a_spent_budget_is_never_complete() {
    let c = Circles::unit_pair(1.0);
    let tight = Options {
        max_boxes: 10,
        ..Options::default()
    };
    let r = solve(&c, &CIRCLE_DOMAIN, &tight).unwrap();
    assert!(!r.complete);
    assert!(r.value.boxes <= 10);
    assert!(r
        .value
        .undecided
        .iter()
        .all(|u| u.reason.contains("budget")));
    // whatever was not found lies in an undecided box
    let (truth, _) = c.truth();
    for t in truth.iter().map(as_vec) {
        let found = r.value.roots.iter().any(|x| encloses(x, &t));
        let open = r.value.undecided.iter().any(|u| in_box(&u.enclosure, &t));
        assert!(found || open);
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let c = Circles::unit_pair(1.0);
    let o = Options::default();
    let e = solve(&c, &[[-1.0, 1.0]], &o).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("count_mismatch", "domain"));
    let e = solve(&c, &[[-1.0, 1.0], [1.0, -1.0]], &o).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("empty_domain", "domain[1]"));
    let e = solve(&c, &[[f64::NAN, 1.0], [-1.0, 1.0]], &o).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "domain[0]"));
    let e = certify_root(&c, &[0.5, f64::INFINITY], &o).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "guess[1]"));
    let e = certify_root(&c, &[0.5], &o).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("count_mismatch", "guess"));
    let bad = Options {
        min_width: -1.0,
        ..Options::default()
    };
    let e = solve(&c, &CIRCLE_DOMAIN, &bad).unwrap_err();
    assert_eq!(
        (e.kind(), e.field()),
        ("invalid_value", "options.min_width")
    );
    // a system that returns the wrong number of equations
    struct Short;
    impl geocert::certify::System for Short {
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: geocert::num::Real>(&self, x: &[T]) -> Vec<T> {
            vec![x[0].clone()]
        }
    }
    let e = solve(&Short, &CIRCLE_DOMAIN, &o).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("count_mismatch", "system.eval"));
}
