//! Surface ∩ surface (issue 15; BENCHMARKS.md has the table and the command): the float
//! trace against the certified answer, in one run, on a suite of pairs.
//!
//! Each group measures `float` ([`intersect_surface_surface_f64_of`]: §9.2 start points,
//! §9.3 marching in both directions), `certified_chains` (the float answer, then every
//! curve covered by a proven box chain with proven vertex bounds and the singular points
//! certified; `complete` not proven) and `certified_complete` (the library's certified
//! operation: in addition the boundary and height-critical systems solved over the whole
//! domain, so that `complete` is proven).
//!
//! Two spheres have a fourth variant, `certified_exact`: the front door
//! ([`geocert::ops::intersect`]), which decides them exactly through the radical plane
//! (an exact circle), against the same float trace.
//!
//! Before the timings the bench prints the number of points per branch against the chord
//! tolerance (the step control of §9.3 with the sagitta bound `h²κ/8 ≤ tol`).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use geocert::ops::surface_surface::{
    intersect_surface_surface_f64_of, intersect_surface_surface_of, Options, SurfaceOperand,
};
use geocert::ops::{intersect as front_intersect, Answer, Options as FrontOptions, Shape};
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
    // What is timed: the certified answer is complete and proven — verified, or
    // verified_singular where the pair has singular points (Steinmetz) — else the pair
    // is reported and skipped: timing an undecided answer says nothing.
    let full = intersect_surface_surface_of(a, b, &o).expect("valid input");
    if !(full.complete && full.status != Status::Undecided) {
        eprintln!("{name}: not proven ({:?}); skipped", full.reason);
        return;
    }
    eprintln!(
        "{name}: {:?}, {} curve(s), {} singular point(s)",
        full.status,
        full.value.curves.len(),
        full.value.singular_points.len()
    );
    let mut g = c.benchmark_group(format!("surface_surface/{name}"));
    g.bench_function("float", |bch| {
        bch.iter(|| intersect_surface_surface_f64_of(black_box(a), b, &o))
    });
    g.bench_function("certified_chains", |bch| {
        bch.iter(|| intersect_surface_surface_of(black_box(a), b, &chains))
    });
    g.bench_function("certified_complete", |bch| {
        bch.iter(|| intersect_surface_surface_of(black_box(a), b, &o))
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

/// Two spheres through the front door: the exact route (radical plane, an exact circle)
/// against the float trace of the same pair.
fn group_exact(c: &mut Criterion, name: &str, a: &Sphere, b: &Sphere) {
    let o = Options::default();
    let shapes: [Shape; 2] = [a.clone().into(), b.clone().into()];
    let opts = FrontOptions::default();
    let answer = front_intersect(&shapes, &opts).expect("valid input");
    let exact = matches!(&answer.value, Answer::Curves(cv) if cv.conic.is_some());
    if !exact || answer.status == Status::Undecided {
        eprintln!("{name}: no exact circle ({:?}); skipped", answer.status);
        return;
    }
    eprintln!("{name}: {:?}, the exact circle", answer.status);
    let mut g = c.benchmark_group(format!("surface_surface/{name}"));
    g.bench_function("float", |bch| {
        bch.iter(|| intersect_surface_surface_f64_of(black_box(a), b, &o))
    });
    g.bench_function("certified_exact", |bch| {
        bch.iter(|| front_intersect(black_box(&shapes), &opts))
    });
    g.finish();
}

/// Sphere ∩ cylinder: the sphere's centre 0.5 off the axis, `R = 1.7 > ρ + 0.5`, so two
/// loops, one above and one below the centre, both within the cylinder's heights.
fn sphere_cylinder() -> (Sphere, Cylinder) {
    let sphere = Sphere::new([0.5, 0.0, 0.25], 1.75, None, None).expect("s");
    let cyl = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [-3.0, 3.0]).expect("c");
    (sphere, cyl)
}

/// Steinmetz: two unit cylinders at right angles, crossing at `(0, ±1, 0)` (singular).
fn steinmetz() -> (Cylinder, Cylinder) {
    let c1 = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [-2.0, 2.0]).expect("c");
    let c2 = Cylinder::new([0.0; 3], [1.0, 1.0], [1.0, 0.0, 0.0], None, [-2.0, 2.0]).expect("c");
    (c1, c2)
}

/// Torus (R = 2, r = 0.7 about z) ∩ a thin cylinder along x inside the tube: four loops
/// (as in tests/ssi_families.rs, torus and cylinder).
fn torus_cylinder() -> (Torus, Cylinder) {
    let torus = Torus::new([0.0; 3], 2.0, 0.7, [0.0, 0.0, 1.0], None).expect("t");
    let cyl = Cylinder::new(
        [0.0, 0.1, 0.05],
        [0.25, 0.25],
        [1.0, 0.0, 0.0],
        None,
        [-4.0, 4.0],
    )
    .expect("c");
    (torus, cyl)
}

/// The height end touching a loop (ops::surface_surface::ends): cylinder `ρ = 3.5` along
/// z ∩ the sphere `R = 5` centred `0.5` off the axis; `(ρ − c, t, R) = (3, 4, 5)`, so the
/// upper loop is highest at `z = 4`, exactly the cylinder's upper end.
fn cylinder_sphere_end() -> (Cylinder, Sphere) {
    let cyl = Cylinder::new([0.0; 3], [3.5, 3.5], [0.0, 0.0, 1.0], None, [-10.0, 4.0]).expect("c");
    let sphere = Sphere::new([0.5, 0.0, 0.0], 5.0, None, None).expect("s");
    (cyl, sphere)
}

/// A gently curved bicubic patch over `[−1, 1]²` (`|∇h| ≤ 0.1`) ∩ a sphere whose one
/// loop lies inside the patch (as in tests/ssi_families.rs, patch and sphere).
fn patch_sphere() -> (BezierSurface, Sphere) {
    let patch = bicubic(-1.0, -1.0, |x, y| 0.04 * x * y + 0.03 * x - 0.02 * y);
    let sphere = Sphere::new([0.1, -0.15, 0.2], 0.8, None, None).expect("s");
    (patch, sphere)
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
        let a = count(intersect_surface_surface_f64_of(&cyl, &plane, &o).expect("f"));
        let b = count(intersect_surface_surface_f64_of(&sphere, &par, &o).expect("f"));
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
    group_exact(c, "sphere_sphere_exact", &s1, &s2);
    let (sphere, cyl) = sphere_cylinder();
    group(c, "sphere_cylinder", &sphere, &cyl);
    let (c1, c2) = steinmetz();
    group(c, "cylinder_cylinder_steinmetz", &c1, &c2);
    let (cyl, sphere) = cylinder_sphere_end();
    group(c, "cylinder_sphere_height_end", &cyl, &sphere);
    let (patch, sphere) = patch_sphere();
    group(c, "bezier_sphere", &patch, &sphere);
    let (torus, cyl) = torus_cylinder();
    group(c, "torus_cylinder", &torus, &cyl);
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
