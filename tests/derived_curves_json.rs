//! The derived curves of the case format (`offset_curve(2)`, `composite_curve(2)`,
//! `extended_curve(2)`) end to end through JSON, against truths in closed form at 1024
//! bits (tests/truth_support): every reported box holds exactly one truth and every
//! truth lies in exactly one box. Families: `line2` ∩ the offset of a `circle2` (a
//! circle of radius `r − a`), `plane` ∩ a composite of a segment and a quadratic
//! Bézier (every third case through the joint exactly: reported once), projections of
//! a point onto the offset circle (both feet, and the nearest); then the JSON round
//! trip and the malformed-input family (each field its typed error).

mod truth_support;

use geocert::io::shapes::{parse_curve2, parse_curve3};
use geocert::num::rng::Rng;
use rug::Float;
use serde_json::{json, Value};
use truth_support::*;

fn dyadic(g: &mut Rng, lo: f64, hi: f64, bits: i32) -> f64 {
    let s = 2f64.powi(bits);
    g.int((lo * s).ceil() as i64, (hi * s).floor() as i64) as f64 / s
}

fn offset_circle(c: [f64; 2], r: f64, a: f64) -> String {
    format!(
        r#"{{"type":"offset_curve2","base":{{"type":"circle2","center":{},"radius":{}}},"distance":{}}}"#,
        nums(&c),
        num(r),
        num(a)
    )
}

/// A truth near the circle's seam `t = 0` (the point `c + (ρ, 0)`): tested elsewhere.
fn near_seam(p: &[Float], c: [f64; 2], rho: f64) -> bool {
    let dy = Float::with_val(BITS, &p[1] - c[1]).abs();
    dy < rho * 1e-6 && p[0] > c[0]
}

fn judge(r: &geocert::io::CaseResult, truths: &[Vec<Float>], case: &str) {
    assert!(r.error.is_none(), "{case}: {:?}", r.error);
    if let Err(e) = one_to_one(&point_boxes(r), truths) {
        panic!("{case}: {e}; status {}", r.status);
    }
}

#[test]
fn line_meets_an_offset_circle() {
    let mut g = Rng::new(1611);
    let mut done = 0;
    for i in 0..cases(40) {
        let c = [dyadic(&mut g, -2.0, 2.0, 3), dyadic(&mut g, -2.0, 2.0, 3)];
        let r = dyadic(&mut g, 1.0, 3.0, 4);
        let a = dyadic(&mut g, -1.0, 0.75, 4);
        let rho = r - a; // exact: dyadic
        let o = [0, 1].map(|k| c[k] + dyadic(&mut g, -rho / 3.0, rho / 3.0, 5));
        let d = [dyadic(&mut g, -1.0, 1.0, 3), dyadic(&mut g, -1.0, 1.0, 3)];
        if d == [0.0, 0.0] {
            continue;
        }
        // |o + s d − c|² = ρ²
        let (ox, oy) = (fl(o[0]) - c[0], fl(o[1]) - c[1]);
        let aa: Float = fl(d[0] * d[0]) + d[1] * d[1];
        let bb: Float = (ox.clone() * d[0] + oy.clone() * d[1]) * 2;
        let cc: Float = ox.clone().square() + oy.clone().square() - rho * rho;
        let four_ac: Float = aa.clone() * &cc * 4u32;
        let disc: Float = bb.clone().square() - four_ac;
        let disc = disc.sqrt();
        let truths: Vec<Vec<Float>> = [-1, 1]
            .iter()
            .map(|&sg| {
                let s: Float = (-bb.clone() + disc.clone() * sg) / (aa.clone() * 2);
                vec![s.clone() * d[0] + o[0], s * d[1] + o[1]]
            })
            .collect();
        if truths.iter().any(|t| near_seam(t, c, rho)) {
            continue;
        }
        let reach = 8.0 * rho / d[0].abs().max(d[1].abs());
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{{"type":"line2","origin":{},"dir":{},"range":{}}}]}}"#,
            offset_circle(c, r, a),
            nums(&o),
            nums(&d),
            nums(&[-reach, reach])
        );
        judge(&solve(&case), &truths, &case);
        done += 1;
    }
    assert!(done >= cases(40) / 2, "{done} cases ran");
}

