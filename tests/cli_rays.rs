//! Rays in the case format (docs/FORMAT.md "Linear objects"): a `line` whose `range`
//! has a `null` end, end to end through `geocert solve` — the answers of kind `ray`,
//! `segment`, `points` and `empty` with exact values known by construction, the
//! `[null, null]` spelling of the whole line, and one typed error per bad range naming
//! its field.

use serde_json::{json, Value};

mod cli_support;

use cli_support::f64s;

fn solve_one(case: Value) -> Value {
    let (mut r, _) = cli_support::solve_text(&format!("{case}\n"));
    assert_eq!(r.len(), 1, "{r:?}");
    r.remove(0)
}

fn line(origin: [i32; 3], dir: [i32; 3], range: Value) -> Value {
    json!({"type": "line", "origin": origin, "dir": dir, "range": range})
}

fn intersect(a: Value, b: Value) -> Value {
    solve_one(json!({"id": 1, "op": "intersect", "objects": [a, b]}))
}

/// Two rays along the x-axis going the same way: the later one, exactly; with
/// `options.exact`, the direction as strings.
#[test]
fn same_way_rays_answer_the_later_ray() {
    let a = line([0, 0, 0], [2, 0, 0], json!([0, null]));
    let b = line([3, 0, 0], [1, 0, 0], json!([1, null]));
    let r = intersect(a.clone(), b.clone());
    assert_eq!(r["status"], "exact", "{r}");
    assert_eq!(r["kind"], "ray", "{r}");
    assert_eq!(r["complete"], true);
    let ray = &r["ray"];
    // b starts at x = 4 (t₂ = 1), where t₁ = 2.
    assert_eq!(f64s(&ray["start"]["xyz"]), vec![4.0, 0.0, 0.0], "{r}");
    assert_eq!(f64s(&ray["start"]["params"][0]), vec![2.0]);
    assert_eq!(f64s(&ray["start"]["params"][1]), vec![1.0]);
    assert_eq!(f64s(&ray["dir"]), vec![2.0, 0.0, 0.0]);
    assert_eq!(ray["increasing"], json!([true, true]));
    assert!(ray.get("exact").is_none(), "{r}");
    let r = solve_one(json!({"id": 2, "op": "intersect", "objects": [a, b],
                             "options": {"exact": true}}));
    assert_eq!(r["ray"]["exact"]["dir"], json!(["2", "0", "0"]), "{r}");
    assert_eq!(
        r["ray"]["start"]["exact"]["xyz"],
        json!(["4", "0", "0"]),
        "{r}"
    );
}

/// A ray `t ≤ 1` against the x-axis reversed: the ray from x = 1 towards −x, the second
/// object's parameter growing along it.
#[test]
fn a_backward_ray_on_a_reversed_line() {
    let a = line([0, 0, 0], [1, 0, 0], json!([null, 1]));
    let b = line([5, 0, 0], [-1, 0, 0], json!(null));
    let r = intersect(a, b);
    assert_eq!(r["kind"], "ray", "{r}");
    assert_eq!(f64s(&r["ray"]["start"]["xyz"]), vec![1.0, 0.0, 0.0]);
    assert_eq!(f64s(&r["ray"]["start"]["params"][1]), vec![4.0]);
    assert_eq!(f64s(&r["ray"]["dir"]), vec![-1.0, 0.0, 0.0]);
    assert_eq!(r["ray"]["increasing"], json!([false, true]));
}

/// Opposite rays: a segment, or one point where they only touch, or nothing.
#[test]
fn opposite_rays_meet_in_a_segment_a_point_or_not() {
    let up = line([0, 0, 0], [0, 1, 0], json!([0, null]));
    let down = |y: i32| line([0, y, 0], [0, -1, 0], json!([0, null]));
    let r = intersect(up.clone(), down(3));
    assert_eq!(r["kind"], "segment", "{r}");
    assert_eq!(f64s(&r["segment"]["a"]["xyz"]), vec![0.0, 0.0, 0.0]);
    assert_eq!(f64s(&r["segment"]["b"]["xyz"]), vec![0.0, 3.0, 0.0]);
    let r = intersect(up.clone(), down(0));
    assert_eq!(r["kind"], "points", "{r}");
    assert_eq!(f64s(&r["points"][0]["xyz"]), vec![0.0, 0.0, 0.0]);
    let r = intersect(up, down(-1));
    assert_eq!(r["kind"], "empty", "{r}");
    assert_eq!(r["reason"], "collinear_disjoint");
}

