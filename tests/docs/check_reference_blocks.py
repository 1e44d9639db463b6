#!/usr/bin/env python3
"""Checks the code blocks of the reference documents against `g2d check`.

Usage: check_reference_blocks.py G2D REPO_ROOT [DOC.md ...]
       (default documents: docs/language.md docs/compiling.md)

Every fenced block whose info string is `g2d`, and every fenced block with no
info string, must be preceded, on the line right before its opening fence,
by a marker (an HTML comment, invisible on GitHub):

  <!-- check: complete [id=NAME] [warnings-ok] -->
      The block is a whole program: `g2d check` exits 0 and prints nothing
      (with `warnings-ok`: exits 0, warnings allowed).

  <!-- check: fragment with=NAME[,NAME...] [id=NAME] [warnings-ok] -->
      The block is part of a program: it is appended to the blocks named by
      `with` (blocks of the same document marked `id=NAME`, themselves with
      their own `with` blocks in front), and the whole must pass as above.

  <!-- check: error "FILE:LINE:COL: error: MESSAGE" [output=next] [json=next] -->
  <!-- check: warning "FILE:LINE:COL: warning: MESSAGE" [output=next] -->
      The block is a whole program written to FILE; `g2d check FILE` exits 1
      (error) or 0 (warning) and the first line it prints is exactly the
      quoted text (as tests/bad/*.expected). With `output=next` the next
      fenced block of the document is exactly what `g2d check FILE` prints on
      standard error; with `json=next` it is exactly what
      `g2d check --diagnostics-format json FILE` prints on standard output.
      Inside the quotes, \\" is a quote and \\\\ a backslash.

  <!-- check: skip reason="WHY" -->
      Only for blocks without an info string (syntax templates, the EBNF
      summary, keyword lists): not g2d, not checked. A `g2d` block cannot be
      skipped.

Blocks with another info string (sh, text, json, cmake, cpp) need no marker.
A marker anywhere else, a malformed marker or an unmarked block is a failure.
Prints one line per block and `N passed, N failed`; exits 1 on any failure
or when no block was found, 2 on bad usage.
"""

import json
import os
import re
import subprocess
import sys
import tempfile

MARKER_RE = re.compile(r"^<!--\s*check:(.*?)-->\s*$")
MARKER_START_RE = re.compile(r"^\s*<!--\s*check:")
FENCE_RE = re.compile(r"^(\s*)(`{3,}|~{3,})(.*)$")
LOCATION_RE = re.compile(r"^(?P<file>[^\s:]+\.g2d):(?P<line>\d+):(?P<col>\d+): (?P<sev>error|warning): ")
KINDS = ("complete", "fragment", "error", "warning", "skip")
OPTIONS = {
    "complete": {"id", "warnings-ok"},
    "fragment": {"with", "id", "warnings-ok"},
    "error": {"output", "json"},
    "warning": {"output"},
    "skip": {"reason"},
}
FLAGS = {"warnings-ok"}
TIMEOUT = 60


class MarkerError(Exception):
    pass


class Block:
    def __init__(self, doc, line, info, text, marker):
        self.doc = doc          # the document's path relative to the repository root
        self.line = line        # 1-based line of the opening fence
        self.info = info        # the info string ("" when none)
        self.text = text        # the contents, ending in a newline (or empty)
        self.marker = marker    # parsed marker (dict) or None
        self.next_block = None  # the next fenced block of the document

    @property
    def where(self):
        return f"{self.doc}:{self.line}"


def tokenize_marker(body):
    """Splits a marker's body into words, `key=value` pairs and quoted strings."""
    tokens = []
    i = 0
    while i < len(body):
        c = body[i]
        if c.isspace():
            i += 1
            continue
        key = None
        m = re.match(r"([A-Za-z][A-Za-z0-9_-]*)=", body[i:])
        if m:
            key = m.group(1)
            i += m.end()
            if i >= len(body) or body[i].isspace():
                raise MarkerError(f"`{key}=` has no value")
            c = body[i]
        if c == '"':
            i += 1
            value = []
            while True:
                if i >= len(body):
                    raise MarkerError("unterminated quoted string")
                c = body[i]
                if c == "\\" and i + 1 < len(body) and body[i + 1] in '"\\':
                    value.append(body[i + 1])
                    i += 2
                elif c == '"':
                    i += 1
                    break
                else:
                    value.append(c)
                    i += 1
            if i < len(body) and not body[i].isspace():
                raise MarkerError("a quoted string must be followed by a space")
            tokens.append((key, "".join(value), True))
        else:
            j = i
            while j < len(body) and not body[j].isspace():
                if body[j] == '"':
                    raise MarkerError("a quote inside a word")
                j += 1
            tokens.append((key, body[i:j], False))
            i = j
    return tokens


