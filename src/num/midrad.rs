//! Midpoint–radius enclosures over f64, rounded upward without touching the rounding
//! mode: the fast enclosure arithmetic of the surface jets (`surface::taylor_fast`).
//!
//! A [`MidRad`] `⟨m, r⟩` stands for the real interval `[m − r, m + r]`. Its operations
//! return an enclosure of the exact result for all operands in the enclosures: the
//! midpoint is the round-to-nearest (RN) result, and the radius bounds the propagated
//! radii plus the midpoint's own rounding error, `≤ u|m| + η` (`u = 2⁻⁵³`, `η = 2⁻¹⁰⁷⁴`
//! for an underflowing product; a sum is exact when it underflows). Unlike
//! [`crate::num::Interval`] (tightest, IEEE 1788) these bounds are not the tightest,
//! but they cost a handful of flops and no branches: about a fifth of an interval
//! product. Radii are computed in RN and made upper bounds by two primitives:
//!
//! * [`up`]`(x) = RN(RN(x + RN(x·2⁻⁵²)) + η)` for `x ≥ 0` is at least `next_up(x)`,
//!   hence at least every real whose RN is `x`: for normal `x ∈ [2^e, 2^{e+1})`,
//!   `x·2⁻⁵² ≥ 2^{e−52} = ulp(x)` and RN is monotone; for subnormal `x`, `x + η` is exact.
//! * [`inflate`]`(s)`, for `s` the RN value of a sum of at most 64 products `x_t·y_t` of
//!   non-negative doubles (any order): every term passes through at most 64 roundings,
//!   each a factor in `[1 − u, 1 + u]`, and an underflowing product adds at most `η/2`,
//!   so `Σ x_t y_t ≤ s/(1 − 64u) + 32η ≤ s(1 + 2⁻⁴⁶) + 2⁻¹⁰⁶⁹`. The returned
//!   `RN(RN(s(1 + 2⁻⁴⁵)) + 2⁻¹⁰⁶⁰)` exceeds that: for `s ≥ 2⁻¹⁰¹³` the multiplication
//!   alone gains at least `s·2⁻⁴⁷ ≥ 2⁻¹⁰⁶⁰`; below, the addition loses at most half an
//!   ulp of a number below `2⁻¹⁰¹²`, i.e. `2⁻¹⁰⁶⁵`.
//!
//! A NaN or infinite midpoint or radius means "unknown": callers check
//! [`MidRad::is_finite`] and fall back to interval arithmetic.

use super::real::Arith;
use super::Interval;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The smallest positive subnormal, `η = 2⁻¹⁰⁷⁴`.
pub const ETA: f64 = 5e-324;
/// `2⁻⁵²`.
pub const EPS: f64 = f64::EPSILON;
/// `2⁻⁵³`, the unit roundoff of RN.
pub const U: f64 = f64::EPSILON / 2.0;
/// `1 + 2⁻⁴⁵`.
const ONE_PLUS: f64 = 1.0 + 1.0 / (1u64 << 45) as f64;
/// `2⁻¹⁰⁶⁰` (subnormal: `2¹⁴ η`).
const TINY: f64 = ETA * 16384.0;

/// An upper bound of every real whose round-to-nearest is `x ≥ 0` (module doc).
#[inline(always)]
pub fn up(x: f64) -> f64 {
    (x + x * EPS) + ETA
}

/// A lower bound of every real whose round-to-nearest is `x ≥ 0`:
/// `RN(RN(x − RN(x·2⁻⁵²)) − η) ≤ prev(x)` by the argument of [`up`].
#[inline(always)]
pub fn down(x: f64) -> f64 {
    (x - x * EPS) - ETA
}

/// An upper bound of `Σ x_t y_t` from its RN value `s` (at most 64 non-negative terms;
/// module doc).
#[inline(always)]
pub fn inflate(s: f64) -> f64 {
    s * ONE_PLUS + TINY
}

/// The enclosure `[mid − rad, mid + rad]` (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MidRad {
    pub mid: f64,
    pub rad: f64,
}

impl MidRad {
    /// `⟨m, r⟩`; the caller proves that it encloses the quantity.
    #[inline(always)]
    pub fn new(mid: f64, rad: f64) -> MidRad {
        MidRad { mid, rad }
    }

