//! CGAL's kernels timed from Rust through the oracle (feature `cgal`): the cost of
//! each way of asking CGAL for three planes' point and a 2D segment crossing, so
//! later benches can quote geocert's paths as ratios to these. A cxx call costs
//! ~12 ns (BUILD-NOTES.md), small beside every CGAL kernel timed here.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use geocert::oracle::{epeck, epeck_f64, epick, EpeckToDouble, PlaneInput, Segment2Input};
use std::time::Duration;

/// Deterministic well-spread inputs (not cherry-picked: a fixed xorshift stream).
fn stream(seed: u64, n: usize) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s ^= s >> 12;
            s ^= s << 25;
            s ^= s >> 27;
            (s.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        })
        .collect()
}

fn planes(n: usize) -> Vec<[PlaneInput; 3]> {
    let v = stream(3, n * 27);
    v.chunks(27)
        .map(|c| {
            let p = |k: usize| PlaneInput::Parametric {
                origin: [c[k], c[k + 1], c[k + 2]],
                u: [c[k + 3], c[k + 4], c[k + 5]],
                v: [c[k + 6], c[k + 7], c[k + 8]],
            };
            [p(0), p(9), p(18)]
        })
        .collect()
}

fn segments(n: usize) -> Vec<[Segment2Input; 2]> {
    let v = stream(5, n * 8);
    v.chunks(8)
        .map(|c| {
            [
                Segment2Input {
                    source: [c[0], c[1]],
                    target: [c[2], c[3]],
                },
                Segment2Input {
                    source: [c[4], c[5]],
                    target: [c[6], c[7]],
                },
            ]
        })
        .collect()
}

fn three_planes(c: &mut Criterion) {
    let data = planes(64);
    let mut g = c.benchmark_group("three_planes_64");
    g.bench_function("epick", |b| {
        b.iter(|| {
            for [p, q, r] in &data {
                black_box(epick::intersect_three_planes(p, q, r).ok());
            }
        })
    });
    for (name, mode) in [
        ("epeck_to_double", EpeckToDouble::Approx),
        ("epeck_exact_to_double", EpeckToDouble::Exact),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| {
                for [p, q, r] in &data {
                    black_box(epeck_f64::intersect_three_planes(mode, p, q, r).ok());
                }
            })
        });
    }
    g.bench_function("epeck_exact_rational", |b| {
        b.iter(|| {
            for [p, q, r] in &data {
                black_box(epeck::intersect_three_planes(p, q, r).ok());
            }
        })
    });
    g.finish();
}

fn segments_2d(c: &mut Criterion) {
    let data = segments(64);
    let mut g = c.benchmark_group("segments_2d_64");
    g.bench_function("epick", |b| {
        b.iter(|| {
            for [s, t] in &data {
                black_box(epick::intersect_segment2_segment2(s, t).ok());
            }
        })
    });
    g.bench_function("epeck_to_double", |b| {
        b.iter(|| {
            for [s, t] in &data {
                black_box(epeck_f64::intersect_segment2_segment2(EpeckToDouble::Approx, s, t).ok());
            }
        })
    });
    g.bench_function("epeck_exact_rational", |b| {
        b.iter(|| {
            for [s, t] in &data {
                black_box(epeck::intersect_segment2_segment2(s, t).ok());
            }
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3))
        .sample_size(30);
    targets = three_planes, segments_2d
}
criterion_main!(benches);
