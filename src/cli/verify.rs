//! `geocert verify FILE|-`: certify or refute the `claim` of each case (docs/FORMAT.md
//! "Claims"), one JSON line per case. Exit status: 0 when every claim is confirmed,
//! 1 when a case failed to read or solve, 3 when some claimed item was refuted or
//! left undecided or some solution was missed.

use geocert::io::{read_cases, verify_case};
use std::process::ExitCode;

pub fn run(file: &str) -> ExitCode {
    let text = match super::solve::read_input(file) {
        Ok(text) => text,
        Err(e) => {
            eprintln!("geocert verify: cannot read {file}: {e}");
            return ExitCode::from(2);
        }
    };
    let results: Vec<_> = read_cases(&text).into_iter().map(verify_case).collect();
    let failed = results.iter().filter(|r| r.status == "error").count();
    let disputed = results
        .iter()
        .filter(|r| {
            r.claims.iter().flatten().any(|c| c.verdict != "confirmed")
                || r.missed.as_ref().is_some_and(|m| !m.is_empty())
        })
        .count();
    if super::solve::write_lines(results.iter().map(|r| r.to_json_line())).is_err() {
        return ExitCode::from(2);
    }
    if failed > 0 {
        eprintln!("geocert verify: {failed} case(s) failed");
        ExitCode::from(1)
    } else if disputed > 0 {
        eprintln!("geocert verify: {disputed} case(s) with refuted, undecided or missed items");
        ExitCode::from(3)
    } else {
        ExitCode::SUCCESS
    }
}
