#!/usr/bin/env python3
"""Drives `g2d lsp` over stdio as an editor would (Python standard library only):
initialize -> didOpen with an error -> diagnostics (the same text as `g2d check`)
-> didChange that fixes it -> no diagnostics -> hover -> definition ->
documentSymbol -> completion -> shutdown -> exit (status 0).

usage: lsp_client_test.py G2D SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

g2d, src = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from checks import check, finish  # noqa: E402


class Client:
    def __init__(self):
        self.proc = subprocess.Popen([g2d, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.next_id = 0
        self.notifications = []

    def send(self, message):
        body = json.dumps(message).encode()
        self.proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.proc.stdin.flush()

    def read(self):
        length = None
        while True:
            line = self.proc.stdout.readline()
            if not line:
                raise EOFError("the server closed its output")
            line = line.strip()
            if not line:
                break
            if line.lower().startswith(b"content-length:"):
                length = int(line.split(b":")[1])
        return json.loads(self.proc.stdout.read(length))

    def request(self, method, params):
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": self.next_id, "method": method, "params": params})
        while True:
            m = self.read()
            if m.get("id") == self.next_id:
                return m
            self.notifications.append(m)

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def diagnostics(self):
        while True:
            for i, m in enumerate(self.notifications):
                if m.get("method") == "textDocument/publishDiagnostics":
                    return self.notifications.pop(i)["params"]
            self.notifications.append(self.read())


work = tempfile.mkdtemp()
path = os.path.join(work, "grammar.g2d")
uri = "file://" + path
broken = """node Point { size: float = 1; }
edge Seg directed { lod: int = 0; }
param levels: int = 3 in 1..8;
axiom { a: Point at (0, 0); b: Point at (1, 0); a -[Seg]-> b; }
rule Split {
    match { s: Point; e: Point; old: s -[Seg]-> e where old.lod < levles; }
    let v = e.pos - s.pos;
    produce { s; e; m: Point at s.pos + rotate(v, 0) / 2; s -[Seg { lod = old.lod + 1 }]-> m; m -[Seg]-> e; }
}
"""
fixed = broken.replace("levles", "levels")
with open(path, "w") as f:
    f.write(broken)
expected = subprocess.run([g2d, "check", path], capture_output=True, text=True).stderr.splitlines()[0]

c = Client()
init = c.request("initialize", {"processId": None, "rootUri": "file://" + work, "capabilities": {}})
caps = init["result"]["capabilities"]
check(caps.get("hoverProvider") and caps.get("definitionProvider") and caps.get("documentSymbolProvider")
      and "completionProvider" in caps, "capabilities: %s" % caps)
c.notify("initialized", {})

c.notify("textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "g2d", "version": 1, "text": broken}})
d = c.diagnostics()
check(d["uri"] == uri, "diagnostics for the wrong document: %s" % d["uri"])
check(len(d["diagnostics"]) == 1, "one diagnostic expected: %s" % d["diagnostics"])
if d["diagnostics"]:
    diag = d["diagnostics"][0]
    # `g2d check` says FILE:LINE:COL: error: MESSAGE; LSP counts from 0.
    check(expected.endswith(": error: " + diag["message"]), "message %r vs g2d check %r" % (diag["message"], expected))
    col = broken.splitlines()[5].index("levles")
    check(diag["range"] == {"start": {"line": 5, "character": col}, "end": {"line": 5, "character": col + 6}}
          and diag["severity"] == 1, "range: %s" % diag)
    check(expected.startswith("%s:6:%d: error: " % (path, col + 1)), "g2d check's location: %s" % expected)

c.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": 2},
                                    "contentChanges": [{"text": fixed}]})
d = c.diagnostics()
check(d["diagnostics"] == [], "no diagnostics expected after the fix: %s" % d["diagnostics"])

lines = fixed.splitlines()
def pos(line, text, nth=0):
    col = -1
    for _ in range(nth + 1):
        col = lines[line].index(text, col + 1)
    return {"line": line, "character": col}

doc = {"uri": uri}
h = c.request("textDocument/hover", {"textDocument": doc, "position": pos(5, "lod")})["result"]
check(h and "attribute" in h["contents"]["value"] and "lod: int = 0" in h["contents"]["value"], "hover on old.lod: %s" % h)
h = c.request("textDocument/hover", {"textDocument": doc, "position": pos(5, "old")})["result"]
check(h and "matched edge" in h["contents"]["value"] and "`Seg`" in h["contents"]["value"], "hover on old: %s" % h)
h = c.request("textDocument/hover", {"textDocument": doc, "position": pos(5, "levels")})["result"]
check(h and "parameter" in h["contents"]["value"] and "param levels: int = 3 in 1..8;" in h["contents"]["value"], "hover on levels (its range too): %s" % h)

h = c.request("textDocument/hover", {"textDocument": doc, "position": pos(7, "v,")})["result"]
check(h and "let binding" in h["contents"]["value"] and "`v`: `vec2`" in h["contents"]["value"], "hover on let v (type inferred): %s" % h)
h = c.request("textDocument/hover", {"textDocument": doc, "position": pos(7, "rotate")})["result"]
check(h and "built-in function" in h["contents"]["value"] and "rotate(v: vec2, angle: float" in h["contents"]["value"], "hover on rotate: %s" % h)
h = c.request("textDocument/hover", {"textDocument": doc, "position": {"line": 7, "character": 0}})["result"]
check(h is None, "hover on white space: %s" % h)
defn = c.request("textDocument/definition", {"textDocument": doc, "position": pos(7, "Point")})["result"]
check(defn and defn["uri"] == uri and defn["range"]["start"] == {"line": 0, "character": 5}, "definition of Point: %s" % defn)
defn = c.request("textDocument/definition", {"textDocument": doc, "position": pos(7, "v,")})["result"]
check(defn and defn["range"]["start"] == {"line": 6, "character": 8}, "definition of let v: %s" % defn)
defn = c.request("textDocument/definition", {"textDocument": doc, "position": pos(7, "old")})["result"]
check(defn and defn["range"]["start"] == {"line": 5, "character": 32}, "definition of old: %s" % defn)

syms = c.request("textDocument/documentSymbol", {"textDocument": doc})["result"]
names = [s["name"] for s in syms]
check(names == ["Point", "Seg", "levels", "Split"], "document symbols: %s" % names)
split = [s for s in syms if s["name"] == "Split"]
check(split and {ch["name"] for ch in split[0]["children"]} >= {"s", "e", "old", "v", "m"}, "children of Split: %s" % split)

items = c.request("textDocument/completion", {"textDocument": doc, "position": pos(5, "lod")})["result"]
labels = {i["label"] for i in items}
# An edge: its attributes and the facts edges have (no position; its degree, its ends' bounds).
check(labels == {"lod", "age", "generation", "id", "faces", "length", "direction", "midpoint", "degree", "lo", "hi"}, "completion after old.: %s" % labels)
# Each one offered is accepted by `g2d check` where it was offered.
for label in sorted(labels):
    with open(os.path.join(work, "offered.g2d"), "w") as f:
        f.write(fixed.replace("old.lod < levels", "old.%s == old.%s and old.lod < levels" % (label, label)))
    r = subprocess.run([g2d, "check", os.path.join(work, "offered.g2d")], capture_output=True, text=True)
    check(r.returncode == 0, "completion offered old.%s, which g2d check rejects: %s" % (label, r.stderr))
items = c.request("textDocument/completion", {"textDocument": doc, "position": pos(6, "pos")})["result"]
labels = {i["label"] for i in items}
check(labels == {"size", "pos", "age", "generation", "id", "degree", "in_degree", "out_degree", "faces"}, "completion after e.: %s" % labels)
items = c.request("textDocument/completion", {"textDocument": doc, "position": {"line": 7, "character": 14}})["result"]
labels = {i["label"] for i in items}
check({"Point", "Seg", "levels", "s", "old", "v", "perp_left", "rotate", "produce", "where"} <= labels,
      "completion in a daughter: missing %s" % ({"Point", "Seg", "levels", "s", "old", "v", "perp_left", "rotate", "produce", "where"} - labels))
# `canvas` is a declaration the lexer does not reserve: offered all the same.
check(any(i["label"] == "canvas" and i["detail"] == "keyword" for i in items), "completion offers `canvas`")

# A face of any corner count (`f: Room;`, written like a node): hover and completion know it is a face.
face_path = os.path.join(work, "faces.g2d")
face_uri = "file://" + face_path
face_text = """node P;
face Room { level: int = 0; }
axiom { a: P at (0, 0); b: P at (1, 0); c: P at (0, 1); Room(a, b, c); }
rule R {
    match { f: Room where f.level < 2; }
    produce { f { level = f.level + 1 }; }
}
"""
with open(face_path, "w") as f:
    f.write(face_text)
c.notify("textDocument/didOpen", {"textDocument": {"uri": face_uri, "languageId": "g2d", "version": 1, "text": face_text}})
d = c.diagnostics()
check(d["diagnostics"] == [], "the face grammar has no diagnostics: %s" % d["diagnostics"])
face_doc = {"uri": face_uri}
face_line = face_text.splitlines()[4]
h = c.request("textDocument/hover", {"textDocument": face_doc, "position": {"line": 4, "character": face_line.index("f:")}})["result"]
check(h and "face" in h["contents"]["value"] and "`Room`" in h["contents"]["value"], "hover on a matched face: %s" % h)
items = c.request("textDocument/completion", {"textDocument": face_doc,
                                               "position": {"line": 4, "character": face_line.index("level")}})["result"]
labels = {i["label"] for i in items}
check(labels == {"level", "age", "generation", "id", "corners", "area", "signed_area", "perimeter", "centroid", "neighbours", "touching", "lo", "hi"},
      "completion after f.: %s" % labels)

# Edits of ranges (LSP positions: UTF-16 units; past a line's end is its end), applied in order.
c.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": 3}, "contentChanges": [
    {"range": {"start": {"line": 5, "character": col}, "end": {"line": 5, "character": col + 6}}, "text": "levles"}]})
d = c.diagnostics()
check(len(d["diagnostics"]) == 1 and d["diagnostics"][0]["range"]["start"] == {"line": 5, "character": col},
      "a ranged edit that breaks the grammar: %s" % d["diagnostics"])
c.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": 4}, "contentChanges": [
    {"range": {"start": {"line": 5, "character": col + 3}, "end": {"line": 5, "character": col + 5}}, "text": "el"},
    {"range": {"start": {"line": 99, "character": 0}, "end": {"line": 99, "character": 7}}, "text": "// end\n"}]})
d = c.diagnostics()
check(d["diagnostics"] == [], "ranged edits that fix it, one past the last line: %s" % d["diagnostics"])
syms = c.request("textDocument/documentSymbol", {"textDocument": doc})["result"]
check([s["name"] for s in syms] == ["Point", "Seg", "levels", "Split"], "symbols after ranged edits: %s" % syms)

# Malformed requests are answered with errors, never the end of the server.
bad = c.request("textDocument/hover", {"textDocument": doc, "position": {"line": -1, "character": 0}})
check(bad.get("error", {}).get("code") == -32602 and "line" in bad["error"]["message"], "a negative line: %s" % bad)
bad = c.request("textDocument/hover", {"textDocument": doc, "position": {"line": 4294967295, "character": 0}})
check(bad.get("error", {}).get("code") == -32602, "a line past 2^31: %s" % bad)
h = c.request("textDocument/hover", {"textDocument": doc, "position": {"line": 4000, "character": 9}})
check(h.get("result", "missing") is None, "a line past the end: %s" % h)
c.next_id += 1
c.send({"jsonrpc": "2.0", "id": c.next_id, "method": 42})
bad = c.read()
check(bad.get("id") == c.next_id and bad.get("error", {}).get("code") == -32600, "a method that is no string: %s" % bad)
bad = c.request("textDocument/didChange", {"textDocument": {"uri": uri}, "contentChanges": [
    {"range": {"start": {"line": 5, "character": 4}, "end": {"line": 2, "character": 0}}, "text": ""}]})
check(bad.get("error", {}).get("code") == -32602, "a range that ends before it starts: %s" % bad)

unknown = c.request("textDocument/formatting", {"textDocument": doc, "options": {}})
check(unknown.get("error", {}).get("code") == -32601, "unknown request: %s" % unknown)

check(c.request("shutdown", None).get("result", "missing") is None, "shutdown")
c.notify("exit", None)
check(c.proc.wait(timeout=10) == 0, "exit status after shutdown")

finish()
