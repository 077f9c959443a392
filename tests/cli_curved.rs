//! The command line on curved objects (CASES.md): worked examples §16.3, §16.4, §16.6
//! and closed forms, end to end through `geocert solve`.

use std::io::Write;
use std::process::{Command, Stdio};

fn solve(lines: &[&str]) -> Vec<serde_json::Value> {
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

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().expect("a number")
}

#[test]
fn all_projections_onto_the_ellipse_of_16_3() {
    let r = solve(&[
        r#"{"id":"e","op":"project","point":[0.5,0.2],"onto":{"type":"ellipse2","center":[0,0],"a":3,"b":2}}"#,
    ]);
    let r = &r[0];
    assert_eq!(r["status"], "verified", "{r}");
    assert_eq!(r["complete"], true);
    let pts = r["points"].as_array().expect("points");
    assert_eq!(pts.len(), 4);
    let mut ts: Vec<f64> = pts.iter().map(|p| f(&p["params"][0][0])).collect();
    ts.sort_by(f64::total_cmp);
    for (t, e) in ts
        .iter()
        .zip([1.2901854022, 3.2031430402, 5.0463134705, 6.1683213550])
    {
        assert!((t - e).abs() < 1e-9, "{ts:?}");
    }
    let near = solve(&[
        r#"{"id":"n","op":"project","nearest":true,"point":[0.5,0.2],"onto":{"type":"ellipse2","center":[0,0],"a":3,"b":2}}"#,
    ]);
    let p = &near[0]["points"][0];
    assert!(
        (f(&p["distance"]) - 1.7532681048).abs() < 1e-9,
        "{}",
        near[0]
    );
    assert_eq!(near[0]["status"], "verified");
}

#[test]
fn line_and_sphere_of_16_4_crossing_and_tangent() {
    let r = solve(&[
        r#"{"id":"x","op":"intersect","objects":[{"type":"line","origin":[-3,0.5,0.2],"dir":[1,0,0]},{"type":"sphere","center":[0,0,0],"radius":2}]}"#,
        r#"{"id":"t","op":"intersect","objects":[{"type":"line","origin":[-3,2,0],"dir":[1,0,0]},{"type":"sphere","center":[0,0,0],"radius":2}]}"#,
        r#"{"id":"m","op":"intersect","objects":[{"type":"sphere","center":[0,0,0],"radius":2},{"type":"line","origin":[-3,2.000001,0],"dir":[1,0,0]}]}"#,
    ]);
    assert_eq!(r[0]["status"], "verified", "{}", r[0]);
    assert_eq!(r[0]["complete"], true);
    let pts = r[0]["points"].as_array().expect("points");
    assert_eq!(pts.len(), 2);
    let ts: Vec<f64> = pts.iter().map(|p| f(&p["params"][0][0])).collect();
    assert!(
        (ts[0] - 1.0738639716).abs() < 1e-9 && (ts[1] - 4.9261360284).abs() < 1e-9,
        "{ts:?}"
    );
    // (u, v) on the sphere, the second object.
    assert!((f(&pts[0]["params"][1][0]) - 2.8876114213).abs() < 1e-9);
    assert!((f(&pts[0]["params"][1][1]) - 0.1001674212).abs() < 1e-9);
    assert_eq!(r[1]["status"], "verified_singular", "{}", r[1]);
    let p = &r[1]["points"][0];
    assert_eq!(p["tangent"], true);
    assert_eq!(p["multiplicity"], 2);
    let b = &p["box"][0];
    assert!(f(&b[0]) <= 0.0 && 0.0 <= f(&b[1]), "{p}");
    assert_eq!(r[2]["kind"], "empty", "{}", r[2]);
    assert_eq!(r[2]["complete"], true);
}

