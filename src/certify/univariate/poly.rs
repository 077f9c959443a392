//! Dense univariate polynomials with exact rational coefficients: the input type of the
//! exact root finder and the ring the algebraic operations (`ops::algebraic`) build their
//! equations in. Every operation is exact; nothing is rounded.

use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

use rug::Rational;

use crate::error::GeomError;
use crate::num::parse::rational_from_f64;
use crate::num::MpfrInterval;

/// `Σ cᵢ xⁱ` with exact rational coefficients, lowest degree first. The stored vector
/// has no trailing zeros, so the zero polynomial has no coefficients.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Polynomial {
    coeffs: Vec<Rational>,
}

impl Polynomial {
    /// The zero polynomial.
    pub fn zero() -> Polynomial {
        Polynomial { coeffs: Vec::new() }
    }

    /// The constant `c`.
    pub fn constant(c: Rational) -> Polynomial {
        Polynomial::from_coeffs(vec![c])
    }

    /// The polynomial `x`.
    pub fn x() -> Polynomial {
        Polynomial::from_coeffs(vec![Rational::new(), Rational::from(1)])
    }

    /// `Σ coeffs[i] xⁱ` (trailing zeros are dropped).
    pub fn from_coeffs(mut coeffs: Vec<Rational>) -> Polynomial {
        while coeffs.last().is_some_and(|c| c.cmp0() == Ordering::Equal) {
            coeffs.pop();
        }
        Polynomial { coeffs }
    }

    /// Integer coefficients, lowest degree first.
    pub fn from_i64s(coeffs: &[i64]) -> Polynomial {
        Polynomial::from_coeffs(coeffs.iter().map(|&c| Rational::from(c)).collect())
    }

    /// The exact values of doubles, lowest degree first; NaN and infinities are rejected
    /// naming `field[i]`.
    pub fn from_f64s(field: &str, coeffs: &[f64]) -> Result<Polynomial, GeomError> {
        let exact = coeffs
            .iter()
            .enumerate()
            .map(|(i, &c)| rational_from_f64(&format!("{field}[{i}]"), c))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Polynomial::from_coeffs(exact))
    }

    /// `Π (x − rᵢ)^{mᵢ}`: a monic polynomial with the given roots and multiplicities.
    pub fn from_roots(roots: &[(Rational, u32)]) -> Polynomial {
        let mut p = Polynomial::constant(Rational::from(1));
        for (r, m) in roots {
            let factor = Polynomial::from_coeffs(vec![Rational::from(-r), Rational::from(1)]);
            for _ in 0..*m {
                p = &p * &factor;
            }
        }
        p
    }

    /// The coefficients, lowest degree first (empty for the zero polynomial).
    pub fn coeffs(&self) -> &[Rational] {
        &self.coeffs
    }

    /// The coefficient of `xⁱ` (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> Rational {
        self.coeffs.get(i).cloned().unwrap_or_default()
    }

    /// The degree; `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// The leading coefficient; `None` for the zero polynomial.
    pub fn leading(&self) -> Option<&Rational> {
        self.coeffs.last()
    }

    /// The exact value at `x` (Horner).
    pub fn eval(&self, x: &Rational) -> Rational {
        let mut acc = Rational::new();
        for c in self.coeffs.iter().rev() {
            acc *= x;
            acc += c;
        }
        acc
    }

    /// An enclosure of the values over `x` at `bits` of precision: Horner's scheme in
    /// MPFR interval arithmetic, each coefficient enclosed outward
    /// ([`MpfrInterval::from_rational`]) and every operation rounded outward, so the
    /// result holds `p(ξ)` for every `ξ ∈ x`.
    pub fn enclose(&self, x: &MpfrInterval, bits: u32) -> MpfrInterval {
        let mut acc = MpfrInterval::from_rational(&Rational::new(), bits);
        for c in self.coeffs.iter().rev() {
            acc = acc.mul(x).add(&MpfrInterval::from_rational(c, bits));
        }
        acc
    }

    /// The derivative.
    pub fn derivative(&self) -> Polynomial {
        Polynomial::from_coeffs(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| Rational::from(c * i as u64))
                .collect(),
        )
    }

    /// `c · self`.
    pub fn scale(&self, c: &Rational) -> Polynomial {
        Polynomial::from_coeffs(self.coeffs.iter().map(|a| Rational::from(a * c)).collect())
    }

    /// `selfⁿ`.
    pub fn pow(&self, n: u32) -> Polynomial {
        let mut p = Polynomial::constant(Rational::from(1));
        for _ in 0..n {
            p = &p * self;
        }
        p
    }

    /// `self(a + b·x)`: substitution of an affine map (used to move a line parameter).
    pub fn compose_affine(&self, a: &Rational, b: &Rational) -> Polynomial {
        let inner = Polynomial::from_coeffs(vec![a.clone(), b.clone()]);
        let mut acc = Polynomial::zero();
        for c in self.coeffs.iter().rev() {
            acc = &(&acc * &inner) + &Polynomial::constant(c.clone());
        }
        acc
    }

    /// Euclidean division `self = q·d + r`, `deg r < deg d`; `None` when `d` is zero.
    pub fn div_rem(&self, d: &Polynomial) -> Option<(Polynomial, Polynomial)> {
        let dd = d.degree()?;
        let lead = d.leading()?;
        let mut r = self.coeffs.clone();
        let n = r.len();
        if n <= dd {
            return Some((Polynomial::zero(), self.clone()));
        }
        let mut q = vec![Rational::new(); n - dd];
        for k in (0..n - dd).rev() {
            let f = Rational::from(&r[k + dd] / lead);
            if f.cmp0() != Ordering::Equal {
                for (j, dj) in d.coeffs.iter().enumerate() {
                    r[k + j] -= Rational::from(&f * dj);
                }
            }
            q[k] = f;
        }
        r.truncate(dd);
        Some((Polynomial::from_coeffs(q), Polynomial::from_coeffs(r)))
    }

    /// The same polynomial divided by its leading coefficient (zero stays zero).
    pub fn monic(&self) -> Polynomial {
        match self.leading() {
            Some(l) => self.scale(&Rational::from(l.recip_ref())),
            None => Polynomial::zero(),
        }
    }

    /// The largest bit length of a numerator or denominator of a coefficient: the
    /// `bits` a certificate built on this polynomial reports.
    pub fn max_bits(&self) -> u32 {
        self.coeffs
            .iter()
            .map(|c| {
                c.numer()
                    .significant_bits()
                    .max(c.denom().significant_bits())
            })
            .max()
            .unwrap_or(0)
    }
}

