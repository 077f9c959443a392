//! The command line on curved objects (CASES.md): worked examples §16.3, §16.4, §16.6
//! and closed forms, end to end through `geocert solve`.

mod cli_support;

/// `geocert solve` on the lines, with one and three threads (the same bytes).
fn solve(lines: &[&str]) -> Vec<serde_json::Value> {
    cli_support::solve_text(&lines.join("\n")).0
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().expect("a number")
}

/// A truth at 1024 bits (far beyond any box's resolution).
fn mp(x: f64) -> rug::Float {
    rug::Float::with_val(1024, x)
}

/// `lo ≤ x ≤ hi` for a box `[lo, hi]` of the output, compared exactly (no slack).
fn holds(b: &serde_json::Value, x: &rug::Float) -> bool {
    *x >= f(&b[0]) && *x <= f(&b[1])
}

#[test]
fn all_projections_onto_the_ellipse_of_16_3() {
    let r = solve(&[
        r#"{"id":"e","op":"project","point":[0.5,0.2],"onto":{"type":"ellipse2","center":[0,0],"a":3,"b":2}}"#,
    ]);
    let r = &r[0];
    // Decided exactly through the Apollonius conic (ops::algebraic::foot2).
    assert_eq!(r["status"], "exact", "{r}");
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
    assert_eq!(near[0]["status"], "exact");
}

#[test]
fn line_and_sphere_of_16_4_crossing_and_tangent() {
    let r = solve(&[
        r#"{"id":"x","op":"intersect","objects":[{"type":"line","origin":[-3,0.5,0.2],"dir":[1,0,0]},{"type":"sphere","center":[0,0,0],"radius":2}]}"#,
        r#"{"id":"t","op":"intersect","objects":[{"type":"line","origin":[-3,2,0],"dir":[1,0,0]},{"type":"sphere","center":[0,0,0],"radius":2}]}"#,
        r#"{"id":"m","op":"intersect","objects":[{"type":"sphere","center":[0,0,0],"radius":2},{"type":"line","origin":[-3,2.000001,0],"dir":[1,0,0]}]}"#,
    ]);
    // A line against a sphere is algebraic: decided exactly (CERTIFICATION.md `exact`).
    assert_eq!(r[0]["status"], "exact", "{}", r[0]);
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
    assert_eq!(r[1]["status"], "exact", "{}", r[1]);
    let p = &r[1]["points"][0];
    assert_eq!(p["tangent"], true);
    assert_eq!(p["multiplicity"], 2);
    assert_eq!(p["exact"]["xyz"], serde_json::json!(["0", "2", "0"]), "{p}");
    assert_eq!(p["exact"]["params"][0], serde_json::json!(["3"]));
    // (u, v) = (π/2, 0) enclosed: π/2 at 1024 bits, strictly inside the box.
    let half_pi = rug::Float::with_val(1024, rug::float::Constant::Pi) / 2u32;
    let u = &p["param_box"][1][0];
    assert!(holds(u, &half_pi), "{u}");
    assert!(holds(&p["param_box"][1][1], &mp(0.0)), "{p}");
    assert_eq!(r[2]["kind"], "empty", "{}", r[2]);
    assert_eq!(r[2]["complete"], true);
}

