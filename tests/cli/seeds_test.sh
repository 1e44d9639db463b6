#!/usr/bin/env bash
# Many seeds (`--seeds A..B -j N`, runtime/run/internal/g2d/seed_batch.hpp): each
# seed's files equal a run of that seed alone (interpreted and compiled), the
# summary has one line per seed in seed order whatever -j, failing seeds are
# reported with a non-zero exit, and bad arguments exit 2 with a clear message.
# Usage: seeds_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
# pattern_square: every seed ends by itself, with 160 to 432 elements (two numbers drawn per run).
square="$src/examples/pattern_square.g2d"
# The summary without the seconds (which vary).
rows() { sed 's/"seconds": [0-9.]*, //' "$1"; }

# Each seed's SVG and JSON equal a single run's, byte for byte; the summary is exact.
mkdir -p j2 j1 alone
expect_code 0 "$g2d" run "$square" --seeds 1..12 -j 2 -o 'j2/{seed}.svg' --json 'j2/{seed}.json'
cp out.txt j2.rows
[ -s err.txt ] && fail "a successful batch printed on stderr: $(cat err.txt)"
: > alone.stats
for seed in $(seq 1 12); do
  expect_code 0 "$g2d" run "$square" --seed "$seed" -o "alone/$seed.svg" --json "alone/$seed.json" --stats
  cat out.txt >> alone.stats
  for ext in svg json; do
    cmp -s "alone/$seed.$ext" "j2/$seed.$ext" || fail "seed $seed: the batch's $ext differs from a run alone"
  done
done
# The lines single runs' --stats imply.
/usr/bin/python3 - alone.stats > alone.rows <<'PY'
import json, sys
for line in open(sys.argv[1]):
    s = json.loads(line)
    print(f'{{"seed": {s["seed"]}, "steps": {s["steps"]}, "elements": {s["nodes"] + s["edges"]}, "faces": {s["faces"]}, "stopped": "{s["stopped"]}"}}')
PY
rows j2.rows > j2.exact
cmp -s j2.exact alone.rows || fail "summary rows differ from single runs: $(diff j2.exact alone.rows | head -5)"
[ "$(wc -l < j2.rows)" = 12 ] || fail "12 summary lines expected: $(cat j2.rows)"
grep -qx '{"seed": 11, "steps": 70, "elements": 160, "faces": 0, "seconds": [0-9.]*, "stopped": "terminal"}' j2.rows \
  || fail "seed 11's line: $(grep '"seed": 11,' j2.rows)"
# Several seeds vary (the comparison above is not of twelve equal files).
[ "$(sort -u j2.exact | cut -d, -f2 | sort -u | wc -l)" -gt 2 ] || fail "the seeds gave too few different step counts"

# Faces are counted: a grammar that splits faces, its lines as single runs' --stats say.
sub="$src/examples/subdivide.g2d"
expect_code 0 "$g2d" run "$sub" --seeds 1..3 -j 2 --no-svg
rows out.txt > sub.rows
for seed in 1 2 3; do
  expect_code 0 "$g2d" run "$sub" --seed "$seed" --no-svg --stats
  faces=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["faces"])' out.txt)
  [ "$faces" -gt 1 ] || fail "subdivide seed $seed: $faces faces"
  grep -q "^{\"seed\": $seed, .*\"faces\": $faces, \"stopped\"" sub.rows || fail "seed $seed's faces ($faces): $(cat sub.rows)"
done

# -j 1 gives the same files and the same lines; so does a list, and --summary.
expect_code 0 "$g2d" run "$square" --seeds 1..12 -j 1 -o 'j1/{seed}.svg' --json 'j1/{seed}.json' --quiet
rows out.txt > j1.exact
cmp -s j1.exact j2.exact || fail "-j1 and -j2 summaries differ"
for seed in $(seq 1 12); do
  cmp -s "j1/$seed.svg" "j2/$seed.svg" && cmp -s "j1/$seed.json" "j2/$seed.json" || fail "seed $seed: -j1 and -j2 differ"
done
expect_code 0 "$g2d" run "$square" --seeds 9..12,1..4 -j 3 --no-svg --summary list.jsonl
[ -s out.txt ] && fail "--summary still printed on stdout: $(cat out.txt)"
rows list.jsonl > list.exact
grep -E '"seed": ([1-4]|9|1[0-2]),' j2.exact | cmp -s - list.exact || fail "a seed list: $(cat list.jsonl)"
# One seed needs no placeholder.
expect_code 0 "$g2d" run "$square" --seeds 6..6 -o six.svg
cmp -s six.svg alone/6.svg || fail "--seeds 6..6 differs from --seed 6"

# Compiled: the same files as the interpreter.
expect_code 0 "$g2d" build "$square" -o square
mkdir -p c
expect_code 0 ./square --seeds 1..12 -j 2 -o 'c/{seed}.svg' --json 'c/{seed}.json'
rows out.txt > c.exact
cmp -s c.exact j2.exact || fail "compiled summary differs: $(diff c.exact j2.exact | head -5)"
for seed in $(seq 1 12); do
  cmp -s "c/$seed.svg" "alone/$seed.svg" && cmp -s "c/$seed.json" "alone/$seed.json" || fail "seed $seed: compiled batch differs"
done

