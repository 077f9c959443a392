//! `geocert demo`: the worked examples of OPERATIONS.md §16.2–§16.9 and a few degenerate
//! linear ones, then curved cases (§16.3 ellipse feet, §16.4 line ∩ sphere, §16.6 conics,
//! a parabola touching its osculating circle (a proven 4-fold point),
//! a torus, surface ∩ surface curves with singular points, three spheres, the §16.10
//! ellipsoid section, a point hidden by a sphere (§16.14 visibility), a fillet whose
//! radius grows along the edge), solved
//! through the same path as `geocert solve` and printed as a table of status, kind,
//! point and time.

use super::table::{answer_text, id_text};
use geocert::io::result::CaseResult;
use geocert::io::{read_cases, solve_case};
use std::process::ExitCode;

const CASES: &str = include_str!("demo_cases.jsonl");

pub fn run() -> ExitCode {
    let results: Vec<CaseResult> = read_cases(CASES).into_iter().map(solve_case).collect();
    let id_width = results
        .iter()
        .map(|r| id_text(&r.id).chars().count())
        .max()
        .unwrap_or(4)
        .max(4);
    println!(
        "{:<id_width$}  {:<17}  {:<10}  {:<10}  {:>7}  answer",
        "case", "status", "kind", "decided by", "µs"
    );
    println!("{}", "-".repeat(id_width + 88));
    let mut failed = false;
    for r in &results {
        failed |= r.status == "error";
        println!(
            "{:<id_width$}  {:<17}  {:<10}  {:<10}  {:>7}  {}",
            id_text(&r.id),
            r.status,
            r.kind.unwrap_or("-"),
            r.arithmetic.unwrap_or("-"),
            r.micros.map_or("-".to_string(), |m| m.to_string()),
            answer_text(r)
        );
    }
    println!();
    println!("Statuses: `exact` decided for the exact input, coordinates correctly rounded;");
    println!(
        "`verified` / `verified_singular` proven in boxes (JSON `box`); `undecided` says why."
    );
    println!("Run `geocert solve FILE` for JSON Lines of the same results (docs/FORMAT.md),");
    println!("or `geocert solve --format table FILE` for this table without the times.");
    if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
