#!/usr/bin/env bash
# Renders every example to docs/gallery/*.png (several seeds for the random
# ones; 3D grammars through their --view page in headless Chromium) and
# writes docs/gallery.md with steps, elements and time per run, after the
# thesis's examples beside the tool's grammars (scripts/gallery_thesis.sh).
# Needs the release build (scripts/build.sh; or G2D=path/to/g2d) and
# rsvg-convert (librsvg2-bin, installed here if missing).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
g2d="${G2D:-$root/build/release/bin/g2d}"
[ -x "$g2d" ] || bash scripts/build.sh release
if ! command -v rsvg-convert >/dev/null; then
  sudo_cmd=(); [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq && "${sudo_cmd[@]}" apt-get install -y -qq librsvg2-bin
fi

out=docs/gallery
mkdir -p "$out"
rm -f "$out"/*.png
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
ln -s "$root/examples/assets" "$work/assets" 2>/dev/null || true

# name | seeds | caption
examples=(
  "koch_snowflake|1|Koch snowflake, level 4 (thesis §7.1)"
  "sierpinski|1|Sierpinski triangle, generation 5 (AGTIVE 2007 case), parallel steps"
  "tree|1 2 3 4|Tree (thesis §7.3), 200 steps"
  "tree_painting|1 2 3|Painted tree (thesis §7.3, Fig. 7.17)"
  "pattern_square|1 2 3|Tiling square pattern (thesis §7.2.1)"
  "pattern_circle|1 2 3 4|Circular pattern with Bézier leaves (thesis §7.2.2)"
  "facade|1 2 3|Façade with unrolled blinds (thesis §7.4)"
  "facade_varied|1 2 3|Varied façade with sills and a random door (thesis Fig. 7.21)"
  "lsystem_filament|1|L-system filament (original tool's example)"
  "lsystem_tree|1 2 3|L-system tree (original tool's example)"
  "mondrian|1 2 3|Mondrian subdivision (g2d example: weights, styles)"
  "maze|1 2 3|Maze: a grid built by rules, then carved (g2d example: NACs, phases)"
  "floor_plan|1|Floor plan: faces in the axiom (g2d example: face kinds, styles)"
  "koch_faces|1|Koch snowflake of faces, level 4 (g2d example: daughters create faces)"
  "fan|1|Fans: one rule for any corner count (g2d example: for (u, v) in f.sides)"
  "subdivide|1|Quad subdivision, depth 4 (g2d example: matched faces, parallel steps)"
  "stained_glass|1 2 3|Stained glass: panes split, then coloured unlike their neighbours (g2d example: faces sharing a side)"
  "g3_box|1|G^3's open box (Laganeckiene 2012, Table 3.1): Create face, then Split edge, with merging; 3D, drawn from the front right"
  "g3_grid_split|1|G^3's Fig. 3.11: Split edge and two-corner Split face cut squares into cells; Split face on the cells with eight neighbouring faces (\`-D squares=2\`: four)"
  "g3_compound|1|G^3's Fig. 3.12: the same commands as a compound on two squares: within each square's scope only its middle cell has eight neighbours"
  "g3_flags|1 2|G^3's flags (Fig. 3.7): Create edge, then Create face with intersection testing: a flag that would cut another is not made"
  "g3_tree_box|1|G^3's tree in a box (Figs 3.6, 5.4): Create edge with intersection testing against the walls and the tree itself"
  "g3_house|1|A house in the spirit of G^3's Fig. 5.1 (our own rules, of Table 5.1's size): windows and a door by compound commands, merging"
  "g3_cupboard|1|A cupboard in the spirit of G^3's Fig. 5.2: one compound gives drawers on narrow panels and doors on wide ones"
  "g3_sofa|1|A sofa in the spirit of G^3's Fig. 5.3: a maple-leaf compound on every tile, in any orientation"
  "g3_windmill|1|G^3's windmill compound (Figs 3.13, 3.14): Split face, Edit node, Create edge and Create face, sized by the face it starts from"
  "extrude|1|Extrusion of any footprint: one rule turns a triangle, a square and a hexagon into closed prisms (faces over a loop's turns: Top(all t)), storey on storey"
)

{
  echo "# Gallery"
  echo
  echo "Every example under [examples/](../examples/), derived with \`g2d run\` and"
  echo "rendered from its SVG with \`rsvg-convert\` (3D grammars: a screenshot of"
  echo "their \`--view\` page in headless Chromium) by \`scripts/gallery.sh\`. Random"
  echo "examples are shown for several seeds. *Elements* = nodes + edges at the end;"
  echo "*time* is the derivation alone (\`--stats\` seconds) of the interpreter, on"
  echo "the 2-core machine this page was made on. First, the thesis's examples"
  echo "beside the original tool's own grammars."
  echo
  echo "<!-- thesis:begin -->"
  G2D="$g2d" bash scripts/gallery_thesis.sh
  echo "<!-- thesis:end -->"
  echo
} > "$work/gallery.md"

for entry in "${examples[@]}"; do
  IFS='|' read -r name seeds caption <<<"$entry"
  file="examples/$name.g2d"
  [ -f "$file" ] || { echo "skipping $name (no $file)" >&2; continue; }
  {
    echo "## $name"
    echo
    echo "$caption — [\`$file\`](../$file)"
    echo
    echo "| seed | steps | elements | stopped | time |"
    echo "|---:|---:|---:|---|---:|"
  } >> "$work/gallery.md"
  images=""
  for seed in $seeds; do
    if grep -q '^space 3d;' "$file" && command -v chromium >/dev/null; then
      # 3D grammars: a screenshot of the --view page (three.js, software WebGL).
      stats=$(cd "$work" && "$g2d" run "$root/$file" --seed "$seed" --no-svg --view "$work/$name-$seed.html" --stats)
      timeout 120 chromium --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
        --host-resolver-rules="MAP * ~NOTFOUND" --hide-scrollbars --window-size=480,360 --virtual-time-budget=5000 \
        --screenshot="$out/$name-$seed.png" "file://$work/$name-$seed.html#hide=axes&panel=off" >/dev/null 2>&1
    else
      # Images embedded: librsvg reads no file outside the SVG's folder.
      stats=$(cd "$work" && "$g2d" run "$root/$file" --seed "$seed" -o "$work/$name-$seed.svg" --embed-images --stats)
      rsvg-convert -w 360 -b white "$work/$name-$seed.svg" -o "$out/$name-$seed.png"
    fi
    read -r steps nodes edges seconds stopped < <(python3 -c 'import json,sys; d=json.loads(sys.argv[1]); print(d["steps"], d["nodes"], d["edges"], d["seconds"], d["stopped"])' "$stats")
    printf '| %s | %s | %s | %s | %.4f s |\n' "$seed" "$steps" "$((nodes + edges))" "$stopped" "$seconds" >> "$work/gallery.md"
    images+="<img src=\"gallery/$name-$seed.png\" width=\"240\" alt=\"$name, seed $seed\"> "
  done
  { echo; echo "$images"; echo; } >> "$work/gallery.md"
done
mv "$work/gallery.md" docs/gallery.md
echo "wrote docs/gallery.md and $(ls "$out" | wc -l) images in $out"
