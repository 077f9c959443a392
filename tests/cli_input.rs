//! Reading case files through `geocert solve` (spec/CASES.md, README "Input"): one
//! bad byte, byte-order mark, lone CR or syntax error costs one case, with its line
//! number and whatever id could be read; JSON arrays are read element by element;
//! duplicate keys, a missing `op` and non-finite numbers are errors naming the field;
//! numeric ids are echoed exactly as written. Every run also checks that one and
//! three threads give the same bytes (cli_support).

mod cli_support;

use cli_support::{json_lines, run};
use serde_json::{json, Value};

const GOOD: &str = r#"{"id":"g","op":"intersect","objects":[{"type":"line2","origin":[0,0],"dir":[1,0]},{"type":"line2","origin":[0,1],"dir":[1,-1]}]}"#;

fn solve_bytes(input: &[u8]) -> (Vec<Value>, i32) {
    let out = run("solve", &[], input);
    (json_lines(&out), out.status.code().unwrap_or(-1))
}

fn is_good(r: &Value) -> bool {
    r["status"] == "exact" && r["points"][0]["xyz"] == json!([1.0, 0.0])
}

fn error_at(r: &Value, field: &str) {
    assert_eq!(r["status"], "error", "{r}");
    assert_eq!(r["error"]["field"], field, "{r}");
}

#[test]
fn each_bad_line_costs_that_line_only() {
    // Line 1 starts with a BOM (skipped), line 3 holds a byte that is not UTF-8,
    // line 4 is cut short, lines 5 and 6 are separated by a lone CR, line 7 ends in
    // CRLF, line 8 is blank, line 9 starts with a BOM (files joined with cat).
    let mut input = Vec::new();
    input.extend_from_slice(b"\xEF\xBB\xBF");
    input.extend_from_slice(GOOD.as_bytes());
    input.extend_from_slice(b"\n");
    input.extend_from_slice(GOOD.as_bytes());
    input.extend_from_slice(b"\n{\"id\": \"caf\xE9\", \"op\": \"intersect\"}\n");
    input.extend_from_slice(b"{\"id\": 44, \"op\": \"inter\n");
    input.extend_from_slice(GOOD.as_bytes());
    input.extend_from_slice(b"\r");
    input.extend_from_slice(GOOD.as_bytes());
    input.extend_from_slice(b"\r\n");
    input.extend_from_slice(GOOD.as_bytes());
    input.extend_from_slice(b"\r\n   \n\xEF\xBB\xBF");
    input.extend_from_slice(GOOD.as_bytes());
    let (r, code) = solve_bytes(&input);
    assert_eq!(code, 1);
    assert_eq!(r.len(), 8);
    for i in [0, 1, 4, 5, 6, 7] {
        assert!(is_good(&r[i]), "{i}: {}", r[i]);
    }
    error_at(&r[2], "line 3");
    assert!(r[2]["error"]["message"].as_str().unwrap().contains("UTF-8"));
    assert_eq!(
        r[2]["id"], "caf\u{FFFD}",
        "the id as far as it could be read"
    );
    error_at(&r[3], "line 4");
    assert_eq!(r[3]["id"], 44);
}

#[test]
fn a_broken_array_element_costs_that_element_only() {
    let input = format!(
        "[\n {GOOD},\n {{\"id\": \"x\", \"op\": tru}},\n {{\"id\": \"s\", \"op\": \"intersect\n }},\n {GOOD}, {{\"id\": 5, \"op\": NaN}}\n]\n"
    );
    let (r, code) = solve_bytes(input.as_bytes());
    assert_eq!(code, 1);
    assert_eq!(r.len(), 5, "{r:?}");
    assert!(is_good(&r[0]) && is_good(&r[3]));
    error_at(&r[1], "line 3");
    assert_eq!(r[1]["id"], "x");
    // The unterminated string ends at the line break; the element is one error.
    error_at(&r[2], "line 4");
    assert_eq!(r[2]["id"], "s");
    error_at(&r[4], "op");
    assert_eq!(r[4]["error"]["kind"], "non_finite");
    // Array and JSON Lines forms of the same cases give the same results.
    let (lines, _) = solve_bytes(format!("{GOOD}\n{GOOD}\n").as_bytes());
    let (array, _) = solve_bytes(format!("[{GOOD},{GOOD}]").as_bytes());
    assert_eq!(lines, array);
}

