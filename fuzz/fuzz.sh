#!/usr/bin/env bash
# Build the fuzz targets with libFuzzer on the stable toolchain and run one of them
# (docs/RELIABILITY.md). Usage:
#   fuzz/fuzz.sh build                 # instrumented build of every target
#   fuzz/fuzz.sh run TARGET [SECONDS]  # fuzz TARGET (default 600 s) from its corpus
#   fuzz/fuzz.sh merge TARGET DIR      # add DIR's new coverage to fuzz/corpus/TARGET
# Findings (crashes, timeouts, out-of-memory) land in fuzz/artifacts/TARGET/; the run
# goes on after one (libFuzzer's fork mode), so one finding does not end a campaign.
# No nightly: coverage comes from LLVM's SanitizerCoverage pass, asked for with
# stable `-C passes`/`-C llvm-args` flags; no AddressSanitizer (it needs -Zsanitizer),
# which safe Rust does not need. An explicit --target keeps the flags off build scripts.
set -euo pipefail
cd "$(dirname "$0")"
TRIPLE=$(rustc -vV | sed -n 's/^host: //p')
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$PWD/target}
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
BIN=$CARGO_TARGET_DIR/$TRIPLE/release
case "${1:-}" in
  build)
    cargo build --release --target "$TRIPLE" --bins ;;
  run)
    t=$2; secs=${3:-600}
    mkdir -p "corpus/$t" "artifacts/$t" "$CARGO_TARGET_DIR/work/$t"
    len=4096; [ "$t" = json_lines ] && len=16384
    "$BIN/$t" "$CARGO_TARGET_DIR/work/$t" "corpus/$t" -max_total_time="$secs" \
      -max_len=$len -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
      -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
      -artifact_prefix="artifacts/$t/" ;;
  merge)
    t=$2
    "$BIN/$t" -merge=1 -max_len=16384 -timeout=10 "corpus/$t" "$3" ;;
  *)
    sed -n 2,7p "$0"; exit 2 ;;
esac
