//! Issue 5: the JSON surface objects of spec/CASES.md. Every type reads, serializes and
//! reads back to an equal spec with the same bits; the built surfaces follow the
//! parametrisations written in CASES.md; unknown fields, wrong types, out-of-range
//! numbers and unknown types are errors naming the field path.

use geocert::io::shapes::surface::{parse_surface, SurfaceSpec, SURFACE_TYPES};
use geocert::surface::Surface;
use serde_json::{json, Value};

fn examples() -> Vec<Value> {
    vec![
        json!({"type": "plane", "origin": [1, 2, 3], "u": [2, 0, 1], "v": [1, 1, 0]}),
        json!({"type": "plane", "origin": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0],
               "domain": [[-1, 1], [0, 2]]}),
        json!({"type": "sphere", "center": [0, 0, 0], "radius": 1}),
        json!({"type": "sphere", "center": [1, -2, 0.5], "radius": 2.5, "axis": [1, 2, 3],
               "ref": [0, 1, 0], "domain": [[0, 3], [-1, 1]]}),
        json!({"type": "ellipsoid", "center": [0, 0, 0], "a": 3, "b": 2, "c": 1}),
        json!({"type": "hyperboloid1", "center": [0, 0, 0], "a": 1, "b": 2, "c": 3,
               "axis": [0, 0, 1], "range": [-1, 1]}),
        json!({"type": "hyperboloid2", "center": [0, 0, 1], "a": 1, "b": 1, "c": 0.5,
               "axis": [0, 1, 0], "ref": [1, 0, 0], "range": [0, 2]}),
        json!({"type": "paraboloid", "center": [0, 0, 0], "a": 1, "b": 2, "axis": [0, 0, 1],
               "range": [0, 1.5]}),
        json!({"type": "hyperbolic_paraboloid", "center": [0, 0, 0], "a": 1, "b": 2,
               "domain": [[-1, 1], [-2, 2]]}),
        json!({"type": "cylinder", "origin": [0, 0, 0], "radius": 2, "axis": [0, 0, 1],
               "height": [0, 5]}),
        json!({"type": "elliptic_cylinder", "origin": [0, 0, 0], "a": 2, "b": 1,
               "axis": [1, 1, 0], "height": [-1, 1]}),
        json!({"type": "cone", "origin": [0, 0, 0], "radius": 0, "half_angle": 0.5,
               "axis": [0, 0, 1], "height": [0, 2]}),
        json!({"type": "torus", "center": [0, 0, 0], "major": 3, "minor": 1, "axis": [0, 0, 1]}),
        json!({"type": "bezier_surface", "points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 1]]]}),
        json!({"type": "bezier_surface",
               "points": [[[0, 0, 0], [1, 0, 1], [2, 0, 0]], [[0, 1, 0], [1, 1, 2], [2, 1, 0]]],
               "weights": [[1, 0.5, 1], [1, 2, 1]]}),
        json!({"type": "nurbs_surface", "degree_u": 2, "degree_v": 1,
               "knots_u": [0, 0, 0, 0.5, 1, 1, 1], "knots_v": [0, 0, 1, 1],
               "points": [[[0, 0, 0], [1, 0, 1], [2, 0, 0], [3, 0, 1]],
                          [[0, 1, 0], [1, 1, 2], [2, 1, 0], [3, 1, 1]]],
               "weights": [[1, 0.5, 1, 1], [1, 2, 1, 0.25]]}),
        json!({"type": "revolution", "profile": {"type": "segment", "a": [1.25, 0, 0],
               "b": [0.5, 0, 2]}, "origin": [0, 0, 0], "axis": [0, 0, 1]}),
        json!({"type": "extrusion", "profile": {"type": "circle", "center": [0, 0, 0],
               "radius": 1.25, "axis": [0, 0, 1]}, "dir": [0, 1, 2]}),
        json!({"type": "ruled",
               "a": {"type": "circle", "center": [0, 0, 0], "radius": 1.5, "axis": [0, 0, 1]},
               "b": {"type": "bezier", "points": [[0, 0, 2], [1, 1, 2], [2, 0, 3]]}}),
    ]
}

#[test]
fn every_type_round_trips_through_json() {
    let mut seen = std::collections::BTreeSet::new();
    for value in examples() {
        let spec = parse_surface(&value, "s").unwrap_or_else(|e| panic!("{value}: {e}"));
        seen.insert(spec.type_name());
        assert_eq!(value["type"], json!(spec.type_name()));
        let text = serde_json::to_string(&spec).unwrap();
        let back = parse_surface(&serde_json::from_str(&text).unwrap(), "s").unwrap();
        assert_eq!(back, spec, "{text}");
        assert_eq!(parse_surface(&spec.to_json(), "").unwrap(), spec);
        spec.build().unwrap_or_else(|e| panic!("{value}: {e}"));
    }
    assert_eq!(seen.len(), SURFACE_TYPES.len(), "{seen:?}");
}

#[test]
fn doubles_read_back_to_the_same_bits() {
    let tricky = [
        0.1 + 0.2,
        1e-300,
        -0.0,
        5e-324,
        1.7976931348623157e308,
        2.0f64.sqrt(),
    ];
    for x in tricky {
        let value = json!({"type": "sphere", "center": [x, 0, 0], "radius": 1});
        let spec = parse_surface(&value, "").unwrap();
        let text = serde_json::to_string(&spec).unwrap();
        let back = parse_surface(&serde_json::from_str(&text).unwrap(), "").unwrap();
        let SurfaceSpec::Sphere(s) = back else {
            panic!("not a sphere")
        };
        assert_eq!(s.center[0].to_bits(), x.to_bits(), "{text}");
    }
}

/// `center + (R + r cos v)(cos u X + sin u Y) + r sin v Z` etc., with axis +z.
#[test]
fn built_surfaces_follow_the_parametrisations_of_cases_md() {
    let build = |v: Value| parse_surface(&v, "").unwrap().build().unwrap();
    let (u, v): (f64, f64) = (0.7, -0.4);
    let close = |a: [f64; 3], b: [f64; 3]| (0..3).all(|i| (a[i] - b[i]).abs() < 1e-14);
    let torus = build(
        json!({"type": "torus", "center": [1, 2, 3], "major": 3, "minor": 1,
                              "axis": [0, 0, 1]}),
    );
    let ring = 3.0 + f64::cos(v);
    let expect = [1.0 + ring * u.cos(), 2.0 + ring * u.sin(), 3.0 + v.sin()];
    assert!(close(torus.jet(&u, &v, 0)[0], expect));
    assert_eq!(
        torus.domain(),
        ([0.0, std::f64::consts::TAU], [0.0, std::f64::consts::TAU])
    );
    let cone = build(
        json!({"type": "cone", "origin": [0, 0, 0], "radius": 0, "half_angle": 0.5,
                             "axis": [0, 0, 1], "height": [0, 2]}),
    );
    assert_eq!(
        cone.jet(&1.0, &0.0, 0)[0],
        [0.0, 0.0, 0.0],
        "r = 0 puts the apex at the origin"
    );
    let rho = 0.5f64.tan() * 1.5;
    assert!(close(
        cone.jet(&u, &1.5, 0)[0],
        [rho * u.cos(), rho * u.sin(), 1.5]
    ));
    let cyl = build(
        json!({"type": "cylinder", "origin": [0, 0, 1], "radius": 2, "axis": [0, 0, 1],
                            "height": [0, 5]}),
    );
    assert!(close(
        cyl.jet(&u, &4.0, 0)[0],
        [2.0 * u.cos(), 2.0 * u.sin(), 5.0]
    ));
    assert_eq!(cyl.domain().1, [0.0, 5.0]);
    let par = build(
        json!({"type": "paraboloid", "center": [0, 0, 0], "a": 1, "b": 2,
                            "axis": [0, 0, 1], "range": [0, 2]}),
    );
    assert!(close(
        par.jet(&u, &1.5, 0)[0],
        [1.5 * u.cos(), 3.0 * u.sin(), 2.25]
    ));
    let h2 = build(
        json!({"type": "hyperboloid2", "center": [0, 0, 0], "a": 1, "b": 2, "c": 3,
                           "axis": [0, 0, 1], "range": [0, 2]}),
    );
    let w = 1.25f64;
    assert!(close(
        h2.jet(&u, &w, 0)[0],
        [w.sinh() * u.cos(), 2.0 * w.sinh() * u.sin(), 3.0 * w.cosh()]
    ));
    let sphere = build(json!({"type": "sphere", "center": [0, 0, 0], "radius": 2}));
    assert!(close(
        sphere.jet(&u, &v, 0)[0],
        [
            2.0 * v.cos() * u.cos(),
            2.0 * v.cos() * u.sin(),
            2.0 * v.sin()
        ]
    ));
    let plane =
        build(json!({"type": "plane", "origin": [1, 2, 3], "u": [2, 0, 1], "v": [1, 1, 0]}));
    assert_eq!(plane.jet(&2.0, &-1.0, 0)[0], [4.0, 1.0, 5.0]);
    assert_eq!(
        plane.domain().0,
        [f64::NEG_INFINITY, f64::INFINITY],
        "CASES: ℝ² by default"
    );
    let hp = build(
        json!({"type": "hyperbolic_paraboloid", "center": [0, 0, 0], "a": 1, "b": 2,
                           "domain": [[-1, 1], [-2, 2]]}),
    );
    assert_eq!(hp.jet(&0.5, &1.5, 0)[0], [0.5, 3.0, 0.25 - 2.25]);
    // The 2×2 Bézier surface is the bilinear patch.
    let bez = build(json!({"type": "bezier_surface",
                            "points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 1]]]}));
    assert_eq!(bez.jet(&0.5, &0.5, 0)[0], [0.5, 0.5, 0.25]);
}

#[test]
fn format_errors_name_the_field_path() {
    let err = |v: Value| parse_surface(&v, "objects[1]").unwrap_err();
    let e = err(json!({"type": "sphere", "center": [0, 0, 0], "radius": 1, "colour": 2}));
    assert_eq!(e.kind(), "format");
    assert!(e.to_string().contains("colour"), "{e}");
    assert!(e.field().starts_with("objects[1]"), "{}", e.field());
    let e = err(json!({"type": "sphere", "center": [0, 0, 0], "radius": "1/3"}));
    assert_eq!((e.kind(), e.field()), ("format", "objects[1].radius"));
    let e = err(json!({"type": "sphere", "center": [0, 0], "radius": 1}));
    assert_eq!(e.field(), "objects[1].center");
    let e = err(json!({"type": "sphere", "center": [0, 0, 0]}));
    assert!(e.to_string().contains("radius"), "{e}");
    let e = err(
        json!({"type": "nurbs_surface", "degree_u": -1, "degree_v": 1, "knots_u": [],
                       "knots_v": [], "points": []}),
    );
    assert_eq!(e.field(), "objects[1].degree_u");
    let e = err(json!({"type": "bezier_surface", "points": [[[0, 0, 0], [1, 0, "x"]]]}));
    assert_eq!(e.field(), "objects[1].points[0][1][2]");
    let e = err(json!({"type": "teapot"}));
    assert_eq!((e.kind(), e.field()), ("unsupported", "objects[1].type"));
    let e = err(json!({"type": "plane", "normal": [0, 0, 1], "d": 0}));
    assert_eq!((e.kind(), e.field()), ("unsupported", "objects[1]"));
    let e = err(json!([1, 2]));
    assert_eq!((e.kind(), e.field()), ("format", "objects[1]"));
    let e = err(json!({"radius": 1}));
    assert_eq!(e.field(), "objects[1].type");
}

#[test]
fn out_of_range_numbers_are_rejected() {
    // JSON has no NaN or infinity; a literal beyond the double range is a parse error.
    assert!(serde_json::from_str::<Value>(r#"{"r": NaN}"#).is_err());
    let text = r#"{"type": "sphere", "center": [0, 0, 0], "radius": 1e999}"#;
    let parsed = serde_json::from_str::<Value>(text);
    assert!(
        parsed.is_err(),
        "serde_json refuses 1e999 with float_roundtrip"
    );
    // A spec built in code with NaN is refused when built, naming the field.
    let spec = parse_surface(
        &json!({"type": "sphere", "center": [0, 0, 0], "radius": 1}),
        "",
    )
    .unwrap();
    let SurfaceSpec::Sphere(mut s) = spec else {
        panic!()
    };
    s.radius = f64::NAN;
    let e = SurfaceSpec::Sphere(s.clone()).build().unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "radius"));
    s.radius = 1.0;
    s.center[2] = f64::INFINITY;
    let e = SurfaceSpec::Sphere(s).build().unwrap_err().at("objects[0]");
    assert_eq!(
        (e.kind(), e.field()),
        ("non_finite", "objects[0].center[2]")
    );
}
