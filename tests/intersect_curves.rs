//! Curve ∩ curve, float path (OPERATIONS.md §6.4, §6.5), against the worked examples
//! §16.6 and closed forms.

use geocert::ops::float::Precision;
use geocert::ops::intersect::intersect_curve_curve_f64;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

mod ops_support;
use ops_support::{samples, Ellipse2, Line3};

fn wrap(t: f64) -> f64 {
    t.rem_euclid(TAU)
}

#[test]
fn circle_and_ellipse_of_16_6_meet_in_four_transversal_points() {
    let circle = Ellipse2 { a: 2.0, b: 2.0 };
    let ellipse = Ellipse2 { a: 3.0, b: 1.0 };
    let pts = intersect_curve_curve_f64(
        &circle,
        &ellipse,
        &samples(&circle, 20),
        &samples(&ellipse, 20),
        &Precision::default(),
    );
    assert_eq!(pts.len(), 4, "{pts:?}");
    let (x, y) = ((27.0f64 / 8.0).sqrt(), (5.0f64 / 8.0).sqrt());
    let (ac, ae) = (0.4063777807, 0.9117382910);
    let expected = [
        ([x, y], [ac, ae]),
        ([-x, y], [PI - ac, PI - ae]),
        ([-x, -y], [PI + ac, PI + ae]),
        ([x, -y], [TAU - ac, TAU - ae]),
    ];
    for (p, (xy, params)) in pts.iter().zip(expected) {
        assert!(!p.tangent, "{p:?}");
        assert!(
            (p.point[0] - xy[0]).abs() < 1e-12 && (p.point[1] - xy[1]).abs() < 1e-12,
            "{p:?}"
        );
        assert!(
            (wrap(p.params[0]) - params[0]).abs() < 1e-9
                && (wrap(p.params[1]) - params[1]).abs() < 1e-9
        );
    }
}

#[test]
fn circle_inside_ellipse_of_16_6_touches_at_two_tangent_points() {
    let circle = Ellipse2 { a: 1.0, b: 1.0 };
    let ellipse = Ellipse2 { a: 3.0, b: 1.0 };
    let pts = intersect_curve_curve_f64(
        &circle,
        &ellipse,
        &samples(&circle, 20),
        &samples(&ellipse, 20),
        &Precision::default(),
    );
    assert_eq!(pts.len(), 2, "{pts:?}");
    for (p, t) in pts.iter().zip([FRAC_PI_2, 3.0 * FRAC_PI_2]) {
        assert!(p.tangent, "{p:?}");
        // A tangency is located to about √ε (§6.4).
        assert!(
            (p.params[0] - t).abs() < 1e-5 && (p.params[1] - t).abs() < 1e-5,
            "{p:?}"
        );
        assert!(p.point[0].abs() < 1e-5 && (p.point[1].abs() - 1.0).abs() < 1e-10);
    }
}

#[test]
fn disjoint_ellipses_have_no_points() {
    let small = Ellipse2 { a: 1.0, b: 0.5 };
    let big = Ellipse2 { a: 3.0, b: 1.0 };
    let pts = intersect_curve_curve_f64(
        &small,
        &big,
        &samples(&small, 20),
        &samples(&big, 20),
        &Precision::default(),
    );
    assert!(pts.is_empty(), "{pts:?}");
}

