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
