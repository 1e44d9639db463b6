#!/usr/bin/env python3
"""The stages depend on each other in one direction only (docs/architecture.md):
every quoted #include of compiler/ and tools/ must name a stage this file
allows for the including one. A new folder must be listed.
Also the runtime's two libraries (runtime/engine → g2d_engine, runtime/run →
g2d_run, which builds on the engine):
  - every runtime #include names a header of the runtime (never the compiler),
    one the including library can see;
  - public headers (LIB/include, installed) include no internal ones, and
    each is reached from an entry point (ENTRIES): what embedding programs
    and generated code include; a header nothing installed needs is internal;
  - the engine includes nothing of the run library, and none of the run
    library's third-party headers (CLI11, librsvg, cairo): embedding programs
    link the engine alone.

usage: check_layers.py SOURCE_DIR
"""
import os
import re
import sys

root = sys.argv[1]
# Folder of compiler/ or tools/ -> the folders it may include ("engine" and
# "run" are the runtime's libraries, "antlr" the parser ANTLR generates from
# grammar/G2d.g4).
ALLOWED = {
    "diag": {"engine"},   # the runtime's source excerpts
    "ast": {"diag"},
    "parse": {"ast", "diag", "antlr", "engine"},   # the runtime's UTF-8 helpers
    "ir": {"diag", "engine"},
    "sema": {"ast", "diag", "ir", "engine"},
    "lower": {"ir", "engine"},
    "front": {"ast", "diag", "ir", "parse", "sema"},
    "interp": {"diag", "ir", "lower", "engine"},
    "emit": {"diag", "ir", "lower", "engine"},
    "lsp": {"ast", "diag", "front", "sema", "engine", "antlr"},   # the lexer's keyword list
    "show": {"diag", "ir", "sema", "engine"},
    "studio": {"ast", "diag", "ir", "front", "interp", "lsp", "infer", "engine", "run"},   # g2d studio: check, complete, run and infer on a server
    "driver": {"ast", "diag", "ir", "front", "interp", "emit", "lsp", "show", "studio", "infer", "import", "engine", "run"},
}
# The tools beside the compiler (tools/) include none of its stages.
TOOLS = {
    "infer": {"engine"},   # the runtime's plane geometry
    "import": {"engine"},   # the runtime's UTF-8 helpers
}
# The runtime's libraries, and those each may include (itself first).
LIBRARIES = {"engine": ("engine",), "run": ("run", "engine")}
# The public entry points: embedding programs include grammar.hpp, generated
# code compiled.hpp, and a generated program with a main run_options.hpp.
ENTRIES = ("grammar.hpp", "compiled.hpp", "run_options.hpp")
# Third-party headers only the run library may include (<...>).
RUN_ONLY_SYSTEM = re.compile(r"^(CLI/|librsvg/|cairo|gio/|glib)")

include = re.compile(r'^\s*#include "([^"]+)"', re.M)
system_include = re.compile(r"^\s*#include <([^>]+)>", re.M)
failures, checked = [], 0


def headers(lib, part):
    path = os.path.join(root, "runtime", lib, part, "g2d")
    return set(os.listdir(path)) if os.path.isdir(path) else set()


# Header name -> (library, "include" or "internal").
HEADER = {}
for lib in LIBRARIES:
    for part in ("include", "internal"):
        for name in headers(lib, part):
            if name in HEADER:
                failures.append("g2d/%s is in two places: runtime/%s/%s/g2d and runtime/%s/%s/g2d"
                                % ((name,) + HEADER[name] + (lib, part)))
            HEADER[name] = (lib, part)


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


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
            for inc in include.findall(read(os.path.join(path, name))):
                checked += 1
                if re.fullmatch(r"G2d\w+\.h", inc):
                    stage = "antlr"
                elif inc.startswith("g2d/"):
                    if inc[4:] not in HEADER:
                        failures.append("%s/%s/%s includes %s: no runtime header of that name" % (top, folder, name, inc))
                        continue
                    stage = HEADER[inc[4:]][0]
                else:
                    stage = inc.split("/")[0]
                if stage != folder and stage not in table[folder]:
                    failures.append("%s/%s/%s includes %s: %s may not depend on %s" % (top, folder, name, inc, folder, stage))

for lib, visible in LIBRARIES.items():
    for part in ("include", "internal", "src"):
        base = os.path.join(root, "runtime", lib, part)
        for dirpath, _, files in os.walk(base):
            for name in sorted(files):
                if not name.endswith((".cpp", ".hpp")):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                text = read(path)
                for inc in include.findall(text):
                    checked += 1
                    where = HEADER.get(inc[4:]) if inc.startswith("g2d/") else None
                    if where is None:
                        failures.append("%s includes %s: the runtime includes only its own headers" % (rel, inc))
                    elif where[0] not in visible:
                        failures.append("%s includes %s: the %s library may not depend on %s" % (rel, inc, lib, where[0]))
                    elif part == "include" and where[1] == "internal":
                        failures.append("%s includes %s: a public header may not include an internal one" % (rel, inc))
                for inc in system_include.findall(text):
                    checked += 1
                    if lib == "engine" and RUN_ONLY_SYSTEM.match(inc):
                        failures.append("%s includes <%s>: the engine links no CLI11, librsvg or cairo" % (rel, inc))

# Every public header is reached from an entry point through public headers.
reached, todo = set(), [name for name in ENTRIES if name in HEADER]
while todo:
    name = todo.pop()
    if name in reached or HEADER.get(name, (None, None))[1] != "include":
        continue
    reached.add(name)
    lib = HEADER[name][0]
    todo += [inc[4:] for inc in include.findall(read(os.path.join(root, "runtime", lib, "include", "g2d", name)))
             if inc.startswith("g2d/")]
for name, (lib, part) in sorted(HEADER.items()):
    checked += 1
    if part == "include" and name not in reached:
        failures.append("runtime/%s/include/g2d/%s: public, but no entry point (%s) includes it: move it to internal/"
                        % (lib, name, ", ".join(ENTRIES)))

for f in failures:
    print("FAIL:", f)
print("%d includes checked" % checked)
print("%d passed, %d failed" % (checked - len(failures), len(failures)))
sys.exit(1 if failures or checked == 0 else 0)
