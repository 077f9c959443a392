//! Shared by the fillet test files: the faces as shapes, the blend spec, 256-bit MPFR
//! points and the checks that a certified f64 box holds an MPFR truth.

#![allow(dead_code)]

use geocert::num::MpfrInterval;
use geocert::ops::fillet::{BlendSpec, Law, SectorChoice};
use geocert::ops::{Answer, BlendAnswer, Options, Shape};
use geocert::surface::plane::Plane;
use geocert::surface::quadrics::{Cylinder, Sphere};
use geocert::surface::AnySurface;
use geocert::Status;

pub const PREC: u32 = 256;

pub fn plane(origin: [f64; 3], u: [f64; 3], v: [f64; 3]) -> Shape {
    Shape::Surface(AnySurface::Plane(Plane::new(origin, u, v).unwrap()))
}

/// The implicit plane `normal·x + d = 0`.
pub fn implicit_plane(normal: [f64; 3], d: f64) -> Shape {
    Shape::Linear(geocert::ops::shape::Linear::Double(
        geocert::ops::LinearObject::Plane(geocert::geom::Plane::Implicit {
            normal: nalgebra::Vector3::new(normal[0], normal[1], normal[2]),
            d,
        }),
    ))
}

pub fn cylinder(origin: [f64; 3], r: f64, axis: [f64; 3], height: [f64; 2]) -> Shape {
    Shape::Surface(AnySurface::Cylinder(
        Cylinder::new(origin, [r, r], axis, None, height).unwrap(),
    ))
}

pub fn sphere(center: [f64; 3], r: f64) -> Shape {
    Shape::Surface(AnySurface::Sphere(
        Sphere::new(center, r, None, None).unwrap(),
    ))
}

pub fn spec(sector: u8, range: Option<[f64; 2]>, grid: [usize; 2]) -> BlendSpec {
    BlendSpec {
        sector: SectorChoice::Number(sector),
        range,
        grid,
    }
}

/// The sector numbered by the signs `(σ₁, σ₂)` (§11.1).
pub fn sector_of(signs: [f64; 2]) -> u8 {
    match (signs[0] > 0.0, signs[1] > 0.0) {
        (true, true) => 1,
        (true, false) => 2,
        (false, false) => 3,
        (false, true) => 4,
    }
}

fn unwrap_blend(c: geocert::Certified<Answer>) -> (BlendAnswer, Status) {
    let status = c.status;
    match c.value {
        Answer::Blend(b) => (b, status),
        other => panic!("not a blend: {other:?}"),
    }
}

/// A constant-radius fillet's answer and status.
pub fn blend(a: &Shape, b: &Shape, rho: f64, s: &BlendSpec) -> (BlendAnswer, Status) {
    unwrap_blend(geocert::ops::fillet(a, b, rho, s, &Options::default()).unwrap())
}

/// A fillet with a radius law.
pub fn blend_law(a: &Shape, b: &Shape, law: &Law, s: &BlendSpec) -> (BlendAnswer, Status) {
    unwrap_blend(geocert::ops::fillet::fillet_law(a, b, law, s, &Options::default()).unwrap())
}

/// A chamfer with leg laws.
pub fn chamfer_laws(a: &Shape, b: &Shape, legs: &[Law; 2], s: &BlendSpec) -> (BlendAnswer, Status) {
    unwrap_blend(geocert::ops::fillet::chamfer_laws(a, b, legs, s, &Options::default()).unwrap())
}

pub fn m(x: f64) -> MpfrInterval {
    MpfrInterval::point(x, PREC)
}

/// `b` (a certified f64 box) contains the MPFR enclosure `truth`.
pub fn contains(b: [f64; 2], truth: &MpfrInterval) -> bool {
    b[0] <= truth.lo_f64() && truth.hi_f64() <= b[1]
}

pub fn assert_box_contains(b: &[[f64; 2]], truth: &[MpfrInterval], what: &str) {
    for k in 0..truth.len() {
        assert!(
            contains(b[k], &truth[k]),
            "{what}[{k}]: box {:?} misses the truth [{}, {}]",
            b[k],
            truth[k].lo_f64(),
            truth[k].hi_f64()
        );
    }
}

/// Upper bound of the distance from the f64 point `p` to the MPFR point `q`.
pub fn dist(p: &[f64], q: &[MpfrInterval; 3]) -> f64 {
    let s = (0..3)
        .map(|k| (q[k].clone() - m(p[k])).sqr())
        .fold(m(0.0), |a, b| a + b);
    s.sqrt().hi_f64()
}

pub fn cross(a: &[MpfrInterval; 3], b: &[MpfrInterval; 3]) -> [MpfrInterval; 3] {
    geocert::num::vector::cross(a, b)
}

pub fn dot(a: &[MpfrInterval; 3], b: &[MpfrInterval; 3]) -> MpfrInterval {
    geocert::num::vector::dot(a, b)
}

pub fn norm(a: &[MpfrInterval; 3]) -> MpfrInterval {
    geocert::num::vector::norm_sq(a).sqrt()
}

pub fn unit(a: &[MpfrInterval; 3]) -> [MpfrInterval; 3] {
    let n = norm(a);
    a.clone().map(|c| c / n.clone())
}

/// `a + s·b` in MPFR.
pub fn axpy(a: &[MpfrInterval; 3], s: &MpfrInterval, b: &[MpfrInterval; 3]) -> [MpfrInterval; 3] {
    [0, 1, 2].map(|k| a[k].clone() + s.clone() * b[k].clone())
}

pub fn lift3(x: [f64; 3]) -> [MpfrInterval; 3] {
    x.map(m)
}

/// The kind and field of an expected error.
pub fn error_kind<T: std::fmt::Debug>(r: Result<T, geocert::GeomError>) -> (String, String) {
    let e = r.expect_err("a typed error");
    (e.kind().to_string(), e.field().to_string())
}

/// A case through the command line's reader and solver, as JSON.
pub fn solve(text: &str) -> serde_json::Value {
    let mut read = geocert::io::read_cases(text);
    serde_json::to_value(geocert::io::solve_case(read.remove(0))).unwrap()
}
