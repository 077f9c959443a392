//! Curve evaluation cost: a rational cubic NURBS curve (8 control points, non-uniform
//! knots) — point, point by de Boor, point + 3 derivatives, and the enclosure of
//! point + 3 derivatives over a thin parameter interval in f64 intervals and in
//! 128-bit MPFR intervals; a circle in a frame for comparison. Each benchmark
//! evaluates 256 prepared parameters (Throughput: 256 elements). Results and the
//! command: BENCHMARKS.md.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use geocert::curve::{Analytic, Curve, Frame, NurbsCurve, Shape};
use geocert::num::{Interval, MpfrInterval};
use std::time::Duration;

const N: usize = 256;

fn params(lo: f64, hi: f64) -> Vec<f64> {
    let mut s = 0x2545_F491_4F6C_DD1Du64;
    (0..N)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            lo + (hi - lo) * ((s >> 11) as f64 / (1u64 << 53) as f64)
        })
        .collect()
}

fn nurbs() -> NurbsCurve<3> {
    NurbsCurve::new(
        3,
        vec![0.0, 0.0, 0.0, 0.0, 0.7, 1.5, 1.9, 2.25, 3.0, 3.0, 3.0, 3.0],
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 2.0, 0.5],
            [2.0, -1.0, 1.0],
            [3.0, 0.5, -0.5],
            [4.0, 2.0, 0.0],
            [5.0, 1.0, 2.0],
            [5.5, -1.0, 1.0],
            [6.0, 0.0, 0.0],
        ],
        Some(vec![1.0, 0.5, 2.0, 1.5, 0.75, 1.0, 3.0, 1.0]),
        None,
    )
    .expect("valid NURBS")
}

fn bench_curves(c: &mut Criterion) {
    let curve = nurbs();
    let ts = params(0.0, 3.0);
    // Thin intervals (width ~1e-9) that stay inside one knot span.
    let boxes: Vec<Interval> = ts
        .iter()
        .map(|&t| Interval::from_bounds(t, t + 1e-9))
        .collect();
    let mp: Vec<MpfrInterval> = boxes
        .iter()
        .map(|b| MpfrInterval::from_interval(b, 128))
        .collect();
    let frame = Frame::new([1.0, 2.0, 3.0], [1.0, 2.0, 2.0], None).expect("valid frame");
    let circle = Analytic::new(frame, Shape::Circle { radius: 2.0 }, None).expect("valid circle");

    let mut g = c.benchmark_group("curves");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("nurbs_point_f64", |b| {
        b.iter(|| ts.iter().map(|t| curve.point(black_box(t))[0]).sum::<f64>())
    });
    g.bench_function("nurbs_point_de_boor_f64", |b| {
        b.iter(|| {
            ts.iter()
                .map(|t| curve.point_de_boor(black_box(t))[0])
                .sum::<f64>()
        })
    });
    g.bench_function("nurbs_jet3_f64", |b| {
        b.iter(|| {
            ts.iter()
                .map(|t| curve.jet(black_box(t), 3)[3][0])
                .sum::<f64>()
        })
    });
    g.bench_function("nurbs_jet3_interval", |b| {
        b.iter(|| {
            boxes
                .iter()
                .map(|t| curve.jet(black_box(t), 3)[3][0].hi())
                .sum::<f64>()
        })
    });
    g.bench_function("nurbs_jet3_mpfr128", |b| {
        b.iter(|| {
            mp.iter()
                .map(|t| curve.jet(black_box(t), 3)[3][0].hi_f64())
                .sum::<f64>()
        })
    });
    g.bench_function("circle_jet3_f64", |b| {
        b.iter(|| {
            ts.iter()
                .map(|t| circle.jet(black_box(t), 3)[3][0])
                .sum::<f64>()
        })
    });
    g.bench_function("circle_jet3_interval", |b| {
        b.iter(|| {
            boxes
                .iter()
                .map(|t| circle.jet(black_box(t), 3)[3][0].hi())
                .sum::<f64>()
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(2));
    targets = bench_curves
}
criterion_main!(benches);
