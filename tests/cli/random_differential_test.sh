#!/usr/bin/env bash
# Random valid grammars (tests/gen/random_grammar.py), each interpreted and
# compiled for two seeds: the outputs must be byte-identical. Incremental
# matching is checked after every step as well (--verify-matches: the back
# ends share it, so comparing their outputs alone would not catch a lost match).
# Usage: random_differential_test.sh G2D SOURCE_DIR FIRST LAST [GENERATOR]
# GENERATOR: a script of tests/gen/ (default random_grammar.py).
set -u
g2d="$1"; src="$2"; first="$3"; last="$4"; generator="${5:-random_grammar.py}"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
failures=0
for n in $(seq "$first" "$last"); do
  python3 "$src/tests/gen/$generator" "$n" > "$work/random_$n.g2d"
  if ! "$g2d" check "$work/random_$n.g2d" 2>"$work/check.txt"; then
    echo "FAIL: generated grammar $n is invalid (a generator bug):"; cat "$work/check.txt"; failures=$((failures + 1)); continue
  fi
  if ! bash "$src/tests/cli/differential_test.sh" --verify-matches "$g2d" "$work/random_$n.g2d" 1 2 > "$work/diff.txt" 2>&1; then
    echo "FAIL: grammar $n:"; cat "$work/diff.txt"; cp "$work/random_$n.g2d" "/tmp/g2d-random-failure-$n.g2d"
    echo "(kept as /tmp/g2d-random-failure-$n.g2d)"; failures=$((failures + 1))
  else
    echo "grammar $n: same output ($(head -1 "$work/diff.txt"))"
  fi
done
echo "$failures failed"
[ "$failures" = 0 ]
