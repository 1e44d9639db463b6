#!/usr/bin/env bash
# The thesis's examples beside the original tool's own grammars, for
# docs/gallery.md: each of the tool's files (tests/import/model_gen-examples)
# imported by `g2d import` and run by g2d, the nearest honest "original" (the
# tool itself does not run here), next to g2d's hand-written example, same
# seed and steps. Renders docs/gallery/thesis/*.png and prints the page's
# section (Markdown) on stdout; with --update it puts the section into
# docs/gallery.md between its markers instead (scripts/gallery.sh calls it).
# G2D names the g2d binary (default build/release/bin/g2d); needs rsvg-convert.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
g2d="${G2D:-$root/build/release/bin/g2d}"
yml="$root/tests/import/model_gen-examples"
out=docs/gallery/thesis
mkdir -p "$out"
rm -f "$out"/*.png
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
ln -s "$root/examples/assets" "$work/assets"   # for the imported painted tree

# name | the tool's file | g2d's example | seed | steps ("" = to the end) | caption
pairs=(
  "koch|koch_flake|koch_snowflake|1|192|Koch snowflake (thesis §7.1), 192 steps as in the paper"
  "tree|tree|tree|1|200|Tree (thesis §7.3), 200 steps"
  "tree_painting|tree_painting|tree_painting|1||Painted tree (thesis §7.3, Fig. 7.17)"
  "facade|facade|facade_varied|1||Varied façade (thesis Fig. 7.21, the paper's 116 steps)"
  "facade3|ex_shape_ex1_facade3|facade|1||Façade (thesis Fig. 7.20)"
  "pattern_circle|pattern_circle|pattern_circle|4||Circular pattern (thesis §7.2.2; seed 4 draws the thesis's 9 leaves)"
  "pattern_square|pattern_square|pattern_square|1||Square pattern (thesis §7.2.1)"
)

# What still differs, per pair (Markdown bullets).
differences() {
  case $1 in
    koch) cat <<'EOF'
* The spike: the tool's file puts the new tip at `1/3 · perp_left(v)`, as
  the thesis's table says; g2d's example uses the exact `√3/6`, so the
  tool's spikes are taller and its curve bends.
* The order of growth: at 192 steps (short of level 4's 255) the tool's
  file picks the oldest segment by the tool's `.generation` (imported as
  `pick oldest generation`), g2d's example by age (`pick oldest`); the
  unsplit segments lie elsewhere. Both end alike at whole levels.
* The imported nodes are the tool's invisible circles (stroke width 0, r 0.4
  cm), which widen the margin; the example draws no nodes.
EOF
    ;;
    tree) cat <<'EOF'
* The branches' random angles: the tool's file draws them in its own order,
  the example through `stdlib/plants.g2d`; the same seed gives other trees.
* The order of growth: `pick oldest generation` (the tool's measure) against
  the example's `pick oldest` (age): at 200 steps other branches are grown.
* Same widths (10 px = 0.282 units, × 0.7 per segment) and butt ends.
EOF
    ;;
    tree_painting) cat <<'EOF'
* The tool's brush image `brush2.png` was never published: both sides use
  `examples/assets/brush.png` (the imported file's href is replaced).
* Random angles and growth order differ as for the tree; both grow 150 steps
  and paint every segment (602 steps).
EOF
    ;;
    facade) cat <<'EOF'
* The same sizes, colours, widths and layers (each fill over its frame's
  inner half, the blind's outline over the glass); a few blinds hang to other
  depths, as the two grammars draw the random depths in another order.
* The tool ended with 18 dangling edges (invisible); g2d deletes them, so
  450 elements against the tool's 468.
EOF
    ;;
    facade3) cat <<'EOF'
* The same picture, pixel for pixel. 147 edges against the tool's 165: g2d
  deletes the 18 it left dangling.
EOF
    ;;
    pattern_circle) cat <<'EOF'
* The tool built each leaf's path in SVG pixels with y down (`{s.x*35}`);
  both g2d grammars write it in graph units, y up, so the tool's own picture
  was this one mirrored top to bottom, scaled by 35 / 35.43307.
* Otherwise the same picture: the same random draws give the same leaves.
EOF
    ;;
    pattern_square) cat <<'EOF'
* The same picture, pixel for pixel: the same random draws give the same
  dots and lines. (The thesis's 128 steps / 294 elements cannot come from
  this file.)
EOF
    ;;
  esac
}

# run FILE SEED STEPS PNG: renders the run; prints "steps elements stopped".
run() {
  local file=$1 seed=$2 steps=$3 png=$4 stats
  stats=$(cd "$work" && "$g2d" run "$file" --seed "$seed" ${steps:+--steps "$steps"} -q -o "$work/run.svg" --embed-images --stats)
  rsvg-convert -w 400 -h 400 --keep-aspect-ratio -b white "$work/run.svg" -o "$png"   # within 400 × 400
  python3 -c 'import json,sys; d=json.loads(sys.argv[1]); print(d["steps"], d["nodes"] + d["edges"], d["stopped"])' "$stats"
}

section() {
  echo "## The thesis's examples beside the original tool's grammars"
  echo
  echo "Left, the tool's own grammar file imported by \`g2d import\` (docs/import.md)"
  echo "and run by g2d: the tool itself does not run here, and its grammar, drawn"
  echo "as the tool drew (its units and order), is the nearest honest original."
  echo "Right, g2d's hand-written example. Same seed and steps; made by"
  echo "\`scripts/gallery_thesis.sh\`. Below each pair, what differs between the"
  echo "two. What g2d does not reproduce of the tool itself shows on neither side:"
  echo "its Python random numbers and set orders (docs/import.md, \"What differs\"),"
  echo "and its frame, the vertices' bounding box without margin, which cut the"
  echo "strokes and shapes at the border (g2d frames every element, with a 2 %"
  echo "margin)."
  echo
  for entry in "${pairs[@]}"; do
    IFS='|' read -r name tool example seed steps caption <<<"$entry"
    "$g2d" import -q "$yml/$tool.yml" -o "$work/$tool.g2d"
    sed -i 's|"brush2.png"|"assets/brush.png"|g' "$work/$tool.g2d"
    read -r s1 e1 stop1 < <(run "$work/$tool.g2d" "$seed" "$steps" "$out/$name-tool.png")
    read -r s2 e2 stop2 < <(run "$root/examples/$example.g2d" "$seed" "$steps" "$out/$name-g2d.png")
    echo "### $caption"
    echo
    echo "| | grammar | seed | steps | elements | stopped |"
    echo "|---|---|---:|---:|---:|---|"
    echo "| left | the tool's \`$tool.yml\`, imported | $seed | $s1 | $e1 | $stop1 |"
    echo "| right | [\`examples/$example.g2d\`](../examples/$example.g2d) | $seed | $s2 | $e2 | $stop2 |"
    echo
    echo "<img src=\"gallery/thesis/$name-tool.png\" alt=\"$tool.yml imported, seed $seed\"> <img src=\"gallery/thesis/$name-g2d.png\" alt=\"$example.g2d, seed $seed\">"
    echo
    differences "$name"
    echo
  done
}

if [ "${1:-}" = --update ]; then
  section >"$work/section.md"
  python3 - "$work/section.md" <<'EOF'
import sys
page, begin, end = 'docs/gallery.md', '<!-- thesis:begin -->', '<!-- thesis:end -->'
text = open(page).read()
head, rest = text.split(begin, 1)
tail = rest.split(end, 1)[1]
open(page, 'w').write(head + begin + '\n' + open(sys.argv[1]).read() + end + tail)
EOF
  echo "updated the thesis section of docs/gallery.md and $(ls "$out" | wc -l) images in $out"
else
  section
fi
