//! Numbers beyond the double range (issue 14 item 7; docs/FORMAT.md "Numbers beyond the
//! double range"): exact answers whose coordinates, parameters or distances exceed
//! `f64::MAX` never lose a number. Families of ranged lines, segments, 2D lines and
//! three planes meeting beyond the range, and projections at distances beyond it, each
//! with its exact truth computed here in rationals:
//!
//! - no `null` stands for a number anywhere in the record, and the record fits
//!   docs/result.schema.json;
//! - every number is the exact value correctly rounded: a finite double, or `"inf"` /
//!   `"-inf"` exactly when the value is beyond the range, with its sign;
//! - the point then carries `exact`, whose rationals are the exact truth (round trip),
//!   even without `options.exact`; the status is `exact` and the answer complete;
//! - each box holds the truth (an `"inf"` end is unbounded);
//! - the record fed back to `geocert verify` as the claim, at tolerance 0, is confirmed.
//!
//! Cases per family: `GEOCERT_VERIFY_CASES` (default 60).

use boon::{Compiler, SchemaIndex, Schemas};
use geocert::io::{read_cases, solve_case, verify_case};
use geocert::num::round::round_rational;
use geocert::robust::rng::Rng;
use rug::Rational;
use serde_json::{json, Value};

fn schema() -> (Schemas, SchemaIndex) {
    let text = std::fs::read_to_string("docs/result.schema.json").expect("the schema file");
    let value: Value = serde_json::from_str(&text).expect("JSON");
    let mut schemas = Schemas::new();
    let mut compiler = Compiler::new();
    let url = "file:///geocert/docs/result.schema.json";
    compiler.add_resource(url, value).expect("adds the schema");
    let index = compiler.compile(url, &mut schemas).expect("compiles");
    (schemas, index)
}

fn run(case: &Value, verify: bool) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    let r = if verify {
        verify_case(read)
    } else {
        solve_case(read)
    };
    serde_json::from_str(&r.to_json_line()).unwrap()
}

