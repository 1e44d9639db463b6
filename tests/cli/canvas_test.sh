#!/usr/bin/env bash
# The SVG's frame (#32 item 5): fitted to the drawing without a canvas; the
# grammar's `canvas LOWER to UPPER;` exactly, with no margin (a parameter may
# set it); --viewbox over both; compiled programs write the same bytes; a bad
# canvas or --viewbox fails with a located or named message and writes nothing.
# Usage: canvas_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"

# has_frame FILE 'width=… height=… viewBox=…': FILE's <svg> element, exactly.
has_frame() {
  local want="<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" $2>"
  [ "$(sed -n 2p "$1")" = "$want" ] || fail "$1: wanted $2, got: $(sed -n 2p "$1")"
}
# first_error LINE: the first line of err.txt, exactly.
first_error() { [ "$(head -1 err.txt)" = "$1" ] || fail "wanted: $1 -- got: $(head -3 err.txt)"; }
no_file() { [ -e "$1" ] && fail "$1 was written"; true; }

cat > fitted.g2d <<'G2D'
node Dot { style { r = 0.5; fill = "teal"; } }
axiom { a: Dot at (0, 0); b: Dot at (4, 2); }
G2D
{ cat fitted.g2d; printf '%s\n' 'const m = 1;' 'param top: float = 3;' 'canvas (-m, -m) to (4 + m, top);'; } > canvas.g2d

# (a) No canvas: the measured extent, the widest stroke and a 2 % margin.
expect_code 0 "$g2d" run fitted.g2d -o i_fitted.svg
has_frame i_fitted.svg 'width="5.24cm" height="3.24cm" viewBox="-0.62 -2.62 5.24 3.24"'
# (b) The canvas, exactly (y up: the viewBox's y is -y1); a parameter moves its top.
expect_code 0 "$g2d" run canvas.g2d -o i_canvas.svg
has_frame i_canvas.svg 'width="6cm" height="4cm" viewBox="-1 -3 6 4"'
expect_code 0 "$g2d" run canvas.g2d -D top=5 -o i_top.svg
has_frame i_top.svg 'width="6cm" height="6cm" viewBox="-1 -5 6 6"'
# Only the frame differs: the drawing is the same.
cmp -s <(tail -n +3 i_fitted.svg) <(tail -n +3 i_canvas.svg) || fail "a canvas changed more than the frame"
# (c) --viewbox overrides the canvas and the fitted frame.
expect_code 0 "$g2d" run canvas.g2d --viewbox -2,-2,8,6 -o i_vb.svg
has_frame i_vb.svg 'width="10cm" height="8cm" viewBox="-2 -6 10 8"'
expect_code 0 "$g2d" run fitted.g2d --viewbox=-0.5,0,1.5,1 -o i_vb_fitted.svg
has_frame i_vb_fitted.svg 'width="2cm" height="1cm" viewBox="-0.5 -1 2 1"'
expect_code 0 "$g2d" run canvas.g2d --seeds 1..2 --viewbox -2,-2,8,6 -o 's{seed}.svg' -q
has_frame s2.svg 'width="10cm" height="8cm" viewBox="-2 -6 10 8"'
# The PNG is rendered from that SVG: 2.54 cm by 5.08 cm at 96 dpi.
expect_code 0 "$g2d" run fitted.g2d --viewbox 0,0,2.54,5.08 -o vb.png
[ "$(od -An -tu1 -j16 -N8 vb.png | tr -s ' ')" = " 0 0 0 96 0 0 0 192" ] ||
  fail "the PNG is not 96 x 192: $(od -An -tu1 -j16 -N8 vb.png)"

# (d) The compiled program writes the same bytes.
expect_code 0 "$g2d" build canvas.g2d -o canvas_exe
expect_code 0 ./canvas_exe -o c_canvas.svg
cmp -s i_canvas.svg c_canvas.svg || fail "compiled canvas SVG differs"
expect_code 0 ./canvas_exe -D top=5 -o c_top.svg
cmp -s i_top.svg c_top.svg || fail "compiled canvas SVG with -D top=5 differs"
expect_code 0 ./canvas_exe --viewbox -2,-2,8,6 -o c_vb.svg
cmp -s i_vb.svg c_vb.svg || fail "compiled --viewbox SVG differs"

