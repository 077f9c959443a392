//! Exact arithmetic on floating-point expansions (Shewchuk 1997): a value is an unevaluated
//! sum of non-overlapping doubles, increasing in magnitude, with zeros eliminated. Sums
//! (`fast_expansion_sum_zeroelim`), products (`scale_expansion_zeroelim` accumulated,
//! then `compress`) and signs are exact and need no gcd and, for up to six components,
//! no allocation. The middle tier of the linear kernel (`Arithmetic::Expansion`).
//!
//! Exactness needs every `two_prod` to be error-free (no underflow: `|ab| ≥ 2⁻⁹⁶⁹`, and
//! Veltkamp's split needs `|a|, |b| ≤ 2⁹⁹⁵`) and no sum to overflow. These are checked at
//! run time: a violation *poisons* the current computation (a thread-local flag, see
//! [`Poison`]), after which operations return 0 at once, and the caller discards the
//! result and uses rationals instead. So does an operand too long to be worth it. Products
//! use Dekker's algorithm, so the tier needs no FMA.

use std::cell::Cell;
use std::cmp::Ordering;

use super::dd::{fast_two_sum, two_sum, ProductMode, WithoutFma};
use super::ring::Ring;
use super::round::{next_down, next_up, Rounded};

const INLINE: usize = 6;
/// Longest operand size handled (a sum's total length, a product's `len·len`); beyond,
/// the computation is left to rationals.
const MAX_LEN: usize = 4096;
/// Smallest product magnitude for which `two_prod` is error-free: 2⁻⁹⁶⁹.
const PROD_MIN: f64 = 2.004168360008973e-292;
/// Largest factor Veltkamp's split handles: 2⁹⁹⁵.
const SPLIT_MAX: f64 = 3.3484643974570854e299;

thread_local! {
    static POISONED: Cell<bool> = const { Cell::new(false) };
}

/// The thread-local poison flag of the expansion tier.
pub struct Poison;

impl Poison {
    /// Clear the flag before a computation.
    pub fn reset() {
        POISONED.with(|p| p.set(false));
    }
    /// Whether a computation since the last reset lost exactness.
    pub fn is_set() -> bool {
        POISONED.with(|p| p.get())
    }
    pub(crate) fn set() {
        POISONED.with(|p| p.set(true));
    }
}

/// A floating-point expansion.
#[derive(Clone)]
pub struct Expansion {
    len: usize,
    inline: [f64; INLINE],
    heap: Vec<f64>,
}

impl std::fmt::Debug for Expansion {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Expansion{:?}", self.as_slice())
    }
}

