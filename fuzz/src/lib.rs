//! geocert's fuzz targets (see `targets`); the binaries in `fuzz_targets/` hand them to
//! libFuzzer. `tests/fuzz_corpus.rs` in the main crate includes the same module.

pub mod targets;
