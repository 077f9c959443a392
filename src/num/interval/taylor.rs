//! Fast proven enclosures of `sin x`, `cos x` and `exp x` at a double `x`: argument
//! reduction with error-free transformations, a Taylor polynomial evaluated in plain
//! f64 (Horner), and an a-priori bound on every error, derived below in `u = 2^-53`:
//! rounding in the reduction (`ε_r`), rounding in the evaluation (Higham, *Accuracy and
//! Stability of Numerical Algorithms*, 2nd ed., eq. (5.2): Horner's result is
//! `Σ c_i z^i (1 + θ_{2i+1})`, `|θ_k| ≤ γ_k = ku/(1 − ku)`), rounding of the
//! coefficients (each the nearest double to `±1/n!`, relative error ≤ u), and the Lagrange
//! remainder of the truncated series. The enclosure is `[ŷ − E', ŷ + E']` rounded outward
//! with `E' = E·(1 + 2^-40)` (+ `64·2^-1074` for results below 10^-270): the factor
//! covers the ≤ 20 roundings in computing `E` itself, the additive term any underflow. A few ulps wide, not
//! tightest; the callers use MPFR outside `|x| ≤ 2^19` (trig) and `|x| ≤ 700` (exp).
//! The numeric constants of each bound are re-derived from their definitions at 300 bits
//! by the test `taylor_error_bound_constants_rederived`; the enclosures are checked
//! against 200-bit MPFR values (`taylor_sin_cos_exp_enclose_200_bit_values…`) and, per
//! interval, against a brute-force 2000-bit range (tests/interval_elementary.rs).
//!
//! Constants, each checked by `taylor_constants_are_what_they_claim`: `P1`, `P2` are the
//! first two 33-bit pieces of π/2 (31 and 32 significant bits), `P3` the double nearest
//! to `π/2 − P1 − P2` with `|P3 − (π/2 − P1 − P2)| ≤ D3 = 2^-121`; `L1` is ln 2 truncated
//! to 32 bits, `L2` the nearest double to `ln 2 − L1`, error ≤ `D2 = 2^-85`; the series
//! coefficients are nearest doubles to `±1/n!`.

use super::directed::{add_down, add_up};
use super::Interval;

/// |x| ≤ 2^19 for the trigonometric fast path: `k = round(2x/π)` has at most 19 bits,
/// so `k·P1` (31-bit `P1`) and `k·P2` (32-bit `P2`) are exact doubles.
pub(crate) const TRIG_FAST_MAX: f64 = 524_288.0;
/// |x| ≤ 700 for the exponential fast path: `|k| ≤ 1010` (so `k·L1` is exact) and
/// `2^k·[0.7, 1.42]` stays in the normal range, so scaling by `2^k` is exact.
pub(crate) const EXP_FAST_MAX: f64 = 700.0;

/// u = 2^-53, the unit roundoff.
const U: f64 = f64::EPSILON / 2.0;
/// Slack for the roundings in computing an error bound (≥ 20u relative).
const BOUND_SLACK: f64 = 1.0 + 1.0 / (1u64 << 40) as f64;

pub(crate) const P1: f64 = 1.570_796_326_734_125_6; // 0x3ff921fb54400000
pub(crate) const P2: f64 = 6.077_100_506_303_966e-11; // 0x3dd0b4611a600000
pub(crate) const P3: f64 = 2.022_266_248_795_950_6e-21; // 0x3ba3198a2e037073
pub(crate) const D3: f64 = 3.761_581_922_631_32e-37; // 2^-121
pub(crate) const L1: f64 = 0.693_147_180_369_123_8; // 0x3fe62e42fee00000
pub(crate) const L2: f64 = 1.908_214_929_270_587_7e-10; // 0x3dea39ef35793c76
pub(crate) const D2: f64 = 2.584_939_414_228_211_5e-26; // 2^-85

