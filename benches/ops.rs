//! Issue 6 benchmarks (BENCHMARKS.md has the table and the command): the float path of
//! an operation against its certified counterparts, in one run.
//!
//! * `project/nurbs` and `project/torus`: all feet of a point on a rational bicubic
//!   NURBS patch (6 × 6 net, interior knots) and on a torus;
//! * `intersect/nurbs_curve_patch`: a cubic NURBS curve crossing the same patch
//!   (transversal).
//!
//! Each group measures `float` (the §3–§5 float path from the walk's initial guesses:
//! Newton, merging), `certify_answers` (the float answers, then each one certified by
//! Krawczyk in f64 intervals — what a caller who trusts the search pays for proofs) and
//! `certified_complete` (the library's certified operation: the float path, then
//! subdivision with exclusion of the whole domain, so that `complete` is proven). The
//! walk's samples are prepared once, outside the timing.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use geocert::certify::{certify_root, Options, System};
use geocert::curve::nurbs::NurbsCurve;
use geocert::curve::Curve;
use geocert::ops::float::Precision;
use geocert::ops::intersect::curve_surface::{
    intersect_curve_surface, intersect_curve_surface_f64, CurveSurfaceSystem,
};
use geocert::ops::project::surface::{
    project_point_surface, project_point_surface_f64, SurfaceFeet, SurfaceFootSystem,
};
use geocert::surface::nurbs::NurbsSurface;
use geocert::surface::torus::Torus;
use geocert::surface::Surface;
use geocert::walk::surface::{SurfaceWalk, SurfaceWalkOptions};
use geocert::walk::{CurveWalk, WalkOptions};
use std::f64::consts::PI;
use std::time::Duration;

/// A smooth rational bicubic patch over `[0, 5]²`: heights of a gentle bump, weights
/// varying in `[0.7, 1.6]`.
fn patch() -> NurbsSurface {
    let n = 6;
    let points: Vec<Vec<[f64; 3]>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let (x, y) = (j as f64, i as f64);
                    [x, y, 0.3 * (x * 0.9).sin() * (y * 0.7).cos()]
                })
                .collect()
        })
        .collect();
    let weights: Vec<Vec<f64>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| 0.7 + 0.9 * (((i * 7 + j * 3) % 5) as f64) / 4.0)
                .collect()
        })
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.7, 1.0, 1.0, 1.0, 1.0];
    NurbsSurface::new([3, 3], knots.clone(), knots, &points, Some(&weights)).expect("valid patch")
}

/// A cubic NURBS curve from below the patch to above it.
fn crossing_curve() -> NurbsCurve<3> {
    let points = vec![
        [1.0, 1.2, -2.0],
        [1.8, 2.0, -0.7],
        [2.6, 2.4, 0.6],
        [3.3, 3.1, 1.9],
        [4.0, 3.6, 3.0],
    ];
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0];
    NurbsCurve::new(3, knots, points, Some(vec![1.0, 0.8, 1.3, 0.9, 1.0]), None)
        .expect("valid curve")
}

fn nodes<S: Surface>(s: &S) -> Vec<[f64; 4]> {
    SurfaceWalk::new(s, SurfaceWalkOptions::new(PI / 10.0))
        .expect("walk")
        .map(|n| [n.u, n.v, n.du, n.dv])
        .collect()
}

fn samples<C: Curve<3>>(c: &C) -> Vec<(f64, f64)> {
    CurveWalk::new(c, WalkOptions::default())
        .expect("walk")
        .map(|s| (s.t, s.step))
        .collect()
}

/// Certify each float answer on its own (Krawczyk in f64 intervals, MPFR only if that
/// fails); panics if one is not verified, so the timing is of successful proofs.
fn certify_each<S: System>(sys: &S, answers: &[Vec<f64>], opts: &Options) -> usize {
    answers
        .iter()
        .filter(|x| {
            let c = certify_root(sys, x, opts).expect("certifies");
            c.status == geocert::Status::Verified
        })
        .count()
}

fn projections<S: Surface>(c: &mut Criterion, name: &str, s: &S, p: [f64; 3], feet: usize) {
    let nodes = nodes(s);
    let precision = Precision::default();
    let opts = Options::default();
    let answers = |s: &S| -> Vec<Vec<f64>> {
        match project_point_surface_f64(s, &p, &nodes, &precision, false) {
            SurfaceFeet::Finite(f) => f.iter().map(|x| x.params.to_vec()).collect(),
            SurfaceFeet::Infinite => Vec::new(),
        }
    };
    // Check what is timed: the float path finds every foot, each certifies, and the
    // complete search proves there are no others.
    assert_eq!(answers(s).len(), feet, "{name}: float feet");
    let sys = SurfaceFootSystem {
        surface: s,
        point: p,
    };
    assert_eq!(certify_each(&sys, &answers(s), &opts), feet);
    let full = project_point_surface(s, &p, &nodes, &precision, &opts).expect("certifies");
    assert!(
        full.complete && full.value.len() == feet,
        "{name}: {full:?}"
    );

    let mut g = c.benchmark_group(format!("project/{name}"));
    g.bench_function("float", |b| b.iter(|| answers(black_box(s))));
    g.bench_function("certify_answers", |b| {
        b.iter(|| certify_each(&sys, &answers(black_box(s)), &opts))
    });
    g.bench_function("certified_complete", |b| {
        b.iter(|| project_point_surface(black_box(s), &p, &nodes, &precision, &opts))
    });
    g.finish();
}

fn bench_projections(c: &mut Criterion) {
    projections(c, "nurbs", &patch(), [2.6, 2.4, 1.5], 1);
    let torus = Torus::new([0.0; 3], 3.0, 1.0, [0.0, 0.0, 1.0], None).expect("torus");
    projections(c, "torus", &torus, [1.0, 2.0, 3.0], 4);
}

fn bench_curve_surface(c: &mut Criterion) {
    let (s, curve) = (patch(), crossing_curve());
    let (nodes, samples) = (nodes(&s), samples(&curve));
    let precision = Precision::default();
    let opts = Options::default();
    let turn = PI / 10.0;
    let answers = || -> Vec<Vec<f64>> {
        intersect_curve_surface_f64(&s, &curve, &samples, &nodes, turn, &precision)
            .iter()
            .map(|h| vec![h.surface_params[0], h.surface_params[1], h.t])
            .collect()
    };
    assert_eq!(answers().len(), 1, "one crossing");
    let sys = CurveSurfaceSystem {
        surface: &s,
        curve: &curve,
    };
    assert_eq!(certify_each(&sys, &answers(), &opts), 1);
    let full = intersect_curve_surface(&s, &curve, &samples, &nodes, turn, &precision, &opts)
        .expect("certifies");
    assert!(full.complete && full.value.len() == 1, "{full:?}");

    let mut g = c.benchmark_group("intersect/nurbs_curve_patch");
    g.bench_function("float", |b| b.iter(|| black_box(answers())));
    g.bench_function("certify_answers", |b| {
        b.iter(|| certify_each(&sys, &black_box(answers()), &opts))
    });
    g.bench_function("certified_complete", |b| {
        b.iter(|| {
            intersect_curve_surface(
                black_box(&s),
                &curve,
                &samples,
                &nodes,
                turn,
                &precision,
                &opts,
            )
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    targets = bench_projections, bench_curve_surface
}
criterion_main!(benches);