#[test]
fn plane_meets_a_composite_curve() {
    let mut g = Rng::new(1612);
    let mut joints = 0;
    for i in 0..cases(45) {
        let mut p = || [0; 3].map(|_| dyadic(&mut g, -1.0, 1.0, 3));
        let (a, b, p1, p2) = (p(), p(), p(), p());
        let through_joint = i % 3 == 0;
        let h = if through_joint {
            b[2]
        } else {
            dyadic(&mut g, -1.0, 1.0, 4)
        };
        // segment a → b: z = a_z + t (b_z − a_z)
        let mut truths: Vec<Vec<Float>> = Vec::new();
        let mut skip = false;
        let dz = b[2] - a[2];
        if dz != 0.0 {
            let t: Float = Float::with_val(BITS, fl(h) - a[2]) / dz;
            let edge: Float = Float::with_val(BITS, &t - 1u32);
            if through_joint && t == 1 {
                // the joint: counted once, with the Bézier's u = 0
            } else if t.clone().abs() < 1e-6 || edge.clone().abs() < 1e-6 {
                skip = true;
            } else if t > 0 && t < 1 {
                truths.push((0..3).map(|k| t.clone() * (b[k] - a[k]) + a[k]).collect());
            }
        } else if a[2] == h {
            skip = true; // the segment lies in the plane
        }
        // Bézier b, p1, p2: (b − 2p1 + p2) u² + 2(p1 − b) u + (b − h) = 0 in z
        let qa: Float = fl(b[2]) - 2.0 * p1[2] + p2[2];
        let qb: Float = (fl(p1[2]) - b[2]) * 2;
        let qc: Float = fl(b[2]) - h;
        let four_ac: Float = qa.clone() * &qc * 4u32;
        let disc: Float = qb.clone().square() - four_ac;
        if qa.clone().abs() < 1e-3 || disc.clone().abs() < 1e-6 {
            continue; // nearly linear or tangent: not this family
        }
        if disc > 0 {
            for sg in [-1, 1] {
                let u: Float = (-qb.clone() + disc.clone().sqrt() * sg) / (qa.clone() * 2);
                let u = snap(&u);
                if u == 0 {
                    // the joint point b
                    truths.push(b.iter().map(|&x| fl(x)).collect());
                    joints += 1;
                } else if u.clone().abs() < 1e-6 || Float::with_val(BITS, &u - 1u32).abs() < 1e-6 {
                    skip = true;
                } else if u > 0 && u < 1 {
                    let w = [
                        (fl(1) - &u).square(),
                        (fl(1) - &u) * &u * 2,
                        u.clone().square(),
                    ];
                    truths.push(
                        (0..3)
                            .map(|k| {
                                w[0].clone() * b[k] + w[1].clone() * p1[k] + w[2].clone() * p2[k]
                            })
                            .collect(),
                    );
                }
            }
        }
        if skip {
            continue;
        }
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{{"type":"composite_curve","pieces":[{{"type":"segment","a":{},"b":{}}},{{"type":"bezier","points":[{},{},{}]}}]}},{{"type":"plane","normal":[0,0,1],"d":{}}}]}}"#,
            nums(&a),
            nums(&b),
            nums(&b),
            nums(&p1),
            nums(&p2),
            num(-h)
        );
        // The truths' z is `h` exactly, up to the rounding of the 1024-bit computation:
        // snapped, so that a box tight in z (the plane's own enclosure) is judged right.
        judge(&solve(&case), &snap_all(truths), &case);
    }
    assert!(joints > 3, "{joints} roots exactly at a joint");
}

