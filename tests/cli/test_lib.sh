# Shared by the CLI test scripts: sourced after `g2d` and `src` are set.
# Works in a fresh temporary folder (removed on exit), counts failures, and
# `finish` ends the script with the count.
work=$(mktemp -d); trap 'chmod -R u+rwx "$work"; rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# expect_code WANT COMMAND...: runs COMMAND with stdout in out.txt and stderr in
# err.txt; its exit code must be WANT.
expect_code() {
  local want=$1; shift
  "$@" >out.txt 2>err.txt; local got=$?
  [ "$got" = "$want" ] || fail "exit $got (wanted $want): $* -- $(head -c 600 err.txt)"
}
finish() {
  echo "$failures failed"
  [ "$failures" = 0 ]
}
# compiled_same PROGRAM STEM "EXTS" ARGS...: runs the compiled PROGRAM with ARGS,
# writing c/i_STEM.EXT for each of EXTS (json svg obj; obj brings its mtl),
# which must equal the interpreter's i_STEM.EXT byte for byte (the same name
# in another folder: an OBJ names its MTL).
compiled_same() {
  local program=$1 stem=$2 exts=$3; shift 3
  local outs=() ext
  mkdir -p c
  for ext in $exts; do
    case $ext in json) outs+=(--json "c/i_$stem.json") ;; obj) outs+=(--obj "c/i_$stem.obj") ;; svg) outs+=(-o "c/i_$stem.svg") ;; esac
  done
  [[ " $exts " == *" svg "* ]] || outs+=(--no-svg)
  [[ " $exts " == *" obj "* ]] && exts="$exts mtl"
  expect_code 0 "$program" "$@" "${outs[@]}"
  for ext in $exts; do cmp -s "i_$stem.$ext" "c/i_$stem.$ext" || fail "$stem: interpreted and compiled $ext differ"; done
}
