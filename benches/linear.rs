//! Linear kernel: plain f64 vs certified (filter → integers → expansions → rationals)
//! vs the pure exact-rational path, on generic and on exactly degenerate input (a fixed
//! seeded batch of 64 cases per iteration). Ratios are in BENCHMARKS.md.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use geocert::geom::line_plane::{
    intersect_line_plane, intersect_line_plane_batch, intersect_line_plane_exact,
    intersect_line_plane_f64, LinePlaneCase,
};
use geocert::geom::plane_plane::{
    intersect_plane_plane, intersect_plane_plane_batch, intersect_plane_plane_exact,
    intersect_plane_plane_f64, PlanePlaneCase,
};
use geocert::geom::three_planes::{
    intersect_three_planes, intersect_three_planes_batch, intersect_three_planes_exact,
    intersect_three_planes_f64,
};
use geocert::geom::{Line, Linear, Plane};
use nalgebra::Vector3;
use rug::Rational;

const BATCH: usize = 64;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
    /// A small integer in [-8, 8] (exact data for degenerate cases).
    fn int(&mut self) -> f64 {
        (self.next() * 8.0).round()
    }
    fn v(&mut self, s: f64) -> Vector3<f64> {
        Vector3::new(self.next() * s, self.next() * s, self.next() * s)
    }
    fn vi(&mut self) -> Vector3<f64> {
        Vector3::new(self.int(), self.int(), self.int())
    }
}

fn q(p: &Plane<f64>) -> Plane<Rational> {
    let r = |v: &Vector3<f64>| v.map(|x| Rational::from_f64(x).unwrap());
    match p {
        Plane::Parametric { origin, u, v } => Plane::parametric(r(origin), r(u), r(v)).unwrap(),
        Plane::Implicit { normal, d } => {
            Plane::implicit(r(normal), Rational::from_f64(*d).unwrap()).unwrap()
        }
    }
}
fn ql(l: &Line<f64>) -> Line<Rational> {
    let r = |v: &Vector3<f64>| v.map(|x| Rational::from_f64(x).unwrap());
    Line::new(r(l.origin()), r(l.dir())).unwrap()
}

fn random_plane(r: &mut Rng) -> Plane<f64> {
    loop {
        if let Ok(p) = Plane::parametric(r.v(10.0), r.v(1.0), r.v(1.0)) {
            return p;
        }
    }
}
fn int_plane(r: &mut Rng) -> Plane<f64> {
    loop {
        if let Ok(p) = Plane::parametric(r.vi(), r.vi(), r.vi()) {
            return p;
        }
    }
}

/// Generic triples, and exactly degenerate ones: the third plane contains the line of
/// the first two (`origin` on both, spanned by the line direction and a combination of
/// the first plane's vectors), so the answer is a line and every determinant is 0.
fn triples(degenerate: bool) -> Vec<[Plane<f64>; 3]> {
    let mut r = Rng(0x9E3779B97F4A7C15);
    (0..BATCH)
        .map(|_| {
            if !degenerate {
                return [
                    random_plane(&mut r),
                    random_plane(&mut r),
                    random_plane(&mut r),
                ];
            }
            loop {
                let (o, u1, v1, u2) = (r.vi(), r.vi(), r.vi(), r.vi());
                let (Ok(a), Ok(b)) = (
                    Plane::parametric(o, u1, v1),
                    Plane::parametric(o + u1, u2, v1),
                ) else {
                    continue;
                };
                // both contain o + t·v1 (v1 spans each): a third plane through that line
                let w = u1 * r.int() + u2;
                if let Ok(c) = Plane::parametric(o + u1 + v1 * 2.0, v1, w) {
                    return [a, b, c];
                }
            }
        })
        .collect()
}

fn pairs(degenerate: bool) -> Vec<(Plane<f64>, Plane<f64>)> {
    let mut r = Rng(0xD1B54A32D192ED03);
    (0..BATCH)
        .map(|_| {
            if !degenerate {
                return (random_plane(&mut r), random_plane(&mut r));
            }
            // the same plane through another origin, or a parallel shift (integers)
            let a = int_plane(&mut r);
            let Plane::Parametric { origin, u, v } = &a else {
                unreachable!()
            };
            let shift = if r.next() > 0.0 {
                u + v
            } else {
                Vector3::new(0.0, 0.0, 1.0)
            };
            let b = Plane::parametric(origin + shift, *v, *u).unwrap();
            (a, b)
        })
        .collect()
}

fn lines(degenerate: bool) -> Vec<(Line<f64>, Plane<f64>)> {
    let mut r = Rng(0x2545F4914F6CDD1D);
    (0..BATCH)
        .map(|_| {
            if !degenerate {
                return (
                    Line::new(r.v(10.0), r.v(1.0)).unwrap(),
                    random_plane(&mut r),
                );
            }
            // a direction in the plane (exactly orthogonal to the normal): contained or parallel
            let p = int_plane(&mut r);
            let Plane::Parametric { origin, u, v } = &p else {
                unreachable!()
            };
            let dir = u * r.int() + v;
            let dir = if dir == Vector3::zeros() { *u } else { dir };
            let o = if r.next() > 0.0 {
                origin + u
            } else {
                origin + Vector3::new(1.0, 1.0, 1.0)
            };
            (Line::new(o, dir).unwrap(), p)
        })
        .collect()
}

