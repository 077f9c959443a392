//! Batch entry points of the linear kernel: many cases certified in one call, four at a
//! time through the filter ([`crate::num::lane::F4`] lanes).
//!
//! The cases are queued by *shape* (line or segment, parametric or implicit plane: the
//! formulas differ by shape, the lanes must not); each time four cases of one shape are
//! queued they go through the four-lane filter, which is the scalar filter's formula
//! instantiated for `F4` — every lane computes, bit for bit, what the scalar filter
//! computes for its case, so a lane decides exactly when the scalar filter would. Lanes
//! the filter cannot decide, the cases left over at the end, and every case on a CPU
//! without AVX and FMA take the scalar path (filter, then the exact tiers). Each answer
//! is therefore the answer of the scalar entry point for that case (tested in
//! `tests/linear_batch.rs`), in the order of the input.

use std::mem::MaybeUninit;

/// Number of shape queues (three planes: 2³ shapes).
const SHAPES: usize = 8;

/// The four-lane filter of one operation: decides `cases[idx[i]]` for the lanes it can,
/// writes their answers to `out[idx[i]]` — exactly those — and returns the decided lanes
/// as bits.
pub(crate) type LaneKernel<C, T> = fn(&[C], [usize; 4], &mut [MaybeUninit<T>]) -> u32;

/// Append the answers for `cases` to `out`, in order. `shape(c) < 8` groups cases that
/// one lane kernel can take together; `lanes` (when the CPU can run it) decides four
/// cases of one shape; `scalar` answers one case (the full certified path), and
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
            let mut queue = [[0usize; 4]; SHAPES];
            let mut fill = [0usize; SHAPES];
            for (i, c) in cases.iter().enumerate() {
                let s = shape(c);
                queue[s][fill[s]] = i;
                fill[s] += 1;
                if fill[s] == 4 {
                    fill[s] = 0;
                    let decided = lanes(cases, queue[s], slots);
                    for (k, &j) in queue[s].iter().enumerate() {
                        if decided >> k & 1 == 0 {
                            slots[j].write(undecided(&cases[j]));
                        }
                    }
                }
            }
            for (q, &n) in queue.iter().zip(&fill) {
                for &j in &q[..n] {
                    slots[j].write(scalar(&cases[j]));
                }
            }
        }
    }
    // SAFETY: every index `i < cases.len()` entered exactly one queue position (or the
    // first loop), and every position was written exactly once: by the kernel for its
    // decided lanes (its contract), else by `undecided`, or by `scalar` for what was
    // left in the queues. (A panic before this line leaks the written answers; it
    // cannot expose an unwritten one.)
    unsafe { out.set_len(start + cases.len()) };
}

/// The [`LaneKernel`] `$fast4::<WithFma>` compiled with AVX and FMA enabled, when the
/// CPU has them (x86-64: runtime detection; [`crate::num::lane::available`]); `None`
/// otherwise (the batch then runs case by case).
macro_rules! lane_kernel {
    ($fast4:ident, $case:ty, $answer:ty) => {{
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx,fma")]
        unsafe fn with_avx(
            c: &[$case],
            idx: [usize; 4],
            out: &mut [std::mem::MaybeUninit<$answer>],
        ) -> u32 {
            $fast4::<$crate::num::dd::WithFma>(c, idx, out)
        }
        #[cfg(target_arch = "x86_64")]
        fn kernel(c: &[$case], idx: [usize; 4], out: &mut [std::mem::MaybeUninit<$answer>]) -> u32 {
            // SAFETY: this function is only handed out after `lane::available()`.
            unsafe { with_avx(c, idx, out) }
        }
        #[cfg(not(target_arch = "x86_64"))]
        fn kernel(c: &[$case], idx: [usize; 4], out: &mut [std::mem::MaybeUninit<$answer>]) -> u32 {
            $fast4::<$crate::num::dd::WithFma>(c, idx, out)
        }
        let k: Option<$crate::geom::batch::LaneKernel<$case, $answer>> =
            if $crate::num::lane::available() {
                Some(kernel)
            } else {
                None
            };
        k
    }};
}
pub(crate) use lane_kernel;
