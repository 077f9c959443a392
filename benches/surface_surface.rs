//! Surface ∩ surface (issue 15; BENCHMARKS.md has the table and the command): the float
//! trace against the certified answer, in one run, on a suite of pairs.
//!
//! Each group measures `float` ([`intersect_surface_surface_f64`]: §9.2 start points,
//! §9.3 marching in both directions), `certified_chains` (the float answer, then every
//! curve covered by a proven box chain with proven vertex bounds and the singular points
//! certified; `complete` not proven) and `certified_complete` (the library's certified
//! operation: in addition the boundary and height-critical systems solved over the whole
//! domain, so that `complete` is proven).
//!
//! Before the timings the bench prints the number of points per branch against the chord
//! tolerance (the step control of §9.3 with the sagitta bound `h²κ/8 ≤ tol`).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use geocert::ops::surface_surface::{
    intersect_surface_surface, intersect_surface_surface_f64, Options, SurfaceOperand,
};
use geocert::surface::bezier::BezierSurface;
use geocert::surface::plane::Plane;
use geocert::surface::quadrics::{Cylinder, Paraboloid, Sphere};
use geocert::surface::torus::Torus;
use geocert::Status;
use std::time::Duration;

/// A bicubic Bézier patch over `[0, 1]²` mapped to `[x0, x0 + 2] × [y0, y0 + 2]` with
/// heights `h(x, y)` at the control points.
fn bicubic(x0: f64, y0: f64, h: impl Fn(f64, f64) -> f64) -> BezierSurface {
    let points: Vec<Vec<[f64; 3]>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let (x, y) = (x0 + 2.0 * j as f64 / 3.0, y0 + 2.0 * i as f64 / 3.0);
                    [x, y, h(x, y)]
                })
                .collect()
        })
        .collect();
    BezierSurface::new(&points, None).expect("valid patch")
}

fn group<A: SurfaceOperand, B: SurfaceOperand>(c: &mut Criterion, name: &str, a: &A, b: &B) {
    let o = Options::default();
    let chains = Options {
        completeness: false,
        ..Options::default()
    };
    // What is timed: the certified answer is complete and verified (else the pair is
    // reported and skipped: timing an undecided answer says nothing).
    let full = intersect_surface_surface(a, b, &o).expect("valid input");
    if !(full.complete && full.status == Status::Verified) {
        eprintln!("{name}: not proven ({:?}); skipped", full.reason);
        return;
    }
    let mut g = c.benchmark_group(format!("surface_surface/{name}"));
    g.bench_function("float", |bch| {
        bch.iter(|| intersect_surface_surface_f64(black_box(a), b, &o))
    });
    g.bench_function("certified_chains", |bch| {
        bch.iter(|| intersect_surface_surface(black_box(a), b, &chains))
    });
    g.bench_function("certified_complete", |bch| {
        bch.iter(|| intersect_surface_surface(black_box(a), b, &o))
    });
    g.finish();
}

fn cylinder_plane() -> (Cylinder, Plane) {
    let cyl = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 1.0]).expect("c");
    let plane = Plane::new([0.0, 0.0, 0.5], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
        .expect("p")
        .with_domain(([-2.0, 2.0], [-2.0, 2.0]))
        .expect("d");
    (cyl, plane)
}

fn sphere_paraboloid() -> (Sphere, Paraboloid) {
    let sphere = Sphere::new([0.5, 0.0, 1.0], 1.0, None, None).expect("s");
    let par = Paraboloid::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 2.0]).expect("p");
    (sphere, par)
}

/// Points per branch against the chord tolerance (printed once).
fn steps_table() {
    let (cyl, plane) = cylinder_plane();
    let (sphere, par) = sphere_paraboloid();
    eprintln!("chord tolerance | points: cylinder ∩ plane (circle r = 1) | sphere ∩ paraboloid (loop 6.63)");
    for tol in [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7] {
        let o = Options {
            chord_tolerance: Some(tol),
            ..Options::default()
        };
        let count = |r: geocert::ops::surface_surface::SurfaceIntersectionF64| {
            r.curves.iter().map(|c| c.points.len()).sum::<usize>()
        };
        let a = count(intersect_surface_surface_f64(&cyl, &plane, &o).expect("f"));
        let b = count(intersect_surface_surface_f64(&sphere, &par, &o).expect("f"));
        eprintln!("{tol:e} | {a} | {b}");
    }
}

fn bench_pairs(c: &mut Criterion) {
    steps_table();
    let (cyl, plane) = cylinder_plane();
    group(c, "cylinder_plane", &cyl, &plane);
    let (sphere, par) = sphere_paraboloid();
    group(c, "sphere_paraboloid", &sphere, &par);
    let s1 = Sphere::new([0.0; 3], 1.0, None, None).expect("s");
    let s2 = Sphere::new([1.2, 0.3, 0.2], 0.8, Some([0.3, 0.4, 0.8]), None).expect("s");
    group(c, "sphere_sphere", &s1, &s2);
    let torus = Torus::new([0.0; 3], 2.0, 0.7, [0.0, 0.0, 1.0], None).expect("t");
    let tilted = Plane::new([0.0; 3], [1.0, 0.0, 0.2], [0.0, 1.0, 0.1])
        .expect("p")
        .with_domain(([-3.5, 3.5], [-3.5, 3.5]))
        .expect("d");
    group(c, "torus_plane", &torus, &tilted);
    let p1 = bicubic(0.0, 0.0, |x, y| 0.3 * (x - 1.0) * (y - 0.8) + 0.1);
    let p2 = bicubic(0.2, -0.1, |x, y| 0.2 * x - 0.25 * y + 0.05 * x * y);
    group(c, "bezier_bezier", &p1, &p2);
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    targets = bench_pairs
}
criterion_main!(benches);