/// Structural equality (same components), which for zero-eliminated, compressed
/// expansions of equal values need not hold; use [`Expansion::sign`] of a difference for
/// value comparisons.
impl PartialEq for Expansion {
    fn eq(&self, other: &Self) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl Expansion {
    fn empty() -> Self {
        Expansion {
            len: 0,
            inline: [0.0; INLINE],
            heap: Vec::new(),
        }
    }
    /// The double `x`, exactly.
    pub fn from_f64(x: f64) -> Self {
        let mut e = Self::empty();
        if !x.is_finite() {
            Poison::set();
        }
        if x != 0.0 {
            e.push(x);
        }
        e
    }
    fn reserve(&mut self, n: usize) {
        if n > INLINE {
            self.heap.reserve(n);
        }
    }
    #[inline]
    fn push(&mut self, x: f64) {
        if self.len < INLINE {
            self.inline[self.len] = x;
        } else {
            if self.len == INLINE {
                self.heap.extend_from_slice(&self.inline);
            }
            self.heap.push(x);
        }
        self.len += 1;
    }
    /// The components, smallest first.
    pub fn as_slice(&self) -> &[f64] {
        if self.len <= INLINE {
            &self.inline[..self.len]
        } else {
            &self.heap[..self.len]
        }
    }
    /// The exact sign.
    pub fn sign(&self) -> Ordering {
        match self.as_slice().last() {
            None => Ordering::Equal,
            Some(x) => x.partial_cmp(&0.0).unwrap_or(Ordering::Equal),
        }
    }
    /// An approximation (the components summed, largest last).
    pub fn estimate(&self) -> f64 {
        self.as_slice().iter().sum()
    }
    /// Number of components.
    pub fn len(&self) -> usize {
        self.len
    }
    /// True for the zero expansion.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// `e + f` (Shewchuk's `fast_expansion_sum_zeroelim`); `e − f` when `neg`.
    fn sum(e: &[f64], f: &[f64]) -> Expansion {
        Self::sum_signed(e, f, false)
    }

    fn sum_signed(e: &[f64], f_in: &[f64], neg: bool) -> Expansion {
        // Negating f on the fly (into a stack copy) avoids a temporary expansion.
        let mut f_stack = [0.0; 16];
        let f_heap: Vec<f64>;
        let f: &[f64] = if !neg {
            f_in
        } else if f_in.len() <= 16 {
            for (d, &x) in f_stack.iter_mut().zip(f_in) {
                *d = -x;
            }
            &f_stack[..f_in.len()]
        } else {
            f_heap = f_in.iter().map(|x| -x).collect();
            &f_heap
        };
        let mut h = Expansion::empty();
        h.reserve(e.len() + f.len());
        if e.is_empty() || f.is_empty() {
            for &x in if e.is_empty() { f } else { e } {
                h.push(x);
            }
            return h;
        }
        let (mut i, mut j) = (0, 0);
        let smaller = |a: f64, b: f64| (b > a) == (b > -a); // |a| < |b| (or tie)
        let mut q;
        if smaller(e[0], f[0]) {
            q = e[0];
            i = 1;
        } else {
            q = f[0];
            j = 1;
        }
        let mut first = true;
        while i < e.len() && j < f.len() {
            let x = if smaller(e[i], f[j]) {
                i += 1;
                e[i - 1]
            } else {
                j += 1;
                f[j - 1]
            };
            let (s, err) = if first {
                fast_two_sum(x, q)
            } else {
                two_sum(q, x)
            };
            first = false;
            q = s;
            if err != 0.0 {
                h.push(err);
            }
        }
        for &x in e[i..].iter().chain(f[j..].iter()) {
            let (s, err) = two_sum(q, x);
            q = s;
            if err != 0.0 {
                h.push(err);
            }
        }
        if q != 0.0 || h.len == 0 {
            if !q.is_finite() {
                Poison::set();
            }
            if q != 0.0 {
                h.push(q);
            }
        }
        h
    }

    #[inline]
    fn two_prod(a: f64, b: f64) -> (f64, f64) {
        let p = a * b;
        if !(p.abs() >= PROD_MIN
            && p.abs() <= f64::MAX
            && a.abs() <= SPLIT_MAX
            && b.abs() <= SPLIT_MAX)
        {
            Poison::set();
        }
        WithoutFma::two_prod(a, b)
    }

    /// `e · b` (Shewchuk's `scale_expansion_zeroelim`).
    fn scale(e: &[f64], b: f64) -> Expansion {
        let mut h = Expansion::empty();
        if e.is_empty() || b == 0.0 {
            return h;
        }
        let (mut q, hh) = Self::two_prod(e[0], b);
        if hh != 0.0 {
            h.push(hh);
        }
        for &x in &e[1..] {
            let (p1, p0) = Self::two_prod(x, b);
            let (s, hh) = two_sum(q, p0);
            if hh != 0.0 {
                h.push(hh);
            }
            let (q2, hh) = fast_two_sum(p1, s);
            if hh != 0.0 {
                h.push(hh);
            }
            q = q2;
        }
        if !q.is_finite() {
            Poison::set();
        }
        if q != 0.0 {
            h.push(q);
        }
        h
    }

    /// Shewchuk's `compress`: the same value with (usually) fewer components.
    fn compress(mut self) -> Expansion {
        let n = self.len;
        if n <= 2 {
            return self;
        }
        // Scratch on the stack up to 16 components (no allocation in the common case).
        let mut e_stack = [0.0; 16];
        let mut h_stack = [0.0; 16];
        let (mut e_heap, mut h_heap) = (Vec::new(), Vec::new());
        let (e, h): (&mut [f64], &mut [f64]) = if n <= 16 {
            (&mut e_stack[..n], &mut h_stack[..n])
        } else {
            e_heap.resize(n, 0.0);
            h_heap.resize(n, 0.0);
            (&mut e_heap[..], &mut h_heap[..])
        };
        e.copy_from_slice(self.as_slice());
        let mut bottom = n - 1;
        let mut q = e[n - 1];
        for k in (0..n - 1).rev() {
            let (s, small) = fast_two_sum(q, e[k]);
            if small != 0.0 {
                h[bottom] = s;
                bottom -= 1;
                q = small;
            } else {
                q = s;
            }
        }
        let mut top = 0;
        for k in bottom + 1..n {
            let (s, small) = fast_two_sum(h[k], q);
            if small != 0.0 {
                h[top] = small;
                top += 1;
            }
            q = s;
        }
        h[top] = q;
        self.len = 0;
        self.heap.clear();
        for &x in &h[..=top] {
            if x != 0.0 {
                self.push(x);
            }
        }
        self
    }

    /// `self · 2^k` exactly, for a power of two `scale` (poisons on underflow/overflow).
    fn scale_pow2(&self, scale: f64) -> Expansion {
        let mut h = Expansion::empty();
        for &x in self.as_slice() {
            let y = x * scale;
            if !(y.abs() >= f64::MIN_POSITIVE && y.is_finite()) {
                Poison::set();
            }
            h.push(y);
        }
        h
    }
}

impl Ring for Expansion {
    fn zero() -> Self {
        Expansion::empty()
    }
    fn one() -> Self {
        Expansion::from_f64(1.0)
    }
    fn plus(&self, rhs: &Self) -> Self {
        if self.len + rhs.len > MAX_LEN || Poison::is_set() {
            // Once exactness is lost the result is discarded: stop computing (garbage
            // components need not compress, and lengths would multiply).
            Poison::set();
            return Expansion::empty();
        }
        Expansion::sum(self.as_slice(), rhs.as_slice())
    }
    fn minus(&self, rhs: &Self) -> Self {
        if self.len + rhs.len > MAX_LEN || Poison::is_set() {
            Poison::set();
            return Expansion::empty();
        }
        Expansion::sum_signed(self.as_slice(), rhs.as_slice(), true)
    }
    fn times(&self, rhs: &Self) -> Self {
        if self.len * rhs.len > MAX_LEN || Poison::is_set() {
            Poison::set();
            return Expansion::empty();
        }
        let (a, b) = if self.len >= rhs.len {
            (self, rhs)
        } else {
            (rhs, self)
        };
        let b = b.as_slice();
        if b.is_empty() || a.len == 0 {
            return Expansion::empty();
        }
        let mut acc = Expansion::scale(a.as_slice(), b[0]);
        for &x in &b[1..] {
            acc = Expansion::sum(acc.as_slice(), Expansion::scale(a.as_slice(), x).as_slice());
        }
        acc.compress()
    }
    fn negate(&self) -> Self {
        let mut h = Expansion::empty();
        for &x in self.as_slice() {
            h.push(-x);
        }
        h
    }
}

/// The quotient `p/q` (`q ≠ 0`) correctly rounded, decided exactly: a candidate `c`, the
/// exact residual `R = p − c·q`, and the exact tests `2|R| < gap·|q|` on the side of `R`
/// (moving `c` by one double while the test says it lies beyond the cell; equality is
/// a tie, rounded to even). `None` when the value is outside `[2⁻⁹⁶⁰, 2¹⁰⁰⁰]` in
/// magnitude (or poisoned): the caller uses rationals.
pub fn round_quotient(p: &Expansion, q: &Expansion) -> Option<Rounded> {
    if p.is_empty() {
        return Some(Rounded::exact(0.0));
    }
    let (p, q) = if q.sign() == Ordering::Less {
        (p.negate(), q.negate())
    } else {
        (p.clone(), q.clone())
    };
    let mut c = p.estimate() / q.estimate();
    for _ in 0..4 {
        if !(c.abs() >= 1.0261342003245941e-289 && c.abs() <= 1.0715086071862673e301) {
            return None;
        }
        let r = p.minus(&q.times(&Expansion::from_f64(c)));
        let side = r.sign();
        if side == Ordering::Equal {
            return Some(Rounded::exact(c));
        }
        // Compare 2|R| with the gap on R's side times q.
        let (neighbour, gap) = if side == Ordering::Greater {
            (next_up(c), next_up(c) - c)
        } else {
            (next_down(c), c - next_down(c))
        };
        let two_r = r.scale_pow2(if side == Ordering::Greater { 2.0 } else { -2.0 });
        let test = q.scale_pow2(gap).minus(&two_r).sign();
        match test {
            Ordering::Greater => return Some(Rounded::inexact(c, side)),
            Ordering::Equal => {
                let even = if c.to_bits() & 1 == 0 { c } else { neighbour };
                let (lo, hi) = if c < neighbour {
                    (c, neighbour)
                } else {
                    (neighbour, c)
                };
                return Some(Rounded {
                    nearest: even,
                    lo,
                    hi,
                });
            }
            Ordering::Less => c = neighbour,
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::round::round_rational;
    use rug::Rational;

    fn exact(e: &Expansion) -> Rational {
        e.as_slice()
            .iter()
            .map(|&x| Rational::from_f64(x).unwrap())
            .sum()
    }

    #[test]
    fn arithmetic_is_exact() {
        Poison::reset();
        let mut seed = 0x9E3779B97F4A7C15u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            ((seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2f64.powi((seed % 64) as i32 - 32)
        };
        for _ in 0..300 {
            let (a, b, c) = (
                Expansion::from_f64(next()),
                Expansion::from_f64(next()),
                Expansion::from_f64(next()),
            );
            let x = a.times(&b).plus(&c).times(&a.minus(&c));
            let truth = (exact(&a) * exact(&b) + exact(&c)) * (exact(&a) - exact(&c));
            assert_eq!(exact(&x), truth);
            assert_eq!(x.sign(), truth.cmp0());
            let s = x.as_slice();
            assert!(s.windows(2).all(|w| w[0].abs() < w[1].abs()));
        }
        assert!(!Poison::is_set());
        // Underflow poisons.
        let _ = Expansion::from_f64(1e-200).times(&Expansion::from_f64(1e-200));
        assert!(Poison::is_set());
        Poison::reset();
    }

    #[test]
    fn quotients_round_correctly_including_ties() {
        for (a, b) in [
            (1.0, 3.0),
            (-2.0, 7.0),
            (6.0, 3.0),
            (1.0, -1024.0),
            (1e290, 1e-5),
        ] {
            let r = round_quotient(&Expansion::from_f64(a), &Expansion::from_f64(b)).unwrap();
            let truth =
                round_rational(&(Rational::from_f64(a).unwrap() / Rational::from_f64(b).unwrap()));
            assert_eq!(r, truth, "{a}/{b}");
        }
        // (1 + 2^-53)·3 / 3: the midpoint between 1 and 1 + 2^-52, a tie to even (1).
        let p = Expansion::from_f64(3.0).plus(&Expansion::from_f64(3.0 * f64::EPSILON / 2.0));
        let r = round_quotient(&p, &Expansion::from_f64(3.0)).unwrap();
        assert_eq!((r.nearest, r.lo, r.hi), (1.0, 1.0, 1.0 + f64::EPSILON));
    }
}
