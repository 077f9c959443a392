//! Eight `f64` lanes in one AVX-512 register ([`F8`]), the widest [`Lane`] type of the
//! batch kernels (x86-64 only; selected at run time when the CPU has AVX-512F).
//!
//! As for [`super::lane::F4`], every operation is the IEEE binary64 operation of the
//! scalar code applied lane by lane (`vaddpd`, `vfmadd…pd`, `vcmppd` into a mask
//! register, …), so each lane computes bit for bit what the scalar filter computes for
//! its case. Code using `F8` must run only where AVX-512F is present, compiled inside a
//! `#[target_feature(enable = "avx512f")]` function.

use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Sub};

use super::lane::{Lane, Wide, EXPONENT_BITS, MAX_LANES};

/// Eight `f64` lanes.
#[derive(Clone, Copy)]
#[repr(transparent)]
pub struct F8(__m512d);

/// One comparison result per lane (an AVX-512 mask register).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct M8(__mmask8);

// SAFETY (every `unsafe` block below): AVX-512F instructions, executed only where the
// batch kernels have checked the CPU; memory is touched only through the local arrays
// of `store`.

impl F8 {
    /// The eight lanes.
    #[inline(always)]
    pub fn lanes(self) -> [f64; 8] {
        let mut x = [0.0; 8];
        unsafe { _mm512_storeu_pd(x.as_mut_ptr(), self.0) };
        x
    }
}

impl std::fmt::Debug for F8 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "F8({:?})", self.lanes())
    }
}

impl PartialEq for F8 {
    fn eq(&self, b: &F8) -> bool {
        self.lanes() == b.lanes()
    }
}

macro_rules! f8_op {
    ($tr:ident, $f:ident, $intr:ident) => {
        impl $tr for F8 {
            type Output = F8;
            #[inline(always)]
            fn $f(self, b: F8) -> F8 {
                F8(unsafe { $intr(self.0, b.0) })
            }
        }
    };
}
f8_op!(Add, add, _mm512_add_pd);
f8_op!(Sub, sub, _mm512_sub_pd);
f8_op!(Mul, mul, _mm512_mul_pd);
f8_op!(Div, div, _mm512_div_pd);

impl Neg for F8 {
    type Output = F8;
    #[inline(always)]
    fn neg(self) -> F8 {
        F8(unsafe {
            _mm512_castsi512_pd(_mm512_xor_si512(
                _mm512_castpd_si512(self.0),
                _mm512_set1_epi64(i64::MIN),
            ))
        })
    }
}

impl BitAnd for M8 {
    type Output = M8;
    #[inline(always)]
    fn bitand(self, b: M8) -> M8 {
        M8(self.0 & b.0)
    }
}

impl BitOr for M8 {
    type Output = M8;
    #[inline(always)]
    fn bitor(self, b: M8) -> M8 {
        M8(self.0 | b.0)
    }
}

impl Lane for F8 {
    type Mask = M8;
    type Group = ();
    #[inline(always)]
    fn splat(x: f64) -> Self {
        F8(unsafe { _mm512_set1_pd(x) })
    }
    #[inline(always)]
    fn fused_mul_add(self, b: Self, c: Self) -> Self {
        F8(unsafe { _mm512_fmadd_pd(self.0, b.0, c.0) })
    }
    #[inline(always)]
    fn abs(self) -> Self {
        F8(unsafe { _mm512_abs_pd(self.0) })
    }
    #[inline(always)]
    fn max(self, b: Self) -> Self {
        F8(unsafe { _mm512_max_pd(self.0, b.0) })
    }
    #[inline(always)]
    fn less(self, b: Self) -> M8 {
        M8(unsafe { _mm512_cmp_pd_mask::<_CMP_LT_OQ>(self.0, b.0) })
    }
    #[inline(always)]
    fn less_eq(self, b: Self) -> M8 {
        M8(unsafe { _mm512_cmp_pd_mask::<_CMP_LE_OQ>(self.0, b.0) })
    }
    #[inline(always)]
    fn equal(self, b: Self) -> M8 {
        M8(unsafe { _mm512_cmp_pd_mask::<_CMP_EQ_OQ>(self.0, b.0) })
    }
    #[inline(always)]
    fn any(m: M8) -> bool {
        m.0 != 0
    }
    #[inline(always)]
    fn select(m: M8, a: Self, b: Self) -> Self {
        // blend: lanes of the second operand where the mask is set
        F8(unsafe { _mm512_mask_blend_pd(m.0, b.0, a.0) })
    }
    #[inline(always)]
    fn exponent_power(self) -> Self {
        // (AVX-512F has bitwise operations on integer vectors only)
        F8(unsafe {
            _mm512_castsi512_pd(_mm512_and_si512(
                _mm512_castpd_si512(self.0),
                _mm512_set1_epi64(EXPONENT_BITS as i64),
            ))
        })
    }
}

