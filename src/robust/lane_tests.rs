//! The lane kernels of geom's batch operations against the scalar path on every
//! robustness generator (near-degenerate, tiny and huge, perturbed cases): the cases
//! come from here, the checks from geom (`assert_four_lane_run_equals_scalar`), so the
//! test sits above both.

use super::{case, case::same, Case, Construction, Generator};
use crate::geom::{line_plane, plane_plane, three_planes};

/// 400 cases of every generator for `construction`.
fn cases(construction: Construction) -> impl Iterator<Item = Case> {
    (0..400).flat_map(move |i| Generator::ALL.map(|g| case(construction, g, i)))
}

#[test]
fn line_plane_four_lane_run_equals_scalar() {
    let objs: Vec<_> = cases(Construction::LinePlane)
        .map(|c| {
            let Case::LinePlane(l, p) = c else {
                unreachable!()
            };
            (l.object(same).unwrap(), p.object(same).unwrap())
        })
        .collect();
    let cases: Vec<line_plane::LinePlaneCase> = objs.iter().map(|(l, p)| (l.linear(), p)).collect();
    line_plane::assert_four_lane_run_equals_scalar(&cases);
}

#[test]
fn plane_plane_four_lane_run_equals_scalar() {
    let objs: Vec<_> = cases(Construction::PlanePlane)
        .map(|c| {
            let Case::PlanePlane(a, b) = c else {
                unreachable!()
            };
            (a.object(same).unwrap(), b.object(same).unwrap())
        })
        .collect();
    let cases: Vec<plane_plane::PlanePlaneCase> = objs.iter().map(|(a, b)| (a, b)).collect();
    plane_plane::assert_four_lane_run_equals_scalar(&cases);
}

#[test]
fn three_planes_four_lane_run_equals_scalar() {
    let cases: Vec<_> = cases(Construction::ThreePlanes)
        .map(|c| {
            let Case::ThreePlanes(p) = c else {
                unreachable!()
            };
            p.map(|q| q.object(same).unwrap())
        })
        .collect();
    three_planes::assert_four_lane_run_equals_scalar(&cases);
}