/// sin r = r + r·z·Σ SIN_C[i]·z^i (z = r²), SIN_C[i] ≈ (−1)^(i+1)/(2i+3)!: degree 17.
pub(crate) const SIN_C: [f64; 8] = [
    -0.16666666666666666,
    0.008333333333333333,
    -0.0001984126984126984,
    2.7557319223985893e-06,
    -2.505210838544172e-08,
    1.6059043836821613e-10,
    -7.647163731819816e-13,
    2.8114572543455206e-15,
];
/// cos r = 1 + z·Σ COS_C[i]·z^i, COS_C[i] ≈ (−1)^(i+1)/(2i+2)!: degree 18.
pub(crate) const COS_C: [f64; 9] = [
    -0.5,
    0.041666666666666664,
    -0.001388888888888889,
    2.48015873015873e-05,
    -2.755731922398589e-07,
    2.08767569878681e-09,
    -1.1470745597729725e-11,
    4.779477332387385e-14,
    -1.5619206968586225e-16,
];
/// exp r = 1 + r·Σ EXP_C[i]·r^i, EXP_C[i] ≈ 1/(i+1)!: degree 15.
pub(crate) const EXP_C: [f64; 15] = [
    1.0,
    0.5,
    0.16666666666666666,
    0.041666666666666664,
    0.008333333333333333,
    0.001388888888888889,
    0.0001984126984126984,
    2.48015873015873e-05,
    2.7557319223985893e-06,
    2.755731922398589e-07,
    2.505210838544172e-08,
    2.08767569878681e-09,
    1.6059043836821613e-10,
    1.1470745597729725e-11,
    7.647163731819816e-13,
];

/// Knuth's two_sum: `s + e = a + b` exactly (no overflow in our ranges).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

#[inline]
fn horner(c: &[f64], z: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &ci| acc * z + ci)
}

/// The interval `[ŷ − E', ŷ + E']` rounded outward (module doc). The additive
/// `64·2^-1074` (covering underflow in computing `E`) is needed only when `0 < |ŷ| <
/// 10^-270`: otherwise `E ≥ u|ŷ| > 10^-286` and the relative slack `E·2^-40` already
/// exceeds any absolute underflow error; `ŷ = 0` comes only from `r = 0` exactly
/// (sin 0 = 0, with `E = ε_r`).
#[inline]
fn enclose(y: f64, e: f64) -> Interval {
    let tiny = if y != 0.0 && y.abs() < 1e-270 {
        64.0 * f64::from_bits(1)
    } else {
        0.0
    };
    let e = e * BOUND_SLACK + tiny;
    Interval::from_neg_lo_hi(-add_down(y, -e), add_up(y, e))
}

/// `x = k·π/2 + r_true` for `|x| ≤ TRIG_FAST_MAX`: returns `k = round(x·2/π)`, a double
/// `r` and `ε_r ≥ |r_true − r|`; `|r| ≤ π/4 + 2^-30`.
///
/// `k = 0`: `r = x`, `ε_r = 0`. Otherwise `k·P1`, `k·P2` are exact, two_sum gives
/// `t + e0 = x − k·P1` and `s + e1 = t − k·P2` exactly; `c = fl(k·P3)`, `f = fl(e0 + e1)`,
/// `d = fl(f − c)`, `r = fl(s + d)`. Then `r_true = s + e1 + e0 − k(π/2 − P1 − P2)`, and
/// each of the four roundings errs by at most `u` times its result, the constant by
/// `|k|·D3`: `ε_r = u(|r| + |d| + |f| + |c|) + |k|·D3` (computed with `BOUND_SLACK`; all
/// terms ≥ 2^-121, no underflow).
#[inline]
pub(crate) fn reduce_half_pi(x: f64) -> (i64, f64, f64) {
    let k = (x * std::f64::consts::FRAC_2_PI).round();
    if k == 0.0 {
        return (0, x, 0.0);
    }
    let (t, e0) = two_sum(x, -(k * P1));
    let (s, e1) = two_sum(t, -(k * P2));
    let c = k * P3;
    let f = e0 + e1;
    let d = f - c;
    let r = s + d;
    let er = (((r.abs() + d.abs()) + (f.abs() + c.abs())) * U + k.abs() * D3) * BOUND_SLACK;
    (k as i64, r, er)
}

