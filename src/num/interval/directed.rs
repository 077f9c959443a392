//! Directed rounding of single f64 operations without switching the rounding mode.
//!
//! Each `*_up` function returns the exact result rounded toward +∞ (`*_down`: toward
//! −∞) — the tightest double bound, subnormal and overflow cases included. Method: the
//! hardware computes the round-to-nearest result `r`; an error-free transformation
//! (two_sum; two_prod via Dekker/Veltkamp splitting, or FMA where the target has it)
//! gives the exact sign of `exact − r` (FMA is used where the target has it at compile
//! time; the interval operations also detect it at run time on x86-64 and run an
//! FMA-compiled copy of themselves — allowed, unlike compile flags); if the exact value
//! lies above `r`, the upward
//! rounding is the next double above `r`, else `r` itself. Error-free transformations
//! are exact only away from overflow and underflow; outside the guarded ranges (stated
//! per function) the slow path asks MPFR for the correctly rounded result at 53 bits,
//! then for the directed conversion to a double (both roundings in the same direction,
//! so their composition is the directed rounding to doubles). Nothing here depends on
//! the FPU rounding mode or on compiler flags (BUILD-NOTES.md "Interval arithmetic").

use rug::float::Round;
use rug::ops::{AddAssignRound, DivAssignRound, MulAssignRound};
use rug::Float;

/// Below this magnitude (≥ 2^-960 ≈ 1.02e-289) a product's rounding error may not be a
/// double; the exactness condition of two_prod is e_a + e_b ≥ e_min + 52 = −970.
const TINY: f64 = 1e-288;
/// At most 2^995 ≈ 6.7e299: Veltkamp's split multiplies by 2^27 + 1, which must not
/// overflow.
const SPLIT_MAX: f64 = 1e299;
/// At most 2^1020 ≈ 1.1e307: the partial products of two_prod stay finite below this
/// product magnitude.
const PRODUCT_MAX: f64 = 1e307;