#[test]
fn circle_and_ellipse_of_16_6() {
    let r = solve(&[
        r#"{"id":"4","op":"intersect","objects":[{"type":"circle2","center":[0,0],"radius":2},{"type":"ellipse2","center":[0,0],"a":3,"b":1}]}"#,
        r#"{"id":"2","op":"intersect","objects":[{"type":"circle2","center":[0,0],"radius":1},{"type":"ellipse2","center":[0,0],"a":3,"b":1}]}"#,
    ]);
    assert_eq!(r[0]["status"], "verified", "{}", r[0]);
    assert_eq!(r[0]["points"].as_array().expect("points").len(), 4);
    for p in r[0]["points"].as_array().expect("points") {
        assert!((f(&p["xyz"][0]).abs() - 1.8371173071).abs() < 1e-9);
        assert!((f(&p["xyz"][1]).abs() - 0.7905694150).abs() < 1e-9);
    }
    let tangent = r[1]["points"].as_array().expect("points");
    assert_eq!(tangent.len(), 2, "{}", r[1]);
    assert!(tangent.iter().all(|p| p["tangent"] == true));
}

#[test]
fn torus_projection_and_classification() {
    let r = solve(&[
        r#"{"id":"pp-1","op":"project","point":[1,2,3],"onto":{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,1]}}"#,
        r#"{"id":"in","op":"classify","point":[3,0,0],"shell":{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,1]}}"#,
        r#"{"id":"on","op":"classify","point":[4,0,0],"shell":{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,1]}}"#,
        r#"{"id":"out","op":"classify","point":[0,0,0],"shell":{"type":"sphere","center":[1,1,1],"radius":1}}"#,
    ]);
    assert_eq!(r[0]["status"], "verified", "{}", r[0]);
    assert_eq!(r[0]["points"].as_array().expect("points").len(), 4);
    let near = ((5f64.sqrt() - 3.0).powi(2) + 9.0).sqrt() - 1.0;
    let mut d: Vec<f64> = r[0]["points"]
        .as_array()
        .expect("points")
        .iter()
        .map(|p| f(&p["distance"]))
        .collect();
    d.sort_by(f64::total_cmp);
    assert!((d[0] - near).abs() < 1e-12, "{d:?}");
    assert_eq!(r[1]["kind"], "inside");
    assert_eq!(r[1]["status"], "exact");
    assert_eq!(r[2]["kind"], "on");
    assert_eq!(r[3]["kind"], "outside");
}

#[test]
fn curved_bad_input_names_the_field() {
    let r = solve(&[
        r#"{"id":1,"op":"intersect","objects":[{"type":"line","origin":[0,0,0],"dir":[1,0,0]},{"type":"sphere","center":[0,0,0],"radius":-1}]}"#,
        r#"{"id":2,"op":"project","point":[0,0,0],"onto":{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,0]}}"#,
        r#"{"id":3,"op":"project","point":[0,"1/3"],"onto":{"type":"circle2","center":[0,0],"radius":1}}"#,
        r#"{"id":4,"op":"intersect","objects":[{"type":"nurbs_curve","degree":2,"knots":[0,0,1,1],"points":[[0,0,0],[1,0,0],[1,1,0]]},{"type":"sphere","center":[0,0,0],"radius":1}]}"#,
    ]);
    assert_eq!(r[0]["status"], "error");
    assert!(
        r[0]["error"]["field"]
            .as_str()
            .expect("field")
            .starts_with("objects[1].radius"),
        "{}",
        r[0]
    );
    assert_eq!(r[1]["status"], "error");
    assert!(
        r[1]["error"]["field"]
            .as_str()
            .expect("field")
            .starts_with("onto.axis"),
        "{}",
        r[1]
    );
    assert_eq!(r[2]["error"]["field"], "point[1]", "{}", r[2]);
    assert_eq!(r[3]["status"], "error");
    assert!(
        r[3]["error"]["field"]
            .as_str()
            .expect("field")
            .starts_with("objects[0].knots"),
        "{}",
        r[3]
    );
}
