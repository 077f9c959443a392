//! Real root isolation of a square-free integer polynomial by Sturm bisection.
//!
//! Why Sturm rather than Descartes/Vincent–Akritas: the counts are exact in any
//! interval (the public count in `[a, b]` is the same code), the end point rule
//! `#(a, b] = V(a) − V(b)` handles roots that fall on split points without special
//! cases, and the polynomials of the algebraic operations have degree ≤ 4, where the
//! sequence is short. Descartes' rule would need a Taylor shift per sub-interval and
//! only bounds counts.
//!
//! Magnitudes: every non-zero root lies in `2^kl < |x| < 2^kh` (Fujiwara's bound on the
//! polynomial and on its reverse). Intervals between powers of two far apart are split
//! at the geometric mean `2^{⌊(ka+kb)/2⌋}`, so a root near 1e-150 or 1e150 costs about
//! log₂ of its exponent in steps, not its exponent.

use std::cmp::Ordering;

use rug::{Integer, Rational};

use super::bracket::{dyadic, Bracket};
use super::int_poly::At;
#[cfg(test)]
use super::int_poly::IntPoly;
use super::sturm::Sturm;

/// One isolated root of the square-free polynomial.
#[derive(Debug, Clone)]
pub(crate) enum Isolated {
    Exact(Rational),
    Bracket(Bracket),
}

/// `m/2ᵉ`.
#[derive(Debug, Clone)]
struct Dy {
    m: Integer,
    e: u32,
}

impl Dy {
    /// `sign·2ᵏ`.
    fn power(sign: i32, k: i64) -> Dy {
        let (m, e) = if k >= 0 {
            (Integer::from(1) << (k as u32), 0)
        } else {
            (Integer::from(1), (-k) as u32)
        };
        Dy {
            m: if sign < 0 { -m } else { m },
            e,
        }
    }

    fn at(&self) -> At<'_> {
        At::Dyadic(&self.m, self.e)
    }

    fn rational(&self) -> Rational {
        dyadic(&self.m, self.e)
    }

    /// Both numerators over `2^max(e)`.
    fn common(a: &Dy, b: &Dy) -> (Integer, Integer, u32) {
        let e = a.e.max(b.e);
        (
            Integer::from(&a.m << (e - a.e)),
            Integer::from(&b.m << (e - b.e)),
            e,
        )
    }

    fn midpoint(a: &Dy, b: &Dy) -> Dy {
        let (x, y, e) = Dy::common(a, b);
        Dy { m: x + y, e: e + 1 }
    }
}

/// An open interval `(a, b)` holding `count` distinct roots.
struct Work {
    a: Dy,
    b: Dy,
    va: usize,
    vb: usize,
    a_root: bool,
    b_root: bool,
    count: usize,
    /// `(ka, kb)` when the ends are `±2^ka`, `±2^kb` (same sign) and may be split
    /// geometrically.
    powers: Option<(i64, i64)>,
}

/// `⌈a/b⌉` for `b > 0`.
fn ceil_div(a: i64, b: i64) -> i64 {
    -((-a).div_euclid(b))
}

/// `k` with every complex root of `p = Σ cᵢxⁱ` strictly below `2^k` in absolute value,
/// by Fujiwara's bound `|z| ≤ 2·maxᵢ |a_{n−i}/a_n|^{1/i}` (its last term taken without
/// the factor ½, which only enlarges it) with `|a_{n−i}| < 2^{Lᵢ}`, `|a_n| ≥ 2^{L_n−1}`
/// from the bit lengths; `None` when `p` has no non-zero coefficient below the leading
/// one (then 0 is its only root).
fn upper_exponent(c: &[Integer]) -> Option<i64> {
    let n = c.len() - 1;
    let ln = i64::from(c[n].significant_bits());
    let mut best: Option<i64> = None;
    for i in 1..=n {
        let a = &c[n - i];
        if a.cmp0() == Ordering::Equal {
            continue;
        }
        // |a_{n−i}/a_n| < 2^{L_i − L_n + 1}, so its i-th root is below 2^{⌈·/i⌉}.
        let li = i64::from(a.significant_bits());
        let k = ceil_div(li - ln + 1, i as i64);
        best = Some(best.map_or(k, |b: i64| b.max(k)));
    }
    best.map(|k| k + 1)
}