    /// The same set as a non-empty, bounded interval (its IEEE 1788 midpoint and
    /// radius, the radius rounded up); an empty or unbounded one is "unknown".
    pub fn from_interval(x: &Interval) -> MidRad {
        if x.is_empty() || !x.is_bounded() {
            return MidRad::new(f64::NAN, f64::INFINITY);
        }
        MidRad::new(x.midpoint(), x.radius())
    }

    /// Both fields finite: the enclosure is meaningful.
    #[inline(always)]
    pub fn is_finite(&self) -> bool {
        self.mid.is_finite() && self.rad.is_finite()
    }

    /// The tightest interval containing `[mid − rad, mid + rad]` (outward by the
    /// interval addition); `None` if not finite.
    pub fn to_interval(&self) -> Option<Interval> {
        self.is_finite()
            .then(|| Interval::point(self.mid) + Interval::from_bounds(-self.rad, self.rad))
    }
}

impl Add for MidRad {
    type Output = MidRad;
    /// `|x + y − m| ≤ r_x + r_y + u|m|` (a sum that underflows is exact).
    #[inline(always)]
    fn add(self, y: MidRad) -> MidRad {
        let mid = self.mid + y.mid;
        MidRad::new(mid, inflate(self.rad + y.rad + U * mid.abs()))
    }
}

impl Sub for MidRad {
    type Output = MidRad;
    /// As [`Add`].
    #[inline(always)]
    fn sub(self, y: MidRad) -> MidRad {
        let mid = self.mid - y.mid;
        MidRad::new(mid, inflate(self.rad + y.rad + U * mid.abs()))
    }
}

impl Mul for MidRad {
    type Output = MidRad;
    /// `|xy − m| ≤ |m_x| r_y + r_x |m_y| + r_x r_y + u|m| + η`.
    #[inline(always)]
    fn mul(self, y: MidRad) -> MidRad {
        let mid = self.mid * y.mid;
        let rad = self.mid.abs() * y.rad + self.rad * y.mid.abs() + self.rad * y.rad;
        MidRad::new(mid, inflate(rad + U * mid.abs() + ETA))
    }
}

impl Div for MidRad {
    type Output = MidRad;
    /// For `y` bounded away from 0 above (`m_y − r_y > 0`): `x/y − m_x/m_y =
    /// ((x − m_x) m_y − m_x (y − m_y))/(y m_y)`, so `|x/y − m| ≤ (r_x + |m_x/m_y| r_y)/(m_y −
    /// r_y) + u|m| + η`, with `|m_x/m_y| ≤ up(|m|)` and the denominator rounded down.
    /// A divisor that may be ≤ 0 gives "unknown".
    #[inline(always)]
    fn div(self, y: MidRad) -> MidRad {
        let mid = self.mid / y.mid;
        let den = down(y.mid - y.rad);
        #[allow(clippy::neg_cmp_op_on_partial_ord)] // NaN is "unknown" too
        if !(den > 0.0) {
            return MidRad::new(f64::NAN, f64::INFINITY);
        }
        let num = inflate(self.rad + up(mid.abs()) * y.rad);
        MidRad::new(mid, inflate(up(num / den) + U * mid.abs() + ETA))
    }
}

impl Neg for MidRad {
    type Output = MidRad;
    /// Exact.
    #[inline(always)]
    fn neg(self) -> MidRad {
        MidRad::new(-self.mid, self.rad)
    }
}

/// The by-value and by-reference forms the generic formulas use, forwarded.
macro_rules! forward {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr<&MidRad> for &MidRad {
            type Output = MidRad;
            #[inline(always)]
            fn $f(self, y: &MidRad) -> MidRad {
                $tr::$f(*self, *y)
            }
        }
    )*};
}
forward!(Add add, Sub sub, Mul mul, Div div);

impl Add<&MidRad> for MidRad {
    type Output = MidRad;
    #[inline(always)]
    fn add(self, y: &MidRad) -> MidRad {
        self + *y
    }
}
impl Sub<&MidRad> for MidRad {
    type Output = MidRad;
    #[inline(always)]
    fn sub(self, y: &MidRad) -> MidRad {
        self - *y
    }
}
impl Mul<&MidRad> for MidRad {
    type Output = MidRad;
    #[inline(always)]
    fn mul(self, y: &MidRad) -> MidRad {
        self * *y
    }
}
impl Div<&MidRad> for MidRad {
    type Output = MidRad;
    #[inline(always)]
    fn div(self, y: &MidRad) -> MidRad {
        self / *y
    }
}

