//! Point → curve projection, float path (OPERATIONS.md §3.2), against the worked
//! example §16.3 and closed-form facts.

use geocert::ops::float::Precision;
use geocert::ops::project::{project_point_on_curve_f64, CurveFeet};

mod ops_support;
use ops_support::{samples, Ellipse2};

#[test]
fn all_four_feet_on_the_ellipse_of_16_3() {
    let e = Ellipse2 { a: 3.0, b: 2.0 };
    let CurveFeet::Finite(feet) = project_point_on_curve_f64(
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
    let CurveFeet::Finite(feet) = project_point_on_curve_f64(
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
    let r = project_point_on_curve_f64(
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
    let CurveFeet::Finite(feet) = project_point_on_curve_f64(
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