/// `(ŷ, E)` with `|sin r − ŷ| ≤ E` for `|r| ≤ 0.8` (so `z̃ = fl(r²) ≤ 0.7`):
/// `ŷ = fl(r + fl(r·fl(z̃·q̂)))`, `q̂` Horner of `SIN_C` at `z̃`.
/// * Horner and the two products: term i carries `θ_{2i+3}`, so the error is at most
///   `|r|z̃(γ_3/6 + γ_17·Σ_{i≥1}|c_i|z̃^i) ≤ |r|z̃·u(0.5001 + 0.1446z̃)`
///   (`Σ_{i≥1} z̃^i/(2i+3)! ≤ 1.02·z̃/120` for `z̃ ≤ 0.7`);
/// * coefficients: `|r|z̃·u·Σ|a_i|z̃^i ≤ |r|z̃·u(0.1667 + 0.0085z̃)`;
/// * `z̃ = z(1 + δ)`: `|∂/∂z (r z A(z))| ≤ |r|(1/6 + 0.018z)`, so `|r|z̃·u(0.1668 + 0.0181z̃)`;
/// * the last addition: `u|ŷ|/(1 − u) ≤ 1.0001u|ŷ|`;
/// * remainder: `|r|^19/19! ≤ 8.23·10^-18·|r|z̃^9`.
///
/// Sum: `E = 1.0001u|ŷ| + u|r|z̃(0.84 + 0.18z̃) + 8.23·10^-18·|r|z̃^9`.
#[inline]
pub(crate) fn sin_poly(r: f64) -> (f64, f64) {
    let z = r * r;
    let q = horner(&SIN_C, z);
    let y = r + r * (z * q);
    let ar = r.abs();
    let z3 = z * z * z;
    let e = 1.0001 * U * y.abs() + U * ar * z * (0.84 + 0.18 * z) + 8.23e-18 * ar * (z3 * z3 * z3);
    (y, e)
}

/// `(ŷ, E)` with `|cos r − ŷ| ≤ E` for `|r| ≤ 0.8`: `ŷ = fl(1 + fl(z̃·q̂))`, `q̂` Horner
/// of `COS_C` at `z̃`.
/// * Horner and the product: term i carries `θ_{2i+2}`:
///   `z̃(γ_2/2 + γ_18·Σ_{i≥1}|c_i|z̃^i) ≤ z̃u(1.0001 + 0.77z̃)`;
/// * coefficients (`−1/2` is exact): `z̃u·0.0427z̃`;
/// * `z̃ = z(1 + δ)`: `|∂/∂z (1 + zB(z))| ≤ 0.5 + 0.087z`, so `z̃u(0.5001 + 0.0871z̃)`;
/// * the last addition: `1.0001u|ŷ|`; remainder `z^10/20! ≤ 4.12·10^-19·z̃^10`.
///
/// Sum: `E = 1.0001u|ŷ| + z̃u(1.51 + 0.91z̃) + 4.12·10^-19·z̃^10`.
#[inline]
pub(crate) fn cos_poly(r: f64) -> (f64, f64) {
    let z = r * r;
    let q = horner(&COS_C, z);
    let y = 1.0 + z * q;
    let z2 = z * z;
    let z4 = z2 * z2;
    let e = 1.0001 * U * y.abs() + U * z * (1.51 + 0.91 * z) + 4.12e-19 * (z4 * z4 * z2);
    (y, e)
}

