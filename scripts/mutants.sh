#!/usr/bin/env bash
# The suite's own proof (issue 21): deliberate faults in src/, each of which must make
# at least one test fail. cargo-mutants is not available offline, so the faults are
# written here as exact text replacements; each is applied in place (the file saved
# first), the named tests run, and the file is restored (also on interrupt). Run it
# on a clean tree: it edits src/ while it runs.
#
#   scripts/mutants.sh            all mutants
#   scripts/mutants.sh M2 M4      some of them
#
# Prints one line per mutant: KILLED (some test failed, as it must), SURVIVED (no test
# failed: the suite is too weak there), or STALE (the text to replace is gone: update
# the mutant). Exit status 1 if any mutant survived or is stale. Results are recorded
# in tests/README.md.
set -uo pipefail
cd "$(dirname "$0")/.."
export CARGO_PROFILE_RELEASE_INCREMENTAL=true

# id @ file @ text @ replacement @ test files (tests/<name>.rs; each runs inside its suite)
MUTANTS=(
  "M1@src/num/mpfr_interval/mod.rs@let lo = self.lo.to_f64_round(Round::Down);@let lo = self.lo.to_f64_round(Round::Up);@cli_curved curved_forms intersect_three_surfaces verify_rational"
  "M2@src/ops/certified/seam.rs@if !unknowns.periodic.iter().any(|&p| p) {@if true {@cli_curved"
  "M3@src/certify/ledger.rs@        let status = roots@        roots.truncate(roots.len() - usize::from(roots.len() > 2));\n        let status = roots@intersect_curves project_surface curved_forms"
  "M4@src/certify/ledger.rs@let complete = self.undecided.is_empty();@let complete = true;@certify_systems certify_properties"
  "M5@src/certify/ledger.rs@perturbation: Some(d.perturbation()),@perturbation: Some(d.perturbation() * 1e-6),@certify_properties certify_systems intersect_curve_surface"
  "M6@src/ops/algebraic/line_surface.rs@sign_at_root(&mut h.t, &s) != std::cmp::Ordering::Less@sign_at_root(&mut h.t, &s) != std::cmp::Ordering::Equal@ops_algebraic"
)

want=("$@")
status=0
for m in "${MUTANTS[@]}"; do
  IFS='@' read -r id file from to tests <<<"$m"
  if [ ${#want[@]} -gt 0 ] && [[ ! " ${want[*]} " =~ " $id " ]]; then
    continue
  fi
  backup=$(mktemp)
  cp "$file" "$backup"
  trap 'cp "$backup" "$file"; exit 130' INT TERM
  if ! FROM="$from" TO="$to" python3 - "$file" <<'PY'
import os, sys
p = sys.argv[1]
s = open(p).read()
frm, to = os.environ["FROM"], os.environ["TO"].replace("\\n", "\n")
if s.count(frm) != 1:
    sys.exit(1)
open(p, "w").write(s.replace(frm, to))
PY
  then
    echo "$id STALE ($file: the text to replace is not there exactly once)"
    status=1
    rm -f "$backup"
    continue
  fi
  # A test file is a module of one suite binary (tests/suites/): run that suite,
  # filtered to the file's module.
  args=()
  filters=()
  for t in $tests; do
    suite=$(grep -l "^mod $t;" tests/suites/*.rs | head -1)
    suite=$(basename "${suite:-tests/$t.rs}" .rs)
    [[ " ${args[*]} " =~ " $suite " ]] || args+=(--test "$suite")
    filters+=("$t::")
  done
  if cargo test --release --features cgal "${args[@]}" -- "${filters[@]}" >"/tmp/mutant-$id.log" 2>&1; then
    echo "$id SURVIVED ($file; tests: $tests; log /tmp/mutant-$id.log)"
    status=1
  else
    failed=$(grep -E '^test .* FAILED$|^error: could not compile' "/tmp/mutant-$id.log" | head -3 | tr '\n' ' ')
    echo "$id KILLED by: $failed"
  fi
  cp "$backup" "$file"
  rm -f "$backup"
  trap - INT TERM
done
exit $status
