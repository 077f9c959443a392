//! The surface systems' explicit Jacobians (feet (3.9), curve ∩ surface (5.2), three
//! surfaces (7.3)) (`eval_with_jacobian` from the surface's own
//! derivatives, which for interval boxes run through the fast centred form of the
//! patch) enclose the derivatives the dual-number evaluation computes: over random
//! boxes of a rational NURBS patch, the f64-interval Jacobian of the box contains the
//! 200-bit MPFR dual-number Jacobian at points of the box. And the certifier's
//! smoothness guard: a box inside one pair of knot spans is smooth, one across a knot
//! is not.

mod surface_support;

use geocert::certify::dual::value_and_jacobian;
use geocert::certify::guarded::Guarded;
use geocert::certify::System;
use geocert::curve::lines::Segment;
use geocert::num::{Interval, MpfrInterval};
use geocert::ops::intersect::curve_surface::CurveSurfaceSystem;
use geocert::ops::intersect::three_surfaces::ThreeSurfaceSystem;
use geocert::ops::project::surface::SurfaceFootSystem;
use geocert::surface::Surface;
use surface_support::{nurbs_bicubic, Rng};

const PREC: u32 = 200;

/// For `boxes` random boxes of width `w` in the patch domain `[0, 1] × [−1, 2]`
/// (extra unknowns in `[0, 1]`), the box Jacobian contains the MPFR dual Jacobian at
/// three random points of the box and the box values contain the point values.
fn check<S: System>(name: &str, sys: &S, extra: usize, w: f64, rng: &mut Rng) {
    for _ in 0..25 {
        let mut lo = vec![rng.range(0.0, 1.0 - w), rng.range(-1.0, 2.0 - w)];
        lo.extend((0..extra).map(|_| rng.range(0.0, 1.0 - w)));
        let bx: Vec<Interval> = lo
            .iter()
            .map(|&a| Interval::from_bounds(a, a + w))
            .collect();
        let (fb, jb) = sys.eval_with_jacobian(&bx);
        assert_eq!(jb.len(), sys.dim(), "{name}: Jacobian rows");
        for _ in 0..3 {
            let x: Vec<MpfrInterval> = lo
                .iter()
                .map(|&a| MpfrInterval::point(a + w * rng.unit(), PREC))
                .collect();
            let (fp, jp) = value_and_jacobian(&x, |d| sys.eval(d));
            for i in 0..sys.dim() {
                assert!(
                    fp[i].to_interval().is_subset(&fb[i]),
                    "{name}: F[{i}] {:?} ⊄ {:?}",
                    fp[i],
                    fb[i]
                );
                for j in 0..sys.dim() {
                    assert!(
                        jp[i][j].to_interval().is_subset(&jb[i][j]),
                        "{name} box {lo:?} w {w}: J[{i}][{j}] {:?} ⊄ {:?}",
                        jp[i][j],
                        jb[i][j]
                    );
                }
            }
        }
    }
}

#[test]
fn explicit_jacobians_enclose_the_dual_ones() {
    let s = nurbs_bicubic();
    let foot = SurfaceFootSystem {
        surface: &s,
        point: [2.5, 1.5, 1.0],
    };
    let segment = Segment::new([0.5, -0.5, -2.0], [4.0, 3.0, 2.0], None).unwrap();
    let crossing = CurveSurfaceSystem {
        surface: &s,
        curve: &segment,
    };
    let three = ThreeSurfaceSystem {
        r: &s,
        s: &s,
        q: &s,
    };
    let mut rng = Rng(99);
    for w in [0.05, 1e-3, 1e-7] {
        check("foot", &foot, 0, w, &mut rng);
        check("curve-surface", &crossing, 1, w, &mut rng);
        check("three surfaces", &three, 4, w, &mut rng);
    }
}

#[test]
fn guarded_jets_are_smooth_on_one_pair_of_spans_only() {
    // Knots: u has 0.4 (double), v has 0.5 inside the domain.
    let s = nurbs_bicubic();
    let g = |a: f64, b: f64| Guarded::new(Interval::from_bounds(a, b));
    let inside = s.jet(&g(0.1, 0.2), &g(0.6, 0.8), 2);
    assert!(inside.iter().flatten().all(|e| e.smooth));
    let across_u = s.jet(&g(0.35, 0.45), &g(0.6, 0.8), 2);
    assert!(!across_u.iter().flatten().all(|e| e.smooth));
    let across_v = s.jet(&g(0.1, 0.2), &g(0.45, 0.55), 2);
    assert!(!across_v.iter().flatten().all(|e| e.smooth));
    // An input already non-smooth stays so.
    let mut u = g(0.1, 0.2);
    u.smooth = false;
    assert!(!s
        .jet(&u, &g(0.6, 0.8), 1)
        .iter()
        .flatten()
        .any(|e| e.smooth));
    // And the guarded values are the interval ones.
    let plain = s.jet(
        &Interval::from_bounds(0.1, 0.2),
        &Interval::from_bounds(0.6, 0.8),
        2,
    );
    for (a, b) in inside.iter().flatten().zip(plain.iter().flatten()) {
        assert_eq!(a.value, *b);
    }
}
