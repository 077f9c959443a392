//! Integer polynomials, kept up to a positive constant factor: the working form of the
//! root finder. Multiplying a polynomial by a positive constant changes neither its roots
//! nor its signs, so denominators are cleared and contents divided out freely, which
//! keeps the numbers small (primitive pseudo-remainder sequences, Collins/Brown).
//!
//! Signs at a point are computed exactly from homogeneous integer forms:
//! `p(m/2ᵉ)·2^{e·n} = Σ cᵢ mⁱ 2^{e(n−i)}` for dyadic points and
//! `p(a/b)·bⁿ = Σ cᵢ aⁱ bⁿ⁻ⁱ` (`b > 0`) for rational ones.

use std::cmp::Ordering;

use rug::{Assign, Integer, Rational};

use super::poly::Polynomial;

/// `Σ c[i] xⁱ` over the integers; no trailing zeros (the zero polynomial is empty).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct IntPoly {
    pub(crate) c: Vec<Integer>,
}

/// A point at which a sign is asked for.
#[derive(Debug, Clone, Copy)]
pub(crate) enum At<'a> {
    NegInf,
    PosInf,
    /// `m / 2ᵉ`.
    Dyadic(&'a Integer, u32),
    Rational(&'a Rational),
}

impl IntPoly {
    fn trimmed(mut c: Vec<Integer>) -> IntPoly {
        while c.last().is_some_and(|x| x.cmp0() == Ordering::Equal) {
            c.pop();
        }
        IntPoly { c }
    }

    /// A positive multiple of `p` with coprime integer coefficients (sign kept).
    pub(crate) fn from_polynomial(p: &Polynomial) -> IntPoly {
        let mut l = Integer::from(1);
        for q in p.coeffs() {
            l = l.lcm(q.denom());
        }
        IntPoly::trimmed(
            p.coeffs()
                .iter()
                .map(|q| q.numer() * Integer::from(&l / q.denom()))
                .collect(),
        )
        .primitive()
    }

    /// The same polynomial over the rationals.
    pub(crate) fn to_polynomial(&self) -> Polynomial {
        Polynomial::from_coeffs(self.c.iter().map(|x| Rational::from(x.clone())).collect())
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    /// Degree (0 for constants and for zero).
    pub(crate) fn degree(&self) -> usize {
        self.c.len().saturating_sub(1)
    }

    /// The leading coefficient (zero for the zero polynomial).
    pub(crate) fn lc(&self) -> Integer {
        self.c.last().cloned().unwrap_or_default()
    }

    /// Divide by the positive content (the gcd of the coefficients).
    pub(crate) fn primitive(self) -> IntPoly {
        let mut g = Integer::new();
        for x in &self.c {
            g = g.gcd(x);
            if g == 1 {
                return self;
            }
        }
        if g.cmp0() == Ordering::Equal {
            return self;
        }
        IntPoly {
            c: self.c.into_iter().map(|x| x.div_exact(&g)).collect(),
        }
    }

    /// The primitive polynomial with a positive leading coefficient.
    pub(crate) fn normalized(self) -> IntPoly {
        let p = self.primitive();
        if p.lc().cmp0() == Ordering::Less {
            IntPoly {
                c: p.c.into_iter().map(|x| -x).collect(),
            }
        } else {
            p
        }
    }

    /// A positive multiple of the derivative.
    pub(crate) fn derivative(&self) -> IntPoly {
        IntPoly::trimmed(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, x)| Integer::from(x * i as u64))
                .collect(),
        )
        .primitive()
    }

    /// The pseudo-remainder `lc(b)^{δ+1}·a mod b`, `δ = deg a − deg b` (`b ≠ 0`).
    /// Returns it with the sign of `lc(b)^{δ+1}`, so that the true remainder is a
    /// positive multiple of the result when that sign is positive.
    pub(crate) fn pseudo_rem(a: &IntPoly, b: &IntPoly) -> (IntPoly, Ordering) {
        let db = b.degree();
        let lb = b.lc();
        if a.c.len() < b.c.len() {
            return (a.clone(), Ordering::Greater);
        }
        let delta = a.degree() - db;
        let mut r = a.c.clone();
        for k in (0..=delta).rev() {
            // r ← lb·r − r[k+db]·x^k·b : eliminates the coefficient of x^{k+db}.
            let top = r[k + db].clone();
            for x in r.iter_mut() {
                *x *= &lb;
            }
            if top.cmp0() != Ordering::Equal {
                for (j, bj) in b.c.iter().enumerate() {
                    r[k + j] -= Integer::from(&top * bj);
                }
            }
        }
        r.truncate(db);
        let sign = if lb.cmp0() == Ordering::Less && (delta + 1) % 2 == 1 {
            Ordering::Less
        } else {
            Ordering::Greater
        };
        (IntPoly::trimmed(r).primitive(), sign)
    }

    /// The gcd (primitive, positive leading coefficient) by the primitive
    /// pseudo-remainder sequence.
    pub(crate) fn gcd(a: &IntPoly, b: &IntPoly) -> IntPoly {
        let (mut a, mut b) = if a.c.len() >= b.c.len() {
            (a.clone().primitive(), b.clone().primitive())
        } else {
            (b.clone().primitive(), a.clone().primitive())
        };
        while !b.is_zero() {
            let (r, _) = IntPoly::pseudo_rem(&a, &b);
            a = b;
            b = r;
        }
        a.normalized()
    }

    /// `p(m/2ᵉ)·2^{e·n}`, `n = deg p`: the sign of `p` at `m/2ᵉ` and, between two points
    /// of the same `e`, the ratio of the values.
    pub(crate) fn eval_dyadic(&self, m: &Integer, e: u32) -> Integer {
        let n = self.degree();
        let mut acc = Integer::with_capacity(
            (self
                .c
                .iter()
                .map(|c| c.significant_bits())
                .max()
                .unwrap_or(0) as usize)
                + (n + 1) * (m.significant_bits().max(e) as usize + 1),
        );
        let mut term = Integer::new();
        for (i, ci) in self.c.iter().enumerate().rev() {
            acc *= m;
            if ci.cmp0() != Ordering::Equal {
                term.assign(ci << (e as usize * (n - i)) as u32);
                acc += &term;
            }
        }
        acc
    }

    /// `p(a/b)·bⁿ` with `b > 0` the reduced denominator of `x`.
    pub(crate) fn eval_rational(&self, x: &Rational) -> Integer {
        let (a, b) = (x.numer(), x.denom());
        let mut acc = Integer::new();
        let mut bpow = Integer::from(1);
        // Horner in a; the coefficient of aⁱ carries b^{n−i}.
        for ci in self.c.iter().rev() {
            acc *= a;
            acc += Integer::from(ci * &bpow);
            bpow *= b;
        }
        acc
    }

    /// The exact sign of `p` at a point (±∞: the sign of the leading term).
    pub(crate) fn sign_at(&self, at: At<'_>) -> Ordering {
        match at {
            At::PosInf => self.lc().cmp0(),
            At::NegInf => {
                let s = self.lc().cmp0();
                if self.degree() % 2 == 1 {
                    s.reverse()
                } else {
                    s
                }
            }
            At::Dyadic(m, e) => self.eval_dyadic(m, e).cmp0(),
            At::Rational(x) => self.eval_rational(x).cmp0(),
        }
    }
}

