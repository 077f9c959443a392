//! docs/result.schema.json describes every record geocert writes: each line of
//! tests/data/cases.expected.jsonl (the answers of `geocert solve` on the ~1300 cases of
//! the corpus, pinned by tests/front_door.rs) and each line `geocert verify` writes for
//! the corpus cases that carry a `claim` validate against it, and records mutated to
//! break one rule of docs/FORMAT.md are rejected — so the schema is neither looser nor
//! stricter than the output.

use std::f64::consts::FRAC_PI_2;
use std::io::Write;
use std::process::{Command, Stdio};

use boon::{Compiler, SchemaIndex, Schemas};
use serde_json::{json, Value};

const SCHEMA: &str = "docs/result.schema.json";
const CASES: &str = "tests/data/cases.jsonl";
const EXPECTED: &str = "tests/data/cases.expected.jsonl";

fn schema() -> (Schemas, SchemaIndex) {
    let text = std::fs::read_to_string(SCHEMA).expect("the schema file");
    let value: Value = serde_json::from_str(&text).expect("the schema is JSON");
    let mut schemas = Schemas::new();
    let mut compiler = Compiler::new();
    let url = "file:///geocert/docs/result.schema.json";
    compiler.add_resource(url, value).expect("adds the schema");
    let index = compiler
        .compile(url, &mut schemas)
        .unwrap_or_else(|e| panic!("{SCHEMA} does not compile: {e:#}"));
    (schemas, index)
}

/// Every line validates; the message names the first failing line and why.
fn assert_all_valid(what: &str, lines: &[String]) {
    let (schemas, index) = schema();
    for (n, line) in lines.iter().enumerate() {
        let record: Value = serde_json::from_str(line)
            .unwrap_or_else(|e| panic!("{what} line {}: not JSON: {e}", n + 1));
        if let Err(e) = schemas.validate(&record, index) {
            panic!("{what} line {} violates {SCHEMA}:\n{e}\n{line}", n + 1);
        }
    }
}

fn lines(path: &str) -> Vec<String> {
    std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("{path}: {e}"))
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(String::from)
        .collect()
}

#[test]
fn every_expected_answer_fits_the_schema() {
    let expected = lines(EXPECTED);
    assert!(expected.len() > 1000, "the corpus covers the suite");
    assert_all_valid(EXPECTED, &expected);
}