#[test]
fn circle_and_ellipse_of_16_6() {
    let r = solve(&[
        r#"{"id":"4","op":"intersect","objects":[{"type":"circle2","center":[0,0],"radius":2},{"type":"ellipse2","center":[0,0],"a":3,"b":1}]}"#,
        r#"{"id":"2","op":"intersect","objects":[{"type":"circle2","center":[0,0],"radius":1},{"type":"ellipse2","center":[0,0],"a":3,"b":1}]}"#,
    ]);
    assert_eq!(r[0]["status"], "exact", "{}", r[0]);
    assert_eq!(r[0]["points"].as_array().expect("points").len(), 4);
    for p in r[0]["points"].as_array().expect("points") {
        assert!((f(&p["xyz"][0]).abs() - 1.8371173071).abs() < 1e-9);
        assert!((f(&p["xyz"][1]).abs() - 0.7905694150).abs() < 1e-9);
    }
    let tangent = r[1]["points"].as_array().expect("points");
    assert_eq!(tangent.len(), 2, "{}", r[1]);
    assert!(tangent
        .iter()
        .all(|p| p["tangent"] == true && p["multiplicity"] == 2));
    assert_eq!(r[1]["status"], "exact");
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

#[test]
fn nearest_is_proven_against_feet_ends_and_edges() {
    let r = solve(&[
        // An open Bézier arc whose distance still falls at its end: the end is nearest.
        r#"{"id":"end","op":"project","nearest":true,"point":[3,-1],"onto":{"type":"bezier2","points":[[0,0],[1,1],[2,0]]}}"#,
        // A cylinder piece, interior foot (3,0,1.9) → (1,0,1.9) at distance 2; its top
        // edge is at distance ≥ √4.01.
        r#"{"id":"foot","op":"project","nearest":true,"point":[3,0,1.9],"onto":{"type":"cylinder","origin":[0,0,0],"radius":1,"axis":[0,0,1],"height":[0,2]}}"#,
        // Above the top edge: no interior foot; the nearest point is on the edge.
        r#"{"id":"edge","op":"project","nearest":true,"point":[3,0,2.5],"onto":{"type":"cylinder","origin":[0,0,0],"radius":1,"axis":[0,0,1],"height":[0,2]}}"#,
        // A torus has no edges: the nearest of its four feet.
        r#"{"id":"torus","op":"project","nearest":true,"point":[1,2,3],"onto":{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,1]}}"#,
    ]);
    let end = &r[0];
    assert_eq!(end["status"], "verified", "{end}");
    assert_eq!(end["complete"], true);
    let p = &end["points"][0];
    assert_eq!(p["nearest"], true);
    assert_eq!(f(&p["params"][0][0]), 1.0, "{p}");
    assert_eq!((f(&p["xyz"][0]), f(&p["xyz"][1])), (2.0, 0.0));
    assert!((f(&p["distance"]) - 2f64.sqrt()).abs() < 1e-15);

    let foot = &r[1];
    assert_eq!(foot["status"], "verified", "{foot}");
    assert_eq!(foot["points"].as_array().expect("points").len(), 1);
    let p = &foot["points"][0];
    assert!((f(&p["distance"]) - 2.0).abs() < 1e-12, "{p}");
    assert!((f(&p["xyz"][0]) - 1.0).abs() < 1e-12 && (f(&p["xyz"][2]) - 1.9).abs() < 1e-12);

    assert_eq!(r[2]["status"], "undecided", "{}", r[2]);

    let torus = &r[3];
    assert_eq!(torus["status"], "verified", "{torus}");
    assert_eq!(torus["points"].as_array().expect("points").len(), 1);
    let d = f(&torus["points"][0]["distance"]);
    let near = ((5f64.sqrt() - 3.0).powi(2) + 9.0).sqrt() - 1.0;
    assert!((d - near).abs() < 1e-12, "{torus}");
}

#[test]
fn projection_along_a_direction_finds_both_hits_and_the_nearer() {
    let r = solve(&[
        r#"{"id":"all","op":"project","point":[0.3,0.2,3],"direction":[0,0,-1],"onto":{"type":"sphere","center":[0,0,0],"radius":1}}"#,
        r#"{"id":"near","op":"project","nearest":true,"point":[0.3,0.2,3],"direction":[0,0,-1],"onto":{"type":"sphere","center":[0,0,0],"radius":1}}"#,
    ]);
    let z = (1.0f64 - 0.13).sqrt();
    // Decided through the exact line ∩ sphere route (coordinates correctly rounded).
    assert_eq!(r[0]["status"], "exact", "{}", r[0]);
    assert_eq!(r[0]["complete"], true);
    let mut zs: Vec<f64> = r[0]["points"]
        .as_array()
        .expect("points")
        .iter()
        .map(|p| f(&p["xyz"][2]))
        .collect();
    zs.sort_by(f64::total_cmp);
    assert_eq!(zs.len(), 2);
    assert!(
        (zs[0] + z).abs() < 1e-12 && (zs[1] - z).abs() < 1e-12,
        "{zs:?}"
    );
    assert_eq!(r[1]["status"], "exact", "{}", r[1]);
    let pts = r[1]["points"].as_array().expect("points");
    assert_eq!(pts.len(), 1);
    assert!((f(&pts[0]["xyz"][2]) - z).abs() < 1e-12);
}

#[test]
fn lines_through_a_torus_hit_0_2_3_and_4_times_exactly() {
    let torus = r#"{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,1]}"#;
    let line = |o: &str| format!(r#"{{"type":"line","origin":{o},"dir":[1,0,0]}}"#);
    let cases: Vec<String> = ["[-5,0,2]", "[-5,0,1]", "[-5,2,0]", "[-5,0,0]"]
        .iter()
        .map(|o| {
            format!(
                r#"{{"id":"t","op":"intersect","objects":[{},{torus}]}}"#,
                line(o)
            )
        })
        .collect();
    let r = solve(&cases.iter().map(String::as_str).collect::<Vec<_>>());
    let mults = |r: &serde_json::Value| -> Vec<u64> {
        r["points"]
            .as_array()
            .expect("points")
            .iter()
            .map(|p| p["multiplicity"].as_u64().expect("multiplicity"))
            .collect()
    };
    for x in &r {
        assert_eq!(x["status"], "exact", "{x}");
        assert_eq!(x["complete"], true);
    }
    assert_eq!(r[0]["kind"], "empty");
    // Over the tube's top circle: two tangencies at (±3, 0, 1).
    assert_eq!(mults(&r[1]), vec![2, 2]);
    // Tangent to the inner equator at (0, 2, 0), crossing at x = ±√12.
    assert_eq!(mults(&r[2]), vec![1, 2, 1]);
    let x0 = f(&r[2]["points"][0]["xyz"][0]);
    assert_eq!(x0, -(12f64.sqrt()), "{}", r[2]);
    assert_eq!(mults(&r[3]), vec![1, 1, 1, 1]);
    let xs: Vec<f64> = r[3]["points"]
        .as_array()
        .expect("points")
        .iter()
        .map(|p| f(&p["xyz"][0]))
        .collect();
    assert_eq!(xs, vec![-4.0, -2.0, 2.0, 4.0]);
}

#[test]
fn plane_conics_and_clipped_lines_are_exact() {
    let r = solve(&[
        // Exact input strings: the segment ends at x = 1/3 and touches the circle at
        // (0, 1), its parameter 6/7.
        r#"{"id":"s","op":"intersect","objects":[{"type":"segment2","a":[-2,1],"b":["1/3",1]},{"type":"circle2","center":[0,0],"radius":1}]}"#,
        // The same line cut off before the circle: nothing.
        r#"{"id":"short","op":"intersect","objects":[{"type":"segment2","a":[-2,1],"b":[-1,1]},{"type":"circle2","center":[0,0],"radius":1}]}"#,
        // The unit circle inside x² + 4y² = 4, touching it at (0, ±1).
        r#"{"id":"cc","op":"intersect","objects":[{"type":"conic2","coeffs":[1,0,1,0,0,-1]},{"type":"conic2","coeffs":[1,0,4,0,0,-4]}]}"#,
        // A space segment reaching into a sphere: one crossing at t = 1/3.
        r#"{"id":"seg","op":"intersect","objects":[{"type":"sphere","center":[0,0,0],"radius":2},{"type":"segment","a":[-3,0,0],"b":[0,0,0]}]}"#,
    ]);
    let s = &r[0];
    assert_eq!(s["status"], "exact", "{s}");
    let p = &s["points"][0];
    assert_eq!(p["multiplicity"], 2);
    assert_eq!(p["exact"]["params"][0], serde_json::json!(["6/7"]), "{p}");
    assert_eq!(r[1]["kind"], "empty", "{}", r[1]);
    assert_eq!(r[1]["status"], "exact");
    let cc = r[2]["points"].as_array().expect("points");
    assert_eq!(cc.len(), 2, "{}", r[2]);
    for (p, y) in cc.iter().zip([-1.0, 1.0]) {
        assert_eq!((f(&p["xyz"][0]), f(&p["xyz"][1])), (0.0, y));
        assert_eq!(p["multiplicity"], 2);
    }
    let seg = &r[3]["points"].as_array().expect("points");
    assert_eq!(seg.len(), 1, "{}", r[3]);
    assert_eq!(seg[0]["exact"]["params"][1], serde_json::json!(["1/3"]));
    assert_eq!(seg[0]["exact"]["xyz"], serde_json::json!(["-2", "0", "0"]));
}

#[test]
fn a_tangency_outside_the_algebraic_cases_is_verified_singular() {
    // A cylinder piece (its height cuts the implicit surface) goes to the certifier.
    let r = solve(&[
        r#"{"id":"c","op":"intersect","objects":[{"type":"line","origin":[-3,1,0.5],"dir":[1,0,0]},{"type":"cylinder","origin":[0,0,0],"radius":1,"axis":[0,0,1],"height":[0,1]}]}"#,
    ]);
    assert_eq!(r[0]["status"], "verified_singular", "{}", r[0]);
    let p = &r[0]["points"][0];
    assert_eq!(p["multiplicity"], 2);
    let b = &p["box"];
    assert!(f(&b[0][0]) <= 0.0 && 0.0 <= f(&b[0][1]), "{p}");
    assert!(f(&b[1][0]) <= 1.0 && 1.0 <= f(&b[1][1]), "{p}");
}

#[test]
fn a_foot_on_the_seam_is_reported_once() {
    // (3, 0, 1.9) onto a cylinder: feet at u = 0 (= 2π, on the seam) and u = π. The
    // seam root is found at both ends of the domain and must be counted once.
    let r = solve(&[
        r#"{"id":"seam","op":"project","point":[3,0,1.9],"onto":{"type":"cylinder","origin":[0,0,0],"radius":1,"axis":[0,0,1],"height":[0,2]}}"#,
    ]);
    assert_eq!(r[0]["status"], "verified", "{}", r[0]);
    assert_eq!(r[0]["complete"], true);
    let mut d: Vec<f64> = r[0]["points"]
        .as_array()
        .expect("points")
        .iter()
        .map(|p| f(&p["distance"]))
        .collect();
    d.sort_by(f64::total_cmp);
    assert_eq!(d.len(), 2, "{}", r[0]);
    assert!((d[0] - 2.0).abs() < 1e-12 && (d[1] - 4.0).abs() < 1e-12);
}

#[test]
fn classify_reports_the_proven_nearest_point_of_the_shell() {
    let r = solve(&[
        r#"{"id":"in","op":"classify","point":[3.5,0,0],"shell":{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,1]}}"#,
        r#"{"id":"out","op":"classify","point":[0,0,0],"shell":{"type":"sphere","center":[1,1,1],"radius":1}}"#,
        r#"{"id":"centre","op":"classify","point":[1,1,1],"shell":{"type":"sphere","center":[1,1,1],"radius":1}}"#,
    ]);
    assert_eq!(r[0]["kind"], "inside");
    let p = &r[0]["points"][0];
    assert_eq!(p["nearest"], true, "{}", r[0]);
    // (4, 0, 0) at distance 1/2, inside the certified box.
    for (b, x) in p["box"]
        .as_array()
        .expect("box")
        .iter()
        .zip([4.0, 0.0, 0.0])
    {
        assert!(f(&b[0]) <= x && x <= f(&b[1]), "{p}");
    }
    assert!((f(&p["distance"]) - 0.5).abs() < 1e-12);
    assert_eq!(r[1]["kind"], "outside");
    let q = &r[1]["points"][0];
    // (1, 1, 1)·(1 − 1/√3) at 1024 bits.
    let x = mp(1.0) - mp(3.0).sqrt().recip();
    for b in q["box"].as_array().expect("box") {
        assert!(holds(b, &x) && f(&b[1]) - f(&b[0]) < 1e-12, "{q}");
    }
    // Every point of the sphere is nearest to its centre: no point, and the reason.
    assert_eq!(r[2]["kind"], "inside");
    assert!(r[2].get("points").is_none(), "{}", r[2]);
    assert!(r[2]["reason"].as_str().expect("reason").contains("centre"));
}

#[test]
fn space_curves_are_proven_apart_or_boxed_where_they_meet() {
    let r = solve(&[
        r#"{"id":"miss","op":"intersect","objects":[{"type":"circle","center":[0,0,0],"radius":1,"axis":[0,0,1]},{"type":"circle","center":[0,0,0.001],"radius":1,"axis":[0,0,1]}]}"#,
        r#"{"id":"near","op":"intersect","objects":[{"type":"circle","center":[0,0,0],"radius":1,"axis":[0,0,1]},{"type":"segment","a":[1,0,1e-9],"b":[1,1,1e-9]}]}"#,
        r#"{"id":"helix","op":"intersect","objects":[{"type":"helix","center":[0,0,0],"radius":1,"pitch":1,"axis":[0,0,1],"range":[0,12.566370614359172]},{"type":"line","origin":[0,1,-5],"dir":[0,0,1]}]}"#,
        // The line meets the circle on its seam (t = 0 = 2π): one place, one box.
        r#"{"id":"seam","op":"intersect","objects":[{"type":"circle","center":[0,0,0],"radius":1,"axis":[0,0,1]},{"type":"line","origin":[1,0,-1],"dir":[0,0,1]}]}"#,
    ]);
    let seam = r[3]["points"].as_array().expect("points");
    assert_eq!(seam.len(), 1, "{}", r[3]);
    for (b, x) in seam[0]["box"]
        .as_array()
        .expect("box")
        .iter()
        .zip([1.0, 0.0, 0.0])
    {
        assert!(f(&b[0]) <= x && x <= f(&b[1]), "{}", r[3]);
    }
    // Parallel circles 1e-3 apart and a segment 1e-9 above a circle: proven disjoint
    // exactly (the planes parallel, the segment parallel to the circle's plane, issue 16).
    for (x, status) in r[..2].iter().zip(["exact", "exact"]) {
        assert_eq!(x["status"], status, "{x}");
        assert_eq!(x["kind"], "empty");
        assert_eq!(x["complete"], true);
    }
    // The helix crosses the line at z = 1/4 and 5/4: two undecided boxes holding them.
    let h = &r[2];
    assert_eq!(h["status"], "undecided", "{h}");
    let pts = h["points"].as_array().expect("points");
    assert_eq!(pts.len(), 2, "{h}");
    for (p, z) in pts.iter().zip([0.25, 1.25]) {
        for (b, x) in p["box"].as_array().expect("box").iter().zip([0.0, 1.0, z]) {
            assert!(f(&b[0]) <= x && x <= f(&b[1]), "{p}");
        }
    }
}

#[test]
fn projection_onto_a_sphere_is_complete_in_closed_form() {
    let r = solve(&[
        r#"{"id":"gen","op":"project","point":[1,2,3],"onto":{"type":"sphere","center":[0,0,0],"radius":1}}"#,
        r#"{"id":"pole","op":"project","point":[0,0,5],"onto":{"type":"sphere","center":[0,0,0],"radius":2}}"#,
    ]);
    let g = &r[0];
    assert_eq!(g["status"], "verified", "{g}");
    assert_eq!(g["complete"], true);
    let pts = g["points"].as_array().expect("points");
    assert_eq!(pts.len(), 2);
    let n = 14f64.sqrt();
    let root14 = mp(14.0).sqrt();
    for (p, sign) in pts.iter().zip([1.0, -1.0]) {
        // ±(1, 2, 3)/√14 at 1024 bits, strictly inside boxes narrower than 1e-15.
        for (b, x) in p["box"]
            .as_array()
            .expect("box")
            .iter()
            .zip([1.0, 2.0, 3.0])
        {
            let x = mp(sign * x) / &root14;
            assert!(
                holds(b, &x) && f(&b[1]) - f(&b[0]) < 1e-15,
                "{x} not in {p}"
            );
        }
        assert!((f(&p["distance"]) - (n - sign)).abs() < 1e-14);
        // The latitude v = ±asin(3/√14) and longitude u = atan2(2, 1) (or + π).
        let v = (mp(3.0) / &root14).asin() * sign;
        assert!(holds(&p["param_box"][0][1], &v), "{v} not in {p}");
        let mut u = mp(2.0 * sign).atan2(&mp(sign));
        if u < 0 {
            u += rug::Float::with_val(1024, rug::float::Constant::Pi) * 2u32;
        }
        assert!(holds(&p["param_box"][0][0], &u), "{u} not in {p}");
    }
    // On the axis: the poles, their longitude any angle.
    let p = &r[1]["points"][0];
    assert_eq!(p["xyz"], serde_json::json!([0.0, 0.0, 2.0]));
    let u = &p["param_box"][0][0];
    assert!(
        f(&u[0]) <= 0.0 && f(&u[1]) >= 2.0 * std::f64::consts::PI,
        "{p}"
    );
}

#[test]
fn a_rotated_ellipsoid_is_exact_too() {
    // Axis (3, 4, 0) (length 5), the semi-axis 5 along it: the poles are (±3, ±4, 0).
    let e = r#"{"type":"ellipsoid","center":[0,0,0],"a":3,"b":2,"c":5,"axis":[3,4,0]}"#;
    let r = solve(&[
        &format!(
            r#"{{"id":"a","op":"intersect","objects":[{{"type":"line","origin":[0,0,0],"dir":[3,4,0]}},{e}]}}"#
        ),
        &format!(
            r#"{{"id":"b","op":"intersect","objects":[{{"type":"line","origin":[3,4,-10],"dir":[0,0,1]}},{e}]}}"#
        ),
    ]);
    assert_eq!(r[0]["status"], "exact", "{}", r[0]);
    let ts: Vec<&serde_json::Value> = r[0]["points"]
        .as_array()
        .expect("points")
        .iter()
        .map(|p| &p["exact"]["params"][0][0])
        .collect();
    assert_eq!(ts, vec!["-1", "1"]);
    // Tangent at the pole (3, 4, 0), along the frame's X = +z.
    let p = &r[1]["points"][0];
    assert_eq!(r[1]["status"], "exact");
    assert_eq!(p["multiplicity"], 2);
    assert_eq!(p["exact"]["xyz"], serde_json::json!(["3", "4", "0"]));
}
