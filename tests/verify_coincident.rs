//! `verify` of a claimed `arc` when the answer is `coincident` (issue 20): one shape lies
//! in the other, so the arcs the two share are arcs of the smaller one. A generated
//! family with exact truth — every coordinate below is a double taken exactly:
//!
//! - a quadratic Bézier on a 2D line (control points on the line, monotone);
//! - a rational quadratic arc of a circle (weights `q, p, q` for a half-angle `φ` with
//!   `cos φ = p/q`, `sin φ = r/q` from a Pythagorean triple), as `bezier2` or as a
//!   one-piece `nurbs_curve2`, on its `circle2`;
//! - a cubic Bézier in a plane;
//! - the same circle twice;
//!
//! each in both orders, rotated by quarter turns, translated, and scaled by `2^s`
//! (`s` = 0, ±500: coordinates near 10^±150). Claimed ends are points exactly on the
//! curve, points of the larger shape beyond the curve (on the line past the Bézier's
//! ends, on the circle past the arc, in the plane away from the curve), and points
//! moved off an interior point of the curve along its normal, `2^-16` of the tolerance
//! inside or outside it (the exact distance to the curve is the length of that move).
//! A claim is never confirmed with an end beyond the tolerance of the curve, never
//! refuted with both ends within it, and at scale 1 always decided.

use geocert::io::{read_cases, verify_case};
use geocert::num::rng::Rng;
use serde_json::{json, Value};

fn verify(case: &Value) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&verify_case(read).to_json_line()).unwrap()
}

/// One generated pair: the objects (in order), points exactly on the curve, points of
/// the larger shape (or of space) beyond the tolerance of the curve, and an interior
/// point of the curve with an exact normal direction `n` (moving by `λn` puts the point
/// at distance `λ|n|`, `|n|` given).
struct Setup {
    name: &'static str,
    objects: Vec<Value>,
    on: Vec<Vec<f64>>,
    off: Vec<Vec<f64>>,
    interior: Vec<f64>,
    normal: Vec<f64>,
    normal_len: f64,
}

/// Pythagorean half-angles `(p, r, q)`: `cos φ = p/q`, `sin φ = r/q`.
const HALF_ANGLES: [(i64, i64, i64); 4] = [(4, 3, 5), (12, 5, 13), (3, 4, 5), (24, 7, 25)];

fn rotate(v: [i64; 2], quarter: usize) -> [i64; 2] {
    (0..quarter).fold(v, |[x, y], _| [-y, x])
}

fn bezier_on_line(rng: &mut Rng) -> Setup {
    let (p, r, q) = HALF_ANGLES[rng.below(4)];
    let g = rng.int(1, 3);
    let d = rotate([g * p, g * r], rng.below(4));
    let o = [rng.int(-20, 20), rng.int(-20, 20)];
    let a = rng.int(-6, 0);
    let b = a + rng.int(1, 4);
    let c = b + rng.int(1, 4);
    let at = |k: f64| vec![o[0] as f64 + k * d[0] as f64, o[1] as f64 + k * d[1] as f64];
    let mid = (a + 2 * b + c) as f64 / 4.0;
    Setup {
        name: "bezier on line2",
        objects: vec![
            json!({"type": "line2", "origin": o, "dir": d}),
            json!({"type": "bezier2", "points": [at(a as f64), at(b as f64), at(c as f64)]}),
        ],
        on: vec![at(a as f64), at(c as f64), at(mid)],
        off: vec![at((c + 1) as f64), at((a - 2) as f64), at((c + 7) as f64)],
        interior: at(mid),
        normal: vec![-d[1] as f64, d[0] as f64],
        normal_len: (g * q) as f64,
    }
}

