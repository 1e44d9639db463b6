#!/usr/bin/env python3
"""The stages depend on each other in one direction only (docs/architecture.md):
every quoted #include of compiler/ and tools/ must name a stage this file
allows for the including one. A new folder must be listed.
Also: the runtime's public headers (runtime/include, installed) include no
internal ones, and the runtime includes nothing of the compiler.

usage: check_layers.py SOURCE_DIR
"""
import os
import re
import sys

root = sys.argv[1]
# Folder of compiler/ or tools/ -> the folders it may include ("g2d" is the
# runtime, "antlr" the parser ANTLR generates from grammar/G2d.g4).
ALLOWED = {
    "diag": {"g2d"},
    "ast": {"diag"},
    "parse": {"ast", "diag", "antlr", "g2d"},   # the runtime's UTF-8 helpers
    "ir": {"diag", "g2d"},
    "sema": {"ast", "diag", "ir", "g2d"},
    "lower": {"ir", "g2d"},
    "front": {"ast", "diag", "ir", "parse", "sema"},
    "interp": {"diag", "ir", "lower", "g2d"},
    "emit": {"diag", "ir", "lower", "g2d"},
    "lsp": {"ast", "diag", "front", "sema", "g2d", "antlr"},   # the lexer's keyword list
    "show": {"diag", "ir", "sema", "g2d"},
    "driver": {"ast", "diag", "ir", "front", "interp", "emit", "lsp", "show", "infer", "import", "g2d"},
}
# The tools beside the compiler (tools/) include none of its stages.
TOOLS = {
    "infer": {"g2d"},   # the runtime's plane geometry
    "import": {"g2d"},   # the runtime's UTF-8 helpers
}
INTERNAL = set(os.listdir(os.path.join(root, "runtime", "internal", "g2d")))
include = re.compile(r'^\s*#include "([^"]+)"', re.M)
failures, checked = [], 0


def includes(path):
    with open(path, encoding="utf-8") as f:
        return include.findall(f.read())


for top, table in (("compiler", ALLOWED), ("tools", TOOLS)):
    base = os.path.join(root, top)
    for folder in sorted(os.listdir(base)):
        path = os.path.join(base, folder)
        if not os.path.isdir(path):
            continue
        if folder not in table:
            failures.append("%s/%s: a folder tests/arch/check_layers.py does not place" % (top, folder))
            continue
        for name in sorted(os.listdir(path)):
            if not name.endswith((".cpp", ".hpp")):
                continue
            for inc in includes(os.path.join(path, name)):
                checked += 1
                stage = "antlr" if re.fullmatch(r"G2d\w+\.h", inc) else inc.split("/")[0]
                if stage != folder and stage not in table[folder]:
                    failures.append("%s/%s/%s includes %s: %s may not depend on %s" % (top, folder, name, inc, folder, stage))

for part in ("include", "internal", "src"):
    base = os.path.join(root, "runtime", part)
    for dirpath, _, files in os.walk(base):
        for name in sorted(files):
            if not name.endswith((".cpp", ".hpp")):
                continue
            rel = os.path.relpath(os.path.join(dirpath, name), root)
            for inc in includes(os.path.join(dirpath, name)):
                checked += 1
                if not inc.startswith("g2d/"):
                    failures.append("%s includes %s: the runtime includes only its own headers" % (rel, inc))
                elif part == "include" and inc[4:] in INTERNAL:
                    failures.append("%s includes %s: a public header may not include an internal one" % (rel, inc))

for f in failures:
    print("FAIL:", f)
print("%d includes checked" % checked)
print("%d passed, %d failed" % (checked - len(failures), len(failures)))
sys.exit(1 if failures or checked == 0 else 0)
