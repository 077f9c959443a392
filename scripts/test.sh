#!/usr/bin/env bash
# Run the whole test suite on a fresh Debian machine: check the toolchain, install the
# system packages, then build and test everything (library, CLI, ITF1788 vectors, CGAL
# differential tests) in release mode, in one cargo invocation (BUILD-NOTES.md: a
# second invocation rebuilds the C++ once). Then the checks CI holds the code to:
# formatting, clippy with warnings denied, and the documentation with warnings denied.
# Arguments go to `cargo test` (then only the tests run, not the checks).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/check-rust.sh
scripts/install-deps.sh test
cargo test --release --features cgal "$@"
if [ $# -gt 0 ]; then
  exit 0
fi
echo "== cargo fmt --check" >&2
cargo fmt --all -- --check
echo "== cargo clippy (warnings denied)" >&2
cargo clippy --release --features cgal --all-targets -- -D warnings
echo "== cargo doc (warnings denied)" >&2
RUSTDOCFLAGS="-D warnings" cargo doc --release --no-deps --features cgal
