//! Plane ∩ plane for many cases (OPERATIONS.md §8; `geom::batch`): the filter tier
//! in lanes, and the batch entry point.

use std::mem::MaybeUninit;

use nalgebra::{Vector2, Vector3};

use super::exact::exact_tiers;
use super::filter::{decide, ParamDecisions};
use super::{intersect_plane_plane, ParamLine, PlaneLine, PlanePlane};
use crate::certificate::Certified;
use crate::geom::batch::{self, lane_kernel};
use crate::geom::exact_tier::filter_certified;
use crate::geom::objects::Plane;
use crate::geom::raw::RawPlane;
use crate::num::dd::ProductMode;
use crate::num::filter::RoundedLanes;
use crate::num::lane::Wide;
use crate::num::round::Rounded;

/// A parameter line's roundings in lanes.
pub(super) struct ParamLanes {
    origin: [RoundedLanes; 2],
    dir: [RoundedLanes; 2],
}

impl ParamLanes {
    #[allow(clippy::manual_map)] // `match`, not a closure: see below
    #[inline(always)]
    fn new<F: Wide>(p: &Option<ParamDecisions<F>>) -> Option<ParamLanes> {
        match p {
            Some(p) => Some(ParamLanes {
                origin: [p.origin[0].lanes(), p.origin[1].lanes()],
                dir: [p.dir[0].lanes(), p.dir[1].lanes()],
            }),
            None => None,
        }
    }
    #[inline(always)]
    fn get(&self, i: usize) -> ParamLine<Rounded> {
        ParamLine {
            origin: Vector2::new(self.origin[0].get(i), self.origin[1].get(i)),
            dir: Vector2::new(self.dir[0].get(i), self.dir[1].get(i)),
        }
    }
}

/// A case of the batch entry point.
pub type PlanePlaneCase<'a> = (&'a Plane<f64>, &'a Plane<f64>);

/// The filter tier for `F::N` cases of one shape ([`batch_shape`]) or of mixed shapes
/// in lanes: writes the answers of the decided lanes to `out` (see
/// [`batch::LaneKernel`]).
#[inline(always)]
pub(super) fn fast_lanes<M: ProductMode, F: Wide>(
    cases: &[PlanePlaneCase],
    idx: &[usize],
    real: usize,
    out: &mut [MaybeUninit<Certified<PlanePlane<Rounded>>>],
) -> u32 {
    let c = |i: usize| cases[idx[i]];
    let (a, b) = (
        RawPlane::<F>::gather(|i| c(i).0),
        RawPlane::<F>::gather(|i| c(i).1),
    );
    // (two instances: the uniform groups' straight-line code stays as it was)
    let dc = if a.is_mixed() || b.is_mixed() {
        decide::<M, F, true>(&a, &b)
    } else {
        decide::<M, F, false>(&a, &b)
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
    let dir = [dc.dir[0].lanes(), dc.dir[1].lanes(), dc.dir[2].lanes()];
    let (on_a, on_b) = (ParamLanes::new(&dc.on_a), ParamLanes::new(&dc.on_b));
    for (i, &j) in idx.iter().enumerate().take(real) {
        if ok >> i & 1 == 1 {
            out[j].write(filter_certified(PlanePlane::Line(PlaneLine {
                point: Vector3::new(point[0].get(i), point[1].get(i), point[2].get(i)),
                dir: Vector3::new(dir[0].get(i), dir[1].get(i), dir[2].get(i)),
                dir_exponent: 0,
                // (in a mixed group, only the parametric lanes have parameters)
                on_a: match (&on_a, c(i).0) {
                    (Some(p), Plane::Parametric { .. }) => Some(p.get(i)),
                    _ => None,
                },
                on_b: match (&on_b, c(i).1) {
                    (Some(p), Plane::Parametric { .. }) => Some(p.get(i)),
                    _ => None,
                },
            })));
        }
    }
    ok
}

/// The batch shape: the kinds of the two planes (parametric or implicit), as bits.
pub(super) fn batch_shape((a, b): &PlanePlaneCase) -> usize {
    let implicit = |q: &Plane<f64>| usize::from(matches!(q, Plane::Implicit { .. }));
    implicit(a) | implicit(b) << 1
}

/// Certified plane ∩ plane for many cases: appends to `out`, in order, exactly the
/// answer [`intersect_plane_plane`] gives for each pair (see `geom::batch`: lane groups
/// through the lane filter, one shape each, then what is left of the shapes mixed).
/// `out` only allocates when it grows.
pub fn intersect_plane_plane_batch(
    cases: &[PlanePlaneCase],
    out: &mut Vec<Certified<PlanePlane<Rounded>>>,
) {
    let lanes = lane_kernel!(fast_lanes, PlanePlaneCase, Certified<PlanePlane<Rounded>>);
    batch::run(
        cases,
        out,
        batch_shape,
        lanes,
        |&(a, b)| intersect_plane_plane(a, b),
        |&(a, b)| exact_tiers(a, b),
    );
}

/// For `robust`'s tests, which drive it with every robustness generator: the
/// four-lane (AVX) kernel end to end, whatever the CPU's widest — `batch::run` answers
/// `cases` as the scalar path does (nothing to run on a CPU without AVX and FMA).
#[cfg(test)]
pub(crate) fn assert_four_lane_run_equals_scalar(cases: &[PlanePlaneCase]) {
    let lanes = lane_kernel!(
        fast_lanes,
        PlanePlaneCase,
        Certified<PlanePlane<Rounded>>,
        4
    );
    if lanes.is_none() {
        return; // no AVX/FMA
    }
    batch::testing::assert_run_equals_scalar(
        cases,
        batch_shape,
        lanes,
        |&(a, b)| intersect_plane_plane(a, b),
        |&(a, b)| exact_tiers(a, b),
    );
}