impl Wide for F8 {
    const N: usize = 8;
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        let x = [f(0), f(1), f(2), f(3), f(4), f(5), f(6), f(7)];
        F8(unsafe { _mm512_set_pd(x[7], x[6], x[5], x[4], x[3], x[2], x[1], x[0]) })
    }
    #[inline(always)]
    fn store(self, out: &mut [f64; MAX_LANES]) {
        unsafe { _mm512_storeu_pd(out.as_mut_ptr(), self.0) };
    }
    #[inline(always)]
    fn bits(m: M8) -> u32 {
        u32::from(m.0)
    }
    #[inline(always)]
    fn group() {}
}

/// True when [`F8`] can run here (AVX-512F, runtime detection).
#[inline]
pub fn available() -> bool {
    std::is_x86_feature_detected!("avx512f")
        && std::is_x86_feature_detected!("avx")
        && std::is_x86_feature_detected!("fma")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every lane of `F8` computes exactly what `f64` computes.
    #[test]
    fn lanes_agree_with_scalars() {
        if !available() {
            return;
        }
        let xs = [1.5, -0.0, f64::NAN, 3e-310, -2.5, 1e300, 0.1, -7.0];
        let ys = [1.5, 2.0, 1.0, -7e300, 0.3, 1e300, -0.1, f64::INFINITY];
        let (a, b) = (F8::from_fn(|i| xs[i]), F8::from_fn(|i| ys[i]));
        let fm = a.fused_mul_add(b, b);
        let same = |p: f64, q: f64| p.to_bits() == q.to_bits() || (p.is_nan() && q.is_nan());
        let l = |v: F8, i: usize| v.lanes()[i];
        for i in 0..8 {
            let (x, y) = (xs[i], ys[i]);
            assert!(same(l(a + b, i), x + y));
            assert!(same(l(a - b, i), x - y));
            assert!(same(l(a * b, i), x * y));
            assert!(same(l(a / b, i), x / y));
            assert!(same(l(-a, i), -x));
            assert!(same(l(a.abs(), i), x.abs()));
            assert!(same(l(a.max(b), i), Lane::max(x, y)));
            assert!(same(l(fm, i), x.mul_add(y, y)));
            assert!(same(l(a.exponent_power(), i), x.exponent_power()));
            assert_eq!(F8::bits(a.less(b)) >> i & 1 == 1, x < y);
            assert_eq!(F8::bits(a.less_eq(b)) >> i & 1 == 1, x <= y);
            assert_eq!(F8::bits(a.equal(b)) >> i & 1 == 1, x == y);
            assert!(same(
                l(F8::select(a.less(b), a, b), i),
                f64::select(x < y, x, y)
            ));
        }
        let mut out = [0.0; MAX_LANES];
        a.store(&mut out);
        assert_eq!(out.map(f64::to_bits)[..2], xs.map(f64::to_bits)[..2]);
    }
}
