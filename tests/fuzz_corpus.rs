//! Replays every committed fuzz corpus input (`fuzz/corpus/<target>/`) and every
//! recorded finding (`fuzz/findings/<target>/`) through the fuzz targets, uninstrumented,
//! as an ordinary test, then fuzzes them for a minute: the short fuzz pass CI runs
//! (docs/RELIABILITY.md). A target checks the promise on each input (no panic, an
//! answer or a typed error, boxes around estimates, linear answers equal to the exact
//! truth) and panics when it fails.
//!
//! The minute of fuzzing mutates corpus inputs as libFuzzer's mutators do (bit flips,
//! interesting bytes, insertions, deletions, copies, crossover with another input of
//! the same target, and for the JSON target numbers replaced by edge values), without
//! coverage feedback: the coverage-guided campaigns run by hand with `fuzz/fuzz.sh`
//! (its instrumented build alone takes longer than CI's budget allows). CI uses a fixed
//! seed, so a failure there is a regression, not luck; `GEOCERT_FUZZ_SEED` and
//! `GEOCERT_FUZZ_SECONDS` run other seeds and longer passes by hand.

#[path = "../fuzz/src/targets/mod.rs"]
#[allow(dead_code)]
mod targets;

use geocert::num::rng::Rng;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn inputs(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .map(|e| e.expect("a readable corpus directory").path())
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    files
}