#[test]
fn array_structure_errors_are_records_of_their_own() {
    // Text after the array, a missing `]`, an empty element.
    let (r, _) = solve_bytes(format!("[{GOOD}]\nxyz\n").as_bytes());
    assert!(is_good(&r[0]));
    error_at(&r[1], "line 2");
    let (r, _) = solve_bytes(format!("[{GOOD},\n{GOOD}\n").as_bytes());
    assert_eq!(r.len(), 3);
    assert!(is_good(&r[0]) && is_good(&r[1]));
    error_at(&r[2], "line 3");
    assert!(r[2]["error"]["message"].as_str().unwrap().contains("]"));
    let (r, _) = solve_bytes(format!("[{GOOD},,{GOOD}]").as_bytes());
    assert_eq!(r.len(), 3);
    assert!(is_good(&r[0]) && is_good(&r[2]));
    error_at(&r[1], "line 1");
    // An unbalanced bracket cannot be resynchronised: one record for the rest.
    let (r, _) = solve_bytes(format!("[{GOOD},\n{{\"op\": [,\n{GOOD}]").as_bytes());
    assert_eq!(r.len(), 2);
    assert!(is_good(&r[0]));
    assert_eq!(r[1]["status"], "error");
}

#[test]
fn fields_are_named_for_duplicates_missing_op_and_non_finite_numbers() {
    let plane = |d: &str| format!(r#"{{"type":"plane","normal":[0,0,1],"d":{d}}}"#);
    let case = |id: &str, d: &str| {
        format!(
            r#"{{"id":{id},"op":"intersect","objects":[{},{}]}}"#,
            plane("0"),
            plane(d)
        )
    };
    let lines = [
        case("1", "NaN"),
        case("2", "Infinity"),
        case("3", "-Infinity"),
        case("4", "1e309"),
        case("5", &"9".repeat(400)),
        r#"{"id": 6, "objects": []}"#.to_string(),
        r#"{"id": 7, "op": "intersect", "op": "project"}"#.to_string(),
        r#"{"id": 8, "op": "intersect", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0, "d": 1}, {}]}"#.to_string(),
        r#"{"id": 9, "op": "intersect", "options": {"max_bits": 1e300}}"#.to_string(),
    ];
    let (r, code) = solve_bytes(lines.join("\n").as_bytes());
    assert_eq!(code, 1);
    for (i, word) in ["NaN", "Infinity", "-Infinity", "1e309"].iter().enumerate() {
        error_at(&r[i], "objects[1].d");
        assert_eq!(r[i]["error"]["kind"], "non_finite");
        assert_eq!(r[i]["id"], i + 1);
        assert!(r[i]["error"]["message"].as_str().unwrap().contains(word));
    }
    error_at(&r[4], "objects[1].d");
    let long = r[4]["error"]["message"].as_str().unwrap();
    assert!(long.len() < 100, "{long}");
    error_at(&r[5], "op");
    error_at(&r[6], "op");
    assert!(r[6]["error"]["message"]
        .as_str()
        .unwrap()
        .contains("duplicate key `op`"));
    assert_eq!(r[6]["id"], 7);
    error_at(&r[7], "objects[0].d");
    // A number printed in an error message is in shortest form, never 300 digits.
    let m = r[8]["error"]["message"].as_str().unwrap();
    assert!(m.len() < 200 && !m.contains("0000000000"), "{m}");
}

#[test]
fn numeric_ids_are_echoed_exactly_as_written() {
    let ids = [
        "18446744073709551617",
        "-9223372036854775809",
        "123456789012345678901234567890",
        "1.50",
        "1e2",
        "-0",
        "0.1000000000000000000000001",
    ];
    let mut input = String::new();
    for id in &ids {
        input += &GOOD.replace(r#""id":"g""#, &format!(r#""id":{id}"#));
        input += "\n";
        input += &format!("{{\"id\": {id}, \"op\": \"intersect\"}}\n");
        input += &format!("{{\"id\": {id}, \"op\": \"intersect\", \n");
    }
    let out = run("solve", &[], input.as_bytes());
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 3 * ids.len());
    for (i, id) in ids.iter().enumerate() {
        for line in &lines[3 * i..3 * i + 3] {
            assert!(line.starts_with(&format!("{{\"id\":{id},")), "{line}");
        }
    }
    // The table shows them as written too.
    let out = run("solve", &["--format", "table"], input.as_bytes());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("18446744073709551617 "), "{text}");
}
