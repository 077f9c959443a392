//! Families of curved cases with independent truths for the `verify` tests: each case
//! is a `solve` case (no claim) with its true solution points computed in closed form
//! in MPFR at 256 bits (`rug::Float`, a route independent of geocert's solvers), and,
//! where the objects have parameters, the true parameters of each solution as a claim
//! by `params`.
#![allow(dead_code)]

use geocert::io::{read_cases, solve_case, verify_case};
use geocert::robust::rng::Rng;
use rug::Float;
use serde_json::{json, Value};

/// The precision of the truths.
pub const PREC: u32 = 256;

pub fn f(x: f64) -> Float {
    Float::with_val(PREC, x)
}

pub fn pi() -> Float {
    Float::with_val(PREC, rug::float::Constant::Pi)
}

/// An angle in `[0, 2π)`.
pub fn angle(y: &Float, x: &Float) -> Float {
    let a = Float::with_val(PREC, y.atan2_ref(x));
    if a < 0 {
        a + 2 * pi()
    } else {
        a
    }
}

/// One case of a family.
pub struct Case {
    /// The `solve` case (no `claim`).
    pub case: Value,
    /// Every solution (the answer's points), in MPFR.
    pub truths: Vec<Vec<Float>>,
    /// Per solution, its parameters on each object (a `params` claim), when known.
    pub params: Option<Vec<Value>>,
}

pub fn doubles(v: &[Float]) -> Vec<f64> {
    v.iter().map(Float::to_f64).collect()
}

/// The Euclidean distance of a double point from a true one, in MPFR.
pub fn distance(claim: &[f64], truth: &[Float]) -> Float {
    let s = claim.iter().zip(truth).fold(f(0.0), |acc, (c, t)| {
        let d = Float::with_val(PREC, t - *c);
        acc + d.square()
    });
    s.sqrt()
}

fn run(case: &Value, solve: bool) -> Value {
    let read = read_cases(&case.to_string());
    assert_eq!(read.len(), 1);
    let read = read.into_iter().next().unwrap();
    let r = if solve {
        solve_case(read)
    } else {
        verify_case(read)
    };
    serde_json::from_str(&r.to_json_line()).unwrap()
}

pub fn solve(case: &Value) -> Value {
    run(case, true)
}

pub fn verify(case: &Value) -> Value {
    run(case, false)
}

/// The case with a claim.
pub fn claiming(case: &Value, claim: Value) -> Value {
    let mut c = case.clone();
    c["claim"] = claim;
    c
}

fn xyz(v: &[f64]) -> Value {
    json!(v)
}

/// A random unit vector.
pub fn unit(rng: &mut Rng, dim: usize) -> Vec<f64> {
    loop {
        let v: Vec<f64> = (0..dim).map(|_| rng.unit()).collect();
        let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        if n > 0.1 && n <= 1.0 {
            return v.iter().map(|x| x / n).collect();
        }
    }
}

fn in_range(rng: &mut Rng, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * (rng.unit() + 1.0) / 2.0
}

fn point3(rng: &mut Rng, scale: f64) -> [f64; 3] {
    [
        rng.generic() * scale,
        rng.generic() * scale,
        rng.generic() * scale,
    ]
}

/// The two roots of `a t² + b t + c = 0` (real and apart by construction).
fn quadratic(a: &Float, b: &Float, c: &Float) -> [Float; 2] {
    let disc = Float::with_val(PREC, b.square_ref()) - Float::with_val(PREC, 4 * a.clone() * c);
    assert!(disc > 0, "the family builds two crossings");
    let s = disc.sqrt();
    let two_a = Float::with_val(PREC, 2 * a.clone());
    [
        Float::with_val(PREC, -b.clone() - &s) / &two_a,
        Float::with_val(PREC, -b.clone() + &s) / &two_a,
    ]
}

