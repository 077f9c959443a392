//! The case analyses shared by [`super::Interval`] and
//! [`crate::num::MpfrInterval`]: which multiples of π/2 an argument interval may contain
//! (extrema of sin and cos, poles of tan), and which corners or constants bound
//! `atan2` over a box. Written once, evaluated in either number type.

use rug::float::Constant;
use rug::{Float, Integer};
use std::cmp::Ordering;

use super::mpfr_eval::{rd, ru};

/// Which integers `m` with `m·π/2 ∈ [a, b]` may exist, as a bitmask over `m mod 4`
/// (bit `j` set: some such `m ≡ j (mod 4)` may exist).
///
/// The caller reduces both bounds, `a = k_a·π/2 + r_a`, `b = k_b·π/2 + r_b` with
/// `|r| < π/2` (the true remainders; `k` exact integers, `k_a ≤ k_b`), and passes
/// `k_a mod 4`, `span = k_b − k_a` (saturated), and what an enclosure of each remainder
/// allows: `a_at_or_below` = "r_a ≤ 0 is possible" (then `m = k_a` may satisfy
/// `m·π/2 ≥ a`), `b_at_or_above` = "r_b ≥ 0 is possible". Then every `m` with
/// `a ≤ m·π/2 ≤ b` lies in `[m_min, m_max]`, `m_min = k_a + (0 if a_at_or_below else 1)`,
/// `m_max = k_b − (0 if b_at_or_above else 1)`: for `m ≤ k_a − 1`,
/// `m·π/2 ≤ a − r_a − π/2 < a`, and symmetrically above `k_b`. An undecided sign only
/// widens the set (soundness), never narrows it.
pub(crate) fn half_pi_multiples(
    ka_mod4: u32,
    span: u64,
    a_at_or_below: bool,
    b_at_or_above: bool,
) -> u8 {
    let skip_a = u64::from(!a_at_or_below);
    let skip_b = u64::from(!b_at_or_above);
    let count = span.saturating_add(1).saturating_sub(skip_a + skip_b);
    if count >= 4 {
        return 0b1111;
    }
    let first = (ka_mod4 + skip_a as u32) % 4;
    (0..count as u32).fold(0u8, |mask, i| mask | 1 << ((first + i) % 4))
}

/// Bit masks of [`half_pi_multiples`]: sin reaches +1 at `m ≡ 1`, −1 at `m ≡ 3`; cos
/// reaches +1 at `m ≡ 0`, −1 at `m ≡ 2`; tan has poles at odd `m`.
pub(crate) const SIN_MAX: u8 = 0b0010;
pub(crate) const SIN_MIN: u8 = 0b1000;
pub(crate) const COS_MAX: u8 = 0b0001;
pub(crate) const COS_MIN: u8 = 0b0100;
pub(crate) const TAN_POLE: u8 = 0b1010;

/// One bound of `atan2(Y, X)` over a box `Y × X = [c, d] × [a, b]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Atan2Bound {
    /// `atan2(y, x)` at a corner: `y_hi` picks `d` (else `c`), `x_hi` picks `b` (else
    /// `a`). The chosen `y` is never 0 and the two coordinates are never both infinite.
    Corner {
        y_hi: bool,
        x_hi: bool,
    },
    NegPi,
    NegHalfPi,
    Zero,
    HalfPi,
    Pi,
}

/// The bounds of `atan2` over a box, or EMPTY (the box is the origin).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Atan2Plan {
    Empty,
    Range(Atan2Bound, Atan2Bound),
}

/// Which corners or constants bound `{atan2(y, x) : (x, y) ∈ box, (x, y) ≠ 0}` ⊆ (−π, π]
/// for `y ∈ [c, d]`, `x ∈ [a, b]` (non-empty), given the signs of `c, d, a, b`
/// (IEEE 1788 `atan2`; the branch cut is the negative x-axis, where the value is π).
///
/// * `d < 0` (below the axis, θ ∈ (−π, 0), continuous): moving left lowers θ, so the
///   minimum is at `x = a`, where θ falls as `y` grows if `a < 0` (take `y = d`) and
///   rises if `a ≥ 0` (take `y = c`); the maximum at `x = b` with `y = d` if `b ≥ 0`,
///   else `y = c`.
/// * `c > 0`: the mirror image (minimum at `x = b`, maximum at `x = a`).
/// * `c ≤ 0 ≤ d`, `X = [0, 0]`: the points `(0, y≠0)` give ±π/2.
/// * `c ≤ 0 ≤ d`, `a ≥ 0 < b`: θ ∈ [−π/2, π/2], extremes at `x = a`, `y = c` / `y = d`
///   (0 when `c = 0` / `d = 0`).
/// * `c ≤ 0 ≤ d`, `a < 0`: the box meets the negative x-axis (θ = π); if also `c < 0`
///   it holds points just below it, so the hull is [−π, π]. If `c = 0` the maximum is π
///   and the minimum is 0 (if `b > 0`), `atan2(d, b)` (if `b ≤ 0 < d`), or π.
pub(crate) fn atan2_plan(c: Ordering, d: Ordering, a: Ordering, b: Ordering) -> Atan2Plan {
    use Atan2Bound::*;
    use Ordering::*;
    let corner = |y_hi, x_hi| Corner { y_hi, x_hi };
    let range = |lo, hi| Atan2Plan::Range(lo, hi);
    if d == Less {
        return range(corner(a == Less, false), corner(b != Less, true));
    }
    if c == Greater {
        return range(corner(b == Less, true), corner(a != Less, false));
    }
    // c ≤ 0 ≤ d.
    if a == Equal && b == Equal {
        if c == Equal && d == Equal {
            return Atan2Plan::Empty;
        }
        let lo = if c == Less { NegHalfPi } else { HalfPi };
        let hi = if d == Greater { HalfPi } else { NegHalfPi };
        return range(lo, hi);
    }
    if a != Less {
        let lo = if c == Less {
            corner(false, false)
        } else {
            Zero
        };
        let hi = if d == Greater {
            corner(true, false)
        } else {
            Zero
        };
        return range(lo, hi);
    }
    if c == Less {
        return range(NegPi, Pi);
    }
    let lo = if b == Greater {
        Zero
    } else if d == Greater {
        corner(true, true)
    } else {
        Pi
    };
    range(lo, Pi)
}

