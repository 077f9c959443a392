//! f64 vs `Interval` vs `MpfrInterval` (128 bits), per operation and for one generic
//! formula (a torus point and its two partial derivatives), measured in the same run.
//! Each benchmark evaluates the operation on 256 prepared inputs; criterion reports the
//! time per batch (Throughput: 256 elements). Results and the command: BENCHMARKS.md.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use geocert::num::{Interval, MpfrInterval, Real};
use nalgebra::Vector3;
use std::time::Duration;

const N: usize = 256;

/// Deterministic inputs in [lo, hi).
fn inputs(seed: u64, lo: f64, hi: f64) -> Vec<f64> {
    let mut s = seed | 1;
    (0..N)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            lo + (hi - lo) * ((s >> 11) as f64 / (1u64 << 53) as f64)
        })
        .collect()
}

/// Thin intervals around the inputs (width ~1e-9 relative), as in a Krawczyk step.
fn thin(xs: &[f64]) -> Vec<Interval> {
    xs.iter()
        .map(|&x| Interval::from_bounds(x, x + x.abs() * 1e-9 + 1e-12))
        .collect()
}

fn mpfr(xs: &[Interval]) -> Vec<MpfrInterval> {
    xs.iter()
        .map(|x| MpfrInterval::from_interval(x, 128))
        .collect()
}

/// A torus point and its derivatives, written once (see tests/generic_real.rs).
fn torus<T: Real>(u: &T, v: &T) -> [Vector3<T>; 3] {
    let (rr, r) = (u.lift(3.0), u.lift(1.25));
    let (cu, su, cv, sv) = (u.cos(), u.sin(), v.cos(), v.sin());
    let ring = rr + r.clone() * cv.clone();
    [
        Vector3::new(
            ring.clone() * cu.clone(),
            ring.clone() * su.clone(),
            r.clone() * sv.clone(),
        ),
        Vector3::new(
            -(ring.clone() * su.clone()),
            ring * cu.clone(),
            u.zero_like(),
        ),
        Vector3::new(
            -(r.clone() * sv.clone() * cu),
            -(r.clone() * sv * su),
            r * cv,
        ),
    ]
}

macro_rules! bench_unary {
    ($c:expr, $name:expr, $xs:expr, $f:expr) => {{
        let xs = $xs;
        let mut g = $c.benchmark_group($name);
        g.throughput(Throughput::Elements(N as u64));
        let (f64s, ivs) = (&xs, thin(&xs));
        let mps = mpfr(&ivs);
        g.bench_function("f64", |b| {
            b.iter(|| {
                f64s.iter()
                    .map(|x| $f(black_box(x)))
                    .fold(0.0f64, |s, y: f64| s + y)
            })
        });
        g.bench_function("Interval", |b| {
            b.iter(|| {
                ivs.iter()
                    .map(|x| $f(black_box(x)))
                    .fold(0.0, |s, y: Interval| s + y.hi())
            })
        });
        g.bench_function("MpfrInterval128", |b| {
            b.iter(|| {
                for x in &mps {
                    black_box($f(black_box(x)));
                }
            })
        });
        g.finish();
    }};
}

macro_rules! bench_binary {
    ($c:expr, $name:expr, $xs:expr, $ys:expr, $f:expr) => {{
        let (xs, ys) = ($xs, $ys);
        let mut g = $c.benchmark_group($name);
        g.throughput(Throughput::Elements(N as u64));
        let (ix, iy) = (thin(&xs), thin(&ys));
        let (mx, my) = (mpfr(&ix), mpfr(&iy));
        g.bench_function("f64", |b| {
            b.iter(|| {
                xs.iter()
                    .zip(&ys)
                    .map(|(x, y)| $f(black_box(x), black_box(y)))
                    .fold(0.0f64, |s, y: f64| s + y)
            })
        });
        g.bench_function("Interval", |b| {
            b.iter(|| {
                ix.iter()
                    .zip(&iy)
                    .map(|(x, y)| $f(black_box(x), black_box(y)))
                    .fold(0.0, |s, y: Interval| s + y.hi())
            })
        });
        g.bench_function("MpfrInterval128", |b| {
            b.iter(|| {
                for (x, y) in mx.iter().zip(&my) {
                    black_box($f(black_box(x), black_box(y)));
                }
            })
        });
        g.finish();
    }};
}

fn add<T: Real>(x: &T, y: &T) -> T {
    x.clone() + y
}
fn mul<T: Real>(x: &T, y: &T) -> T {
    x.clone() * y
}
fn div<T: Real>(x: &T, y: &T) -> T {
    x.clone() / y
}
fn atan2<T: Real>(y: &T, x: &T) -> T {
    y.atan2(x)
}
fn powi5<T: Real>(x: &T) -> T {
    x.powi(5)
}

fn operations(c: &mut Criterion) {
    let a = inputs(1, -100.0, 100.0);
    let b = inputs(2, 0.5, 100.0);
    bench_binary!(c, "add", a.clone(), b.clone(), add);
    bench_binary!(c, "mul", a.clone(), b.clone(), mul);
    bench_binary!(c, "div", a.clone(), b.clone(), div);
    bench_binary!(c, "atan2", a.clone(), b.clone(), atan2);
    bench_unary!(c, "sqrt", b.clone(), Real::sqrt);
    bench_unary!(c, "sqr", a.clone(), Real::sqr);
    bench_unary!(c, "powi5", inputs(3, -3.0, 3.0), powi5);
    bench_unary!(c, "sin", inputs(4, -10.0, 10.0), Real::sin);
    bench_unary!(c, "cos", inputs(5, -10.0, 10.0), Real::cos);
    // Beyond the Taylor path's range (|x| > 2^19): MPFR endpoints.
    bench_unary!(c, "sin_large_arg", inputs(6, 1e7, 1e8), Real::sin);
    bench_unary!(c, "tan", inputs(7, -1.4, 1.4), Real::tan);
    bench_unary!(c, "exp", inputs(8, -20.0, 20.0), Real::exp);
    bench_unary!(c, "ln", b.clone(), Real::ln);
    bench_unary!(c, "cosh", inputs(9, -5.0, 5.0), Real::cosh);
}

fn torus_formula(c: &mut Criterion) {
    let us = inputs(10, -3.0, 3.0);
    let vs = inputs(11, -3.0, 3.0);
    let (iu, iv) = (thin(&us), thin(&vs));
    let (mu, mv) = (mpfr(&iu), mpfr(&iv));
    let mut g = c.benchmark_group("torus_point_and_derivatives");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("f64", |b| {
        b.iter(|| {
            us.iter()
                .zip(&vs)
                .map(|(u, v)| torus(black_box(u), black_box(v))[1][0])
                .sum::<f64>()
        })
    });
    g.bench_function("Interval", |b| {
        b.iter(|| {
            iu.iter()
                .zip(&iv)
                .map(|(u, v)| torus(black_box(u), black_box(v))[1][0].hi())
                .sum::<f64>()
        })
    });
    g.bench_function("MpfrInterval128", |b| {
        b.iter(|| {
            for (u, v) in mu.iter().zip(&mv) {
                black_box(torus(black_box(u), black_box(v)));
            }
        })
    });
    g.finish();
}

fn config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30)
}

criterion_group! {
    name = benches;
    config = config();
    targets = operations, torus_formula
}
criterion_main!(benches);
