#!/usr/bin/env bash
# Installs the dependencies (if missing) and builds g2d with a CMake preset.
# Usage: scripts/build.sh [release|debug] [TARGET...]   (debug = AddressSanitizer + UBSan;
# targets: only those and what they need, e.g. `g2d`; none: everything, tests included)
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
bash scripts/install-deps.sh
cmake --preset "$preset" >/dev/null
targets=()
for t in "${@:2}"; do targets+=(--target "$t"); done
cmake --build --preset "$preset" -j "$(nproc)" "${targets[@]}"