# Bad --viewbox values: usage errors (exit 2) that name the option, no file.
expect_code 2 "$g2d" run canvas.g2d --viewbox 1,2,3 -o bad.svg
first_error 'g2d run: error: --viewbox 1,2,3: expected four numbers X0,Y0,X1,Y1 (the lower left and the upper right corner, y up)'
expect_code 2 "$g2d" run canvas.g2d --viewbox 5,0,1,1 -o bad.svg
first_error 'g2d run: error: --viewbox 5,0,1,1: the box is empty: X0 must be less than X1 and Y0 less than Y1'
expect_code 2 "$g2d" run canvas.g2d --viewbox x,0,1,1 -o bad.png
first_error 'g2d run: error: --viewbox x,0,1,1: expected four numbers X0,Y0,X1,Y1 (the lower left and the upper right corner, y up)'
expect_code 2 ./canvas_exe --viewbox 0,0,1,0 -o bad.svg
first_error 'canvas_exe: error: --viewbox 0,0,1,0: the box is empty: X0 must be less than X1 and Y0 less than Y1'
no_file bad.svg
no_file bad.png

# A parameter that empties the canvas: a run-time error at the declaration, no file.
expect_code 1 "$g2d" run canvas.g2d -D top=-2 -o empty.svg
first_error 'canvas.g2d:5:1: error: the canvas is empty: its first corner (-1, -1) must lie below and left of its second (5, -2) (before the first step)'
expect_code 1 ./canvas_exe -D top=-2 -o empty.svg
first_error 'canvas.g2d:5:1: error: the canvas is empty: its first corner (-1, -1) must lie below and left of its second (5, -2) (before the first step)'
no_file empty.svg

# Bad canvases in the grammar: located errors.
check_error() {   # NAME 'LAST LINES' 'FIRST ERROR LINE': the grammar is fitted.g2d and the lines
  { cat fitted.g2d; printf '%s\n' "$2"; } > "$1.g2d"
  expect_code 1 "$g2d" check "$1.g2d"
  first_error "$3"
}
check_error twice $'canvas (0, 0) to (1, 1);\ncanvas (0, 0) to (2, 2);' 'twice.g2d:4:1: error: the canvas is set twice'
check_error inverted 'canvas (1, 0) to (0, 1);' \
  'inverted.g2d:3:1: error: the canvas is empty: its first corner (1, 0) must lie below and left of its second (0, 1)'
check_error flat 'canvas (0, 0) to (4, 0);' \
  'flat.g2d:3:1: error: the canvas is empty: its first corner (0, 0) must lie below and left of its second (4, 0)'
check_error words 'canvas ("left", 0) to (1, 1);' 'words.g2d:3:9: error: the x of a vector must be float, but this is string'
check_error number 'canvas 0 to (1, 1);' 'number.g2d:3:8: error: a canvas corner must be vec2, but this is int'
check_error no_to 'canvas (0, 0) (1, 1);' \
  'no_to.g2d:3:15: error: expected a name, found `(`; a canvas is written `canvas (x0, y0) to (x1, y1);`'
check_error misspelt 'canvs (0, 0) to (1, 1);' \
  'misspelt.g2d:3:1: error: expected a declaration (`node`, `edge`, `face`, `axiom`, `rule`, `param`, `const`, `enum`, `fn`, `import`, `limit`, `priority`, `defs`, `space`, `merge`, `sequence` or `canvas`), found name `canvs`; did you mean `canvas`?'
printf '%s\n' 'space 3d;' 'node P;' 'axiom { a: P at (0, 0, 0); }' 'canvas (0, 0) to (1, 1);' > solid.g2d
expect_code 1 "$g2d" check solid.g2d
first_error 'solid.g2d:4:1: error: `canvas` frames a 2D grammar'"'"'s drawing; a 3D grammar'"'"'s SVG is a projection (--view-from): frame it with --viewbox X0,Y0,X1,Y1'
# … where --viewbox frames the projection.
printf '%s\n' 'space 3d;' 'node P;' 'axiom { a: P at (0, 0, 0); }' > solid.g2d
expect_code 0 "$g2d" run solid.g2d --viewbox -1,-1,1,1 -o solid.svg
has_frame solid.svg 'width="2cm" height="2cm" viewBox="-1 -1 2 2"'

# Neither word is reserved.
cat > names.g2d <<'G2D'
param to: float = 2;
node canvas { canvas: float = 1; }
canvas (0, 0) to (to, to);
axiom { canvas: canvas at (1, 1) { canvas = to }; }
G2D
expect_code 0 "$g2d" run names.g2d -o names.svg
has_frame names.svg 'width="2cm" height="2cm" viewBox="0 -2 2 2"'
finish
