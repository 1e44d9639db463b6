#!/usr/bin/env bash
# Writing outputs: the compact SVG (--svg-compact) and --precision, their exact
# text (interpreted and compiled alike); an unwritable output fails before the
# derivation; an output cut short (a file-size limit, a signal) leaves no file.
# Usage: svg_output_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"

cat > small.g2d <<'G2D'
node P { style { tag = "none"; } }
edge S { style { stroke = "navy"; } }
edge T directed { style { stroke = "red"; stroke_width = 0.1; } }
axiom {
    a: P at (0, 0); b: P at (1, 0); c: P at (1, 1); d: P at (0.123456, 2);
    a -[S]- b; b -[S]- c; c -[T]-> d; d -[T]-> a; a -[S]- c;
}
G2D
head='<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="1.28cm" height="2.28cm" viewBox="-0.14 -2.1399999999999997 1.28 2.28">
<g transform="scale(1 -1)">'
# Runs of alike lines become one path each; a line starting where the last
# ended continues its subpath.
printf '%s\n%s\n' "$head" '<path d="M 0 0 L 1 0 1 1" fill="none" stroke-width="0.05" stroke="navy"/>
<path d="M 1 1 L 0.12 2 0 0" fill="none" stroke="red" stroke-width="0.1"/>
<path d="M 0 0 L 1 1" fill="none" stroke-width="0.05" stroke="navy"/>
</g>
</svg>' > want_compact.svg
printf '%s\n%s\n' "$head" '<line x1="0" y1="0" x2="1" y2="0" stroke-width="0.05" stroke="navy"/>
<line x1="1" y1="0" x2="1" y2="1" stroke-width="0.05" stroke="navy"/>
<line x1="1" y1="1" x2="0.1" y2="2" stroke="red" stroke-width="0.1"/>
<line x1="0.1" y1="2" x2="0" y2="0" stroke="red" stroke-width="0.1"/>
<line x1="0" y1="0" x2="1" y2="1" stroke-width="0.05" stroke="navy"/>
</g>
</svg>' > want_precision.svg

expect_code 0 "$g2d" run small.g2d --svg-compact --precision 2 -o compact.svg
cmp -s compact.svg want_compact.svg || fail "the compact SVG differs: $(diff want_compact.svg compact.svg)"
expect_code 0 "$g2d" run small.g2d --precision 1 -o precision.svg
cmp -s precision.svg want_precision.svg || fail "--precision 1 differs: $(diff want_precision.svg precision.svg)"
expect_code 0 "$g2d" run small.g2d -o exact.svg
grep -q 'x2="0.123456"' exact.svg || fail "without --precision coordinates are exact"
expect_code 2 "$g2d" run small.g2d --precision 16
expect_code 2 "$g2d" run small.g2d --precision -1

# The same from a compiled program, on a larger drawing.
expect_code 0 "$g2d" build "$src/examples/koch_snowflake.g2d" -o koch
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=4 --svg-compact -o i_koch.svg
expect_code 0 ./koch -D max_lod=4 --svg-compact -o c_koch.svg
cmp -s i_koch.svg c_koch.svg || fail "interpreted and compiled compact SVG differ"
expect_code 0 ./koch -D max_lod=4 -o full_koch.svg
[ "$(grep -c '<path' c_koch.svg)" -ge 1 ] && [ "$(grep -c '<line' c_koch.svg)" = 0 ] ||
  fail "Koch's lines should all be in paths"
[ "$(stat -c %s c_koch.svg)" -lt "$(stat -c %s full_koch.svg)" ] || fail "the compact SVG is not smaller"

# An unwritable output fails before the derivation (which would fail here, at
# run time) and leaves nothing.
cat > fails.g2d <<'G2D'
node P;
axiom { a: P at (0, 0); }
rule Grow { match { p: P; } produce { p; q: P at (1 / (p.pos.x - p.pos.x), 0); } }
limit 1;
G2D
mkdir locked && chmod a-w locked
if [ "$(id -u)" != 0 ]; then
  expect_code 1 "$g2d" run fails.g2d -o locked/x.svg
  grep -q "cannot write" err.txt || fail "the unwritable output is not named: $(cat err.txt)"
fi
expect_code 1 "$g2d" run fails.g2d -o no/such/folder/x.svg --json ok.json
grep -q "cannot write" err.txt || fail "the missing folder is not reported: $(cat err.txt)"
grep -q "Grow" err.txt && fail "the derivation ran before the outputs were checked"
[ -e ok.json ] && fail "an output was left after an unwritable one"

# An output cut short by a file-size limit: an error, and no file (nor a
# temporary one) left.
( ulimit -f 64; "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=6 -o cut.svg >out.txt 2>err.txt ); code=$?
[ "$code" = 1 ] || fail "a write cut short by the file-size limit exits $code, not 1"
grep -q "cannot write" err.txt || fail "the cut-short write is not reported: $(cat err.txt)"
ls | grep -q '^cut\.svg' && fail "a cut-short SVG left a file: $(ls)"
( ulimit -f 64; ./koch -D max_lod=6 --no-svg --json cut.json >out.txt 2>err.txt ); code=$?
[ "$code" = 1 ] || fail "a JSON write cut short exits $code, not 1"
ls | grep -q '^cut\.json' && fail "a cut-short JSON left a file: $(ls)"

# Interrupted while writing a big output (SIGTERM): no file, no temporary.
./koch -D max_lod=9 -o big.svg --json big.json >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 400); do
  [ -n "$(ls -A | grep '^big\.svg\.tmp-' )" ] && [ "$(stat -c %s big.svg.tmp-* 2>/dev/null | head -1)" -gt 0 ] 2>/dev/null && break
  sleep 0.02
done
kill -TERM "$pid" 2>/dev/null
wait "$pid"
ls | grep -q '^big\.' && fail "an interrupted output left files: $(ls | grep '^big\.')"

finish
