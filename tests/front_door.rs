//! The library front door and the command line give the same answers: every case of
//! `tests/data/cases.jsonl` (the cases the test suite sends through the command line,
//! and generated cases over every curved object type) is solved twice — by the
//! `geocert solve` binary, and in-process by a library caller that builds the shapes
//! with `io::shape` and calls `ops::intersect` / `ops::project` / `ops::classify`
//! itself — and both must equal `tests/data/cases.expected.jsonl` byte for byte
//! (timings removed). The expected file pins the answers: a change of any answer shows
//! here; after an intended change, regenerate it with `GEOCERT_BLESS=1 cargo test
//! --release --features cgal --test cli front_door::`.

use std::process::Command;

use geocert::io::{self, answer_result, position, read_cases, shape, CaseResult, Op};
use geocert::ops::{self, ProjectOptions};
use geocert::GeomError;

const CASES: &str = "tests/data/cases.jsonl";
const EXPECTED: &str = "tests/data/cases.expected.jsonl";

fn without_timing(mut r: CaseResult) -> String {
    r.micros = None;
    r.to_json_line()
}

/// What a library user writes: shapes and options from the case, then the front door.
fn library(case: &io::Case) -> Result<geocert::Certified<ops::Answer>, GeomError> {
    let options = io::options(case)?;
    let missing = |field: &str| GeomError::Format {
        field: field.into(),
        message: format!("`{}` needs `{field}`", case.op.as_str()),
    };
    let point = || {
        let p = case.point.as_deref().ok_or_else(|| missing("point"))?;
        position(p, "point")
    };
    match case.op {
        Op::Intersect => {
            let shapes = case
                .objects
                .iter()
                .enumerate()
                .map(|(i, o)| shape(o, &format!("objects[{i}]")))
                .collect::<Result<Vec<_>, _>>()?;
            ops::intersect(&shapes, &options)
        }
        Op::Project => {
            let p = point()?;
            let onto = shape(case.onto.as_ref().ok_or_else(|| missing("onto"))?, "onto")?;
            let direction = case
                .direction
                .as_deref()
                .map(|d| position(d, "direction"))
                .transpose()?;
            let how = ProjectOptions {
                nearest: case.nearest,
                direction,
                options,
            };
            ops::project(&p, &onto, &how)
        }
        Op::Classify => {
            let p = point()?;
            let shell = shape(
                case.shell.as_ref().ok_or_else(|| missing("shell"))?,
                "shell",
            )?;
            ops::classify(&p, &shell, &options)
        }
        Op::Section => {
            if case.objects.len() != 2 {
                return Err(GeomError::CountMismatch {
                    field: "objects".into(),
                    expected: "2 objects (the shape, then the cutting plane)".into(),
                    found: case.objects.len().to_string(),
                });
            }
            let at = |i: usize| shape(&case.objects[i], &format!("objects[{i}]"));
            ops::section(&at(0)?, &at(1)?, &options)
        }
        other => Err(GeomError::Unsupported {
            field: "op".into(),
            reason: format!("`{}` is not implemented in this build", other.as_str()),
        }),
    }
}

fn library_lines(text: &str) -> Vec<String> {
    read_cases(text)
        .into_iter()
        .map(|read| {
            let r = match read.case {
                Err(e) => CaseResult::error(read.id, &e),
                Ok(case) => match library(&case) {
                    Ok(c) => answer_result(case.id.clone(), &c),
                    Err(e) => CaseResult::error(case.id.clone(), &e),
                },
            };
            without_timing(r)
        })
        .collect()
}

fn cli_lines() -> Vec<String> {
    let out = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args(["solve", CASES])
        .output()
        .expect("runs geocert");
    String::from_utf8(out.stdout)
        .expect("UTF-8")
        .lines()
        .map(strip_micros)
        .collect()
}

/// The line without its `"micros":N` field (the only field that varies between runs).
fn strip_micros(line: &str) -> String {
    match line.find(",\"micros\":") {
        Some(start) => {
            let rest = &line[start + 1..];
            let end = rest.find([',', '}']).unwrap_or(rest.len());
            format!("{}{}", &line[..start], &rest[end..])
        }
        None => line.to_string(),
    }
}

fn expected(actual: &[String]) -> Vec<String> {
    if std::env::var_os("GEOCERT_BLESS").is_some() {
        std::fs::write(EXPECTED, actual.join("\n") + "\n").expect("writes the expected file");
    }
    std::fs::read_to_string(EXPECTED)
        .expect("the expected answers")
        .lines()
        .map(String::from)
        .collect()
}

fn assert_same(what: &str, actual: &[String], expected: &[String]) {
    assert_eq!(actual.len(), expected.len(), "{what}: number of results");
    let differing: Vec<usize> = (0..actual.len())
        .filter(|&i| actual[i] != expected[i])
        .collect();
    assert!(
        differing.is_empty(),
        "{what}: {} answers differ from {EXPECTED}, first at line {}:\n  got      {}\n  expected {}",
        differing.len(),
        differing[0] + 1,
        actual[differing[0]],
        expected[differing[0]]
    );
}

#[test]
fn the_library_front_door_gives_the_expected_answers() {
    let text = std::fs::read_to_string(CASES).expect("the case corpus");
    let lines = library_lines(&text);
    assert!(lines.len() > 1000, "the corpus covers the suite");
    assert_same("library", &lines, &expected(&lines));
}

#[test]
fn the_command_line_gives_the_same_answers() {
    let lines = cli_lines();
    let text = std::fs::read_to_string(EXPECTED).expect("the expected answers");
    let expected: Vec<String> = text.lines().map(String::from).collect();
    assert_same("geocert solve", &lines, &expected);
}
