//! `geocert solve` / `verify` as a program (README "Command line"): exit status bits,
//! parallel output equal to one thread's on every case file of the tests, `--timings`,
//! `--format table`, command-line budgets, progress only when asked for or on a
//! terminal, and a panic in one case costing that case only.

mod cli_support;

use cli_support::{json_lines, run, run_once};
use serde_json::{json, Value};
use std::process::{Command, Stdio};

const GOOD: &str = r#"{"id":"g","op":"intersect","objects":[{"type":"line2","origin":[0,0],"dir":[1,0]},{"type":"line2","origin":[0,1],"dir":[1,-1]}]}"#;
const HELIX: &str = r#"{"id":"h","op":"intersect","objects":[{"type":"helix","center":[0,0,0],"radius":1,"pitch":1,"axis":[0,0,1],"range":[0,12.566370614359172]},{"type":"line","origin":[0,1,-5],"dir":[0,0,1]}]}"#;

fn geocert(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("the binary runs")
}

fn bench_cases(family: &str, count: &str) -> Vec<u8> {
    let out = geocert(&["bench", "cases", family, "--count", count, "--seed", "7"]);
    assert!(out.status.success());
    out.stdout
}

#[test]
fn parallel_output_equals_one_thread_on_every_case_file() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/cases");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("tests/data/cases")
        .map(|e| e.expect("entry").path())
        .collect();
    files.sort();
    assert!(files.len() >= 3);
    for file in &files {
        let input = std::fs::read(file).unwrap();
        let subcommand = if file.to_string_lossy().contains("verify") {
            "verify"
        } else {
            "solve"
        };
        // cli_support::run compares --jobs 1 and --jobs 3 byte for byte.
        let out = run(subcommand, &[], &input);
        assert!(!out.stdout.is_empty(), "{}", file.display());
        run(subcommand, &["--format", "table"], &input);
    }
    let demo = include_str!("../src/cli/demo_cases.jsonl");
    run("solve", &[], demo.as_bytes());
    // Generated files, larger than the window of cases in flight.
    let lines = bench_cases("line-plane", "20000");
    let out = run("solve", &[], &lines);
    assert_eq!(json_lines(&out).len(), 20000);
    let curved = bench_cases("curved", "24");
    let out = run("solve", &[], &curved);
    let ids: Vec<Value> = json_lines(&out).iter().map(|r| r["id"].clone()).collect();
    assert_eq!(ids, (0..24).map(|i| json!(i)).collect::<Vec<_>>());
}

#[test]
fn generated_files_are_reproducible() {
    assert_eq!(
        bench_cases("line-plane", "50"),
        bench_cases("line-plane", "50")
    );
    let text = String::from_utf8(bench_cases("curved", "8")).unwrap();
    assert_eq!(text.lines().count(), 8);
}

#[test]
fn timings_only_when_asked_and_the_same_bytes_otherwise() {
    let input = format!("{GOOD}\n{HELIX}\n");
    let plain = run("solve", &[], input.as_bytes());
    assert!(!String::from_utf8_lossy(&plain.stdout).contains("micros"));
    let again = run_once(&["solve", "-"], input.as_bytes());
    assert_eq!(plain.stdout, again.stdout);
    let timed = run_once(&["solve", "--timings", "-"], input.as_bytes());
    for r in json_lines(&timed) {
        assert!(r["micros"].is_u64(), "{r}");
    }
    let table = run_once(
        &["solve", "--timings", "--format", "table", "-"],
        input.as_bytes(),
    );
    assert!(String::from_utf8_lossy(&table.stdout).contains("µs"));
}

