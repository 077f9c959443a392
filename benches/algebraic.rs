//! Algebraic intersections: the exact path (`ops::algebraic`, rational quartic, Yun,
//! Sturm, correctly rounded points) against a plain f64 solve of the same quartic
//! (coefficients in f64, companion-matrix eigenvalues, real parts of the roots with
//! |imaginary part| ≤ 1e-8). Batches of 64 seeded lines per iteration; ratios in
//! BENCHMARKS.md.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use geocert::certify::univariate::{real_roots, Polynomial};
use geocert::ops::algebraic::{intersect_conic_conic, intersect_line_torus, Conic, TorusData};
use nalgebra::Matrix4;
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
}

type Line3 = ([f64; 3], [f64; 3]);

/// Lines through a random point of the box [−3, 3]³ in a random direction: most of
/// them cross the torus R = 2, r = 1 about z in 2 or 4 points.
fn generic_lines() -> Vec<Line3> {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    (0..BATCH)
        .map(|_| {
            let o = [rng.next() * 3.0, rng.next() * 3.0, rng.next() * 0.8];
            let d = [rng.next(), rng.next(), rng.next() * 0.3];
            (o, d)
        })
        .collect()
}

/// Exactly tangent lines: y = 1 (touching the inner equator) and y = 3 (the outer),
/// at dyadic heights and offsets, so every one has a double root.
fn tangent_lines() -> Vec<Line3> {
    (0..BATCH)
        .map(|i| {
            let y = if i % 2 == 0 { 1.0 } else { 3.0 };
            (
                [-5.0 - (i as f64) / 8.0, y, 0.0],
                [1.0 + (i as f64) / 64.0, 0.0, 0.0],
            )
        })
        .collect()
}

/// The plain f64 baseline: the same quartic in f64, roots from the companion matrix.
fn line_torus_f64(o: &[f64; 3], d: &[f64; 3]) -> Vec<[f64; 3]> {
    let (big_r, r) = (2.0f64, 1.0f64);
    let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    // |q|² = a t² + b t + c, ρ² = |q|² − q_z²
    let (a, b, c) = (dot(d, d), 2.0 * dot(o, d), dot(o, o));
    let (az, bz, cz) = (d[2] * d[2], 2.0 * o[2] * d[2], o[2] * o[2]);
    let k = big_r * big_r - r * r;
    // (a t² + b t + c + k)² − 4R²((a − az)t² + (b − bz)t + (c − cz))
    let (s2, s1, s0) = (a, b, c + k);
    let f = 4.0 * big_r * big_r;
    let coeffs = [
        s0 * s0 - f * (c - cz),
        2.0 * s0 * s1 - f * (b - bz),
        s1 * s1 + 2.0 * s0 * s2 - f * (a - az),
        2.0 * s1 * s2,
        s2 * s2,
    ];
    let m = Matrix4::new(
        0.0,
        0.0,
        0.0,
        -coeffs[0] / coeffs[4],
        1.0,
        0.0,
        0.0,
        -coeffs[1] / coeffs[4],
        0.0,
        1.0,
        0.0,
        -coeffs[2] / coeffs[4],
        0.0,
        0.0,
        1.0,
        -coeffs[3] / coeffs[4],
    );
    m.complex_eigenvalues()
        .iter()
        .filter(|z| z.im.abs() <= 1e-8 * (1.0 + z.re.abs()))
        .map(|z| [o[0] + z.re * d[0], o[1] + z.re * d[1], o[2] + z.re * d[2]])
        .collect()
}

fn bench_line_torus(c: &mut Criterion) {
    let torus = TorusData::new([0.0; 3], [0.0, 0.0, 1.0], 2.0, 1.0).unwrap();
    for (name, lines) in [("generic", generic_lines()), ("tangent", tangent_lines())] {
        let mut g = c.benchmark_group(format!("intersect_line_torus_exact/{name}"));
        g.bench_function("f64_companion", |b| {
            b.iter(|| {
                for (o, d) in &lines {
                    black_box(line_torus_f64(black_box(o), black_box(d)));
                }
            })
        });
        g.bench_function("exact", |b| {
            b.iter(|| {
                for (o, d) in &lines {
                    black_box(intersect_line_torus(*black_box(o), *black_box(d), &torus).ok());
                }
            })
        });
        g.finish();
    }
}

fn bench_univariate(c: &mut Criterion) {
    // (x² − 2)(x² − 3x + 1) and (x − 1)²(x² − 5): generic and with a double root.
    let polys = [
        Polynomial::from_i64s(&[-2, 6, -1, -3, 1]),
        &Polynomial::from_roots(&[(Rational::from(1), 2)]) * &Polynomial::from_i64s(&[-5, 0, 1]),
    ];
    let mut g = c.benchmark_group("univariate");
    for (name, p) in ["quartic_simple", "quartic_double"].iter().zip(&polys) {
        g.bench_function(*name, |b| {
            b.iter(|| black_box(real_roots(black_box(p)).ok()))
        });
    }
    g.finish();
}

fn bench_conics(c: &mut Criterion) {
    let circle2 = Conic::circle([0.0, 0.0], 2.0).unwrap();
    let circle1 = Conic::circle([0.0, 0.0], 1.0).unwrap();
    let ellipse = Conic::conic([1.0 / 9.0, 0.0, 1.0, 0.0, 0.0, -1.0]).unwrap();
    let mut g = c.benchmark_group("conics");
    g.bench_function("four_points_16_6", |b| {
        b.iter(|| black_box(intersect_conic_conic(&circle2, &ellipse).ok()))
    });
    g.bench_function("two_tangencies_16_6", |b| {
        b.iter(|| black_box(intersect_conic_conic(&circle1, &ellipse).ok()))
    });
    g.finish();
}

criterion_group!(benches, bench_line_torus, bench_univariate, bench_conics);
criterion_main!(benches);