/// A line `o + t·d` against the quadric `Σ ((x_i − c_i)/s_i)² = 1`: its two crossings
/// (o inside, so two transversal crossings) as (t, point).
fn line_quadric(
    o: &[f64; 3],
    d: &[f64; 3],
    c: &[f64; 3],
    s: &[f64; 3],
) -> Vec<(Float, Vec<Float>)> {
    let (mut a, mut b, mut cc) = (f(0.0), f(0.0), f(-1.0));
    for i in 0..3 {
        let w = f(s[i]).square();
        let e = f(o[i]) - f(c[i]);
        a += f(d[i]).square() / &w;
        b += Float::with_val(PREC, 2 * f(d[i]) * &e) / &w;
        cc += e.square() / &w;
    }
    quadratic(&a, &b, &cc)
        .into_iter()
        .map(|t| {
            let p = (0..3)
                .map(|i| f(o[i]) + Float::with_val(PREC, &t * d[i]))
                .collect();
            (t, p)
        })
        .collect()
}

/// A line through a point well inside the quadric (at most 0.6 of the way out),
/// in a random direction.
fn inner_line(rng: &mut Rng, c: &[f64; 3], s: &[f64; 3]) -> ([f64; 3], [f64; 3]) {
    let w = unit(rng, 3);
    let k = 0.6 * (rng.unit() + 1.0) / 2.0;
    let o = [
        c[0] + k * s[0] * w[0],
        c[1] + k * s[1] * w[1],
        c[2] + k * s[2] * w[2],
    ];
    let d = unit(rng, 3);
    let scale = in_range(rng, 0.5, 4.0);
    (o, [d[0] * scale, d[1] * scale, d[2] * scale])
}

/// Line × sphere (through the front door's exact algebraic route).
pub fn line_sphere(rng: &mut Rng) -> Case {
    let c = point3(rng, 1.0);
    let r = in_range(rng, 0.5, 5.0);
    let (o, d) = inner_line(rng, &c, &[r; 3]);
    let hits = line_quadric(&o, &d, &c, &[r; 3]);
    let params = hits
        .iter()
        .map(|(t, p)| {
            let rel: Vec<Float> = (0..3)
                .map(|i| Float::with_val(PREC, &p[i] - c[i]))
                .collect();
            let u = angle(&rel[1], &rel[0]);
            let v = Float::with_val(PREC, &rel[2] / r).asin();
            json!([[t.to_f64()], [u.to_f64(), v.to_f64()]])
        })
        .collect();
    Case {
        case: json!({"op": "intersect", "objects": [
            {"type": "line", "origin": o, "dir": d},
            {"type": "sphere", "center": c, "radius": r}]}),
        truths: hits.into_iter().map(|h| h.1).collect(),
        params: Some(params),
    }
}

/// Line × ellipsoid.
pub fn line_ellipsoid(rng: &mut Rng) -> Case {
    let c = point3(rng, 1.0);
    let s = [
        in_range(rng, 0.5, 4.0),
        in_range(rng, 0.5, 4.0),
        in_range(rng, 0.5, 4.0),
    ];
    let (o, d) = inner_line(rng, &c, &s);
    let hits = line_quadric(&o, &d, &c, &s);
    let params = hits
        .iter()
        .map(|(t, p)| {
            let rel: Vec<Float> = (0..3)
                .map(|i| Float::with_val(PREC, &p[i] - c[i]) / s[i])
                .collect();
            let u = angle(&rel[1], &rel[0]);
            let v = rel[2].clone().asin();
            json!([[t.to_f64()], [u.to_f64(), v.to_f64()]])
        })
        .collect();
    Case {
        case: json!({"op": "intersect", "objects": [
            {"type": "line", "origin": o, "dir": d},
            {"type": "ellipsoid", "center": c, "a": s[0], "b": s[1], "c": s[2]}]}),
        truths: hits.into_iter().map(|h| h.1).collect(),
        params: Some(params),
    }
}

