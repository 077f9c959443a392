//! The JSON form of every curve type of spec/CASES.md: parse → spec → JSON → spec is
//! the identity to the bit, the built curves follow the CASES.md parametrisations,
//! and they equal the curves built directly.

use geocert::curve::{Analytic, AnyCurve3, Curve, Frame, NurbsCurve, Shape};
use geocert::io::shapes::{curve3_from_json, parse_curve2, parse_curve3, Curve2Spec, PlaneShape};
use proptest::prelude::*;
use serde_json::{json, Value};
use std::f64::consts::PI;

fn space_cases() -> Vec<Value> {
    vec![
        json!({"type": "line", "origin": [0, 1, 2], "dir": [1, 1, 0.5]}),
        json!({"type": "line", "origin": [0, 1, 2], "dir": [1, 1, 0.5], "range": [-1, 2]}),
        json!({"type": "segment", "a": [0, 1, 2], "b": [3, -1, 0.1]}),
        json!({"type": "segment", "a": [0, 1, 2], "b": [3, -1, 0.1], "domain": [0.25, 0.5]}),
        json!({"type": "circle", "center": [1, 2, 3], "radius": 2, "axis": [0, 0, 1]}),
        json!({"type": "circle", "center": [1, 2, 3], "radius": 2, "axis": [0, 1, 1], "ref": [1, 0, 0], "domain": [0.5, 2]}),
        json!({"type": "ellipse", "center": [0, 0, 0], "a": 3, "b": 1.5, "axis": [1, 0, 0]}),
        json!({"type": "hyperbola", "center": [0, 0, 0], "a": 2, "b": 1, "axis": [0, 0, 1], "range": [-1, 1]}),
        json!({"type": "parabola", "vertex": [0, 0, 1], "p": 0.5, "axis": [0, 0, 1], "ref": [0, 1, 0], "range": [-2, 2]}),
        json!({"type": "helix", "center": [0, 0, 0], "radius": 1, "pitch": 2, "axis": [0, 0, 1], "range": [0, 12.5]}),
        json!({"type": "bezier", "points": [[0, 0, 0], [1, 2, 0], [3, 2, 1], [4, 0, -1]]}),
        json!({"type": "bezier", "points": [[1, 0, 0], [1, 1, 0], [0, 1, 0]], "weights": [1, 0.75, 1]}),
        json!({"type": "nurbs_curve", "degree": 2, "knots": [0, 0, 0, 0.5, 1, 1, 1],
               "points": [[0, 0, 0], [1, 1, 0], [2, 0, 1], [3, 1, 1]], "weights": [1, 2, 1, 0.5], "domain": [0.1, 0.9]}),
        json!({"type": "polyline", "points": [[0, 0, 0], [1, 1, 1], [2, 0, 0]], "params": [0, 0.5, 3]}),
    ]
}

fn plane_cases() -> Vec<Value> {
    vec![
        json!({"type": "line2", "origin": [0, 1], "dir": [1, 1]}),
        json!({"type": "segment2", "a": [0, 1], "b": [1e-300, -5e-324]}),
        json!({"type": "circle2", "center": [1, 2], "radius": 0.1}),
        json!({"type": "ellipse2", "center": [1, 2], "a": 0.1, "b": 3, "domain": [-1, 1]}),
        json!({"type": "bezier2", "points": [[0, 0], [1, 2], [-0.0, 3]], "weights": [1, 0.5, 2]}),
        json!({"type": "nurbs_curve2", "degree": 1, "knots": [0, 0, 1, 2, 2], "points": [[0, 0], [1, 1], [2, 0]]}),
        json!({"type": "polyline2", "points": [[0, 0], [1, 1]]}),
        json!({"type": "conic2", "coeffs": [1, 0, 1, 0, 0, -1]}),
    ]
}

/// `{:?}` of a spec prints every double in shortest round-trip form, `-0.0` included,
/// so equal strings mean equal bits.
#[test]
fn every_curve_type_round_trips_to_the_bit() {
    for case in space_cases() {
        let spec = parse_curve3(case.clone(), "objects[0]").unwrap();
        let text = serde_json::to_string(&spec.to_json()).unwrap();
        let back = parse_curve3(serde_json::from_str(&text).unwrap(), "objects[0]").unwrap();
        assert_eq!(format!("{spec:?}"), format!("{back:?}"), "{case}");
        assert_eq!(spec.to_json(), back.to_json());
        assert_eq!(spec.to_json()["type"], case["type"]);
        assert_eq!(spec.build().unwrap(), back.build().unwrap());
    }
    for case in plane_cases() {
        let spec = parse_curve2(case.clone(), "onto").unwrap();
        let text = serde_json::to_string(&spec.to_json()).unwrap();
        let back = parse_curve2(serde_json::from_str(&text).unwrap(), "onto").unwrap();
        assert_eq!(format!("{spec:?}"), format!("{back:?}"), "{case}");
        assert_eq!(spec.build().unwrap(), back.build().unwrap());
    }
    // The written names are those of CASES.md.
    let parabola = parse_curve3(space_cases()[8].clone(), "")
        .unwrap()
        .to_json();
    assert!(parabola.get("vertex").is_some() && parabola.get("range").is_some());
    assert!(parabola.get("center").is_none() && parabola.get("domain").is_none());
}

