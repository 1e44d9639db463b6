#!/usr/bin/env python3
"""Checks the g2d editor support files (Python 3 standard library only).

    python3 editors/test/check_grammar.py             # run all checks
    python3 editors/test/check_grammar.py --dump FILE # print the TextMate scopes of FILE

What is checked:

* editors/vscode/package.json, language-configuration.json and
  syntaxes/g2d.tmLanguage.json parse and fit together;
* every `match`/`begin`/`end` regex of the TextMate grammar stays in the
  subset common to Oniguruma and Python's `re` and compiles with `re`;
* a small interpreter of the grammar (match rules, begin/end rules, captures,
  includes) tokenizes examples/*.g2d, stdlib/*.g2d and the ```g2d blocks of
  docs/language.md, and chosen tokens get the expected scopes;
* every keyword of grammar/G2d.g4 and every built-in function of
  compiler/sema/builtins.cpp is known to both the TextMate grammar and
  editors/vim/syntax/g2d.vim, and the keywords are the ones docs/language.md lists;
* if `vim` is installed: the Vim files load without errors and give chosen
  tokens the expected syntax groups.

The last line is `N passed, M failed`; the exit code is 1 if anything failed.
"""

import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
EDITORS = os.path.dirname(HERE)
ROOT = os.path.dirname(EDITORS)
VSCODE = os.path.join(EDITORS, "vscode")
VIM = os.path.join(EDITORS, "vim")

IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")

# --------------------------------------------------------------------------
# Test bookkeeping


class Results:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, ok, what, detail=""):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print("FAIL: " + what + (("\n      " + detail) if detail else ""))
        return ok


R = Results()


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def rel(path):
    return os.path.relpath(path, ROOT)


# --------------------------------------------------------------------------
# Oniguruma -> Python regex translation.
#
# The grammar keeps to the subset both engines read the same way. Constructs
# that exist only in Oniguruma (or mean something else in Python) are
# rejected, the one harmless spelling difference is translated.

ONIG_ONLY_ESCAPES = {
    "h": r"\h (hex digit)", "H": r"\H", "G": r"\G (match start)", "K": r"\K", "R": r"\R",
    "X": r"\X", "y": r"\y", "Y": r"\Y", "Z": r"\Z (differs from Python's \Z)",
    "p": r"\p{...} (property)", "P": r"\P{...}", "k": r"\k<name> (named backreference)",
    "g": r"\g<name> (subexpression call)", "O": r"\O", "o": r"\o{...}",
}


class RegexError(Exception):
    pass


def translate(rx):
    """Returns the Python spelling of Oniguruma regex `rx`, or raises RegexError."""
    out = []
    i = 0
    in_class = False
    n = len(rx)
    prev_quantifier = False
    while i < n:
        c = rx[i]
        if c == "\\":
            if i + 1 >= n:
                raise RegexError("trailing backslash")
            e = rx[i + 1]
            if e in ONIG_ONLY_ESCAPES:
                raise RegexError("Oniguruma-only escape " + ONIG_ONLY_ESCAPES[e])
            if e == "x" and i + 2 < n and rx[i + 2] == "{":
                raise RegexError(r"\x{...} escape")
            if e == "z":
                out.append(r"\Z")  # Oniguruma \z == Python \Z: the very end
            else:
                out.append(c + e)
            i += 2
            prev_quantifier = False
            continue
        if in_class:
            if rx.startswith("[:", i):
                raise RegexError("POSIX bracket expression [:...:]")
            if rx.startswith("&&", i):
                raise RegexError("character class intersection &&")
            if c == "[":
                raise RegexError("nested character class")
            if c == "]":
                in_class = False
            out.append(c)
            i += 1
            continue
        if c == "[":
            in_class = True
            out.append(c)
            i += 1
            # a leading ] or ^] is a literal
            if rx.startswith("^", i):
                out.append("^")
                i += 1
            if rx.startswith("]", i):
                out.append("]")
                i += 1
            prev_quantifier = False
            continue
        if c == "(" and rx.startswith("(?", i):
            if rx.startswith("(?>", i):
                raise RegexError("atomic group (?>...)")
            if rx.startswith("(?~", i):
                raise RegexError("absent operator (?~...)")
            m = re.match(r"\(\?<([A-Za-z_]\w*)>", rx[i:])
            if m:
                out.append("(?P<" + m.group(1) + ">")
                i += m.end()
            else:
                out.append("(?")
                i += 2
            prev_quantifier = False
            continue
        is_quant = c in "*+?" or (c == "}" and re.search(r"\{\d*,?\d*\Z", "".join(out)) is not None)
        if is_quant and prev_quantifier:
            if c == "+":
                raise RegexError("possessive quantifier")
            if c == "?":  # lazy quantifier: the same in both engines
                out.append(c)
                i += 1
                prev_quantifier = False
                continue
        if is_quant:
            out.append(c)
            i += 1
            prev_quantifier = True
            continue
        out.append(c)
        i += 1
        prev_quantifier = False
    if in_class:
        raise RegexError("unterminated character class")
    return "".join(out)


_compiled = {}


def compile_rx(rx):
    if rx not in _compiled:
        _compiled[rx] = re.compile(translate(rx))
    return _compiled[rx]


# --------------------------------------------------------------------------
# A small TextMate interpreter: enough of vscode-textmate's algorithm for
# grammars made of match rules, begin/end rules, captures (with nested
# patterns) and includes. Lines are fed with a trailing "\n", as VS Code does.


class Frame:
    def __init__(self, rule, scopes, content_scopes, end_rx, patterns):
        self.rule = rule
        self.scopes = scopes              # scopes of the begin/end matches
        self.content_scopes = content_scopes
        self.end_rx = end_rx
        self.patterns = patterns


