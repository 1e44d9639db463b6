#!/usr/bin/env bash
# The thesis's examples draw as the original tool did (#32 item 3), both the
# hand-written ports and the tool's own grammars imported by `g2d import`:
# its units (1 unit = 1 cm = 35.43307 px; a default line is 1 mm; a plain
# .svg_stroke_width is px) and its drawing order (each part over the parts
# made before it: docs/import.md, "Drawing order").
# Usage: thesis_drawing_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
ex="$src/examples"
yml="$src/tests/import/model_gen-examples"
layers="$(dirname "$0")/fill_layers.py"

# stroke_widths SVG: the distinct stroke-width values of its lines, sorted.
stroke_widths() { grep -o '<line [^>]*stroke-width="[^"]*"' "$1" | sed 's/.*stroke-width="//; s/"$//' | sort -gu | tr '\n' ' '; }

for g in koch_flake tree facade pattern_circle; do expect_code 0 "$g2d" import -q "$yml/$g.yml" -o "imp_$g.g2d"; done
expect_code 0 "$g2d" import -q "$yml/ex_shape_ex1_facade3.yml" -o imp_facade3.g2d

# Koch: the tool's default line, 1 mm.
expect_code 0 "$g2d" run "$ex/koch_snowflake.g2d" -D max_lod=2 -o koch.svg
expect_code 0 "$g2d" run imp_koch_flake.g2d --steps 15 -o imp_koch.svg
for f in koch.svg imp_koch.svg; do
  [ "$(stroke_widths "$f")" = "0.1 " ] || fail "$f: line widths $(stroke_widths "$f"), wanted only 0.1 (1 mm)"
done

# Tree: .svg_stroke_width 10 (px), times 0.7 per level, is 10/35.43307 units.
expect_code 0 "$g2d" run "$ex/tree.g2d" --steps 20 -o tree.svg
expect_code 0 "$g2d" run imp_tree.g2d --steps 20 -o imp_tree.svg
for f in tree.svg imp_tree.svg; do
  python3 - "$f" <<'EOF' || fail "$f: trunk widths are not the tool's 10 px, 7 px"
import re, sys
widths = sorted({float(w) for w in re.findall(r'<line [^>]*stroke-width="([^"]*)"', open(sys.argv[1]).read())}, reverse=True)
sys.exit(0 if len(widths) >= 2 and abs(widths[0] - 10 / 35.43307) < 1e-12 and abs(widths[1] - 7 / 35.43307) < 1e-12 else 1)
EOF
done
grep -q 'stroke-linecap' tree.svg && fail "tree.svg: the tool's lines had no round caps"

# Façades: a window's glass over its frame, the blind's outline over the
# glass, the blind's cloth over its outline (16 windows and blinds, or 15
# windows beside the door).
for run in "$ex/facade.g2d:32:16" "$ex/facade_varied.g2d:31:15" "imp_facade3.g2d:32:16" "imp_facade.g2d:31:15"; do
  IFS=: read -r file outlined covered <<<"$run"
  name=$(basename "$file" .g2d)
  expect_code 0 "$g2d" run "$file" -o "$name.svg"
  python3 "$layers" "$name.svg" "$outlined" "$covered" || fail "$name: fills and outlines in the wrong order"
done

# Circular pattern: the disc (the axiom's vertex) under the leaves.
expect_code 0 "$g2d" run imp_pattern_circle.g2d -o imp_circle.svg
disc=$(grep -n '<circle [^>]*r="3.1"' imp_circle.svg | head -1 | cut -d: -f1)
leaf=$(grep -n '<path ' imp_circle.svg | head -1 | cut -d: -f1)
[ -n "$disc" ] && [ -n "$leaf" ] && [ "$disc" -lt "$leaf" ] || fail "imported pattern_circle: disc (line $disc) not under the leaves (line $leaf)"

finish