/// Where a finite number lies relative to the multiples of π/2: `x = k·π/2 + r`.
pub(crate) struct HalfPiReduction {
    /// `k`, the integer nearest to `x/(π/2)` (as computed; any integer with `|r| < π/2`
    /// keeps the analysis valid).
    pub k: Integer,
    /// `k mod 4` in `0..4`.
    pub k_mod4: u32,
    /// An enclosure of `r` allows `r ≤ 0`.
    pub r_may_be_le0: bool,
    /// An enclosure of `r` allows `r ≥ 0`.
    pub r_may_be_ge0: bool,
}

/// Reduce a finite `x` modulo π/2, rigorously: with `[h↓, h↑] ∋ π/2` at working
/// precision `w = max(e, 0) + 2p + 64` (`e` the exponent, `p` the precision of `x`),
/// `k = round(x / h↓)` and `r ∈ [x − k·h↑, x − k·h↓]` (for `k ≥ 0`; swapped for
/// `k < 0`), each operation rounded outward. `|x/(π/2) − k| ≤ 1/2 + 2^-w·|k|`, so
/// `|r| < π/2` as [`crate::num::interval`] `cases::half_pi_multiples` requires. The
/// sign of `r` is undecided only if `x` lies within about `2^(e−w)` of `k·π/2`.
pub(crate) fn reduce_half_pi_mpfr(x: &Float) -> HalfPiReduction {
    if x.is_zero() {
        return HalfPiReduction {
            k: Integer::new(),
            k_mod4: 0,
            r_may_be_le0: true,
            r_may_be_ge0: true,
        };
    }
    let e = x.get_exp().unwrap_or(0).max(0) as u32;
    let w = e + 2 * x.prec() + 64;
    let mut h_lo = rd(w, Constant::Pi);
    let mut h_hi = ru(w, Constant::Pi);
    h_lo /= 2u32;
    h_hi /= 2u32;
    let q = Float::with_val(w, x / &h_lo);
    let k = q.to_integer().unwrap_or_default();
    let kf = Float::with_val(k.significant_bits().max(2), &k);
    let (for_lo, for_hi) = if k >= 0 {
        (&h_hi, &h_lo)
    } else {
        (&h_lo, &h_hi)
    };
    let r_lo = rd(w, x - &ru(w, &kf * for_lo));
    let r_hi = ru(w, x - &rd(w, &kf * for_hi));
    HalfPiReduction {
        k_mod4: k.mod_u(4),
        k,
        r_may_be_le0: r_lo <= 0,
        r_may_be_ge0: r_hi >= 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn multiples_in_small_ranges() {
        // [0.1, 0.2]: k_a = k_b = 0, r > 0 both: no multiple.
        assert_eq!(half_pi_multiples(0, 0, false, true), 0);
        // [−0.1, 0.1]: contains m = 0.
        assert_eq!(half_pi_multiples(0, 0, true, true), 0b0001);
        // [1, 2]: k_a = 1 (r_a < 0, 1 < π/2), k_b = 1 (r_b > 0): m = 1 (π/2).
        assert_eq!(half_pi_multiples(1, 0, true, true), 0b0010);
        // [2, 4]: k_a = 1 (r_a > 0), k_b = 3 (r_b < 0, 4 < 3π/2): m = 2 only.
        assert_eq!(half_pi_multiples(1, 2, false, false), 0b0100);
        // k from −1 (mod 4 = 3) spanning 5 values: all classes.
        assert_eq!(half_pi_multiples(3, 5, true, true), 0b1111);
        // k_a ≡ 3, skip it, then m ≡ 0, 1.
        assert_eq!(half_pi_multiples(3, 2, false, true), 0b0011);
        // A saturated span means "many": every class.
        assert_eq!(half_pi_multiples(0, u64::MAX, false, false), 0b1111);
    }

    #[test]
    fn atan2_cases_match_hand_analysis() {
        use Atan2Bound::*;
        use Ordering::*;
        let r = Atan2Plan::Range;
        // Y = [1, 2], X = [1, 2]: min at (b, c), max at (a, d).
        assert_eq!(
            atan2_plan(Greater, Greater, Greater, Greater),
            r(
                Corner {
                    y_hi: false,
                    x_hi: true
                },
                Corner {
                    y_hi: true,
                    x_hi: false
                }
            )
        );
        // Y = [-1, 1], X = [-2, -1]: crosses the branch cut.
        assert_eq!(atan2_plan(Less, Greater, Less, Less), r(NegPi, Pi));
        // Y = [0, 0], X = [0, 0]: empty.
        assert_eq!(atan2_plan(Equal, Equal, Equal, Equal), Atan2Plan::Empty);
        // Y = [0, 0], X = [-2, -1]: exactly π.
        assert_eq!(atan2_plan(Equal, Equal, Less, Less), r(Pi, Pi));
        // Y = [-2, 0], X = [0, 0]: −π/2.
        assert_eq!(
            atan2_plan(Less, Equal, Equal, Equal),
            r(NegHalfPi, NegHalfPi)
        );
    }
}