impl Arith for MidRad {
    /// `⟨v, 0⟩` (exact).
    #[inline(always)]
    fn lift(&self, v: f64) -> MidRad {
        MidRad::new(v, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;

    fn exact(x: f64) -> Rational {
        Rational::from_f64(x).unwrap()
    }

    /// `[m − r, m + r] ∋ q`, decided exactly.
    fn encloses(x: MidRad, q: &Rational) -> bool {
        let d = (q - exact(x.mid)).abs();
        d <= exact(x.rad)
    }

    #[test]
    fn constants_are_the_intended_powers_of_two() {
        assert_eq!(ETA.to_bits(), 1);
        assert_eq!(TINY.to_bits(), 1 << 14);
        assert_eq!(ONE_PLUS.to_bits(), 0x3FF0_0000_0000_0080);
        assert_eq!(U, 2f64.powi(-53));
    }

    #[test]
    fn up_and_down_bracket_the_neighbours() {
        for x in [
            0.0,
            ETA,
            3.0 * ETA,
            f64::MIN_POSITIVE,
            1.0,
            1.5,
            2.0,
            1e300,
            0.1,
        ] {
            let next = f64::from_bits(x.to_bits() + 1);
            assert!(up(x) >= next, "{x:e}");
            if x > 0.0 {
                let prev = f64::from_bits(x.to_bits() - 1);
                assert!(down(x) <= prev, "{x:e}");
            }
        }
    }

    #[test]
    fn inflate_bounds_sums_of_products_that_round_down() {
        // 64 products that each round down (and some underflow): the exact sum is above
        // the RN sum, and inflate covers it.
        let xs: Vec<f64> = (0..64).map(|i| 1.0 + (2 * i + 1) as f64 * EPS).collect();
        let mut s = 0.0;
        let mut exact_sum = Rational::new();
        for (i, &x) in xs.iter().enumerate() {
            let y = if i % 2 == 0 { 1.0 - EPS } else { 3e-310 };
            s += x * y;
            exact_sum += exact(x) * exact(y);
        }
        assert!(exact(inflate(s)) >= exact_sum);
        // The bound is not loose: within 2⁻⁴⁰ relative.
        assert!(exact(inflate(s)) <= exact_sum * exact(1.0 + 2f64.powi(-40)));
    }

    #[test]
    fn operations_enclose_the_exact_results_at_the_corners() {
        // x·y, x ± y, x/y at all corner combinations, exact in rationals.
        let cases = [
            (MidRad::new(0.1, 1e-17), MidRad::new(3.0, 1e-16)),
            (MidRad::new(-7.25, 0.5), MidRad::new(2.0 / 3.0, 0.1)),
            (MidRad::new(1e-300, 1e-310), MidRad::new(1e-20, 1e-30)),
            (MidRad::new(1e200, 1e180), MidRad::new(-3e-100, 1e-120)),
        ];
        for (x, y) in cases {
            // The exact endpoints m ± r of each operand.
            let ex = |a: MidRad, s: i32| {
                let (m, r) = (exact(a.mid), exact(a.rad));
                if s < 0 {
                    m - r
                } else {
                    m + r
                }
            };
            for sx in [-1, 1] {
                for sy in [-1, 1] {
                    let (qx, qy) = (ex(x, sx), ex(y, sy));
                    assert!(encloses(x + y, &Rational::from(&qx + &qy)));
                    assert!(encloses(x - y, &Rational::from(&qx - &qy)));
                    assert!(encloses(x * y, &Rational::from(&qx * &qy)));
                    if y.mid > 0.0 {
                        assert!(encloses(x / y, &Rational::from(&qx / &qy)));
                    }
                }
            }
        }
        // A divisor interval containing 0 is unknown.
        let bad = MidRad::new(1.0, 1.0) / MidRad::new(0.5, 0.5);
        assert!(!bad.is_finite());
    }

    #[test]
    fn conversions_keep_the_set() {
        let i = Interval::from_bounds(0.1, 0.30000000000000004);
        let m = MidRad::from_interval(&i);
        let back = m.to_interval().unwrap();
        assert!(i.is_subset(&back));
        assert!(MidRad::from_interval(&Interval::ENTIRE)
            .to_interval()
            .is_none());
    }
}
