//! A helix against an implicit plane `n·x + d = 0` (OPERATIONS.md §13.4): the plane's
//! doubles are exact, and the certified roots must be those of that plane — not of a
//! parametric plane rebuilt from it in f64 (origin `−d n/|n|²` and a frame, each
//! rounded), whose roots near a tangency moved by 1e-13 while their boxes were 2e-15
//! wide: `verified` boxes that held no root of the input.
//!
//! Family: normals with components like 1, 3, 0.1, 1e-3 (rarely powers of two), helices
//! of several pitches and radii about the z axis, planes through a random point of the
//! helix and planes 1e-9, 1e-12 and 1e-15 (relative) from tangency on both sides. The
//! truth is independent of the solver: on the helix `g(t) = A cos t + B sin t + C t + D`,
//! whose critical points are `t = ψ ± acos(−C/R) + 2kπ` in closed form; between two of
//! them `g` is monotone, so its roots are found by bisection in 256-bit MPFR.

use geocert::io::{read_cases, solve_case};
use geocert::num::rng::Rng;
use rug::float::Constant;
use rug::ops::Pow;
use rug::Float;
use serde_json::{json, Value};

const PREC: u32 = 256;

fn f(x: f64) -> Float {
    Float::with_val(PREC, x)
}

/// `g(t) = A cos t + B sin t + C t + D` of the helix `(r cos t, r sin t, p t/2π)` and
/// the plane `n·x + d = 0`.
struct G {
    a: Float,
    b: Float,
    c: Float,
    d: Float,
}

impl G {
    fn new(n: [f64; 3], d: f64, radius: f64, pitch: f64) -> G {
        let two_pi = Float::with_val(PREC, Constant::Pi) * 2u32;
        G {
            a: f(n[0]) * f(radius),
            b: f(n[1]) * f(radius),
            c: f(n[2]) * f(pitch) / two_pi,
            d: f(d),
        }
    }

    fn at(&self, t: &Float) -> Float {
        self.a.clone() * t.clone().cos()
            + self.b.clone() * t.clone().sin()
            + self.c.clone() * t
            + &self.d
    }

    /// Every root in `[lo, hi]`, increasing (module doc).
    fn roots(&self, lo: f64, hi: f64) -> Vec<Float> {
        // g' = −A sin t + B cos t + C = R cos(t + ψ) + C with R = √(A² + B²),
        // ψ = atan2(A, B).
        let r = (self.a.clone().square() + self.b.clone().square()).sqrt();
        let psi = self.a.clone().atan2(&self.b);
        let mut cuts = vec![f(lo), f(hi)];
        let ratio = -self.c.clone() / &r;
        if ratio.clone().abs() <= 1 {
            let alpha = ratio.acos();
            let two_pi = Float::with_val(PREC, Constant::Pi) * 2u32;
            for k in -3..6 {
                for s in [1, -1] {
                    let t = alpha.clone() * s - &psi + two_pi.clone() * k;
                    if t > lo && t < hi {
                        cuts.push(t);
                    }
                }
            }
        }
        cuts.sort_by(|x, y| x.partial_cmp(y).unwrap());
        let mut roots: Vec<Float> = Vec::new();
        for w in cuts.windows(2) {
            let (mut a, mut b) = (w[0].clone(), w[1].clone());
            let (ga, gb) = (self.at(&a), self.at(&b));
            if ga.is_zero() {
                roots.push(a.clone());
                continue;
            }
            if (ga.is_sign_negative()) == (gb.is_sign_negative()) || gb.is_zero() {
                continue;
            }
            for _ in 0..200 {
                let m = (a.clone() + &b) / 2u32;
                if (self.at(&m).is_sign_negative()) == ga.is_sign_negative() {
                    a = m;
                } else {
                    b = m;
                }
            }
            roots.push(a);
        }
        let end = f(hi);
        if self.at(&end).is_zero() {
            roots.push(end);
        }
        roots.dedup_by(|x, y| (x.clone() - &*y).abs() < Float::with_val(PREC, 2).pow(-200));
        roots
    }
}

fn solve(case: &Value) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&solve_case(read).to_json_line()).unwrap()
}