fn count() -> usize {
    std::env::var("GEOCERT_VERIFY_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(60)
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap()
}

/// No `null` stands for a number: the only nulls allowed are an absent `id` and the
/// `null` of a line's `params` for an object without parameters.
fn assert_no_null(v: &Value, path: &str) {
    match v {
        Value::Null => {
            let allowed = path == ".id" || path.starts_with(".line.params[");
            assert!(allowed, "null at {path}");
        }
        Value::Array(a) => a
            .iter()
            .enumerate()
            .for_each(|(i, x)| assert_no_null(x, &format!("{path}[{i}]"))),
        Value::Object(o) => o
            .iter()
            .for_each(|(k, x)| assert_no_null(x, &format!("{path}.{k}"))),
        _ => {}
    }
}

/// A written number is the exact value `t` correctly rounded: the double nearest to
/// it, or `"inf"`/`"-inf"` beyond the range.
fn assert_rounded(written: &Value, t: &Rational, what: &str) {
    let r = round_rational(t).nearest;
    if r.is_finite() {
        assert_eq!(written.as_f64(), Some(r), "{what}: {written} for {}", r);
    } else {
        let text = if r > 0.0 { "inf" } else { "-inf" };
        assert_eq!(written, &json!(text), "{what}");
    }
}

/// A written bound as a comparable value (`None`: unbounded).
fn bound(v: &Value) -> Option<Rational> {
    match v {
        Value::String(s) => {
            assert!(s == "inf" || s == "-inf", "{s}");
            None
        }
        _ => Some(q(v.as_f64().expect("a number"))),
    }
}

fn assert_in_box(b: &Value, t: &Rational, what: &str) {
    let (lo, hi) = (bound(&b[0]), bound(&b[1]));
    if let Some(lo) = lo {
        assert!(lo <= *t, "{what}: {b}");
    } else {
        assert_eq!(b[0], "-inf", "{what}");
    }
    if let Some(hi) = hi {
        assert!(*t <= hi, "{what}: {b}");
    } else {
        assert_eq!(b[1], "inf", "{what}");
    }
}

/// All the checks of the module doc on one case whose single point is `truth` (with
/// the exact distance squared for projections).
fn check(
    case: &Value,
    truth: &[Rational],
    distance2: Option<&Rational>,
    schemas: &(Schemas, SchemaIndex),
) -> bool {
    let r = run(case, false);
    assert_no_null(&r, "");
    if let Err(e) = schemas.0.validate(&r, schemas.1) {
        panic!("violates the schema: {e}\n{r}");
    }
    assert_eq!(r["status"], "exact", "{case}: {r}");
    assert_eq!(r["complete"], true);
    let p = &r["points"][0];
    let distance_beyond = distance2.is_some_and(|d| {
        let d = rug::Float::with_val(4096, d).sqrt();
        !d.to_f64().is_finite()
    });
    let beyond = truth.iter().any(|t| !round_rational(t).nearest.is_finite()) || distance_beyond;
    for (k, t) in truth.iter().enumerate() {
        assert_rounded(&p["xyz"][k], t, &format!("{case}: xyz[{k}]"));
        assert_in_box(&p["box"][k], t, &format!("{case}: box[{k}]"));
    }
    if beyond {
        let exact = p["exact"]["xyz"]
            .as_array()
            .expect("exact values beyond the range");
        for (k, t) in truth.iter().enumerate() {
            let back: Rational = exact[k].as_str().unwrap().parse().unwrap();
            assert_eq!(back, *t, "{case}: exact.xyz[{k}]");
        }
    } else {
        assert!(p.get("exact").is_none(), "exact only on request: {r}");
    }
    if let Some(d2) = distance2 {
        if distance_beyond {
            assert_eq!(p["distance"], "inf", "{r}");
            let back: Rational = p["exact"]["distance_squared"]
                .as_str()
                .unwrap()
                .parse()
                .unwrap();
            assert_eq!(back, *d2);
        }
    }
    // Fed back as the claim: confirmed — at tolerance 0 where the exact values are
    // carried, else within the rounding of the coordinates.
    let mut claim = r.clone();
    let rounding = truth
        .iter()
        .map(|t| round_rational(t).nearest.abs())
        .fold(0.0, f64::max)
        * f64::EPSILON;
    claim["tolerance"] = json!(if beyond { 0.0 } else { rounding });
    let mut v = case.clone();
    v["claim"] = claim;
    let checked = run(&v, true);
    assert_no_null(&checked, "");
    // claims[0] is the record's `kind`.
    assert_eq!(checked["claims"][0]["item"], "kind");
    assert_eq!(checked["claims"][1]["verdict"], "confirmed", "{checked}");
    assert_eq!(checked["missed"], json!([]));
    beyond
}

/// A double of magnitude in `[2^1000, f64::MAX]`, random sign when `signed`.
fn huge(rng: &mut Rng, signed: bool) -> f64 {
    huge_from(rng, 1000, signed)
}

/// A double of magnitude in `[2^low, f64::MAX]`.
fn huge_from(rng: &mut Rng, low: i64, signed: bool) -> f64 {
    let m = 1.0 + (rng.unit() + 1.0) / 2.0 * 0.999_999;
    let x = m * 2f64.powi(rng.int(low, 1023) as i32);
    if signed && rng.coin() {
        -x
    } else {
        x
    }
}

#[test]
fn ranged_lines_meeting_planes_beyond_the_range() {
    let schemas = schema();
    let mut rng = Rng::new(14);
    let mut beyond = 0;
    for _ in 0..count() {
        // A line along a direction with components up to 2, over [0, 1.79e308] or a
        // random huge range; a plane x_k = X with X huge.
        // Half the cases steep in the other coordinates (|dir_j| ∈ [4, 8]), so that they
        // leave the range before the plane is reached.
        let steep = rng.coin();
        let dir: Vec<f64> = (0..3)
            .map(|_| {
                if steep {
                    (4.0 + 2.0 * (rng.unit() + 1.0)).copysign(rng.unit())
                } else {
                    rng.unit() * 2.0
                }
            })
            .collect();
        let k = rng.below(3);
        let mut dir = dir;
        dir[k] = if steep { 1.0 } else { dir[k].abs().max(0.25) };
        let origin: Vec<f64> = (0..3).map(|_| rng.generic()).collect();
        let x = huge_from(&mut rng, if steep { 1022 } else { 1000 }, false);
        let range = if rng.coin() {
            [0.0, 1.79e308]
        } else {
            [0.0, f64::MAX]
        };
        let t = (q(x) - q(origin[k])) / q(dir[k]);
        if t > q(range[1]) {
            continue;
        }
        let truth: Vec<Rational> = (0..3)
            .map(|i| q(origin[i]) + t.clone() * q(dir[i]))
            .collect();
        let mut normal = [0.0; 3];
        normal[k] = 1.0;
        let case = json!({"op": "intersect", "objects": [
            {"type": "line", "origin": origin, "dir": dir, "range": range},
            {"type": "plane", "normal": normal, "d": -x}]});
        beyond += check(&case, &truth, None, &schemas) as usize;
    }
    assert!(beyond >= count() / 4, "{beyond} cases beyond the range");
}

/// The case: `[0, 1.79e308]` along `(1, 2, 1)` against `x = 1.7e308`.
#[test]
fn the_reported_case_gives_every_number() {
    let case = json!({"op": "intersect", "objects": [
        {"type": "line", "origin": [0, 0, 0], "dir": [1, 2, 1], "range": [0, 1.79e308]},
        {"type": "plane", "normal": [1, 0, 0], "d": -1.7e308}]});
    let t = q(1.7e308);
    let truth = [t.clone(), t.clone() * 2u32, t];
    assert!(check(&case, &truth, None, &schema()));
    let r = run(&case, false);
    assert_eq!(r["points"][0]["xyz"][1], "inf");
    assert_eq!(r["points"][0]["box"][1], json!([f64::MAX, "inf"]));
}

#[test]
fn segments_spanning_the_range_meet_planes_exactly() {
    let schemas = schema();
    let mut rng = Rng::new(15);
    for _ in 0..count() {
        // b − a overflows the doubles; the crossing is inside the segment.
        let a: Vec<f64> = (0..3).map(|_| -huge(&mut rng, false)).collect();
        let b: Vec<f64> = (0..3).map(|_| huge(&mut rng, false)).collect();
        let k = rng.below(3);
        let x = rng.generic() * 1e300;
        let t = (q(x) - q(a[k])) / (q(b[k]) - q(a[k]));
        let truth: Vec<Rational> = (0..3)
            .map(|i| q(a[i]) + t.clone() * (q(b[i]) - q(a[i])))
            .collect();
        let mut normal = [0.0; 3];
        normal[k] = 1.0;
        let case = json!({"op": "intersect", "objects": [
            {"type": "segment", "a": a, "b": b},
            {"type": "plane", "normal": normal, "d": -x}]});
        check(&case, &truth, None, &schemas);
    }
}

#[test]
fn three_planes_meeting_beyond_the_range() {
    let schemas = schema();
    let mut rng = Rng::new(16);
    let mut beyond = 0;
    for _ in 0..count() {
        // x = X, x − δ·y = 0, z = Z in a random order of the axes: y = X/δ.
        let x = huge_from(&mut rng, 1018, true);
        let delta = (rng.unit() + 1.0) / 2.0 * 0.9 + 0.05;
        let z = rng.generic();
        let perm = [[0, 1, 2], [1, 2, 0], [2, 0, 1], [0, 2, 1]][rng.below(4)];
        let place = |v: [f64; 3]| -> Vec<f64> {
            let mut out = vec![0.0; 3];
            for i in 0..3 {
                out[perm[i]] = v[i];
            }
            out
        };
        let truth3 = [q(x), q(x) / q(delta), q(z)];
        let mut truth = vec![Rational::new(); 3];
        for i in 0..3 {
            truth[perm[i]] = truth3[i].clone();
        }
        let case = json!({"op": "intersect", "objects": [
            {"type": "plane", "normal": place([1.0, 0.0, 0.0]), "d": -x},
            {"type": "plane", "normal": place([1.0, -delta, 0.0]), "d": 0},
            {"type": "plane", "normal": place([0.0, 0.0, 1.0]), "d": -z}]});
        beyond += check(&case, &truth, None, &schemas) as usize;
    }
    assert!(beyond >= count() / 4, "{beyond} cases beyond the range");
}

#[test]
fn lines2_meeting_beyond_the_range() {
    let schemas = schema();
    let mut rng = Rng::new(17);
    let mut beyond = 0;
    for _ in 0..count() {
        // y = 0 and the line through (X, 0)… moved: o + t·d with a shallow slope, meeting
        // y = 0 at x = o_x − o_y·d_x/d_y, beyond the range for small slopes.
        let o = [rng.generic(), 1.0 + (rng.unit() + 1.0)];
        let d = [huge_from(&mut rng, 1020, true), -1.0];
        let x = q(o[0]) + q(o[1]) * q(d[0]);
        let case = json!({"op": "intersect", "objects": [
            {"type": "line2", "origin": o, "dir": d},
            {"type": "line2", "origin": [0, 0], "dir": [1, 0]}]});
        beyond += check(&case, &[x, Rational::new()], None, &schemas) as usize;
    }
    assert!(beyond >= count() / 8, "{beyond} cases beyond the range");
}

#[test]
fn projections_at_distances_beyond_the_range() {
    let schemas = schema();
    let mut rng = Rng::new(18);
    for _ in 0..count() {
        // A point far off the plane n·x = 0 with n = (1, 1, 0): the distance is
        // |p·n|/√2, beyond the range when p₀ + p₁ is; the foot is p − (p·n/2)·n.
        let p = [huge(&mut rng, false), huge(&mut rng, false), rng.generic()];
        let s = q(p[0]) + q(p[1]);
        let half = s.clone() / 2u32;
        let truth = [q(p[0]) - half.clone(), q(p[1]) - half, q(p[2])];
        let d2 = s.clone() * s / 2u32;
        let case = json!({"op": "project", "point": p,
                          "onto": {"type": "plane", "normal": [1, 1, 0], "d": 0}});
        check(&case, &truth, Some(&d2), &schemas);
    }
}
