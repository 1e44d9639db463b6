#!/usr/bin/env bash
# Installs the npm packages of the VS Code extension (editors/vscode):
# vscode-languageclient; vscode-textmate and vscode-oniguruma for the grammar
# tests; @vscode/vsce to package. And those of the --view page (web/view):
# three and esbuild, which bundles the page's script into
# web/view/dist/view.bundle.js (and the 2D trace player's into
# trace.bundle.js) for CMake to embed in the runtime, and
# puppeteer-core, which drives chromium in tests/view. And the Khronos glTF
# validator (tests/gltf-check), which the tests run on `--gltf` output. And
# those of the studio's page (web/studio): CodeMirror and esbuild, which
# bundles it (with web/view's viewer) into web/studio/dist/studio.bundle.js. As
# pinned by their package-lock.json files, without install scripts. Idempotent: does
# nothing (and needs no network) when they are installed, the lock files have
# not changed since and the bundle is newer than its sources. The editor
# tests run it first (a ctest fixture), so they pass alone and in any order.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"

npm_ci() {  # npm ci in $1 unless its node_modules match its lock file
  if [ ! -f "$1/node_modules/.package-lock.json" ] || [ "$1/package-lock.json" -nt "$1/node_modules/.package-lock.json" ]; then
    echo "install-npm: npm ci in ${1#"$root"/}" >&2
    (cd "$1" && npm ci --no-audit --no-fund --ignore-scripts --loglevel=error)
  fi
}

npm_ci "$root/editors/vscode"
npm_ci "$root/tests/gltf-check"
view="$root/web/view"
npm_ci "$view"
# Bundled again when the script, the package set or the build command changed.
# (dist/trace.bundle.js, the 2D trace player, is made by the same command, after.)
bundle="$view/dist/view.bundle.js" trace="$view/dist/trace.bundle.js"
if [ ! -f "$bundle" ] || [ ! -f "$trace" ] || [ -n "$(find "$view/src" "$view/package.json" "$view/node_modules/.package-lock.json" -newer "$bundle" -print -quit)" ]; then
  echo "install-npm: bundling web/view" >&2
  (cd "$view" && npm run --silent build -- --log-level=warning)
fi
studio="$root/web/studio"
npm_ci "$studio"
# The studio's page also bundles web/view's viewer and the VS Code extension's word lists.
bundle="$studio/dist/studio.bundle.js"
if [ ! -f "$bundle" ] || [ -n "$(find "$studio/src" "$studio/package.json" "$studio/node_modules/.package-lock.json" "$view/src" \
     "$root/editors/vscode/syntaxes/g2d.tmLanguage.json" -newer "$bundle" -print -quit)" ]; then
  echo "install-npm: bundling web/studio" >&2
  (cd "$studio" && npm run --silent build -- --log-level=warning)
fi
