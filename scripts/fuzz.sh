#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) and runs each for a set
# time, starting from the seed corpus (examples/ and tests/bad/) and what
# earlier runs found (build/fuzz/corpus/). Prints executions and coverage.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
#   targets: front_end structured interpreter (default: all three)
# A crash leaves its input in build/fuzz/artifacts/; copy it to
# tests/fuzz/regressions/ once fixed, so that `fuzz.replay` keeps checking it.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"; shift || true
targets=("$@"); [ ${#targets[@]} -gt 0 ] || targets=(front_end structured interpreter)

bash scripts/install-deps.sh fuzz
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)" --target $(printf 'fuzz_%s ' "${targets[@]}")

out=build/fuzz
mkdir -p "$out/artifacts" "$out/logs"
# The targets run side by side; each prints its summary when all are done.
run_target() {
  local t=$1 corpus="$out/corpus/$1"
  mkdir -p "$corpus"
  # Seeds: every example and every bad-input test, and the saved regressions.
  cp -n examples/*.g2d tests/bad/*.g2d tests/fuzz/regressions/* "$corpus/" 2>/dev/null || true
  # -timeout: an input taking over 10 s is a hang; -rss_limit_mb: a memory blow-up.
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    "$out/tests/fuzz/fuzz_$t" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$out/artifacts/$t-" >"$out/logs/$t.log" 2>&1
}
pids=()
for t in "${targets[@]}"; do
  echo "== fuzz_$t for ${seconds} s"
  run_target "$t" &
  pids+=($!)
done
status=0
for i in "${!targets[@]}"; do
  t=${targets[$i]}; log="$out/logs/$t.log"
  if ! wait "${pids[$i]}"; then
    echo "fuzz_$t FAILED: see $log and $out/artifacts/"
    grep -E "ERROR|SUMMARY|fuzz check failed|Test unit written" "$log" | head -20 || true
    status=1
  fi
  echo "-- fuzz_$t"
  grep -E "^stat::number_of_executed_units|^stat::average_exec_per_sec|^stat::peak_rss_mb" "$log" || true
  grep -E "DONE|INITED" "$log" | tail -2 || true
done
exit $status