/// The least double greater than `x` (`+∞` and NaN are fixed points, `−∞` gives
/// `−f64::MAX`, both zeros give the least positive subnormal). Bit arithmetic, so the
/// crate does not depend on `f64::next_up` (Rust ≥ 1.86).
#[inline]
pub fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        x
    } else if x == 0.0 {
        f64::from_bits(1)
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

/// The greatest double less than `x` (mirror of [`next_up`]).
#[inline]
pub fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// `a + b` rounded up: two_sum gives the exact error `e` of `s = RN(a + b)`
/// (`s + e = a + b`, Knuth); the sum is exact if `e = 0`, above `s` if `e > 0`.
/// Subnormal sums are exact. Overflow: `RN(a + b) = +∞` from finite operands means the
/// exact sum exceeds `f64::MAX`, so `+∞` is its upward rounding; `−∞` from finite
/// operands means it is below `−f64::MAX`, whose upward rounding is `−f64::MAX`.
#[inline]
pub fn add_up(a: f64, b: f64) -> f64 {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    if e.is_finite() {
        if e > 0.0 {
            next_up(s)
        } else {
            s
        }
    } else {
        add_up_special(a, b, s)
    }
}

#[cold]
fn add_up_special(a: f64, b: f64, s: f64) -> f64 {
    if a.is_infinite() || b.is_infinite() || s.is_nan() {
        // An infinite operand makes the sum exact (∞ − ∞ never occurs for intervals).
        s
    } else if s == f64::NEG_INFINITY {
        -f64::MAX
    } else if s == f64::INFINITY {
        f64::INFINITY
    } else {
        mpfr_binary(a, b, Round::Up, |x, y, r| x.add_assign_round(y, r))
    }
}

/// `a + b` rounded down.
#[inline]
pub fn add_down(a: f64, b: f64) -> f64 {
    -add_up(-a, -b)
}

/// `a − b` rounded up.
#[inline]
pub fn sub_up(a: f64, b: f64) -> f64 {
    add_up(a, -b)
}

/// True where FMA is available at compile time (aarch64, or x86-64 built with `+fma`).
pub(crate) const STATIC_FMA: bool = cfg!(any(target_arch = "aarch64", target_feature = "fma"));

/// The exact rounding error `a·b − p` of `p = RN(a·b)`, valid when `|a|, |b| ≤ 2^995`,
/// `2^-960 ≤ |p| ≤ 2^1020` (no overflow in the split, error representable).
/// `FMA = true`: one fused multiply-add (call it only where FMA is a compile-time or
/// `#[target_feature]` feature, else it is a slow libm call); `FMA = false`: Dekker's
/// two_prod with Veltkamp's split (Dekker 1971; exactness without underflow: Boldo 2006).
#[inline(always)]
pub(crate) fn two_prod_err<const FMA: bool>(a: f64, b: f64, p: f64) -> f64 {
    if FMA {
        a.mul_add(b, -p)
    } else {
        dekker_err(a, b, p)
    }
}

/// True if the CPU executing this has FMA (runtime detection, cached by std); the
/// interval operations use it to run an FMA-compiled copy of themselves.
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
#[inline]
pub(crate) fn fma_detected() -> bool {
    std::arch::is_x86_feature_detected!("fma")
}

/// Dekker's two_prod error term (always compiled, so that tests check it on every
/// target against MPFR).
#[inline]
pub(crate) fn dekker_err(a: f64, b: f64, p: f64) -> f64 {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let ca = SPLITTER * a;
    let ah = ca - (ca - a);
    let al = a - ah;
    let cb = SPLITTER * b;
    let bh = cb - (cb - b);
    let bl = b - bh;
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

#[inline]
fn product_in_safe_range(a: f64, b: f64, p: f64) -> bool {
    let ap = p.abs();
    (TINY..=PRODUCT_MAX).contains(&ap) && a.abs() <= SPLIT_MAX && b.abs() <= SPLIT_MAX
}

/// `a·b` rounded up: the sign of the exact error of `RN(a·b)` decides (see module doc).
/// Outside `2^-960 ≤ |a·b| ≤ 2^1020` (or with an operand above 2^995), the slow path:
/// zeros give 0 (also `0·∞ = 0`, the interval convention), infinities are exact, and
/// the rest is MPFR's correctly rounded product.
#[inline]
pub fn mul_up(a: f64, b: f64) -> f64 {
    mul_up_k::<STATIC_FMA>(a, b)
}

/// [`mul_up`] with the error term chosen by `FMA` (see [`two_prod_err`]).
#[inline(always)]
pub(crate) fn mul_up_k<const FMA: bool>(a: f64, b: f64) -> f64 {
    let p = a * b;
    if product_in_safe_range(a, b, p) {
        if two_prod_err::<FMA>(a, b, p) > 0.0 {
            next_up(p)
        } else {
            p
        }
    } else {
        mul_up_special(a, b, p)
    }
}

#[cold]
fn mul_up_special(a: f64, b: f64, p: f64) -> f64 {
    if a == 0.0 || b == 0.0 {
        0.0
    } else if a.is_infinite() || b.is_infinite() {
        p
    } else {
        mpfr_binary(a, b, Round::Up, |x, y, r| x.mul_assign_round(y, r))
    }
}

/// `a·b` rounded down.
#[inline]
pub fn mul_down(a: f64, b: f64) -> f64 {
    -mul_up(-a, b)
}

/// `a / b` rounded up (`b ≠ 0`). `q = RN(a/b)`; with `p + e = q·b` exactly (two_prod),
/// the remainder `a − q·b = (a − p) − e`, where `a − p` is exact (Sterbenz: `p` is
/// within a factor `1 + 2u` of `a`) and the final subtraction has the correct sign.
/// The exact quotient exceeds `q` iff the remainder has the sign of `b`.
/// Fast path for `2^-960 ≤ |a| ≤ 2^1020` and `|q|, |b|` in the two_prod range;
/// otherwise exact special values (infinities, zero dividend) or MPFR.
#[inline]
pub fn div_up(a: f64, b: f64) -> f64 {
    div_up_k::<STATIC_FMA>(a, b)
}

/// [`div_up`] with the error term chosen by `FMA`.
#[inline(always)]
pub(crate) fn div_up_k<const FMA: bool>(a: f64, b: f64) -> f64 {
    let q = a / b;
    let aa = a.abs();
    if (TINY..=PRODUCT_MAX).contains(&aa) && product_in_safe_range(q, b, q * b) {
        let p = q * b;
        let e = two_prod_err::<FMA>(q, b, p);
        let r = (a - p) - e;
        if r != 0.0 && (r > 0.0) == (b > 0.0) {
            next_up(q)
        } else {
            q
        }
    } else {
        div_up_special(a, b, q)
    }
}

#[cold]
fn div_up_special(a: f64, b: f64, q: f64) -> f64 {
    if a == 0.0 || a.is_infinite() || b.is_infinite() || b == 0.0 {
        q
    } else {
        mpfr_binary(a, b, Round::Up, |x, y, r| x.div_assign_round(y, r))
    }
}

/// `a / b` rounded down.
#[inline]
pub fn div_down(a: f64, b: f64) -> f64 {
    -div_up(-a, b)
}

/// Sign of `x − RN(√x)²` as −1, 0, 1, for `2^-960 ≤ x ≤ 2^1020` (two_prod of the
/// root, Sterbenz for `x − p`); `None` outside that range.
#[inline(always)]
fn sqrt_residual_sign<const FMA: bool>(x: f64, s: f64) -> Option<i8> {
    if (TINY..=PRODUCT_MAX).contains(&x) {
        let p = s * s;
        let r = (x - p) - two_prod_err::<FMA>(s, s, p);
        Some(if r > 0.0 {
            1
        } else if r < 0.0 {
            -1
        } else {
            0
        })
    } else {
        None
    }
}

/// `√x` rounded up, `x ≥ 0` (IEEE `sqrt` is correctly rounded to nearest; the residual
/// `x − s²` says on which side of `s` the exact root lies). MPFR outside the safe range.
#[inline]
pub fn sqrt_up(x: f64) -> f64 {
    sqrt_up_k::<STATIC_FMA>(x)
}

/// [`sqrt_up`] with the error term chosen by `FMA`.
#[inline(always)]
pub(crate) fn sqrt_up_k<const FMA: bool>(x: f64) -> f64 {
    let s = x.sqrt();
    match sqrt_residual_sign::<FMA>(x, s) {
        Some(1) => next_up(s),
        Some(_) => s,
        None => sqrt_special(x, s, Round::Up),
    }
}

/// `√x` rounded down, `x ≥ 0`.
#[inline]
pub fn sqrt_down(x: f64) -> f64 {
    sqrt_down_k::<STATIC_FMA>(x)
}

/// [`sqrt_down`] with the error term chosen by `FMA`.
#[inline(always)]
pub(crate) fn sqrt_down_k<const FMA: bool>(x: f64) -> f64 {
    let s = x.sqrt();
    match sqrt_residual_sign::<FMA>(x, s) {
        Some(-1) => next_down(s),
        Some(_) => s,
        None => sqrt_special(x, s, Round::Down),
    }
}

#[cold]
fn sqrt_special(x: f64, s: f64, round: Round) -> f64 {
    if x == 0.0 || x.is_infinite() || x.is_nan() {
        s
    } else {
        let mut f = Float::with_val(53, x);
        f.sqrt_round(round);
        f.to_f64_round(round)
    }
}

/// MPFR fallback: `op(a, b)` correctly rounded at 53 bits in direction `round`, then
/// converted to a double in the same direction (exact unless the result is subnormal or
/// out of range, where the conversion rounds in the same direction).
fn mpfr_binary(
    a: f64,
    b: f64,
    round: Round,
    op: impl FnOnce(&mut Float, &Float, Round) -> std::cmp::Ordering,
) -> f64 {
    let mut x = Float::with_val(53, a);
    let y = Float::with_val(53, b);
    op(&mut x, &y, round);
    x.to_f64_round(round)
}
