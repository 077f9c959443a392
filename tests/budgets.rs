//! Every case ends within the budget the user controls (issue 20): degenerate patches are
//! refused naming the field, subnormal weights too, exact strings beyond the size caps are
//! an `invalid_value` error naming the coordinate, and cases that used to run for minutes
//! (a helix of pitch 0 lying on a sphere, a line lying in a flat degree-30 patch, a
//! nearly degenerate patch) end `undecided` with the limit that stopped them as the
//! reason. The assertions are on the status and the reason, never on elapsed time: a
//! case that hangs fails the suite by its global timeout. Each case carries a small
//! `time_limit` or `max_boxes`.

use geocert::curve::bezier::Bezier;
use geocert::io::{read_cases, solve_case};
use geocert::num::parse::{MAX_EXACT_BITS, MAX_EXACT_DIGITS};
use geocert::robust::rng::Rng;
use geocert::surface::bezier::BezierSurface;
use serde_json::{json, Value};

fn run(case: &Value) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&solve_case(read).to_json_line()).unwrap()
}

fn error_of(r: &Value) -> (&str, &str) {
    assert_eq!(r["status"], "error", "{r}");
    (
        r["error"]["kind"].as_str().unwrap(),
        r["error"]["field"].as_str().unwrap(),
    )
}

fn reason(r: &Value) -> &str {
    r["reason"].as_str().unwrap_or("")
}

fn line() -> Value {
    json!({"type": "line", "origin": [0.25, -1, 0.125], "dir": [0, 1, 0]})
}

fn point(rng: &mut Rng) -> [f64; 3] {
    [rng.generic(), rng.generic(), rng.generic()]
}

/// A net of `rows × cols` points from `at(row, col)`.
fn net(
    rows: usize,
    cols: usize,
    mut at: impl FnMut(usize, usize) -> [f64; 3],
) -> Vec<Vec<[f64; 3]>> {
    (0..rows)
        .map(|r| (0..cols).map(|c| at(r, c)).collect())
        .collect()
}

fn bezier_surface(points: &[Vec<[f64; 3]>], weights: Option<&[Vec<f64>]>) -> Value {
    let mut s = json!({"type": "bezier_surface", "points": points});
    if let Some(w) = weights {
        s["weights"] = json!(w);
    }
    s
}

fn clamped_knots(degree: usize, n: usize) -> Vec<f64> {
    let inner = n - degree - 1;
    let mut k = vec![0.0; degree + 1];
    k.extend((1..=inner).map(|i| i as f64 / (inner + 1) as f64));
    k.extend(vec![1.0; degree + 1]);
    k
}

fn nurbs_surface(points: &[Vec<[f64; 3]>], du: usize, dv: usize) -> Value {
    let (rows, cols) = (points.len(), points[0].len());
    json!({"type": "nurbs_surface", "degree_u": du, "degree_v": dv,
           "knots_u": clamped_knots(du, cols), "knots_v": clamped_knots(dv, rows),
           "points": points})
}

fn intersect(a: Value, b: Value, options: Value) -> Value {
    json!({"id": "b", "op": "intersect", "objects": [a, b], "options": options})
}

/// The kinds of degenerate nets, each a function of the net's size.
fn degenerate_nets(rng: &mut Rng, rows: usize, cols: usize) -> Vec<Vec<Vec<[f64; 3]>>> {
    let p = point(rng);
    // integers times a power of two: p + k·d is exact in doubles, so the points are
    // exactly collinear
    let scale = (rng.int(-20, 20) as f64).exp2();
    let mut int = || rng.int(-1000, 1000) as f64 * scale;
    let (q, d) = ([int(), int(), int()], [int(), int(), int() + 0.5 * scale]);
    let row: Vec<[f64; 3]> = (0..cols).map(|_| point(rng)).collect();
    let column: Vec<[f64; 3]> = (0..rows).map(|_| point(rng)).collect();
    let mut k = || rng.int(-8, 8) as f64;
    let collinear = net(rows, cols, |_, _| {
        let s = k();
        std::array::from_fn(|i| q[i] + s * d[i])
    });
    vec![
        net(rows, cols, |_, _| p),
        collinear,
        net(rows, cols, |_, c| row[c]),
        net(rows, cols, |r, _| column[r]),
    ]
}

