#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) and runs each for a set
# time, starting from its seed corpus and what earlier runs found
# (build/fuzz/corpus/TARGET/), with its format's dictionary
# (tests/fuzz/dicts/). Prints executions and coverage.
# Usage: scripts/fuzz.sh [-j JOBS] [SECONDS_PER_TARGET] [TARGET...]
#   grammars:     front_end structured interpreter
#   other inputs: infer_json infer_svg svg_attribute import_yaml
#                 python_expression lsp inference
#   (default: all); JOBS targets run at once (default: all of them).
# A crash leaves its input in build/fuzz/artifacts/; copy it to
# tests/fuzz/regressions/CHECK/ once fixed (docs/robustness.md), so that the
# `fuzz.replay` tests keep checking it.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=0
if [ "${1:-}" = -j ]; then jobs=$2; shift 2; fi
seconds="${1:-60}"; shift || true
all=(front_end structured interpreter infer_json infer_svg svg_attribute import_yaml python_expression lsp inference)
targets=("$@"); [ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")
[ "$jobs" -gt 0 ] || jobs=${#targets[@]}

bash scripts/install-deps.sh fuzz
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)" --target $(printf 'fuzz_%s ' "${targets[@]}")

out=build/fuzz
mkdir -p "$out/artifacts" "$out/logs"

# seed CORPUS FILE...: copies each file in, named after its path (examples
# in different folders share names).
seed() {
  local corpus=$1; shift
  for f in "$@"; do
    [ -f "$f" ] || continue
    local name=${f//\//_}
    [ -e "$corpus/${name// /_}" ] || cp "$f" "$corpus/${name// /_}"
  done
}

seed_target() {
  local t=$1 corpus="$out/corpus/$1" r=tests/fuzz/regressions s=tests/fuzz/seeds
  mkdir -p "$corpus"
  shopt -s nullglob globstar
  case $t in
    front_end|structured|interpreter) seed "$corpus" examples/*.g2d tests/bad/*.g2d $r/g2d/* ;;
    infer_json) seed "$corpus" examples/infer/merrell/**/*.json $r/infer_json/* ;;
    infer_svg) seed "$corpus" examples/infer/*.svg $s/infer_svg/* $r/infer_svg/* ;;
    import_yaml) seed "$corpus" tests/import/**/*.yml $r/import_yaml/* ;;
    lsp) seed "$corpus" $s/lsp/* examples/*.g2d $r/lsp/* ;;
    *) seed "$corpus" $s/$t/* $r/$t/* ;;
  esac
}

dict_of() {
  local d=tests/fuzz/dicts/$1.dict
  [ -f "$d" ] && echo "-dict=$d"
}

run_target() {
  local t=$1 corpus="$out/corpus/$1"
  seed_target "$t"
  # -timeout: an input taking over 10 s is a hang (30 s for inference,
  # which runs a whole generation); -rss_limit_mb: a memory blow-up.
  local timeout=10; [ "$t" = inference ] && timeout=30
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    "$out/tests/fuzz/fuzz_$t" "$corpus" -max_total_time="$seconds" -timeout=$timeout -rss_limit_mb=4096 \
    -max_len=65536 -print_final_stats=1 $(dict_of "$t") -artifact_prefix="$out/artifacts/$t-" >"$out/logs/$t.log" 2>&1
}

report() {
  local t=$1 status=$2 log="$out/logs/$1.log"
  if [ "$status" -ne 0 ]; then
    echo "fuzz_$t FAILED: see $log and $out/artifacts/"
    grep -E "ERROR|SUMMARY|fuzz check failed|Test unit written" "$log" | head -20 || true
  fi
  echo "-- fuzz_$t"
  grep -E "^stat::number_of_executed_units|^stat::average_exec_per_sec|^stat::peak_rss_mb" "$log" || true
  grep -E "DONE|INITED" "$log" | tail -2 || true
}

# Up to $jobs targets side by side; each is reported as it ends.
status=0
declare -A pid_of=()
for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
  echo "== fuzz_$t for ${seconds} s"
  run_target "$t" &
  pid_of[$t]=$!
done
for t in "${targets[@]}"; do
  s=0; wait "${pid_of[$t]}" || s=$?
  [ "$s" -eq 0 ] || status=1
  report "$t" "$s"
done
exit $status
