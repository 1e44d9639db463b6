#!/usr/bin/env bash
# Prints one line per output file of every example, seeds 1-3: the SHA-256 of
# its SVG, JSON and OBJ, written by the interpreter. Two revisions agree
# byte for byte when their snapshots are equal; the suite's
# `examples.compiled.*` tests hold compiled output to the interpreter's.
# Usage: bench/output_snapshot.sh G2D [EXAMPLES_DIR] > snapshot.txt
#   compare: diff <(bench/output_snapshot.sh old/g2d) <(bench/output_snapshot.sh new/g2d)
set -euo pipefail
g2d=$(realpath "$1")
examples=$(realpath "${2:-$(dirname "$0")/../examples}")
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
for example in "$examples"/*.g2d; do
  name=$(basename "$example" .g2d)
  for seed in 1 2 3; do
    # From the example's folder, so relative image paths resolve as in the gallery.
    if (cd "$examples" && "$g2d" run "$example" --seed "$seed" -o "$work/out.svg" \
          --json "$work/out.json" --obj "$work/out.obj") >/dev/null 2>"$work/err.txt"; then
      for f in "$work"/out.*; do
        echo "$(sha256sum <"$f" | cut -c1-16) $name seed $seed ${f##*.}"
      done
    else
      echo "failed $name seed $seed: $(head -1 "$work/err.txt")"
    fi
    rm -f "$work"/out.*
  done
done
