//! The scalar type of the filter tier: one `f64`, or [`F4`] (and, on x86-64 with
//! AVX-512, [`super::lane8::F8`]), independent `f64` lanes evaluated together (the batch
//! entry points of the linear kernel, which run a group of cases of the same shape
//! through one formula).
//!
//! The double-double arithmetic ([`crate::num::dd`]) and the rounding tests
//! ([`crate::num::filter`]) are written once over [`Lane`]. Every operation of `F4` is
//! the `f64` operation applied lane by lane (IEEE 754 binary64, round to nearest, the
//! same fused `mul_add`), so each lane computes bit for bit what the scalar code
//! computes for its case and every error bound proved for one `f64` holds lane-wise. On
//! x86-64 each operation is one AVX intrinsic (the batch kernels are compiled with AVX
//! and FMA enabled, runtime-detected as for the scalar FMA path); elsewhere the
//! portable arrays below (checked against the AVX lanes by a test).
//!
//! Tests are comparisons in [`Lane::Mask`] form, written as the condition to *accept*
//! (`a ≤ b`, never `!(a > b)`): a comparison with NaN is false, so NaN anywhere fails
//! every acceptance test, as in the scalar code.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Sub};

/// A number type of the filter: `f64` or a group of `f64` lanes.
pub trait Lane:
    Copy
    + std::fmt::Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + 'static
{
    /// The result of a comparison: `bool`, or one `bool` per lane.
    type Mask: Copy + std::fmt::Debug + BitAnd<Output = Self::Mask> + BitOr<Output = Self::Mask>;
    /// A witness that values are lane groups: `()` for [`Wide`] types, uninhabited
    /// ([`std::convert::Infallible`]) for `f64`. A variant that only lane groups can
    /// hold (planes of mixed kinds, `geom::raw`) carries one, so that for one case the
    /// compiler knows it cannot occur and its code costs the scalar path nothing.
    type Group: Copy + std::fmt::Debug;
    /// `x` in every lane.
    fn splat(x: f64) -> Self;
    /// `self·b + c` with one rounding (the caller enables FMA; `f64::mul_add`).
    fn fused_mul_add(self, b: Self, c: Self) -> Self;
    /// `|self|` (exact).
    fn abs(self) -> Self;
    /// `if self > b { self } else { b }` (so `b` when either is NaN, as `vmaxpd`).
    fn max(self, b: Self) -> Self;
    /// `self < b` (false for NaN).
    fn less(self, b: Self) -> Self::Mask;
    /// `self ≤ b` (false for NaN).
    fn less_eq(self, b: Self) -> Self::Mask;
    /// `self == b` (false for NaN).
    fn equal(self, b: Self) -> Self::Mask;
    /// `if m { a } else { b }`, lane-wise.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// True when some lane of `m` is true.
    fn any(m: Self::Mask) -> bool;
    /// The power of two `2^e` with `2^e ≤ |self| < 2^(e+1)` for a normal double: the
    /// exponent field alone (exact, no rounding).
    fn exponent_power(self) -> Self;
}