# Failing seeds: past --max-elements 400 (on the way, seed 6 grows past it; seeds 4, 5 and 11 do not).
mkdir -p f
expect_code 1 "$g2d" run "$square" --seeds 1..12 -j 2 --max-elements 400 -o 'f/{seed}.svg'
grep -qx '{"seed": 6, "steps": [0-9]*, "elements": [0-9]*, "faces": 0, "seconds": [0-9.]*, "stopped": "element_limit", "error": ".*"}' out.txt \
  || fail "seed 6 not reported as failed: $(grep '"seed": 6,' out.txt)"
grep -qx '{"seed": 11, "steps": 70, "elements": 160, "faces": 0, "seconds": [0-9.]*, "stopped": "terminal"}' out.txt \
  || fail "seed 11 should succeed: $(grep '"seed": 11,' out.txt)"
[ -e f/6.svg ] && fail "a failed seed wrote its SVG"
[ -e f/11.svg ] || fail "a good seed beside failing ones wrote no SVG"
grep -q '^seed 6: .*error: .*400' err.txt || fail "no message for seed 6: $(cat err.txt)"
grep -q 'seeds failed (.*6.*); their summary lines say why' err.txt || fail "no closing message: $(tail -2 err.txt)"
[ "$(wc -l < out.txt)" = 12 ] || fail "failed seeds still get their line"
ls f | grep -q tmp && fail "temporary files left: $(ls f)"
expect_code 1 ./square --seeds 5..7 --max-elements 400 --no-svg
grep -q '"seed": 6, .*"stopped": "element_limit"' out.txt || fail "compiled failing seed: $(cat out.txt)"

# Bad arguments: exit 2 and a message that says what to do.
expect_code 2 "$g2d" run "$square" --seeds 5..1 --no-svg
grep -q 'error: --seeds 5..1: the range 5..1 is empty' err.txt || fail "reversed range: $(cat err.txt)"
expect_code 2 "$g2d" run "$square" --seeds 1..x --no-svg
grep -q "error: --seeds 1..x: \`x\` is not a seed" err.txt || fail "bad range: $(cat err.txt)"
expect_code 2 "$g2d" run "$square" --seeds 1..3,2 --no-svg
grep -q 'seed 2 is listed twice' err.txt || fail "duplicate seed: $(cat err.txt)"
expect_code 2 "$g2d" run "$square" --seeds 1..3 -o same.svg
grep -q 'error: -o same.svg: every seed would write this file; put {seed} in the name' err.txt || fail "no placeholder: $(cat err.txt)"
expect_code 2 "$g2d" run "$square" --seeds 1..3 --no-svg --json same.json
grep -q 'error: --json same.json: every seed would write this file' err.txt || fail "no placeholder in --json: $(cat err.txt)"
expect_code 2 "$g2d" run "$square" --seeds 1..3
grep -q "every seed would write pattern_square.svg (the default SVG name)" err.txt || fail "default name: $(cat err.txt)"
expect_code 2 "$g2d" run "$square" --seeds 1..3 --seed 4 --no-svg
grep -q -- '--seeds.*excludes.*--seed\|--seed.*excludes.*--seeds' err.txt || fail "--seed with --seeds: $(cat err.txt)"
expect_code 2 "$g2d" run "$square" -j 2 --no-svg
grep -q -- '-j.*requires --seeds\|--jobs.*requires --seeds' err.txt || fail "-j without --seeds: $(cat err.txt)"
expect_code 2 "$g2d" run "$square" --seeds 1..3 -j 0 --no-svg
expect_code 2 "$g2d" run "$square" --seeds 1..3 --stats --no-svg
grep -q -- '--stats does not go with --seeds' err.txt || fail "--stats with --seeds: $(cat err.txt)"
# A bad -D is said once, not once per seed.
expect_code 2 "$g2d" run "$square" --seeds 1..20 --no-svg -D nosuch=1
[ "$(grep -c 'no parameter `nosuch`' err.txt)" = 1 ] || fail "-D error once: $(cat err.txt)"
expect_code 2 ./square --seeds 1..x --no-svg
# An unwritable output fails once, before the work.
expect_code 1 "$g2d" run "$square" --seeds 1..5 -o 'nodir/{seed}.svg'
[ "$(grep -c 'error: cannot write' err.txt)" = 1 ] || fail "unwritable output: $(cat err.txt)"
[ -s out.txt ] && fail "an unwritable output still ran seeds: $(cat out.txt)"

# Interrupted: the workers stop and no output is half written.
mkdir -p int
"$g2d" run "$square" --seeds 1..100000 -j 2 -o 'int/{seed}.svg' --json 'int/{seed}.json' >int.rows 2>int.err &
batch=$!
# Interrupted once some seeds are written (a loaded machine may take longer to start them).
for _ in $(seq 100); do ls int 2>/dev/null | grep -q 'svg$' && break; sleep 0.1; done
sleep 0.3
kill -TERM "$batch"
wait "$batch"; code=$?
[ "$code" -ne 0 ] || fail "an interrupted batch exited 0"
ls int | grep -q tmp && fail "temporary files left after SIGTERM: $(ls int | grep tmp | head -3)"
[ -n "$(ls int)" ] || fail "the interrupted batch wrote nothing in 10 s"
for f in int/*.svg; do tail -c 7 "$f" | grep -q '</svg>' || fail "$f is incomplete"; done
sleep 0.2
ps -eo args | grep -F "int/{seed}.svg" | grep -vq grep && fail "workers outlived the batch"

finish
