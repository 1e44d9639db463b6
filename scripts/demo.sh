#!/usr/bin/env bash
# Sets everything up, builds g2d and checks the bundled examples.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release
for example in examples/*.g2d; do
  ./build/release/bin/g2d check "$example"
  echo "ok: $example"
done