#[test]
fn degenerate_patches_of_every_degree_are_refused_naming_the_net() {
    let mut rng = Rng::new(20);
    let mut count = 0;
    for rows in 2..=6 {
        for cols in 2..=6 {
            for points in degenerate_nets(&mut rng, rows, cols) {
                for (surface, at) in [
                    (bezier_surface(&points, None), 1),
                    (nurbs_surface(&points, cols.min(3) - 1, rows.min(3) - 1), 0),
                ] {
                    let case = if at == 1 {
                        intersect(line(), surface, json!({"max_boxes": 10}))
                    } else {
                        intersect(surface, line(), json!({"max_boxes": 10}))
                    };
                    let r = run(&case);
                    assert_eq!(r["status"], "error", "{case}");
                    assert_eq!(
                        error_of(&r),
                        (
                            "degenerate_surface",
                            format!("objects[{at}].points").as_str()
                        ),
                        "{case}"
                    );
                    count += 1;
                }
            }
        }
    }
    assert_eq!(count, 25 * 4 * 2);
}

#[test]
fn proportional_weights_keep_a_patch_degenerate_and_others_do_not() {
    let mut rng = Rng::new(21);
    for _ in 0..50 {
        // three or more columns: two would put every point on one line
        let (rows, cols) = (2 + rng.below(3), 3 + rng.below(3));
        let row: Vec<[f64; 3]> = (0..cols).map(|_| point(&mut rng)).collect();
        let points = net(rows, cols, |_, c| row[c]);
        let base: Vec<f64> = (0..cols).map(|_| 1.0 + rng.below(4) as f64).collect();
        let scale: Vec<f64> = (0..rows).map(|_| 1.0 + rng.below(4) as f64).collect();
        let weights: Vec<Vec<f64>> = scale
            .iter()
            .map(|s| base.iter().map(|b| b * s).collect())
            .collect();
        let r = run(&intersect(
            line(),
            bezier_surface(&points, Some(&weights)),
            json!({}),
        ));
        assert_eq!(error_of(&r), ("degenerate_surface", "objects[1].points"));
        // one weight off the proportion: a genuine rational surface (no error)
        let mut w = weights.clone();
        w[rows - 1][cols - 1] += 0.5;
        assert!(BezierSurface::new(&points, Some(&w)).is_ok());
    }
}

#[test]
fn a_pole_or_a_one_ulp_change_is_a_surface_not_an_error() {
    let mut rng = Rng::new(22);
    for _ in 0..40 {
        let (rows, cols) = (2 + rng.below(3), 2 + rng.below(3));
        let row: Vec<[f64; 3]> = (0..cols).map(|_| point(&mut rng)).collect();
        let pole = point(&mut rng);
        let with_pole = net(rows, cols, |r, c| if r == 0 { pole } else { row[c] });
        let mut nudged = net(rows, cols, |_, c| row[c]);
        nudged[rows - 1][0][2] = f64::from_bits(nudged[rows - 1][0][2].to_bits() + 1);
        for points in [with_pole, nudged] {
            assert!(BezierSurface::new(&points, None).is_ok(), "{points:?}");
        }
    }
}

#[test]
fn subnormal_weights_are_refused_naming_the_weight() {
    let mut rng = Rng::new(23);
    for _ in 0..60 {
        let tiny = f64::from_bits(1 + rng.below(1 << 40) as u64); // subnormal
        let n = 2 + rng.below(4);
        let i = rng.below(n);
        let mut w = vec![1.0; n];
        w[i] = tiny;
        let pts: Vec<[f64; 3]> = (0..n).map(|k| [k as f64, (k * k) as f64, 0.5]).collect();
        let curve = json!({"type": "bezier", "points": pts, "weights": w});
        let r = run(&intersect(curve, line(), json!({})));
        let field = format!("objects[0].weights[{i}]");
        assert_eq!(error_of(&r), ("degenerate_weight", field.as_str()));

        let points = net(n, 3, |r, c| [c as f64, r as f64, ((r + c) % 2) as f64]);
        let mut ws = vec![vec![1.0; 3]; n];
        let j = rng.below(3);
        ws[i][j] = tiny;
        let r = run(&intersect(
            line(),
            bezier_surface(&points, Some(&ws)),
            json!({}),
        ));
        let field = format!("objects[1].weights[{i}][{j}]");
        assert_eq!(error_of(&r), ("degenerate_weight", field.as_str()));
    }
    // the smallest normal weight is accepted
    let w = vec![1.0, f64::MIN_POSITIVE, 1.0];
    let pts = vec![[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]];
    assert!(Bezier::<3>::new(pts, Some(w), None).is_ok());
}

