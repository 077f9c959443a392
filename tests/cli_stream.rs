//! `geocert solve -` on a stream that stays open (README "Command line"): each case
//! is answered as it arrives, not when a batch fills or the input ends; a run killed
//! mid-stream keeps every answer it had written, byte for byte; and memory stays flat
//! however many cases go through.

use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{self, Receiver};
use std::time::Duration;

/// A fast exact case (two lines in the plane), with its id.
fn case(id: usize) -> String {
    format!(
        r#"{{"id":{id},"op":"intersect","objects":[{{"type":"line2","origin":[0,{id}],"dir":[1,0]}},{{"type":"line2","origin":[0,1],"dir":[1,-1]}}]}}"#
    )
}

/// `geocert solve --jobs 2 -`, its standard input, and its output lines as they come.
fn start() -> (Child, ChildStdin, Receiver<String>) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args(["solve", "--jobs", "2", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("the binary starts");
    let stdin = child.stdin.take().expect("stdin");
    let stdout = BufReader::new(child.stdout.take().expect("stdout"));
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        for line in stdout.lines() {
            let Ok(line) = line else { break };
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    (child, stdin, rx)
}

/// The next output line; fails the test if none comes within a minute (the answer is
/// being held back).
fn next_line(rx: &Receiver<String>, what: &str) -> String {
    rx.recv_timeout(Duration::from_secs(60))
        .unwrap_or_else(|e| panic!("no answer for {what} while the input stays open: {e}"))
}

fn id_of(line: &str) -> u64 {
    let v: serde_json::Value = serde_json::from_str(line).expect("a whole JSON line");
    v["id"].as_u64().expect("a numeric id")
}

#[test]
fn each_case_is_answered_while_the_input_stays_open() {
    let (mut child, mut stdin, rx) = start();
    // One at a time, then small groups: none may wait for a batch to fill.
    let mut id = 0;
    for group in [1, 1, 3, 1, 7, 2] {
        let text: String = (id..id + group).map(|i| case(i) + "\n").collect();
        stdin.write_all(text.as_bytes()).unwrap();
        stdin.flush().unwrap();
        for want in id..id + group {
            let line = next_line(&rx, &format!("case {want}"));
            assert_eq!(id_of(&line), want as u64);
        }
        id += group;
    }
    drop(stdin);
    assert!(child.wait().unwrap().success());
    assert!(rx.recv().is_err(), "nothing after the last answer");
}

#[test]
fn a_killed_run_keeps_every_answer_it_wrote() {
    let cases: String = (0..300).map(|i| case(i) + "\n").collect();
    // The whole answer of an uninterrupted run.
    let whole = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args(["solve", "--jobs", "2", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .and_then(|mut child| {
            child.stdin.take().unwrap().write_all(cases.as_bytes())?;
            child.wait_with_output()
        })
        .unwrap();
    let whole = String::from_utf8(whole.stdout).unwrap();
    let whole: Vec<&str> = whole.lines().collect();
    assert_eq!(whole.len(), 300);
    for kill_after in [1, 137, 300] {
        let (mut child, mut stdin, rx) = start();
        stdin.write_all(cases.as_bytes()).unwrap();
        stdin.flush().unwrap();
        let got: Vec<String> = (0..kill_after)
            .map(|i| next_line(&rx, &format!("case {i}")))
            .collect();
        child.kill().unwrap(); // SIGKILL: nothing is flushed at exit
        child.wait().unwrap();
        // Whatever else was already written also survives, and is whole.
        let after: Vec<String> = rx.iter().collect();
        let all: Vec<&String> = got.iter().chain(&after).collect();
        assert!(all.len() >= kill_after);
        for (i, line) in all.iter().enumerate() {
            assert_eq!(line.as_str(), whole[i], "answer {i} after a kill");
        }
    }
}

/// The peak resident memory of a running process, in kB (Linux).
fn peak_kb(child: &Child) -> u64 {
    let status = std::fs::read_to_string(format!("/proc/{}/status", child.id())).unwrap();
    let line = status.lines().find(|l| l.starts_with("VmHWM:")).unwrap();
    line.split_whitespace().nth(1).unwrap().parse().unwrap()
}

/// Feed `count` cases, read all the answers, and measure the peak memory before the
/// input ends.
fn peak_after(count: usize) -> u64 {
    let (mut child, mut stdin, rx) = start();
    let writer = std::thread::spawn(move || {
        let mut out = std::io::BufWriter::new(&mut stdin);
        for i in 0..count {
            out.write_all(case(i).as_bytes()).unwrap();
            out.write_all(b"\n").unwrap();
        }
        out.flush().unwrap();
        drop(out);
        stdin
    });
    for i in 0..count {
        let line = next_line(&rx, &format!("case {i}"));
        assert_eq!(id_of(&line), i as u64);
    }
    let peak = peak_kb(&child);
    drop(writer.join().unwrap());
    assert!(child.wait().unwrap().success());
    peak
}

#[test]
fn memory_stays_flat_however_many_cases_stream_through() {
    let small = peak_after(2_000);
    let large = peak_after(200_000); // about 30 MB of input
    assert!(
        large < small + small / 2 + 8_192,
        "peak memory {small} kB after 2 000 cases, {large} kB after 200 000"
    );
}
