//! One test per error kind the linear constructors produce, each naming its field.

use geocert::geom::{Line, Line2, Plane, Segment, Segment2};
use geocert::num::parse::{parse_rational, rational_from_f64};
use nalgebra::{Vector2, Vector3};
use rug::Rational;

fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}

#[test]
fn non_finite_numbers_name_the_component() {
    let e = Line::new(v(0.0, f64::NAN, 0.0), v(1.0, 0.0, 0.0)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "origin[1]"));
    let e = Plane::parametric(
        v(0.0, 0.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(0.0, f64::INFINITY, 0.0),
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "v[1]"));
    let e = Plane::implicit(v(0.0, 0.0, 1.0), f64::NEG_INFINITY).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "d"));
    let e =
        Line::with_range(v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), Some([0.0, f64::NAN])).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "range[1]"));
    let e = Segment2::new(Vector2::new(0.0, 0.0), Vector2::new(f64::NAN, 1.0)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "b[0]"));
    let e = rational_from_f64("objects[0].d", f64::NAN).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "objects[0].d"));
}

#[test]
fn zero_directions_are_rejected() {
    let e = Line::new(v(1.0, 2.0, 3.0), v(0.0, -0.0, 0.0)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("zero_direction", "dir"));
    let e = Line2::new(Vector2::new(1.0, 2.0), Vector2::new(0.0, 0.0)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("zero_direction", "dir"));
    let e = Plane::parametric(v(0.0, 0.0, 0.0), v(0.0, 0.0, 0.0), v(0.0, 1.0, 0.0)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("zero_direction", "u"));
    // tiny is not zero
    assert!(Line::new(v(0.0, 0.0, 0.0), v(0.0, 0.0, 1e-320)).is_ok());
}

#[test]
fn degenerate_segments_are_rejected() {
    let e = Segment::new(v(1.0, 2.0, 3.0), v(1.0, 2.0, 3.0)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("zero_direction", "b"));
    let e = Segment2::new(Vector2::new(0.0, 0.0), Vector2::new(-0.0, 0.0)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("zero_direction", "b"));
    assert!(Segment::new(v(1.0, 2.0, 3.0), v(1.0, 2.0, 3.0000000000000004)).is_ok());
}

#[test]
fn collinear_plane_vectors_are_decided_exactly() {
    let e = Plane::parametric(v(0.0, 0.0, 0.0), v(1.0, 2.0, 3.0), v(-0.5, -1.0, -1.5)).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("collinear_plane_vectors", "v"));
    // 0.1·3 vs 0.3 in doubles: u = (0.1, 0.3, 0), v = (1, 3, 0) are not collinear exactly
    // (0.1·3 ≠ 0.3 as exact products of doubles), so the plane is accepted.
    assert!(Plane::parametric(v(0.0, 0.0, 0.0), v(0.1, 0.3, 0.0), v(1.0, 3.0, 0.0)).is_ok());
    // huge components go through rationals
    let e = Plane::parametric(
        v(0.0, 0.0, 0.0),
        v(1e300, 2e300, 0.0),
        v(1e-300, 2e-300, 0.0),
    )
    .unwrap_err();
    assert_eq!(e.kind(), "collinear_plane_vectors");
    let q = |a: i64, b: i64, c: i64| {
        Vector3::new(Rational::from(a), Rational::from(b), Rational::from(c))
    };
    let e = Plane::parametric(q(0, 0, 0), q(1, 2, 3), q(2, 4, 6)).unwrap_err();
    assert_eq!(e.kind(), "collinear_plane_vectors");
}

#[test]
fn zero_normals_are_rejected() {
    let e = Plane::implicit(v(0.0, 0.0, 0.0), 1.0).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("zero_normal", "normal"));
}

#[test]
fn inverted_ranges_are_rejected() {
    let e = Line::with_range(v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), Some([1.0, 0.5])).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("empty_domain", "range"));
    let e = Line2::with_range(
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 0.0),
        Some([2.0, -2.0]),
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), ("empty_domain", "range"));
    assert!(Line::with_range(v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), Some([0.5, 0.5])).is_ok());
}

#[test]
fn invalid_number_strings_are_rejected() {
    let e = parse_rational("objects[0].origin[2]", "1/0").unwrap_err();
    assert_eq!(
        (e.kind(), e.field()),
        ("invalid_number", "objects[0].origin[2]")
    );
    let e = parse_rational("d", "0.1.2").unwrap_err();
    assert_eq!(e.kind(), "invalid_number");
    assert_eq!(
        parse_rational("d", "-1.5e-3").unwrap(),
        Rational::from((-3, 2000))
    );
}
