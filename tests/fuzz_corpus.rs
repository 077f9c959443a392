//! Replays every committed fuzz corpus input (`fuzz/corpus/<target>/`) and every
//! recorded finding (`fuzz/findings/<target>/`) through the fuzz targets, uninstrumented,
//! as an ordinary test: the short fuzz pass CI runs (docs/RELIABILITY.md). A target
//! checks the promise on each input (no panic, an answer or a typed error, boxes
//! around estimates, linear answers equal to the exact truth) and panics when it fails.

#[path = "../fuzz/src/targets/mod.rs"]
#[allow(dead_code)]
mod targets;

use std::path::{Path, PathBuf};

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