#[test]
fn projection_onto_an_offset_circle() {
    let mut g = Rng::new(1613);
    for i in 0..cases(40) {
        let c = [dyadic(&mut g, -2.0, 2.0, 3), dyadic(&mut g, -2.0, 2.0, 3)];
        let r = dyadic(&mut g, 1.0, 3.0, 4);
        let a = dyadic(&mut g, -1.0, 0.75, 4);
        let rho = r - a;
        let p = [0, 1].map(|k| c[k] + dyadic(&mut g, -3.0 * rho, 3.0 * rho, 4));
        let (dx, dy) = (fl(p[0]) - c[0], fl(p[1]) - c[1]);
        let n: Float = (dx.clone().square() + dy.clone().square()).sqrt();
        if n < rho * 1e-2 {
            continue; // the centre: every point a foot
        }
        let feet: Vec<Vec<Float>> = [1, -1]
            .iter()
            .map(|&s| {
                let k: Float = Float::with_val(BITS, &n / rho) * s;
                vec![dx.clone() / &k + c[0], dy.clone() / &k + c[1]]
            })
            .collect();
        if feet.iter().any(|f| near_seam(f, c, rho)) {
            continue;
        }
        let curve = offset_circle(c, r, a);
        let case = format!(
            r#"{{"id":{i},"op":"project","point":{},"onto":{curve}}}"#,
            nums(&p)
        );
        judge(&solve(&case), &feet, &case);
        let case = format!(
            r#"{{"id":{i},"op":"project","nearest":true,"point":{},"onto":{curve}}}"#,
            nums(&p)
        );
        judge(&solve(&case), &feet[..1], &case);
    }
}

#[test]
fn derived_curves_round_trip_through_json() {
    let circle2 = json!({"type": "circle2", "center": [1, 2], "radius": 0.5});
    let seg = |a: [f64; 3], b: [f64; 3]| json!({"type": "segment", "a": a, "b": b});
    let space = [
        json!({"type": "offset_curve", "base": {"type": "circle", "center": [0, 0, 0], "radius": 2, "axis": [0, 0, 1]}, "offset": [0, 0.5, 0.25]}),
        json!({"type": "composite_curve", "pieces": [seg([0.0; 3], [1.0, 0.0, 0.0]), {"type": "bezier", "points": [[1, 0, 0], [2, 1, 0], [3, 0, 1]]}]}),
        json!({"type": "extended_curve", "base": seg([0.0; 3], [1.0, 1.0, 0.0]), "extend": [0.5, 2]}),
        json!({"type": "offset_curve", "base": {"type": "composite_curve", "pieces": [{"type": "bezier", "points": [[0, 0, 0], [1, 1, 0], [2, 0, 0]]}]}, "offset": [0, 0, 1]}),
    ];
    for v in space {
        let spec = parse_curve3(v.clone(), "objects[0]").expect("valid");
        let back = spec.to_json();
        let again = parse_curve3(back.clone(), "objects[0]").expect("valid");
        assert_eq!(spec, again, "{v}");
        assert_eq!(back, parse_curve3(v.clone(), "").unwrap().to_json());
        spec.build().expect("builds");
    }
    let plane = [
        json!({"type": "offset_curve2", "base": circle2, "distance": -0.25}),
        json!({"type": "composite_curve2", "pieces": [{"type": "segment2", "a": [0, 0], "b": [1, 0]}, {"type": "segment2", "a": [1, 0], "b": [1, 1]}]}),
        json!({"type": "extended_curve2", "base": {"type": "bezier2", "points": [[0, 0], [1, 1], [2, 0]]}, "extend": [0, 1]}),
    ];
    for v in plane {
        let spec = parse_curve2(v.clone(), "onto").expect("valid");
        let again = parse_curve2(spec.to_json(), "onto").expect("valid");
        assert_eq!(spec, again, "{v}");
    }
}

/// The kind and field of the error that reading `v` gives.
fn error_of(v: Value, dim: u8) -> (String, String) {
    let e = if dim == 3 {
        parse_curve3(v, "objects[0]").map(|_| ()).unwrap_err()
    } else {
        parse_curve2(v, "objects[0]").map(|_| ()).unwrap_err()
    };
    (e.kind().to_string(), e.field().to_string())
}