def parse_marker(body):
    tokens = tokenize_marker(body)
    if not tokens or tokens[0][0] is not None or tokens[0][2]:
        raise MarkerError(f"expected one of {', '.join(KINDS)} after `check:`")
    kind = tokens[0][1]
    if kind not in KINDS:
        raise MarkerError(f"unknown kind `{kind}` (expected one of {', '.join(KINDS)})")
    marker = {"kind": kind}
    rest = tokens[1:]
    if kind in ("error", "warning"):
        if not rest or rest[0][0] is not None or not rest[0][2]:
            raise MarkerError(f'`{kind}` needs the expected first diagnostic in quotes: {kind} "FILE:LINE:COL: {kind}: …"')
        message = rest[0][1]
        m = LOCATION_RE.match(message)
        if not m or m.group("sev") != kind:
            raise MarkerError(f"the expected diagnostic must read `FILE.g2d:LINE:COL: {kind}: MESSAGE`, got `{message}`")
        if "/" in m.group("file"):
            raise MarkerError("the file of an expected diagnostic must be a plain file name")
        marker["message"] = message
        marker["file"] = m.group("file")
        rest = rest[1:]
    for key, value, quoted in rest:
        name = key if key is not None else value
        if name not in OPTIONS[kind]:
            raise MarkerError(f"`{name}` is not an option of `{kind}` (options: {', '.join(sorted(OPTIONS[kind])) or 'none'})")
        if name in marker:
            raise MarkerError(f"`{name}` given twice")
        if name in FLAGS:
            if key is not None:
                raise MarkerError(f"`{name}` takes no value")
            marker[name] = True
            continue
        if key is None:
            raise MarkerError(f"`{name}` needs a value (`{name}=…`)")
        if name in ("output", "json") and value != "next":
            raise MarkerError(f"`{name}=` must be `next`")
        if name == "id" and not re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]*", value):
            raise MarkerError(f"bad id `{value}`")
        if name == "with":
            names = value.split(",")
            if not all(re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]*", n) for n in names):
                raise MarkerError(f"bad `with` list `{value}`")
            value = names
        if name == "reason" and not value.strip():
            raise MarkerError("`reason=` is empty")
        marker[name] = value
    if kind == "fragment" and "with" not in marker:
        raise MarkerError("a fragment needs `with=NAME`: the blocks it is checked in")
    if kind == "skip" and "reason" not in marker:
        raise MarkerError('`skip` needs `reason="…"`')
    return marker