/// A ray crossing a line behind its start: `extensions_meet`; ahead: the point. A ray
/// against a plane: `outside_domain` behind, and a ray lying in the plane is kind `ray`
/// with `null` for the plane's direction flag.
#[test]
fn rays_crossing_lines_and_planes() {
    let ray = line([0, 0, 0], [1, 1, 0], json!([1, null]));
    let cross = |x: i32| line([x, 0, 0], [0, 1, 0], json!(null));
    let r = intersect(ray.clone(), cross(2));
    assert_eq!(r["kind"], "points", "{r}");
    assert_eq!(f64s(&r["points"][0]["xyz"]), vec![2.0, 2.0, 0.0]);
    let r = intersect(ray.clone(), cross(1));
    assert_eq!(r["kind"], "points", "{r}: on the start");
    let r = intersect(ray.clone(), cross(0));
    assert_eq!(r["kind"], "empty", "{r}");
    assert_eq!(r["reason"], "extensions_meet");
    let plane = |d: i32| json!({"type": "plane", "normal": [1, 0, 0], "d": d});
    let r = intersect(ray.clone(), plane(-3));
    assert_eq!(f64s(&r["points"][0]["xyz"]), vec![3.0, 3.0, 0.0], "{r}");
    let r = intersect(ray.clone(), plane(0));
    assert_eq!(r["kind"], "empty", "{r}");
    assert_eq!(r["reason"], "outside_domain");
    let flat = json!({"type": "plane", "normal": [0, 0, 1], "d": 0});
    let r = intersect(flat, ray);
    assert_eq!(r["kind"], "ray", "{r}");
    assert_eq!(f64s(&r["ray"]["start"]["xyz"]), vec![1.0, 1.0, 0.0]);
    assert_eq!(f64s(&r["ray"]["start"]["params"][1]), vec![1.0]);
    assert_eq!(r["ray"]["increasing"], json!([null, true]));
}

/// `[null, null]` is the whole line: two such lines on one carrier coincide, as
/// without `range`; the alias `domain` takes the same spelling.
#[test]
fn both_ends_null_is_the_whole_line() {
    let a = line([0, 0, 0], [1, 2, 3], json!([null, null]));
    let b = json!({"type": "line", "origin": [1, 2, 3], "dir": [2, 4, 6], "domain": [null, null]});
    let r = intersect(a, b);
    assert_eq!(r["kind"], "coincident", "{r}");
}

/// Bad ranges are typed errors naming the field: inverted, an end that is not a
/// number, a wrong length or type, a ray in the plane (not implemented).
#[test]
fn bad_ranges_are_typed_errors() {
    let other = line([0, 1, 0], [1, 0, 0], json!(null));
    let cases = [
        (json!([2, 1]), "empty_domain", "objects[0].range"),
        (json!([2, "inf"]), "invalid_number", "objects[0].range[1]"),
        (json!(["x", null]), "invalid_number", "objects[0].range[0]"),
        (json!([0, null, 1]), "format", "objects[0].range"),
        (json!([true, null]), "format", "objects[0].range"),
    ];
    for (range, kind, field) in cases {
        let r = intersect(line([0, 0, 0], [1, 0, 0], range.clone()), other.clone());
        assert_eq!(r["status"], "error", "{range}: {r}");
        assert_eq!(r["error"]["kind"], kind, "{range}: {r}");
        let named = r["error"]["field"].as_str().unwrap();
        assert!(named.starts_with(field), "{range}: {r}");
    }
}

/// Rays in the plane are read and honoured: a ray along the x-axis from 0 meets the
/// segment from (−1, −1) to (1, 1) at its start, misses one behind its start, two
/// opposite collinear rays (x ≤ 2 and x ≥ 1) overlap in a segment, and two rays the
/// same way in the later ray.
#[test]
fn rays_in_the_plane_are_answered_exactly() {
    let ray2 = |o: [i32; 2], d: [i32; 2], r: Value| json!({"type": "line2", "origin": o, "dir": d, "range": r});
    let seg2 = |a: [i32; 2], b: [i32; 2]| json!({"type": "segment2", "a": a, "b": b});
    let r = intersect(
        ray2([0, 0], [1, 0], json!([0, null])),
        seg2([-1, -1], [1, 1]),
    );
    assert_eq!(
        (r["status"].as_str(), r["kind"].as_str()),
        (Some("exact"), Some("points")),
        "{r}"
    );
    assert_eq!(r["points"][0]["xyz"], json!([0.0, 0.0]), "{r}");
    let r = intersect(
        ray2([0, 0], [1, 0], json!([0, null])),
        seg2([-2, -1], [-1, 1]),
    );
    assert_eq!(
        (r["status"].as_str(), r["kind"].as_str()),
        (Some("exact"), Some("empty")),
        "{r}"
    );
    let r = intersect(
        ray2([0, 0], [1, 0], json!([null, 2])),
        ray2([3, 0], [-1, 0], json!([null, 2])),
    );
    assert_eq!(
        (r["status"].as_str(), r["kind"].as_str()),
        (Some("exact"), Some("segment")),
        "{r}"
    );
    let r = intersect(
        ray2([0, 0], [1, 0], json!([0, null])),
        ray2([3, 0], [2, 0], json!([0, null])),
    );
    assert_eq!(
        (r["status"].as_str(), r["kind"].as_str()),
        (Some("exact"), Some("ray")),
        "{r}"
    );
    assert_eq!(r["ray"]["start"]["xyz"], json!([3.0, 0.0]), "{r}");
    assert_eq!(r["ray"]["dir"], json!([1.0, 0.0]), "{r}");
}