fn arc_on_circle(rng: &mut Rng) -> Setup {
    let (p, r, q) = HALF_ANGLES[rng.below(4)];
    let k = rng.int(1, 3);
    let radius = k * q * q * p;
    let turn = rng.below(4);
    let c = [rng.int(-50, 50), rng.int(-50, 50)];
    let pt = |v: [i64; 2]| {
        let v = rotate(v, turn);
        vec![(c[0] + v[0]) as f64, (c[1] + v[1]) as f64]
    };
    let controls = [
        pt([radius, 0]),
        pt([radius, k * q * q * r]),
        pt([k * p * (p * p - r * r), k * p * 2 * p * r]),
    ];
    let weights = [q, p, q];
    let curve = if rng.coin() {
        json!({"type": "bezier2", "points": controls, "weights": weights})
    } else {
        json!({"type": "nurbs_curve2", "degree": 2, "knots": [0, 0, 0, 1, 1, 1],
               "points": controls, "weights": weights})
    };
    let mid = pt([k * q * p * p, k * q * p * r]);
    let radial = rotate([p, r], turn);
    Setup {
        name: "rational arc on circle2",
        objects: vec![
            json!({"type": "circle2", "center": c, "radius": radius}),
            curve,
        ],
        on: vec![controls[0].clone(), controls[2].clone(), mid.clone()],
        off: vec![
            pt([-radius, 0]),
            pt([k * q * p * p, -k * q * p * r]), // the circle just before the arc
            pt([0, -radius]),
        ],
        interior: mid,
        normal: vec![radial[0] as f64, radial[1] as f64],
        normal_len: q as f64,
    }
}

fn bezier_in_plane(rng: &mut Rng) -> Setup {
    let h = rng.int(-9, 9) as f64;
    let points: Vec<Vec<f64>> = (0..4)
        .map(|i| {
            vec![
                (3 * i) as f64 + rng.int(0, 2) as f64,
                rng.int(-8, 8) as f64,
                h,
            ]
        })
        .collect();
    let at = |t: f64| -> Vec<f64> {
        let w = [
            (1.0 - t).powi(3),
            3.0 * t * (1.0 - t).powi(2),
            3.0 * t * t * (1.0 - t),
            t.powi(3),
        ];
        (0..3)
            .map(|i| (0..4).map(|j| w[j] * points[j][i]).sum())
            .collect()
    };
    Setup {
        name: "bezier in plane",
        objects: vec![
            json!({"type": "plane", "normal": [0, 0, 2], "d": -2.0 * h}),
            json!({"type": "bezier", "points": points}),
        ],
        on: vec![at(0.0), at(1.0), at(0.5), at(0.25)],
        off: vec![vec![-30.0, 0.0, h], vec![5.0, 40.0, h], vec![60.0, -3.0, h]],
        interior: at(0.5),
        normal: vec![0.0, 0.0, 1.0],
        normal_len: 1.0,
    }
}

fn same_circle(rng: &mut Rng) -> Setup {
    let radius = rng.int(1, 40);
    let c = [rng.int(-50, 50), rng.int(-50, 50)];
    let circle = json!({"type": "circle2", "center": c, "radius": radius});
    let pt = |x: i64, y: i64| vec![(c[0] + x) as f64, (c[1] + y) as f64];
    Setup {
        name: "same circle2 twice",
        objects: vec![circle.clone(), circle],
        on: vec![pt(radius, 0), pt(0, radius), pt(-radius, 0)],
        off: vec![pt(2 * radius, 0), pt(radius, radius), pt(0, -3 * radius)],
        interior: pt(0, -radius),
        normal: vec![0.0, -1.0],
        normal_len: 1.0,
    }
}

/// `2^s` times every number in a JSON value (exact for doubles far from the range's
/// ends); knots, weights and a plane's normal are left alone (its `d` scales).
fn scaled(v: &Value, s: f64) -> Value {
    match v {
        Value::Number(n) => json!(n.as_f64().unwrap() * s),
        Value::Array(a) => Value::Array(a.iter().map(|x| scaled(x, s)).collect()),
        Value::Object(o) => Value::Object(
            o.iter()
                .map(|(k, x)| {
                    let keep = matches!(
                        k.as_str(),
                        "knots" | "weights" | "degree" | "type" | "normal"
                    );
                    (k.clone(), if keep { x.clone() } else { scaled(x, s) })
                })
                .collect(),
        ),
        _ => v.clone(),
    }
}

