#!/usr/bin/env bash
# tests/cli/differential_test.sh itself: it fails when both back ends fail,
# even the same way, unless the case is marked --expect-error; then both must
# report the same located error.
# Usage: differential_selftest.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
diff_test="$src/tests/cli/differential_test.sh"

cat > div.g2d <<'G'
node P;
axiom { p: P at (0, 0); }
limit 3;
rule R { match { p: P; } produce { p at (1 / (p.pos.x * 0), 0); } }
G
cat > fine.g2d <<'G'
node P;
axiom { p: P at (0, 0); }
limit 3;
rule R { match { p: P; } produce { p at p.pos + (1, 0); } }
G
# Both back ends fail alike: not a pass.
expect_code 1 bash "$diff_test" "$g2d" div.g2d 1
grep -q 'FAIL: seed 1: the interpreted run failed (exit 1)' out.txt || fail "same failure passed: $(cat out.txt)"
# ... unless the failure is what the case expects.
expect_code 0 bash "$diff_test" --expect-error "$g2d" div.g2d 1
# A case expected to fail that succeeds is a failure too.
expect_code 1 bash "$diff_test" --expect-error "$g2d" fine.g2d 1
grep -q 'expected a reported error (exit 1), the interpreter exited 0' out.txt || fail "--expect-error on success: $(cat out.txt)"
expect_code 0 bash "$diff_test" --verify-matches "$g2d" fine.g2d 1 2
# A warning in the generated code (here one -Wall leaves off) fails the build.
printf '#!/bin/sh\nexec c++ -Wpadded "$@"\n' > padded-c++ && chmod +x padded-c++
CXX="$PWD/padded-c++" expect_code 1 bash "$diff_test" "$g2d" fine.g2d 1
grep -q 'FAIL: g2d build (warnings in the generated code are errors here)' out.txt && grep -q 'Werror=padded' out.txt \
  || fail "a warning in the generated code passed: $(cat out.txt)"
finish
