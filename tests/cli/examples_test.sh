#!/usr/bin/env bash
# Every example: `g2d check --werror` passes, and `g2d run` completes for three
# seeds with no options but the seed (and --verify-matches: incremental
# matching checked after every step), writing well-formed SVG and JSON.
# Usage: examples_test.sh G2D SOURCE_DIR EXAMPLE.g2d
set -u
g2d="$1"; src="$2"; example="$3"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
"$g2d" check --werror "$example" || fail "g2d check --werror $example"
for seed in 1 2 3; do
  # Run from the example's folder so relative image paths resolve as in the gallery.
  (cd "$(dirname "$example")" && "$g2d" run "$example" --seed "$seed" -o "$work/out.svg" --json "$work/out.json" --stats --verify-matches) \
      >"$work/stats.txt" 2>"$work/err.txt" || { fail "seed $seed: $(cat "$work/err.txt")"; continue; }
  grep -q '"stopped": "\(terminal\|step_limit\)"' "$work/stats.txt" || fail "seed $seed: stats $(cat "$work/stats.txt")"
  grep -q 'warning' "$work/err.txt" && fail "seed $seed: warnings: $(cat "$work/err.txt")"
  xmllint --noout "$work/out.svg" || fail "seed $seed: SVG is not well-formed XML"
  python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['directed'] and d['multigraph']" "$work/out.json" \
      || fail "seed $seed: JSON does not parse as node-link"
  echo "seed $seed: $(cat "$work/stats.txt")"
done
echo "$failures failed"
[ "$failures" = 0 ]
