//! Line ∩ plane for many cases (OPERATIONS.md §5.1; `geom::batch`): the filter tier
//! in lanes, and the batch entry point.

use std::mem::MaybeUninit;

use super::exact::exact_tiers;
use super::filter::{answer, decide, scales};
use super::{intersect_line_plane, LinePlane};
use crate::certificate::Certified;
use crate::geom::batch::{self, lane_kernel};
use crate::geom::data::Linear;
use crate::geom::exact_tier::filter_certified;
use crate::geom::objects::Plane;
use crate::geom::raw::{RawLine, RawPlane};
use crate::num::dd::ProductMode;
use crate::num::lane::Wide;
use crate::num::round::Rounded;

/// A case of the batch entry point.
pub type LinePlaneCase<'a> = (Linear<'a, f64>, &'a Plane<f64>);

/// The filter tier for `F::N` cases of one shape ([`batch_shape`]) or of mixed shapes
/// in lanes: writes the answers of the decided lanes to `out` (see
/// [`batch::LaneKernel`]).
#[allow(clippy::manual_map)] // `match`, not a closure: see below
#[inline(always)]
pub(super) fn fast_lanes<M: ProductMode, F: Wide>(
    cases: &[LinePlaneCase],
    idx: &[usize],
    real: usize,
    out: &mut [MaybeUninit<Certified<LinePlane<Rounded>>>],
) -> u32 {
    let c = |i: usize| cases[idx[i]];
    let p = RawPlane::<F>::gather(|i| c(i).1);
    let l = RawLine::<F>::gather(|i| c(i).0);
    let Some(dc) = decide(
        &l.data::<M>(),
        &p.data(),
        scales(&l, &p),
        p.implicit_lanes(),
    ) else {
        return 0;
    };
    let ok = F::bits(dc.ok) & ((1 << real) - 1);
    // (no closures over lanes here: a closure may be compiled out of line, without
    // this function's target features)
    let t = dc.t.lanes();
    let point = [
        dc.point[0].lanes(),
        dc.point[1].lanes(),
        dc.point[2].lanes(),
    ];
    let uv = match &dc.uv {
        Some([u, v]) => Some([u.lanes(), v.lanes()]),
        None => None,
    };
    for (i, &j) in idx.iter().enumerate().take(real) {
        if ok >> i & 1 == 1 {
            // (in a mixed group, only the parametric lanes have parameters)
            let uv = match (&uv, c(i).1) {
                (Some([u, v]), Plane::Parametric { .. }) => Some([u.get(i), v.get(i)]),
                _ => None,
            };
            let p = [point[0].get(i), point[1].get(i), point[2].get(i)];
            out[j].write(filter_certified(answer(c(i).0, t.get(i), p, uv)));
        }
    }
    ok
}

/// The batch shape: line or segment, parametric or implicit plane.
pub(super) fn batch_shape((l, p): &LinePlaneCase) -> usize {
    usize::from(matches!(l, Linear::Segment(_))) * 2
        + usize::from(matches!(p, Plane::Implicit { .. }))
}

/// Certified line ∩ plane for many cases: appends to `out`, in order, exactly the
/// answer [`intersect_line_plane`] gives for each case (see `geom::batch`: lane groups
/// through the lane filter, one shape each, then what is left of the shapes mixed).
/// `out` only allocates when it grows.
pub fn intersect_line_plane_batch(
    cases: &[LinePlaneCase],
    out: &mut Vec<Certified<LinePlane<Rounded>>>,
) {
    let lanes = lane_kernel!(fast_lanes, LinePlaneCase, Certified<LinePlane<Rounded>>);
    batch::run(
        cases,
        out,
        batch_shape,
        lanes,
        |&(l, p)| intersect_line_plane(l, p),
        |&(l, p)| exact_tiers(l, p),
    );
}

/// For `robust`'s tests, which drive it with every robustness generator: the
/// four-lane (AVX) kernel end to end, whatever the CPU's widest — `batch::run` answers
/// `cases` as the scalar path does (nothing to run on a CPU without AVX and FMA).
#[cfg(test)]
pub(crate) fn assert_four_lane_run_equals_scalar(cases: &[LinePlaneCase]) {
    let lanes = lane_kernel!(fast_lanes, LinePlaneCase, Certified<LinePlane<Rounded>>, 4);
    if lanes.is_none() {
        return; // no AVX/FMA
    }
    batch::testing::assert_run_equals_scalar(
        cases,
        batch_shape,
        lanes,
        |&(l, p)| intersect_line_plane(l, p),
        |&(l, p)| exact_tiers(l, p),
    );
}
