//! Exact real roots of univariate polynomials with rational coefficients
//! (docs/CERTIFICATES.md level `exact`: algebraic cases are decided by exact polynomial
//! discriminants, resultants and Sturm sequences; singular roots, issue 4 (a)).
//!
//! Pipeline, every step exact (`rug::Integer` / `rug::Rational`):
//!
//! 1. square-free decomposition by Yun's algorithm ([`square_free_decomposition`]):
//!    `f = lc·Π aᵢⁱ`; a root of `aᵢ` has multiplicity exactly `i`, so a double root is
//!    reported with multiplicity 2 however close two simple roots of another input are;
//! 2. isolation of the distinct roots (the roots of `Π aᵢ`) by Sturm bisection, with
//!    exact end point handling (`isolate`);
//! 3. for each root, the factor `aᵢ` that vanishes there (the one whose signs differ at
//!    the bracket's ends), an exact rationality decision, and the correctly rounded
//!    double (`root`);
//! 4. on request, refinement of the interval to any width (bisection and quadratic
//!    interval refinement, `bracket`).
//!
//! Tests modulo small primes (`modular`) may prove square-freeness or the absence of
//! rational roots first and skip exact work; they never decide anything alone.
//!
//! Entry points: [`real_roots`], [`real_roots_in`], [`count_real_roots`],
//! [`count_real_roots_in`]. The zero polynomial is rejected (every number is a root).

mod bracket;
mod int_poly;
mod isolate;
mod modular;
mod poly;
mod root;
mod squarefree;
mod sturm;

use std::cmp::Ordering;

use rug::Rational;

use crate::error::GeomError;
use bracket::Bracket;
use int_poly::{At, IntPoly};
use isolate::{isolate, Isolated};
use sturm::Sturm;

pub use poly::Polynomial;
pub use root::RealRoot;
pub use squarefree::{gcd, square_free_decomposition, square_free_part, SquareFreeFactor};

/// How many real roots lie in a closed interval.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RootCount {
    /// Distinct roots.
    pub distinct: usize,
    /// Roots counted with their multiplicities.
    pub with_multiplicity: usize,
}

fn reject_zero(p: &Polynomial) -> Result<(), GeomError> {
    if p.is_zero() {
        return Err(GeomError::InvalidValue {
            field: "poly".into(),
            reason: "the zero polynomial vanishes everywhere: its roots are not isolated".into(),
        });
    }
    Ok(())
}

fn check_range(lo: &Rational, hi: &Rational) -> Result<(), GeomError> {
    if lo > hi {
        return Err(GeomError::EmptyDomain {
            field: "interval".into(),
            lo: lo.to_string(),
            hi: hi.to_string(),
        });
    }
    Ok(())
}

/// The square-free factors as primitive integer polynomials with their multiplicities.
fn integer_factors(p: &Polynomial) -> Vec<(IntPoly, u32)> {
    square_free_decomposition(p)
        .into_iter()
        .map(|f| {
            (
                IntPoly::from_polynomial(&f.factor).normalized(),
                f.multiplicity,
            )
        })
        .collect()
}

/// For each factor: proven to have no rational root (a cheap modular test; degrees 1
/// and 2 are decided in closed form later anyway).
fn irrational_flags(factors: &[(IntPoly, u32)]) -> Vec<bool> {
    factors
        .iter()
        .map(|(g, _)| g.degree() >= 3 && modular::proves_no_rational_root(g))
        .collect()
}

/// All real roots of a non-zero polynomial, increasing, each with its multiplicity and
/// correctly rounded double. A non-zero constant has none.
pub fn real_roots(p: &Polynomial) -> Result<Vec<RealRoot>, GeomError> {
    reject_zero(p)?;
    Ok(roots_between(p, None, None))
}

/// The real roots in the closed interval `[lo, hi]` (roots at the ends included,
/// exactly).
pub fn real_roots_in(
    p: &Polynomial,
    lo: &Rational,
    hi: &Rational,
) -> Result<Vec<RealRoot>, GeomError> {
    reject_zero(p)?;
    check_range(lo, hi)?;
    Ok(roots_between(p, Some(lo), Some(hi)))
}

fn roots_between(p: &Polynomial, lo: Option<&Rational>, hi: Option<&Rational>) -> Vec<RealRoot> {
    let factors = integer_factors(p);
    if factors.is_empty() {
        return Vec::new();
    }
    let product = factors
        .iter()
        .fold(Polynomial::constant(Rational::from(1)), |acc, (g, _)| {
            &acc * &g.to_polynomial()
        });
    let sturm = Sturm::new(&IntPoly::from_polynomial(&product));
    let irrational = irrational_flags(&factors);
    let mut out = Vec::new();
    for iso in isolate(&sturm, lo, hi) {
        let root = match iso {
            Isolated::Exact(x) => factors
                .iter()
                .find(|(g, _)| g.sign_at(At::Rational(&x)) == Ordering::Equal)
                .map(|(g, m)| RealRoot::new_exact(x, *m, g.clone())),
            Isolated::Bracket(b) => factors.iter().zip(&irrational).find_map(|((g, m), &irr)| {
                let sl = g.sign_at(At::Dyadic(&b.lo, b.e));
                let sh = g.sign_at(At::Dyadic(&b.hi, b.e));
                // g divides the square-free product, whose ends are not roots: g has a
                // root in the bracket (then exactly one, simple) iff its signs differ.
                (sl != Ordering::Equal && sh != Ordering::Equal && sl != sh).then(|| {
                    RealRoot::new_isolated(
                        Bracket::new(b.lo.clone(), b.hi.clone(), b.e, sl),
                        *m,
                        g.clone(),
                        irr,
                    )
                })
            }),
        };
        debug_assert!(
            root.is_some(),
            "every root of the product is a root of a factor"
        );
        if let Some(root) = root {
            let inside = lo.is_none_or(|l| root.compare(l) != Ordering::Less)
                && hi.is_none_or(|h| root.compare(h) != Ordering::Greater);
            if inside {
                out.push(root);
            }
        }
    }
    out
}

/// The number of real roots of a non-zero polynomial.
pub fn count_real_roots(p: &Polynomial) -> Result<RootCount, GeomError> {
    reject_zero(p)?;
    Ok(count_between(p, None, None))
}

/// The number of real roots in the closed interval `[lo, hi]`, by Sturm sequences of
/// the square-free factors (no isolation): `#[a, b] = V(a) − V(b) + [g(a) = 0]`.
pub fn count_real_roots_in(
    p: &Polynomial,
    lo: &Rational,
    hi: &Rational,
) -> Result<RootCount, GeomError> {
    reject_zero(p)?;
    check_range(lo, hi)?;
    Ok(count_between(p, Some(lo), Some(hi)))
}

fn count_between(p: &Polynomial, lo: Option<&Rational>, hi: Option<&Rational>) -> RootCount {
    let mut count = RootCount {
        distinct: 0,
        with_multiplicity: 0,
    };
    for (g, m) in integer_factors(p) {
        let sturm = Sturm::new(&g);
        let a = lo.map_or(At::NegInf, At::Rational);
        let b = hi.map_or(At::PosInf, At::Rational);
        let at_lo = lo.is_some_and(|l| g.sign_at(At::Rational(l)) == Ordering::Equal);
        let n = sturm.count_half_open(a, b) + usize::from(at_lo);
        count.distinct += n;
        count.with_multiplicity += n * m as usize;
    }
    count
}
