//! `geocert solve FILE|-`: one JSON line per case; the exit status is non-zero if any
//! case could not be read or solved.

use geocert::io::{read_cases, solve_case};
use std::io::{Read, Write};
use std::process::ExitCode;

pub fn run(file: &str) -> ExitCode {
    let text = match read_input(file) {
        Ok(text) => text,
        Err(e) => {
            eprintln!("geocert solve: cannot read {file}: {e}");
            return ExitCode::from(2);
        }
    };
    let mut failed = 0usize;
    let lines = read_cases(&text).into_iter().map(|read| {
        let result = solve_case(read);
        if result.status == "error" {
            failed += 1;
        }
        result.to_json_line()
    });
    if write_lines(lines).is_err() {
        return ExitCode::from(2);
    }
    if failed > 0 {
        eprintln!("geocert solve: {failed} case(s) failed");
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// Write JSON lines to standard output as they come.
pub fn write_lines(lines: impl Iterator<Item = String>) -> std::io::Result<()> {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    for line in lines {
        writeln!(out, "{line}")?;
    }
    out.flush()
}

pub fn read_input(file: &str) -> std::io::Result<String> {
    if file == "-" {
        let mut text = String::new();
        std::io::stdin().read_to_string(&mut text)?;
        Ok(text)
    } else {
        std::fs::read_to_string(file)
    }
}
