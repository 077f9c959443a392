//! The implicit conic of the plane (docs/FORMAT.md `conic2`; OPERATIONS.md §1.7):
//! `F(x, y) = a x² + b xy + c y² + d x + e y + f`, i.e. `a₁₁ = a`, `a₁₂ = b/2`,
//! `a₂₂ = c`, `a₁₃ = d/2`, `a₂₃ = e/2`, `a₃₃ = f` in the matrix form of (1.19).
//! Implements [`Implicit<2>`] (value, gradient, Hessian, generic over [`Real`]: each a
//! polynomial, so interval arguments give enclosures) and the exact classification by
//! the invariants (1.19), decided in rationals.

use super::implicit::{Implicit, ImplicitJet};
use crate::error::{require_finite_all, GeomError};
use crate::num::Real;
use rug::Rational;
use std::cmp::Ordering;

/// `a x² + b xy + c y² + d x + e y + f = 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct Conic2 {
    coeffs: [f64; 6],
}

/// The type of a conic by the signs of its invariants (1.19), decided exactly.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConicKind {
    /// `δ > 0`; `imaginary` when `IΔ > 0` (no real points).
    Elliptic { imaginary: bool },
    /// `δ = 0`.
    Parabolic,
    /// `δ < 0`.
    Hyperbolic,
}

impl Conic2 {
    /// Errors: `non_finite` (`coeffs[i]`), `invalid_value` (`coeffs`) when `a … e` are
    /// all zero (no curve).
    pub fn new(coeffs: [f64; 6]) -> Result<Conic2, GeomError> {
        require_finite_all("coeffs", &coeffs)?;
        if coeffs[..5].iter().all(|&x| x == 0.0) {
            return Err(GeomError::InvalidValue {
                field: "coeffs".into(),
                reason: "a, b, c, d and e are all zero: the equation defines no curve".into(),
            });
        }
        Ok(Conic2 { coeffs })
    }

    /// `[a, b, c, d, e, f]` as given.
    pub fn coeffs(&self) -> [f64; 6] {
        self.coeffs
    }

    /// The invariants `(I, δ, Δ)` of (1.19) in the number system of `like`.
    pub fn invariants<T: Real>(&self, like: &T) -> (T, T, T) {
        let [a, b, c, d, e, f] = self.coeffs.map(|x| like.lift(x));
        let half = like.lift(0.5);
        let (a12, a13, a23) = (b * &half, d * &half, e * &half);
        let i = a.clone() + &c;
        let delta = a.clone() * &c - a12.sqr();
        // Δ = det [[a, a12, a13], [a12, c, a23], [a13, a23, f]], expanded along row 1.
        let big = a.clone() * (c.clone() * &f - a23.sqr())
            - a12.clone() * (a12.clone() * &f - a23.clone() * &a13)
            + a13.clone() * (a12 * &a23 - c * &a13);
        (i, delta, big)
    }

    /// `true` when `Δ = 0` exactly (a degenerate conic: a point, lines, or nothing).
    pub fn is_degenerate(&self) -> bool {
        self.exact_invariants().2.cmp0() == Ordering::Equal
    }

    /// The type by (1.19), exact: `δ` and `IΔ` evaluated in rationals.
    pub fn kind(&self) -> ConicKind {
        let (i, delta, big) = self.exact_invariants();
        match delta.cmp0() {
            Ordering::Greater => ConicKind::Elliptic {
                imaginary: (i * big).cmp0() == Ordering::Greater,
            },
            Ordering::Equal => ConicKind::Parabolic,
            Ordering::Less => ConicKind::Hyperbolic,
        }
    }

    fn exact_invariants(&self) -> (Rational, Rational, Rational) {
        let [a, b, c, d, e, f] = self
            .coeffs
            .map(|x| Rational::from_f64(x).unwrap_or_default());
        let (a12, a13, a23) = (b / 2u32, d / 2u32, e / 2u32);
        let i = a.clone() + &c;
        let delta = a.clone() * &c - a12.clone() * &a12;
        let big = a * (c.clone() * &f - a23.clone() * &a23)
            - a12.clone() * (a12.clone() * &f - a23.clone() * &a13)
            + a13.clone() * (a12 * &a23 - c * &a13);
        (i, delta, big)
    }
}

impl Implicit<2> for Conic2 {
    /// `F`, `∇F = (2a x + b y + d, b x + 2c y + e)`, Hessian `[[2a, b], [b, 2c]]`.
    fn implicit_jet<T: Real>(&self, x: &[T; 2], order: usize) -> ImplicitJet<T, 2> {
        let [a, b, c, d, e, f] = self.coeffs.map(|v| x[0].lift(v));
        let (px, py) = (&x[0], &x[1]);
        let value = a.clone() * px.sqr()
            + b.clone() * px * py
            + c.clone() * py.sqr()
            + d.clone() * px
            + e.clone() * py
            + f;
        let two = x[0].lift(2.0);
        let gradient = (order >= 1).then(|| {
            [
                two.clone() * &a * px + b.clone() * py + &d,
                b.clone() * px + two.clone() * &c * py + &e,
            ]
        });
        let hessian = (order >= 2).then(|| [[two.clone() * &a, b.clone()], [b.clone(), two * &c]]);
        ImplicitJet {
            value,
            gradient,
            hessian,
        }
    }
}
