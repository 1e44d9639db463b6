#!/usr/bin/env bash
# Differential fuzzing: random valid grammars (tests/gen/random_grammar.py),
# each run interpreted and compiled for two seeds with --verify-matches; the
# SVG, JSON and error messages must be byte-identical, and every run must
# succeed. Runs for SECONDS, from grammar FIRST on (seeds go up by one), so a
# later run can go on where an earlier one stopped. A failing grammar is kept
# in build/fuzz-differential/ with what differed.
# Usage: scripts/fuzz-differential.sh [SECONDS] [FIRST]   (default 600 s from 1000)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"; first="${2:-1000}"
[ -x build/release/bin/g2d ] || bash scripts/build.sh release
g2d="$PWD/build/release/bin/g2d"
out=build/fuzz-differential
mkdir -p "$out"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
end=$(( $(date +%s) + seconds ))
n=$first; tried=0; failed=0
while [ "$(date +%s)" -lt "$end" ]; do
  python3 tests/gen/random_grammar.py "$n" > "$work/random_$n.g2d"
  if ! "$g2d" check "$work/random_$n.g2d" 2>"$work/check.txt"; then
    echo "grammar $n: invalid (a generator bug)"; cp "$work/random_$n.g2d" "$out/"
    cp "$work/check.txt" "$out/random_$n.check.txt"; failed=$((failed + 1))
  elif ! bash tests/cli/differential_test.sh --verify-matches "$g2d" "$work/random_$n.g2d" 1 2 > "$work/diff.txt" 2>&1; then
    echo "grammar $n: FAILED"; grep FAIL "$work/diff.txt" | head -5
    cp "$work/random_$n.g2d" "$out/"; cp "$work/diff.txt" "$out/random_$n.diff.txt"; failed=$((failed + 1))
  fi
  tried=$((tried + 1)); n=$((n + 1))
done
echo "grammars $first..$((n - 1)): $tried tried, $failed failed (kept in $out/); next time start at $n"
[ "$failed" = 0 ]