/// `(ŷ, E)` with `|exp r − ŷ| ≤ E` for `|r| ≤ 0.35`: `ŷ = fl(1 + fl(r·q̂))`, `q̂` Horner
/// of `EXP_C` at `r`.
/// * Horner and the product: `|r|·Σ γ_{2i+2}|r|^i/(i+1)! ≤ |r|u·1.0001·(2 + 2(e^{|r|} − 1))
///   ≤ |r|u(2.0002 + 2.39|r|)`;
/// * coefficients (the first two exact): `|r|u(e^{|r|} − 1 − |r|) ≤ 0.57u·r²`;
/// * the last addition: `1.0001u|ŷ|`; remainder `e^{|r|}|r|^16/16! ≤ 6.8·10^-14·r^16`.
///
/// Sum: `E = 1.0001u|ŷ| + |r|u(2.001 + 2.97|r|) + 6.8·10^-14·r^16`.
#[inline]
pub(crate) fn exp_poly(r: f64) -> (f64, f64) {
    let q = horner(&EXP_C, r);
    let y = 1.0 + r * q;
    let ar = r.abs();
    let r2 = r * r;
    let r4 = r2 * r2;
    let r8 = r4 * r4;
    let e = 1.0001 * U * y.abs() + U * ar * (2.001 + 2.97 * ar) + 6.8e-14 * (r8 * r8);
    (y, e)
}

/// `±f(r)` for the quadrant: `sin x = sin r, cos r, −sin r, −cos r` and
/// `cos x = cos r, −sin r, −cos r, sin r` for `k ≡ 0, 1, 2, 3 (mod 4)`.
#[inline]
fn quadrant(k: i64, r: f64, cosine: bool) -> (f64, f64) {
    let q = (k + i64::from(cosine)).rem_euclid(4);
    let (y, e) = if q % 2 == 0 { sin_poly(r) } else { cos_poly(r) };
    if q >= 2 {
        (-y, e)
    } else {
        (y, e)
    }
}

/// An enclosure of `sin x` (`cosine = false`) or `cos x` for `x = kπ/2 + r`,
/// `|r − r_true| ≤ er` (both are 1-Lipschitz, so `er` adds to the bound), intersected
/// with [−1, 1].
#[inline]
pub(crate) fn sin_cos_reduced(k: i64, r: f64, er: f64, cosine: bool) -> Interval {
    let (y, e) = quadrant(k, r, cosine);
    enclose(y, e + er).intersection(&Interval::from_neg_lo_hi(1.0, 1.0))
}

/// An enclosure of `tan x` as `sin x / cos x` in interval arithmetic, or `None` when the
/// cosine enclosure contains 0 (next to a pole: the caller uses MPFR).
pub(crate) fn tan_reduced(k: i64, r: f64, er: f64) -> Option<Interval> {
    let c = sin_cos_reduced(k, r, er, true);
    if c.contains_zero() {
        None
    } else {
        Some(sin_cos_reduced(k, r, er, false).div(&c))
    }
}

/// An enclosure of `exp x` for `|x| ≤ EXP_FAST_MAX`. Reduction: `k = round(x·log2 e)`,
/// `t + e0 = x − k·L1` (two_sum; `k·L1` exact), `c = fl(k·L2)`, `d = fl(e0 − c)`,
/// `r = fl(t + d)`, `|r| ≤ 0.35`, `ε_r = u(|r| + |d| + |c|) + |k|·D2`; `exp` is
/// `e^{0.36} ≤ 1.44`-Lipschitz there, so `E = E_poly + 1.44ε_r`. Then
/// `exp x = 2^k·exp r`, an exact scaling of both bounds in the normal range.
pub(crate) fn exp_point(x: f64) -> Interval {
    let k = (x * std::f64::consts::LOG2_E).round();
    let (r, er) = if k == 0.0 {
        (x, 0.0)
    } else {
        let (t, e0) = two_sum(x, -(k * L1));
        let c = k * L2;
        let d = e0 - c;
        let r = t + d;
        (
            r,
            ((r.abs() + d.abs() + c.abs()) * U + k.abs() * D2) * BOUND_SLACK,
        )
    };
    let (y, e) = exp_poly(r);
    let enc = enclose(y, e + 1.44 * er);
    // 2^k as a double (k + 1023 ∈ [13, 2033]: normal).
    let scale = f64::from_bits(((k as i64 + 1023) as u64) << 52);
    Interval::from_neg_lo_hi(enc.neg_lo() * scale, enc.hi() * scale)
}
