//! README.md's case examples are valid and answer what README shows. Every fenced
//! block tagged `jsonl` (cases for `geocert solve`) or `jsonl verify` (for `geocert
//! verify`) must be followed by a `jsonl result` block with one result per case; each
//! field shown there must match the real result (fields left out are not checked,
//! arrays match element by element and in length, and a number shown with fewer
//! digits matches the result rounded to those digits).

mod cli_support;

use serde_json::Value;

struct Example {
    verify: bool,
    cases: String,
    results: Vec<Value>,
    line: usize,
}

/// The fenced blocks of a Markdown text: (info string, body, line of the fence).
fn blocks(text: &str) -> Vec<(String, String, usize)> {
    let mut out = Vec::new();
    let mut open: Option<(String, String, usize)> = None;
    for (n, line) in text.lines().enumerate() {
        match (&mut open, line.strip_prefix("```")) {
            (None, Some(info)) => open = Some((info.trim().to_string(), String::new(), n + 1)),
            (Some(_), Some(_)) => out.extend(open.take()),
            (Some((_, body, _)), None) => {
                body.push_str(line);
                body.push('\n');
            }
            (None, None) => {}
        }
    }
    out
}

fn examples() -> Vec<Example> {
    let readme = include_str!("../README.md");
    let mut out = Vec::new();
    let mut pending: Option<(bool, String, usize)> = None;
    for (info, body, line) in blocks(readme) {
        match info.as_str() {
            "jsonl" | "jsonl verify" => {
                assert!(
                    pending.is_none(),
                    "README line {line}: the cases before have no result block"
                );
                pending = Some((info == "jsonl verify", body, line));
            }
            "jsonl result" => {
                let (verify, cases, line) = pending.take().expect("a result block follows cases");
                let results = body
                    .lines()
                    .map(|l| {
                        serde_json::from_str(l)
                            .unwrap_or_else(|e| panic!("README line {line}: {e}"))
                    })
                    .collect();
                out.push(Example {
                    verify,
                    cases,
                    results,
                    line,
                });
            }
            _ => {}
        }
    }
    assert!(
        pending.is_none(),
        "the last cases of README have no result block"
    );
    out
}

/// Half a unit in the last digit of `x`'s shortest decimal form.
fn shown_precision(x: f64) -> f64 {
    let text = format!("{x:e}");
    let (mantissa, exp) = text.split_once('e').unwrap();
    let digits = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    0.5 * 10f64.powi(exp.parse::<i32>().unwrap() - digits)
}

/// Whether `actual` shows everything `shown` shows (see the module documentation).
fn matches(shown: &Value, actual: &Value, path: &str) -> Result<(), String> {
    match (shown, actual) {
        (Value::Object(s), Value::Object(a)) => s.iter().try_for_each(|(k, v)| {
            let sub = format!("{path}.{k}");
            a.get(k)
                .ok_or(format!("{sub} is missing"))
                .and_then(|x| matches(v, x, &sub))
        }),
        (Value::Array(s), Value::Array(a)) if s.len() == a.len() => s
            .iter()
            .zip(a)
            .enumerate()
            .try_for_each(|(i, (v, x))| matches(v, x, &format!("{path}[{i}]"))),
        (Value::Number(s), Value::Number(a)) => {
            let (s, a) = (s.as_f64().unwrap(), a.as_f64().unwrap());
            if (s - a).abs() <= shown_precision(s) {
                Ok(())
            } else {
                Err(format!("{path}: README shows {s}, the result is {a}"))
            }
        }
        _ if shown == actual => Ok(()),
        _ => Err(format!(
            "{path}: README shows {shown}, the result is {actual}"
        )),
    }
}

#[test]
fn every_readme_example_answers_what_readme_shows() {
    let examples = examples();
    assert!(examples.len() >= 4, "README has its examples");
    let mut cases = 0;
    for ex in &examples {
        let command = if ex.verify { "verify" } else { "solve" };
        let out = cli_support::run(command, &[], ex.cases.as_bytes());
        let results = cli_support::json_lines(&out);
        assert_eq!(
            results.len(),
            ex.cases.lines().count(),
            "README line {}",
            ex.line
        );
        assert_eq!(
            results.len(),
            ex.results.len(),
            "README line {}: one result per case",
            ex.line
        );
        for (shown, actual) in ex.results.iter().zip(&results) {
            if let Err(e) = matches(shown, actual, "result") {
                panic!("README line {}: {e}\nresult: {actual}", ex.line);
            }
        }
        cases += results.len();
    }
    assert!(cases >= 7);
}

#[test]
fn the_matcher_is_strict_where_it_should_be() {
    let v = |t: &str| serde_json::from_str::<Value>(t).unwrap();
    assert!(matches(&v("{\"a\":1}"), &v("{\"a\":1,\"b\":2}"), "r").is_ok());
    assert!(matches(&v("{\"c\":1}"), &v("{\"a\":1}"), "r").is_err());
    assert!(matches(&v("[1]"), &v("[1,2]"), "r").is_err());
    assert!(matches(&v("2.0957377"), &v("2.095737736792518"), "r").is_ok());
    assert!(matches(&v("2.0957378"), &v("2.095737736792518"), "r").is_err());
    assert!(matches(&v("0.3333333333333333"), &v("0.33333333333333337"), "r").is_err());
    assert!(matches(&v("\"exact\""), &v("\"verified\""), "r").is_err());
}
