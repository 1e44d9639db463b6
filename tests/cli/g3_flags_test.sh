#!/usr/bin/env bash
# examples/g3_flags.g2d: G^3's Fig. 3.7. Fifteen poles (Create edge), then a
# flag on each (Create face) turned at random. Without testing every pole
# has its flag; with intersection testing the flags that would cut through
# another are not made — the rest are the same flags, where they were — and
# every pole is still there. Interpreted and compiled runs give the same bytes.
# Usage: g3_flags_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the interpreter only)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/examples/g3_flags.g2d"

[ "$compiled" = yes ] && expect_code 0 "$g2d" build "$grammar" -o flags
for testing in true false; do
  expect_code 0 "$g2d" run "$grammar" -D "testing=$testing" --json "i_$testing.json" -o "i_$testing.svg" --verify-matches
  [ "$compiled" = yes ] && compiled_same ./flags "$testing" "json svg" -D "testing=$testing"
done
python3 - i_true.json i_false.json <<'PY' || fail "wrong flags"
import json, sys
tested, untested = (json.load(open(f)) for f in sys.argv[1:])
def flags(d):
    pos = {v["id"]: tuple(v["pos"]) for v in d["nodes"]}
    return {tuple(pos[c] for c in f["corners"]) for f in d["faces"]}
def poles(d):
    pos = {v["id"]: tuple(v["pos"]) for v in d["nodes"]}
    return {(pos[l["source"]], pos[l["target"]]) for l in d["links"] if pos[l["target"]][2] - pos[l["source"]][2] == 1}
assert len(flags(untested)) == 15, len(flags(untested))
assert 0 < len(flags(tested)) < 15, len(flags(tested))
assert flags(tested) <= flags(untested), "a kept flag moved"
assert len(poles(tested)) == len(poles(untested)) == 15
# the undone flags left nothing behind: 15 poles + 2 edges and a tip per flag
assert len(tested["links"]) == 15 + 2 * len(flags(tested)) and len(tested["nodes"]) == 30 + len(flags(tested))
PY
finish
