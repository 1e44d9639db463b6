#!/usr/bin/env bash
# PNG output (-o x.png): the SVG rendered by librsvg. The file is a PNG of the
# size asked for (--dpi, --width), the same bytes interpreted and compiled and
# run after run; bad options and unwritable or unrenderable outputs fail
# clearly and leave no file.
# Usage: png_output_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
tree="$src/examples/tree.g2d"

# png_size FILE: "WIDTH HEIGHT" from the IHDR chunk, or "" when FILE is no PNG.
png_size() {
  [ "$(head -c 8 "$1" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || return 0
  [ "$(head -c 16 "$1" | tail -c 4)" = IHDR ] || return 0
  local w h
  w=$(head -c 20 "$1" | tail -c 4 | od -An -tu1 | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
  h=$(head -c 24 "$1" | tail -c 4 | od -An -tu1 | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
  echo "$w $h"
}

expect_code 0 "$g2d" run "$tree" -q -o i96.png
expect_code 0 "$g2d" run "$tree" -q -o again96.png
expect_code 0 "$g2d" run "$tree" -q -o i192.PNG --dpi 192
expect_code 0 "$g2d" run "$tree" -q -o i400.png --width 400
expect_code 0 "$g2d" run "$tree" -q -o tree.svg
read -r w96 h96 <<<"$(png_size i96.png)"
read -r w192 h192 <<<"$(png_size i192.PNG)"
read -r w400 h400 <<<"$(png_size i400.png)"
[ -n "${w96:-}" ] || fail "-o i96.png wrote no PNG (starts: $(head -c 16 i96.png | od -An -c | head -1))"
[ -n "${w192:-}" ] || fail "-o i192.PNG (capitals) wrote no PNG"
[ -n "${w400:-}" ] || fail "-o i400.png --width 400 wrote no PNG"
if [ -n "${w96:-}" ] && [ -n "${w192:-}" ] && [ -n "${w400:-}" ]; then
  # tree.svg's width in cm, at 96 pixels an inch.
  cm=$(sed -n 's/.*<svg [^>]*width="\([0-9.]*\)cm".*/\1/p' tree.svg)
  want96=$(awk -v cm="$cm" 'BEGIN { printf "%d", cm / 2.54 * 96 + 0.5 }')
  [ "$w96" = "$want96" ] || fail "at 96 dpi the PNG is $w96 wide, wanted $want96 (${cm}cm)"
  [ "$w96" -gt 100 ] && [ "$h96" -gt 100 ] || fail "the 96 dpi PNG is too small: $w96 x $h96"
  # Each size is rounded on its own (12.95 cm: 489.46 px, 978.91 px).
  [ $((w192 - 2 * w96)) -ge -1 ] && [ $((w192 - 2 * w96)) -le 1 ] || fail "--dpi 192 gives width $w192, not about twice $w96"
  [ $((h192 - 2 * h96)) -ge -1 ] && [ $((h192 - 2 * h96)) -le 1 ] || fail "--dpi 192 gives height $h192, not about twice $h96"
  [ "$w400" = 400 ] || fail "--width 400 gives width $w400"
  want400=$(awk -v w="$w96" -v h="$h96" 'BEGIN { printf "%d", h * 400 / w + 0.5 }')
  [ $((h400 - want400)) -ge -1 ] && [ $((h400 - want400)) -le 1 ] || fail "--width 400 gives height $h400, wanted about $want400"
fi
cmp -s i96.png again96.png || fail "two runs wrote different PNGs"
# Not one colour: something was drawn (the PNG of a blank image is tiny).
[ "$(stat -c %s i96.png)" -gt 2000 ] || fail "the PNG looks blank ($(stat -c %s i96.png) bytes)"

# --svg-compact and --precision shape the SVG that is rendered.
expect_code 0 "$g2d" run "$tree" -q -o compact.png --svg-compact --precision 3
[ -n "$(png_size compact.png)" ] || fail "--svg-compact --precision 3 -o compact.png wrote no PNG"

# The same bytes from a compiled program, at each size.
expect_code 0 "$g2d" build "$tree" -o tree_c
expect_code 0 ./tree_c -q -o c96.png
expect_code 0 ./tree_c -q -o c192.PNG --dpi 192
expect_code 0 ./tree_c -q -o c400.png --width 400
cmp -s i96.png c96.png || fail "interpreted and compiled PNGs differ"
cmp -s i192.PNG c192.PNG || fail "interpreted and compiled PNGs differ at --dpi 192"
cmp -s i400.png c400.png || fail "interpreted and compiled PNGs differ at --width 400"

# Many seeds: a PNG each.
expect_code 0 "$g2d" run "$tree" -q --seeds 1..2 -o 'seed{seed}.png' --width 50 --summary summary.jsonl
[ "$(png_size seed1.png)" != "" ] && [ "$(png_size seed2.png)" != "" ] || fail "--seeds with -o '{seed}.png' wrote no PNGs"

# Usage errors: exit 2, a clear message, no file.
expect_code 2 "$g2d" run "$tree" -o both.png --dpi 192 --width 400
grep -q -- "--dpi and --width" err.txt || fail "--dpi with --width: unclear message: $(cat err.txt)"
expect_code 2 ./tree_c -o both.png --dpi 192 --width 400
grep -q -- "--dpi and --width" err.txt || fail "compiled --dpi with --width: unclear message: $(cat err.txt)"
expect_code 2 "$g2d" run "$tree" -o svg.svg --width 400
grep -q "PNG output only" err.txt || fail "--width with an SVG output: unclear message: $(cat err.txt)"
expect_code 2 "$g2d" run "$tree" -o zero.png --dpi 0
expect_code 2 "$g2d" run "$tree" -o zero.png --width 0
[ -e both.png ] || [ -e svg.svg ] || [ -e zero.png ] && fail "a usage error left a file"

# An unwritable path fails before the work, naming the path.
expect_code 1 "$g2d" run "$tree" -o /nonexistent/dir/x.png
grep -q 'cannot write `/nonexistent/dir/x.png`' err.txt || fail "unwritable PNG: unclear message: $(cat err.txt)"
# A PNG too large to render: an error naming the output, and no file (nor a temporary one).
expect_code 1 "$g2d" run "$tree" -q -o huge.png --dpi 9000
grep -q 'cannot write `huge.png`: the image would be' err.txt || fail "too large a PNG: unclear message: $(cat err.txt)"
[ -z "$(ls | grep huge)" ] || fail "a failed PNG left a file: $(ls | grep huge)"

finish
