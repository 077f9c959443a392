//! Issue 5 benchmarks: a rational bicubic NURBS patch (6 × 6 net, interior knots).
//! * the point alone vs the point with first and second derivatives (f64; goal ≤ 3×);
//! * the interval enclosure of the same jet over a small box (f64 intervals; goal ≤ 20×
//!   one f64 evaluation of the jet) in the centred form that `jet` uses, and by the
//!   direct sums (`direct_jet`: cheaper, looser); over a box that straddles a knot; and
//!   at 200-bit MPFR for reference.
//!
//! Each benchmark evaluates 256 prepared inputs per iteration (Throughput: 256).
//! Results and the command: BENCHMARKS.md.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use geocert::num::{Interval, MpfrInterval};
use geocert::surface::nurbs::NurbsSurface;
use geocert::surface::Surface;
use std::time::Duration;

const N: usize = 256;

struct Rng(u64);
impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn bicubic() -> NurbsSurface {
    let mut rng = Rng(3);
    let n = 6;
    let points: Vec<Vec<[f64; 3]>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| [j as f64, i as f64, 2.0 * rng.unit() - 1.0])
                .collect()
        })
        .collect();
    let weights: Vec<Vec<f64>> = (0..n)
        .map(|_| (0..n).map(|_| 0.5 + 1.5 * rng.unit()).collect())
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.7, 1.0, 1.0, 1.0, 1.0];
    NurbsSurface::new([3, 3], knots.clone(), knots, &points, Some(&weights)).unwrap()
}

fn bench_nurbs(c: &mut Criterion) {
    let s = bicubic();
    let mut rng = Rng(17);
    let params: Vec<(f64, f64)> = (0..N).map(|_| (rng.unit(), rng.unit())).collect();
    // Boxes of width 1e-3 inside one span, and boxes of width 0.02 across the knot 0.3.
    let boxes: Vec<(Interval, Interval)> = params
        .iter()
        .map(|&(u, v)| {
            let (u, v) = (0.31 + 0.38 * u, 0.31 + 0.38 * v);
            (
                Interval::from_bounds(u, u + 1e-3),
                Interval::from_bounds(v, v + 1e-3),
            )
        })
        .collect();
    let straddling: Vec<(Interval, Interval)> = params
        .iter()
        .map(|&(_, v)| {
            (
                Interval::from_bounds(0.29, 0.31),
                Interval::from_bounds(v, v + 1e-3),
            )
        })
        .collect();
    let mpfr: Vec<(MpfrInterval, MpfrInterval)> = boxes
        .iter()
        .map(|(u, v)| {
            (
                MpfrInterval::from_interval(u, 200),
                MpfrInterval::from_interval(v, 200),
            )
        })
        .collect();

    let mut g = c.benchmark_group("nurbs_bicubic");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("f64_point", |b| {
        b.iter(|| {
            for (u, v) in &params {
                black_box(s.jet(black_box(u), black_box(v), 0));
            }
        })
    });
    g.bench_function("f64_jet2", |b| {
        b.iter(|| {
            for (u, v) in &params {
                black_box(s.jet(black_box(u), black_box(v), 2));
            }
        })
    });
    g.bench_function("interval_box_jet2", |b| {
        b.iter(|| {
            for (u, v) in &boxes {
                black_box(s.jet(black_box(u), black_box(v), 2));
            }
        })
    });
    g.bench_function("interval_box_jet2_direct_sums", |b| {
        b.iter(|| {
            for (u, v) in &boxes {
                black_box(s.direct_jet(black_box(u), black_box(v), 2));
            }
        })
    });
    g.bench_function("interval_box_jet2_across_knot", |b| {
        b.iter(|| {
            for (u, v) in &straddling {
                black_box(s.jet(black_box(u), black_box(v), 2));
            }
        })
    });
    g.bench_function("mpfr200_box_jet2", |b| {
        b.iter(|| {
            for (u, v) in &mpfr {
                black_box(s.jet(black_box(u), black_box(v), 2));
            }
        })
    });
    g.finish();

    // The floor of any interval evaluation: one multiply-add, f64 vs f64 interval, on
    // the same 256 inputs (a dependent chain, as in a basis or tensor sum).
    let xs: Vec<f64> = params.iter().map(|p| 0.5 + 0.5 * p.0).collect();
    let ixs: Vec<Interval> = xs
        .iter()
        .map(|&x| Interval::from_bounds(x, x + 1e-3))
        .collect();
    let mut g = c.benchmark_group("multiply_add");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("f64", |b| {
        b.iter(|| {
            let mut acc = 0.0f64;
            for x in &xs {
                acc = acc * black_box(*x) + x;
            }
            acc
        })
    });
    g.bench_function("interval", |b| {
        b.iter(|| {
            let mut acc = Interval::ZERO;
            for x in &ixs {
                acc = acc * black_box(*x) + x;
            }
            acc
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2))
        .sample_size(20);
    targets = bench_nurbs
}
criterion_main!(benches);
