//! "Never a hang" (issue 20; docs/RELIABILITY.md, findings 3 and 6): the fuzzer's
//! over-time inputs, generalised into families. A curve against an identical copy of
//! itself (rational weights 1e±30, huge and tiny control points, repeated or collapsed
//! points) is `coincident`, decided exactly without subdividing. Hard cases (those
//! copies perturbed, rational cubics with a control point near 1e41 against planes,
//! spheres against cylinders at 1e±150, patches against quadrics) run with a deadline
//! already passed (`time_limit` 1e-300 s, which is no time at all) or a box budget of 1,
//! and must come back: either a complete exact answer, or an answer that names the
//! limit that stopped it. The assertions are on status and reason, never on elapsed
//! time; a case that ignored the limit would make the suite hang, not pass.

use geocert::io::{read_cases, solve_case};
use geocert::num::rng::Rng;
use serde_json::{json, Value};

fn run(case: &Value) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&solve_case(read).to_json_line()).unwrap()
}

fn intersect(a: &Value, b: &Value, options: Value) -> Value {
    json!({"op": "intersect", "objects": [a, b], "options": options})
}

/// A double of magnitude `10^k`, `k` in `[-e, e]`, of either sign.
fn magnitude(rng: &mut Rng, e: i64) -> f64 {
    let s = if rng.coin() { 1.0 } else { -1.0 };
    s * (1.0 + rng.unit()) * 10f64.powi(rng.int(-e, e) as i32)
}

fn points(rng: &mut Rng, n: usize, dim: usize, e: i64) -> Vec<Vec<f64>> {
    (0..n)
        .map(|_| (0..dim).map(|_| magnitude(rng, e)).collect())
        .collect()
}

/// A plane or space curve of one of the adversarial kinds the fuzzer found.
fn hard_curve(rng: &mut Rng, dim: usize) -> Value {
    let n = 2 + rng.below(4);
    let (bezier, polyline) = if dim == 2 {
        ("bezier2", "polyline2")
    } else {
        ("bezier", "polyline")
    };
    match rng.below(5) {
        // rational, weights 1e±30, points 1e±30
        0 => {
            let w: Vec<f64> = (0..n).map(|_| magnitude(rng, 30).abs()).collect();
            json!({"type": bezier, "points": points(rng, n, dim, 30), "weights": w})
        }
        // every control point the same: the curve is one point
        1 => {
            let p = points(rng, 1, dim, 30).remove(0);
            json!({"type": bezier, "points": vec![p; n]})
        }
        // a polyline whose points repeat
        2 => {
            let mut p = points(rng, 2, dim, 4);
            let last = p[1].clone();
            p.extend(std::iter::repeat_n(last, n));
            json!({"type": polyline, "points": p})
        }
        // a huge control point among small ones
        3 => {
            let mut p = points(rng, n, dim, 2);
            p[rng.below(n)][0] = magnitude(rng, 41).abs().max(1e30);
            json!({"type": bezier, "points": p})
        }
        // an ordinary small curve
        _ => json!({"type": bezier, "points": points(rng, n, dim, 1)}),
    }
}

#[test]
fn a_curve_against_an_identical_copy_is_coincident_exactly() {
    let mut rng = Rng::new(2020);
    for i in 0..300 {
        let c = hard_curve(&mut rng, 2 + i % 2);
        let r = run(&intersect(&c, &c, json!({"time_limit": 30})));
        assert_eq!(r["status"], "exact", "{c}: {r}");
        assert_eq!(r["kind"], "coincident", "{c}: {r}");
        assert_eq!(r["complete"], true, "{c}: {r}");
        assert_eq!(r["reason"], "the two curves are identical", "{r}");
    }
}

/// A copy of `c` with its first number moved by one ulp: not identical, so the
/// numeric route runs (and has the curves nearly overlapping).
fn nudged(c: &Value) -> Value {
    let mut d = c.clone();
    let x = d["points"][0][0].as_f64().unwrap();
    d["points"][0][0] = json!(f64::from_bits(x.to_bits() + 1));
    d
}