/// Rays against circles (in the plane) and spheres, exactly: a ray against a bounded
/// shape is decided as its piece up to that shape's certified box (`ops::front::rays`),
/// by the exact algebraic pairs. The carrier `c + (s₀ + m·t)·e` meets the circle or
/// sphere of centre `c` and radius `|e|` (`e = (3, 4)`, radius 5; `e = (2, 3, 6)`,
/// radius 7) exactly at `c ± e`, at `t = (±1 − s₀)/m`; rays start on both hits, between
/// and beyond them, either way. Asserted for every case: `exact` and complete, exactly
/// the true points on the ray, each correctly rounded and inside its box, with its
/// ray parameter. (A ray starting on the circle was a domain end the numeric path
/// could not decide: 408 of the 672 plane cases were `undecided` before.)
#[test]
fn rays_against_circles_and_spheres_are_exact() {
    let mut text = String::new();
    let mut truths: Vec<Vec<(Vec<f64>, f64)>> = Vec::new();
    // Pythagorean directions, and hits on the circle's seam (angle 0), the sphere's
    // seam (u = 0) and its poles.
    let frames: [(&[f64], &[f64], f64); 9] = [
        (&[1.0, -1.0], &[5.0, 0.0], 5.0),
        (&[1.0, -1.0, 2.0], &[7.0, 0.0, 0.0], 7.0),
        (&[1.0, -1.0, 2.0], &[0.0, 0.0, 7.0], 7.0),
        (&[0.0, 0.0], &[3.0, 4.0], 5.0),
        (&[-2.0, 1.0], &[3.0, 4.0], 5.0),
        (&[3.0, -2.5], &[3.0, 4.0], 5.0),
        (&[0.0, 0.0, 0.0], &[2.0, 3.0, 6.0], 7.0),
        (&[-2.0, 1.0, 0.5], &[2.0, 3.0, 6.0], 7.0),
        (&[3.0, -2.5, 1.0], &[2.0, 3.0, 6.0], 7.0),
    ];
    for (c, e, radius) in frames {
        let at = |s: f64| -> Vec<f64> { c.iter().zip(e).map(|(c, e)| c + s * e).collect() };
        let other = if c.len() == 2 {
            json!({"type": "circle2", "center": c, "radius": radius})
        } else {
            json!({"type": "sphere", "center": c, "radius": radius})
        };
        for s0 in [-3.0, -1.0, -0.5, 0.0, 0.5, 1.0, 3.0] {
            for m in [1.0, -1.0, 2.0, -2.0] {
                let hits = [(1.0 - s0) / m, (-1.0 - s0) / m];
                for a in [0.0, 0.5, hits[0], hits[1]] {
                    for ends in [[Some(a), None], [None, Some(a)]] {
                        let inside = |t: f64| {
                            ends[0].is_none_or(|lo| t >= lo) && ends[1].is_none_or(|hi| t <= hi)
                        };
                        let mut points: Vec<(Vec<f64>, f64)> = hits
                            .iter()
                            .zip([1.0, -1.0])
                            .filter(|(t, _)| inside(**t))
                            .map(|(t, k)| (at(k), *t))
                            .collect();
                        points.sort_by(|p, q| p.1.total_cmp(&q.1));
                        let dir: Vec<f64> = e.iter().map(|e| m * e).collect();
                        let ray = json!({"type": if c.len() == 2 { "line2" } else { "line" },
                            "origin": at(s0), "dir": dir, "range": ends});
                        let case = json!({"id": truths.len(), "op": "intersect",
                            "objects": [ray, other]});
                        text.push_str(&format!("{case}\n"));
                        truths.push(points);
                    }
                }
            }
        }
    }
    let (results, _) = cli_support::solve_text(&text);
    assert_eq!(results.len(), truths.len());
    for (r, truth) in results.iter().zip(&truths) {
        assert_eq!(
            (&r["status"], &r["complete"]),
            (&json!("exact"), &json!(true)),
            "{r}"
        );
        let points = r["points"].as_array().cloned().unwrap_or_default();
        assert_eq!(points.len(), truth.len(), "{r}");
        let mut got: Vec<&Value> = points.iter().collect();
        got.sort_by(|p, q| {
            p["params"][0][0]
                .as_f64()
                .unwrap()
                .total_cmp(&q["params"][0][0].as_f64().unwrap())
        });
        for (p, (x, t)) in got.iter().zip(truth) {
            assert_eq!(&f64s(&p["xyz"]), x, "{r}");
            assert_eq!(f64s(&p["params"][0]), vec![*t], "{r}");
            for (i, xi) in x.iter().enumerate() {
                let b = f64s(&p["box"][i]);
                assert!(b[0] <= *xi && *xi <= b[1], "{r}");
            }
        }
    }
}
