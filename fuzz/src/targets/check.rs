//! Checks every result record must pass, whatever the case: it is one JSON object with
//! a known status; an error names its kind and is never `internal` (a panic); no
//! number of an answer is `null`; every box contains its estimate
//! (docs/FORMAT.md "Results", "Numbers beyond the double range").

use serde_json::Value;

/// The statuses of docs/FORMAT.md.
const STATUSES: &[&str] = &[
    "exact",
    "verified",
    "verified_singular",
    "undecided",
    "error",
];

/// Check one output line; the parsed record.
pub fn record(line: &str) -> Value {
    let v: Value = serde_json::from_str(line).unwrap_or_else(|e| panic!("not JSON ({e}): {line}"));
    let status = v["status"]
        .as_str()
        .unwrap_or_else(|| panic!("no status: {line}"));
    assert!(
        STATUSES.contains(&status),
        "unknown status {status}: {line}"
    );
    if status == "error" {
        let kind = v["error"]["kind"].as_str().unwrap_or("");
        assert!(!kind.is_empty(), "an error without a kind: {line}");
        assert_ne!(kind, "internal", "an internal error (a panic): {line}");
        assert!(
            v["error"]["field"].is_string(),
            "an error without a field: {line}"
        );
        return v;
    }
    assert!(v["kind"].is_string(), "an answer without a kind: {line}");
    for p in v["points"].as_array().into_iter().flatten() {
        point(p, line);
    }
    if let Some(s) = v.get("segment") {
        point(&s["a"], line);
        point(&s["b"], line);
    }
    v
}

/// A number of an answer: a JSON number, or `"inf"`/`"-inf"` beyond the double range.
pub fn number(x: &Value, line: &str) -> Option<f64> {
    match x {
        Value::Number(n) => Some(n.as_f64().expect("a JSON number")),
        Value::String(s) if s == "inf" => Some(f64::INFINITY),
        Value::String(s) if s == "-inf" => Some(f64::NEG_INFINITY),
        _ => panic!("{x} is not a number: {line}"),
    }
}

/// A point of an answer: `xyz` numbers, its `box` (when given) around them, and
/// `params` and `param_box` likewise.
fn point(p: &Value, line: &str) {
    let xyz = p["xyz"]
        .as_array()
        .unwrap_or_else(|| panic!("a point without xyz: {line}"));
    let xyz: Vec<f64> = xyz.iter().map(|x| number(x, line).unwrap()).collect();
    if let Some(b) = p.get("box") {
        enclose(b, &xyz, line);
    }
    let params: Vec<Vec<f64>> = p["params"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|ps| {
            let ps = ps
                .as_array()
                .unwrap_or_else(|| panic!("params not lists: {line}"));
            ps.iter().map(|x| number(x, line).unwrap()).collect()
        })
        .collect();
    if let Some(pb) = p.get("param_box") {
        let pb = pb
            .as_array()
            .unwrap_or_else(|| panic!("param_box not a list: {line}"));
        assert_eq!(
            pb.len(),
            params.len(),
            "param_box and params differ: {line}"
        );
        for (b, ps) in pb.iter().zip(&params) {
            enclose(b, ps, line);
        }
    }
}

/// `b` is a list of `[lo, hi]` with `lo ≤ x ≤ hi` for each `x` of `xs`.
fn enclose(b: &Value, xs: &[f64], line: &str) {
    let b = b
        .as_array()
        .unwrap_or_else(|| panic!("a box that is not a list: {line}"));
    assert_eq!(b.len(), xs.len(), "a box of the wrong dimension: {line}");
    for (iv, &x) in b.iter().zip(xs) {
        let lo = number(&iv[0], line).unwrap();
        let hi = number(&iv[1], line).unwrap();
        assert!(lo <= hi, "an empty box [{lo}, {hi}]: {line}");
        assert!(
            lo <= x && x <= hi,
            "{x} outside its box [{lo}, {hi}]: {line}"
        );
    }
}

/// The `[lo, hi]` bounds of a point's box, as read.
pub fn bounds(p: &Value, line: &str) -> Option<Vec<(f64, f64)>> {
    let b = p.get("box")?.as_array()?;
    Some(
        b.iter()
            .map(|iv| (number(&iv[0], line).unwrap(), number(&iv[1], line).unwrap()))
            .collect(),
    )
}

/// Prints the case when a check (or geocert) panics while it is alive, so that a
/// finding can be read and replayed as a JSON case.
pub struct ShowOnPanic<'a>(pub &'a Value);

impl Drop for ShowOnPanic<'_> {
    fn drop(&mut self) {
        if std::thread::panicking() {
            eprintln!("the case: {}", self.0);
        }
    }
}