impl Add for &Polynomial {
    type Output = Polynomial;
    fn add(self, rhs: &Polynomial) -> Polynomial {
        let n = self.coeffs.len().max(rhs.coeffs.len());
        Polynomial::from_coeffs(
            (0..n)
                .map(|i| match (self.coeffs.get(i), rhs.coeffs.get(i)) {
                    (Some(a), Some(b)) => Rational::from(a + b),
                    (Some(a), None) | (None, Some(a)) => a.clone(),
                    (None, None) => Rational::new(),
                })
                .collect(),
        )
    }
}

impl Neg for &Polynomial {
    type Output = Polynomial;
    fn neg(self) -> Polynomial {
        Polynomial::from_coeffs(self.coeffs.iter().map(|c| Rational::from(-c)).collect())
    }
}

impl Sub for &Polynomial {
    type Output = Polynomial;
    fn sub(self, rhs: &Polynomial) -> Polynomial {
        self + &(-rhs)
    }
}

impl Mul for &Polynomial {
    type Output = Polynomial;
    fn mul(self, rhs: &Polynomial) -> Polynomial {
        if self.is_zero() || rhs.is_zero() {
            return Polynomial::zero();
        }
        let mut out = vec![Rational::new(); self.coeffs.len() + rhs.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            if a.cmp0() == Ordering::Equal {
                continue;
            }
            for (j, b) in rhs.coeffs.iter().enumerate() {
                out[i + j] += Rational::from(a * b);
            }
        }
        Polynomial::from_coeffs(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    #[test]
    fn ring_operations_are_exact() {
        let p = Polynomial::from_roots(&[(q(1, 3), 2), (q(-2, 1), 1)]);
        // (x − 1/3)²(x + 2) = x³ + (4/3)x² − (11/9)x + 2/9
        assert_eq!(p.coeffs(), &[q(2, 9), q(-11, 9), q(4, 3), q(1, 1)][..]);
        assert_eq!(p.eval(&q(1, 3)), 0);
        assert_eq!(p.derivative().eval(&q(1, 3)), 0);
        let (quo, rem) = p.div_rem(&Polynomial::from_roots(&[(q(1, 3), 1)])).unwrap();
        assert!(rem.is_zero());
        assert_eq!(quo, Polynomial::from_roots(&[(q(1, 3), 1), (q(-2, 1), 1)]));
        assert_eq!((&p - &p).degree(), None);
        // p(1 + 2x) at x = −2/3 is p(−1/3)
        let c = p.compose_affine(&q(1, 1), &q(2, 1));
        assert_eq!(c.eval(&q(-2, 3)), p.eval(&q(-1, 3)));
    }
}