class Tokenizer:
    def __init__(self, grammar):
        self.grammar = grammar
        self.repo = grammar.get("repository", {})
        self.root_scope = grammar["scopeName"]
        self._flat = {}

    def initial_stack(self):
        scopes = [self.root_scope]
        return [Frame(None, scopes, scopes, None, self.grammar["patterns"])]

    def _lookup(self, include):
        if include in ("$self", "$base"):
            return {"patterns": self.grammar["patterns"]}
        if include.startswith("#"):
            name = include[1:]
            if name not in self.repo:
                raise KeyError("unknown repository entry " + include)
            return self.repo[name]
        raise KeyError("external include not supported: " + include)

    def flatten(self, patterns):
        key = id(patterns)
        if key in self._flat:
            return self._flat[key]
        out = []
        seen = set()

        def walk(pats):
            for p in pats:
                if "include" in p:
                    target = self._lookup(p["include"])
                    if id(target) in seen:
                        continue
                    seen.add(id(target))
                    walk([target])
                elif "match" in p or "begin" in p:
                    out.append(p)
                elif "patterns" in p:
                    walk(p["patterns"])
        walk(patterns)
        self._flat[key] = out
        return out

    def _apply_captures(self, caps, m, scopes_of, text, limit):
        """Adds capture scopes to scopes_of[i] (a list per character)."""
        if not caps:
            return
        for key in sorted(caps, key=int):
            g = int(key)
            if g > (m.re.groups or 0):
                continue
            s, e = m.span(g)
            if s < 0 or s == e:
                continue
            cap = caps[key]
            name = cap.get("name")
            for i in range(s, min(e, limit)):
                if name:
                    scopes_of[i].extend(name.split())
            if "patterns" in cap:
                sub = text[s:e]
                stack = [Frame(None, [], [], None, cap["patterns"])]
                sub_scopes, _ = self.tokenize_line(sub, stack, feed_newline=False)
                for j, extra in enumerate(sub_scopes):
                    if s + j < limit:
                        scopes_of[s + j].extend(extra)

    def tokenize_line(self, line, stack, feed_newline=True):
        """Returns (scopes per character of line, new stack)."""
        stack = list(stack)
        text = line + "\n" if feed_newline else line
        limit = len(line)
        scopes_of = [None] * limit
        pos = 0
        pushed_here = set()
        guard = 0
        while pos <= limit:
            guard += 1
            if guard > 10000:
                raise RuntimeError("tokenizer does not advance at column %d" % pos)
            top = stack[-1]
            best = None  # (start, order, kind, rule, match)
            if top.end_rx is not None:
                m = top.end_rx.search(text, pos)
                if m and m.start() <= limit:
                    best = (m.start(), -1, "end", None, m)
            for order, rule in enumerate(self.flatten(top.patterns)):
                rx = compile_rx(rule["match"] if "match" in rule else rule["begin"])
                m = rx.search(text, pos)
                if not m or m.start() > limit:
                    continue
                if best is None or m.start() < best[0]:
                    best = (m.start(), order, "match" if "match" in rule else "begin", rule, m)
            if best is None:
                for i in range(pos, limit):
                    scopes_of[i] = list(top.content_scopes)
                break
            start, _, kind, rule, m = best
            for i in range(pos, min(start, limit)):
                scopes_of[i] = list(top.content_scopes)
            end = m.end()
            if kind == "end":
                for i in range(start, min(end, limit)):
                    scopes_of[i] = list(top.scopes)
                self._apply_captures(top.rule.get("endCaptures", top.rule.get("captures")),
                                     m, scopes_of, text, limit)
                stack.pop()  # the root frame has no end, so the stack never empties
                pos = end
                continue
            base = list(top.content_scopes) + (rule["name"].split() if rule.get("name") else [])
            for i in range(start, min(end, limit)):
                scopes_of[i] = list(base)
            if kind == "match":
                self._apply_captures(rule.get("captures"), m, scopes_of, text, limit)
                if end == start:  # empty match: skip one character
                    if start < limit:
                        scopes_of[start] = list(top.content_scopes)
                    pos = start + 1
                else:
                    pos = end
                continue
            # begin
            self._apply_captures(rule.get("beginCaptures", rule.get("captures")),
                                 m, scopes_of, text, limit)
            if end == start:
                key = (id(rule), start)
                if key in pushed_here:
                    if start < limit:
                        scopes_of[start] = list(top.content_scopes)
                    pos = start + 1
                    continue
                pushed_here.add(key)
            content = base + (rule["contentName"].split() if rule.get("contentName") else [])
            stack.append(Frame(rule, base, content, compile_rx(rule["end"]), rule.get("patterns", [])))
            pos = end
            if pos > limit:
                break
        for i in range(limit):
            if scopes_of[i] is None:
                scopes_of[i] = list(stack[-1].content_scopes)
        return scopes_of, stack

    def tokenize(self, source):
        """Returns (list of per-character scope lists, one per line; final stack)."""
        stack = self.initial_stack()
        lines = []
        for line in source.split("\n"):
            if line.endswith("\r"):
                line = line[:-1]
            scopes, stack = self.tokenize_line(line, stack)
            lines.append(scopes)
        return lines, stack


def has_scope(scopes, prefix):
    return any(s == prefix or s.startswith(prefix + ".") for s in scopes)


def tokens_of(line, scopes):
    """Merges characters with equal scopes into (text, scopes) tokens."""
    out = []
    for i, ch in enumerate(line):
        if out and out[-1][1] == scopes[i]:
            out[-1][0] += ch
        else:
            out.append([ch, scopes[i]])
    return out


# --------------------------------------------------------------------------
# Shared data: keywords from the ANTLR grammar, built-ins from the checker.


def g4_keywords():
    text = read(os.path.join(ROOT, "grammar", "G2d.g4"))
    text = re.sub(r"//[^\n]*", "", text)
    words = set()
    for lit in re.findall(r"'((?:[^'\\]|\\.)*)'", text):
        if IDENT.match(lit):
            words.add(lit)
    return sorted(words)


def builtin_functions():
    text = read(os.path.join(ROOT, "compiler", "sema", "builtins.cpp"))
    body = text[text.index("builtinFunctions()"):]
    body = body[:body.index("};")]
    return sorted(set(re.findall(r'\{"([A-Za-z_]\w*)",\s*-?\d+,\s*-?\d+,\s*Builtin::\w+,', body)))


PRIMITIVE_TYPES = ["int", "float", "bool", "string", "vec2"]
BUILTIN_CONSTANTS = ["pi", "tau"]


# --------------------------------------------------------------------------
# 1. The VS Code extension's JSON files