/// Isolate the real roots of the square-free polynomial of `sturm` lying in the closed
/// range `[lo, hi]` (either end may be open-ended). Roots are returned in increasing
/// order; brackets have non-root end points and hold exactly one root.
pub(crate) fn isolate(
    sturm: &Sturm,
    lo: Option<&Rational>,
    hi: Option<&Rational>,
) -> Vec<Isolated> {
    let p = sturm.poly();
    let mut out: Vec<(Rational, Isolated)> = Vec::new();
    if p.degree() == 0 {
        return Vec::new();
    }
    let in_range = |x: &Rational| lo.is_none_or(|l| x >= l) && hi.is_none_or(|h| x <= h);
    let zero_root = p.c[0].cmp0() == Ordering::Equal;
    if zero_root && in_range(&Rational::new()) {
        out.push((Rational::new(), Isolated::Exact(Rational::new())));
    }
    // Strip the factor x (at most once: p is square-free).
    let stripped: &[Integer] = if zero_root { &p.c[1..] } else { &p.c[..] };
    let reversed: Vec<Integer> = stripped.iter().rev().cloned().collect();
    if let (Some(kh), Some(kl)) = (upper_exponent(stripped), upper_exponent(&reversed)) {
        let mut stack = start(sturm, -kl, kh);
        while let Some(w) = stack.pop() {
            if w.count == 0
                || lo.is_some_and(|l| w.b.rational() <= *l)
                || hi.is_some_and(|h| w.a.rational() >= *h)
            {
                continue;
            }
            if w.count == 1 {
                let iso = finish(sturm, w);
                let key = match &iso {
                    Isolated::Exact(r) => r.clone(),
                    Isolated::Bracket(b) => b.lo_rational(),
                };
                out.push((key, iso));
                continue;
            }
            let (root, left, right) = split(sturm, w);
            if let Some(r) = root.filter(|r| in_range(r)) {
                out.push((r.clone(), Isolated::Exact(r)));
            }
            stack.push(left);
            stack.push(right);
        }
    }
    out.sort_by(|x, y| x.0.cmp(&y.0));
    out.into_iter().map(|(_, iso)| iso).collect()
}

/// The two starting intervals, the negative roots' `[−2^kh, −2^kl]` then the positive
/// roots' `[2^kl, 2^kh]` (`kl`, `kh`: exponents of bounds on the roots' magnitudes, from
/// [`upper_exponent`]), with their root counts.
fn start(sturm: &Sturm, kl: i64, kh: i64) -> Vec<Work> {
    [-1, 1]
        .into_iter()
        .map(|sign| {
            let (a, b, powers) = if sign > 0 {
                (Dy::power(1, kl), Dy::power(1, kh), (kl, kh))
            } else {
                (Dy::power(-1, kh), Dy::power(-1, kl), (kh, kl))
            };
            let va = sturm.variations(a.at());
            let vb = sturm.variations(b.at());
            Work {
                a,
                b,
                va,
                vb,
                a_root: false,
                b_root: false,
                count: va.saturating_sub(vb),
                powers: Some(powers),
            }
        })
        .collect()
}

/// `w` split at [`split_point`]: the point if it is a root, and the two halves with
/// their root counts (a root at the point counted in neither).
fn split(sturm: &Sturm, w: Work) -> (Option<Rational>, Work, Work) {
    let (m, powers) = split_point(&w);
    let vm = sturm.variations(m.at());
    let m_root = sturm.poly().sign_at(m.at()) == Ordering::Equal;
    let root = m_root.then(|| m.rational());
    let left = Work {
        count: w.va.saturating_sub(vm).saturating_sub(usize::from(m_root)),
        a: w.a,
        b: m.clone(),
        va: w.va,
        vb: vm,
        a_root: w.a_root,
        b_root: m_root,
        powers: powers.map(|(ka, km, _)| (ka, km)),
    };
    let right = Work {
        count: vm
            .saturating_sub(w.vb)
            .saturating_sub(usize::from(w.b_root)),
        a: m,
        b: w.b,
        va: vm,
        vb: w.vb,
        a_root: m_root,
        b_root: w.b_root,
        powers: powers.map(|(_, km, kb)| (km, kb)),
    };
    (root, left, right)
}