fn surfaces(rng: &mut Rng) -> (Value, Value) {
    let s = magnitude(rng, 150).abs();
    match rng.below(4) {
        0 => (
            json!({"type": "sphere", "center": [0, 0, 0], "radius": s}),
            json!({"type": "cylinder", "origin": [0, 0, -2.0 * s], "axis": [0, 0, 1],
                   "radius": s * (1.0 - 1e-9 * rng.unit()), "height": [0, 4.0 * s]}),
        ),
        1 => (
            json!({"type": "sphere", "center": [3, 1e7, 1e-3], "radius": s}),
            json!({"type": "paraboloid", "center": [-3e5, 0, 0], "a": 1, "b": 12,
                   "axis": [0, 0, 1], "range": [0, magnitude(rng, 15).abs()]}),
        ),
        2 => (
            json!({"type": "ellipsoid", "center": [0, -3, -7], "a": s, "b": 7, "c": 4}),
            json!({"type": "bezier_surface", "points": [
                [[0, 0, 2], [1, 0, -magnitude(rng, 9).abs()]],
                [[0, 1, -4], [1, 1, magnitude(rng, 19)]],
                [[0, 2, -4], [1, 2, 2e-10]]]}),
        ),
        _ => (
            json!({"type": "bezier_surface", "points": [
                [[0, 0, magnitude(rng, 25)], [1, 0, -2]],
                [[0, 1, -4], [1, 1, -7]],
                [[0, 2, -7.64], [1, 2, 4]]]}),
            json!({"type": "elliptic_cylinder", "origin": [0, 2, 0], "a": 8, "b": 6,
                   "axis": [-4, magnitude(rng, 222).abs(), 0.006],
                   "height": [0, magnitude(rng, 290).abs()]}),
        ),
    }
}

/// The hard pairs: nearly overlapping curves, rational cubics with a huge control point
/// against a plane, surfaces at extreme magnitudes.
fn hard_pairs(rng: &mut Rng, count: usize) -> Vec<(Value, Value)> {
    (0..count)
        .map(|i| match i % 3 {
            0 => {
                let dim = 2 + rng.below(2);
                let c = hard_curve(rng, dim);
                let d = nudged(&c);
                (c, d)
            }
            1 => {
                let mut c = hard_curve(rng, 3);
                if c["type"] == "bezier" {
                    let n = c["points"].as_array().unwrap().len();
                    let w: Vec<f64> = (0..n).map(|_| magnitude(rng, 30).abs()).collect();
                    c["weights"] = json!(w);
                }
                let plane = json!({"type": "plane", "normal": [0, 0, 1], "d": -magnitude(rng, 3)});
                (c, plane)
            }
            _ => surfaces(rng),
        })
        .collect()
}

/// The answer is complete and exact, or it names `limit` as what stopped it.
fn decided_or_stopped_by(case: &Value, r: &Value, limit: &str) {
    assert_ne!(r["status"], "error", "{case}: {r}");
    if r["status"] == "exact" && r["complete"] == true {
        return;
    }
    assert_eq!(r["complete"], false, "{case}: {r}");
    let reason = r["reason"].as_str().unwrap_or("");
    assert!(reason.contains(limit), "{case}: {r}");
}

#[test]
fn a_deadline_already_passed_ends_every_hard_case() {
    let mut rng = Rng::new(2021);
    let mut slowest = (0, Value::Null);
    for (a, b) in hard_pairs(&mut rng, 45) {
        let case = intersect(&a, &b, json!({"time_limit": 1e-300}));
        let r = run(&case);
        decided_or_stopped_by(&case, &r, "time limit reached");
        let micros = r["micros"].as_u64().unwrap_or(0);
        if micros > slowest.0 {
            slowest = (micros, case);
        }
    }
    // Not an assertion (no timed tests): the case that spent longest past its deadline,
    // for whoever tightens the checks further.
    eprintln!("slowest past its deadline: {} µs: {}", slowest.0, slowest.1);
}

