#!/usr/bin/env bash
# The main job: install the system packages if needed, then build and run `geocert demo`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cargo run --release -- demo "$@"
