//! Batch entry points of the linear kernel: many cases certified in one call, eight
//! (AVX-512, [`crate::num::lane8::F8`]) or four (AVX, [`crate::num::lane::F4`]) at a
//! time through the filter.
//!
//! The cases are queued by *shape* (line or segment, parametric or implicit plane: the
//! formulas differ by shape, the lanes must not); each time a lane group of one shape
//! is full it goes through the lane filter, which is the scalar filter's formula
//! instantiated for the lane type — every lane computes, bit for bit, what the scalar
//! filter computes for its case, so a lane decides exactly when the scalar filter
//! would. Lanes the filter cannot decide go to the exact tiers; what is left over at the
//! end goes through a padded lane group (three cases or more) or case by case; on a CPU
//! without AVX and FMA every case takes the scalar path. Each answer is therefore the
//! answer of the scalar entry point for that case (tested in `tests/linear_batch.rs`),
//! in the order of the input.

use std::mem::MaybeUninit;

use crate::num::lane::MAX_LANES;

/// Number of shape queues (three planes: 2³ shapes).
const SHAPES: usize = 8;

/// The fewest cases left over in a shape queue that still go through a (padded) lane
/// group: measured, a lane group of 4 or 8 costs about what three scalar calls cost.
const PAD_FROM: usize = 3;

/// The lane filter of one operation, `width` lanes wide: decides `cases[idx[i]]`
/// (`idx.len() == width`) for the lanes it can, writes the answers of the first `real`
/// lanes among them to `out[idx[i]]` — exactly those (the others are padding) — and
/// returns those lanes as bits.
pub(crate) struct LaneKernel<C, T> {
    pub width: usize,
    pub run: LaneFn<C, T>,
}

/// `(cases, idx, real, out) -> decided lanes` (see [`LaneKernel`]).
pub(crate) type LaneFn<C, T> = fn(&[C], &[usize], usize, &mut [MaybeUninit<T>]) -> u32;

/// Append the answers for `cases` to `out`, in order. `shape(c) < 8` groups cases that
/// one lane kernel can take together; `lanes` (when the CPU can run it) decides a lane
/// group of one shape; `scalar` answers one case (the full certified path), and
/// `undecided` answers a case the lane filter did not decide: the exact tiers, since
/// the scalar filter computes the same bits and would not decide it either.
pub(crate) fn run<C, T>(
    cases: &[C],
    out: &mut Vec<T>,
    shape: impl Fn(&C) -> usize,
    lanes: Option<LaneKernel<C, T>>,
    scalar: impl Fn(&C) -> T,
    undecided: impl Fn(&C) -> T,
) {
    let start = out.len();
    out.reserve(cases.len());
    let slots = &mut out.spare_capacity_mut()[..cases.len()];
    match lanes {
        None => {
            for (slot, c) in slots.iter_mut().zip(cases) {
                slot.write(scalar(c));
            }
        }
        Some(lanes) => {
            let mut queue = [[0usize; MAX_LANES]; SHAPES];
            let mut fill = [0usize; SHAPES];
            let width = lanes.width.min(MAX_LANES);
            for (i, c) in cases.iter().enumerate() {
                let s = shape(c);
                queue[s][fill[s]] = i;
                fill[s] += 1;
                if fill[s] == width {
                    fill[s] = 0;
                    let decided = (lanes.run)(cases, &queue[s][..width], width, slots);
                    for (k, &j) in queue[s][..width].iter().enumerate() {
                        if decided >> k & 1 == 0 {
                            slots[j].write(undecided(&cases[j]));
                        }
                    }
                }
            }
            // What is left of each shape: a lane group padded with copies of its first
            // case when that is cheaper than the scalar path (three cases or more), else
            // case by case.
            for (q, &n) in queue.iter().zip(&fill) {
                if n >= PAD_FROM {
                    let mut idx = *q;
                    idx[n..width].fill(q[0]);
                    let decided = (lanes.run)(cases, &idx[..width], n, slots);
                    for (k, &j) in q[..n].iter().enumerate() {
                        if decided >> k & 1 == 0 {
                            slots[j].write(undecided(&cases[j]));
                        }
                    }
                } else {
                    for &j in &q[..n] {
                        slots[j].write(scalar(&cases[j]));
                    }
                }
            }
        }
    }
    // SAFETY: every index `i < cases.len()` entered exactly one queue position (or the
    // first loop), and every position was written exactly once: by the kernel for its
    // decided real lanes (its contract; a padded group's real lanes are the distinct
    // leftovers, its padding is never written), else by `undecided`, or by `scalar`.
    // (A panic before this line leaks the written answers; it cannot expose an
    // unwritten one.)
    unsafe { out.set_len(start + cases.len()) };
}

