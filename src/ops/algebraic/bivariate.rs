//! Bivariate polynomials of low degree with rational coefficients, and the resultant of
//! two of them with respect to one variable when both have degree ≤ 2 in it — the
//! elimination behind conic ∩ conic (OPERATIONS.md §6.3, "polynomial roots of degree
//! ≤ 4").

use std::cmp::Ordering;

use rug::{Integer, Rational};

use crate::certify::univariate::Polynomial;
use crate::ops::rational::Conic;

/// `Σ c[i][j] xⁱ yʲ`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Bivariate {
    c: Vec<Vec<Rational>>,
}

impl Bivariate {
    /// `a x² + b xy + c y² + d x + e y + f` of a conic.
    pub(crate) fn from_conic(q: &Conic) -> Bivariate {
        let [a, b, c, d, e, f] = q.coefficients();
        let z = Rational::new;
        Bivariate {
            c: vec![vec![f, e, c], vec![d, b, z()], vec![a, z(), z()]],
        }
    }

    fn get(&self, i: usize, j: usize) -> Rational {
        self.c
            .get(i)
            .and_then(|row| row.get(j))
            .cloned()
            .unwrap_or_default()
    }

    fn size(&self) -> usize {
        self.c.len()
    }

    /// The total degree (`None` for zero).
    pub(crate) fn total_degree(&self) -> Option<usize> {
        let mut best = None;
        for (i, row) in self.c.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                if x.cmp0() != Ordering::Equal {
                    best = Some(best.map_or(i + j, |b: usize| b.max(i + j)));
                }
            }
        }
        best
    }

    /// True when `self = μ·other` for some rational `μ ≠ 0` (both non-zero).
    pub(crate) fn proportional(&self, other: &Bivariate) -> bool {
        let n = self.size().max(other.size());
        let cells = || (0..n).flat_map(|i| (0..n).map(move |j| (i, j)));
        let Some((i0, j0)) = cells().find(|&(i, j)| other.get(i, j).cmp0() != Ordering::Equal)
        else {
            return false;
        };
        let mu = self.get(i0, j0) / other.get(i0, j0);
        mu.cmp0() != Ordering::Equal
            && cells().all(|(i, j)| self.get(i, j) == Rational::from(&mu * &other.get(i, j)))
    }

    /// `p(x − λy, y)`: the shear that moves the projection direction.
    pub(crate) fn shear(&self, lambda: &Rational) -> Bivariate {
        let n = self.size();
        let mut c = vec![vec![Rational::new(); 2 * n]; n];
        for i in 0..n {
            for j in 0..n {
                let cij = self.get(i, j);
                if cij.cmp0() == Ordering::Equal {
                    continue;
                }
                // (x − λy)ⁱ = Σ_k C(i,k) xᵏ (−λy)^{i−k}
                for k in 0..=i {
                    let binom = Integer::from(Integer::binomial_u(i as u32, k as u32));
                    let mut term = Rational::from(&cij * &binom);
                    for _ in 0..(i - k) {
                        term *= lambda;
                        term = -term;
                    }
                    c[k][j + i - k] += term;
                }
            }
        }
        Bivariate { c }
    }

    /// The coefficients of `yʲ` as polynomials in `x`, up to the degree in `y`.
    pub(crate) fn in_y(&self) -> Vec<Polynomial> {
        let width = self.c.iter().map(Vec::len).max().unwrap_or(0);
        let mut out: Vec<Polynomial> = (0..width)
            .map(|j| Polynomial::from_coeffs((0..self.size()).map(|i| self.get(i, j)).collect()))
            .collect();
        while out.last().is_some_and(Polynomial::is_zero) {
            out.pop();
        }
        out
    }

    /// The coefficients of `xⁱ` as polynomials in `y`, up to the degree in `x`.
    pub(crate) fn in_x(&self) -> Vec<Polynomial> {
        let width = self.c.iter().map(Vec::len).max().unwrap_or(0);
        let mut out: Vec<Polynomial> = (0..self.size())
            .map(|i| Polynomial::from_coeffs((0..width).map(|j| self.get(i, j)).collect()))
            .collect();
        while out.last().is_some_and(Polynomial::is_zero) {
            out.pop();
        }
        out
    }
}

/// The Sylvester resultant of `f = Σ fᵢ zⁱ` and `g = Σ gᵢ zⁱ` (degrees ≤ 2 in `z`,
/// formal degrees `len − 1`, coefficients polynomials in the other variable), up to
/// sign. It satisfies `Res = A·f + B·g`, so it vanishes wherever `f` and `g` have a
/// common root `z`. Closed forms: `(1,1)`: `f₁g₀ − f₀g₁`; `(2,1)`:
/// `f₂g₀² − f₁g₀g₁ + f₀g₁²`; `(2,2)`: `(f₂g₀ − f₀g₂)² − (f₂g₁ − f₁g₂)(f₁g₀ − f₀g₁)`;
/// a constant (degree 0) `f₀` against degree `n`: `f₀ⁿ`. `None` above degree 2 or for
/// an empty (zero) input.
pub(crate) fn resultant(f: &[Polynomial], g: &[Polynomial]) -> Option<Polynomial> {
    let (df, dg) = (f.len().checked_sub(1)?, g.len().checked_sub(1)?);
    let m = |a: &Polynomial, b: &Polynomial| a * b;
    Some(match (df, dg) {
        (0, n) => f[0].pow(n as u32),
        (n, 0) => g[0].pow(n as u32),
        (1, 1) => &m(&f[1], &g[0]) - &m(&f[0], &g[1]),
        (2, 1) => resultant_21(f, g),
        (1, 2) => resultant_21(g, f),
        (2, 2) => {
            let u = &m(&f[2], &g[0]) - &m(&f[0], &g[2]);
            let v = &m(&f[2], &g[1]) - &m(&f[1], &g[2]);
            let w = &m(&f[1], &g[0]) - &m(&f[0], &g[1]);
            &m(&u, &u) - &m(&v, &w)
        }
        _ => return None,
    })
}

fn resultant_21(f: &[Polynomial], g: &[Polynomial]) -> Polynomial {
    let g0g0 = &g[0] * &g[0];
    let g0g1 = &g[0] * &g[1];
    let g1g1 = &g[1] * &g[1];
    &(&(&f[2] * &g0g0) - &(&f[1] * &g0g1)) + &(&f[0] * &g1g1)
}

/// The common root `z = num/den` of `f` and `g` where they have exactly one, for
/// degrees ≥ 1 with constant leading coefficients: from the linear polynomial
/// `g₂f − f₂g = (g₂f₁ − f₂g₁)z + (g₂f₀ − f₂g₀)` for two quadratics, else from the
/// linear one.
pub(crate) fn common_root(f: &[Polynomial], g: &[Polynomial]) -> Option<(Polynomial, Polynomial)> {
    match (f.len(), g.len()) {
        (3, 3) => Some((
            &(&f[0] * &g[2]) - &(&f[2] * &g[0]),
            &(&f[2] * &g[1]) - &(&f[1] * &g[2]),
        )),
        (_, 2) => Some((-&g[0], g[1].clone())),
        (2, _) => Some((-&f[0], f[1].clone())),
        _ => None,
    }
}