def read_blocks(root, doc):
    """Returns (blocks, problems) of one document."""
    path = os.path.join(root, doc)
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    blocks, problems = [], []
    pending = None   # (line number, marker or None, error) of a marker line just read
    i = 0
    while i < len(lines):
        line = lines[i]
        fence = FENCE_RE.match(line)
        if fence:
            indent, ticks, info = fence.groups()
            info = info.strip()
            start = i + 1
            body = []
            i += 1
            while i < len(lines):
                close = FENCE_RE.match(lines[i])
                if close and close.group(2)[0] == ticks[0] and len(close.group(2)) >= len(ticks) and not close.group(3).strip():
                    break
                body.append(lines[i][len(indent):] if lines[i].startswith(indent) else lines[i].lstrip())
                i += 1
            else:
                problems.append(f"{doc}:{start}: unterminated code fence")
            marker = None
            if pending is not None and pending[0] == start - 1:
                if pending[2] is not None:
                    problems.append(f"{doc}:{pending[0]}: malformed marker: {pending[2]}")
                    marker = {"kind": "malformed"}
                else:
                    marker = pending[1]
            elif pending is not None:
                problems.append(f"{doc}:{pending[0]}: a marker must be on the line right before a code fence")
            pending = None
            text = "\n".join(body) + ("\n" if body else "")
            blocks.append(Block(doc, start, info.split()[0] if info else "", text, marker))
            i += 1
            continue
        if MARKER_START_RE.match(line):
            if pending is not None:
                problems.append(f"{doc}:{pending[0]}: a marker must be on the line right before a code fence")
            m = MARKER_RE.match(line.strip())
            if not m:
                pending = (i + 1, None, "expected `<!-- check: … -->` on one line")
            else:
                try:
                    pending = (i + 1, parse_marker(m.group(1)), None)
                except MarkerError as e:
                    pending = (i + 1, None, str(e))
        elif pending is not None and pending[0] == i:   # the line after the marker is no fence
            problems.append(f"{doc}:{pending[0]}: a marker must be on the line right before a code fence")
            pending = None
        i += 1
    if pending is not None:
        problems.append(f"{doc}:{pending[0]}: a marker must be on the line right before a code fence")
    for a, b in zip(blocks, blocks[1:]):
        a.next_block = b
    return blocks, problems


def mapped(output, file_name, parts):
    """Rewrites `FILE:L:C` of a checked file to the documents' lines."""
    def to_doc(m):
        line = int(m.group(1))
        for block, first, count in parts:
            if first <= line < first + count:
                return f"{block.doc}:{block.line + 1 + line - first}:{m.group(2)}"
        return m.group(0)
    return re.sub(re.escape(file_name) + r":(\d+):(\d+)", to_doc, output)