/// Line × cylinder (axis z): the crossings of the quadric `x² + y² = r²` inside a
/// height range that holds both.
pub fn line_cylinder(rng: &mut Rng) -> Case {
    let c = point3(rng, 1.0);
    let r = in_range(rng, 0.5, 4.0);
    // A direction well away from the axis; the z-scale 1e9 makes the quadric a cylinder
    // over the heights reached.
    let (o, mut d) = inner_line(rng, &c, &[r, r, 1e9]);
    d[2] = d[2].clamp(-1.0, 1.0);
    if d[0].hypot(d[1]) < 0.3 {
        d[0] += 1.0;
    }
    let o = [o[0], o[1], c[2]];
    let hits = line_quadric(&o, &d, &c, &[r, r, f64::INFINITY]);
    let params = hits
        .iter()
        .map(|(t, p)| {
            let rel: Vec<Float> = (0..3)
                .map(|i| Float::with_val(PREC, &p[i] - c[i]))
                .collect();
            json!([
                [t.to_f64()],
                [angle(&rel[1], &rel[0]).to_f64(), rel[2].to_f64()]
            ])
        })
        .collect();
    Case {
        case: json!({"op": "intersect", "objects": [
            {"type": "line", "origin": o, "dir": d},
            {"type": "cylinder", "origin": c, "radius": r, "axis": [0, 0, 1], "height": [-100, 100]}]}),
        truths: hits.into_iter().map(|h| h.1).collect(),
        params: Some(params),
    }
}

/// Line along x (at height `z0`, offset `y0`) × torus of axis z: the crossings
/// `x = ±√((R ± √(r² − z0²))² − y0²)`, two or four.
pub fn line_torus(rng: &mut Rng) -> Case {
    let c = point3(rng, 1.0);
    let big = in_range(rng, 2.0, 5.0);
    let small = in_range(rng, 0.3, 1.0);
    let z0 = in_range(rng, -0.8, 0.8) * small;
    let w = (small * small - z0 * z0).sqrt();
    // y0 inside the hole (four crossings) or across the tube (two), away from tangency.
    let y0 = if rng.coin() {
        in_range(rng, 0.0, 0.8) * (big - w)
    } else {
        in_range(rng, 0.2, 0.8) * (2.0 * w) + (big - w)
    };
    let y0 = if rng.coin() { y0 } else { -y0 };
    // The line's origin in doubles; the truth uses its exact offsets from the center.
    let origin = [c[0], y0 + c[1], z0 + c[2]];
    let (fz0, fy0) = (f(origin[2]) - c[2], f(origin[1]) - c[1]);
    let fw = (f(small).square() - fz0.clone().square()).sqrt();
    let mut truths = vec![];
    for rho in [f(big) - &fw, f(big) + &fw] {
        let x2 = rho.square() - fy0.clone().square();
        if x2 > 0 {
            let x = x2.sqrt();
            for s in [-1, 1] {
                truths.push(vec![
                    Float::with_val(PREC, &x * s) + c[0],
                    f(origin[1]),
                    f(origin[2]),
                ]);
            }
        }
    }
    let params = truths
        .iter()
        .map(|p| {
            let (x, y) = (f(0.0) + &p[0] - c[0], f(0.0) + &p[1] - c[1]);
            let t = x.clone() - f(0.0);
            let rad = Float::with_val(PREC, x.hypot_ref(&y)) - big;
            let u = angle(&y, &x);
            let v = angle(&fz0, &rad);
            json!([[t.to_f64()], [u.to_f64(), v.to_f64()]])
        })
        .collect();
    Case {
        case: json!({"op": "intersect", "objects": [
            {"type": "line", "origin": origin, "dir": [1, 0, 0]},
            {"type": "torus", "center": c, "major": big, "minor": small, "axis": [0, 0, 1]}]}),
        truths,
        params: Some(params),
    }
}