def check_json_files():
    files = {}
    for name in ("package.json", "language-configuration.json", os.path.join("syntaxes", "g2d.tmLanguage.json")):
        path = os.path.join(VSCODE, name)
        try:
            files[name] = json.loads(read(path))
            R.check(True, "parse " + rel(path))
        except (OSError, ValueError) as e:
            R.check(False, "parse " + rel(path), str(e))
    pkg = files.get("package.json")
    conf = files.get("language-configuration.json")
    gram = files.get(os.path.join("syntaxes", "g2d.tmLanguage.json"))
    if pkg:
        langs = pkg.get("contributes", {}).get("languages", [])
        grams = pkg.get("contributes", {}).get("grammars", [])
        lang = next((l for l in langs if l.get("id") == "g2d"), None)
        R.check(lang is not None, "package.json contributes language id `g2d`")
        if lang:
            R.check(".g2d" in lang.get("extensions", []), "package.json: language g2d has extension .g2d")
            cfg = lang.get("configuration", "")
            R.check(os.path.isfile(os.path.join(VSCODE, cfg)),
                    "package.json: language configuration file exists", cfg)
        gr = next((g for g in grams if g.get("language") == "g2d"), None)
        R.check(gr is not None, "package.json contributes a grammar for g2d")
        if gr:
            R.check(os.path.isfile(os.path.join(VSCODE, gr.get("path", ""))),
                    "package.json: grammar file exists", gr.get("path", ""))
            if gram:
                R.check(gr.get("scopeName") == gram.get("scopeName") == "source.g2d",
                        "grammar scopeName is source.g2d in package.json and the grammar")
        R.check(all(k in pkg for k in ("name", "version", "publisher", "engines")),
                "package.json has name, version, publisher, engines")
    if conf:
        R.check(conf.get("comments", {}).get("lineComment") == "//"
                and conf.get("comments", {}).get("blockComment") == ["/*", "*/"],
                "language configuration: comments // and /* */")
        R.check(all(p in conf.get("brackets", []) for p in (["{", "}"], ["[", "]"], ["(", ")"])),
                "language configuration: brackets {} [] ()")
        opens = {p["open"] if isinstance(p, dict) else p[0]: p for p in conf.get("autoClosingPairs", [])}
        R.check(all(o in opens for o in ("{", "[", "(", '"')),
                "language configuration: auto-closing pairs include { [ ( and quotes")
        markers = conf.get("folding", {}).get("markers", {})
        ok = False
        try:
            start, end = re.compile(markers["start"]), re.compile(markers["end"])
            ok = (bool(start.search("rule Split pick oldest {")) and bool(end.search("    }"))
                  and not start.search("produce { a; }") and bool(start.search("match {   // M")))
        except (KeyError, re.error):
            pass
        R.check(ok, "language configuration: folding markers on braces")
    return gram


# --------------------------------------------------------------------------
# 2. Regexes and includes of the TextMate grammar


def walk_rules(node, path, out):
    if isinstance(node, dict):
        for key in ("match", "begin", "end", "while"):
            if key in node:
                out.append((path + "/" + key, node[key]))
        for k, v in node.items():
            walk_rules(v, path + "/" + str(k), out)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            walk_rules(v, path + "/" + str(i), out)


def check_regexes(gram):
    found = []
    walk_rules({"patterns": gram.get("patterns", []), "repository": gram.get("repository", {})}, "", found)
    bad = []
    for where, rx in found:
        if not isinstance(rx, str):
            bad.append("%s: not a string" % where)
            continue
        try:
            compile_rx(rx)
        except (RegexError, re.error) as e:
            bad.append("%s: %s: %s" % (where, rx, e))
    R.check(not bad and len(found) > 20, "%d grammar regexes compile (Oniguruma/Python common subset)" % len(found),
            "\n      ".join(bad))
    # begin rules need an end, includes must resolve
    problems = []
    repo = gram.get("repository", {})

    def visit(node, path):
        if isinstance(node, dict):
            if "begin" in node and "end" not in node:
                problems.append(path + ": begin without end")
            inc = node.get("include")
            if inc is not None and inc not in ("$self", "$base") and not (inc.startswith("#") and inc[1:] in repo):
                problems.append(path + ": unresolved include " + inc)
            for k, v in node.items():
                visit(v, path + "/" + k)
        elif isinstance(node, list):
            for i, v in enumerate(node):
                visit(v, path + "/" + str(i))
    visit(gram, "")
    R.check(not problems, "grammar includes resolve and begin rules have an end", "\n      ".join(problems))
    # the translator itself
    for rx, ok in ((r"a++", False), (r"(?>a)", False), (r"\h", False), (r"[[:alpha:]]", False),
                   (r"(?<=x)a", True), (r"[+-]?\d+", True), (r"a+?", True), (r"(?<n>a)\z", True)):
        try:
            translate(rx)
            res = True
        except RegexError:
            res = False
        R.check(res == ok, "translator %s %s" % ("accepts" if ok else "rejects", rx))


# --------------------------------------------------------------------------
# 3. Tokenizing real code

