#!/usr/bin/env bash
# A grammar run by the interpreter and built into a program must give the same
# SVG and JSON bytes, seed by seed. The emitted C++ must also compile without
# warnings at -Wall -Wextra. Both runs must succeed; with --expect-error, both
# must instead stop with the same located error (exit 1, the same message),
# never a crash. --verify-matches is passed to both runs.
# Usage: differential_test.sh [--expect-error] [--verify-matches] G2D GRAMMAR.g2d [SEED...]
set -u
expect_error=0; run_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --expect-error) expect_error=1; shift ;;
    --verify-matches) run_args+=(--verify-matches); shift ;;
    *) break ;;
  esac
done
g2d="$1"; grammar="$2"; shift 2
seeds=("${@:-1 2 3}")
[ $# -eq 0 ] && seeds=(1 2 3)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
dir=$(cd "$(dirname "$grammar")" && pwd); name=$(basename "$grammar")

# The emitted C++ is compiled once, warnings as errors (-Wall -Wextra -Werror
# through a compiler wrapper), except -Wmaybe-uninitialized: the optimiser's
# guess, false in GCC 12's std::variant (the runtime's Value) wherever a
# style sets a string. G2D_BUILD_OPT: the optimisation level (the sanitizer
# preset uses 0, faster to compile; -O0 must give the same bits too).
cat > "$work/strict-c++" <<'WRAP'
#!/usr/bin/env bash
exec "${G2D_STRICT_CXX:-c++}" -Wall -Wextra -Werror -Wno-maybe-uninitialized "$@"
WRAP
chmod +x "$work/strict-c++"
start=$(date +%s%N)
G2D_STRICT_CXX="${CXX:-c++}" "$g2d" build "$grammar" -o "$work/program" -O "${G2D_BUILD_OPT:-2}" --keep-cpp "$work/program.cpp" \
  --cxx "$work/strict-c++" 2>"$work/build.txt" \
  || { echo "FAIL: g2d build (warnings in the generated code are errors here):"; head -20 "$work/build.txt"; exit 1; }
ms=$(( ($(date +%s%N) - start) / 1000000 ))
# Reported, not asserted: a timed test fails on a loaded machine (CI runs two
# builds at once); build times belong to benchmarks.
echo "built in ${ms} ms"

for seed in "${seeds[@]}"; do
  (cd "$dir" && "$g2d" run "$name" --seed "$seed" -o "$work/i.svg" --json "$work/i.json" "${run_args[@]}" >/dev/null 2>"$work/i.err"); ri=$?
  (cd "$dir" && "$work/program" --seed "$seed" -o "$work/c.svg" --json "$work/c.json" "${run_args[@]}" >/dev/null 2>"$work/c.err"); rc=$?
  [ "$ri" = "$rc" ] || fail "seed $seed: exit $ri (interpreted) vs $rc (compiled)"
  if [ "$expect_error" = 0 ]; then
    [ "$ri" = 0 ] || fail "seed $seed: the interpreted run failed (exit $ri): $(head -3 "$work/i.err")"
    [ "$rc" = 0 ] || fail "seed $seed: the compiled run failed (exit $rc): $(head -3 "$work/c.err")"
    if [ "$ri" = 0 ] && [ "$rc" = 0 ]; then
      cmp -s "$work/i.svg" "$work/c.svg" || fail "seed $seed: SVG differs"
      cmp -s "$work/i.json" "$work/c.json" || fail "seed $seed: JSON differs"
    fi
  else
    # A reported error exits 1; anything else (a signal, an abort) is a crash.
    [ "$ri" = 1 ] || fail "seed $seed: expected a reported error (exit 1), the interpreter exited $ri"
    [ "$rc" = 1 ] || fail "seed $seed: expected a reported error (exit 1), the program exited $rc"
    grep -q ': error: ' "$work/i.err" || fail "seed $seed: no located error message: $(cat "$work/i.err")"
    cmp -s "$work/i.err" "$work/c.err" || fail "seed $seed: error messages differ: $(cat "$work/i.err") // $(cat "$work/c.err")"
  fi
done
echo "$failures failed"
[ "$failures" = 0 ]
