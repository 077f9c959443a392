//! `geocert demo`: the worked linear examples of OPERATIONS.md §16.2, §16.5, §16.7,
//! §16.8 and a few degenerate ones, solved through the same path as `geocert solve`
//! and printed as a table of status, kind, point and time.

use geocert::io::result::CaseResult;
use geocert::io::{read_cases, solve_case};
use std::process::ExitCode;

const CASES: &str = include_str!("demo_cases.jsonl");

pub fn run() -> ExitCode {
    let results: Vec<CaseResult> = read_cases(CASES).into_iter().map(solve_case).collect();
    let id_width = results
        .iter()
        .map(|r| id_text(r).chars().count())
        .max()
        .unwrap_or(4)
        .max(4);
    println!(
        "{:<id_width$}  {:<9}  {:<10}  {:<10}  {:>7}  answer",
        "case", "status", "kind", "decided by", "µs"
    );
    println!("{}", "-".repeat(id_width + 80));
    let mut failed = false;
    for r in &results {
        failed |= r.status == "error";
        println!(
            "{:<id_width$}  {:<9}  {:<10}  {:<10}  {:>7}  {}",
            id_text(r),
            r.status,
            r.kind.unwrap_or("-"),
            r.arithmetic.unwrap_or("-"),
            r.micros.map_or("-".to_string(), |m| m.to_string()),
            answer_text(r)
        );
    }
    println!();
    println!("Every row is decided for the exact input; coordinates are correctly rounded.");
    println!("Run `geocert solve FILE` for JSON Lines of the same results (docs/FORMAT.md).");
    if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

fn id_text(r: &CaseResult) -> String {
    match &r.id {
        serde_json::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Shortest round-trip form, as in the JSON output (1e150, not 151 digits).
fn num_text(x: f64) -> String {
    serde_json::Number::from_f64(x).map_or(format!("{x}"), |n| n.to_string())
}

fn vector_text(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|&x| num_text(x)).collect();
    format!("({})", parts.join(", "))
}

fn answer_text(r: &CaseResult) -> String {
    if let Some(e) = &r.error {
        return format!("{}: {}", e.kind, e.message);
    }
    if let Some(points) = &r.points {
        let texts: Vec<String> = points
            .iter()
            .map(|p| {
                let params: Vec<String> = p
                    .params
                    .iter()
                    .filter(|ps| !ps.is_empty())
                    .map(|ps| vector_text(ps))
                    .collect();
                let mut s = vector_text(&p.xyz);
                if !params.is_empty() {
                    s += &format!(" params {}", params.join(" "));
                }
                if let Some(d) = p.signed_distance.or(p.distance) {
                    s += &format!(" distance {}", num_text(d));
                }
                if let Some(exact) = &p.exact {
                    if !exact.xyz.is_empty() {
                        s += &format!(" exact ({})", exact.xyz.join(", "));
                    }
                }
                s
            })
            .collect();
        return texts.join("; ");
    }
    if let Some(line) = &r.line {
        return format!(
            "point {} dir {}",
            vector_text(&line.point),
            vector_text(&line.dir)
        );
    }
    if let Some(seg) = &r.segment {
        return format!("{} – {}", vector_text(&seg.a.xyz), vector_text(&seg.b.xyz));
    }
    r.reason.clone().unwrap_or_default()
}
