//! A ray against an unbounded-form conic or quadric (a `conic2`, an implicit `quadric`)
//! was an `unsupported` error ("the line needs a `range` here"): the exact pair is now
//! asked for the ray's carrier and the common points kept where they lie on the ray.
//!
//! Family: circles as `conic2` and spheres as `quadric` (exact small-integer centres,
//! dyadic radii), rays from random points and from a point of the curve (a root at the
//! ray's start, `t = 0`), both ways (`[0, null]` and `[null, 0]`). Truth: the quadratic
//! `|o + t d − c|² = r²` in 256-bit MPFR, roots on the ray's side; each answer must be
//! exact, complete, one point per root with the root in its ray-parameter box.

use geocert::io::{read_cases, solve_case};
use geocert::num::rng::Rng;
use rug::Float;
use serde_json::{json, Value};

fn solve(case: &Value) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&solve_case(read).to_json_line()).unwrap()
}

fn f(x: f64) -> Float {
    Float::with_val(256, x)
}

/// The roots of `|o + t d − c|² = r²` on the side `ahead` (`t ≥ 0`) or behind.
fn truth(o: &[f64], d: &[f64], c: &[f64], r: f64, ahead: bool) -> Vec<Float> {
    let w: Vec<Float> = o.iter().zip(c).map(|(o, c)| f(*o) - c).collect();
    let a = d.iter().fold(f(0.0), |s, x| s + f(*x) * x);
    let b = w.iter().zip(d).fold(f(0.0), |s, (w, x)| s + w.clone() * x);
    let cc = w.iter().fold(f(0.0), |s, w| s + w.clone().square()) - f(r) * r;
    let disc = b.clone().square() - a.clone() * &cc;
    let mut ts = Vec::new();
    if disc.is_zero() {
        ts.push(-b.clone() / &a);
    } else if disc > 0 {
        for s in [-1, 1] {
            ts.push((-b.clone() + disc.clone().sqrt() * s) / &a);
        }
    }
    ts.retain(|t| if ahead { *t >= 0 } else { *t <= 0 });
    ts
}

#[test]
fn rays_against_conic2_circles_and_quadric_spheres() {
    let mut rng = Rng::new(0x7a75);
    let (mut points, mut at_start, mut empty) = (0, 0, 0);
    for case in 0..160 {
        let dim = if case % 2 == 0 { 2 } else { 3 };
        let c: Vec<f64> = (0..dim).map(|_| rng.small_int()).collect();
        let r = rng.dyadic().abs() + 0.5;
        let d: Vec<f64> = loop {
            let d: Vec<f64> = (0..dim).map(|_| rng.small_int()).collect();
            if d.iter().any(|&x| x != 0.0) {
                break d;
            }
        };
        // From a point of the curve (x = c + r) every fourth case, else from nearby.
        let o: Vec<f64> = if case % 4 < 2 {
            (0..dim)
                .map(|i| c[i] + if i == 0 { r } else { 0.0 })
                .collect()
        } else {
            (0..dim).map(|i| c[i] + rng.generic() * 0.4).collect()
        };
        let other = if dim == 2 {
            json!({"type": "conic2", "coeffs": [1, 0, 1, -2.0 * c[0], -2.0 * c[1],
                c[0] * c[0] + c[1] * c[1] - r * r]})
        } else {
            let n2: f64 = c.iter().map(|x| x * x).sum();
            json!({"type": "quadric", "matrix": [[1, 0, 0, -c[0]], [0, 1, 0, -c[1]],
                [0, 0, 1, -c[2]], [-c[0], -c[1], -c[2], n2 - r * r]]})
        };
        for ahead in [true, false] {
            let range = if ahead {
                json!([0, null])
            } else {
                json!([null, 0])
            };
            let ray = json!({"type": if dim == 2 { "line2" } else { "line" }, "origin": o,
                "dir": d, "range": range});
            let ray_first = case % 3 == 0;
            let objects = if ray_first {
                json!([ray, other])
            } else {
                json!([other, ray])
            };
            let answer = solve(&json!({"id": case, "op": "intersect", "objects": objects}));
            let tag = format!("case {case} ahead {ahead}");
            assert_eq!(answer["status"], json!("exact"), "{tag}: {answer}");
            assert_eq!(answer["complete"], json!(true), "{tag}: {answer}");
            let ts = truth(&o, &d, &c, r, ahead);
            let pts = answer["points"].as_array().unwrap();
            assert_eq!(pts.len(), ts.len(), "{tag}: {answer}");
            let at = usize::from(!ray_first);
            for t in &ts {
                let inside = pts.iter().any(|p| {
                    let b = &p["param_box"][at][0];
                    *t >= b[0].as_f64().unwrap() && *t <= b[1].as_f64().unwrap()
                });
                assert!(inside, "{tag}: root {} in no box: {answer}", t.to_f64());
                at_start += usize::from(t.is_zero());
            }
            points += ts.len();
            empty += usize::from(ts.is_empty());
        }
    }
    assert!(
        points >= 150 && at_start >= 60 && empty >= 30,
        "{points} points, {at_start} at the start, {empty} empty"
    );
}