#[test]
fn malformed_derived_curves_name_the_field() {
    let circle = json!({"type": "circle", "center": [0, 0, 0], "radius": 1, "axis": [0, 0, 1]});
    let circle2 = json!({"type": "circle2", "center": [0, 0], "radius": 1});
    let seg = |a: [f64; 3], b: [f64; 3]| json!({"type": "segment", "a": a, "b": b});
    let bad: Vec<(Value, u8, &str, &str)> = vec![
        (
            json!({"type": "offset_curve", "offset": [0, 0, 1]}),
            3,
            "format",
            "objects[0].base",
        ),
        (
            json!({"type": "offset_curve", "base": circle}),
            3,
            "format",
            "objects[0].offset",
        ),
        (
            json!({"type": "offset_curve", "base": circle, "offset": [0, "x", 1]}),
            3,
            "format",
            "objects[0].offset[1]",
        ),
        (
            json!({"type": "offset_curve", "base": circle, "offset": [0, 1, 1], "distance": 1}),
            3,
            "format",
            "objects[0].distance",
        ),
        (
            json!({"type": "offset_curve", "base": circle2, "offset": [0, 0, 1]}),
            3,
            "unsupported",
            "objects[0].base.type",
        ),
        (
            json!({"type": "offset_curve", "base": {"type": "circle", "center": [0, 0, 0], "radius": -1, "axis": [0, 0, 1]}, "offset": [0, 0, 1]}),
            3,
            "invalid_value",
            "objects[0].base.radius",
        ),
        (
            json!({"type": "offset_curve2", "base": circle2}),
            2,
            "format",
            "objects[0].distance",
        ),
        (
            json!({"type": "offset_curve2", "distance": 1}),
            2,
            "format",
            "objects[0].base",
        ),
        (
            json!({"type": "offset_curve2", "base": circle, "distance": 1}),
            2,
            "unsupported",
            "objects[0].base.type",
        ),
        (
            json!({"type": "offset_curve2", "base": {"type": "conic2", "coeffs": [1, 0, 1, 0, 0, -1]}, "distance": 1}),
            2,
            "unsupported",
            "objects[0].base.type",
        ),
        (
            json!({"type": "offset_curve2", "base": {"type": "polyline2", "points": [[0, 0], [1, 0], [1, 1]]}, "distance": 1}),
            2,
            "unsupported",
            "objects[0].base",
        ),
        (
            json!({"type": "composite_curve"}),
            3,
            "format",
            "objects[0].pieces",
        ),
        (
            json!({"type": "composite_curve", "pieces": []}),
            3,
            "invalid_value",
            "objects[0].pieces",
        ),
        (
            json!({"type": "composite_curve", "pieces": [seg([0.0; 3], [1.0, 0.0, 0.0]), seg([1.0, 0.0, 1e-300], [2.0, 0.0, 0.0])]}),
            3,
            "invalid_value",
            "objects[0].pieces[0]",
        ),
        (
            json!({"type": "composite_curve", "pieces": [seg([0.0; 3], [1.0, 0.0, 0.0]), {"type": "segment", "a": [1, 0, 0]}]}),
            3,
            "format",
            "objects[0].pieces[1]",
        ),
        (
            json!({"type": "composite_curve", "pieces": [seg([0.0; 3], [1.0, 0.0, 0.0]), {"type": "line", "origin": [1, 0, 0], "dir": [1, 0, 0]}]}),
            3,
            "unsupported",
            "objects[0].pieces[1]",
        ),
        (
            json!({"type": "composite_curve2", "pieces": [{"type": "segment2", "a": [0, 0], "b": [1, 0]}, {"type": "segment2", "a": [1, 0], "b": [1, 0]}]}),
            2,
            "invalid_value",
            "objects[0].pieces[1].b",
        ),
        (
            json!({"type": "extended_curve", "base": seg([0.0; 3], [1.0, 0.0, 0.0])}),
            3,
            "format",
            "objects[0].extend",
        ),
        (
            json!({"type": "extended_curve", "base": seg([0.0; 3], [1.0, 0.0, 0.0]), "extend": [1, -1]}),
            3,
            "invalid_value",
            "objects[0].extend[1]",
        ),
        (
            json!({"type": "extended_curve", "base": circle, "extend": [1, 1]}),
            3,
            "unsupported",
            "objects[0].base",
        ),
        (
            json!({"type": "extended_curve2", "extend": [1, 1]}),
            2,
            "format",
            "objects[0].base",
        ),
    ];
    for (v, dim, kind, field) in bad {
        assert_eq!(
            error_of(v.clone(), dim),
            (kind.to_string(), field.to_string()),
            "{v}"
        );
    }
    // a number too large for a double is refused, naming the field
    let text = r#"{"type": "offset_curve2", "base": {"type": "circle2", "center": [0, 0], "radius": 1}, "distance": 1e999}"#;
    let v: Result<Value, _> = serde_json::from_str(text);
    if let Ok(v) = v {
        let (_, field) = error_of(v, 2);
        assert_eq!(field, "objects[0].distance");
    }
}