def run_check(g2d, directory, file_name, env, json_format=False):
    args = [g2d, "check"] + (["--diagnostics-format", "json"] if json_format else []) + [file_name]
    try:
        p = subprocess.run(args, cwd=directory, env=env, capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return None, "", f"`g2d check` did not finish in {TIMEOUT} s"
    return p.returncode, p.stdout, p.stderr


def assemble(block, ids, seen=()):
    """The parts (block, first line in the file, line count) a block is checked as."""
    parts = []
    for name in block.marker.get("with", []):
        if name in seen or name == block.marker.get("id"):
            raise MarkerError(f"`with={name}` makes a cycle")
        if name not in ids:
            raise MarkerError(f"`with={name}`: no block of {block.doc} has `id={name}`")
        parts.extend(assemble(ids[name], ids, seen + (name,)))
    parts.append(block)
    return parts


def check_block(g2d, block, ids, env, workdir):
    """Returns (passed, description)."""
    marker = block.marker
    kind = marker["kind"]
    if block.info not in ("g2d", ""):
        return False, f"a marker on a ```{block.info} block: only g2d blocks and blocks without an info string take one"
    if kind == "skip":
        if block.info == "g2d":
            return False, "a `g2d` block cannot be skipped (mark it complete, fragment or error)"
        return True, f"skip ({marker['reason']})"
    directory = tempfile.mkdtemp(prefix=f"block{block.line}_", dir=workdir)
    if kind in ("complete", "fragment"):
        try:
            blocks = assemble(block, ids)
        except MarkerError as e:
            return False, str(e)
        file_name = "block.g2d"
        parts, source, first = [], "", 1
        for b in blocks:
            count = b.text.count("\n")
            parts.append((b, first, count))
            source += b.text
            first += count
        with open(os.path.join(directory, file_name), "w", encoding="utf-8") as f:
            f.write(source)
        rc, _, err = run_check(g2d, directory, file_name, env)
        shown = mapped(err, file_name, parts).rstrip()
        label = kind if kind == "complete" else f"fragment with {','.join(marker['with'])}"
        if rc != 0:
            return False, f"{label}: `g2d check` exited {rc}, expected 0:\n{shown}"
        if err.strip() and not marker.get("warnings-ok"):
            return False, f"{label}: `g2d check` printed diagnostics (mark the block `warnings-ok` if they are meant):\n{shown}"
        return True, label + (" (warnings allowed)" if marker.get("warnings-ok") else "")
    # error / warning
    file_name = marker["file"]
    with open(os.path.join(directory, file_name), "w", encoding="utf-8") as f:
        f.write(block.text)
    rc, _, err = run_check(g2d, directory, file_name, env)
    want_rc = 1 if kind == "error" else 0
    first_line = err.split("\n", 1)[0]
    if rc != want_rc:
        return False, f"{kind}: `g2d check` exited {rc}, expected {want_rc}:\n{err.rstrip()}"
    if first_line != marker["message"]:
        return False, f"{kind}: first diagnostic differs\n  expected: {marker['message']}\n  actual:   {first_line}\n\nfull output:\n{err.rstrip()}"
    notes = []
    if marker.get("output") == "next":
        shown = block.next_block
        if shown is None:
            return False, f"{kind}: `output=next` but no block follows"
        if shown.text.rstrip("\n") != err.rstrip("\n"):
            return False, (f"{kind}: the block at {shown.where} differs from what `g2d check {file_name}` prints\n"
                           f"--- documented\n{shown.text.rstrip()}\n--- printed\n{err.rstrip()}")
        notes.append(f"output at line {shown.line}")
    if marker.get("json") == "next":
        shown = block.next_block
        if shown is None:
            return False, f"{kind}: `json=next` but no block follows"
        rc_json, out, err_json = run_check(g2d, directory, file_name, env, json_format=True)
        if rc_json != want_rc:
            return False, f"{kind}: `g2d check --diagnostics-format json` exited {rc_json}, expected {want_rc}:\n{err_json.rstrip()}"
        if shown.text.strip() != out.strip():
            return False, (f"{kind}: the block at {shown.where} differs from what "
                           f"`g2d check --diagnostics-format json {file_name}` prints\n"
                           f"--- documented\n{shown.text.rstrip()}\n--- printed\n{out.rstrip()}")
        try:
            json.loads(out)
        except ValueError as e:
            return False, f"{kind}: the JSON output does not parse: {e}"
        notes.append(f"JSON at line {shown.line}")
    return True, f"{kind} {marker['message']}" + (f" ({', '.join(notes)})" if notes else "")


def main(argv):
    if len(argv) < 3:
        print(f"usage: {argv[0]} G2D REPO_ROOT [DOC.md ...]", file=sys.stderr)
        return 2
    g2d = os.path.abspath(argv[1])
    root = os.path.abspath(argv[2])
    docs = argv[3:] or ["docs/language.md", "docs/compiling.md"]
    if not os.access(g2d, os.X_OK):
        print(f"error: `{g2d}` is not an executable", file=sys.stderr)
        return 2
    env = dict(os.environ)
    env["NO_COLOR"] = "1"
    env["G2D_STDLIB"] = os.path.join(root, "stdlib")
    passed = failed = checked = 0
    with tempfile.TemporaryDirectory(prefix="g2d_doc_blocks_") as workdir:
        for doc in docs:
            try:
                blocks, problems = read_blocks(root, doc)
            except OSError as e:
                print(f"FAIL {doc}: {e}")
                failed += 1
                continue
            for problem in problems:
                print(f"FAIL {problem}")
                failed += 1
            ids = {}
            for b in blocks:
                if b.marker and "id" in b.marker:
                    if b.marker["id"] in ids:
                        print(f"FAIL {b.where}: id `{b.marker['id']}` is also used at line {ids[b.marker['id']].line}")
                        failed += 1
                    ids[b.marker["id"]] = b
            for b in blocks:
                if b.marker is None:
                    if b.info == "g2d":
                        print(f"FAIL {b.where}: g2d block without a marker (<!-- check: complete|fragment|error … -->)")
                        failed += 1
                        checked += 1
                    elif b.info == "":
                        print(f"FAIL {b.where}: block without an info string and without a marker "
                              f'(<!-- check: skip reason="…" --> if it is not g2d)')
                        failed += 1
                    continue
                if b.marker["kind"] == "malformed":
                    continue      # counted with the problems above
                if b.info == "g2d":
                    checked += 1
                ok, description = check_block(g2d, b, ids, env, workdir)
                print(f"{'PASS' if ok else 'FAIL'} {b.where}: {description}")
                if ok:
                    passed += 1
                else:
                    failed += 1
    if checked == 0:
        print("FAIL: no g2d block found")
        failed += 1
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
