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

fn replay(kind: &str, min: usize) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join(kind);
    let mut total = 0;
    for (name, target) in targets::TARGETS {
        for file in inputs(&root.join(name)) {
            let data = std::fs::read(&file).unwrap();
            let run = std::panic::catch_unwind(|| target(&data));
            assert!(
                run.is_ok(),
                "{name}: {} fails (replay it with the fuzz binary)",
                file.display()
            );
            total += 1;
        }
    }
    assert!(total >= min, "only {total} inputs under {}", root.display());
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