/// The points of a circle of radius `rho` around `c` (frame X = x, Y = y) where
/// `p·n = k` for the unit direction of angle `phi`: `t = phi ± acos(k/rho)`.
fn circle_chord(c: &[Float], rho: &Float, phi: &Float, cos: &Float) -> Vec<(Float, Vec<Float>)> {
    let a = cos.clone().acos();
    [
        Float::with_val(PREC, phi - &a),
        Float::with_val(PREC, phi + &a),
    ]
    .into_iter()
    .map(|t| {
        let t = {
            let s = Float::with_val(PREC, t.sin_ref());
            let co = Float::with_val(PREC, t.cos_ref());
            angle(&s, &co)
        };
        let mut p: Vec<Float> = c.to_vec();
        p[0] += Float::with_val(PREC, rho * t.clone().cos());
        p[1] += Float::with_val(PREC, rho * t.clone().sin());
        (t, p)
    })
    .collect()
}

/// Two plane circles crossing at two points.
pub fn circle2_circle2(rng: &mut Rng) -> Case {
    let c1 = [rng.generic() * 0.5, rng.generic() * 0.5];
    let r1 = in_range(rng, 0.5, 4.0);
    let r2 = in_range(rng, 0.5, 4.0);
    // Center distance well inside (|r1 − r2|, r1 + r2).
    let lo = (r1 - r2).abs();
    let dist = lo + (r1 + r2 - lo) * in_range(rng, 0.15, 0.85);
    let dir = unit(rng, 2);
    let c2 = [c1[0] + dist * dir[0], c1[1] + dist * dir[1]];
    // On circle 1: p·dir = (r1² − r2² + dist²)/(2 dist), relative to c1.
    let fd = Float::with_val(
        PREC,
        (f(c2[0]) - c1[0]).square() + (f(c2[1]) - c1[1]).square(),
    )
    .sqrt();
    let k = (f(r1).square() - f(r2).square() + fd.clone().square()) / (2 * fd.clone());
    let phi = angle(&(f(c2[1]) - c1[1]), &(f(c2[0]) - c1[0]));
    let hits = circle_chord(&[f(c1[0]), f(c1[1])], &f(r1), &phi, &(k / r1));
    let params = hits
        .iter()
        .map(|(t, p)| {
            let t2 = angle(&(p[1].clone() - c2[1]), &(p[0].clone() - c2[0]));
            json!([[t.to_f64()], [t2.to_f64()]])
        })
        .collect();
    Case {
        case: json!({"op": "intersect", "objects": [
            {"type": "circle2", "center": c1, "radius": r1},
            {"type": "circle2", "center": c2, "radius": r2}]}),
        truths: hits.into_iter().map(|h| h.1).collect(),
        params: Some(params),
    }
}

/// A circle (axis z) × a sphere whose center lies off the circle's plane: the
/// sphere cuts the circle's plane in a circle, and the two meet at two points.
pub fn circle_sphere(rng: &mut Rng) -> Case {
    let c = point3(rng, 0.5);
    let rho = in_range(rng, 1.0, 4.0);
    let phi = in_range(rng, -3.0, 3.0);
    let cos = in_range(rng, -0.8, 0.8);
    let dist = in_range(rng, 0.5, 1.5) * rho;
    let h = in_range(rng, -1.0, 1.0);
    let s = [c[0] + dist * phi.cos(), c[1] + dist * phi.sin(), c[2] + h];
    // p·n = k on the circle with k = rho·cos; |p − s|² = R² gives R.
    let fc: Vec<Float> = c.iter().map(|x| f(*x)).collect();
    let sd: Vec<Float> = (0..3).map(|i| f(s[i]) - c[i]).collect();
    let fdist = Float::with_val(PREC, sd[0].hypot_ref(&sd[1]));
    let fphi = angle(&sd[1], &sd[0]);
    let k = f(rho) * cos;
    // R² = rho² − 2 k·dist + dist² + h²: rounded to a double radius, then k recomputed.
    let r2: Float = f(rho).square() - Float::with_val(PREC, &k * &fdist) * 2
        + fdist.clone().square()
        + sd[2].clone().square();
    let radius = r2.sqrt().to_f64();
    let k = (f(rho).square() + fdist.clone().square() + sd[2].clone().square()
        - f(radius).square())
        / (2 * fdist.clone());
    let hits = circle_chord(&fc, &f(rho), &fphi, &(k / rho));
    let params = hits
        .iter()
        .map(|(t, p)| {
            let rel: Vec<Float> = (0..3)
                .map(|i| Float::with_val(PREC, &p[i] - s[i]))
                .collect();
            let u = angle(&rel[1], &rel[0]);
            let v = Float::with_val(PREC, &rel[2] / radius).asin();
            json!([[t.to_f64()], [u.to_f64(), v.to_f64()]])
        })
        .collect();
    Case {
        case: json!({"op": "intersect", "objects": [
            {"type": "circle", "center": c, "radius": rho, "axis": [0, 0, 1]},
            {"type": "sphere", "center": s, "radius": radius}]}),
        truths: hits.into_iter().map(|h| h.1).collect(),
        params: Some(params),
    }
}

