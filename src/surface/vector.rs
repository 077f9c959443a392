//! Small fixed-size vector helpers generic over [`Real`], so that every surface formula
//! is written once for f64, intervals and MPFR intervals. (The same helpers as
//! `ops::vector` on main; the coordinator keeps one copy at merge.)
//!
//! Interval evaluation encloses the exact result because each helper is a composition
//! of the enclosing operations of [`Real`].

use crate::num::Real;

/// `a·b`.
pub fn dot<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> T {
    let mut s = a[0].clone() * &b[0];
    for i in 1..D {
        s = s + a[i].clone() * &b[i];
    }
    s
}

/// `a + b`.
pub fn add<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| a[i].clone() + &b[i])
}

/// `a − b`.
pub fn sub<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| a[i].clone() - &b[i])
}

/// `k·a`.
pub fn scale<T: Real, const D: usize>(a: &[T; D], k: &T) -> [T; D] {
    std::array::from_fn(|i| a[i].clone() * k)
}

/// `a + k·b`.
pub fn add_scaled<T: Real, const D: usize>(a: &[T; D], k: &T, b: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| a[i].clone() + k.clone() * &b[i])
}

/// `−a`.
pub fn neg<T: Real, const D: usize>(a: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| -a[i].clone())
}

/// `a × b` (3D).
pub fn cross<T: Real>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    [
        a[1].clone() * &b[2] - a[2].clone() * &b[1],
        a[2].clone() * &b[0] - a[0].clone() * &b[2],
        a[0].clone() * &b[1] - a[1].clone() * &b[0],
    ]
}

/// `|a|²` (with [`Real::sqr`], tight for intervals that contain 0).
pub fn norm_sq<T: Real, const D: usize>(a: &[T; D]) -> T {
    let mut s = a[0].sqr();
    for x in a.iter().skip(1) {
        s = s + x.sqr();
    }
    s
}

/// `a/|a|` (an interval enclosure is unbounded if `a` may vanish).
pub fn normalize<T: Real, const D: usize>(a: &[T; D]) -> [T; D] {
    let n = norm_sq(a).sqrt();
    std::array::from_fn(|i| a[i].clone() / &n)
}

/// Lift an f64 vector into the number system of `like` (exact: [`Real::lift`]).
pub fn lift<T: Real, const D: usize>(like: &T, p: &[f64; D]) -> [T; D] {
    std::array::from_fn(|i| like.lift(p[i]))
}

/// The zero vector in the number system of `like`.
pub fn zero<T: Real, const D: usize>(like: &T) -> [T; D] {
    std::array::from_fn(|_| like.zero_like())
}

/// The Euclidean length of an f64 vector (no proof; float path only).
pub fn norm_f64<const D: usize>(a: &[f64; D]) -> f64 {
    a.iter().map(|x| x * x).sum::<f64>().sqrt()
}
