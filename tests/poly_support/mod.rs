//! Exact univariate polynomials over the rationals (rug), for counting real roots
//! independently of the code under test: Sturm sequences (distinct real roots) and
//! gcds with the derivatives (multiplicities). Coefficients lowest degree first.
#![allow(dead_code)]

use rug::Rational;

/// A polynomial, lowest degree first, without trailing zeros (the zero polynomial is
/// empty).
#[derive(Debug, Clone, PartialEq)]
pub struct Poly(pub Vec<Rational>);

impl Poly {
    pub fn new(mut c: Vec<Rational>) -> Self {
        while c.last().is_some_and(|x| *x == 0) {
            c.pop();
        }
        Poly(c)
    }
    pub fn constant(c: Rational) -> Self {
        Poly::new(vec![c])
    }
    /// `a + b·t`.
    pub fn linear(a: Rational, b: Rational) -> Self {
        Poly::new(vec![a, b])
    }
    pub fn is_zero(&self) -> bool {
        self.0.is_empty()
    }
    /// The degree (`None` for zero).
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }
    pub fn add(&self, o: &Poly) -> Poly {
        let n = self.0.len().max(o.0.len());
        Poly::new(
            (0..n)
                .map(|i| {
                    let a = self.0.get(i).cloned().unwrap_or_default();
                    a + o.0.get(i).cloned().unwrap_or_default()
                })
                .collect(),
        )
    }
    pub fn scale(&self, k: &Rational) -> Poly {
        Poly::new(self.0.iter().map(|c| Rational::from(c * k)).collect())
    }
    pub fn sub(&self, o: &Poly) -> Poly {
        self.add(&o.scale(&Rational::from(-1)))
    }
    pub fn mul(&self, o: &Poly) -> Poly {
        if self.is_zero() || o.is_zero() {
            return Poly(Vec::new());
        }
        let mut c = vec![Rational::new(); self.0.len() + o.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            for (j, b) in o.0.iter().enumerate() {
                c[i + j] += Rational::from(a * b);
            }
        }
        Poly::new(c)
    }
    pub fn derivative(&self) -> Poly {
        Poly::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| Rational::from(c * i as u32))
                .collect(),
        )
    }
    /// The remainder of `self` divided by `d` (nonzero).
    pub fn rem(&self, d: &Poly) -> Poly {
        let dd = d.degree().expect("division by zero");
        let lead = d.0[dd].clone();
        let mut r = self.0.clone();
        while r.len() > dd {
            let k = r.len() - 1;
            let q = Rational::from(&r[k] / &lead);
            for (i, c) in d.0.iter().enumerate() {
                r[k - dd + i] -= Rational::from(&q * c);
            }
            r.pop();
            while r.last().is_some_and(|x| *x == 0) {
                r.pop();
            }
        }
        Poly::new(r)
    }
    pub fn gcd(&self, o: &Poly) -> Poly {
        let (mut a, mut b) = (self.clone(), o.clone());
        while !b.is_zero() {
            let r = a.rem(&b);
            a = b;
            b = r;
        }
        a
    }
    fn sign_at_infinity(&self, negative: bool) -> i32 {
        match self.degree() {
            None => 0,
            Some(d) => {
                let s = self.0[d].cmp0() as i32;
                if negative && d % 2 == 1 {
                    -s
                } else {
                    s
                }
            }
        }
    }
    /// The number of distinct real roots (Sturm's theorem; valid for any nonzero
    /// polynomial, square-free or not).
    pub fn real_roots(&self) -> usize {
        assert!(!self.is_zero(), "the zero polynomial");
        let mut seq = vec![self.clone(), self.derivative()];
        while !seq.last().expect("nonempty").is_zero() {
            let n = seq.len();
            let r = seq[n - 2].rem(&seq[n - 1]).scale(&Rational::from(-1));
            seq.push(r);
        }
        seq.pop();
        let changes = |neg: bool| {
            let signs: Vec<i32> = seq
                .iter()
                .map(|p| p.sign_at_infinity(neg))
                .filter(|&s| s != 0)
                .collect();
            signs.windows(2).filter(|w| w[0] != w[1]).count()
        };
        changes(true) - changes(false)
    }
    /// The real roots counted with multiplicity: Σₖ (distinct real roots of
    /// gcd(F, F′, …, F⁽ᵏ⁻¹⁾)), since those are the roots of multiplicity ≥ k.
    pub fn real_roots_with_multiplicity(&self) -> usize {
        let mut g = self.clone();
        let mut d = self.clone();
        let mut total = 0;
        while g.degree().is_some_and(|k| k > 0) {
            total += g.real_roots();
            d = d.derivative();
            g = g.gcd(&d);
        }
        total
    }
}

impl Poly {
    /// [`Poly::real_roots`], with 0 for the zero polynomial and for constants.
    pub fn real_roots_or_zero(&self) -> usize {
        if self.degree().is_some_and(|d| d > 0) {
            self.real_roots()
        } else {
            0
        }
    }
}

impl Poly {
    /// Sign changes of a sequence at −∞ or +∞.
    fn variations(seq: &[Poly], negative: bool) -> i64 {
        let signs: Vec<i32> = seq
            .iter()
            .map(|p| p.sign_at_infinity(negative))
            .filter(|&s| s != 0)
            .collect();
        signs.windows(2).filter(|w| w[0] != w[1]).count() as i64
    }

    /// The Tarski query `Σ sign(q(x))` over the distinct real roots `x` of `self`
    /// (Sturm–Tarski: the sign variations of the signed remainder sequence of
    /// `self, self′·q`, at −∞ minus at +∞).
    pub fn tarski_query(&self, q: &Poly) -> i64 {
        assert!(!self.is_zero(), "the zero polynomial");
        let mut seq = vec![self.clone(), self.derivative().mul(q)];
        while !seq.last().expect("nonempty").is_zero() {
            let n = seq.len();
            let r = seq[n - 2].rem(&seq[n - 1]).scale(&Rational::from(-1));
            seq.push(r);
        }
        seq.pop();
        Poly::variations(&seq, true) - Poly::variations(&seq, false)
    }

    /// The distinct real roots `x` with `q(x) ≥ 0`:
    /// `N − #{q < 0}` with `#{q < 0} = (TaQ(q²) − TaQ(q))/2`.
    pub fn real_roots_where_nonnegative(&self, q: &Poly) -> usize {
        if self.degree().is_none_or(|d| d == 0) {
            return 0;
        }
        let negative = (self.tarski_query(&q.mul(q)) - self.tarski_query(q)) / 2;
        self.real_roots() - negative as usize
    }

    /// [`Poly::real_roots_with_multiplicity`] restricted to `q ≥ 0`.
    pub fn real_roots_with_multiplicity_where_nonnegative(&self, q: &Poly) -> usize {
        let mut g = self.clone();
        let mut d = self.clone();
        let mut total = 0;
        while g.degree().is_some_and(|k| k > 0) {
            total += g.real_roots_where_nonnegative(q);
            d = d.derivative();
            g = g.gcd(&d);
        }
        total
    }
}