/// A point projected onto a circle (axis z): the nearest and the farthest point of
/// the circle along the direction of the point, `c ± ρ·(p − c)_xy/|(p − c)_xy|`.
pub fn project_circle(rng: &mut Rng) -> Case {
    let c = point3(rng, 0.5);
    let rho = in_range(rng, 0.5, 4.0);
    let w = unit(rng, 2);
    let k = in_range(rng, 0.1, 3.0) * rho;
    let p = [c[0] + k * w[0], c[1] + k * w[1], c[2] + rng.generic() * 0.3];
    let rel = [f(p[0]) - c[0], f(p[1]) - c[1]];
    let n = Float::with_val(PREC, rel[0].hypot_ref(&rel[1]));
    let truths: Vec<Vec<Float>> = [1, -1]
        .iter()
        .map(|s| {
            vec![
                f(c[0]) + Float::with_val(PREC, &rel[0] * rho) / &n * *s,
                f(c[1]) + Float::with_val(PREC, &rel[1] * rho) / &n * *s,
                f(c[2]),
            ]
        })
        .collect();
    let params = truths
        .iter()
        .map(|q| json!([[angle(&(q[1].clone() - c[1]), &(q[0].clone() - c[0])).to_f64()]]))
        .collect();
    Case {
        case: json!({"op": "project", "point": p,
                     "onto": {"type": "circle", "center": c, "radius": rho, "axis": [0, 0, 1]}}),
        truths,
        params: Some(params),
    }
}

/// A point projected onto a sphere: `c ± r·(p − c)/|p − c|`.
pub fn project_sphere(rng: &mut Rng) -> Case {
    let c = point3(rng, 0.5);
    let r = in_range(rng, 0.5, 4.0);
    let w = unit(rng, 3);
    let k = in_range(rng, 0.1, 3.0) * r;
    let p = [c[0] + k * w[0], c[1] + k * w[1], c[2] + k * w[2]];
    let rel: Vec<Float> = (0..3).map(|i| f(p[i]) - c[i]).collect();
    let n = rel
        .iter()
        .fold(f(0.0), |a, x| a + x.clone().square())
        .sqrt();
    let truths: Vec<Vec<Float>> = [1, -1]
        .iter()
        .map(|s| {
            (0..3)
                .map(|i| f(c[i]) + Float::with_val(PREC, &rel[i] * r) / &n * *s)
                .collect()
        })
        .collect();
    let params = truths
        .iter()
        .map(|q| {
            let rel: Vec<Float> = (0..3)
                .map(|i| Float::with_val(PREC, &q[i] - c[i]))
                .collect();
            let v = Float::with_val(PREC, &rel[2] / r).asin();
            json!([[angle(&rel[1], &rel[0]).to_f64(), v.to_f64()]])
        })
        .collect();
    Case {
        case: json!({"op": "project", "point": p,
                     "onto": {"type": "sphere", "center": c, "radius": r}}),
        truths,
        params: Some(params),
    }
}

