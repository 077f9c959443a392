//! The cost of certification (src/certify, issue 4), measured in one run against plain
//! f64 Newton (BENCHMARKS.md has the table and the command):
//!
//! * `regular/<system>/newton_f64`: Newton in f64 from a guess 1e-3 off, to convergence;
//!   `regular/<system>/certify_f64`: [`certify_root`] of Newton's answer (a Newton check
//!   step, Krawczyk in f64 intervals, tightening), the same point. Goal: ≤ 5× for systems
//!   of size ≤ 3.
//! * `escalation/<bits>`: one level of the escalation on the same root
//!   ([`certify_root_at`]: Newton at that precision, then Krawczyk), f64 intervals and
//!   MPFR at 128, 256 and 512 bits.
//! * `solve/circles`: every root of two circles in a box (subdivision, exclusion,
//!   Krawczyk), for scale.

#[path = "../tests/certify_support/mod.rs"]
mod certify_support;

use certify_support::{Circles, LineSphere, ThreeSpheres};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use geocert::certify::newton::newton_f64;
use geocert::certify::{certify_root, certify_root_at, solve, Options, System};
use geocert::num::Real;
use std::time::Duration;

/// `x³ − 2x − 5` (Wallis' example), root ≈ 2.0946.
struct Wallis;

impl System for Wallis {
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        vec![x[0].powi(3) - x[0].lift(2.0) * &x[0] - x[0].lift(5.0)]
    }
}

fn pair<S: System>(c: &mut Criterion, name: &str, sys: &S, truth: &[f64]) {
    let guess: Vec<f64> = truth
        .iter()
        .enumerate()
        .map(|(i, v)| v + 1e-3 * (1.0 + i as f64 * 0.37))
        .collect();
    let (root, _) = newton_f64(sys, &guess, 32).expect("Newton converges");
    let opts = Options::default();
    assert!(certify_root(sys, &root, &opts).unwrap().status == geocert::Status::Verified);
    let mut g = c.benchmark_group(format!("regular/{name}"));
    g.bench_function("newton_f64", |b| {
        b.iter(|| newton_f64(black_box(sys), black_box(&guess), 32))
    });
    g.bench_function("certify_f64", |b| {
        b.iter(|| certify_root(black_box(sys), black_box(&root), &opts))
    });
    g.finish();
}

fn regular(c: &mut Criterion) {
    pair(c, "n1_wallis", &Wallis, &[2.0945514815423265]);
    let circles = Circles::unit_pair(1.0);
    pair(c, "n2_circles", &circles, &[0.5, 0.8660254037844386]);
    let (line, t) = LineSphere::crossing(0.3, 0.2);
    let t: Vec<f64> = t.iter().map(|v| v.to_f64()).collect();
    pair(c, "n3_line_sphere", &line, &t);
    let (spheres, t) = ThreeSpheres::unit_triple();
    let t: Vec<f64> = t.iter().map(|v| v.to_f64()).collect();
    pair(c, "n6_three_spheres", &spheres, &t);
}

fn escalation(c: &mut Criterion) {
    let circles = Circles::unit_pair(1.0);
    let root = [0.5, 0.8660254037844386];
    let mut g = c.benchmark_group("escalation/n2_circles");
    for bits in [53u32, 128, 256, 512] {
        assert!(certify_root_at(&circles, &root, bits).unwrap().is_some());
        g.bench_function(format!("{bits}"), |b| {
            b.iter(|| certify_root_at(black_box(&circles), black_box(&root), bits))
        });
    }
    g.finish();
}

fn whole_domain(c: &mut Criterion) {
    let circles = Circles::unit_pair(1.0);
    let domain = [[-3.0, 3.0], [-3.0, 3.0]];
    let opts = Options::default();
    c.bench_function("solve/n2_circles", |b| {
        b.iter(|| solve(black_box(&circles), &domain, &opts))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2));
    targets = regular, escalation, whole_domain
}
criterion_main!(benches);
