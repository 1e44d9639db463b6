#!/usr/bin/env bash
# Packages the VS Code extension (editors/vscode) as a .vsix with @vscode/vsce
# from npm. Usage: scripts/package-vscode.sh [OUT.vsix]   (default build/g2d.vsix)
# Install it with: code --install-extension build/g2d.vsix
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(realpath -m "${1:-$root/build/g2d.vsix}")"
mkdir -p "$(dirname "$out")"
bash "$root/scripts/install-npm.sh"
cd "$root/editors/vscode"
npx --no-install vsce package --allow-missing-repository --skip-license -o "$out"