impl Lane for f64 {
    type Mask = bool;
    type Group = std::convert::Infallible;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn fused_mul_add(self, b: Self, c: Self) -> Self {
        self.mul_add(b, c)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn max(self, b: Self) -> Self {
        if self > b {
            self
        } else {
            b
        }
    }
    #[inline(always)]
    fn less(self, b: Self) -> bool {
        self < b
    }
    #[inline(always)]
    fn less_eq(self, b: Self) -> bool {
        self <= b
    }
    #[inline(always)]
    fn equal(self, b: Self) -> bool {
        self == b
    }
    #[inline(always)]
    fn any(m: bool) -> bool {
        m
    }
    #[inline(always)]
    fn select(m: bool, a: Self, b: Self) -> Self {
        if m {
            a
        } else {
            b
        }
    }
    #[inline(always)]
    fn exponent_power(self) -> Self {
        f64::from_bits(self.to_bits() & EXPONENT_BITS)
    }
}

pub(crate) const EXPONENT_BITS: u64 = 0x7ff << 52;

/// The most lanes of any [`Wide`] type.
pub const MAX_LANES: usize = 8;

/// A lane type of several cases: [`F4`] (AVX) or, on x86-64, [`F8`](super::lane8::F8)
/// (AVX-512).
pub trait Wide: Lane {
    /// The number of lanes (at most [`MAX_LANES`]).
    const N: usize;
    /// Lane `i` set to `f(i)`, for `i < N`.
    fn from_fn(f: impl FnMut(usize) -> f64) -> Self;
    /// The lanes into `out[..N]`.
    fn store(self, out: &mut [f64; MAX_LANES]);
    /// A mask as bits (bit `i` set when lane `i` is true).
    fn bits(m: Self::Mask) -> u32;
    /// The lane-group witness.
    fn group() -> Self::Group;
}

/// Four `f64` lanes: one AVX register on x86-64, an array elsewhere.
///
/// On x86-64 every operation is one AVX instruction (`vaddpd`, `vfmadd…pd`, `vcmppd`,
/// …): code using `F4` must only run on a CPU with AVX and FMA, and be compiled inside
/// a `#[target_feature(enable = "avx,fma")]` function (the batch kernels check
/// `geom::batch::avx_fma_available` and otherwise take the scalar path).
#[derive(Clone, Copy)]
#[repr(transparent)]
pub struct F4(imp::V);

/// One comparison result per lane.
#[derive(Clone, Copy)]
#[repr(transparent)]
pub struct M4(imp::V);

impl F4 {
    /// The four lanes.
    #[inline(always)]
    pub fn new(x: [f64; 4]) -> F4 {
        F4(imp::load(x))
    }
    /// The four lanes as an array.
    #[inline(always)]
    pub fn lanes(self) -> [f64; 4] {
        imp::store(self.0)
    }
    /// Lane `i`.
    #[inline(always)]
    pub fn lane(self, i: usize) -> f64 {
        self.lanes()[i]
    }
}

impl std::fmt::Debug for F4 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "F4({:?})", self.lanes())
    }
}

impl PartialEq for F4 {
    fn eq(&self, b: &F4) -> bool {
        self.lanes() == b.lanes()
    }
}

impl M4 {
    /// One bit per lane (bit `i` set when lane `i` is true).
    #[inline(always)]
    pub fn bits(self) -> u32 {
        imp::movemask(self.0)
    }
    /// Lane `i`.
    #[inline(always)]
    pub fn lane(self, i: usize) -> bool {
        self.bits() >> i & 1 == 1
    }
}

impl std::fmt::Debug for M4 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "M4({:04b})", self.bits())
    }
}

macro_rules! f4_op {
    ($tr:ident, $f:ident) => {
        impl $tr for F4 {
            type Output = F4;
            #[inline(always)]
            fn $f(self, b: F4) -> F4 {
                F4(imp::$f(self.0, b.0))
            }
        }
    };
}
f4_op!(Add, add);
f4_op!(Sub, sub);
f4_op!(Mul, mul);
f4_op!(Div, div);

impl Neg for F4 {
    type Output = F4;
    #[inline(always)]
    fn neg(self) -> F4 {
        F4(imp::xor(self.0, imp::splat(-0.0)))
    }
}

impl BitAnd for M4 {
    type Output = M4;
    #[inline(always)]
    fn bitand(self, b: M4) -> M4 {
        M4(imp::and(self.0, b.0))
    }
}

impl BitOr for M4 {
    type Output = M4;
    #[inline(always)]
    fn bitor(self, b: M4) -> M4 {
        M4(imp::or(self.0, b.0))
    }
}