/// The split point of an interval, and the exponents of the halves when both stay
/// geometric.
fn split_point(w: &Work) -> (Dy, Option<(i64, i64, i64)>) {
    if let Some((ka, kb)) = w.powers {
        if (ka - kb).abs() >= 2 {
            let km = (ka + kb).div_euclid(2);
            let sign = if w.a.m.cmp0() == Ordering::Less {
                -1
            } else {
                1
            };
            return (Dy::power(sign, km), Some((ka, km, kb)));
        }
    }
    (Dy::midpoint(&w.a, &w.b), None)
}

/// Turn an interval with exactly one root into a bracket whose ends are not roots.
/// At an end that is a root `r`, the sign just inside is that of `p'(r)` on the right
/// of `r` and the opposite on its left (p is square-free, so `p'(r) ≠ 0`); with those
/// signs the interval is bisected until neither end is a root.
fn finish(sturm: &Sturm, w: Work) -> Isolated {
    let p = sturm.poly();
    let dp = sturm.derivative();
    let inner_sign = |x: &Dy, is_root: bool, right_of: bool| -> Ordering {
        if !is_root {
            return p.sign_at(x.at());
        }
        let s = dp.map_or(Ordering::Equal, |d| d.sign_at(x.at()));
        if right_of {
            s
        } else {
            s.reverse()
        }
    };
    let sa = inner_sign(&w.a, w.a_root, true);
    let (mut a, mut b, mut e) = Dy::common(&w.a, &w.b);
    let (mut a_root, mut b_root) = (w.a_root, w.b_root);
    let mut sa = sa;
    while a_root || b_root {
        let m = Integer::from(&a + &b);
        a <<= 1;
        b <<= 1;
        e += 1;
        let s = p.eval_dyadic(&m, e).cmp0();
        if s == Ordering::Equal {
            return Isolated::Exact(dyadic(&m, e));
        }
        if s == sa {
            a = m;
            a_root = false;
            sa = s;
        } else {
            b = m;
            b_root = false;
        }
    }
    Isolated::Bracket(Bracket::new(a, b, e, sa))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certify::univariate::int_poly::small_poly as ip;

    #[test]
    fn isolates_and_finds_split_point_roots() {
        // x(x − 1)(x + 2)(2x − 1) = 2x⁴ + x³ − 5x² + 2x
        let s = Sturm::new(&ip(&[0, 2, -5, 1, 2]));
        let roots = isolate(&s, None, None);
        assert_eq!(roots.len(), 4);
        let exact: Vec<Rational> = roots
            .iter()
            .filter_map(|r| match r {
                Isolated::Exact(x) => Some(x.clone()),
                Isolated::Bracket(_) => None,
            })
            .collect();
        assert!(exact.contains(&Rational::new()));
        // In [0, 1]: 0, 1/2, 1.
        let some = isolate(&s, Some(&Rational::new()), Some(&Rational::from(1)));
        assert_eq!(some.len(), 3);
    }

    #[test]
    fn tiny_and_huge_roots() {
        // (x − 2^-500)(x + 2^600) with integer coefficients: 2^500 x² + (2^1100 − 1)x − 2^600
        let a = Integer::from(1) << 500u32;
        let b = (Integer::from(1) << 1100u32) - 1u32;
        let c = -(Integer::from(1) << 600u32);
        let s = Sturm::new(&IntPoly { c: vec![c, b, a] });
        assert_eq!(isolate(&s, None, None).len(), 2);
    }
}
