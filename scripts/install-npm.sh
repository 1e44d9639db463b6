#!/usr/bin/env bash
# Installs the npm packages of the VS Code extension (editors/vscode):
# vscode-languageclient; vscode-textmate and vscode-oniguruma for the grammar
# tests; @vscode/vsce to package. As pinned by its package-lock.json, without
# install scripts. Idempotent: does nothing (and needs no network) when they
# are installed and the lock file has not changed since. The editor tests run
# it first (a ctest fixture), so they pass alone and in any order.
set -euo pipefail
vscode="$(cd "$(dirname "$0")/.." && pwd)/editors/vscode"
if [ ! -f "$vscode/node_modules/.package-lock.json" ] || [ "$vscode/package-lock.json" -nt "$vscode/node_modules/.package-lock.json" ]; then
  echo "install-npm: npm ci in editors/vscode" >&2
  (cd "$vscode" && npm ci --no-audit --no-fund --ignore-scripts --loglevel=error)
fi
