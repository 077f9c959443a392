//! Tests of line ∩ plane: the lane kernels against the scalar path, the mixed lanes'
//! terms against each shape's, and the filter constants re-derived.

use super::exact::*;
use super::filter::*;
use super::lanes::*;
use super::*;
use crate::geom::batch;
use crate::geom::data::LineData;
use crate::geom::raw::{RawLine, RawPlane};
use crate::geom::Line;
use crate::num::dd::{Dd, U};
use crate::num::error_bound::ErrorBound;
use crate::num::lane::MAX_LANES;
use crate::num::ring::Ring;

/// The lane kernels themselves decide a lane group of generic cases (lines and one
/// plane) and write the scalar answers; a lane whose scale is out of range (a 1e200
/// origin) is left undecided, without disturbing the others.
#[test]
fn lane_kernel_decides_generic_lanes() {
    let plane = Plane::parametric(
        [0.3, -1.7, 2.9].into(),
        [1.1, 0.2, -0.7].into(),
        [-0.4, 1.3, 0.6].into(),
    )
    .unwrap();
    let lines: Vec<Line<f64>> = (0..MAX_LANES)
        .map(|i| {
            let o = if i % 4 == 2 {
                1e200
            } else {
                0.1 * i as f64 + 0.37
            };
            Line::new([o, -2.3, 0.71].into(), [0.9, 0.33 + i as f64, -1.21].into()).unwrap()
        })
        .collect();
    let cases: Vec<LinePlaneCase> = lines.iter().map(|l| (Linear::Line(l), &plane)).collect();
    for kernel in
        batch::test_lane_kernels!(fast_lanes, LinePlaneCase, Certified<LinePlane<Rounded>>)
    {
        let w = kernel.width;
        let (bits, out) =
            batch::testing::run_once(&kernel, &cases, filter_certified(LinePlane::Parallel));
        for i in 0..w {
            if i % 4 == 2 {
                assert_eq!(bits >> i & 1, 0, "lane {i}");
                assert_eq!(out[i], filter_certified(LinePlane::Parallel));
            } else {
                assert_eq!(bits >> i & 1, 1, "lane {i}");
                assert_eq!(out[i], intersect_line_plane(cases[i].0, cases[i].1));
            }
        }
    }
}

/// A mixed lane computes the values of its own shape (so the bounds derived for the
/// shapes hold for it): for lines and segments with planes of either kind, the
/// scales and every numerator (lines and segments as [`MixedLines`], planes as
/// [`PlaneData::General`]; `(u, v)` for the parametric planes) equal those of the
/// shape's own formulas, double-double part by part.
#[test]
fn mixed_terms_are_the_shapes_terms() {
    use crate::geom::raw::{MixedLines, MixedPlanes};
    type D = Dd<crate::num::dd::WithFma>;
    for seed in 0..40u64 {
        let (line, segment) = segment_and_line(seed);
        for l in [Linear::Line(&line), Linear::Segment(&segment)] {
            for implicit in [false, true] {
                let p = batch::testing::generic_plane(1000 * seed + 20, implicit);
                let (r, ml) = (RawLine::new(l), MixedLines::of(l));
                let (u, m) = (RawPlane::new(&p), MixedPlanes::of(&p));
                let (mp, ml_scale) = ml.scales();
                let (mg, gk, mp) = m.scales(mp);
                assert_eq!(scales(&r, &u), [mp, ml_scale, mg, gk]);
                let (lu, lm): (LineData<D>, LineData<D>) = (r.data(), ml.data());
                assert_eq!((&lu.o, &lu.d), (&lm.o, &lm.d));
                let (pu, pm): (PlaneData<D>, PlaneData<D>) = (u.data(), m.data());
                let tu = terms(&lu, &pu);
                let tm = terms(&lm, &pm);
                assert_eq!((tu.den, tu.f0, tu.pnum), (tm.den, tm.f0, tm.pnum));
                if !implicit {
                    assert_eq!(tu.uvnum, tm.uvnum);
                }
            }
        }
    }
}

/// A generic line and segment from the seed `k`.
fn segment_and_line(k: u64) -> (Line<f64>, crate::geom::Segment<f64>) {
    let mut r = crate::num::rng::Rng::new(k);
    let mut v = || batch::testing::unit_vector(&mut r);
    (
        Line::new(v(), v()).unwrap(),
        crate::geom::Segment::new(v(), v()).unwrap(),
    )
}

/// A lane group of lines and segments with planes of both kinds (every combination
/// in turn) is decided in every lane, with the scalar answers (`(u, v)` only on the
/// parametric planes; the point outside a segment's domain where it is).
#[test]
fn lane_kernel_decides_mixed_lanes() {
    let objs: Vec<_> = (0..MAX_LANES as u64)
        .map(|i| {
            let p = batch::testing::generic_plane(1000 * i + 20, i & 1 == 1);
            (segment_and_line(i), p)
        })
        .collect();
    let cases: Vec<LinePlaneCase> = objs
        .iter()
        .enumerate()
        .map(|(i, ((l, s), p))| {
            let l = if i & 2 == 2 {
                Linear::Segment(s)
            } else {
                Linear::Line(l)
            };
            (l, p)
        })
        .collect();
    for kernel in
        batch::test_lane_kernels!(fast_lanes, LinePlaneCase, Certified<LinePlane<Rounded>>)
    {
        batch::testing::assert_kernel_decides_all(
            &kernel,
            &cases,
            filter_certified(LinePlane::Parallel),
            |&(l, p)| intersect_line_plane(l, p),
        );
    }
}

/// Derive the filter constants from the formulas and check the written ones cover them.
#[test]
fn filter_constants() {
    let i = ErrorBound::INPUT;
    let lines = [
        LineData {
            o: [i; 3],
            d: [i; 3],
            ends: [None, None],
        },
        LineData {
            o: [i; 3],
            d: [i.minus(&i); 3],
            ends: [None, None],
        },
    ];
    let planes = [
        PlaneData::Param {
            o: [i; 3],
            u: [i; 3],
            v: [i; 3],
            n: crate::num::ring::cross3(&[i; 3], &[i; 3]),
        },
        PlaneData::Implicit { n: [i; 3], d: i },
    ];
    let mut worst = [ErrorBound::zero(); 4];
    for l in &lines {
        for p in &planes {
            let t = terms(l, p);
            worst[0] = worst[0].max(t.den);
            worst[1] = worst[1].max(t.pnum[0]).max(t.f0);
            if let Some([u, v]) = t.uvnum {
                worst[2] = worst[2].max(u).max(v);
            }
        }
    }
    println!("derived (u²): {:?}", worst.map(|w| w.e_in_u2()));
    for (w, c) in worst.iter().zip([EPS_DEN, EPS_PNUM, EPS_UVNUM]) {
        assert!(
            c >= w.e,
            "constant {} u² below the derived {} u²",
            c / (U * U),
            w.e_in_u2()
        );
    }
}
