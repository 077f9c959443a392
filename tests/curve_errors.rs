//! Bad curve input gives a typed error naming the field (ARCHITECTURE.md "Errors and
//! bad input"), through the JSON layer (paths prefixed by the object's position) and
//! through the Rust constructors. Never a panic.

use geocert::curve::{
    Analytic, Bezier, Frame, NurbsCurve, Polyline, Reparametrised, Segment, Shape,
};
use geocert::io::shapes::{parse_curve2, parse_curve3};
use serde_json::{json, Value};

fn err3(v: Value) -> (String, String) {
    let e = parse_curve3(v, "objects[1]").unwrap_err();
    (e.kind().to_string(), e.field().to_string())
}

fn err2(v: Value) -> (String, String) {
    let e = parse_curve2(v, "onto").unwrap_err();
    (e.kind().to_string(), e.field().to_string())
}

fn is(kind: &str, field: &str) -> (String, String) {
    (kind.to_string(), field.to_string())
}

#[test]
fn knot_vectors() {
    let nurbs = |degree: usize, knots: Value, n: usize| {
        let points: Vec<Value> = (0..n).map(|i| json!([i, i * i, 1])).collect();
        json!({"type": "nurbs_curve", "degree": degree, "knots": knots, "points": points})
    };
    assert_eq!(
        err3(nurbs(2, json!([0, 0, 0, 1, 1, 1]), 4)),
        is("count_mismatch", "objects[1].knots")
    );
    assert_eq!(
        err3(nurbs(2, json!([0, 0, 0, 2, 1, 1, 1]), 4)),
        is("invalid_knots", "objects[1].knots[4]")
    );
    // Multiplicity above p + 1 at an end, above p inside the domain.
    assert_eq!(
        err3(nurbs(1, json!([0, 0, 0, 1, 1]), 3)),
        is("invalid_knots", "objects[1].knots[2]")
    );
    assert_eq!(
        err3(nurbs(2, json!([0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1]), 6)),
        is("invalid_knots", "objects[1].knots[5]")
    );
    // Degree 0, too few points, an empty domain.
    assert_eq!(
        err3(nurbs(0, json!([0, 1, 2]), 2)),
        is("invalid_value", "objects[1].degree")
    );
    assert_eq!(
        err3(nurbs(3, json!([0, 0, 0, 0, 1, 1, 1]), 3)),
        is("count_mismatch", "objects[1].points")
    );
    assert_eq!(
        err3(nurbs(1, json!([0, 1, 1, 2]), 2)),
        is("empty_domain", "objects[1].knots")
    );
    // A huge degree is a count error, not an overflow.
    assert_eq!(
        err3(nurbs(usize::MAX, json!([0, 1]), 2)),
        is("count_mismatch", "objects[1].points")
    );
    // Domain inside [knots[p], knots[n]].
    let mut v = nurbs(1, json!([0, 0, 1, 2, 2]), 3);
    v["domain"] = json!([0.5, 2.5]);
    assert_eq!(
        err3(v.clone()),
        is("parameter_outside_domain", "objects[1].domain[1]")
    );
    v["domain"] = json!([1.5, 0.5]);
    assert_eq!(err3(v), is("empty_domain", "objects[1].domain"));
}

