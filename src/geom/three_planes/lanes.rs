//! Three planes for many cases (OPERATIONS.md §7.1; `geom::batch`): the filter tier
//! in lanes, and the batch entry point.

use std::mem::MaybeUninit;

use nalgebra::{Vector2, Vector3};

use super::exact::exact_tiers;
use super::filter::decide;
use super::{intersect_three_planes, ThreePlanes};
use crate::certificate::Certified;
use crate::geom::batch::{self, lane_kernel};
use crate::geom::exact_tier::filter_certified;
use crate::geom::objects::Plane;
use crate::geom::raw::RawPlane;
use crate::num::dd::ProductMode;
use crate::num::lane::Wide;
use crate::num::ring::each;
use crate::num::round::Rounded;

/// The filter tier for `F::N` cases of one shape ([`batch_shape`]) or of mixed shapes
/// in lanes: writes the answers of the decided lanes to `out` (see
/// [`batch::LaneKernel`]).
#[allow(clippy::manual_map)] // `match`, not a closure: see below
#[inline(always)]
pub(super) fn fast_lanes<M: ProductMode, F: Wide>(
    cases: &[[Plane<f64>; 3]],
    idx: &[usize],
    real: usize,
    out: &mut [MaybeUninit<Certified<ThreePlanes<Rounded>>>],
) -> u32 {
    let c = |i: usize| &cases[idx[i]];
    let r0 = RawPlane::<F>::gather(|i| &c(i)[0]);
    let r1 = RawPlane::<F>::gather(|i| &c(i)[1]);
    let r2 = RawPlane::<F>::gather(|i| &c(i)[2]);
    let raw = [r0, r1, r2];
    // (two instances: the uniform groups' straight-line code stays as it was)
    let dc = if raw.iter().any(RawPlane::is_mixed) {
        decide::<M, F, true>(&raw)
    } else {
        decide::<M, F, false>(&raw)
    };
    let Some(dc) = dc else {
        return 0;
    };
    let ok = F::bits(dc.ok) & ((1 << real) - 1);
    // (no closures over lanes: they may be compiled without the target features)
    let point = [
        dc.point[0].lanes(),
        dc.point[1].lanes(),
        dc.point[2].lanes(),
    ];
    let params = each!(k in [0, 1, 2] => match &dc.params[k] {
        Some([u, v]) => Some([u.lanes(), v.lanes()]),
        None => None,
    });
    for (i, &j) in idx.iter().enumerate().take(real) {
        if ok >> i & 1 == 1 {
            out[j].write(filter_certified(ThreePlanes::Point {
                point: Vector3::new(point[0].get(i), point[1].get(i), point[2].get(i)),
                params: each!(k in [0, 1, 2] => match &params[k] {
                    // (in a mixed group, only the parametric lanes have parameters)
                    Some([u, v]) if matches!(c(i)[k], Plane::Parametric { .. }) => {
                        Some(Vector2::new(u.get(i), v.get(i)))
                    }
                    _ => None,
                }),
            }));
        }
    }
    ok
}

/// The batch shape: the kinds of the three planes (parametric or implicit), as bits.
pub(super) fn batch_shape(p: &[Plane<f64>; 3]) -> usize {
    let implicit = |q: &Plane<f64>| usize::from(matches!(q, Plane::Implicit { .. }));
    implicit(&p[0]) | implicit(&p[1]) << 1 | implicit(&p[2]) << 2
}

/// Certified three planes for many cases: appends to `out`, in order, exactly the
/// answer [`intersect_three_planes`] gives for each triple (see `geom::batch`: lane
/// groups through the lane filter, one shape each, then what is left of the shapes
/// mixed). `out` only allocates when it grows.
pub fn intersect_three_planes_batch(
    cases: &[[Plane<f64>; 3]],
    out: &mut Vec<Certified<ThreePlanes<Rounded>>>,
) {
    let lanes = lane_kernel!(fast_lanes, [Plane<f64>; 3], Certified<ThreePlanes<Rounded>>);
    batch::run(
        cases,
        out,
        batch_shape,
        lanes,
        intersect_three_planes,
        exact_tiers,
    );
}

/// For `robust`'s tests, which drive it with every robustness generator: the
/// four-lane (AVX) kernel end to end, whatever the CPU's widest — `batch::run` answers
/// `cases` as the scalar path does (nothing to run on a CPU without AVX and FMA).
#[cfg(test)]
pub(crate) fn assert_four_lane_run_equals_scalar(cases: &[[Plane<f64>; 3]]) {
    let lanes = lane_kernel!(
        fast_lanes,
        [Plane<f64>; 3],
        Certified<ThreePlanes<Rounded>>,
        4
    );
    if lanes.is_none() {
        return; // no AVX/FMA
    }
    batch::testing::assert_run_equals_scalar(
        cases,
        batch_shape,
        lanes,
        intersect_three_planes,
        exact_tiers,
    );
}
