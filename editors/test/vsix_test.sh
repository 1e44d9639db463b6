#!/usr/bin/env bash
# scripts/package-vscode.sh makes a .vsix holding the extension's client, its
# grammar, configuration and snippets, and the language client library.
set -u
src="$1"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
bash "$src/scripts/package-vscode.sh" "$work/g2d.vsix" >"$work/log.txt" 2>&1 || { cat "$work/log.txt"; echo "FAIL: packaging"; exit 1; }
python3 - "$work/g2d.vsix" <<'PY'
import json, sys, zipfile
names = set(zipfile.ZipFile(sys.argv[1]).namelist())
want = ["extension/package.json", "extension/extension.js", "extension/language-configuration.json",
        "extension/syntaxes/g2d.tmLanguage.json", "extension/snippets/g2d.json", "extension/studio_panel.js",
        "extension/node_modules/vscode-languageclient/package.json"]
missing = [w for w in want if w not in names]
manifest = json.loads(zipfile.ZipFile(sys.argv[1]).read("extension/package.json"))
ok = not missing and manifest["main"] == "./extension.js" and "onLanguage:g2d" in manifest["activationEvents"]
print("FAIL: missing %s" % missing if not ok else "%d files packaged" % len(names))
sys.exit(0 if ok else 1)
PY