/// A point projected onto a torus (axis z): in the half-planes of `u₀ = atan2(p)` and
/// `u₀ + π`, the two points of each tube circle along the direction of the point —
/// four stationary points.
pub fn project_torus(rng: &mut Rng) -> Case {
    let c = point3(rng, 0.5);
    let big = in_range(rng, 2.0, 5.0);
    let small = in_range(rng, 0.3, 1.0);
    let w = unit(rng, 2);
    // Away from the tube's center circle, where the feet turn with the point.
    let (k, z) = loop {
        let k = in_range(rng, 0.3, 1.7) * big;
        let z = in_range(rng, -1.0, 1.0) * small;
        if (k - big).hypot(z) > 0.3 * small {
            break (k, z);
        }
    };
    let p = [c[0] + k * w[0], c[1] + k * w[1], c[2] + z];
    let rel: Vec<Float> = (0..3).map(|i| f(p[i]) - c[i]).collect();
    let u0 = angle(&rel[1], &rel[0]);
    let mut truths = vec![];
    let mut params = vec![];
    for u in [u0.clone(), Float::with_val(PREC, &u0 + pi())] {
        let (cu, su) = (u.clone().cos(), u.clone().sin());
        let center = [
            Float::with_val(PREC, &cu * big),
            Float::with_val(PREC, &su * big),
            f(0.0),
        ];
        let d: Vec<Float> = (0..3)
            .map(|i| Float::with_val(PREC, &rel[i] - &center[i]))
            .collect();
        let n = d.iter().fold(f(0.0), |a, x| a + x.clone().square()).sqrt();
        for s in [1, -1] {
            let q: Vec<Float> = (0..3)
                .map(|i| f(c[i]) + &center[i] + Float::with_val(PREC, &d[i] * small) / &n * s)
                .collect();
            let radial = Float::with_val(PREC, &d[0] * &cu) + Float::with_val(PREC, &d[1] * &su);
            let (vz, vr) = (
                Float::with_val(PREC, &d[2] * s),
                Float::with_val(PREC, radial * s),
            );
            let uu = angle(&u.clone().sin(), &u.clone().cos());
            params.push(json!([[uu.to_f64(), angle(&vz, &vr).to_f64()]]));
            truths.push(q);
        }
    }
    Case {
        case: json!({"op": "project", "point": p,
                     "onto": {"type": "torus", "center": c, "major": big, "minor": small, "axis": [0, 0, 1]}}),
        truths,
        params: Some(params),
    }
}

/// Three spheres centred at `o`, `o + (d, 0, 0)`, `o + (0, e, 0)`: `x = (r₁² − r₂² +
/// d²)/2d`, `y = (r₁² − r₃² + e²)/2e`, `z = ±√(r₁² − x² − y²)`.
pub fn three_spheres(rng: &mut Rng) -> Case {
    let o = point3(rng, 0.5);
    let r1 = in_range(rng, 2.0, 4.0);
    // The two points, chosen first: (x, y, ±z) with |(x, y)| well inside r1.
    let w = unit(rng, 2);
    let k = in_range(rng, 0.1, 0.7) * r1;
    let (x, y) = (k * w[0], k * w[1]);
    let d = in_range(rng, 1.0, 3.0);
    let e = in_range(rng, 1.0, 3.0);
    // r2, r3 as doubles; x, y are then recomputed from them exactly in MPFR.
    let r2 = (r1 * r1 - 2.0 * d * x + d * d).sqrt();
    let r3 = (r1 * r1 - 2.0 * e * y + e * e).sqrt();
    // The centers in doubles; the truth uses their exact offsets.
    let (c2, c3) = ([o[0] + d, o[1], o[2]], [o[0], o[1] + e, o[2]]);
    let (fd, fe) = (f(c2[0]) - o[0], f(c3[1]) - o[1]);
    let fx: Float = (f(r1).square() - f(r2).square() + fd.clone().square()) / (2 * fd);
    let fy: Float = (f(r1).square() - f(r3).square() + fe.clone().square()) / (2 * fe);
    let fz2: Float = f(r1).square() - fx.clone().square() - fy.clone().square();
    let fz = fz2.sqrt();
    let truths = [1, -1]
        .iter()
        .map(|s| {
            vec![
                fx.clone() + o[0],
                fy.clone() + o[1],
                Float::with_val(PREC, &fz * *s) + o[2],
            ]
        })
        .collect();
    Case {
        case: json!({"op": "intersect", "objects": [
            {"type": "sphere", "center": o, "radius": r1},
            {"type": "sphere", "center": c2, "radius": r2},
            {"type": "sphere", "center": c3, "radius": r3}]}),
        truths,
        params: None,
    }
}