fn helix_on_sphere(r: f64, options: Value) -> Value {
    let helix = json!({"type": "helix", "center": [0, 0, 0], "radius": r, "pitch": 0,
                       "axis": [0, 0, 1], "range": [0, std::f64::consts::TAU]});
    let sphere = json!({"type": "sphere", "center": [0, 0, 0], "radius": r});
    intersect(helix, sphere, options)
}

#[test]
fn a_flat_helix_lying_on_spheres_ends_at_the_limit_that_stopped_it() {
    for r in [1e-3, 0.5, 1.0, 3.0, 100.0, 1e4] {
        let t = run(&helix_on_sphere(r, json!({"time_limit": 0.2})));
        assert_eq!(t["status"], "undecided", "{t}");
        assert_eq!(t["complete"], false);
        assert!(reason(&t).contains("time limit reached"), "{t}");
        let b = run(&helix_on_sphere(r, json!({"max_boxes": 60})));
        assert_eq!(b["status"], "undecided", "{b}");
        assert_eq!(b["complete"], false);
        assert!(reason(&b).contains("box budget spent"), "{b}");
    }
}

#[test]
fn a_line_in_a_flat_degree_30_patch_ends_at_the_time_limit() {
    let n = 31;
    let points = net(n, n, |r, c| [c as f64 / 30.0, r as f64 / 30.0, 0.0]);
    let line = json!({"type": "line", "origin": [0, 0.5, 0], "dir": [1, 0, 0]});
    let r = run(&intersect(
        line,
        bezier_surface(&points, None),
        json!({"time_limit": 0.2}),
    ));
    assert_eq!(r["status"], "undecided", "{r}");
    assert!(reason(&r).contains("time limit reached"), "{r}");
}

#[test]
fn nearly_degenerate_patches_end_at_the_limit_that_stopped_them() {
    // rows equal but one coordinate of the last row 1e-300 off: not refused (exactly a
    // surface), and its walk would take 10⁸ nodes; the seeds fall back to a grid.
    let mut rng = Rng::new(24);
    for _ in 0..3 {
        let row: Vec<[f64; 3]> = (0..4).map(|c| [c as f64, rng.unit(), 0.0]).collect();
        let mut points = net(4, 4, |_, c| row[c]);
        points[3][1][2] = 1e-300;
        let r = run(&intersect(
            line(),
            bezier_surface(&points, None),
            json!({"time_limit": 0.2}),
        ));
        assert_ne!(r["status"], "error", "{r}");
        if r["complete"] != true {
            assert!(reason(&r).contains("time limit reached"), "{r}");
        }
    }
}

fn digits(rng: &mut Rng, n: usize) -> String {
    (0..n)
        .map(|_| char::from(b'0' + rng.below(10) as u8))
        .collect()
}

#[test]
fn exact_strings_beyond_the_caps_are_errors_naming_the_coordinate() {
    let mut rng = Rng::new(25);
    let sphere = json!({"type": "sphere", "center": [0, 0, 0], "radius": 2});
    for n in [10, 500, 2000, MAX_EXACT_DIGITS - 2] {
        let s = format!("0.{}", digits(&mut rng, n));
        let line = json!({"type": "line", "origin": [0, &s, 0], "dir": [1, 0, "1/3"]});
        let r = run(&intersect(line, sphere.clone(), json!({})));
        assert_eq!(r["status"], "exact", "{n} digits");
        assert_eq!(r["points"].as_array().unwrap().len(), 2);
    }
    for n in [MAX_EXACT_DIGITS + 1, 10_000, 30_000, 100_000] {
        let s = format!("0.{}", digits(&mut rng, n));
        let i = rng.below(3);
        let mut origin = json!([0, 0, 0]);
        origin[i] = json!(s);
        let line = json!({"type": "line", "origin": origin, "dir": [1, 0, 0]});
        let r = run(&intersect(line, sphere.clone(), json!({})));
        let field = format!("objects[0].origin[{i}]");
        assert_eq!(error_of(&r), ("invalid_value", field.as_str()));
        assert!(r["error"]["message"].as_str().unwrap().len() < 300);
    }
    // few digits, too many bits
    let e = 1 + (MAX_EXACT_BITS as f64 / 10f64.log2()) as usize;
    let plane = json!({"type": "plane", "normal": [0, 0, 1], "d": format!("1e-{e}")});
    let r = run(&intersect(plane, sphere, json!({})));
    assert_eq!(error_of(&r), ("invalid_value", "objects[0].d"));
}