impl Lane for F4 {
    type Mask = M4;
    type Group = ();
    #[inline(always)]
    fn splat(x: f64) -> Self {
        F4(imp::splat(x))
    }
    #[inline(always)]
    fn fused_mul_add(self, b: Self, c: Self) -> Self {
        F4(imp::fmadd(self.0, b.0, c.0))
    }
    #[inline(always)]
    fn abs(self) -> Self {
        F4(imp::andnot(imp::splat(-0.0), self.0))
    }
    #[inline(always)]
    fn max(self, b: Self) -> Self {
        F4(imp::max(self.0, b.0))
    }
    #[inline(always)]
    fn less(self, b: Self) -> M4 {
        M4(imp::lt(self.0, b.0))
    }
    #[inline(always)]
    fn less_eq(self, b: Self) -> M4 {
        M4(imp::le(self.0, b.0))
    }
    #[inline(always)]
    fn equal(self, b: Self) -> M4 {
        M4(imp::eq(self.0, b.0))
    }
    #[inline(always)]
    fn any(m: M4) -> bool {
        m.bits() != 0
    }
    #[inline(always)]
    fn select(m: M4, a: Self, b: Self) -> Self {
        F4(imp::blend(b.0, a.0, m.0))
    }
    #[inline(always)]
    fn exponent_power(self) -> Self {
        F4(imp::and(self.0, imp::splat(f64::from_bits(EXPONENT_BITS))))
    }
}

impl Wide for F4 {
    const N: usize = 4;
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        F4::new([f(0), f(1), f(2), f(3)])
    }
    #[inline(always)]
    fn store(self, out: &mut [f64; MAX_LANES]) {
        out[..4].copy_from_slice(&self.lanes());
    }
    #[inline(always)]
    fn bits(m: M4) -> u32 {
        m.bits()
    }
    #[inline(always)]
    fn group() {}
}

/// True when [`F4`] can run here: x86-64 with AVX and FMA (runtime detection);
/// elsewhere the portable lanes always can.
#[inline]
pub fn available() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::is_x86_feature_detected!("avx") && std::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        true
    }
}

/// AVX intrinsics (each the IEEE operation of the scalar code, lane by lane).
#[cfg(target_arch = "x86_64")]
mod imp {
    use std::arch::x86_64::*;
    pub type V = __m256d;
    // SAFETY (every function): AVX/FMA instructions, executed only where the batch
    // kernels have checked the CPU (see `F4`); no memory is touched except the local
    // arrays of `load`/`store`.
    #[inline(always)]
    /// From four values (register inserts, not a 256-bit load of four separate
    /// stores, which would stall store forwarding).
    pub fn load(x: [f64; 4]) -> V {
        unsafe { _mm256_set_pd(x[3], x[2], x[1], x[0]) }
    }
    #[inline(always)]
    pub fn store(v: V) -> [f64; 4] {
        let mut x = [0.0; 4];
        unsafe { _mm256_storeu_pd(x.as_mut_ptr(), v) };
        x
    }
    #[inline(always)]
    pub fn splat(x: f64) -> V {
        unsafe { _mm256_set1_pd(x) }
    }
    #[inline(always)]
    pub fn add(a: V, b: V) -> V {
        unsafe { _mm256_add_pd(a, b) }
    }
    #[inline(always)]
    pub fn sub(a: V, b: V) -> V {
        unsafe { _mm256_sub_pd(a, b) }
    }
    #[inline(always)]
    pub fn mul(a: V, b: V) -> V {
        unsafe { _mm256_mul_pd(a, b) }
    }
    #[inline(always)]
    pub fn div(a: V, b: V) -> V {
        unsafe { _mm256_div_pd(a, b) }
    }
    /// `a > b ? a : b` lane-wise (`b` when either is NaN).
    #[inline(always)]
    pub fn max(a: V, b: V) -> V {
        unsafe { _mm256_max_pd(a, b) }
    }
    #[inline(always)]
    pub fn fmadd(a: V, b: V, c: V) -> V {
        unsafe { _mm256_fmadd_pd(a, b, c) }
    }
    #[inline(always)]
    pub fn and(a: V, b: V) -> V {
        unsafe { _mm256_and_pd(a, b) }
    }
    #[inline(always)]
    pub fn or(a: V, b: V) -> V {
        unsafe { _mm256_or_pd(a, b) }
    }
    /// `!a & b`.
    #[inline(always)]
    pub fn andnot(a: V, b: V) -> V {
        unsafe { _mm256_andnot_pd(a, b) }
    }
    #[inline(always)]
    pub fn xor(a: V, b: V) -> V {
        unsafe { _mm256_xor_pd(a, b) }
    }
    /// Ordered, non-signalling comparisons: false when either side is NaN.
    #[inline(always)]
    pub fn lt(a: V, b: V) -> V {
        unsafe { _mm256_cmp_pd::<_CMP_LT_OQ>(a, b) }
    }
    #[inline(always)]
    pub fn le(a: V, b: V) -> V {
        unsafe { _mm256_cmp_pd::<_CMP_LE_OQ>(a, b) }
    }
    #[inline(always)]
    pub fn eq(a: V, b: V) -> V {
        unsafe { _mm256_cmp_pd::<_CMP_EQ_OQ>(a, b) }
    }
    /// Lane `i` of `b` where the mask is set, else of `a`.
    #[inline(always)]
    pub fn blend(a: V, b: V, m: V) -> V {
        unsafe { _mm256_blendv_pd(a, b, m) }
    }
    #[inline(always)]
    pub fn movemask(m: V) -> u32 {
        unsafe { _mm256_movemask_pd(m) as u32 }
    }
}