/// The tier expected to decide each batch (checked before timing).
fn tier(degenerate: bool) -> geocert::Arithmetic {
    if degenerate {
        geocert::Arithmetic::Integer
    } else {
        geocert::Arithmetic::Filter
    }
}

fn bench(c: &mut Criterion) {
    for degenerate in [false, true] {
        let kind = if degenerate { "degenerate" } else { "generic" };

        let t = triples(degenerate);
        let tq: Vec<[Plane<Rational>; 3]> =
            t.iter().map(|p| [q(&p[0]), q(&p[1]), q(&p[2])]).collect();
        // The batch is what it claims: every degenerate triple meets in a line.
        for p in &tq {
            let line = matches!(
                intersect_three_planes_exact(p),
                geocert::geom::three_planes::ThreePlanes::Line { .. }
            );
            assert_eq!(line, degenerate);
        }
        for p in &t {
            assert_eq!(intersect_three_planes(p).arithmetic, tier(degenerate));
        }
        let mut g = c.benchmark_group(format!("three_planes/{kind}"));
        g.throughput(Throughput::Elements(BATCH as u64));
        g.bench_function(BenchmarkId::from_parameter("f64"), |b| {
            b.iter(|| {
                for p in &t {
                    black_box(intersect_three_planes_f64(black_box(p)));
                }
            })
        });
        g.bench_function(BenchmarkId::from_parameter("certified"), |b| {
            b.iter(|| {
                for p in &t {
                    black_box(intersect_three_planes(black_box(p)));
                }
            })
        });
        let mut out = Vec::with_capacity(BATCH);
        g.bench_function(BenchmarkId::from_parameter("certified_batch"), |b| {
            b.iter(|| {
                out.clear();
                intersect_three_planes_batch(black_box(&t), &mut out);
                black_box(&out);
            })
        });
        g.bench_function(BenchmarkId::from_parameter("exact"), |b| {
            b.iter(|| {
                for p in &tq {
                    black_box(intersect_three_planes_exact(black_box(p)));
                }
            })
        });
        g.finish();

        let l = lines(degenerate);
        let lq: Vec<(Line<Rational>, Plane<Rational>)> =
            l.iter().map(|(a, p)| (ql(a), q(p))).collect();
        for (a, p) in &l {
            assert_eq!(
                intersect_line_plane(Linear::Line(a), p).arithmetic,
                tier(degenerate)
            );
        }
        let mut g = c.benchmark_group(format!("line_plane/{kind}"));
        g.throughput(Throughput::Elements(BATCH as u64));
        g.bench_function(BenchmarkId::from_parameter("f64"), |b| {
            b.iter(|| {
                for (a, p) in &l {
                    black_box({
                        black_box(intersect_line_plane_f64(Linear::Line(black_box(a)), p))
                    });
                }
            })
        });
        g.bench_function(BenchmarkId::from_parameter("certified"), |b| {
            b.iter(|| {
                for (a, p) in &l {
                    black_box(intersect_line_plane(Linear::Line(black_box(a)), p));
                }
            })
        });
        let cases: Vec<LinePlaneCase> = l.iter().map(|(a, p)| (Linear::Line(a), p)).collect();
        let mut out = Vec::with_capacity(BATCH);
        g.bench_function(BenchmarkId::from_parameter("certified_batch"), |b| {
            b.iter(|| {
                out.clear();
                intersect_line_plane_batch(black_box(&cases), &mut out);
                black_box(&out);
            })
        });
        g.bench_function(BenchmarkId::from_parameter("exact"), |b| {
            b.iter(|| {
                for (a, p) in &lq {
                    black_box({
                        black_box(intersect_line_plane_exact(Linear::Line(black_box(a)), p))
                    });
                }
            })
        });
        g.finish();

        let pp = pairs(degenerate);
        let pq: Vec<(Plane<Rational>, Plane<Rational>)> =
            pp.iter().map(|(a, b)| (q(a), q(b))).collect();
        for (x, y) in &pp {
            assert_eq!(intersect_plane_plane(x, y).arithmetic, tier(degenerate));
        }
        let mut g = c.benchmark_group(format!("plane_plane/{kind}"));
        g.throughput(Throughput::Elements(BATCH as u64));
        g.bench_function(BenchmarkId::from_parameter("f64"), |b| {
            b.iter(|| {
                for (x, y) in &pp {
                    black_box(intersect_plane_plane_f64(black_box(x), y));
                }
            })
        });
        g.bench_function(BenchmarkId::from_parameter("certified"), |b| {
            b.iter(|| {
                for (x, y) in &pp {
                    black_box(intersect_plane_plane(black_box(x), y));
                }
            })
        });
        let cases: Vec<PlanePlaneCase> = pp.iter().map(|(x, y)| (x, y)).collect();
        let mut out = Vec::with_capacity(BATCH);
        g.bench_function(BenchmarkId::from_parameter("certified_batch"), |b| {
            b.iter(|| {
                out.clear();
                intersect_plane_plane_batch(black_box(&cases), &mut out);
                black_box(&out);
            })
        });
        g.bench_function(BenchmarkId::from_parameter("exact"), |b| {
            b.iter(|| {
                for (x, y) in &pq {
                    black_box(intersect_plane_plane_exact(black_box(x), y));
                }
            })
        });
        g.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