#[test]
fn built_curves_follow_the_cases_md_parametrisations() {
    let c = curve3_from_json(space_cases()[4].clone(), "").unwrap();
    // center + r(cos t X + sin t Y), axis +z: X = +x, Y = +y.
    let t = 0.75f64;
    let p = c.point(&t);
    let expected = [1.0 + 2.0 * t.cos(), 2.0 + 2.0 * t.sin(), 3.0];
    assert!((0..3).all(|i| (p[i] - expected[i]).abs() < 1e-15));
    assert_eq!(c.domain(), (0.0, 2.0 * PI));
    assert!(c.is_closed());
    let direct = AnyCurve3::Analytic(
        Analytic::new(
            Frame::new([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], None).unwrap(),
            Shape::Circle { radius: 2.0 },
            None,
        )
        .unwrap(),
    );
    assert_eq!(c, direct);
    // A circle with a domain is an arc.
    let arc = curve3_from_json(space_cases()[5].clone(), "").unwrap();
    assert_eq!(arc.domain(), (0.5, 2.0));
    assert!(!arc.is_closed());
    // vertex + t²/(2p)·X + t·Y with ref +y: X = +y, Y = Z × X = −x.
    let par = curve3_from_json(space_cases()[8].clone(), "").unwrap();
    assert_eq!(par.point(&1.5f64), [-1.5, 1.5 * 1.5 / 1.0, 1.0]);
    // Helix: pitch·t/(2π) along Z.
    let helix = curve3_from_json(space_cases()[9].clone(), "").unwrap();
    assert!((helix.point(&(2.0 * PI))[2] - 2.0).abs() < 1e-15);
    assert_eq!(helix.domain(), (0.0, 12.5));
    // NURBS: the given sub-domain inside [knots[p], knots[n]].
    let nurbs = curve3_from_json(space_cases()[12].clone(), "").unwrap();
    assert_eq!(nurbs.domain(), (0.1, 0.9));
    let direct = NurbsCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [2.0, 0.0, 1.0],
            [3.0, 1.0, 1.0],
        ],
        Some(vec![1.0, 2.0, 1.0, 0.5]),
        Some((0.1, 0.9)),
    )
    .unwrap();
    assert_eq!(nurbs, AnyCurve3::Nurbs(direct));
    // conic2 builds the implicit conic; the others parametric plane curves.
    let conic = parse_curve2(plane_cases()[7].clone(), "").unwrap();
    assert!(matches!(conic, Curve2Spec::Conic(_)));
    assert!(matches!(conic.build().unwrap(), PlaneShape::Conic(_)));
    match parse_curve2(plane_cases()[2].clone(), "")
        .unwrap()
        .build()
        .unwrap()
    {
        PlaneShape::Curve(c) => assert_eq!(c.point(&0.0f64), [1.1, 2.0]),
        other => panic!("{other:?}"),
    }
}

proptest! {
    /// Any finite doubles survive spec → JSON text → spec bit for bit.
    #[test]
    fn random_doubles_round_trip(bits in proptest::collection::vec(any::<u64>(), 9), w in 1e-300f64..1e300) {
        let v: Vec<f64> = bits.iter().map(|&b| f64::from_bits(b)).map(|x| if x.is_finite() { x } else { 0.5 }).collect();
        let case = json!({"type": "bezier", "points": [[v[0], v[1], v[2]], [v[3], v[4], v[5]], [v[6], v[7], v[8]]],
                          "weights": [w, 1.0, w]});
        let spec = parse_curve3(case, "x").unwrap();
        let text = serde_json::to_string(&spec.to_json()).unwrap();
        let back = parse_curve3(serde_json::from_str(&text).unwrap(), "x").unwrap();
        prop_assert_eq!(format!("{spec:?}"), format!("{back:?}"));
    }
}