fn verdict(r: &Value) -> String {
    let item = r["claims"]
        .as_array()
        .and_then(|c| c.iter().find(|c| c["item"] == "arc"));
    item.map_or_else(
        || format!("no arc verdict: {r}"),
        |c| c["verdict"].as_str().unwrap().to_string(),
    )
}

#[test]
fn coincident_arcs_are_judged_on_the_smaller_shape() {
    let mut rng = Rng::new(0xc01c1de);
    let (mut checked, mut decided_far) = (0, 0);
    for case in 0..48 {
        let setup = match case % 4 {
            0 => bezier_on_line(&mut rng),
            1 => arc_on_circle(&mut rng),
            2 => bezier_in_plane(&mut rng),
            _ => same_circle(&mut rng),
        };
        let mut objects = setup.objects.clone();
        if rng.coin() {
            objects.reverse();
        }
        for s in [0, 500, -500] {
            let f = 2f64.powi(s);
            let tol = setup.normal_len * 2f64.powi(-10) * f;
            let pt = |p: &Vec<f64>| json!(p.iter().map(|x| x * f).collect::<Vec<_>>());
            let moved = |lambda: f64| -> Value {
                pt(&setup
                    .interior
                    .iter()
                    .zip(&setup.normal)
                    .map(|(x, n)| x + lambda * n)
                    .collect())
            };
            let objects = scaled(&json!(objects), f);
            let run = |a: Value, b: Value| {
                let claim = json!({"arc": {"a": a, "b": b}, "tolerance": tol});
                let r = verify(&json!({"op": "intersect", "objects": objects, "claim": claim}));
                assert_eq!(
                    r["kind"], "coincident",
                    "{} case {case} scale 2^{s}: {r}",
                    setup.name
                );
                verdict(&r)
            };
            let what = |w: &str| format!("{} case {case} scale 2^{s}: {w}", setup.name);
            let step = 2f64.powi(-10);
            let within = [
                (
                    json!({"xyz": pt(&setup.on[0])}),
                    json!({"xyz": pt(&setup.on[1])}),
                ),
                (
                    json!({"xyz": pt(&setup.on[2])}),
                    json!({"xyz": pt(&setup.on[0])}),
                ),
                (
                    json!({"xyz": moved(step * (1.0 - 2f64.powi(-16)))}),
                    json!({"xyz": pt(&setup.on[1])}),
                ),
                (
                    json!({"xyz": pt(&setup.on[1])}),
                    json!({"xyz": moved(-step * (1.0 - 2f64.powi(-16)))}),
                ),
            ];
            for (i, (a, b)) in within.into_iter().enumerate() {
                let v = run(a, b);
                assert_ne!(
                    v,
                    "refuted",
                    "{}",
                    what(&format!("ends within the tolerance ({i})"))
                );
                if s == 0 {
                    assert_eq!(v, "confirmed", "{}", what(&format!("ends within ({i})")));
                }
                checked += 1;
            }
            let mut beyond: Vec<(Value, Value)> = setup
                .off
                .iter()
                .map(|o| (json!({"xyz": pt(&setup.on[2])}), json!({"xyz": pt(o)})))
                .collect();
            beyond.push((
                json!({"xyz": moved(step * (1.0 + 2f64.powi(-16)))}),
                json!({"xyz": pt(&setup.on[0])}),
            ));
            beyond.push((
                json!({"xyz": pt(&setup.on[0])}),
                json!({"xyz": moved(-step * (1.0 + 2f64.powi(-16)))}),
            ));
            for (i, (a, b)) in beyond.into_iter().enumerate() {
                let v = run(a, b);
                assert_ne!(
                    v,
                    "confirmed",
                    "{}",
                    what(&format!("an end beyond the tolerance ({i})"))
                );
                if s == 0 {
                    assert_eq!(v, "refuted", "{}", what(&format!("an end beyond ({i})")));
                } else if v == "refuted" {
                    decided_far += 1;
                }
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 48 * 3 * 9);
    eprintln!("far scales: {decided_far} beyond-claims refuted");
}