/// The widest [`LaneKernel`] the CPU can run: `$fast::<WithFma, F8>` compiled with
/// AVX-512F (x86-64 with AVX-512F), else `$fast::<WithFma, F4>` compiled with AVX and
/// FMA (x86-64 with both; elsewhere the portable `F4`); `None` on an x86-64 CPU without
/// AVX and FMA (the batch then runs case by case). Runtime detection, no compile flag.
macro_rules! lane_kernel {
    ($fast:ident, $case:ty, $answer:ty) => {
        $crate::geom::batch::lane_kernel!($fast, $case, $answer, 8)
    };
    // At most `$max` lanes (the tests use 4 to exercise the AVX kernels on AVX-512 CPUs).
    ($fast:ident, $case:ty, $answer:ty, $max:expr) => {{
        type Out = [std::mem::MaybeUninit<$answer>];
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx512f,avx,fma")]
        unsafe fn with_avx512(c: &[$case], idx: &[usize], real: usize, out: &mut Out) -> u32 {
            $fast::<$crate::num::dd::WithFma, $crate::num::lane8::F8>(c, idx, real, out)
        }
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx,fma")]
        unsafe fn with_avx(c: &[$case], idx: &[usize], real: usize, out: &mut Out) -> u32 {
            $fast::<$crate::num::dd::WithFma, $crate::num::lane::F4>(c, idx, real, out)
        }
        #[cfg(target_arch = "x86_64")]
        fn wide(c: &[$case], idx: &[usize], real: usize, out: &mut Out) -> u32 {
            // SAFETY: only handed out after `lane8::available()`.
            unsafe { with_avx512(c, idx, real, out) }
        }
        #[cfg(target_arch = "x86_64")]
        fn narrow(c: &[$case], idx: &[usize], real: usize, out: &mut Out) -> u32 {
            // SAFETY: only handed out after `lane::available()`.
            unsafe { with_avx(c, idx, real, out) }
        }
        #[cfg(not(target_arch = "x86_64"))]
        fn narrow(c: &[$case], idx: &[usize], real: usize, out: &mut Out) -> u32 {
            $fast::<$crate::num::dd::WithFma, $crate::num::lane::F4>(c, idx, real, out)
        }
        use $crate::geom::batch::LaneKernel;
        #[cfg(target_arch = "x86_64")]
        let k: Option<LaneKernel<$case, $answer>> = if $max >= 8 && $crate::num::lane8::available()
        {
            Some(LaneKernel {
                width: 8,
                run: wide,
            })
        } else if $crate::num::lane::available() {
            Some(LaneKernel {
                width: 4,
                run: narrow,
            })
        } else {
            None
        };
        #[cfg(not(target_arch = "x86_64"))]
        let k: Option<LaneKernel<$case, $answer>> = Some(LaneKernel {
            width: 4,
            run: narrow,
        });
        k
    }};
}
pub(crate) use lane_kernel;

/// Test drivers shared by the operations' lane-kernel tests.
#[cfg(test)]
pub(crate) mod testing {
    use super::*;

    /// One call of `kernel` on `cases[..kernel.width]`, every slot first filled with
    /// `placeholder` (so that reading them back is sound whatever the kernel wrote):
    /// the decided lanes as bits, and the slots.
    pub(crate) fn run_once<C, T: Clone>(
        kernel: &LaneKernel<C, T>,
        cases: &[C],
        placeholder: T,
    ) -> (u32, Vec<T>) {
        let w = kernel.width;
        let mut out: Vec<MaybeUninit<T>> = (0..w)
            .map(|_| MaybeUninit::new(placeholder.clone()))
            .collect();
        let idx: Vec<usize> = (0..w).collect();
        let bits = (kernel.run)(cases, &idx, w, &mut out);
        // SAFETY: every slot was initialised above (a slot the kernel wrote again only
        // leaks its placeholder).
        let out = out
            .into_iter()
            .map(|x| unsafe { x.assume_init() })
            .collect();
        (bits, out)
    }

    /// [`run`] with `lanes` answers every case as `scalar` does, in order.
    pub(crate) fn assert_run_equals_scalar<C: std::fmt::Debug, T: PartialEq + std::fmt::Debug>(
        cases: &[C],
        shape: impl Fn(&C) -> usize,
        lanes: Option<LaneKernel<C, T>>,
        scalar: impl Fn(&C) -> T,
        undecided: impl Fn(&C) -> T,
    ) {
        let mut out = Vec::new();
        run(cases, &mut out, shape, lanes, &scalar, undecided);
        assert_eq!(out.len(), cases.len());
        for (c, got) in cases.iter().zip(&out) {
            assert_eq!(got, &scalar(c), "{c:?}");
        }
    }
}