/// The helix's parameter boxes of the answer's points (the helix is object `at`).
fn boxes(answer: &Value, at: usize) -> Vec<(f64, f64)> {
    answer["points"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|p| {
            let b = &p["param_box"][at][0];
            (b[0].as_f64().unwrap(), b[1].as_f64().unwrap())
        })
        .collect()
}

const NORMALS: [f64; 7] = [1.0, 3.0, -1.0, 0.1, 0.3, 1e-3, 2.0];

#[test]
fn helix_roots_on_an_implicit_plane_lie_in_their_boxes() {
    let mut rng = Rng::new(0x4e11c5);
    let (mut checked, mut roots_seen, mut near) = (0, 0, 0);
    for case in 0..240 {
        let n = [0; 3].map(|_| NORMALS[rng.below(NORMALS.len())]);
        let radius = [1.0, 0.7, 3.0][rng.below(3)];
        let pitch = [1.0, 0.5, 2.0, 6.25][rng.below(4)];
        let hi = 12.0;
        let g0 = G::new(n, 0.0, radius, pitch);
        // The plane through the helix's point at t0 (case % 4 == 0), or shifted from
        // its nearest tangency by a relative 1e-9, 1e-12, 1e-15 to either side.
        let t0 = f(hi / 2.0 + rng.unit() * (hi / 2.0 - 0.5));
        let mut d = -g0.at(&t0);
        if case % 4 != 0 {
            let r = (g0.a.clone().square() + g0.b.clone().square()).sqrt();
            let ratio = -g0.c.clone() / &r;
            if ratio.clone().abs() < 1 {
                // A critical point in the middle of the range: g there is an extremum.
                let psi = g0.a.clone().atan2(&g0.b);
                let mut tc = ratio.acos() - &psi;
                let two_pi = Float::with_val(PREC, Constant::Pi) * 2u32;
                while tc < 3.0 {
                    tc += &two_pi;
                }
                let scale = [1e-9, 1e-12, 1e-15][case % 4 - 1];
                let side = if rng.coin() { 1.0 } else { -1.0 };
                d = -g0.at(&tc) * (1.0 + side * scale);
                near += 1;
            }
        }
        let d = d.to_f64();
        let truth = G::new(n, d, radius, pitch).roots(0.0, hi);
        let helix = json!({"type": "helix", "center": [0, 0, 0], "radius": radius,
            "pitch": pitch, "axis": [0, 0, 1], "range": [0, hi]});
        let plane = json!({"type": "plane", "normal": n, "d": d});
        let plane_first = case % 2 == 1;
        let objects = if plane_first {
            json!([plane, helix])
        } else {
            json!([helix, plane])
        };
        let answer = solve(&json!({"id": case, "op": "intersect", "objects": objects}));
        let status = answer["status"].as_str().unwrap();
        assert!(
            !matches!(status, "error" | "exact"),
            "case {case}: {answer}"
        );
        if status == "undecided" {
            continue;
        }
        let at = usize::from(plane_first);
        let bs = boxes(&answer, at);
        // Every box holds a root of the exact input; a verified box exactly one.
        for (k, &(lo, hi)) in bs.iter().enumerate() {
            let inside = truth.iter().filter(|t| **t >= lo && **t <= hi).count();
            let tangent = answer["points"][k]["tangent"].as_bool() == Some(true);
            assert!(
                if tangent { inside <= 2 } else { inside == 1 },
                "case {case}: box [{lo}, {hi}] holds {inside} roots of {:?}: {answer}",
                truth.iter().map(Float::to_f64).collect::<Vec<_>>()
            );
        }
        // Complete: every root lies in a box.
        if answer["complete"] == json!(true) {
            for t in &truth {
                assert!(
                    bs.iter().any(|&(lo, hi)| *t >= lo && *t <= hi),
                    "case {case}: the root {} is in no box: {answer}",
                    t.to_f64()
                );
            }
        }
        roots_seen += truth.len();
        checked += 1;
    }
    assert!(checked >= 200, "only {checked} decided answers");
    assert!(
        near >= 100 && roots_seen >= 400,
        "{near} near-tangent cases, {roots_seen} roots"
    );
}
