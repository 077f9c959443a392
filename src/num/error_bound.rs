//! Static error analysis of double-double formulas (the role of CGAL's
//! `Static_filter_error` and `compute_epsilon()`): evaluating a formula in
//! [`ErrorBound`] on inputs bounded by 1 yields, for its result, a bound `b` on the
//! magnitude of the computed value and a bound `e` on its absolute error, both in units
//! of the result's scale `M = Π m_g^{d_g}` (the group maxima of the inputs raised to the
//! formula's degree in each group; see `geom::filter`).
//!
//! The rules are the per-operation bounds documented in [`crate::num::dd`], with `h`,
//! `l` bounds on the two parts and `e` on the error:
//! * input: `h = 1`, `l = 0`, `e = 0`;
//! * `a ± c`: `h = (1+u)(h_a + h_c)`, `l = (1+u)²(u h + l_a + l_c)`,
//!   `e = e_a + e_c + u(1+u)(u h + l_a) + u l`;
//! * `a · c`: `h = (1+u) h_a h_c`, `e' = (1+u)²(u h + h_a l_c)`, `l = (1+u)²(e' + l_a h_c)`,
//!   `e = (1+u)(e_a (h_c + l_c) + e_c (h_a + l_a)) + e_a e_c
//!        + u h_a l_c + u e' + u l_a h_c + u l + l_a l_c + 3u²`;
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
    /// Bound on `|l|` of the computed value.
    pub l: f64,
    /// Bound on `|exact − (h + l)|`.
    pub e: f64,
}

impl ErrorBound {
    /// An input: a double bounded by 1 in scaled units, exact.
    pub const INPUT: ErrorBound = ErrorBound {
        b: 1.0,
        l: 0.0,
        e: 0.0,
    };

    /// The componentwise maximum (the worst case of two ways to compute a value).
    pub fn max(self, o: ErrorBound) -> ErrorBound {
        ErrorBound {
            b: self.b.max(o.b),
            l: self.l.max(o.l),
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
        ErrorBound {
            b: 0.0,
            l: 0.0,
            e: 0.0,
        }
    }
    fn one() -> Self {
        ErrorBound::INPUT
    }
    fn plus(&self, c: &Self) -> Self {
        let g = 1.0 + 2.0 * U; // ≥ 1 + u (1 + u itself rounds to 1)
        let h = g * (self.b + c.b);
        let l = g * g * (U * h + self.l + c.l);
        ErrorBound {
            b: h,
            l,
            e: self.e + c.e + U * g * (U * h + self.l) + U * l,
        }
    }
    fn minus(&self, c: &Self) -> Self {
        self.plus(c)
    }
    fn times(&self, c: &Self) -> Self {
        let g = 1.0 + 2.0 * U; // ≥ 1 + u (1 + u itself rounds to 1)
        let h = g * self.b * c.b;
        let e1 = g * g * (U * h + self.b * c.l);
        let l = g * g * (e1 + self.l * c.b);
        let local =
            U * self.b * c.l + U * e1 + U * self.l * c.b + U * l + self.l * c.l + 3.0 * U * U;
        let e = g * (self.e * (c.b + c.l) + c.e * (self.b + self.l)) + self.e * c.e + local;
        ErrorBound { b: h, l, e }
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
        // each product of inputs: e' = u, l = u, error u·u + u·u + 3u² = 5u²;
        // the subtraction (h = 2, l = 2u·... = 4u): u(u·2 + u) + u·4u = 7u²: 5 + 5 + 7.
        assert!((c[0].e_in_u2() - 17.0).abs() < 1e-9);
        assert!((c[0].l / U - 4.0).abs() < 1e-9);
        let d = dot3(&c, &[i; 3]);
        assert!(d.b > 6.0 && d.b < 6.0 + 1e-12);
    }
}
