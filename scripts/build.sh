#!/usr/bin/env bash
# Installs the dependencies (if missing) and builds g2d with a CMake preset.
# Usage: scripts/build.sh [release|debug]   (debug = AddressSanitizer + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
bash scripts/install-deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
