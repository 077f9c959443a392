//! Running the built `geocert` binary in tests. [`run`] runs every command twice,
//! with `--jobs 1` and `--jobs 3`, and checks that the two outputs are the same bytes
//! and the exit codes equal: so every case file a CLI test builds also tests that
//! parallel output is in input order and does not depend on the thread count.
#![allow(dead_code)]

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Run `geocert ARGS` with `input` on standard input, once.
pub fn run_once(args: &[&str], input: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let mut stdin = child.stdin.take().expect("stdin");
    let input = input.to_vec();
    // Write from another thread: the child's output may fill its pipe first.
    let writer = std::thread::spawn(move || {
        let _ = stdin.write_all(&input);
    });
    let out = child.wait_with_output().expect("the binary runs");
    writer.join().expect("input written");
    out
}

/// Run `geocert SUBCOMMAND [ARGS] -` (solve or verify) with one and with three
/// threads; assert the same bytes and exit code; the one-thread output.
pub fn run(subcommand: &str, args: &[&str], input: &[u8]) -> Output {
    let with = |jobs: &str| {
        let mut all = vec![subcommand, "--jobs", jobs];
        all.extend_from_slice(args);
        all.push("-");
        run_once(&all, input)
    };
    let one = with("1");
    let three = with("3");
    assert_eq!(
        String::from_utf8_lossy(&one.stdout),
        String::from_utf8_lossy(&three.stdout),
        "--jobs 1 and --jobs 3 differ"
    );
    assert_eq!(one.status.code(), three.status.code());
    one
}

/// The output lines as JSON values.
pub fn json_lines(out: &Output) -> Vec<serde_json::Value> {
    String::from_utf8(out.stdout.clone())
        .expect("UTF-8 output")
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect()
}

/// `geocert solve` on JSON Lines text: the results and the exit code.
pub fn solve_text(text: &str) -> (Vec<serde_json::Value>, i32) {
    let out = run("solve", &[], text.as_bytes());
    (json_lines(&out), out.status.code().unwrap_or(-1))
}

/// The numbers of a JSON array (a result's `xyz`, `params`, a box's bounds).
pub fn f64s(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}
