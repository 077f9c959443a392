//! Cheap sufficient tests modulo small primes, used to skip exact work on generic
//! input. Each test only ever proves a property; when it cannot, the exact algorithm
//! runs as before, so the answers never depend on these shortcuts.
//!
//! For an integer polynomial `f` of degree `n` and a prime `p ∤ lc(f)` (so `f̄ = f mod p`
//! keeps degree `n`):
//! * if `gcd(f̄, f̄') = 1` in `F_p[x]`, then `f` is square-free: `Res(f, f') ≡
//!   ±lc^k·Res(f̄, f̄') ≢ 0 (mod p)`, so the discriminant of `f` is not zero;
//! * if `f̄` has no root in `F_p`, then `f` has no rational root: a root `a/b` in lowest
//!   terms has `b | lc(f)`, so `b` is invertible mod `p` and `a·b⁻¹` would be a root of
//!   `f̄`.

use super::int_poly::IntPoly;

/// The primes tried, in order.
const PRIMES: [u32; 12] = [3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41];

/// `f mod p` with residues in `[0, p)` (`mod_u` is the Euclidean remainder), lowest
/// degree first.
fn reduce(f: &IntPoly, p: u32) -> Vec<u64> {
    f.c.iter().map(|c| u64::from(c.mod_u(p))).collect()
}

fn trim(mut a: Vec<u64>) -> Vec<u64> {
    while a.last() == Some(&0) {
        a.pop();
    }
    a
}

/// `b⁻¹ mod p` by Fermat (p prime, b ≠ 0).
fn inverse(b: u64, p: u64) -> u64 {
    let (mut result, mut base, mut e) = (1u64, b % p, p - 2);
    while e > 0 {
        if e & 1 == 1 {
            result = result * base % p;
        }
        base = base * base % p;
        e >>= 1;
    }
    result
}

/// The degree of `gcd(a, b)` in `F_p[x]` (`a` non-zero).
fn gcd_degree(a: Vec<u64>, b: Vec<u64>, p: u64) -> usize {
    let (mut a, mut b) = (trim(a), trim(b));
    while !b.is_empty() {
        // a ← a mod b
        let inv = inverse(b[b.len() - 1], p);
        while a.len() >= b.len() {
            let shift = a.len() - b.len();
            let f = a[a.len() - 1] * inv % p;
            for (i, bi) in b.iter().enumerate() {
                a[shift + i] = (a[shift + i] + p * p - f * bi % p) % p;
            }
            a = trim(a);
            if a.is_empty() {
                break;
            }
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().saturating_sub(1)
}

/// True when some small prime proves `f` square-free (see the module documentation).
pub(crate) fn proves_square_free(f: &IntPoly) -> bool {
    if f.degree() == 0 {
        return true;
    }
    PRIMES.iter().any(|&p| {
        let fp = reduce(f, p);
        let p = u64::from(p);
        if fp.last() == Some(&0) {
            return false;
        }
        let dp: Vec<u64> = fp
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| c * (i as u64 % p) % p)
            .collect();
        let dp = trim(dp);
        !dp.is_empty() && gcd_degree(fp, dp, p) == 0
    })
}

/// True when some small prime proves that `f` has no rational root.
pub(crate) fn proves_no_rational_root(f: &IntPoly) -> bool {
    PRIMES.iter().any(|&p| {
        let fp = reduce(f, p);
        let p = u64::from(p);
        if fp.last() == Some(&0) {
            return false;
        }
        (0..p).all(|x| fp.iter().rev().fold(0u64, |acc, c| (acc * x + c) % p) != 0)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certify::univariate::int_poly::small_poly as ip;

    #[test]
    fn tests_prove_only_true_properties() {
        // (x − 1)²(x + 2) is not square-free: no prime may claim it is.
        assert!(!proves_square_free(&ip(&[2, -3, 0, 1])));
        assert!(proves_square_free(&ip(&[-2, 0, 1])));
        // x² − 2 has no rational root (no root mod 3); 6x² − 5x + 1 has 1/2 and 1/3.
        assert!(proves_no_rational_root(&ip(&[-2, 0, 1])));
        assert!(!proves_no_rational_root(&ip(&[1, -5, 6])));
        // x⁴ + 1 has a root mod every prime of the form 8k + 1 only, but no rational
        // root: some small prime shows it.
        assert!(proves_no_rational_root(&ip(&[1, 0, 0, 0, 1])));
    }
}
