#!/usr/bin/env bash
# The main job: check the toolchain, install the system packages the binary needs if
# missing (GMP, MPFR, m4, pkg-config, gcc; not CGAL, which only the tests use), then build
# and run `geocert demo`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/check-rust.sh
scripts/install-deps.sh demo
cargo run --release -- demo "$@"
