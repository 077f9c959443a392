//! Tests of plane ∩ plane: the lane kernels against the scalar path, the mixed lanes'
//! terms against each shape's, and the filter constants re-derived.

use super::exact::*;
use super::filter::*;
use super::lanes::*;
use super::*;
use crate::geom::batch;
use crate::geom::raw::RawPlane;
use crate::num::dd::{Dd, U};
use crate::num::error_bound::ErrorBound;
use crate::num::lane::MAX_LANES;
use crate::num::ring::Ring;
use crate::num::ring::{cross3, dot3};

/// The lane kernel decides a lane group of generic pairs of one shape and writes the scalar
/// answers; a lane of two parallel planes is left to the scalar path.
#[test]
fn lane_kernel_decides_generic_lanes() {
    let planes: Vec<Plane<f64>> = (0..2 * MAX_LANES)
        .map(|i| {
            let s = 0.41 + 1.37 * i as f64;
            // the pair of lane 1 (mod 4) is parallel: planes 2 and 3 (mod 8) share a normal
            let n = if i % 8 == 3 { s - 1.37 } else { s };
            Plane::implicit(Vector3::new(1.7 / n, n, 0.3 - n * 1.37), s).unwrap()
        })
        .collect();
    let cases: Vec<PlanePlaneCase> = (0..MAX_LANES)
        .map(|i| (&planes[2 * i], &planes[2 * i + 1]))
        .collect();
    for kernel in
        batch::test_lane_kernels!(fast_lanes, PlanePlaneCase, Certified<PlanePlane<Rounded>>)
    {
        let w = kernel.width;
        let (bits, out) =
            batch::testing::run_once(&kernel, &cases, filter_certified(PlanePlane::Parallel));
        for i in 0..w {
            assert_eq!(bits >> i & 1, u32::from(i % 4 != 1), "lane {i}");
            if i % 4 != 1 {
                assert_eq!(out[i], intersect_plane_plane(cases[i].0, cases[i].1));
                assert!(matches!(out[i].value, PlanePlane::Line(_)));
            }
        }
    }
}

/// Mixed lanes compute the values of each lane's own shape (so the bounds derived
/// for the shapes hold for them): for every shape, the scales, `n`, `|n|²`, the point
/// numerators and the parameter lines of the parametric planes of a mixed lane
/// ([`terms_mixed`] on [`PlaneData::General`]) equal those of the shape's own
/// formulas, double-double part by part.
#[test]
fn mixed_terms_are_the_shapes_terms() {
    use crate::geom::raw::MixedPlanes;
    type D = Dd<crate::num::dd::WithFma>;
    for shape in 0..4u64 {
        for seed in 0..40 {
            let plane = |j: u64| {
                batch::testing::generic_plane(100 * seed + 2 * shape + j, shape >> j & 1 == 1)
            };
            let (a, b) = (plane(0), plane(1));
            let (ua, ub) = (RawPlane::new(&a), RawPlane::new(&b));
            let (ma, mb) = (MixedPlanes::of(&a), MixedPlanes::of(&b));
            let (sa, sb) = (ua.scales(SCALE_FLOOR), ma.scales(SCALE_FLOOR));
            assert_eq!(sa, sb);
            assert_eq!(ub.scales(sa.2), mb.scales(sb.2));
            let (pa, pb): (PlaneData<D>, PlaneData<D>) = (ua.data(), ub.data());
            let (qa, qb): (PlaneData<D>, PlaneData<D>) = (ma.data(), mb.data());
            let (n, m) = (cross3(pa.n(), pb.n()), cross3(qa.n(), qb.n()));
            assert_eq!(n, m);
            let (nn, mm) = (dot3(&n, &n), dot3(&m, &m));
            let tu = terms_from(&pa, &pb, n, nn);
            let tm = terms_mixed(&qa, &qb, m, mm, mb.implicit);
            assert_eq!((tu.nn, tu.pnum), (tm.nn, tm.pnum), "shape {shape}");
            for (u, m, implicit) in [
                (&tu.on_a, &tm.on_a, ma.implicit),
                (&tu.on_b, &tm.on_b, mb.implicit),
            ] {
                if !implicit {
                    let (u, m) = (u.as_ref().unwrap(), m.as_ref().unwrap());
                    assert_eq!((u.num, u.dir), (m.num, m.dir), "shape {shape}");
                }
            }
        }
    }
}

/// A lane group of mixed kinds (every pair of parametric and implicit planes, in
/// turn) is decided in every lane, with the scalar answers (parameter lines only on
/// the parametric planes of each lane).
#[test]
fn lane_kernel_decides_mixed_lanes() {
    let plane = batch::testing::generic_plane;
    let planes: Vec<(Plane<f64>, Plane<f64>)> = (0..MAX_LANES as u64)
        .map(|i| (plane(2 * i, i & 1 == 1), plane(2 * i + 1, i & 2 == 2)))
        .collect();
    let cases: Vec<PlanePlaneCase> = planes.iter().map(|(a, b)| (a, b)).collect();
    for kernel in
        batch::test_lane_kernels!(fast_lanes, PlanePlaneCase, Certified<PlanePlane<Rounded>>)
    {
        batch::testing::assert_kernel_decides_all(
            &kernel,
            &cases,
            filter_certified(PlanePlane::Parallel),
            |&(a, b)| intersect_plane_plane(a, b),
        );
    }
}

#[test]
fn direction_range_constants() {
    assert_eq!(DIR_MIN, 2f64.powi(-999));
    assert_eq!(DIR_MAX, 2f64.powi(999));
}

#[test]
fn filter_constants() {
    let mut w = [ErrorBound::zero(); 5];
    for a in &bound_planes() {
        for b in &bound_planes() {
            let t = terms(a, b);
            w[0] = t.n.iter().fold(w[0], |m, x| m.max(*x));
            w[1] = w[1].max(t.nn);
            w[2] = t.pnum.iter().fold(w[2], |m, x| m.max(*x));
            for p in [&t.on_a, &t.on_b].into_iter().flatten() {
                w[3] = p.num.iter().fold(w[3], |m, x| m.max(*x));
                w[4] = p.dir.iter().fold(w[4], |m, x| m.max(*x));
            }
        }
    }
    println!("derived (u²): {:?}", w.map(|x| x.e_in_u2()));
    for (x, c) in w.iter().zip([EPS_N, EPS_NN, EPS_PNUM, EPS_PARAM, EPS_PDIR]) {
        assert!(
            c >= x.e,
            "constant {} u² below the derived {} u²",
            c / (U * U),
            x.e_in_u2()
        );
    }
}
