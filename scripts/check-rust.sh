#!/usr/bin/env bash
# Check that the Rust toolchain is at least the crate's MSRV (Cargo.toml rust-version),
# with a message that says what to do when it is not.
set -euo pipefail
cd "$(dirname "$0")/.."
msrv=$(sed -n 's/^rust-version *= *"\([0-9.]*\)".*/\1/p' Cargo.toml)
if ! command -v cargo >/dev/null 2>&1 || ! command -v rustc >/dev/null 2>&1; then
  echo "geocert needs Rust $msrv or newer, and cargo/rustc are not on PATH." >&2
  echo "Install it with rustup (https://rustup.rs), then run this script again." >&2
  exit 1
fi
have=$(rustc --version | sed -n 's/^rustc \([0-9]*\.[0-9]*\(\.[0-9]*\)\?\).*/\1/p')
# The older of the two, by version order: if it is not the MSRV, rustc is too old.
older=$(printf '%s\n%s\n' "$msrv" "$have" | sort -V | head -n1)
if [ -z "$have" ] || { [ "$older" != "$msrv" ] && [ "$have" != "$msrv" ]; }; then
  echo "geocert needs Rust $msrv or newer (Cargo.toml rust-version); found: $(rustc --version)." >&2
  echo "Update with 'rustup update stable', or install a newer toolchain." >&2
  exit 1
fi
