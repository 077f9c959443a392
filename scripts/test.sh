#!/usr/bin/env bash
# Run the whole test suite on a fresh Debian machine: install the system packages,
# then build and test everything (library, CLI, ITF1788 vectors, CGAL differential
# tests) in release mode, in one cargo invocation (BUILD-NOTES.md: a second invocation
# rebuilds the C++ once).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cargo test --release --features cgal "$@"
