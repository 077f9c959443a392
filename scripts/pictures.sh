#!/usr/bin/env bash
# Redraw the pictures of the worked examples (docs/pictures/examples.jsonl, one case per
# example of OPERATIONS.md §16 that is an operation of geocert) into
# docs/pictures/examples/: SVG with titles, as README.md shows them.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
rm -rf docs/pictures/examples
target/release/geocert render docs/pictures/examples.jsonl --out docs/pictures/examples --size 640x500