/// Every family, by name.
/// A family: its name and its case generator.
pub type Family = (&'static str, fn(&mut Rng) -> Case);

pub fn families() -> Vec<Family> {
    vec![
        ("line_sphere", line_sphere),
        ("line_ellipsoid", line_ellipsoid),
        ("line_cylinder", line_cylinder),
        ("line_torus", line_torus),
        ("circle2_circle2", circle2_circle2),
        ("circle_sphere", circle_sphere),
        ("project_circle", project_circle),
        ("project_sphere", project_sphere),
        ("project_torus", project_torus),
        ("three_spheres", three_spheres),
    ]
}

/// Cases per family (`GEOCERT_VERIFY_CASES`, default `default`).
pub fn count(default: usize) -> usize {
    std::env::var("GEOCERT_VERIFY_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// A claim of the given points at the tolerance.
pub fn point_claim(points: &[Vec<f64>], tol: f64) -> Value {
    json!({"points": points.iter().map(|p| json!({"xyz": xyz(p)})).collect::<Vec<_>>(),
           "tolerance": tol})
}

/// The truth `t` lies in the point's `box` (no slack).
pub fn holds(p: &Value, t: &[Float]) -> bool {
    p["box"].as_array().unwrap().iter().zip(t).all(|(b, x)| {
        let (lo, hi) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
        *x >= lo && *x <= hi
    })
}

/// The diameter of a point's box.
pub fn diameter(p: &Value) -> f64 {
    p["box"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b[1].as_f64().unwrap() - b[0].as_f64().unwrap())
        .map(|w| w * w)
        .sum::<f64>()
        .sqrt()
}

/// The answer is decided and complete, with as many points as there are solutions,
/// each holding exactly one truth in its box; the diameter of each truth's box.
pub fn truth_known(name: &str, r: &Value, truths: &[Vec<Float>]) -> Vec<f64> {
    assert_ne!(r["status"], "undecided", "{name}: {r}");
    assert_eq!(r["complete"], true, "{name}: {r}");
    let points = r["points"].as_array().cloned().unwrap_or_default();
    assert_eq!(points.len(), truths.len(), "{name}: {r}");
    truths
        .iter()
        .map(|t| {
            let h: Vec<&Value> = points.iter().filter(|p| holds(p, t)).collect();
            assert_eq!(
                h.len(),
                1,
                "{name}: one box per truth {:?}: {r}",
                doubles(t)
            );
            diameter(h[0])
        })
        .collect()
}

/// Every verdict on claims by coordinates agrees with the truth: `confirmed` only with
/// a true solution within `tol`, `refuted` only with none.
pub fn sound(name: &str, r: &Value, claimed: &[Vec<f64>], truths: &[Vec<Float>], tol: f64) {
    let tolf = Float::with_val(PREC, tol);
    for (i, c) in claimed.iter().enumerate() {
        let near = truths.iter().any(|t| distance(c, t) <= tolf);
        match r["claims"][i]["verdict"].as_str().unwrap() {
            "confirmed" => assert!(near, "{name}: confirmed far from every solution {c:?}: {r}"),
            "refuted" => assert!(!near, "{name}: refuted near a solution {c:?}: {r}"),
            _ => {}
        }
    }
}