#[test]
fn table_has_a_header_and_one_row_per_case() {
    let input = format!("{GOOD}\n{{\"id\": \"bad\", \"op\": \"intersect\"}}\n");
    let out = run("solve", &["--format", "table"], input.as_bytes());
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 4, "{text}");
    assert!(lines[0].starts_with("case") && lines[0].contains("status"));
    assert!(
        lines[2].starts_with("g ") && lines[2].contains("exact") && lines[2].contains("(1.0, 0.0)")
    );
    assert!(lines[3].starts_with("bad ") && lines[3].contains("error"));
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn command_line_budgets_are_defaults_for_cases_without_their_own() {
    let with_option = HELIX.replace(r#""id":"h","#, r#""id":"h","options":{"max_boxes":1},"#);
    let flag = json_lines(&run("solve", &["--max-boxes", "1"], HELIX.as_bytes()));
    let option = json_lines(&run("solve", &[], with_option.as_bytes()));
    let free = json_lines(&run("solve", &[], HELIX.as_bytes()));
    assert_eq!(flag, option, "the flag acts as options.max_boxes");
    assert_ne!(flag, free, "one box is not enough for the helix");
    assert!(flag[0]["reason"].as_str().unwrap().contains("budget"));
    // A case's own options win over the flag.
    let own = HELIX.replace(
        r#""id":"h","#,
        r#""id":"h","options":{"max_boxes":100000},"#,
    );
    let out = json_lines(&run("solve", &["--max-boxes", "1"], own.as_bytes()));
    assert_eq!(out, free);
    // --max-bits and --time-limit are read; bad values are usage errors (2).
    let ok = run(
        "solve",
        &["--max-bits", "1024", "--time-limit", "2.5"],
        GOOD.as_bytes(),
    );
    assert_eq!(ok.status.code(), Some(0));
    for bad in [["--time-limit", "-1"], ["--jobs", "0"], ["--max-bits", "x"]] {
        let out = run_once(&["solve", bad[0], bad[1], "-"], GOOD.as_bytes());
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
    }
    let timed = GOOD.replace(r#""id":"g","#, r#""id":"g","options":{"time_limit":-1},"#);
    let r = json_lines(&run("solve", &[], timed.as_bytes()));
    assert_eq!(r[0]["error"]["field"], "options.time_limit");
}

#[test]
fn a_spent_time_limit_leaves_the_rest_undecided_and_says_so() {
    // A microsecond is spent before the certifier takes its first box, so the answer
    // does not depend on the machine: nothing is proven, and the reason says why.
    let sphere_ellipsoid = r#"{"id":"se","options":{"time_limit":1e-6},"op":"intersect","objects":[{"type":"sphere","center":[0.1,-0.2,0.3],"radius":2},{"type":"ellipsoid","center":[0,0,0],"a":3,"b":2,"c":1}]}"#;
    let helix_sphere = r#"{"id":"hs","options":{"time_limit":1e-6},"op":"intersect","objects":[{"type":"helix","center":[0,0,0],"radius":1,"pitch":1,"axis":[0,0,1],"range":[0,12.566370614359172]},{"type":"sphere","center":[0,0,1],"radius":1.2}]}"#;
    for input in [sphere_ellipsoid, helix_sphere] {
        let r = json_lines(&run("solve", &[], input.as_bytes()));
        // What was proven before the limit stays (a curve chain may be verified), but
        // nothing is claimed complete.
        assert_ne!(r[0]["complete"], true, "{}", r[0]["reason"]);
        assert!(
            r[0].to_string().contains("time limit reached"),
            "{}",
            r[0]["reason"]
        );
    }
    // Without the limit the same case is decided.
    let free = helix_sphere.replace(r#""options":{"time_limit":1e-6},"#, "");
    let free = json_lines(&run("solve", &[], free.as_bytes()));
    assert_eq!(free[0]["complete"], true, "{}", free[0]);
    // max_bits is capped (2³²−1 bits would never end): a typed error naming it.
    let huge = GOOD.replace(r#""id":"g","#, r#""id":"g","options":{"max_bits":100000},"#);
    let r = json_lines(&run("solve", &[], huge.as_bytes()));
    assert_eq!(r[0]["error"]["field"], "options.max_bits", "{}", r[0]);
}

#[test]
fn exit_status_bits() {
    assert_eq!(
        geocert(&["solve", "/nonexistent/cases.jsonl"])
            .status
            .code(),
        Some(8)
    );
    let dir = env!("CARGO_MANIFEST_DIR");
    assert_eq!(geocert(&["solve", dir]).status.code(), Some(8));
    assert_eq!(
        geocert(&["solve", "--no-such-flag", "x"]).status.code(),
        Some(2)
    );
    assert_eq!(geocert(&["solve"]).status.code(), Some(2));
    // A write error on standard output is reported (16), with the case bits.
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full");
    if let Ok(full) = full {
        let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/cases/mixed.jsonl");
        let out = Command::new(env!("CARGO_BIN_EXE_geocert"))
            .args(["solve", file])
            .stdout(full)
            .output()
            .unwrap();
        let code = out.status.code().unwrap();
        assert_eq!(code & 16, 16, "{code}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write"));
    }
    let help = String::from_utf8(geocert(&["solve", "--help"]).stdout).unwrap();
    for code in ["   1  ", "   4  ", "   8  ", "  16  ", "  32  "] {
        assert!(help.contains(code), "--help documents {code}");
    }
}

#[test]
fn a_panic_in_one_case_costs_that_case_only() {
    let boom = GOOD.replace(r#""id":"g""#, r#""id":"boom""#);
    let input = format!("{GOOD}\n{boom}\n{GOOD}\n");
    for jobs in ["1", "2"] {
        let out = Command::new(env!("CARGO_BIN_EXE_geocert"))
            .args(["solve", "--jobs", jobs, "-"])
            .env("GEOCERT_TEST_PANIC_ID", "boom")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .and_then(|mut child| {
                use std::io::Write;
                child.stdin.take().unwrap().write_all(input.as_bytes())?;
                child.wait_with_output()
            })
            .unwrap();
        let r = json_lines(&out);
        assert_eq!(r.len(), 3);
        assert_eq!(r[0]["status"], "exact");
        assert_eq!(r[2]["status"], "exact");
        assert_eq!(r[1]["id"], "boom");
        assert_eq!(r[1]["error"]["kind"], "internal");
        assert_eq!(out.status.code(), Some(32));
    }
}

#[test]
fn progress_only_on_a_terminal_or_when_asked() {
    let input = format!("{GOOD}\n");
    // Standard error is a pipe here: no progress, nothing at all on success.
    let quiet = run_once(&["solve", "-"], input.as_bytes());
    assert!(
        quiet.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&quiet.stderr)
    );
    let forced = run_once(&["solve", "--progress", "-"], input.as_bytes());
    assert!(String::from_utf8_lossy(&forced.stderr).contains("geocert solve"));
    assert_eq!(
        quiet.stdout, forced.stdout,
        "progress never touches the results"
    );
}
