//! Surface ∩ surface through `geocert solve` (CASES.md `kind: curves`): closed-form
//! circles, an implicit plane cut to the other surface, tangent spheres as an isolated
//! point, proven empty answers, Steinmetz singular points, `options.chord_tolerance`.

use std::io::Write;
use std::process::{Command, Stdio};

use serde_json::Value;

fn solve(lines: &[&str]) -> Vec<Value> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args(["solve", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("geocert runs");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(lines.join("\n").as_bytes())
        .expect("write");
    let out = child.wait_with_output().expect("output");
    String::from_utf8(out.stdout)
        .expect("utf-8")
        .lines()
        .map(|l| serde_json::from_str(l).expect("JSON line"))
        .collect()
}

fn f(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

fn xyz(p: &Value) -> [f64; 3] {
    let a = p["xyz"].as_array().expect("xyz");
    [f(&a[0]), f(&a[1]), f(&a[2])]
}

/// Unit sphere ∩ the sphere of radius 1 at (1, 0, 0): the circle x = ½, ρ = √3/2.
#[test]
fn two_spheres_give_one_verified_closed_curve_with_both_parameters() {
    let r = solve(&[
        r#"{"id":"s","op":"intersect","objects":[{"type":"sphere","center":[0,0,0],"radius":1},{"type":"sphere","center":[1,0,0],"radius":1}]}"#,
    ]);
    let r = &r[0];
    assert_eq!(r["status"], "verified", "{r}");
    assert_eq!(r["kind"], "curves");
    assert_eq!(r["complete"], true);
    let curves = r["curves"].as_array().expect("curves");
    assert_eq!(curves.len(), 1);
    let c = &curves[0];
    assert_eq!(c["closed"], true);
    assert_eq!(c["status"], "verified");
    assert_eq!(c["ends"][0]["kind"], "closed");
    let bound = f(&c["distance_bound"]);
    assert!(bound > 0.0 && bound < 1e-6, "{bound}");
    let pts = c["points"].as_array().expect("points");
    assert!(pts.len() > 10);
    assert_eq!(
        pts.first(),
        pts.last(),
        "a closed polyline repeats its first point"
    );
    for p in pts {
        let [x, y, z] = xyz(p);
        // within the proven bound (plus rounding of this check) of the true circle
        let rho = (y * y + z * z).sqrt();
        let d = ((x - 0.5).powi(2) + (rho - 0.75f64.sqrt()).powi(2)).sqrt();
        assert!(d <= bound + 1e-15, "{d} > {bound}");
        let params = p["params"].as_array().expect("params");
        assert_eq!(params.len(), 2);
        assert_eq!(params[0].as_array().expect("u, v").len(), 2);
        assert_eq!(params[1].as_array().expect("a, b").len(), 2);
    }
    assert_eq!(r["singular_points"].as_array().expect("list").len(), 0);
}

/// An implicit plane (no parameters) cuts a torus in two circles.
#[test]
fn an_implicit_plane_cuts_a_torus_in_two_circles() {
    let r = solve(&[
        r#"{"id":"t","op":"intersect","objects":[{"type":"plane","normal":[0,0,1],"d":-0.5},{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,1]}]}"#,
    ]);
    let r = &r[0];
    assert_eq!(r["status"], "verified", "{r}");
    assert_eq!(r["complete"], true);
    let curves = r["curves"].as_array().expect("curves");
    assert_eq!(curves.len(), 2);
    let mut radii = Vec::new();
    for c in curves {
        assert_eq!(c["closed"], true);
        let bound = f(&c["distance_bound"]);
        let p = &c["points"][0];
        assert_eq!(
            p["params"][0].as_array().expect("none").len(),
            0,
            "implicit plane"
        );
        let [x, y, z] = xyz(p);
        assert!((z - 0.5).abs() <= bound + 1e-15);
        radii.push((x * x + y * y).sqrt());
    }
    radii.sort_by(f64::total_cmp);
    let h = 0.75f64.sqrt();
    assert!((radii[0] - (3.0 - h)).abs() < 1e-6 && (radii[1] - (3.0 + h)).abs() < 1e-6);
}

#[test]
fn tangent_spheres_are_one_point_and_apart_spheres_are_empty() {
    let r = solve(&[
        r#"{"id":"t","op":"intersect","objects":[{"type":"sphere","center":[0,0,0],"radius":1},{"type":"sphere","center":[2,0,0],"radius":1}]}"#,
        r#"{"id":"e","op":"intersect","objects":[{"type":"sphere","center":[0,0,0],"radius":1},{"type":"sphere","center":[2,0,0],"radius":0.999999999}]}"#,
    ]);
    // The exact touching point of the radical-plane section (ops::front::sections).
    assert_eq!(r[0]["status"], "exact", "{}", r[0]);
    assert_eq!(r[0]["kind"], "points");
    assert_eq!(r[0]["complete"], true);
    let p = &r[0]["points"][0];
    assert_eq!(p["tangent"], true);
    let b = p["box"].as_array().expect("box");
    for (k, t) in [1.0, 0.0, 0.0].into_iter().enumerate() {
        assert!(f(&b[k][0]) <= t && t <= f(&b[k][1]), "{b:?}");
    }
    // Decided exactly through the radical plane (ops::section).
    assert_eq!(r[1]["status"], "exact", "{}", r[1]);
    assert_eq!(r[1]["kind"], "empty");
    assert_eq!(r[1]["complete"], true);
}

/// Equal perpendicular cylinders cross at (0, ±1, 0): singular points with certified
/// boxes; the curves end there.
#[test]
fn steinmetz_curves_end_at_singular_points_with_boxes() {
    let r = solve(&[
        r#"{"id":"st","op":"intersect","objects":[{"type":"cylinder","origin":[0,0,0],"radius":1,"axis":[0,0,1],"height":[-2,2]},{"type":"cylinder","origin":[0,0,0],"radius":1,"axis":[1,0,0],"height":[-2,2]}]}"#,
    ]);
    let r = &r[0];
    assert_eq!(r["kind"], "curves", "{r}");
    let sps = r["singular_points"].as_array().expect("singular points");
    assert_eq!(sps.len(), 2);
    for sp in sps {
        assert_eq!(sp["status"], "verified_singular");
        let b = sp["box"].as_array().expect("box");
        let y = if f(&b[1][0]) > 0.0 { 1.0 } else { -1.0 };
        for (k, t) in [0.0, y, 0.0].into_iter().enumerate() {
            assert!(f(&b[k][0]) <= t && t <= f(&b[k][1]), "{b:?}");
        }
    }
    for c in r["curves"].as_array().expect("curves") {
        assert_eq!(c["closed"], false);
        for e in c["ends"].as_array().expect("ends") {
            assert_eq!(e["kind"], "singular");
            assert!(e["index"].as_u64().expect("index") < 2);
        }
    }
    // not every arc is proven: the answer says so
    if r["status"] == "undecided" {
        assert!(r["reason"].as_str().is_some());
        assert_eq!(r["complete"], false);
    }
}

#[test]
fn a_smaller_chord_tolerance_gives_more_points_and_a_bad_one_is_an_error() {
    let case = |tol: &str| {
        format!(
            r#"{{"id":"c","op":"intersect","objects":[{{"type":"sphere","center":[0,0,0],"radius":1}},{{"type":"sphere","center":[1,0,0],"radius":1}}],"options":{{"chord_tolerance":{tol}}}}}"#
        )
    };
    let r = solve(&[&case("1e-2"), &case("1e-6"), &case("-1")]);
    let n = |r: &Value| r["curves"][0]["points"].as_array().expect("points").len();
    assert!(n(&r[1]) > 4 * n(&r[0]), "{} vs {}", n(&r[1]), n(&r[0]));
    assert_eq!(r[2]["status"], "error");
    assert_eq!(r[2]["error"]["field"], "options.chord_tolerance");
}
