//! Square-free factorisation by Yun's algorithm (Yun 1976; von zur Gathen & Gerhard,
//! *Modern Computer Algebra*, Alg. 14.21), exactly over the rationals.
//!
//! For a non-zero `f = lc·Π aᵢⁱ` with `aᵢ` monic, square-free and pairwise coprime,
//! `g = gcd(f, f')`, `b₁ = f/g`, `c₁ = f'/g`, `dᵢ = cᵢ − bᵢ'`, then
//! `aᵢ = gcd(bᵢ, dᵢ)`, `bᵢ₊₁ = bᵢ/aᵢ`, `cᵢ₊₁ = dᵢ/aᵢ`, until `bᵢ = 1`. Every division is
//! exact; the gcds are computed on primitive integer forms (pseudo-remainder sequences)
//! and made monic, so every quotient is the true one and no scaling can go astray.
//! A root of `aᵢ` is a root of `f` of multiplicity exactly `i`.

use super::int_poly::IntPoly;
use super::modular::proves_square_free;
use super::poly::Polynomial;

/// One factor of the square-free decomposition.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SquareFreeFactor {
    /// Monic, square-free, of positive degree, coprime to the other factors.
    pub factor: Polynomial,
    /// Every root of `factor` is a root of the input of exactly this multiplicity.
    pub multiplicity: u32,
}

/// The monic gcd of two rational polynomials (zero only if both are zero).
pub fn gcd(a: &Polynomial, b: &Polynomial) -> Polynomial {
    if a.is_zero() {
        return b.monic();
    }
    if b.is_zero() {
        return a.monic();
    }
    IntPoly::gcd(&IntPoly::from_polynomial(a), &IntPoly::from_polynomial(b))
        .to_polynomial()
        .monic()
}

/// `a / b` for a `b` that divides `a` exactly.
fn exact_quotient(a: &Polynomial, b: &Polynomial) -> Polynomial {
    match a.div_rem(b) {
        Some((q, r)) => {
            debug_assert!(r.is_zero(), "Yun: a division that should be exact is not");
            q
        }
        None => Polynomial::zero(),
    }
}

/// The square-free decomposition `f = lc·Π aᵢⁱ` (factors of degree ≥ 1 only, by
/// increasing multiplicity). Empty for constants and for the zero polynomial.
pub fn square_free_decomposition(f: &Polynomial) -> Vec<SquareFreeFactor> {
    let mut out = Vec::new();
    if f.degree().unwrap_or(0) == 0 {
        return out;
    }
    let f = f.monic();
    if proves_square_free(&IntPoly::from_polynomial(&f)) {
        return vec![SquareFreeFactor {
            factor: f,
            multiplicity: 1,
        }];
    }
    let df = f.derivative();
    let g = gcd(&f, &df);
    if g.degree() == Some(0) {
        // Already square-free: the common case, without the divisions below.
        return vec![SquareFreeFactor {
            factor: f,
            multiplicity: 1,
        }];
    }
    let mut b = exact_quotient(&f, &g);
    let mut c = exact_quotient(&df, &g);
    let mut d = &c - &b.derivative();
    let mut i = 1u32;
    while b.degree().unwrap_or(0) > 0 {
        let a = gcd(&b, &d);
        if a.degree().unwrap_or(0) > 0 {
            out.push(SquareFreeFactor {
                factor: a.clone(),
                multiplicity: i,
            });
        }
        b = exact_quotient(&b, &a);
        c = exact_quotient(&d, &a);
        d = &c - &b.derivative();
        i += 1;
    }
    out
}

/// The square-free part `f / gcd(f, f')` (monic), whose roots are the distinct roots
/// of `f`.
pub fn square_free_part(f: &Polynomial) -> Polynomial {
    if f.degree().unwrap_or(0) == 0 {
        return Polynomial::constant(rug::Rational::from(1));
    }
    let g = gcd(f, &f.derivative());
    exact_quotient(&f.monic(), &g)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;

    #[test]
    fn yun_gives_multiplicities() {
        let r = |n: i64, d: i64| Rational::from((n, d));
        let f = Polynomial::from_roots(&[(r(1, 1), 2), (r(3, 1), 1), (r(-1, 2), 3), (r(5, 7), 3)])
            .scale(&r(-6, 1));
        let sf = square_free_decomposition(&f);
        assert_eq!(sf.len(), 3);
        assert_eq!(sf[0].multiplicity, 1);
        assert_eq!(sf[0].factor, Polynomial::from_roots(&[(r(3, 1), 1)]));
        assert_eq!(sf[1].multiplicity, 2);
        assert_eq!(sf[1].factor, Polynomial::from_roots(&[(r(1, 1), 1)]));
        assert_eq!(sf[2].multiplicity, 3);
        assert_eq!(
            sf[2].factor,
            Polynomial::from_roots(&[(r(-1, 2), 1), (r(5, 7), 1)])
        );
        assert_eq!(
            square_free_part(&f),
            Polynomial::from_roots(&[(r(1, 1), 1), (r(3, 1), 1), (r(-1, 2), 1), (r(5, 7), 1)])
        );
    }
}