#[test]
fn crossing_space_lines_meet_once_and_skew_ones_never() {
    let a = Line3 {
        origin: [0.0, 0.0, 0.0],
        dir: [1.0, 0.0, 0.0],
        range: [-5.0, 5.0],
    };
    let b = Line3 {
        origin: [2.0, -1.0, 0.0],
        dir: [0.0, 1.0, 0.0],
        range: [-5.0, 5.0],
    };
    let pts = intersect_curve_curve_f64(
        &a,
        &b,
        &samples(&a, 1),
        &samples(&b, 1),
        &Precision::default(),
    );
    assert_eq!(pts.len(), 1, "{pts:?}");
    assert_eq!(pts[0].params, [2.0, 1.0]);
    assert_eq!(pts[0].point, [2.0, 0.0, 0.0]);
    let skew = Line3 {
        origin: [2.0, -1.0, 1e-3],
        dir: [0.0, 1.0, 0.0],
        range: [-5.0, 5.0],
    };
    let none = intersect_curve_curve_f64(
        &a,
        &skew,
        &samples(&a, 1),
        &samples(&skew, 1),
        &Precision::default(),
    );
    assert!(none.is_empty(), "{none:?}");
}

#[test]
fn certified_circle_ellipse_points_of_16_6() {
    use geocert::ops::intersect::intersect_curve2_curve2;
    use geocert::Status;
    let circle = Ellipse2 { a: 2.0, b: 2.0 };
    let ellipse = Ellipse2 { a: 3.0, b: 1.0 };
    let r = intersect_curve2_curve2(
        &circle,
        &ellipse,
        &samples(&circle, 20),
        &samples(&ellipse, 20),
        &Precision::default(),
        &Default::default(),
    )
    .expect("valid");
    assert!(r.complete, "{:?}", r.reason);
    assert_eq!(r.status, Status::Verified);
    assert_eq!(r.value.len(), 4, "{r:?}");
    // x = ±√(27/8), y = ±√(5/8) (exact data): the four point boxes and the four true
    // points one-to-one (each box holds exactly one, each point is in exactly one box).
    let prec = 1024;
    let x = (rug::Float::with_val(prec, 27) / 8u32).sqrt();
    let y = (rug::Float::with_val(prec, 5) / 8u32).sqrt();
    let truths: Vec<[rug::Float; 2]> = [(1, 1), (-1, 1), (-1, -1), (1, -1)]
        .iter()
        .map(|&(sx, sy)| [x.clone() * sx, y.clone() * sy])
        .collect();
    let holds = |b: &[geocert::num::Interval; 2], t: &[rug::Float; 2]| {
        (0..2).all(|k| t[k] >= b[k].lo() && t[k] <= b[k].hi())
    };
    for p in &r.value {
        let k = truths.iter().filter(|t| holds(&p.point_box, t)).count();
        assert_eq!(k, 1, "{:?} holds {k} true points", p.point_box);
        assert_eq!(p.root.status, Status::Verified);
    }
    for t in &truths {
        let k = r.value.iter().filter(|p| holds(&p.point_box, t)).count();
        assert_eq!(k, 1, "({}, {}) in {k} boxes", t[0], t[1]);
    }
    // Tangent circle r = 1: two touching points, each verified_singular around (0, ±1).
    let small = Ellipse2 { a: 1.0, b: 1.0 };
    let r = intersect_curve2_curve2(
        &small,
        &ellipse,
        &samples(&small, 20),
        &samples(&ellipse, 20),
        &Precision::default(),
        &Default::default(),
    )
    .expect("valid");
    assert_eq!(r.value.len(), 2, "{r:?}");
    assert!(r.complete, "{:?}", r.reason);
    // (0, ±1) one-to-one with the two singular boxes.
    let touching = [[0.0, 1.0], [0.0, -1.0]];
    for p in &r.value {
        assert_eq!(p.root.status, Status::VerifiedSingular, "{p:?}");
        let b = &p.point_box;
        let k = touching
            .iter()
            .filter(|t| (0..2).all(|i| b[i].lo() <= t[i] && t[i] <= b[i].hi()))
            .count();
        assert_eq!(k, 1, "{b:?}");
    }
    for t in touching {
        let k = r
            .value
            .iter()
            .filter(|p| (0..2).all(|i| p.point_box[i].lo() <= t[i] && t[i] <= p.point_box[i].hi()))
            .count();
        assert_eq!(k, 1, "{t:?} in {k} boxes");
    }
}
