#!/usr/bin/env python3
"""docs/architecture.md names files and code: every path it names must exist,
and every C++ name it quotes (`Graph::setScope`, `kindEffects`, `RewriteLowering`)
must occur in the sources, so that the checklists cannot point at what was
moved or removed.

usage: check_architecture_names.py SOURCE_DIR
"""
import os
import re
import sys

root = sys.argv[1]
doc = open(os.path.join(root, "docs", "architecture.md"), encoding="utf-8").read()
# What the document writes without its top folder (§2: "Paths without a top
# folder are under compiler/"), and the runtime's header and source folders.
PREFIXES = ["", "compiler/", "tools/", "runtime/", "runtime/engine/", "runtime/run/"]
SOURCE_DIRS = ["docs", "compiler", "runtime", "tools", "tests", "cmake", "web/view/src", "grammar", "bench", "scripts", "editors"]
EXTENSIONS = (".cpp", ".hpp", ".py", ".sh", ".g4", ".md", ".cmake", ".vim", ".js", ".txt", ".in")
# Words that look like paths or names but are neither (a library, placeholders).
NOT_NAMES = {"three.js", "fnName", "fn::fnName", "g2d/NAME.hpp"}

sources = {}
basenames = set()
for top in SOURCE_DIRS:
    for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
        dirnames[:] = [d for d in dirnames if d not in ("node_modules", "dist", "build")]
        for name in filenames:
            basenames.add(name)
            if name.endswith((".cpp", ".hpp", ".py", ".sh", ".g4", ".js", ".cmake", ".txt")):
                with open(os.path.join(dirpath, name), encoding="utf-8", errors="replace") as f:
                    sources[os.path.join(dirpath, name)] = f.read()
corpus = "\n".join(sources.values())

failures = []


def path_exists(token):
    token = token.rstrip("/")
    if "/" not in token:
        return token in basenames
    for prefix in PREFIXES:
        for base in (prefix, prefix + "include/", prefix + "internal/", prefix + "src/"):
            if os.path.exists(os.path.join(root, base + token)):
                return True
    # a runtime source kept in a subfolder of its library's src/ (engine/src/graph/graph.cpp)
    name = os.path.basename(token)
    return token.startswith(("runtime/src/", "src/")) and name in basenames


paths = set(re.findall(r"(?<![\w./-])((?:[\w.-]+/)*[\w.-]+(?:%s))(?![\w])" % "|".join(re.escape(e) for e in EXTENSIONS), doc))
for p in sorted(paths):
    if p.startswith(("../", "http")) or "*" in p or p in NOT_NAMES:
        continue
    if not path_exists(p):
        failures.append("path `%s` does not exist" % p)

# C++ names: `A::b`, lowerCamel with a hump, UpperCamel with two humps.
quoted = re.findall(r"`([^`\n]+)`", doc)
names = set()
for q in quoted:
    for tok in re.findall(r"[A-Za-z_][\w:]*", q):
        if "::" in tok or re.fullmatch(r"[a-z]+[A-Z]\w*", tok) or re.fullmatch(r"[A-Z][a-z0-9]+[A-Z]\w*", tok):
            names.add(tok)
for name in sorted(names):
    last = name.split("::")[-1]
    if not last or name in NOT_NAMES:
        continue
    if not re.search(r"\b%s\b" % re.escape(last), corpus):
        failures.append("name `%s` occurs in no source" % name)

if failures:
    print("docs/architecture.md is stale:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("docs/architecture.md: %d paths and %d names found" % (len(paths), len(names)))
