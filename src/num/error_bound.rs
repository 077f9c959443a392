//! Static error analysis of double-double formulas (the role of CGAL's
//! `Static_filter_error` and `compute_epsilon()`): evaluating a formula in
//! [`ErrorBound`] on inputs bounded by 1 yields, for its result, a bound `b` on the
//! magnitude of the computed value and a bound `e` on its absolute error, both in units
//! of the result's scale `M = Π m_g^{d_g}` (the group maxima of the inputs raised to the
//! formula's degree in each group; see `geom::filter`).
//!
//! The rules are the per-operation bounds documented in [`crate::num::dd`]:
//! * input: `b = 1`, `e = 0`;
//! * `a ± c`: `b = (1 + 5u)(b_a + b_c)`, `e = e_a + e_c + 5u²(b_a + b_c)`;
//! * `a · c`: `b = (1 + 6u) b_a b_c`,
//!   `e = (1+u)(e_a b_c + e_c b_a) + e_a e_c + 8u²(1 + 4u) b_a b_c + 3u²`;
//!
//! where the last `3u²` is the underflow term: a rounded product underflows by at most
//! `3η` absolutely; in scaled units that is `3η / M_node ≤ 3η·2^(100·deg) ≤ 3u²` because
//! every group maximum is clamped to at least 2⁻¹⁰⁰ and every formula here has degree
//! at most 9 (`100·9 + 106 ≤ 1074`).
//!
//! The filter constants of `geom/` are written as expressions in u (`k·u²`); their unit
//! tests re-derive them by running the formula through this type and checking the
//! written constant is at least the derived one.

use super::dd::U;
use super::ring::Ring;

/// Magnitude and error bounds of a double-double value, in units of its scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorBound {
    /// Bound on `|h|` of the computed value.
    pub b: f64,
    /// Bound on `|exact − (h + l)|`.
    pub e: f64,
}

impl ErrorBound {
    /// An input: a double bounded by 1 in scaled units, exact.
    pub const INPUT: ErrorBound = ErrorBound { b: 1.0, e: 0.0 };

    /// A derived input with the given bounds.
    pub fn new(b: f64, e: f64) -> Self {
        ErrorBound { b, e }
    }

    /// The componentwise maximum (the worst case of two ways to compute a value).
    pub fn max(self, o: ErrorBound) -> ErrorBound {
        ErrorBound {
            b: self.b.max(o.b),
            e: self.e.max(o.e),
        }
    }

    /// The error bound in units of u².
    pub fn e_in_u2(&self) -> f64 {
        self.e / (U * U)
    }
}

impl Ring for ErrorBound {
    fn zero() -> Self {
        ErrorBound { b: 0.0, e: 0.0 }
    }
    fn one() -> Self {
        ErrorBound { b: 1.0, e: 0.0 }
    }
    fn plus(&self, c: &Self) -> Self {
        let s = self.b + c.b;
        ErrorBound {
            b: (1.0 + 5.0 * U) * s,
            e: self.e + c.e + 5.0 * U * U * s,
        }
    }
    fn minus(&self, c: &Self) -> Self {
        self.plus(c)
    }
    fn times(&self, c: &Self) -> Self {
        let p = self.b * c.b;
        ErrorBound {
            b: (1.0 + 6.0 * U) * p,
            e: (1.0 + U) * (self.e * c.b + c.e * self.b)
                + self.e * c.e
                + 8.0 * U * U * (1.0 + 4.0 * U) * p
                + 3.0 * U * U,
        }
    }
    fn negate(&self) -> Self {
        *self
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::ring::{cross3, dot3};

    #[test]
    fn cross_product_bound_follows_the_rules() {
        let i = ErrorBound::INPUT;
        let c = cross3(&[i; 3], &[i; 3]);
        // each component: two products (8u² + 3u² each) and one subtraction
        // (5u²·(b1 + b2) with b ≈ 1): 22u² + 10u² = 32u² up to O(u³).
        assert!((c[0].e_in_u2() - 32.0).abs() < 1e-9);
        let d = dot3(&c, &[i; 3]);
        assert!(d.b > 6.0 && d.b < 6.0 + 1e-12);
    }
}
