//! Tests of three planes: the mixed lanes' terms against each shape's, the lane
//! kernels against the scalar path, and the filter constants re-derived.

use super::exact::*;
use super::filter::*;
use super::lanes::*;
use super::*;
use crate::geom::batch;
use crate::geom::raw::RawPlane;
use crate::num::dd::{Dd, U};
use crate::num::filter::SCALE_MIN;
use crate::num::ring::{each, Ring};

fn plane(seed: f64, implicit: bool) -> Plane<f64> {
    let v = |a: f64, b: f64, c: f64| Vector3::new(a * seed, b + seed, c - seed);
    if implicit {
        Plane::implicit(v(1.3, -0.2, 0.7), 0.9 * seed).unwrap()
    } else {
        Plane::parametric(v(0.3, 1.1, -2.0), v(1.7, 0.4, 0.2), v(-0.6, 1.9, 0.8)).unwrap()
    }
}

/// Mixed lanes compute the values of each lane's own shape (what makes the
/// filter's bounds, derived for the shapes, hold for them): for every shape, the
/// scales, `D`, the point numerators and the parameter numerators of the parametric
/// planes of a mixed lane ([`terms_mixed`] on [`PlaneData::General`]) equal those of
/// the shape's own formulas, double-double part by part.
#[test]
fn mixed_terms_are_the_shapes_terms() {
    use crate::geom::raw::MixedPlanes;
    type D = Dd<crate::num::dd::WithFma>;
    for shape in 0..8u64 {
        for seed in 0..40 {
            let p: [Plane<f64>; 3] = each!(j in [0, 1, 2] => batch::testing::generic_plane(
                100 * seed + 3 * shape + j as u64,
                shape >> j & 1 == 1,
            ));
            let uniform = p.clone().map(|q| RawPlane::new(&q));
            let mixed = p.clone().map(|q| MixedPlanes::of(&q));
            let mut mp = (SCALE_MIN, SCALE_MIN);
            for (u, m) in uniform.iter().zip(&mixed) {
                let (a, b) = (u.scales(mp.0), m.scales(mp.1));
                assert_eq!(a, b);
                mp = (a.2, b.2);
            }
            let du: [PlaneData<D>; 3] = uniform.map(|r| r.data());
            let dm: [PlaneData<D>; 3] = mixed.map(|r| r.data());
            let ((cu, det_u), (cm, det_m)) = (det_terms(&du), det_terms(&dm));
            assert_eq!(det_u, det_m);
            let tu = terms_from(&du, &cu, det_u);
            let implicit = mixed.map(|m| m.implicit);
            let tm = terms_mixed(&dm, &cm, det_m, implicit);
            assert_eq!(tu.pnum, tm.pnum, "shape {shape}");
            for (k, ((u, m), implicit)) in
                tu.params.iter().zip(&tm.params).zip(implicit).enumerate()
            {
                if !implicit {
                    assert_eq!(u, m, "shape {shape}, plane {k}");
                }
            }
        }
    }
}

/// A lane group of mixed kinds (lane `i` has shape `i mod 8`: every combination of
/// parametric and implicit planes) is decided in every lane, with the scalar answers
/// (parameters only on the parametric planes of each lane).
#[test]
fn lane_kernel_decides_mixed_lanes() {
    for kernel in
        batch::test_lane_kernels!(fast_lanes, [Plane<f64>; 3], Certified<ThreePlanes<Rounded>>)
    {
        let cases: Vec<[Plane<f64>; 3]> = (0..8)
            .map(|k| {
                let p = |j: u64, bit: u64| batch::testing::generic_plane(3 * k + j, k & bit != 0);
                [p(0, 1), p(1, 2), p(2, 4)]
            })
            .collect();
        // (four lanes: the first four shapes, then the other four)
        for group in [&cases[..], &cases[4..]] {
            batch::testing::assert_kernel_decides_all(
                &kernel,
                group,
                filter_certified(ThreePlanes::Empty),
                intersect_three_planes,
            );
            if kernel.width == 8 {
                break;
            }
        }
    }
}

/// The lane kernel decides a lane group of generic triples of one shape and writes the scalar
/// answers; an exactly degenerate lane (three times the same plane) is left to the
/// scalar path.
#[test]
fn lane_kernel_decides_generic_lanes() {
    for kernel in
        batch::test_lane_kernels!(fast_lanes, [Plane<f64>; 3], Certified<ThreePlanes<Rounded>>)
    {
        let w = kernel.width;
        let cases: Vec<[Plane<f64>; 3]> = (0..w)
            .map(|i| {
                let s = 0.37 + i as f64;
                if i % 4 == 1 {
                    [plane(2.0, false), plane(3.0, true), plane(2.0, false)]
                } else {
                    [plane(s, false), plane(s * 1.9, true), plane(-s, false)]
                }
            })
            .collect();
        let (bits, out) =
            batch::testing::run_once(&kernel, &cases, filter_certified(ThreePlanes::Empty));
        for i in 0..w {
            assert_eq!(bits >> i & 1, u32::from(i % 4 != 1), "lane {i}");
            if i % 4 != 1 {
                assert_eq!(out[i], intersect_three_planes(&cases[i]));
                assert!(matches!(out[i].value, ThreePlanes::Point { .. }));
            }
        }
    }
}
use crate::geom::plane_plane::bound_planes;
use crate::num::error_bound::ErrorBound;

#[test]
fn filter_constants() {
    let kinds = bound_planes();
    let mut w = [ErrorBound::zero(); 3];
    for a in &kinds {
        for b in &kinds {
            for c in &kinds {
                let t = terms(&[a.clone(), b.clone(), c.clone()]);
                w[0] = w[0].max(t.det);
                w[1] = t.pnum.iter().fold(w[1], |m, x| m.max(*x));
                for q in t.params.iter().flatten() {
                    w[2] = q.iter().fold(w[2], |m, x| m.max(*x));
                }
            }
        }
    }
    println!("derived (u²): {:?}", w.map(|x| x.e_in_u2()));
    for (x, c) in w.iter().zip([EPS_DET, EPS_PNUM, EPS_PARAM]) {
        assert!(
            c >= x.e,
            "constant {} u² below the derived {} u²",
            c / (U * U),
            x.e_in_u2()
        );
    }
}
