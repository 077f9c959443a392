//! Point → curve projection, float path (OPERATIONS.md §3.2), against the worked
//! example §16.3 and closed-form facts.

use geocert::ops::float::Precision;
use geocert::ops::project::{project_point_curve_f64, CurveFeet};

mod ops_support;
use ops_support::{samples, Ellipse2};

#[test]
fn all_four_feet_on_the_ellipse_of_16_3() {
    let e = Ellipse2 { a: 3.0, b: 2.0 };
    let CurveFeet::Finite(feet) = project_point_curve_f64(
        &e,
        &[0.5, 0.2],
        &samples(&e, 20),
        &Precision::default(),
        false,
    ) else {
        panic!("finite expected")
    };
    let expected = [
        (1.2901854022, [0.8308281882, 1.9217728530], 1.7532681048),
        (3.2031430402, [-2.9943191187, -0.1230230611], 3.5092178617),
        (5.0463134705, [0.9832597720, -1.8895267157], 2.1446822382),
        (6.1683213550, [2.9802311585, -0.2292230762], 2.5170973459),
    ];
    assert_eq!(feet.len(), 4, "{feet:?}");
    for (f, (t, xy, d)) in feet.iter().zip(expected) {
        assert!((f.t - t).abs() < 1e-9, "{f:?}");
        assert!((f.point[0] - xy[0]).abs() < 1e-9 && (f.point[1] - xy[1]).abs() < 1e-9);
        assert!((f.distance - d).abs() < 1e-9);
    }
}

#[test]
fn nearest_foot_of_16_3() {
    let e = Ellipse2 { a: 3.0, b: 2.0 };
    let CurveFeet::Finite(feet) = project_point_curve_f64(
        &e,
        &[0.5, 0.2],
        &samples(&e, 20),
        &Precision::default(),
        true,
    ) else {
        panic!("finite expected")
    };
    assert_eq!(feet.len(), 1);
    assert!((feet[0].t - 1.2901854022).abs() < 1e-9);
    assert!((feet[0].distance - 1.7532681048).abs() < 1e-9);
}

#[test]
fn the_centre_of_a_circle_has_infinitely_many_feet() {
    let c = Ellipse2 { a: 2.0, b: 2.0 };
    let r = project_point_curve_f64(
        &c,
        &[0.0, 0.0],
        &samples(&c, 20),
        &Precision::default(),
        false,
    );
    assert_eq!(r, CurveFeet::Infinite);
}

#[test]
fn a_point_on_the_major_axis_outside_has_the_two_vertices_as_feet() {
    // p = (5, 0) on the x axis beyond the vertex: feet at t = 0 (distance 2) and
    // t = π (distance 8); the evolute's cusp is at x = (a² − b²)/a = 5/3 < 5, so no other.
    let e = Ellipse2 { a: 3.0, b: 2.0 };
    let CurveFeet::Finite(feet) = project_point_curve_f64(
        &e,
        &[5.0, 0.0],
        &samples(&e, 20),
        &Precision::default(),
        false,
    ) else {
        panic!("finite expected")
    };
    assert_eq!(feet.len(), 2, "{feet:?}");
    assert!(feet[0].t.abs() < 1e-12 && (feet[0].distance - 2.0).abs() < 1e-12);
    assert!((feet[1].t - std::f64::consts::PI).abs() < 1e-12);
    assert!((feet[1].distance - 8.0).abs() < 1e-12);
}

/// The foot equation of the ellipse (3, 2) from (0.5, 0.2) at 300 bits:
/// f(t) = (p − c)·c' with c = (3 cos t, 2 sin t).
fn ellipse_foot_mpfr(t: &rug::Float) -> rug::Float {
    let prec = 300;
    let (s, c) = (t.clone().sin(), t.clone().cos());
    let dx = rug::Float::with_val(prec, 0.5) - rug::Float::with_val(prec, 3) * &c;
    let dy = rug::Float::with_val(prec, 0.2) - rug::Float::with_val(prec, 2) * &s;
    dx * (rug::Float::with_val(prec, -3) * &s) + dy * (rug::Float::with_val(prec, 2) * &c)
}

/// A root of the ellipse's foot equation in `[a, b]` by bisection at 300 bits.
fn ellipse_root(a: f64, b: f64) -> rug::Float {
    let (mut lo, mut hi) = (rug::Float::with_val(300, a), rug::Float::with_val(300, b));
    let sign_lo = ellipse_foot_mpfr(&lo).is_sign_negative();
    assert_ne!(
        sign_lo,
        ellipse_foot_mpfr(&hi).is_sign_negative(),
        "no bracket"
    );
    for _ in 0..250 {
        let mid = (lo.clone() + &hi) / 2u32;
        if ellipse_foot_mpfr(&mid).is_sign_negative() == sign_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

#[test]
fn certified_feet_of_16_3_contain_the_true_roots_and_are_complete() {
    use geocert::ops::project::project_point_curve;
    use geocert::Status;
    let e = Ellipse2 { a: 3.0, b: 2.0 };
    let r = project_point_curve(
        &e,
        &[0.5, 0.2],
        &samples(&e, 20),
        &Precision::default(),
        &Default::default(),
    )
    .expect("valid");
    assert!(r.complete, "{:?}", r.reason);
    assert_eq!(r.status, Status::Verified);
    assert_eq!(r.value.len(), 4);
    for (f, t) in r
        .value
        .iter()
        .zip([1.2901854022, 3.2031430402, 5.0463134705, 6.1683213550])
    {
        let truth = ellipse_root(t - 1e-8, t + 1e-8);
        let b = &f.root.enclosure[0];
        assert!(b.lo() <= truth && truth <= b.hi(), "{b:?} misses {truth}");
        assert_eq!(f.root.status, Status::Verified);
        assert_eq!(f.root.max_roots, 1);
        // The point box contains the point at the estimate.
        assert!(
            (0..2).all(|i| f.point_box[i].lo() <= f.point[i] && f.point[i] <= f.point_box[i].hi())
        );
    }
}
