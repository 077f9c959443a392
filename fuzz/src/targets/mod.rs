//! The fuzz targets of geocert, shared by the coverage-guided fuzzers (`fuzz/`, libFuzzer
//! on the stable toolchain) and by `tests/fuzz_corpus.rs`, which replays the committed
//! corpus through the same functions as an ordinary test (docs/RELIABILITY.md).
//!
//! Every target takes raw bytes. `json_lines` reads them as a case file, through the
//! path `geocert solve` uses (the stream reader, `read_chunk`, `solve_case`, the result
//! record). The structure-aware targets decode the bytes with `arbitrary` into a case of
//! one operation family, built valid most of the time and near-degenerate often (ulp
//! perturbations, near-tangencies, huge and tiny magnitudes), and check the promise:
//! no panic, an answer or a typed error, every box around its estimate, and for the
//! linear constructions the certified answer equal to the exact rational truth
//! (computed here independently with `rug`).
//!
//! A failed check panics: libFuzzer records the input as a crash, the replay test fails.

mod check;
mod curved;
mod json;
mod linear;
mod num;
mod objects;

pub use curved::{curve_curve, curve_surface, project, surface_surface};
pub use json::json_lines;
pub use linear::linear;

/// A fuzz target: it panics when a check fails.
pub type Target = fn(&[u8]);

/// Every target by name: the directory of its corpus under `fuzz/corpus/`.
pub const TARGETS: &[(&str, Target)] = &[
    ("json_lines", json_lines),
    ("linear", linear),
    ("curve_curve", curve_curve),
    ("curve_surface", curve_surface),
    ("project", project),
    ("surface_surface", surface_surface),
];

/// The budget every fuzzed case runs under (seconds): small, so that one input costs
/// little and a case that ignores its budget shows up as a libFuzzer timeout.
pub const TIME_LIMIT: f64 = 0.25;
/// The box budget every structured case runs under.
pub const MAX_BOXES: u64 = 2000;
