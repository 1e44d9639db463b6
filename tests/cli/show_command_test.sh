#!/usr/bin/env bash
# `g2d show`: every production as mother beside daughters (kept orange,
# deleted dashed red, new green, negative conditions dashed grey), with its
# options, conditions and weights, and the axiom; as SVG or HTML.
# Usage: show_command_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"

expect_code 0 "$g2d" show "$src/examples/koch_snowflake.g2d" -o koch.svg
xmllint --noout koch.svg || fail "koch.svg is not well-formed"
has() { grep -qF -- "$2" "$1" || fail "$1 lacks: $2"; }
has koch.svg '>axiom</text>'
has koch.svg '>rule Split · pick oldest</text>'
has koch.svg '>where old.lod &lt; max_lod</text>'
# s and e are kept (orange), the matched edge old is deleted (dashed red), p, t, q are new (green).
python3 - koch.svg <<'PY' || fail "koch.svg: colours of the mapping"
import re, sys
svg = open(sys.argv[1]).read()
def colour_of(label):
    # each node: <circle … stroke="C" …/> then its <text>label</text>
    m = re.findall(r'<circle [^>]*stroke="(#[0-9a-f]+)"[^>]*/>\n<text [^>]*>' + re.escape(label) + '</text>', svg)
    return m
assert colour_of("s: Point") == ["#ff8c00", "#ff8c00"], colour_of("s: Point")     # mother, daughter
assert colour_of("p: Point") == ["#1a9e3a"], colour_of("p: Point")
assert re.search(r'<line [^>]*stroke="#d62728"[^>]*stroke-dasharray[^>]*/>\n<text [^>]*>old: Seg</text>', svg), "old: Seg deleted"
assert len(re.findall(r'stroke="#1a9e3a" stroke-width="2" marker-end', svg)) == 4, "four new directed Seg edges"
PY

cat > weighted.g2d <<'G2D'
node P;
node Q;
edge E;
axiom { a: P at (0, 0); b: P at (2, 0); a -[E]- b; }
rule Grow priority 2 {
    match { a: P; b: P; e: a -[E]- b; not { x: Q; a -[E]- x; } }
    produce weight 2 { a; b; e; q: Q at a.pos + (0, 1); a -[E]- q; }
    produce weight 1 { a; b; }
}
G2D
expect_code 0 "$g2d" show weighted.g2d -o weighted.html
has weighted.html '<!DOCTYPE html>'
has weighted.html '>rule Grow · priority 2</text>'
has weighted.html '>daughter 1 · weight 2 (p = 0.67)</text>'
has weighted.html '>daughter 2 · weight 1 (p = 0.33)</text>'
has weighted.html '>not x: Q</text>'
has weighted.html 'stroke="#999999" stroke-width="2" stroke-dasharray'
# The edge e is kept by the first daughter only: drawn kept in the mother.
python3 - weighted.html <<'PY' || fail "weighted.html: e kept"
import re, sys
page = open(sys.argv[1]).read()
assert re.search(r'<line [^>]*stroke="#ff8c00"[^>]*/>\n<text [^>]*>e: E</text>', page), "e kept"
PY

# Options a rule takes from its priority: the limit and parallel steps.
cat > prio.g2d <<'G2D'
node P;
node Q;
param n: int = 4;
axiom { a: P; }
priority 1 limit 3 parallel;
priority 2 limit n;
rule Fill priority 1 { match { a: P; } produce { a; q: Q at (0, 1); } }
rule Count priority 2 { match { q: Q; } produce { } }
G2D
expect_code 0 "$g2d" show prio.g2d -o prio.svg
has prio.svg '>rule Fill · priority 1 · limit 3 (its priority&apos;s) · parallel</text>'
has prio.svg '>rule Count · priority 2 · limit n (its priority&apos;s)</text>'

# Errors: a bad grammar, an unwritable output, no output
printf 'node P;\naxiom { a: Q; }\n' > bad.g2d
expect_code 1 "$g2d" show bad.g2d -o bad.svg
grep -q '^bad.g2d:2:12: error: unknown node kind `Q`' err.txt || fail "grammar error: $(cat err.txt)"
[ -e bad.svg ] && fail "a failed show wrote bad.svg"
expect_code 1 "$g2d" show weighted.g2d -o missing/dir/out.svg
grep -q "g2d show: error: cannot write \`missing/dir/out.svg\`" err.txt || fail "unwritable: $(cat err.txt)"
expect_code 2 "$g2d" show weighted.g2d
# The axiom's faces: a polygon per face, below the edges, labelled with name and kind.
expect_code 0 "$g2d" show "$src/examples/floor_plan.g2d" -o plan.svg
[ "$(grep -c '<polygon' plan.svg)" = 3 ] || fail "axiom faces: $(grep -c '<polygon' plan.svg) polygons"
grep -q '>living: Room</text>' plan.svg || fail "face label missing"
finish
