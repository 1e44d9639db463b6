#!/usr/bin/env bash
# Work a run does for nothing is counted by --stats, the same by both back
# ends (issue #47, language.md §14):
# * tests/cli/box_wrong_order.g2d: G^3's box whose Create face lists its
#   corners the wrong way round: 4 faces against their neighbour, 4 bottom
#   sides run the same way by two faces. With `face F oriented` (G^3's fix)
#   the triangles are turned: 0 counted, no side run the same way twice.
# * tests/cli/silent_work.g2d: 4 inserts on a diagonal (and `g2d check`'s
#   warning about them), 2 compounds without an instance.
# * examples/extrude.g2d with its tops (faces over all turns) reversed:
#   counted, and turned when their kind is oriented.
# Usage: silent_counters_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no:
# the interpreter only, as sanitized builds do)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"

# counters STATS_FILE: the three counters of a --stats line, space-separated.
counters() {
  python3 -c 'import json, sys; d = json.loads(open(sys.argv[1]).readline())
print(d["faces_against_neighbours"], d["inserts_without_side"], d["compounds_without_instances"])' "$1"
}
# same_way JSON: how many pairs of faces run a shared side the same way.
same_way() {
  python3 -c 'import json, sys; uses = {}
for f in json.load(open(sys.argv[1]))["faces"]:
    c = f["corners"]
    for i in range(len(c)): uses.setdefault(frozenset((c[i], c[i - 1])), []).append((c[i - 1], c[i]))
print(sum(1 for s in uses.values() for i in range(len(s)) for j in range(i + 1, len(s)) if s[i] == s[j]))' "$1"
}

cp "$src/tests/cli/box_wrong_order.g2d" plain.g2d
sed 's/^face F;/face F oriented;/' plain.g2d > oriented.g2d
cp "$src/tests/cli/silent_work.g2d" work.g2d
# examples/extrude.g2d, one storey, its tops over all turns written the wrong
# way round: 3 tops against their walls (13 sides); `oriented` turns them.
sed 's/param storeys: int = 3;/param storeys: int = 1;/; s/Top(all t);/Top(all t reversed);/' "$src/examples/extrude.g2d" > ring_plain.g2d
sed 's/^face Top {/face Top oriented {/' ring_plain.g2d > ring_oriented.g2d
check() {   # check NAME WANT_COUNTERS [WANT_SAME_WAY]
  local name=$1 want=$2 want_same=${3:-}
  expect_code 0 "$g2d" run "$name.g2d" --stats --json "i_$name.json" --no-svg --verify-matches
  cp out.txt "i_$name.stats"
  [ "$(counters "i_$name.stats")" = "$want" ] || fail "$name: interpreted counters $(counters "i_$name.stats"), wanted $want"
  [ -z "$want_same" ] || [ "$(same_way "i_$name.json")" = "$want_same" ] ||
    fail "$name: $(same_way "i_$name.json") sides run the same way twice, wanted $want_same"
  if [ "$compiled" = yes ]; then
    expect_code 0 "$g2d" build "$name.g2d" -o "prog_$name"
    compiled_same "./prog_$name" "$name" json --stats
    [ "$(counters out.txt)" = "$want" ] || fail "$name: compiled counters $(counters out.txt), wanted $want"
  fi
}
check plain "4 0 0" 4
check oriented "0 0 0" 0
check ring_plain "3 0 0" 13
check ring_oriented "0 0 0" 0
check work "0 4 2"

expect_code 0 "$g2d" check work.g2d
grep -q '^work.g2d:11:59: warning: `a` and `c` are not neighbouring corners of face `q` (a diagonal)' err.txt ||
  fail "no warning about the diagonal insert: $(head -c 400 err.txt)"
[ "$(grep -c 'warning:' err.txt)" = 1 ] || fail "the side insert is warned about too: $(cat err.txt)"
finish