#[test]
fn every_verify_record_of_the_corpus_claims_fits_the_schema() {
    let claims: Vec<String> = lines(CASES)
        .into_iter()
        .filter(|l| serde_json::from_str::<Value>(l).is_ok_and(|v| v.get("claim").is_some()))
        .collect();
    assert!(
        claims.len() > 100,
        "the corpus has claims: {}",
        claims.len()
    );
    let mut child = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args(["verify", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("runs geocert verify");
    let input = claims.join("\n") + "\n";
    let mut stdin = child.stdin.take().expect("stdin");
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let out = child.wait_with_output().expect("geocert verify finishes");
    writer
        .join()
        .expect("writer thread")
        .expect("writes the cases");
    let records: Vec<String> = String::from_utf8(out.stdout)
        .expect("UTF-8")
        .lines()
        .map(String::from)
        .collect();
    assert_eq!(records.len(), claims.len(), "one record per case");
    assert_all_valid("geocert verify", &records);
    // The verdicts are there: every answer record carries `claims` and `missed`.
    let answered = records
        .iter()
        .map(|l| serde_json::from_str::<Value>(l).expect("JSON"))
        .filter(|r| r["status"] != "error")
        .inspect(|r| assert!(r["claims"].is_array() && r["missed"].is_array(), "{r}"))
        .count();
    assert!(answered > 100, "{answered} answered");
}

/// The first expected record satisfying `pred`.
fn sample(expected: &[Value], pred: impl Fn(&Value) -> bool) -> Value {
    expected
        .iter()
        .find(|r| pred(r))
        .cloned()
        .expect("the corpus has such a record")
}

fn mutated(record: &Value, change: impl FnOnce(&mut Value)) -> Value {
    let mut r = record.clone();
    change(&mut r);
    r
}

#[test]
fn records_breaking_a_rule_are_rejected() {
    let (schemas, index) = schema();
    let expected: Vec<Value> = lines(EXPECTED)
        .iter()
        .map(|l| serde_json::from_str(l).expect("JSON"))
        .collect();
    let points = sample(&expected, |r| r["kind"] == "points");
    let empty = sample(&expected, |r| r["kind"] == "empty");
    let error = sample(&expected, |r| r["status"] == "error");
    let singular = sample(&expected, |r| r["status"] == "verified_singular");
    let undecided = sample(&expected, |r| r["status"] == "undecided");
    let line = sample(&expected, |r| r["kind"] == "line");
    for r in [&points, &empty, &error, &singular, &undecided, &line] {
        assert!(
            schemas.validate(r, index).is_ok(),
            "the originals are valid: {r}"
        );
    }
    let p0 = |r: &mut Value| -> Value { r["points"][0].take() };
    let broken: Vec<(&str, Value)> = vec![
        (
            "no format",
            mutated(&points, |r| {
                drop(r.as_object_mut().unwrap().remove("format"))
            }),
        ),
        ("format 2", mutated(&points, |r| r["format"] = json!(2))),
        (
            "an unknown field",
            mutated(&points, |r| r["colour"] = json!("red")),
        ),
        (
            "an unknown status",
            mutated(&points, |r| r["status"] = json!("proven")),
        ),
        (
            "an unknown kind",
            mutated(&points, |r| r["kind"] = json!("blob")),
        ),
        (
            "arithmetic float",
            mutated(&points, |r| r["arithmetic"] = json!("float")),
        ),
        ("negative bits", mutated(&points, |r| r["bits"] = json!(-1))),
        (
            "no complete",
            mutated(&points, |r| {
                drop(r.as_object_mut().unwrap().remove("complete"))
            }),
        ),
        (
            "kind points, no point",
            mutated(&points, |r| r["points"] = json!([])),
        ),
        ("kind empty with a point", {
            let mut r = empty.clone();
            r["points"] = json!([p0(&mut points.clone())]);
            r
        }),
        (
            "kind empty without points",
            mutated(&empty, |r| {
                drop(r.as_object_mut().unwrap().remove("points"))
            }),
        ),
        (
            "kind line with points",
            mutated(&points, |r| r["kind"] = json!("line")),
        ),
        (
            "kind line without line",
            mutated(&line, |r| drop(r.as_object_mut().unwrap().remove("line"))),
        ),
        (
            "a point without box",
            mutated(&points, |r| {
                drop(r["points"][0].as_object_mut().unwrap().remove("box"))
            }),
        ),
        (
            "a null coordinate (a number must never be lost)",
            mutated(&points, |r| r["points"][0]["xyz"][0] = Value::Null),
        ),
        (
            "a null box bound",
            mutated(&points, |r| r["points"][0]["box"][0][1] = Value::Null),
        ),
        (
            "a coordinate as a string other than \"inf\"",
            mutated(&points, |r| r["points"][0]["xyz"][0] = json!("1e400")),
        ),
        (
            "a point with an unknown field",
            mutated(&points, |r| r["points"][0]["weight"] = json!(1)),
        ),
        (
            "a bound with one end",
            mutated(&points, |r| r["points"][0]["box"][0] = json!([0.5])),
        ),
        (
            "multiplicity 0",
            mutated(&points, |r| r["points"][0]["multiplicity"] = json!(0)),
        ),
        (
            "an exact value that is not a rational",
            mutated(&points, |r| {
                r["points"][0]["exact"] = json!({"xyz": ["1/3", "0.5", "0"]})
            }),
        ),
        (
            "verified_singular without perturbation",
            mutated(&singular, |r| {
                drop(r.as_object_mut().unwrap().remove("perturbation"))
            }),
        ),
        (
            "undecided without reason",
            mutated(&undecided, |r| {
                drop(r.as_object_mut().unwrap().remove("reason"))
            }),
        ),
        (
            "an error record with a kind",
            mutated(&error, |r| r["kind"] = json!("points")),
        ),
        (
            "an unknown error kind",
            mutated(&error, |r| r["error"]["kind"] = json!("oops")),
        ),
        (
            "an error without field",
            mutated(&error, |r| {
                drop(r["error"].as_object_mut().unwrap().remove("field"))
            }),
        ),
        (
            "claims without missed",
            mutated(
                &points,
                |r| {
                    r["claims"] =
                        json!([{"item": "points[0]", "verdict": "confirmed", "status": "exact"}])
                },
            ),
        ),
        (
            "a refutation resting on nothing",
            mutated(&points, |r| {
                r["claims"] =
                    json!([{"item": "points[0]", "verdict": "refuted", "status": "undecided"}]);
                r["missed"] = json!([]);
            }),
        ),
    ];
    for (what, record) in &broken {
        assert!(
            schemas.validate(record, index).is_err(),
            "{SCHEMA} accepts a record with {what}: {record}"
        );
    }
}

#[test]
fn curve_records_that_are_coming_fit_the_schema() {
    let (schemas, index) = schema();
    let curves = json!({
        "id": "ss", "format": 1, "status": "verified", "kind": "curves", "complete": true,
        "bits": 53, "arithmetic": "interval",
        "curves": [{
            "closed": true,
            "points": [{"xyz": [1.0, 0.0, 0.0], "params": [[0.0, 0.0], [0.0, FRAC_PI_2]]},
                       {"xyz": [0.0, 1.0, 0.0], "params": [[FRAC_PI_2, 0.0], [FRAC_PI_2, FRAC_PI_2]]}],
            "singular_points": [{"xyz": [0.0, 0.0, 1.0], "box": [[-1e-15, 1e-15], [-1e-15, 1e-15], [1.0, 1.0]]}]
        }]
    });
    assert!(schemas.validate(&curves, index).is_ok());
    let without_closed = mutated(&curves, |r| {
        drop(r["curves"][0].as_object_mut().unwrap().remove("closed"))
    });
    assert!(schemas.validate(&without_closed, index).is_err());
    let singular_without_box = mutated(&curves, |r| {
        drop(
            r["curves"][0]["singular_points"][0]
                .as_object_mut()
                .unwrap()
                .remove("box"),
        )
    });
    assert!(schemas.validate(&singular_without_box, index).is_err());
    let no_curves = mutated(&curves, |r| {
        drop(r.as_object_mut().unwrap().remove("curves"))
    });
    assert!(schemas.validate(&no_curves, index).is_err());
}

#[test]
fn section_records_fit_the_schema() {
    let (schemas, index) = schema();
    let cases = [
        r#"{"op": "section", "objects": [{"type": "ellipsoid", "center": [0,0,0], "a": 3, "b": 3, "c": 5}, {"type": "plane", "points": [[16,0,0], [1,5,0], [0,0,1]]}]}"#,
        r#"{"op": "section", "objects": [{"type": "cylinder", "origin": [0,0,0], "radius": 1, "axis": [0,0,1], "height": [0,1]}, {"type": "plane", "normal": [1,0,0], "d": 0}]}"#,
        r#"{"op": "section", "objects": [{"type": "polyhedron", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "faces": [[0,2,1],[0,1,3],[0,3,2],[1,2,3]]}, {"type": "plane", "normal": [0,0,1], "d": "-1/2"}]}"#,
    ];
    for case in cases {
        let mut read = geocert::io::read_cases(case);
        let r = serde_json::to_value(geocert::io::solve_case(read.remove(0))).unwrap();
        assert_ne!(r["status"], "error", "{r}");
        assert!(schemas.validate(&r, index).is_ok(), "{r}");
    }
}

/// Records of kind `ray` (collinear rays, a ray in a plane, exact values on request)
/// fit, and a `ray` record without its `ray` field, or a `ray` field on another kind,
/// does not.
#[test]
fn ray_records_fit_the_schema() {
    let (schemas, index) = schema();
    let cases = [
        r#"{"op": "intersect", "objects": [{"type": "line", "origin": [0,0,0], "dir": [1,0,0], "range": [0, null]}, {"type": "line", "origin": [2,0,0], "dir": [3,0,0], "range": [null, null]}]}"#,
        r#"{"op": "intersect", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "line", "origin": [0,0,0], "dir": [1,2,0], "range": [null, "1/3"]}], "options": {"exact": true}}"#,
    ];
    for case in cases {
        let mut read = geocert::io::read_cases(case);
        let r = serde_json::to_value(geocert::io::solve_case(read.remove(0))).unwrap();
        assert_eq!(r["kind"], "ray", "{r}");
        assert!(schemas.validate(&r, index).is_ok(), "{r}");
        let bare = mutated(&r, |r| drop(r.as_object_mut().unwrap().remove("ray")));
        assert!(schemas.validate(&bare, index).is_err(), "{bare}");
        let other = mutated(&r, |r| r["kind"] = json!("segment"));
        assert!(schemas.validate(&other, index).is_err(), "{other}");
    }
}

#[test]
fn arc_records_fit_the_schema() {
    let (schemas, index) = schema();
    let cases = [
        // a half of the other's de Casteljau split, in the plane and in space
        r#"{"op": "intersect", "objects": [{"type": "bezier2", "points": [[0,0],[2,4],[4,0]]}, {"type": "bezier2", "points": [[0,0],[1,2],[2,2]]}]}"#,
        r#"{"op": "intersect", "objects": [{"type": "bezier", "points": [[0,0,0],[2,4,1],[4,0,2]]}, {"type": "bezier", "points": [[2,2,1],[3,2,1.5],[4,0,2]]}]}"#,
    ];
    for case in cases {
        let mut read = geocert::io::read_cases(case);
        let r = serde_json::to_value(geocert::io::solve_case(read.remove(0))).unwrap();
        assert_eq!(r["kind"], "arc", "{r}");
        assert!(schemas.validate(&r, index).is_ok(), "{r}");
        let bare = mutated(&r, |r| drop(r.as_object_mut().unwrap().remove("arc")));
        assert!(schemas.validate(&bare, index).is_err(), "{bare}");
        let other = mutated(&r, |r| r["kind"] = json!("segment"));
        assert!(schemas.validate(&other, index).is_err(), "{other}");
    }
}

#[test]
fn blend_records_fit_the_schema() {
    let (schemas, index) = schema();
    let cases = [
        r#"{"op": "fillet", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "plane", "origin": [0,0,0], "u": [0,1,0], "v": [0,0,1]}], "radius": 1, "sector": 3, "range": [-1, 1], "grid": [3, 5]}"#,
        r#"{"op": "fillet", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "cylinder", "origin": [0,0,-5], "radius": 2, "axis": [0,0,1], "height": [0,10]}], "radius": 0.5, "side": [3,0,1]}"#,
        r#"{"op": "fillet", "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1}, {"type": "plane", "normal": [0,0,1], "d": -5}], "radius": 0.5, "sector": 1}"#,
        r#"{"op": "chamfer", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "plane", "normal": [1,0,0], "d": 0}], "legs": [1, 2], "sector": 3, "range": [0, 1]}"#,
    ];
    for case in cases {
        let mut read = geocert::io::read_cases(case);
        let r = serde_json::to_value(geocert::io::solve_case(read.remove(0))).unwrap();
        assert_ne!(r["status"], "error", "{r}");
        assert!(schemas.validate(&r, index).is_ok(), "{r}");
        if r["kind"] == "surface" {
            let no_blend = mutated(&r, |r| drop(r.as_object_mut().unwrap().remove("blend")));
            assert!(schemas.validate(&no_blend, index).is_err());
        }
    }
    let mut read = geocert::io::read_cases(
        r#"{"op": "fillet", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "sphere", "center": [0,0,0], "radius": 1}], "radius": 2, "sector": 3}"#,
    );
    let r = serde_json::to_value(geocert::io::solve_case(read.remove(0))).unwrap();
    assert_eq!(r["error"]["kind"], "degenerate_blend", "{r}");
    assert!(schemas.validate(&r, index).is_ok(), "{r}");
}
