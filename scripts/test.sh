#!/usr/bin/env bash
# Sets everything up, builds g2d and runs the whole test suite.
# Usage: scripts/test.sh [release|debug]   (debug = AddressSanitizer + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
bash scripts/build.sh "$preset"
ctest --preset "$preset" -j "$(nproc)"
