//! Batch entry points of the linear kernel: many cases certified in one call, eight
//! (AVX-512, [`crate::num::lane8::F8`]) or four (AVX, [`crate::num::lane::F4`]) at a
//! time through the filter.
//!
//! The cases are queued by *shape* (line or segment, parametric or implicit plane);
//! each time a lane group of one shape is full it goes through the lane filter, which
//! is the scalar filter's formula instantiated for the lane type — every lane computes,
//! bit for bit, what the scalar filter computes for its case, so a lane decides exactly
//! when the scalar filter would. What is left over of the shapes at the end is pooled
//! into lane groups of mixed shapes (planes of both kinds written as
//! [`super::data::PlaneData::General`], lines with segments as
//! [`super::raw::MixedLines`]; their lanes compute the values of their own shape —
//! equal as numbers, only the sign of a zero may differ — tested part by part in each
//! operation): full lane groups, then one padded lane group (three cases or
//! more) or case by case. Lanes the filter cannot decide go to the exact tiers; on a
//! CPU without AVX and FMA every case takes the scalar path. Each answer is therefore
//! the answer of the scalar entry point for that case (tested in
//! `tests/linear_batch.rs`), in the order of the input.

use std::mem::MaybeUninit;

use crate::num::lane::MAX_LANES;

/// Number of shape queues (three planes: 2³ shapes).
const SHAPES: usize = 8;

/// The fewest cases left over in the pool that still go through a (padded) lane
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

/// Append the answers for `cases` to `out`, in order. `shape(c) < 8` queues cases of one
/// shape together (what is left over of the shapes at the end is pooled: the kernels
/// also take lane groups of mixed shapes); `lanes` (when the CPU can run it) decides a
/// lane group; `scalar` answers one case (the full certified path), and `undecided`
/// answers a case the lane filter did not decide: the exact tiers, since the scalar
/// filter computes the same values and would not decide it either.
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
            let width = lanes.width.min(MAX_LANES);
            // One lane group: the answers of its undecided real lanes from `undecided`.
            let group = |idx: &[usize], real: usize, slots: &mut [MaybeUninit<T>]| {
                let decided = (lanes.run)(cases, idx, real, slots);
                for (k, &j) in idx[..real].iter().enumerate() {
                    if decided >> k & 1 == 0 {
                        slots[j].write(undecided(&cases[j]));
                    }
                }
            };
            let mut queue = [[0usize; MAX_LANES]; SHAPES];
            let mut fill = [0usize; SHAPES];
            for (i, c) in cases.iter().enumerate() {
                let s = shape(c);
                queue[s][fill[s]] = i;
                fill[s] += 1;
                if fill[s] == width {
                    fill[s] = 0;
                    group(&queue[s][..width], width, slots);
                }
            }
            // What is left of the shapes, pooled (a lane group may mix shapes): full lane
            // groups, then the rest in a lane group padded with copies of its first case
            // when that is cheaper than the scalar path (three cases or more), else case
            // by case.
            let mut pool = [0usize; SHAPES * MAX_LANES];
            let mut n = 0;
            for (q, &k) in queue.iter().zip(&fill) {
                pool[n..n + k].copy_from_slice(&q[..k]);
                n += k;
            }
            let mut rest = &pool[..n];
            while rest.len() >= width {
                group(&rest[..width], width, slots);
                rest = &rest[width..];
            }
            if rest.len() >= PAD_FROM {
                let mut idx = [rest[0]; MAX_LANES];
                idx[..rest.len()].copy_from_slice(rest);
                group(&idx[..width], rest.len(), slots);
            } else {
                for &j in rest {
                    slots[j].write(scalar(&cases[j]));
                }
            }
        }
    }
    // SAFETY: every index `i < cases.len()` entered exactly one queue position (or the
    // first loop); a position left over at the end entered the pool once. Every
    // position was written exactly once: by the kernel for its decided real lanes (its
    // contract; a group's real lanes are distinct positions, a padded group's padding
    // is never written), else by `undecided`, or by `scalar`. (A panic before this line
    // leaks the written answers; it cannot expose an unwritten one.)
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

/// For the tests: the kernels [`lane_kernel!`] builds with at most 4 and at most 8
/// lanes, where the CPU can run them (so the four-lane AVX kernels are exercised on
/// AVX-512 machines too; without AVX-512 both are four lanes wide).
#[cfg(test)]
macro_rules! test_lane_kernels {
    ($fast:ident, $case:ty, $answer:ty) => {
        [4, 8]
            .into_iter()
            .filter_map(|max| $crate::geom::batch::lane_kernel!($fast, $case, $answer, max))
    };
}
#[cfg(test)]
pub(crate) use test_lane_kernels;

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

    /// A vector of `unit()` coordinates from the project's random stream.
    pub(crate) fn unit_vector(r: &mut crate::num::rng::Rng) -> nalgebra::Vector3<f64> {
        nalgebra::Vector3::new(r.unit(), r.unit(), r.unit())
    }

    /// A generic plane from the seed `k`: parametric, or implicit when `implicit`.
    pub(crate) fn generic_plane(k: u64, implicit: bool) -> crate::geom::Plane<f64> {
        let mut r = crate::num::rng::Rng::new(k);
        let a = unit_vector(&mut r);
        if implicit {
            crate::geom::Plane::implicit(a, r.unit()).unwrap()
        } else {
            let (u, v) = (unit_vector(&mut r), unit_vector(&mut r));
            crate::geom::Plane::parametric(a, u, v).unwrap()
        }
    }

    /// `kernel` decides every lane of `cases[..kernel.width]` and writes `scalar`'s
    /// answer, which comes from the filter (checked first: the test is not vacuous).
    pub(crate) fn assert_kernel_decides_all<C: std::fmt::Debug, X>(
        kernel: &LaneKernel<C, crate::Certified<X>>,
        cases: &[C],
        placeholder: crate::Certified<X>,
        scalar: impl Fn(&C) -> crate::Certified<X>,
    ) where
        X: Clone + PartialEq + std::fmt::Debug,
    {
        let w = kernel.width;
        for c in &cases[..w] {
            assert_eq!(scalar(c).arithmetic, crate::Arithmetic::Filter, "{c:?}");
        }
        let (bits, out) = run_once(kernel, cases, placeholder);
        assert_eq!(bits, (1 << w) - 1, "decided lanes");
        for (c, got) in cases.iter().zip(&out) {
            assert_eq!(got, &scalar(c), "{c:?}");
        }
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
