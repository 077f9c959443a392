//! The small ring trait that every polynomial formula of the linear kernel is written
//! against, once (cross products, determinants, Cramer numerators, the metric-tensor
//! parameter recovery of OPERATIONS.md §3.3 eqs. (3.7)–(3.8)).
//!
//! Implementations:
//! * `f64` — plain floating point (the uncertified `*_f64` paths);
//! * [`crate::num::dd::Dd`] — double-double evaluation used by the filter tier;
//! * [`crate::num::error_bound::ErrorBound`] — the static error analysis that derives the
//!   filter constants (CGAL's `Static_filter_error`);
//! * `rug::Rational` — exact arithmetic (the `*_exact` paths and the last tier).
//!
//! [`Field`] adds division and an exact sign; it is what the exact decision procedures
//! (`core` functions in `geom/`) are generic over (`f64` for the plain path, `Rational`
//! for the exact one).

use rug::Rational;
use std::cmp::Ordering;

/// A commutative ring: the operations a polynomial formula needs.
/// Method names avoid clashing with `std::ops`.
pub trait Ring: Clone {
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    fn plus(&self, rhs: &Self) -> Self;
    fn minus(&self, rhs: &Self) -> Self;
    fn times(&self, rhs: &Self) -> Self;
    fn negate(&self) -> Self;
}

/// A ring with division and an exact sign (exact for `Rational`; for `f64` the sign of
/// the rounded value, which proves nothing).
pub trait Field: Ring + nalgebra::Scalar {
    fn divide(&self, rhs: &Self) -> Self;
    fn sign(&self) -> Ordering;
    /// The exact value of a double in this field.
    fn from_f64(x: f64) -> Self;
    fn is_zero(&self) -> bool {
        self.sign() == Ordering::Equal
    }
    /// Compare two values (`self − rhs` against 0).
    fn compare(&self, rhs: &Self) -> Ordering {
        self.minus(rhs).sign()
    }
}

impl Ring for f64 {
    #[inline(always)]
    fn zero() -> Self {
        0.0
    }
    #[inline(always)]
    fn one() -> Self {
        1.0
    }
    #[inline(always)]
    fn plus(&self, rhs: &Self) -> Self {
        self + rhs
    }
    #[inline(always)]
    fn minus(&self, rhs: &Self) -> Self {
        self - rhs
    }
    #[inline(always)]
    fn times(&self, rhs: &Self) -> Self {
        self * rhs
    }
    #[inline(always)]
    fn negate(&self) -> Self {
        -self
    }
}

impl Field for f64 {
    #[inline(always)]
    fn divide(&self, rhs: &Self) -> Self {
        self / rhs
    }
    #[inline(always)]
    fn sign(&self) -> Ordering {
        self.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    }
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn compare(&self, rhs: &Self) -> Ordering {
        self.partial_cmp(rhs).unwrap_or(Ordering::Equal)
    }
}

impl Ring for Rational {
    fn zero() -> Self {
        Rational::new()
    }
    fn one() -> Self {
        Rational::from(1)
    }
    fn plus(&self, rhs: &Self) -> Self {
        Rational::from(self + rhs)
    }
    fn minus(&self, rhs: &Self) -> Self {
        Rational::from(self - rhs)
    }
    fn times(&self, rhs: &Self) -> Self {
        Rational::from(self * rhs)
    }
    fn negate(&self) -> Self {
        Rational::from(-self)
    }
}

impl Field for Rational {
    /// Division by zero is never attempted by the kernel: every quotient is formed after
    /// the denominator's sign was decided non-zero. (rug would panic.)
    fn divide(&self, rhs: &Self) -> Self {
        Rational::from(self / rhs)
    }
    fn sign(&self) -> Ordering {
        self.cmp0()
    }
    /// Exact for finite doubles; non-finite doubles are rejected by the constructors
    /// before they reach a formula (they map to 0 here rather than panic).
    fn from_f64(x: f64) -> Self {
        Rational::from_f64(x).unwrap_or_default()
    }
    fn compare(&self, rhs: &Self) -> Ordering {
        self.cmp(rhs)
    }
}