# (file, text of the line (first line containing it), token, occurrence, scope prefix, expected?)
EXPECT = [
    # examples/koch_snowflake.g2d
    ("examples/koch_snowflake.g2d", "// Koch snowflake", "Koch", 0, "comment.line.double-slash", True),
    ("examples/koch_snowflake.g2d", "// Koch snowflake", "//", 0, "punctuation.definition.comment", True),
    ("examples/koch_snowflake.g2d", "// Splitting the oldest edge", "edge", 0, "comment", True),
    ("examples/koch_snowflake.g2d", "// Splitting the oldest edge", "edge", 0, "keyword", False),
    ("examples/koch_snowflake.g2d", "param max_lod: int = 4;", "param", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "param max_lod: int = 4;", "max_lod", 0, "variable.other.constant", True),
    ("examples/koch_snowflake.g2d", "param max_lod: int = 4;", "int", 0, "support.type.primitive", True),
    ("examples/koch_snowflake.g2d", "param max_lod: int = 4;", "4", 0, "constant.numeric.integer", True),
    ("examples/koch_snowflake.g2d", "const spike = sqrt(3) / 6;", "const", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "const spike = sqrt(3) / 6;", "sqrt", 0, "support.function", True),
    ("examples/koch_snowflake.g2d", "const spike = sqrt(3) / 6;", "/", 0, "keyword.operator.arithmetic", True),
    ("examples/koch_snowflake.g2d", "node Point {", "node", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "node Point {", "Point", 0, "entity.name.type", True),
    ("examples/koch_snowflake.g2d", 'style { tag = "none"; }', "style", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", 'style { tag = "none"; }', "tag", 0, "support.type.property-name", True),
    ("examples/koch_snowflake.g2d", 'style { tag = "none"; }', "// the thesis", 0, "comment", True),
    ("examples/koch_snowflake.g2d", "edge Seg directed {", "edge", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "edge Seg directed {", "Seg", 0, "entity.name.type", True),
    ("examples/koch_snowflake.g2d", "edge Seg directed {", "directed", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "lod: int = 0;", "int", 0, "support.type.primitive", True),
    ("examples/koch_snowflake.g2d", 'stroke = "black"', '"black"', 0, "string.quoted.double", True),
    ("examples/koch_snowflake.g2d", 'stroke = "black"', "stroke_width", 0, "support.type.property-name", True),
    ("examples/koch_snowflake.g2d", 'stroke = "black"', "0.1", 0, "constant.numeric", True),
    ("examples/koch_snowflake.g2d", 'stroke = "black"', "0.1", 0, "constant.numeric.float", True),
    ("examples/koch_snowflake.g2d", "axiom {", "axiom", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "a: Point at (-4, 0);", "a", 0, "variable.other.element", True),
    ("examples/koch_snowflake.g2d", "a: Point at (-4, 0);", "Point", 0, "entity.name.type", True),
    ("examples/koch_snowflake.g2d", "a: Point at (-4, 0);", "at", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "a: Point at (-4, 0);", "-", 0, "keyword.operator.arithmetic", True),
    ("examples/koch_snowflake.g2d", "b: Point at (0, 6.93);", "6.93", 0, "constant.numeric.float", True),
    ("examples/koch_snowflake.g2d", "a -[Seg]-> b;", "-[", 0, "keyword.operator.arrow", True),
    ("examples/koch_snowflake.g2d", "a -[Seg]-> b;", "Seg", 0, "entity.name.type", True),
    ("examples/koch_snowflake.g2d", "a -[Seg]-> b;", "]->", 0, "keyword.operator.arrow", True),
    ("examples/koch_snowflake.g2d", "rule Split pick oldest {", "rule", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "rule Split pick oldest {", "Split", 0, "entity.name.function", True),
    ("examples/koch_snowflake.g2d", "rule Split pick oldest {", "pick", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "rule Split pick oldest {", "oldest", 0, "support.constant", True),
    ("examples/koch_snowflake.g2d", "match {", "match", 0, "keyword.control", True),
    ("examples/koch_snowflake.g2d", "old: s -[Seg]-> e where", "old", 0, "variable.other.element", True),
    ("examples/koch_snowflake.g2d", "old: s -[Seg]-> e where", "s", 0, "entity.name.type", False),
    ("examples/koch_snowflake.g2d", "old: s -[Seg]-> e where", "Seg", 0, "entity.name.type", True),
    ("examples/koch_snowflake.g2d", "old: s -[Seg]-> e where", "where", 0, "keyword.control", True),
    ("examples/koch_snowflake.g2d", "old: s -[Seg]-> e where", "lod", 0, "variable.other.member", True),
    ("examples/koch_snowflake.g2d", "old: s -[Seg]-> e where", "<", 0, "keyword.operator.comparison", True),
    ("examples/koch_snowflake.g2d", "let lod = old.lod + 1;", "let", 0, "keyword", True),
    ("examples/koch_snowflake.g2d", "let lod = old.lod + 1;", "lod", 0, "variable.other.let", True),
    ("examples/koch_snowflake.g2d", "produce {", "produce", 0, "keyword.control", True),
    ("examples/koch_snowflake.g2d", "t: Point at A + v / 2", "perp_left", 0, "support.function", True),
    ("examples/koch_snowflake.g2d", "t: Point at A + v / 2", "spike", 0, "support", False),
    ("examples/koch_snowflake.g2d", "s -[Seg { lod = lod }]-> p;", "Seg", 0, "entity.name.type", True),
    ("examples/koch_snowflake.g2d", "s -[Seg { lod = lod }]-> p;", "{", 0, "punctuation.section.block.begin", True),
    ("examples/koch_snowflake.g2d", "s -[Seg { lod = lod }]-> p;", "=", 0, "keyword.operator.assignment", True),
    ("examples/koch_snowflake.g2d", "s -[Seg { lod = lod }]-> p;", ";", 0, "punctuation.terminator", True),
    # examples/tree.g2d
    ("examples/tree.g2d", 'import "plants.g2d";', "import", 0, "keyword", True),
    ("examples/tree.g2d", 'import "plants.g2d";', '"plants.g2d"', 0, "string", True),
    ("examples/tree.g2d", "limit 200;", "limit", 0, "keyword", True),
    ("examples/tree.g2d", "enum Label { Trunk, Branch, Done }", "enum", 0, "keyword", True),
    ("examples/tree.g2d", "enum Label { Trunk, Branch, Done }", "Label", 0, "entity.name.type", True),
    ("examples/tree.g2d", "label: Label = Trunk;", "Label", 0, "entity.name.type", True),
    ("examples/tree.g2d", "width: float = 10;", "float", 0, "support.type.primitive", True),
    ("examples/tree.g2d", "base: Joint at (0, -2.269129287598944);", "2.269129287598944", 0,
     "constant.numeric.float", True),
    ("examples/tree.g2d", "trunk: a -[Stem]-> b where trunk.label == Trunk and", "and", 0,
     "keyword.operator.logical", True),
    ("examples/tree.g2d", "trunk: a -[Stem]-> b where trunk.label == Trunk and", "==", 0,
     "keyword.operator.comparison", True),
    ("examples/tree.g2d", "side: Joint at B + branch_offset(A, B);", "branch_offset", 0,
     "entity.name.function.call", True),
    ("examples/tree.g2d", "side: Joint at B + branch_offset(A, B);", "branch_offset", 0, "support.function", False),
    # examples/maze.g2d
    ("examples/maze.g2d", "not { r: Cell; c -[Right]-> r; }", "not", 0, "keyword.control", True),
    ("examples/maze.g2d", "not { r: Cell; c -[Right]-> r; }", "Right", 0, "entity.name.type", True),
    ("examples/maze.g2d", "link; u { visited = true }; v -[Corridor]- u;", "-[", 0, "keyword.operator.arrow", True),
    ("examples/maze.g2d", "link; u { visited = true }; v -[Corridor]- u;", "Corridor", 0, "entity.name.type", True),
    ("examples/maze.g2d", "link; u { visited = true }; v -[Corridor]- u;", "]-", 0, "keyword.operator.arrow", True),
    ("examples/maze.g2d", "link; u { visited = true }; v -[Corridor]- u;", "true", 0,
     "constant.language.boolean", True),
    ("examples/maze.g2d", "u: Cell where not u.visited;", "not", 0, "keyword.operator.logical", True),
    ("examples/maze.g2d", "visited: bool = false;", "bool", 0, "support.type.primitive", True),
    ("examples/maze.g2d", "visited: bool = false;", "false", 0, "constant.language.boolean", True),
    ("examples/maze.g2d", 'stroke = "#1c2833"', '"#1c2833"', 0, "string", True),
    ("examples/maze.g2d", "rule GrowRow priority 0 {", "priority", 0, "keyword", True),
    ("examples/maze.g2d", "rule GrowRow priority 0 {", "GrowRow", 0, "entity.name.function", True),
    # examples/mondrian.g2d
    ("examples/mondrian.g2d", "produce weight 4 {", "weight", 0, "keyword", True),
    ("examples/mondrian.g2d", "let t = uniform(0.3, 0.7);", "uniform", 0, "support.function", True),
    ("examples/mondrian.g2d", 'fill = color == "" ? "white" : color;', "?", 0, "keyword.operator.ternary", True),
    ("examples/mondrian.g2d", 'fill = color == "" ? "white" : color;', ":", 0, "keyword.operator.ternary", True),
    ("examples/mondrian.g2d", 'fill = color == "" ? "white" : color;', "color", 1, "entity.name.type", False),
    ("examples/mondrian.g2d", 'fill = color == "" ? "white" : color;', "fill", 0, "support.type.property-name", True),
    ("examples/mondrian.g2d", 'fill = color == "" ? "white" : color;', "color", 0, "support.type.property-name",
     False),
    ("examples/mondrian.g2d", "b { color = choice(", "choice", 0, "support.function", True),
    # examples/sierpinski.g2d
    ("examples/sierpinski.g2d", "rule Split parallel {", "parallel", 0, "keyword", True),
    ("examples/sierpinski.g2d", "where cross(b.pos - a.pos, c.pos - a.pos) > 0;", "cross", 0,
     "support.function", True),
    ("examples/sierpinski.g2d", "limit generations + 1;", "generations", 0, "keyword", False),
]

# Constructs the examples do not (all) contain, as a synthetic file.
SNIPPET = r'''/* a block
   comment with rule and node */
import "x.g2d";
defs "<filter id=\"blur\"/>";
const half: float = 1.5e3 + .5 + 2E-2 + 7;
const turn = tau / 4 + pi;
param who: Side = Left;
param depth: int = 6 in 1..10 step 2;
param tilt: float = 0.5 in 0.25..turn;
enum Side { Left, Right, }
fn mid(a: vec2, b: vec2) -> vec2 = (a + b) / 2;
fn pickone(x: int) -> Side = x > 0 ? Side.Left : Right;
node P { n: int = 0; style { tag = "circle"; r = n > 1 ? 2 : 1; } }
edge U undirected;
edge D directed;
limit 10;
priority 1 limit 5 parallel;
canvas (-1, 0) to (half, 2);
axiom { p: P at vec2(0, 0); q: P at (1, 0); p -[U]- q; q <-[D]- p; }
rule R priority -1 pick random ordered {
    match { x: P @ (0, 0); w: *; e: x -[U { }]- w where w.degree > 1 && !false || true; }
    let k: float = float(x.n) * 2;
    produce weight 2 {
        x { n = int(k), style.fill = "red\n" };
        y: P @ (1, 0.5);
        x -[D]-> y;
    }
}
'''

SNIPPET_EXPECT = [
    ("/* a block", "/*", 0, "comment.block", True),
    ("/* a block", "/*", 0, "punctuation.definition.comment.begin", True),
    ("comment with rule and node */", "rule", 0, "comment.block", True),
    ("comment with rule and node */", "rule", 0, "keyword", False),
    ("comment with rule and node */", "*/", 0, "punctuation.definition.comment.end", True),
    ("defs ", "defs", 0, "keyword", True),
    ("defs ", '\\"', 0, "constant.character.escape", True),
    ("defs ", '\\"', 0, "string.quoted.double", True),
    ("defs ", ";", 0, "string", False),
    ("const half", "1.5e3", 0, "constant.numeric.float", True),
    ("const half", ".5", 0, "constant.numeric.float", True),
    ("const half", "2E-2", 0, "constant.numeric.float", True),
    ("const half", "7", 0, "constant.numeric.integer", True),
    ("const half", "float", 0, "support.type.primitive", True),
    ("const turn", "tau", 0, "support.constant", True),
    ("const turn", "pi", 0, "support.constant", True),
    ("param who: Side", "Side", 0, "entity.name.type", True),
    ("param depth", "in", 0, "keyword.control", True),
    ("param depth", "1", 0, "constant.numeric.integer", True),
    ("param depth", "..", 0, "keyword.operator.range", True),
    ("param depth", "10", 0, "constant.numeric.integer", True),
    ("param depth", "step", 0, "keyword.control", True),
    ("param depth", "2", 0, "constant.numeric.integer", True),
    ("param tilt", "0.25", 0, "constant.numeric.float", True),
    ("param tilt", "..", 0, "keyword.operator.range", True),
    ("param tilt", "turn", 0, "keyword", False),
    ("enum Side", "Side", 0, "entity.name.type", True),
    ("fn mid", "fn", 0, "keyword", True),
    ("fn mid", "mid", 0, "entity.name.function", True),
    ("fn mid", "vec2", 0, "support.type.primitive", True),
    ("fn mid", "->", 0, "keyword.operator.arrow", True),
    ("fn mid", "vec2", 2, "support.type.primitive", True),
    ("fn pickone", "Side", 0, "entity.name.type", True),
    ("fn pickone", "?", 0, "keyword.operator.ternary", True),
    ("fn pickone", "Right", 0, "entity.name.type", False),
    ("node P {", "style", 0, "keyword", True),
    ("node P {", "r", 0, "support.type.property-name", True),
    ("node P {", "2", 0, "constant.numeric", True),
    ("edge U undirected;", "undirected", 0, "keyword", True),
    ("edge U undirected;", "U", 0, "entity.name.type", True),
    ("priority 1 limit 5 parallel;", "parallel", 0, "keyword", True),
    ("canvas (-1, 0) to", "canvas", 0, "keyword.declaration", True),
    ("canvas (-1, 0) to", "to", 0, "keyword.declaration", True),
    ("canvas (-1, 0) to", "half", 0, "keyword", False),
    ("canvas (-1, 0) to", "2", 0, "constant.numeric.integer", True),
    ("axiom {", "vec2", 0, "support.function", True),
    ("axiom {", "vec2", 0, "support.type", False),
    ("axiom {", "<-[", 0, "keyword.operator.arrow", True),
    ("axiom {", "D", 0, "entity.name.type", True),
    ("axiom {", "]-", 1, "keyword.operator.arrow", True),
    ("rule R priority -1", "random", 0, "support.constant", True),
    ("rule R priority -1", "random", 0, "support.function", False),
    ("rule R priority -1", "ordered", 0, "keyword", True),
    ("match { x: P @ (0, 0)", "@", 0, "keyword.operator.sketch", True),
    ("match { x: P @ (0, 0)", "*", 0, "keyword.other.wildcard", True),
    ("match { x: P @ (0, 0)", "w", 0, "variable.other.element", True),
    ("match { x: P @ (0, 0)", "e", 0, "variable.other.element", True),
    ("match { x: P @ (0, 0)", "&&", 0, "keyword.operator.logical", True),
    ("match { x: P @ (0, 0)", "||", 0, "keyword.operator.logical", True),
    ("match { x: P @ (0, 0)", "!", 0, "keyword.operator.logical", True),
    ("match { x: P @ (0, 0)", "degree", 0, "variable.other.member", True),
    ("let k: float", "float", 0, "support.type.primitive", True),
    ("let k: float", "float", 1, "support.function", True),
    ("x { n = int(k)", "int", 0, "support.function", True),
    ("x { n = int(k)", "style", 0, "keyword", True),
    ("x { n = int(k)", "fill", 0, "support.type.property-name", True),
    ("x { n = int(k)", "\\n", 0, "constant.character.escape", True),
    ("y: P @ (1, 0.5);", "0.5", 0, "constant.numeric.float", True),
]


def find_token(line, token, nth):
    """Column of the nth occurrence of token in line (whole words for identifiers)."""
    if IDENT.match(token):
        pat = re.compile(r"(?<![A-Za-z0-9_])" + re.escape(token) + r"(?![A-Za-z0-9_])")
    else:
        pat = re.compile(re.escape(token))
    ms = list(pat.finditer(line))
    if nth >= len(ms):
        return -1
    return ms[nth].start()


def check_expectation(label, lines, scopes, needle, token, nth, prefix, expected):
    what = "%s: %r in %r (#%d) %s %s" % (label, token, needle, nth, "is" if expected else "is not", prefix)
    idx = next((i for i, l in enumerate(lines) if needle in l), None)
    if idx is None:
        R.check(False, what, "line not found")
        return
    col = find_token(lines[idx], token, nth)
    if col < 0:
        R.check(False, what, "token not found in line %d" % (idx + 1))
        return
    span = scopes[idx][col:col + len(token)]
    if expected:
        ok = all(has_scope(s, prefix) for s in span)
    else:
        ok = not any(has_scope(s, prefix) for s in span)
    detail = "line %d col %d: %s" % (idx + 1, col + 1, " | ".join(
        "%r %s" % (t, " ".join(s[1:])) for t, s in tokens_of(lines[idx], scopes[idx])))
    R.check(ok, what, detail)


CODE_RE = re.compile(r"^```g2d\n(.*?)^```", re.S | re.M)
KEYWORD_SCOPES = ("keyword", "constant.language")
# Keywords G2d.g4 also accepts as a parameter's name (`param merge: bool`).
NAME_KEYWORDS = ("merge",)


def check_clean(tok, label, source, keywords, builtins):
    """Tokenizes a whole file: it must end at the root and every keyword or
    built-in call outside comments and strings must be scoped as such."""
    try:
        scopes, stack = tok.tokenize(source)
    except Exception as e:  # noqa: BLE001 - report any interpreter failure
        R.check(False, "tokenize " + label, repr(e))
        return None, None
    lines = source.split("\n")
    problems = []
    if len(stack) != 1:
        problems.append("ends inside " + " ".join(stack[-1].scopes))
    kw_rx = re.compile(r"(?<![A-Za-z0-9_.])(%s)(?![A-Za-z0-9_])" % "|".join(keywords))
    bi_rx = re.compile(r"(?<![A-Za-z0-9_.])(%s)(?=\s*\()" % "|".join(builtins))
    for n, line in enumerate(lines):
        for rx, want in ((kw_rx, KEYWORD_SCOPES), (bi_rx, ("support.function",))):
            for m in rx.finditer(line):
                s = scopes[n][m.start()]
                if has_scope(s, "comment") or has_scope(s, "string"):
                    continue
                if m.group(1) == "random" and has_scope(s, "support.constant.pick"):
                    continue
                if m.group(1) in NAME_KEYWORDS and has_scope(s, "variable"):
                    continue
                if not any(has_scope(s, w) for w in want):
                    problems.append("%d:%d %r scoped %s" % (n + 1, m.start() + 1, m.group(1), " ".join(s)))
    R.check(not problems, "tokenize " + label + " (keywords and built-ins scoped, no open region at the end)",
            "\n      ".join(problems[:10]))
    return lines, scopes


def check_tokenizing(gram):
    tok = Tokenizer(gram)
    keywords = g4_keywords()
    builtins = builtin_functions()
    examples = sorted(glob.glob(os.path.join(ROOT, "examples", "*.g2d")))
    R.check(len(examples) >= 3, "examples/*.g2d found", str(len(examples)))
    tokenized = {}
    for path in examples + sorted(glob.glob(os.path.join(ROOT, "stdlib", "*.g2d"))):
        lines, scopes = check_clean(tok, rel(path), read(path), keywords, builtins)
        tokenized[rel(path)] = (lines, scopes)
    doc = os.path.join(ROOT, "docs", "language.md")
    if os.path.isfile(doc):
        blocks = CODE_RE.findall(read(doc))
        for i, block in enumerate(blocks):
            check_clean(tok, "%s g2d block %d" % (rel(doc), i + 1), block, keywords, builtins)
    for fname, needle, token, nth, prefix, expected in EXPECT:
        key = fname.replace("/", os.sep)
        if key not in tokenized:
            R.check(False, "%s exists" % fname)
            continue
        lines, scopes = tokenized[key]
        if lines is None:
            continue
        check_expectation(fname, lines, scopes, needle, token, nth, prefix, expected)
    lines, scopes = check_clean(tok, "snippet", SNIPPET, keywords, builtins)
    if lines is not None:
        for needle, token, nth, prefix, expected in SNIPPET_EXPECT:
            check_expectation("snippet", lines, scopes, needle, token, nth, prefix, expected)
    # keywords and built-ins, each alone
    for kw in keywords:
        s, _ = tok.tokenize_line(kw, tok.initial_stack())
        R.check(all(any(has_scope(x, w) for w in KEYWORD_SCOPES) for x in s),
                "keyword `%s` from G2d.g4 is highlighted by the TextMate grammar" % kw, " ".join(s[0]))
    for b in builtins:
        s, _ = tok.tokenize_line(b + "(x)", tok.initial_stack())
        R.check(all(has_scope(x, "support.function") for x in s[:len(b)]),
                "built-in `%s(` from builtins.cpp is support.function" % b, " ".join(s[0]))
    for t in PRIMITIVE_TYPES:
        s, _ = tok.tokenize_line("x: " + t + ";", tok.initial_stack())
        R.check(all(has_scope(x, "support.type.primitive") for x in s[3:3 + len(t)]),
                "type `%s` is support.type.primitive" % t)
    for c in BUILTIN_CONSTANTS:
        s, _ = tok.tokenize_line(c, tok.initial_stack())
        R.check(all(has_scope(x, "support.constant") for x in s), "constant `%s` is support.constant" % c)
    # a block comment and an unterminated string across lines
    scopes, stack = tok.tokenize('/* one\n two */ node\n"open\nrule')
    R.check(has_scope(scopes[1][1], "comment.block") and has_scope(scopes[1][8], "keyword")
            and has_scope(scopes[2][2], "string") and has_scope(scopes[3][0], "keyword") and len(stack) == 1,
            "block comments span lines; an unterminated string ends at the line end")


# --------------------------------------------------------------------------
# 4. Vim


def vim_words(text):
    """Words of a Vim script outside its comment lines."""
    code = "\n".join(l for l in text.split("\n") if not l.lstrip().startswith('"'))
    return set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", code))


VIM_EXPECT = [
    # (file, line text, token, occurrence, syntax group)
    ("examples/koch_snowflake.g2d", "// Koch snowflake", "Koch", 0, "g2dLineComment"),
    ("examples/koch_snowflake.g2d", "param max_lod: int = 4;", "param", 0, "g2dDeclKeyword"),
    ("examples/koch_snowflake.g2d", "param max_lod: int = 4;", "int", 0, "g2dElemType"),
    ("examples/koch_snowflake.g2d", "param max_lod: int = 4;", "4", 0, "g2dInteger"),
    ("examples/koch_snowflake.g2d", "const spike = sqrt(3) / 6;", "sqrt", 0, "g2dBuiltin"),
    ("examples/koch_snowflake.g2d", "node Point {", "Point", 0, "g2dTypeName"),
    ("examples/koch_snowflake.g2d", "edge Seg directed {", "directed", 0, "g2dModifier"),
    ("examples/koch_snowflake.g2d", 'stroke = "black"', '"black"', 0, "g2dString"),
    ("examples/koch_snowflake.g2d", 'stroke = "black"', "stroke_width", 0, "g2dStylePropName"),
    ("examples/koch_snowflake.g2d", 'stroke = "black"', "0.1", 0, "g2dFloat"),
    ("examples/koch_snowflake.g2d", "a: Point at (-4, 0);", "Point", 0, "g2dKindRef"),
    ("examples/koch_snowflake.g2d", "a: Point at (-4, 0);", "at", 0, "g2dRuleKeyword"),
    ("examples/koch_snowflake.g2d", "a -[Seg]-> b;", "-[", 0, "g2dArrow"),
    ("examples/koch_snowflake.g2d", "a -[Seg]-> b;", "Seg", 0, "g2dArrowKind"),
    ("examples/koch_snowflake.g2d", "a -[Seg]-> b;", "]->", 0, "g2dArrow"),
    ("examples/koch_snowflake.g2d", "rule Split pick oldest {", "rule", 0, "g2dDeclKeyword"),
    ("examples/koch_snowflake.g2d", "rule Split pick oldest {", "Split", 0, "g2dFuncName"),
    ("examples/koch_snowflake.g2d", "rule Split pick oldest {", "oldest", 0, "g2dPickPolicy"),
    ("examples/koch_snowflake.g2d", "old: s -[Seg]-> e where", "s", 0, ""),
    ("examples/koch_snowflake.g2d", "old: s -[Seg]-> e where", "where", 0, "g2dRuleKeyword"),
    ("examples/koch_snowflake.g2d", "t: Point at A + v / 2", "perp_left", 0, "g2dBuiltin"),
    ("examples/koch_snowflake.g2d", "produce {", "produce", 0, "g2dRuleKeyword"),
    ("examples/maze.g2d", "not { r: Cell; c -[Right]-> r; }", "not", 0, "g2dNegative"),
    ("examples/maze.g2d", "u: Cell where not u.visited;", "not", 0, "g2dLogical"),
    ("examples/maze.g2d", "link; u { visited = true }; v -[Corridor]- u;", "]-", 0, "g2dArrow"),
    ("examples/maze.g2d", "link; u { visited = true }; v -[Corridor]- u;", "true", 0, "g2dBoolean"),
    ("examples/mondrian.g2d", 'fill = color == "" ? "white" : color;', "color", 1, ""),
    ("examples/mondrian.g2d", 'fill = color == "" ? "white" : color;', "?", 0, "g2dOperator"),
    ("snippet", "comment with rule and node */", "rule", 0, "g2dBlockComment"),
    ("snippet", "defs ", '\\"', 0, "g2dEscape"),
    ("snippet", "const half", ".5", 0, "g2dFloat"),
    ("snippet", "const half", "2E-2", 0, "g2dFloat"),
    ("snippet", "const turn", "tau", 0, "g2dConstant"),
    ("snippet", "fn pickone", "->", 0, "g2dReturnArrow"),
    ("snippet", "fn pickone", "Side", 0, "g2dReturnKind"),
    ("snippet", "fn pickone", "Right", 0, ""),
    ("snippet", "param depth", "1", 0, "g2dInteger"),
    ("snippet", "param depth", "10", 0, "g2dInteger"),
    ("snippet", "param depth", "step", 0, "g2dRuleKeyword"),
    ("snippet", "param tilt", "0.25", 0, "g2dFloat"),
    ("snippet", "canvas (-1, 0) to", "canvas", 0, "g2dDeclKeyword"),
    ("snippet", "canvas (-1, 0) to", "to", 0, "g2dDeclKeyword"),
    ("snippet", "axiom {", "vec2", 0, "g2dBuiltin"),
    ("snippet", "axiom {", "<-[", 0, "g2dArrow"),
    ("snippet", "axiom {", "D", 0, "g2dArrowKind"),
    ("snippet", "rule R priority -1", "random", 0, "g2dPickPolicy"),
    ("snippet", "match { x: P @ (0, 0)", "@", 0, "g2dSketch"),
    ("snippet", "match { x: P @ (0, 0)", "*", 0, "g2dWildcard"),
    ("snippet", "let k: float", "float", 0, "g2dElemType"),
    ("snippet", "let k: float", "float", 1, "g2dBuiltin"),
    ("snippet", "x { n = int(k)", "fill", 0, "g2dStyleProp"),
    ("snippet", "x -[D]-> y;", "y", 0, ""),
]


# Vim groups that only contain others and are not linked to a highlight group
VIM_UNCOLOURED = ("", "g2dStyleBlock", "g2dTernary", "g2dElement", "g2dReturnType")


def check_vim():
    syn_path = os.path.join(VIM, "syntax", "g2d.vim")
    ftd_path = os.path.join(VIM, "ftdetect", "g2d.vim")
    try:
        syn, ftd = read(syn_path), read(ftd_path)
    except OSError as e:
        R.check(False, "read the Vim files", str(e))
        return
    words = vim_words(syn)
    for kw in g4_keywords():
        R.check(kw in words, "keyword `%s` from G2d.g4 is in %s" % (kw, rel(syn_path)))
    for b in builtin_functions():
        R.check(b in words, "built-in `%s` from builtins.cpp is in %s" % (b, rel(syn_path)))
    for w in PRIMITIVE_TYPES + BUILTIN_CONSTANTS:
        R.check(w in words, "`%s` is in %s" % (w, rel(syn_path)))
    R.check("current_syntax" in syn, "syntax file sets b:current_syntax")
    R.check("*.g2d" in ftd and "g2d" in ftd, "ftdetect maps *.g2d to filetype g2d")

    vim = shutil.which("vim")
    if not vim:
        print("note: vim not installed, Vim load test skipped")
        return
    files = sorted(set(e[0] for e in VIM_EXPECT))
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.txt")
        snippet = os.path.join(tmp, "snippet.g2d")
        with open(snippet, "w", encoding="utf-8") as f:
            f.write(SNIPPET)

        def path_of(fname):
            return snippet if fname == "snippet" else os.path.join(ROOT, fname)
        cases = []
        for fname, needle, token, nth, group in VIM_EXPECT:
            lines = read(path_of(fname)).split("\n")
            idx = next((i for i, l in enumerate(lines) if needle in l), None)
            col = find_token(lines[idx], token, nth) if idx is not None else -1
            cases.append((fname, idx, col, token, group, needle, nth))
        script = ["set nocompatible", "let &rtp = %s . ',' . &rtp" % vim_str(VIM),
                  "filetype on", "syntax on", "let g:out = []"]
        for f in files:
            script.append("execute 'edit ' . fnameescape(%s)" % vim_str(path_of(f)))
            script.append("call add(g:out, 'FILE ' . %s . ' ft=' . &filetype . ' syn=' . get(b:, 'current_syntax', ''))"
                          % vim_str(f))
            for (fname, idx, col, token, group, needle, nth) in cases:
                if fname != f or idx is None or col < 0:
                    continue
                for k in range(len(token)):
                    script.append("call add(g:out, '%d:%d:' . synIDattr(synID(%d, %d, 1), 'name'))"
                                  % (idx + 1, col + k + 1, idx + 1, col + k + 1))
        script.append("call add(g:out, 'ERR ' . v:errmsg)")
        script.append("call writefile(g:out, %s)" % vim_str(out))
        script.append("qa!")
        sfile = os.path.join(tmp, "check.vim")
        with open(sfile, "w", encoding="utf-8") as f:
            f.write("\n".join(script) + "\n")
        try:
            proc = subprocess.run([vim, "-Es", "-N", "-u", "NONE", "-i", "NONE", "-S", sfile],
                                  stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  timeout=60, cwd=ROOT)
        except subprocess.TimeoutExpired:
            R.check(False, "vim runs the syntax check", "timeout")
            return
        if not R.check(os.path.isfile(out), "vim runs the syntax check",
                       (proc.stdout + proc.stderr).decode(errors="replace")):
            return
        result = read(out).split("\n")
        groups = {}
        for l in result:
            m = re.match(r"(\d+):(\d+):(.*)$", l)
            if m:
                groups.setdefault(current, {})[(int(m.group(1)), int(m.group(2)))] = m.group(3)
            elif l.startswith("FILE "):
                current = l.split()[1]
                R.check("ft=g2d" in l and "syn=g2d" in l, "vim: %s gets filetype and syntax g2d" % current, l)
            elif l.startswith("ERR "):
                R.check(l.strip() == "ERR", "vim loads the g2d files without errors", l)
        for (fname, idx, col, token, group, needle, nth) in cases:
            what = "vim: %s: %r in %r (#%d) is %s" % (fname, token, needle, nth, group or "not highlighted")
            if idx is None or col < 0:
                R.check(False, what, "token not found")
                continue
            got = [groups.get(fname, {}).get((idx + 1, col + k + 1)) for k in range(len(token))]
            if group:
                ok = all(g == group for g in got)
            else:  # plain text, possibly inside a container item that has no colour
                ok = all(g in VIM_UNCOLOURED for g in got)
            R.check(ok, what, "got %s" % got)


def vim_str(s):
    return "'" + s.replace("'", "''") + "'"


# --------------------------------------------------------------------------


def dump(path):
    gram = json.loads(read(os.path.join(VSCODE, "syntaxes", "g2d.tmLanguage.json")))
    tok = Tokenizer(gram)
    source = read(path)
    scopes, _ = tok.tokenize(source)
    for n, (line, sc) in enumerate(zip(source.split("\n"), scopes)):
        print("%4d  %s" % (n + 1, line))
        for text, s in tokens_of(line, sc):
            if text.strip():
                print("        %-24r %s" % (text, " ".join(s[1:])))


def check_docs_keywords():
    """The reference's list of reserved words is the grammar's."""
    path = os.path.join(ROOT, "docs", "language.md")
    text = read(path)
    start = text.find("**Keywords** are reserved")
    block = re.search(r"```\n(.*?)```", text[start:], re.S) if start >= 0 else None
    listed = set(block.group(1).split()) if block else set()
    R.check(bool(listed), "%s lists the keywords" % rel(path))
    for kw in g4_keywords():
        R.check(kw in listed, "keyword `%s` from G2d.g4 is listed in %s" % (kw, rel(path)))
    for w in sorted(listed - set(g4_keywords())):
        R.check(False, "`%s` listed as a keyword in %s is not one in G2d.g4" % (w, rel(path)))


def main(argv):
    if len(argv) == 3 and argv[1] == "--dump":
        dump(argv[2])
        return 0
    if len(argv) != 1:
        print(__doc__)
        return 2
    gram = check_json_files()
    if gram:
        check_regexes(gram)
        check_tokenizing(gram)
    check_vim()
    check_docs_keywords()
    print("%d passed, %d failed" % (R.passed, R.failed))
    return 1 if R.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
