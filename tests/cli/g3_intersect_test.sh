#!/usr/bin/env bash
# `intersect` (docs/language.md §16.8) beyond Create edge and Create face:
# a thick edge against a face by its radius, an Edit node, a Split edge and
# a Split face undone exactly (the graph as if the rule had not matched:
# byte-identical JSON), growth over a background face in 2D, and --stats'
# rejected_intersections. Interpreted and compiled runs give the same bytes.
# Usage: g3_intersect_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the interpreter only)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
dir="$src/tests/cli"

# stats STEM GRAMMAR ARGS...: runs it with --stats and --json i_STEM.json (and
# the compiled program, which must write the same bytes and numbers); the
# stats line without its seconds goes to STEM.stats.
stats() {
  local stem=$1 grammar=$2; shift 2
  expect_code 0 "$g2d" run "$grammar" "$@" --stats --json "i_$stem.json" --no-svg --verify-matches
  sed 's/"seconds": [^,]*, //' out.txt > "$stem.stats"
  if [ "$compiled" = yes ]; then
    [ -x "prog_$(basename "$grammar" .g2d)" ] || expect_code 0 "$g2d" build "$grammar" -o "prog_$(basename "$grammar" .g2d)"
    compiled_same "./prog_$(basename "$grammar" .g2d)" "$stem" json "$@" --stats
    sed 's/"seconds": [^,]*, //' out.txt | cmp -s - "$stem.stats" || fail "$stem: compiled stats differ: $(cat out.txt)"
  fi
}
line() {   # line STEM NODES EDGES FACES APPLICATIONS REJECTED [STEPS]
  local want="{\"steps\": ${7:-1}, \"nodes\": $2, \"edges\": $3, \"faces\": $4, \"seed\": 1, \"stopped\": \"terminal\", \"applications\": $5, "
  want+="\"lookahead_guesses\": 0, \"lookahead_hits\": 0, \"repairs\": REPAIRS, \"repairs_skipped\": 0, \"rejected_drawings\": 0, "
  want+="\"rejected_by_cost\": 0, \"rejected_splits\": 0, \"bends_reduced\": 0, \"faces_against_neighbours\": 0, \"inserts_without_side\": 0, "
  want+="\"compounds_without_instances\": 0, \"rejected_intersections\": $6}"
  local got; got=$(sed 's/"repairs": [0-9]*,/"repairs": REPAIRS,/' "$1.stats")
  [ "$got" = "$want" ] || fail "$1: stats $got (wanted $want)"
}

# A branch of radius 0.1 grown towards a wall: ending 0.01 from it, it is
# refused (its cylinder reaches the wall); 0.2 from it, kept. Its tip's
# radius then swells to 0.5: the branch (the mean, 0.3) would reach the
# wall, and the radius is put back; to 0.15 (the mean 0.125), it is kept.
stats near "$dir/intersect_thick.g2d" -D gap=0.01
line near 5 4 1 0 1 2
stats clear "$dir/intersect_thick.g2d" -D gap=0.2
line clear 6 5 1 1 1 2
stats swell "$dir/intersect_thick.g2d" -D gap=0.2 -D swell=0.15
line swell 6 5 1 2 0 2
python3 - i_clear.json i_swell.json <<'PY' || fail "wrong radii"
import json, sys
tips = [[v["radius"] for v in json.load(open(f))["nodes"] if v["kind"] == "N" and v["pos"][0] > 0.5] for f in sys.argv[1:]]
assert tips == [[0.1], [0.15]], tips
PY

# Edit node: the stick whose drop would cross the bar is put back, the other drops.
stats move "$dir/intersect_move.g2d"
line move 6 3 0 1 1
stats move_none "$dir/intersect_move.g2d" -D go=false
cmp -s i_move.json i_move_none.json || fail "an undone move left the graph changed"
python3 - i_move.json <<'PY' || fail "wrong moves"
import json, sys
pos = sorted(tuple(v["pos"]) for v in json.load(open(sys.argv[1]))["nodes"])
assert pos == [(0, 0), (1, 1), (1, 2), (2, 0), (3, -0.5), (3, 1)], pos
PY

# Split edge and Split face under sticks: both undone, the graph exactly as
# when neither matched (the triangle's corners, the square back with its id);
# moved clear (`far`), both kept.
stats split "$dir/intersect_split.g2d"
line split 11 9 2 0 2 2
stats split_none "$dir/intersect_split.g2d" -D go=false
cmp -s i_split.json i_split_none.json || fail "an undone split left the graph changed"
stats split_far "$dir/intersect_split.g2d" -D far=true
line split_far 13 14 5 2 0 2
python3 - i_split_far.json <<'PY' || fail "wrong splits"
import json, sys
faces = json.load(open(sys.argv[1]))["faces"]
assert [len(f["corners"]) for f in faces] == [4, 3, 3, 3, 3], faces
assert faces[0]["id"] == 0 and [f["id"] for f in faces[1:]] == [2, 3, 4, 5], faces
PY

# 2D: growth over a background face, refused only where it would cross the outline.
stats plane "$dir/intersect_plane.g2d"
line plane 7 2 1 2 2 4
python3 - i_plane.json <<'PY' || fail "wrong growth"
import json, sys
pos = [v["pos"] for v in json.load(open(sys.argv[1]))["nodes"] if v["kind"] == "N"]
assert pos == [[0, 0], [2, 1], [4, 2]], pos
PY
finish
