//! Sturm sequences (Sturm 1829; Basu, Pollack & Roy, *Algorithms in Real Algebraic
//! Geometry*, Thm. 2.50) for counting the distinct real roots of a square-free
//! polynomial in any interval, exactly.
//!
//! `s₀ = p`, `s₁ = p'`, `sₖ₊₁ = −rem(sₖ₋₁, sₖ)`, each kept up to a positive factor
//! (primitive pseudo-remainders with the sign of `lc^{δ+1}` corrected), which changes no
//! sign. With `V(x)` the number of sign changes of `(sₖ(x))` (zeros skipped), `V` is
//! right-continuous for a square-free `p` (at a root `r`, `s₀` drops out and `s₀s₁ > 0`
//! just right of `r`), so the number of distinct roots in `(a, b]` is `V(a) − V(b)`
//! for any `a < b`, roots at the end points included — the exact endpoint rule the
//! isolation relies on.

use std::cmp::Ordering;

use super::int_poly::{At, IntPoly};

/// The Sturm sequence of a square-free polynomial of positive degree.
#[derive(Debug, Clone)]
pub(crate) struct Sturm {
    seq: Vec<IntPoly>,
}

impl Sturm {
    pub(crate) fn new(p: &IntPoly) -> Sturm {
        let mut seq = vec![p.clone().primitive()];
        let d = p.derivative();
        if d.is_zero() {
            return Sturm { seq };
        }
        seq.push(d);
        loop {
            let n = seq.len();
            let (r, sign) = IntPoly::pseudo_rem(&seq[n - 2], &seq[n - 1]);
            if r.is_zero() {
                break;
            }
            // r is a positive multiple of lc^{δ+1}·rem: −rem is a positive multiple of
            // −r when lc^{δ+1} > 0, of r otherwise.
            let next = if sign == Ordering::Greater {
                IntPoly {
                    c: r.c.into_iter().map(|x| -x).collect(),
                }
            } else {
                r
            };
            seq.push(next);
        }
        Sturm { seq }
    }

    /// The polynomial itself (primitive).
    pub(crate) fn poly(&self) -> &IntPoly {
        &self.seq[0]
    }

    /// The derivative (a positive multiple).
    pub(crate) fn derivative(&self) -> Option<&IntPoly> {
        self.seq.get(1)
    }

    /// `V(x)`: sign changes of the sequence at `x`, zeros skipped.
    pub(crate) fn variations(&self, at: At<'_>) -> usize {
        let mut last = Ordering::Equal;
        let mut changes = 0;
        for s in &self.seq {
            let sg = s.sign_at(at);
            if sg == Ordering::Equal {
                continue;
            }
            if last != Ordering::Equal && sg != last {
                changes += 1;
            }
            last = sg;
        }
        changes
    }

    /// The number of distinct roots in `(a, b]` for `a < b`.
    pub(crate) fn count_half_open(&self, a: At<'_>, b: At<'_>) -> usize {
        self.variations(a).saturating_sub(self.variations(b))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::{Integer, Rational};

    #[test]
    fn counts_with_roots_at_the_end_points() {
        // (x − 1)(x − 2)(x + 3) = x³ − 7x + 6
        let p = IntPoly {
            c: [6, -7, 0, 1].iter().map(|&x| Integer::from(x)).collect(),
        };
        let s = Sturm::new(&p);
        assert_eq!(s.count_half_open(At::NegInf, At::PosInf), 3);
        let one = Rational::from(1);
        let two = Rational::from(2);
        // (1, 2] holds 2 only; (−3, 1] holds 1 only.
        assert_eq!(s.count_half_open(At::Rational(&one), At::Rational(&two)), 1);
        let m3 = Rational::from(-3);
        assert_eq!(s.count_half_open(At::Rational(&m3), At::Rational(&one)), 1);
        assert_eq!(s.count_half_open(At::NegInf, At::Rational(&m3)), 1);
    }
}