/// Replay every input of `fuzz/<kind>/<target>/`, on two threads (CI has two cores;
/// the corpus replay is one of the longest tests of the `cli` suite).
fn replay(kind: &str, min: usize) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join(kind);
    let mut work = Vec::new();
    for (name, target) in targets::TARGETS {
        for file in inputs(&root.join(name)) {
            work.push((*name, *target, file));
        }
    }
    let failures: Vec<String> = std::thread::scope(|s| {
        let lanes: Vec<_> = (0..2)
            .map(|lane| {
                let work = &work;
                s.spawn(move || {
                    work.iter()
                        .skip(lane)
                        .step_by(2)
                        .filter_map(|(name, target, file)| {
                            let data = std::fs::read(file).unwrap();
                            std::panic::catch_unwind(|| target(&data))
                                .is_err()
                                .then(|| {
                                    format!(
                                        "{name}: {} fails (replay it with the fuzz binary)",
                                        file.display()
                                    )
                                })
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        lanes
            .into_iter()
            .flat_map(|h| h.join().expect("a replay lane"))
            .collect()
    });
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        work.len() >= min,
        "only {} inputs under {}",
        work.len(),
        root.display()
    );
}

/// Every target has a committed corpus, and every input of it passes.
#[test]
fn corpus_inputs_pass() {
    for (name, _) in targets::TARGETS {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("fuzz/corpus")
            .join(name);
        assert!(!inputs(&dir).is_empty(), "no corpus for {name}");
    }
    replay("corpus", targets::TARGETS.len());
}

/// Every input that once failed (a finding, kept as a regression test) passes now.
#[test]
fn findings_pass() {
    replay("findings", 0);
}

/// Numbers a mutation may put in place of a number of a JSON case: edges of the double
/// range, signed zero, near-degenerate offsets, exact strings, non-numbers.
const EDGE_NUMBERS: &[&str] = &[
    "0",
    "-0",
    "1",
    "-1",
    "1e308",
    "-1e308",
    "1e309",
    "5e-324",
    "2.2250738585072014e-308",
    "1e-9",
    "1e-15",
    "4503599627370497",
    "9007199254740993",
    "\"1/3\"",
    "\"-0.1\"",
    "NaN",
    "null",
    "[]",
    "1e-300",
    "6.283185307179586",
];

/// One random mutation of `data` (module doc); `other` is another input of the target.
fn mutate(rng: &mut Rng, data: &mut Vec<u8>, other: &[u8], json: bool) {
    let pick = |rng: &mut Rng, n: usize| if n == 0 { 0 } else { rng.below(n) };
    match rng.below(if json { 8 } else { 7 }) {
        0 if !data.is_empty() => {
            let i = pick(rng, data.len());
            data[i] ^= 1 << rng.below(8);
        }
        1 if !data.is_empty() => {
            let i = pick(rng, data.len());
            data[i] = [0, 1, 0x7f, 0x80, 0xff, b'-', b'9', b'e'][rng.below(8)];
        }
        2 => {
            let i = pick(rng, data.len() + 1);
            let bytes: Vec<u8> = (0..1 + rng.below(8))
                .map(|_| rng.below(256) as u8)
                .collect();
            data.splice(i..i, bytes);
        }
        3 if !data.is_empty() => {
            let i = pick(rng, data.len());
            let n = 1 + pick(rng, (data.len() - i).min(16));
            data.drain(i..i + n);
        }
        4 if !data.is_empty() => {
            // Copy a piece of the input over another place of it.
            let i = pick(rng, data.len());
            let n = 1 + pick(rng, (data.len() - i).min(32));
            let piece = data[i..i + n].to_vec();
            let j = pick(rng, data.len() + 1);
            data.splice(j..j, piece);
        }
        5 if !other.is_empty() => {
            // Crossover: a head of this input and a tail of the other.
            let i = pick(rng, data.len() + 1);
            let j = pick(rng, other.len());
            data.truncate(i);
            data.extend_from_slice(&other[j..]);
        }
        6 if !data.is_empty() => {
            // Repeat a piece (longer arrays, more lines).
            let i = pick(rng, data.len());
            let n = 1 + pick(rng, (data.len() - i).min(64));
            let piece = data[i..i + n].to_vec();
            data.splice(i..i, piece);
        }
        7 => {
            // A number of the case replaced by an edge value.
            let starts: Vec<usize> = (0..data.len())
                .filter(|&k| {
                    (data[k].is_ascii_digit() || data[k] == b'-')
                        && (k == 0 || !(data[k - 1].is_ascii_alphanumeric() || data[k - 1] == b'.'))
                })
                .collect();
            if starts.is_empty() {
                return;
            }
            let i = starts[rng.below(starts.len())];
            let mut j = i + 1;
            while j < data.len() && (data[j].is_ascii_alphanumeric() || b".+-".contains(&data[j])) {
                j += 1;
            }
            let edge = EDGE_NUMBERS[rng.below(EDGE_NUMBERS.len())]
                .as_bytes()
                .to_vec();
            data.splice(i..j, edge);
        }
        _ => {}
    }
}

fn env_number(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(default)
}

/// The mutation pass (module doc): two threads, each on its own seed, for the time
/// given; a failing or hanging input (over 10 s, libFuzzer's `-timeout` of
/// `fuzz/fuzz.sh`) is written under the test's temporary directory and reported.
#[test]
fn mutated_corpus_inputs_pass() {
    let seconds = env_number("GEOCERT_FUZZ_SECONDS", 60);
    let seed = env_number("GEOCERT_FUZZ_SEED", 0x0067_656f_6365_7274);
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus");
    let corpora: Vec<(&str, targets::Target, Vec<Vec<u8>>)> = targets::TARGETS
        .iter()
        .map(|(name, target)| {
            let inputs = inputs(&root.join(name))
                .iter()
                .map(|f| std::fs::read(f).unwrap())
                .collect();
            (*name, *target, inputs)
        })
        .collect();
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz-pass");
    let end = Instant::now() + Duration::from_secs(seconds);
    let results: Vec<(usize, Vec<String>)> = std::thread::scope(|s| {
        let lanes: Vec<_> = (0..2u64)
            .map(|lane| {
                let (corpora, out) = (&corpora, &out);
                s.spawn(move || {
                    let mut rng = Rng::new(seed ^ lane.wrapping_mul(0x9e37_79b9_7f4a_7c15));
                    let (mut runs, mut failures) = (0, Vec::new());
                    while Instant::now() < end && failures.len() < 5 {
                        let (name, target, inputs) = &corpora[rng.below(corpora.len())];
                        let mut data = inputs[rng.below(inputs.len())].clone();
                        let other = &inputs[rng.below(inputs.len())];
                        for _ in 0..1 + rng.below(4) {
                            mutate(&mut rng, &mut data, other, *name == "json_lines");
                        }
                        let start = Instant::now();
                        let failed = std::panic::catch_unwind(|| target(&data)).is_err();
                        let slow = start.elapsed() > Duration::from_secs(10);
                        runs += 1;
                        if failed || slow {
                            std::fs::create_dir_all(out).unwrap();
                            let file = out.join(format!("{name}-{lane}-{runs}"));
                            std::fs::write(&file, &data).unwrap();
                            failures.push(format!(
                                "{name}: {} {} (seed {seed}, lane {lane}; replay it, then keep it \
                                 under fuzz/findings/{name}/)",
                                file.display(),
                                if failed { "fails" } else { "runs over 10 s" }
                            ));
                        }
                    }
                    (runs, failures)
                })
            })
            .collect();
        lanes
            .into_iter()
            .map(|h| h.join().expect("a fuzz lane"))
            .collect()
    });
    let runs: usize = results.iter().map(|(n, _)| n).sum();
    let failures: Vec<String> = results.into_iter().flat_map(|(_, f)| f).collect();
    eprintln!("fuzz pass: {runs} mutated inputs in {seconds} s (seed {seed})");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(runs >= 100 || seconds < 10, "only {runs} inputs ran");
}
