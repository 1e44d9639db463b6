#!/usr/bin/env bash
# Installs g2d's build dependencies from Debian's packages, and the npm packages
# of the VS Code extension (editors/vscode) and of the --view page (web/view,
# bundled for the build to embed), pinned by their lock files. Idempotent: does
# nothing (and needs no network) when everything is already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  antlr4 libantlr4-runtime-dev
  libglm-dev libcli11-dev catch2
  nlohmann-json3-dev
  libeigen3-dev libxml2-dev
  libyaml-cpp-dev
  libxml2-utils
  librsvg2-dev libcairo2-dev
  libtinygltf-dev
  libcpp-httplib-dev
  python3-networkx
  chromium
  ccache
)

# `install-deps.sh gallery`: also librsvg's rsvg-convert, which renders the
# gallery's SVGs to PNG (scripts/infer_gallery.sh).
if [ "${1:-}" = gallery ]; then
  packages+=(librsvg2-bin)
fi

# The editor tests, the VS Code package and the --view page's script use Node.js packages from npm.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi

# `install-deps.sh fuzz`: also clang and its libFuzzer runtime (scripts/fuzz.sh).
if [ "${1:-}" = fuzz ]; then
  packages+=(clang libclang-rt-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# npm packages of the VS Code extension and the --view page, as pinned by their lock files.
bash "$(dirname "$0")/install-npm.sh"
