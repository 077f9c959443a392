//! Small vector helpers over `[T; D]` for any [`Real`] `T`, so that curve, surface and
//! operation formulas read like the equations they implement. For interval `T` each helper is
//! a composition of enclosing operations and therefore encloses the exact result.

use crate::num::Real;

/// `a + b`.
pub fn add<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| a[i].clone() + &b[i])
}

/// `a − b`.
pub fn sub<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| a[i].clone() - &b[i])
}

/// `s·a`.
pub fn scale<T: Real, const D: usize>(s: &T, a: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| s.clone() * &a[i])
}

/// `a + s·b`.
pub fn add_scaled<T: Real, const D: usize>(a: &[T; D], s: &T, b: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| a[i].clone() + s.clone() * &b[i])
}

/// `a · b`.
pub fn dot<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> T {
    let mut s = a[0].clone() * &b[0];
    for i in 1..D {
        s = s + a[i].clone() * &b[i];
    }
    s
}

/// `|a|²`, with [`Real::sqr`] per component (tighter than `a·a` for intervals).
pub fn norm_sq<T: Real, const D: usize>(a: &[T; D]) -> T {
    let mut s = a[0].sqr();
    for x in a.iter().skip(1) {
        s = s + x.sqr();
    }
    s
}

/// `a × b` in 3D.
pub fn cross<T: Real>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    [
        a[1].clone() * &b[2] - a[2].clone() * &b[1],
        a[2].clone() * &b[0] - a[0].clone() * &b[2],
        a[0].clone() * &b[1] - a[1].clone() * &b[0],
    ]
}

/// The scalar 2D cross product `a_x b_y − a_y b_x` (OPERATIONS.md §0.3).
pub fn cross2<T: Real>(a: &[T; 2], b: &[T; 2]) -> T {
    a[0].clone() * &b[1] - a[1].clone() * &b[0]
}

/// `|a × b|²` in 2D (the square of the scalar cross product) or 3D; in other
/// dimensions by Lagrange's identity `|a|²|b|² − (a·b)²`.
pub fn cross_norm_sq<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> T {
    match D {
        2 => (a[0].clone() * &b[1] - a[1].clone() * &b[0]).sqr(),
        3 => {
            let c0 = a[1].clone() * &b[2] - a[2].clone() * &b[1];
            let c1 = a[2].clone() * &b[0] - a[0].clone() * &b[2];
            let c2 = a[0].clone() * &b[1] - a[1].clone() * &b[0];
            c0.sqr() + c1.sqr() + c2.sqr()
        }
        _ => norm_sq(a) * norm_sq(b) - dot(a, b).sqr(),
    }
}

/// `[v₀, …]` lifted into the number system of `like` (exact for doubles).
pub fn lift<T: Real, const D: usize>(like: &T, v: &[f64; D]) -> [T; D] {
    std::array::from_fn(|i| like.lift(v[i]))
}

/// The zero vector in the number system of `like`.
pub fn zero<T: Real, const D: usize>(like: &T) -> [T; D] {
    std::array::from_fn(|_| like.zero_like())
}

/// Componentwise hull of two vectors (see [`Real::hull_with`]).
pub fn hull<T: Real, const D: usize>(a: &[T; D], b: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| a[i].hull_with(&b[i]))
}

/// Componentwise hull of two jets of the same length.
pub fn hull_jets<T: Real, const D: usize>(a: &[[T; D]], b: &[[T; D]]) -> Vec<[T; D]> {
    a.iter().zip(b).map(|(x, y)| hull(x, y)).collect()
}

/// `−a`.
pub fn neg<T: Real, const D: usize>(a: &[T; D]) -> [T; D] {
    std::array::from_fn(|i| -a[i].clone())
}

/// `a/|a|` (an interval enclosure is unbounded if `a` may vanish).
pub fn normalize<T: Real, const D: usize>(a: &[T; D]) -> [T; D] {
    let n = norm_sq(a).sqrt();
    std::array::from_fn(|i| a[i].clone() / &n)
}

/// The Euclidean length of an f64 vector (no proof; float path only).
pub fn norm_f64<const D: usize>(a: &[f64; D]) -> f64 {
    a.iter().map(|x| x * x).sum::<f64>().sqrt()
}
