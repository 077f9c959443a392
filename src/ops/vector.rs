//! Small fixed-size vector helpers generic over [`Real`], so that an operation's
//! equations are written once for f64, intervals and MPFR intervals.

use crate::num::Real;

/// `a·b`.
pub fn dot<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> T {
    let mut s = a[0].clone() * &b[0];
    for i in 1..D {
        s = s + a[i].clone() * &b[i];
    }
    s
}

/// `a − b`.
pub fn sub<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| a[i].clone() - &b[i])
}

/// `a × b` (3D).
pub fn cross<T: Real>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    [
        a[1].clone() * &b[2] - a[2].clone() * &b[1],
        a[2].clone() * &b[0] - a[0].clone() * &b[2],
        a[0].clone() * &b[1] - a[1].clone() * &b[0],
    ]
}

/// The Euclidean length of an f64 vector (no proof; float path only).
pub fn norm_f64<const D: usize>(a: &[f64; D]) -> f64 {
    a.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Lift an f64 point into the number system of `like` (exact: `Real::lift`).
pub fn lift<T: Real, const D: usize>(like: &T, p: &[f64; D]) -> [T; D] {
    std::array::from_fn(|i| like.lift(p[i]))
}
