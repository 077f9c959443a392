//! Exact truths computed independently of CGAL, in rug::Rational, for the oracle tests.
#![allow(dead_code)]

use geocert::oracle::{Intersection, PlaneInput};
use rug::{Float, Rational};

pub type Q3 = [Rational; 3];

/// The exact rational value of a double.
pub fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite test data")
}

pub fn frac(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

pub fn q3(v: [f64; 3]) -> Q3 {
    v.map(q)
}

pub fn ints3(v: [i64; 3]) -> Q3 {
    v.map(Rational::from)
}

pub fn sub(a: &Q3, b: &Q3) -> Q3 {
    [
        Rational::from(&a[0] - &b[0]),
        Rational::from(&a[1] - &b[1]),
        Rational::from(&a[2] - &b[2]),
    ]
}

pub fn dot(a: &Q3, b: &Q3) -> Rational {
    Rational::from(&a[0] * &b[0]) + Rational::from(&a[1] * &b[1]) + Rational::from(&a[2] * &b[2])
}

pub fn cross(a: &Q3, b: &Q3) -> Q3 {
    [
        Rational::from(&a[1] * &b[2]) - Rational::from(&a[2] * &b[1]),
        Rational::from(&a[2] * &b[0]) - Rational::from(&a[0] * &b[2]),
        Rational::from(&a[0] * &b[1]) - Rational::from(&a[1] * &b[0]),
    ]
}

pub fn is_zero3(a: &Q3) -> bool {
    a.iter().all(|x| *x == 0)
}

/// The plane as `n·x = k`, from the input doubles taken exactly.
pub fn plane_equation(p: &PlaneInput) -> (Q3, Rational) {
    match *p {
        PlaneInput::Parametric { origin, u, v } => {
            let n = cross(&q3(u), &q3(v));
            let k = dot(&n, &q3(origin));
            (n, k)
        }
        PlaneInput::Implicit { a, b, c, d } => ([q(a), q(b), q(c)], -q(d)),
    }
}

pub fn on_plane(x: &Q3, p: &PlaneInput) -> bool {
    let (n, k) = plane_equation(p);
    dot(&n, x) == k
}

/// The double nearest to `x` (rug's `Rational::to_f64` truncates instead).
pub fn nearest(x: &Rational) -> f64 {
    Float::with_val(53, x).to_f64()
}

pub fn parametric(origin: [f64; 3], u: [f64; 3], v: [f64; 3]) -> PlaneInput {
    PlaneInput::Parametric { origin, u, v }
}

pub fn implicit(a: f64, b: f64, c: f64, d: f64) -> PlaneInput {
    PlaneInput::Implicit { a, b, c, d }
}

/// `|a − b| ≤ tol·max(1, |b|)` componentwise.
pub fn close<const D: usize>(a: &[f64; D], b: &[f64; D], tol: f64) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= tol * y.abs().max(1.0))
}

pub fn kind<T, const D: usize>(r: &Intersection<T, D>) -> &'static str {
    match r {
        Intersection::Empty => "empty",
        Intersection::Point(_) => "point",
        Intersection::Line { .. } => "line",
        Intersection::Segment { .. } => "segment",
        Intersection::Ray { .. } => "ray",
        Intersection::Plane(_) => "plane",
    }
}

/// A deterministic xorshift64* stream of test doubles.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed.max(1))
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in [−1, 1), a multiple of 2⁻⁵² (so sums of two are exact).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
    pub fn vec3(&mut self) -> [f64; 3] {
        [self.unit(), self.unit(), self.unit()]
    }
}
