//! One case from its text to its output line, on a worker thread: parse, apply the
//! command-line defaults, solve or verify (a panic becomes an `internal` error
//! record), then shape the record: `micros` only with `--timings`, long numbers in
//! error messages in shortest form, a numeric id echoed exactly as written.

use super::exit::{self, Status};
use super::table;
use geocert::error::GeomError;
use geocert::io::lenient::salvage;
use geocert::io::number::tidy_numbers;
use geocert::io::result::CaseResult;
use geocert::io::stream::Chunk;
use geocert::io::{read_chunk, solve_case, verify_case, Double, ReadCase};
use serde_json::Value;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// `solve` or `verify`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    Solve,
    Verify,
}

impl Mode {
    pub fn name(self) -> &'static str {
        match self {
            Mode::Solve => "solve",
            Mode::Verify => "verify",
        }
    }
}

/// The output format (`--format`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// One JSON object per line (docs/FORMAT.md "Results").
    Jsonl,
    /// A table for people: status, kind, completeness, arithmetic, answer.
    Table,
}

/// Budgets given on the command line, for cases whose `options` do not set them.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Defaults {
    pub max_boxes: Option<u64>,
    pub max_bits: Option<u32>,
    pub time_limit: Option<f64>,
}

/// Everything a worker needs to turn a case into its output.
#[derive(Debug, Clone)]
pub struct Context {
    pub mode: Mode,
    pub format: Format,
    pub timings: bool,
    pub defaults: Defaults,
    /// Test hook: a case with this id panics (`GEOCERT_TEST_PANIC_ID`), to check that
    /// a bug in one case costs that case only.
    pub panic_id: Option<String>,
}

/// The output of a batch of consecutive cases, tagged with its place in the input.
#[derive(Debug, Default)]
pub struct Done {
    /// The batch's index (batches are numbered in input order).
    pub index: u64,
    /// The input offset after the batch's last case (progress).
    pub end: u64,
    /// The output lines, each ending in a newline.
    pub text: String,
    pub cases: u64,
    pub errors: u64,
    /// The exit bits the cases set.
    pub status: Status,
}

impl Context {
    /// The table header, if the format has one.
    pub fn header(&self) -> Option<String> {
        (self.format == Format::Table).then(|| table::header(self.timings))
    }

    /// Solve or verify a batch of cases, in order. Never panics.
    pub fn process_batch(&self, index: u64, batch: Vec<Chunk>) -> Done {
        let mut done = Done {
            index,
            ..Done::default()
        };
        for chunk in batch {
            let (text, is_error, status) = self.process(&chunk);
            done.text.push_str(&text);
            done.cases += 1;
            done.errors += u64::from(is_error);
            done.status.set(status.0);
            done.end = chunk.end;
        }
        done
    }

    /// Solve or verify one case (see the module documentation): its output text,
    /// whether it is an error, and its exit bits. Never panics.
    pub fn process(&self, chunk: &Chunk) -> (String, bool, Status) {
        let solved = catch_unwind(AssertUnwindSafe(|| self.solve(chunk)));
        let (result, raw_id) = solved.unwrap_or_else(|panic| internal(chunk, &*panic));
        let shaped = catch_unwind(AssertUnwindSafe(|| self.shape(result, raw_id.as_deref())));
        shaped.unwrap_or_else(|_| {
            let line = "{\"id\":null,\"status\":\"error\",\"error\":{\"kind\":\"internal\",\
                        \"field\":\"\",\"message\":\"the result could not be written\"}}\n";
            (line.to_string(), true, Status(exit::INTERNAL))
        })
    }

    fn solve(&self, chunk: &Chunk) -> (CaseResult, Option<String>) {
        let mut record = read_chunk(chunk);
        self.apply_defaults(&mut record.read);
        if let (Some(bad), Value::String(id)) = (&self.panic_id, &record.read.id) {
            assert!(bad != id, "GEOCERT_TEST_PANIC_ID: case {id}");
        }
        let result = match self.mode {
            Mode::Solve => solve_case(record.read),
            Mode::Verify => verify_case(record.read),
        };
        (result, record.raw_id)
    }

    fn apply_defaults(&self, read: &mut ReadCase) {
        let Ok(case) = &mut read.case else {
            return;
        };
        let o = &mut case.options;
        o.max_boxes = o.max_boxes.or(self.defaults.max_boxes);
        o.max_bits = o.max_bits.or(self.defaults.max_bits);
        o.time_limit = o.time_limit.or(self.defaults.time_limit.map(Double));
    }

    /// The output text of a result, whether it is an error, and its exit bits.
    fn shape(&self, mut r: CaseResult, raw_id: Option<&str>) -> (String, bool, Status) {
        if !self.timings {
            r.micros = None;
        }
        let mut status = Status::default();
        if let Some(e) = &mut r.error {
            e.message = tidy_numbers(&e.message).into_owned();
            status.set(if e.kind == "internal" {
                exit::INTERNAL
            } else {
                exit::BAD_CASE
            });
        }
        let disputed = r.claims.iter().flatten().any(|c| c.verdict != "confirmed")
            || r.missed.as_ref().is_some_and(|m| !m.is_empty());
        if self.mode == Mode::Verify && disputed {
            status.set(exit::DISPUTED);
        }
        let text = match self.format {
            Format::Jsonl => {
                let mut line = r.to_json_line();
                if let Some(raw) = raw_id {
                    line = with_raw_id(line, &r.id, raw);
                }
                line.push('\n');
                line
            }
            Format::Table => {
                let id = raw_id.map_or_else(|| table::id_text(&r.id), str::to_string);
                table::row(&r, &id, self.timings)
            }
        };
        (text, r.error.is_some(), status)
    }
}

/// The line with its `id` (the first field of a result) replaced by the raw text.
fn with_raw_id(line: String, id: &Value, raw: &str) -> String {
    let prefix = format!("{{\"id\":{id}");
    match line.strip_prefix(&prefix) {
        Some(rest) if rest.starts_with([',', '}']) => format!("{{\"id\":{raw}{rest}"),
        _ => line,
    }
}

/// The record of a case whose computation panicked (a bug in geocert).
fn internal(chunk: &Chunk, panic: &(dyn std::any::Any + Send)) -> (CaseResult, Option<String>) {
    let what = panic
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic".to_string());
    let raw = salvage(&String::from_utf8_lossy(&chunk.bytes)).id;
    let id = raw
        .as_deref()
        .and_then(|r| serde_json::from_str(r).ok())
        .unwrap_or(Value::Null);
    let raw_number = raw.filter(|r| r.starts_with(|c: char| c == '-' || c.is_ascii_digit()));
    let error = GeomError::Format {
        field: String::new(),
        message: format!("internal error (a bug in geocert; please report it): {what}"),
    };
    let mut r = CaseResult::error(id, &error);
    if let Some(e) = &mut r.error {
        e.kind = "internal";
    }
    (r, raw_number)
}