/// `[e(0), e(1), ...]` written out, so that the expression is inlined into the caller
/// (array `map` with a closure may be compiled out of line, which loses the caller's
/// `#[target_feature(enable = "fma")]` and turns `mul_add` into a software call).
macro_rules! each {
    ($i:ident in [$($n:expr),*] => $e:expr) => {
        [$({
            let $i = $n;
            $e
        }),*]
    };
}
pub(crate) use each;

/// A 3-vector in a ring.
pub type V3<R> = [R; 3];
/// A 2-vector in a ring.
pub type V2<R> = [R; 2];

/// `a·d − b·c`, the 2×2 determinant (and the 2D cross product of `(a, b)`, `(c, d)`).
#[inline(always)]
pub fn det2<R: Ring>(a: &R, b: &R, c: &R, d: &R) -> R {
    a.times(d).minus(&b.times(c))
}

/// `a − b` componentwise.
#[inline(always)]
pub fn sub3<R: Ring>(a: &V3<R>, b: &V3<R>) -> V3<R> {
    [a[0].minus(&b[0]), a[1].minus(&b[1]), a[2].minus(&b[2])]
}

/// `a − b` componentwise in 2D.
#[inline(always)]
pub fn sub2<R: Ring>(a: &V2<R>, b: &V2<R>) -> V2<R> {
    [a[0].minus(&b[0]), a[1].minus(&b[1])]
}

/// `a·b`.
#[inline(always)]
pub fn dot3<R: Ring>(a: &V3<R>, b: &V3<R>) -> R {
    a[0].times(&b[0])
        .plus(&a[1].times(&b[1]))
        .plus(&a[2].times(&b[2]))
}

/// `a·b` in 2D.
#[inline(always)]
pub fn dot2<R: Ring>(a: &V2<R>, b: &V2<R>) -> R {
    a[0].times(&b[0]).plus(&a[1].times(&b[1]))
}

/// `a × b`.
#[inline(always)]
pub fn cross3<R: Ring>(a: &V3<R>, b: &V3<R>) -> V3<R> {
    [
        det2(&a[1], &a[2], &b[1], &b[2]),
        det2(&a[2], &a[0], &b[2], &b[0]),
        det2(&a[0], &a[1], &b[0], &b[1]),
    ]
}

/// The 2D cross product `a × b = a_x b_y − a_y b_x` (OPERATIONS.md §0.3).
#[inline(always)]
pub fn cross2<R: Ring>(a: &V2<R>, b: &V2<R>) -> R {
    det2(&a[0], &a[1], &b[0], &b[1])
}

/// `det(a, b, c) = a·(b × c)`.
#[inline(always)]
pub fn det3<R: Ring>(a: &V3<R>, b: &V3<R>, c: &V3<R>) -> R {
    dot3(a, &cross3(b, c))
}

/// `s·a` for a scalar `s`.
#[inline(always)]
pub fn scale3<R: Ring>(s: &R, a: &V3<R>) -> V3<R> {
    [s.times(&a[0]), s.times(&a[1]), s.times(&a[2])]
}

/// `a + b` componentwise.
#[inline(always)]
pub fn add3<R: Ring>(a: &V3<R>, b: &V3<R>) -> V3<R> {
    [a[0].plus(&b[0]), a[1].plus(&b[1]), a[2].plus(&b[2])]
}

/// Every component is exactly zero (decided by the field's sign).
pub fn is_zero3<R: Field>(a: &V3<R>) -> bool {
    a.iter().all(|x| x.is_zero())
}

/// Map a vector of doubles into a ring element by element.
#[inline(always)]
pub fn lift3<R>(a: &[f64; 3], f: impl Fn(f64) -> R) -> V3<R> {
    [f(a[0]), f(a[1]), f(a[2])]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generic_formulas_agree_in_f64_and_rationals() {
        let a = [1.0, 2.0, 3.0];
        let b = [-2.0, 0.5, 4.0];
        let c = [0.25, -1.0, 2.0];
        let q = |v: &[f64; 3]| lift3(v, <Rational as Field>::from_f64);
        assert_eq!(cross3(&a, &b), [6.5, -10.0, 4.5]);
        let d = det3(&q(&a), &q(&b), &q(&c));
        assert_eq!(d, Rational::from_f64(det3(&a, &b, &c)).unwrap());
        // 6.5*0.25 + 10 + 9 = 20.625
        assert_eq!(d, Rational::from((165, 8)));
    }
}