#[test]
fn a_box_budget_of_one_ends_every_hard_case() {
    let mut rng = Rng::new(2022);
    // Every pair, surfaces too: the float stage of surface ∩ surface spends at most
    // 64 units of work per box of `max_boxes` (iso-curves, guesses, march points,
    // contact seeds), so a budget of one box ends it at once.
    for (i, (a, b)) in hard_pairs(&mut rng, 90).into_iter().enumerate() {
        let case = intersect(&a, &b, json!({"max_boxes": 1, "time_limit": 30}));
        let r = run(&case);
        assert_ne!(r["status"], "error", "{case}: {r}");
        if r["complete"] != true {
            let reason = r["reason"].as_str().unwrap_or("");
            assert!(
                // … or a polyline's collapsed piece at a common point, decided at once
                // (every parameter of the piece is a solution: `ops::front::polylines`)
                [
                    "box budget",
                    "precision cap",
                    "suspected overlap",
                    "continuum of parameters"
                ]
                .iter()
                .any(|l| reason.contains(l)),
                "{case}: {r}"
            );
        }
        if i % 3 == 2 && r["kind"] == "curves" && r["complete"] != true {
            // A surface pair whose float stage stopped on the budget says so.
            let reason = r["reason"].as_str().unwrap_or("");
            assert!(reason.contains("box budget"), "{case}: {r}");
        }
    }
}

/// A Bézier curve of degree 1–6 with one control point near `1e30` or `1e-30` (of
/// either sign, in either coordinate), polynomial or with weights `1e±30`, against a
/// copy with one number moved by one ulp: a control point coordinate (the huge one or
/// another) or a weight. The copies run together along their whole length, so the
/// subdivision of the parameter square finds common points in every box along the
/// diagonal (issue 20: 2.3 s past a 0.25 s limit, most of it clustering those boxes
/// after the deadline).
fn nudged_family(rng: &mut Rng, i: usize, dim: usize) -> (Value, Value) {
    let n = 2 + i % 6;
    let mut p = points(rng, n, dim, 2);
    let (j, k) = (rng.below(n), rng.below(dim));
    let huge = if rng.coin() { 1e30 } else { 1e-30 };
    p[j][k] = magnitude(rng, 0) * huge;
    let t = if dim == 2 { "bezier2" } else { "bezier" };
    let mut c = json!({"type": t, "points": p});
    let weighted = !i.is_multiple_of(3);
    if weighted {
        let w: Vec<f64> = (0..n).map(|_| magnitude(rng, 30).abs()).collect();
        c["weights"] = json!(w);
    }
    let mut d = c.clone();
    let up = |x: f64| f64::from_bits(x.to_bits() + 1);
    match i % 4 {
        0 => d["points"][j][k] = json!(up(p[j][k])),
        1 if weighted => {
            let m = rng.below(n);
            let w = d["weights"][m].as_f64().unwrap();
            d["weights"][m] = json!(up(w));
        }
        _ => {
            let (m, l) = (rng.below(n), rng.below(dim));
            d["points"][m][l] = json!(up(p[m][l]));
        }
    }
    (c, d)
}

#[test]
fn a_one_ulp_copy_with_a_huge_control_point_ends_decided_or_at_its_limit() {
    let mut rng = Rng::new(2023);
    for i in 0..48 {
        let (c, d) = nudged_family(&mut rng, i, 2 + (i / 6) % 2);
        let case = intersect(&c, &d, json!({"time_limit": 0.25}));
        let r = run(&case);
        assert_ne!(r["status"], "error", "{case}: {r}");
        if r["complete"] == true {
            continue;
        }
        let reason = r["reason"].as_str().unwrap_or("");
        assert!(
            [
                "time limit reached",
                "box budget",
                "suspected overlap",
                "precision cap"
            ]
            .iter()
            .any(|l| reason.contains(l)),
            "{case}: {r}"
        );
        if reason.contains("suspected overlap") {
            // Never a list of float points along the suspected arc.
            assert_eq!(r["status"], "undecided", "{case}: {r}");
            assert_eq!(r["points"].as_array().map_or(0, Vec::len), 0, "{case}: {r}");
        }
        // And with the deadline already passed, the limit is what stops it.
        let late = intersect(&c, &d, json!({"time_limit": 1e-300}));
        decided_or_stopped_by(&late, &run(&late), "time limit reached");
    }
}