#[test]
fn weights_and_control_nets() {
    let bez = |w: Value| json!({"type": "bezier", "points": [[0, 0, 0], [1, 1, 1], [2, 0, 0]], "weights": w});
    assert_eq!(
        err3(bez(json!([1, 0, 1]))),
        is("non_positive_weight", "objects[1].weights[1]")
    );
    assert_eq!(
        err3(bez(json!([1, 1, -2]))),
        is("non_positive_weight", "objects[1].weights[2]")
    );
    assert_eq!(
        err3(bez(json!([1, 1]))),
        is("count_mismatch", "objects[1].weights")
    );
    assert_eq!(
        err3(json!({"type": "bezier", "points": [[0, 0, 0]]})),
        is("count_mismatch", "objects[1].points")
    );
    assert_eq!(
        err3(json!({"type": "bezier", "points": [[0, 0, 0], [1, 1]]})),
        is("format", "objects[1].points[1]")
    );
    assert_eq!(
        err2(
            json!({"type": "nurbs_curve2", "degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]], "weights": [1, -0.0]})
        ),
        is("non_positive_weight", "onto.weights[1]")
    );
    assert_eq!(
        err2(json!({"type": "polyline2", "points": [[0, 0], [1, 1], [2, 2]], "params": [0, 1, 1]})),
        is("invalid_value", "onto.params[2]")
    );
    assert_eq!(
        err2(json!({"type": "conic2", "coeffs": [0, 0, 0, 0, 0, 1]})),
        is("invalid_value", "onto.coeffs")
    );
}

#[test]
fn radii_axes_and_domains() {
    let circle = |r: Value, axis: Value| json!({"type": "circle", "center": [0, 0, 0], "radius": r, "axis": axis});
    assert_eq!(
        err3(circle(json!(0), json!([0, 0, 1]))),
        is("invalid_value", "objects[1].radius")
    );
    assert_eq!(
        err3(circle(json!(-1), json!([0, 0, 1]))),
        is("invalid_value", "objects[1].radius")
    );
    assert_eq!(
        err3(circle(json!(1), json!([0, 0, 0]))),
        is("zero_direction", "objects[1].axis")
    );
    let mut v = circle(json!(1), json!([0, 0, 2]));
    v["ref"] = json!([0, 0, -3]);
    assert_eq!(err3(v.clone()), is("invalid_value", "objects[1].ref"));
    v["ref"] = json!([0, 0, 0]);
    assert_eq!(err3(v), is("zero_direction", "objects[1].ref"));
    assert_eq!(
        err3(json!({"type": "ellipse", "center": [0, 0, 0], "a": 1, "b": 0, "axis": [0, 0, 1]})),
        is("invalid_value", "objects[1].b")
    );
    assert_eq!(
        err3(json!({"type": "hyperbola", "center": [0, 0, 0], "a": 1, "b": 1, "axis": [0, 0, 1]})),
        is("format", "objects[1].range")
    );
    assert_eq!(
        err3(
            json!({"type": "helix", "center": [0, 0, 0], "radius": 1, "pitch": 1, "axis": [0, 0, 1], "range": [2, 2]})
        ),
        is("empty_domain", "objects[1].range")
    );
    assert_eq!(
        err3(
            json!({"type": "parabola", "vertex": [0, 0, 0], "p": -1, "axis": [0, 0, 1], "range": [0, 1]})
        ),
        is("invalid_value", "objects[1].p")
    );
    assert_eq!(
        err3(json!({"type": "line", "origin": [0, 0, 0], "dir": [0, 0, 0]})),
        is("zero_direction", "objects[1].dir")
    );
    assert_eq!(
        err3(json!({"type": "segment", "a": [1, 2, 3], "b": [1, 2, 3]})),
        is("invalid_value", "objects[1].b")
    );
    assert_eq!(
        err2(json!({"type": "circle2", "center": [0, 0], "radius": 1, "domain": [1, -1]})),
        is("empty_domain", "onto.domain")
    );
}

#[test]
fn format_errors_name_the_field() {
    let base = json!({"type": "circle", "center": [0, 0, 0], "radius": 1, "axis": [0, 0, 1]});
    let with = |k: &str, v: Value| {
        let mut x = base.clone();
        x[k] = v;
        x
    };
    assert_eq!(
        err3(with("colour", json!("red"))),
        is("format", "objects[1].colour")
    );
    assert_eq!(
        err3(with("colour", json!(1))),
        is("format", "objects[1].colour")
    );
    assert_eq!(
        err3(with("pitch", json!(1))),
        is("format", "objects[1].pitch")
    );
    assert_eq!(
        err3(with("vertex", json!([0, 0, 0]))),
        is("format", "objects[1].vertex")
    );
    assert_eq!(
        err3(with("center", json!([0, "1/3", 0]))),
        is("unsupported", "objects[1].center[1]")
    );
    assert_eq!(
        err3(json!({"type": "circle", "center": [0, 0, 0], "axis": [0, 0, 1]})),
        is("format", "objects[1].radius")
    );
    assert_eq!(
        err3(json!({"type": "torus_knot"})),
        is("unsupported", "objects[1].type")
    );
    assert_eq!(
        err3(json!({"type": "circle2", "center": [0, 0], "radius": 1})),
        is("unsupported", "objects[1].type")
    );
    assert_eq!(
        err2(json!({"type": "circle", "center": [0, 0, 0], "radius": 1, "axis": [0, 0, 1]})),
        is("unsupported", "onto.type")
    );
    assert_eq!(err3(json!([1, 2, 3])), is("format", "objects[1]"));
    assert_eq!(err3(json!({"radius": 1})), is("format", "objects[1].type"));
    assert_eq!(
        err3(json!({"type": "nurbs_curve", "degree": -1, "knots": [], "points": []})),
        is("format", "objects[1].degree")
    );
    // A non-finite number cannot come from JSON text; from a Value it is null.
    assert_eq!(
        err3(with("radius", json!(f64::NAN))),
        is("format", "objects[1].radius")
    );
}

#[test]
fn rust_constructors_reject_non_finite_input() {
    let f = Frame::standard([0.0; 3]).unwrap();
    let e = Analytic::new(f.clone(), Shape::Circle { radius: f64::NAN }, None).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "radius"));
    let e = Analytic::new(
        f.clone(),
        Shape::Helix {
            radius: 1.0,
            pitch: f64::INFINITY,
        },
        Some((0.0, 1.0)),
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "pitch"));
    let e = Frame::new([0.0; 3], [0.0, f64::INFINITY, 0.0], None).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "axis[1]"));
    let e = Bezier::new(vec![[0.0, 0.0], [f64::NAN, 1.0]], None, None).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "points[1][0]"));
    let e = NurbsCurve::new(
        1,
        vec![0.0, 0.0, f64::NAN, 1.0],
        vec![[0.0, 0.0], [1.0, 1.0]],
        None,
        None,
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "knots[2]"));
    let e =
        NurbsCurve::<2>::periodic(3, vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], None).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("count_mismatch", "points"));
    let e = Polyline::new(vec![[0.0, 0.0, 0.0]], None).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("count_mismatch", "points"));
    let e = Analytic::new(
        f.clone(),
        Shape::Ellipse { a: 1.0, b: 1.0 },
        Some((0.0, f64::INFINITY)),
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "domain[1]"));
    let seg = Segment::new([0.0, 0.0], [1.0, 0.0], None).unwrap();
    let e = Reparametrised::trimmed(seg.clone(), 0.0, 2.0, 0.0, 1.0).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("invalid_value", "sigma"));
    let e = Reparametrised::reparametrised(seg, 1.0, 1.0).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("empty_domain", "domain"));
    let e = Segment::new([0.0, 0.0], [1.0, 0.0], Some((-0.5, 0.5))).unwrap_err();
    assert_eq!(
        (e.kind(), e.field()),
        ("parameter_outside_domain", "domain[0]")
    );
}