#[cfg(not(target_arch = "x86_64"))]
use portable as imp;

/// Portable lanes (arrays; the same IEEE operations lane by lane). Masks are all-ones
/// or zero bit patterns, as on x86-64. (Compiled on x86-64 for the tests, which check
/// it against the AVX lanes.)
#[cfg(any(not(target_arch = "x86_64"), test))]
#[allow(dead_code)]
mod portable {
    pub type V = [f64; 4];
    fn zip(a: V, b: V, f: impl Fn(f64, f64) -> f64) -> V {
        [f(a[0], b[0]), f(a[1], b[1]), f(a[2], b[2]), f(a[3], b[3])]
    }
    fn bits(a: V, b: V, f: impl Fn(u64, u64) -> u64) -> V {
        zip(a, b, |x, y| f64::from_bits(f(x.to_bits(), y.to_bits())))
    }
    fn mask(a: V, b: V, f: impl Fn(f64, f64) -> bool) -> V {
        zip(a, b, |x, y| {
            f64::from_bits(if f(x, y) { u64::MAX } else { 0 })
        })
    }
    pub fn load(x: [f64; 4]) -> V {
        x
    }
    pub fn store(v: V) -> [f64; 4] {
        v
    }
    pub fn splat(x: f64) -> V {
        [x; 4]
    }
    pub fn add(a: V, b: V) -> V {
        zip(a, b, |x, y| x + y)
    }
    pub fn sub(a: V, b: V) -> V {
        zip(a, b, |x, y| x - y)
    }
    pub fn mul(a: V, b: V) -> V {
        zip(a, b, |x, y| x * y)
    }
    pub fn div(a: V, b: V) -> V {
        zip(a, b, |x, y| x / y)
    }
    pub fn max(a: V, b: V) -> V {
        zip(a, b, |x, y| if x > y { x } else { y })
    }
    pub fn fmadd(a: V, b: V, c: V) -> V {
        [
            a[0].mul_add(b[0], c[0]),
            a[1].mul_add(b[1], c[1]),
            a[2].mul_add(b[2], c[2]),
            a[3].mul_add(b[3], c[3]),
        ]
    }
    pub fn and(a: V, b: V) -> V {
        bits(a, b, |x, y| x & y)
    }
    pub fn or(a: V, b: V) -> V {
        bits(a, b, |x, y| x | y)
    }
    pub fn andnot(a: V, b: V) -> V {
        bits(a, b, |x, y| !x & y)
    }
    pub fn xor(a: V, b: V) -> V {
        bits(a, b, |x, y| x ^ y)
    }
    pub fn lt(a: V, b: V) -> V {
        mask(a, b, |x, y| x < y)
    }
    pub fn le(a: V, b: V) -> V {
        mask(a, b, |x, y| x <= y)
    }
    pub fn eq(a: V, b: V) -> V {
        mask(a, b, |x, y| x == y)
    }
    pub fn blend(a: V, b: V, m: V) -> V {
        [0, 1, 2, 3].map(|i| {
            if m[i].to_bits() >> 63 == 1 {
                b[i]
            } else {
                a[i]
            }
        })
    }
    pub fn movemask(m: V) -> u32 {
        (0..4).map(|i| ((m[i].to_bits() >> 63) as u32) << i).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every lane of `F4` computes exactly what `f64` computes (bit patterns, NaN
    /// included in the comparisons).
    #[test]
    fn lanes_agree_with_scalars() {
        if !available() {
            return; // F4 needs AVX and FMA on x86-64
        }
        let xs = [1.5, -0.0, f64::NAN, 3e-310];
        let ys = [1.5, 2.0, 1.0, -7e300];
        let (a, b) = (F4::new(xs), F4::new(ys));
        let fm = a.fused_mul_add(b, b);
        let same = |p: f64, q: f64| p.to_bits() == q.to_bits() || (p.is_nan() && q.is_nan());
        for i in 0..4 {
            let (x, y) = (xs[i], ys[i]);
            assert!(same((a + b).lane(i), x + y));
            assert!(same((a - b).lane(i), x - y));
            assert!(same((a * b).lane(i), x * y));
            assert!(same((a / b).lane(i), x / y));
            assert!(same((-a).lane(i), -x));
            assert!(same(a.abs().lane(i), x.abs()));
            assert!(same(a.max(b).lane(i), Lane::max(x, y)));
            assert!(same(fm.lane(i), x.mul_add(y, y)));
            assert!(same(a.exponent_power().lane(i), x.exponent_power()));
            assert_eq!(a.less(b).lane(i), x < y);
            assert_eq!(a.less_eq(b).lane(i), x <= y);
            assert_eq!(a.equal(b).lane(i), x == y);
            assert!(same(
                F4::select(a.less(b), a, b).lane(i),
                f64::select(x < y, x, y)
            ));
        }
        assert_eq!(1.5f64.exponent_power(), 1.0);
        assert_eq!((-0.375f64).exponent_power(), 0.25);
        assert_eq!((a.less_eq(b) & a.equal(b)).bits(), 0b0001);
    }

    /// The portable lanes (other architectures) compute what the AVX lanes compute.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn portable_lanes_agree_with_avx() {
        if !available() {
            return;
        }
        let (x, y, z) = (
            [1.5, -0.0, f64::NAN, 3e-310],
            [1.5, 2.0, 1.0, -7e300],
            [0.1, -3.0, 2.5, 1e-320],
        );
        let (a, b, c) = (imp::load(x), imp::load(y), imp::load(z));
        let bits = |v: [f64; 4]| v.map(f64::to_bits);
        let same = |v: imp::V, w: [f64; 4]| assert_eq!(bits(imp::store(v)), bits(w));
        same(imp::add(a, b), portable::add(x, y));
        same(imp::sub(a, b), portable::sub(x, y));
        same(imp::mul(a, b), portable::mul(x, y));
        same(imp::div(a, b), portable::div(x, y));
        same(imp::max(a, b), portable::max(x, y));
        same(imp::fmadd(a, b, c), portable::fmadd(x, y, z));
        same(imp::and(a, b), portable::and(x, y));
        same(imp::andnot(a, b), portable::andnot(x, y));
        same(imp::xor(a, b), portable::xor(x, y));
        for (m, n) in [
            (imp::lt(a, b), portable::lt(x, y)),
            (imp::le(a, b), portable::le(x, y)),
            (imp::eq(a, b), portable::eq(x, y)),
        ] {
            same(m, n);
            assert_eq!(imp::movemask(m), portable::movemask(n));
            same(imp::blend(a, c, m), portable::blend(x, z, n));
        }
    }
}