/// For the tests: the polynomial `Σ c_i xⁱ` of small integer coefficients.
#[cfg(test)]
pub(crate) fn small_poly(c: &[i64]) -> IntPoly {
    IntPoly::trimmed(c.iter().map(|&x| Integer::from(x)).collect())
}

#[cfg(test)]
mod tests {
    use super::small_poly as ip;
    use super::*;

    #[test]
    fn gcd_and_pseudo_remainders() {
        // (x−1)²(x+2) and (x−1)(x−3): gcd x − 1
        let a = ip(&[2, -3, 0, 1]);
        let b = ip(&[3, -4, 1]);
        assert_eq!(IntPoly::gcd(&a, &b), ip(&[-1, 1]));
        // 2x² + 1 mod (−3x + 1): lc^{2} = 9 > 0, 9(2x²+1) = (−6x − 2)(−3x + 1) + 11
        let (r, s) = IntPoly::pseudo_rem(&ip(&[1, 0, 2]), &ip(&[1, -3]));
        assert_eq!((r, s), (ip(&[1]), Ordering::Greater));
        let (_, s) = IntPoly::pseudo_rem(&ip(&[1, 0, 0, 2]), &ip(&[1, -3]));
        assert_eq!(s, Ordering::Less);
    }

    #[test]
    fn exact_signs() {
        let p = ip(&[-2, 0, 1]); // x² − 2
        assert_eq!(
            p.sign_at(At::Dyadic(&Integer::from(182), 7)),
            Ordering::Greater
        ); // 1.421875² > 2
        assert_eq!(
            p.sign_at(At::Dyadic(&Integer::from(181), 7)),
            Ordering::Less
        ); // 1.4140625² < 2
        assert_eq!(p.sign_at(At::Dyadic(&Integer::from(45), 5)), Ordering::Less); // 1.40625
        assert_eq!(
            p.sign_at(At::Rational(&Rational::from((3, 2)))),
            Ordering::Greater
        );
        assert_eq!(p.eval_rational(&Rational::from((3, 2))), 1); // (9/4 − 2)·4
        assert_eq!(ip(&[0, 1]).sign_at(At::NegInf), Ordering::Less);
        assert_eq!(
            IntPoly::from_polynomial(&Polynomial::from_coeffs(vec![
                Rational::from((1, 2)),
                Rational::from((-3, 4))
            ])),
            ip(&[2, -3])
        );
    }
}
