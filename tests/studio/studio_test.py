#!/usr/bin/env python3
"""`g2d studio`: the server's API and its security rules, over HTTP.

Starts `g2d studio FILE --port 0` on a copy of an example, reads the URL from
the first line of its output, then checks: the page and its script; GET and
PUT /api/file (a stale version is refused and says so; only the edited file
is ever written, atomically, no temporary file left); POST /api/check (the
diagnostics of `g2d check --diagnostics-format json`); POST /api/run (the
SVG of `g2d run`, a 3D model, a broken grammar, a run error, a time budget,
a long run cancelled by a newer one); GET /api/imports; Server-Sent Events
when the file changes on disk; the Host and Origin checks, the JSON content
type, the body size limit, path traversal; and a clean exit on SIGINT and
SIGTERM.
Usage: studio_test.py G2D SOURCE_DIR
"""
import http.client
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
import studio_client  # noqa: E402
from checks import check, finish  # noqa: E402

G2D, SRC = (os.path.abspath(p) for p in sys.argv[1:3])


def start(args, cwd):
    return studio_client.start(G2D, args, cwd)


def request(port, method, path, body=None, headers=None, host=None):
    """(status, parsed JSON or text) of one request; `host` replaces the Host header."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    h = {"Host": host or f"127.0.0.1:{port}"}
    if body is not None and not isinstance(body, (bytes, str)):
        body = json.dumps(body)
        h["Content-Type"] = "application/json"
    h.update(headers or {})
    conn.putrequest(method, path, skip_host=True, skip_accept_encoding=True)
    for k, v in h.items():
        if v is not None:
            conn.putheader(k, v)
    data = body.encode() if isinstance(body, str) else body
    if data is not None:
        conn.putheader("Content-Length", str(len(data)))
    conn.endheaders(data)
    res = conn.getresponse()
    data = res.read()
    conn.close()
    try:
        text = data.decode()
    except UnicodeDecodeError:   # a PNG or a .glb
        return res.status, data
    try:
        return res.status, json.loads(text)
    except ValueError:
        return res.status, text


def raw(port, data, read_all=True):
    """The status line and body of a request sent byte for byte (no client normalises the path)."""
    with socket.create_connection(("127.0.0.1", port), timeout=30) as s:
        s.sendall(data)
        chunks = []
        while True:
            try:
                c = s.recv(65536)
            except (ConnectionResetError, socket.timeout):
                break
            if not c:
                break
            chunks.append(c)
            if not read_all:
                break
    return b"".join(chunks).decode(errors="replace")


def stopped_by(proc, sig):
    """The exit code after `sig` (None if it did not exit within 10 s)."""
    proc.send_signal(sig)
    try:
        return proc.wait(10)
    except subprocess.TimeoutExpired:
        return None


def superseded(port, slow_text):
    """Starts a long run, sends a short one after 0.5 s: (the long run's answer, the short one's status, seconds)."""
    slow = {}
    t = threading.Thread(target=lambda: slow.update(r=request(port, "POST", "/api/run", {"text": slow_text, "steps": 10 ** 12, "timeout": 30})))
    began = time.monotonic()
    t.start()
    time.sleep(0.5)
    status, _ = request(port, "POST", "/api/run", {"text": original})
    t.join(30)
    return slow.get("r", (0, {})), status, time.monotonic() - began


def snapshot(folder):
    return {n: open(os.path.join(folder, n), "rb").read() for n in sorted(os.listdir(folder)) if os.path.isfile(os.path.join(folder, n))}


def g2d_check_json(folder, name):
    out = subprocess.run([G2D, "check", "--diagnostics-format", "json", name], cwd=folder, capture_output=True, text=True)
    return json.loads(out.stdout)


work = tempfile.mkdtemp(prefix="g2d-studio-")
NAME = "sierpinski.g2d"
shutil.copy(os.path.join(SRC, "examples", NAME), work)
with open(os.path.join(work, "secret.txt"), "w") as f:
    f.write("not for the browser\n")
original = open(os.path.join(work, NAME)).read()
SPIN = ("node Point { v: float = 0; }\naxiom { a: Point at (0, 0); }\n"
        "rule Spin { match { p: Point; } produce { p { v = p.v + 1 }; } }\n")
RUN_ERROR = ("param d: int = 0;\nnode Point { v: float = 0; }\naxiom { a: Point at (0, 0); }\nlimit 1;\n"
             "rule R { match { p: Point; } produce { p { v = 10 / d }; } }\n")
# A step that never finishes: 2^59 function calls from step 4 on (tests/cli/run_command_test.sh).
EXPO = ("node P { n: int = 0; }\nfn f0(x: int) -> int = x;\n"
        + "".join(f"fn f{i}(x: int) -> int = f{i - 1}(x) + f{i - 1}(x) - x;\n" for i in range(1, 60))
        + "axiom { a: P at (0, 0); }\nlimit 20;\n"
        + "rule R { match { p: P; } produce { p at (p.n > 2 ? f59(1) : 0, 0) { n = p.n + 1 }; } }\n")
IMAGES = ('node A { style { tag = "image"; href = "pics/dot.png"; width = 1; height = 1; } }\n'
          'node B { style { tag = "image"; href = "secret.txt"; width = 1; height = 1; } }\n'
          'node D { style { tag = "image"; href = "data:image/png;base64,AAAA"; width = 1; height = 1; } }\n'
          "axiom { a: A at (0, 0); b: B at (1, 0); a2: A at (2, 0); d: D at (3, 0); }\n")
BROKEN = original.replace("limit generations + 1;", "limit generations +;")
assert BROKEN != original

proc, port = start([NAME, "--port", "0"], work)
own = f"http://127.0.0.1:{port}"
try:
    # The page and its script, from the binary.
    status, page = request(port, "GET", "/")
    check(status == 200 and '<script src="/studio.js">' in page and 'id="editor"' in page, f"GET /: {status}")
    # The page's policy, whole: its own script and connections only, and framed only by
    # itself or VS Code's studio panel (the webview's frames and the workbench window).
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    conn.request("GET", "/")
    res = conn.getresponse()
    res.read()
    check(res.getheader("Content-Security-Policy") ==
          "default-src 'none'; script-src 'self'; connect-src 'self'; style-src 'unsafe-inline'; img-src 'self' data: blob:; "
          "base-uri 'none'; form-action 'none'; frame-ancestors 'self' vscode-webview: vscode-file:",
          f"the page's Content-Security-Policy: {res.getheader('Content-Security-Policy')!r}")
    conn.close()
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    conn.request("GET", "/api/file")
    res = conn.getresponse()
    res.read()
    check(res.getheader("Cross-Origin-Resource-Policy") == "same-origin" and res.getheader("X-Content-Type-Options") == "nosniff",
          f"headers against embedding by other sites: {res.getheaders()}")
    conn.close()
    status, script = request(port, "GET", "/studio.js")
    check(status == 200 and "/api/run" in script, f"GET /studio.js: {status}")

    # The file, with its version.
    status, file = request(port, "GET", "/api/file")
    check(status == 200 and file["text"] == original and file["path"] == NAME and file["exists"], f"GET /api/file: {status} {file}")
    version = file["version"]

    # check: the diagnostics of `g2d check`, as data.
    status, valid = request(port, "POST", "/api/check", {"text": original})
    check(status == 200 and valid["status"] == "ok" and valid["diagnostics"] == g2d_check_json(work, NAME),
          f"check of the example: {valid}")
    other = tempfile.mkdtemp(prefix="g2d-studio-broken-")
    with open(os.path.join(other, NAME), "w") as f:
        f.write(BROKEN)
    status, broken = request(port, "POST", "/api/check", {"text": BROKEN})
    expected = g2d_check_json(other, NAME)
    check(status == 200 and broken["status"] == "invalid" and broken["diagnostics"] == expected and expected
          and expected[0]["line"] > 0 and expected[0]["column"] > 0, f"check of a broken grammar: {broken} vs {expected}")

    # run: the SVG `g2d run --svg-compact` writes (the same picture in fewer elements), with
    # steps, counts and time. Exports (below) are the plain SVG.
    status, run = request(port, "POST", "/api/run", {"text": original, "seed": 3, "params": {"generations": 3}})
    subprocess.run([G2D, "run", NAME, "--seed", "3", "-D", "generations=3", "-o", os.path.join(other, "cli.svg")],
                   cwd=work, check=True)
    subprocess.run([G2D, "run", NAME, "--seed", "3", "-D", "generations=3", "--svg-compact", "-o", os.path.join(other, "compact.svg")],
                   cwd=work, check=True)
    cli_svg = open(os.path.join(other, "cli.svg")).read()
    compact_svg = open(os.path.join(other, "compact.svg")).read()
    check(compact_svg != cli_svg, "the compact SVG differs from the plain one")
    check(status == 200 and run["status"] == "ok" and run["space"] == "2d" and run["svg"] == compact_svg, f"run: {status}")
    check(run.get("steps") == 3 and run["elements"]["nodes"] == (3 ** 4 + 3) // 2 and run["elements"]["edges"] == 3 ** 4
          and run["ms"] >= 0 and run["stopped"] == "step_limit" or run.get("stopped") == "terminal",
          f"run counts: {run.get('steps')} {run.get('elements')} {run.get('stopped')}")
    status, bad_param = request(port, "POST", "/api/run", {"text": original, "params": {"generations": "many"}})
    check(status == 422 and bad_param["message"] == "parameter `generations`: expected an int, got `many`",
          f"a bad parameter: {status} {bad_param}")

    # No answer is compressed, though the browser accepts it: on loopback it only costs time
    # (Brotli took 200 ms for this picture, and seconds for the page's script).
    for method, path, body in [("POST", "/api/run", {"text": original}), ("GET", "/studio.js", None),
                               ("POST", "/api/export", {"text": original, "format": "svg"})]:
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
        conn.request(method, path, json.dumps(body) if body else None,
                     {"Accept-Encoding": "gzip, deflate, br", "Content-Type": "application/json"})
        res = conn.getresponse()
        res.read()
        check(res.status == 200 and res.getheader("Content-Encoding") is None, f"{path} is sent as it is: {res.getheader('Content-Encoding')}")
        conn.close()

    # The parameters panel's specs come with every run.
    check(run.get("params") == [{"name": "generations", "type": "int", "type_name": "int", "default": 5}],
          f"run params: {run.get('params')}")
    check(bad_param.get("params") == run.get("params"), f"a failed run still gives the params: {bad_param.get('params')}")

    # Completion: the language server's list at a place in the text (UTF-16 columns, as the browser counts).
    lines = original.split("\n")
    row = next(i for i, l in enumerate(lines) if "ab.gen < generations" in l)
    at = lines[row].index("ab.gen") + 3   # just after `ab.`
    status, done = request(port, "POST", "/api/complete", {"text": original, "line": row + 1, "character": at})
    labels = {i["label"]: i for i in done.get("items", [])} if isinstance(done, dict) else {}
    check(status == 200 and "gen" in labels and labels["gen"]["detail"] == "int (Side)" and "Corner" not in labels,
          f"completion after `ab.`: {status} {sorted(labels)[:12]}")
    status, done = request(port, "POST", "/api/complete", {"text": original, "line": row + 1, "character": 8})
    labels = {i["label"] for i in done.get("items", [])} if isinstance(done, dict) else set()
    check(status == 200 and {"Corner", "Side", "generations", "sin", "rule", "ab"} <= labels,
          f"completion in a rule: {status} {sorted(labels)[:20]}")
    status, _ = request(port, "POST", "/api/complete", {"text": original, "line": -1, "character": 0})
    check(status == 400, f"a bad completion request: {status}")

    # A range in the declaration comes with the spec, for a slider.
    house = open(os.path.join(SRC, "examples", "g3_house.g2d")).read()
    status, ranged = request(port, "POST", "/api/run", {"text": house.replace("int = 3 in 1..16", "int = 3 in 1..16 step 3")})
    check(status == 200 and ranged["params"][:2] == [
        {"name": "windows", "type": "int", "type_name": "int", "default": 3, "min": 1, "max": 16, "step": 3},
        {"name": "storeys", "type": "int", "type_name": "int", "default": 2, "min": 1, "max": 7}], f"ranged params: {ranged.get('params')}")

    # A 3D grammar: the --view page's model, and no SVG (the page draws the model).
    box = open(os.path.join(SRC, "examples", "g3_box.g2d")).read()
    status, run3 = request(port, "POST", "/api/run", {"text": box})
    check(status == 200 and run3["space"] == "3d" and run3["model"]["nodes"] and "svg" not in run3,
          f"3D run: {status} {str(run3)[:200]}")

    # Exports: the bytes `g2d run` writes for the same grammar, seed and parameters.
    def cli_outputs(text, args, files):
        folder = tempfile.mkdtemp(dir=other)
        with open(os.path.join(folder, NAME), "w") as f:
            f.write(text)
        subprocess.run([G2D, "run", NAME, *args], cwd=folder, check=True, capture_output=True)
        return {k: open(os.path.join(folder, v), "rb").read() for k, v in files.items()}
    flat = cli_outputs(original, ["--seed", "3", "-D", "generations=3", "-o", "s.png", "--json", "s.json"],
                       {"png": "s.png", "json": "s.json"})
    solid = cli_outputs(box, ["--obj", "sierpinski.obj", "--gltf", "s.glb", "--no-svg"],
                        {"obj": "sierpinski.obj", "mtl": "sierpinski.mtl", "glb": "s.glb"})
    for fmt, text, args, want in [("svg", original, {"seed": 3, "params": {"generations": 3}}, cli_svg.encode()),
                                  ("png", original, {"seed": 3, "params": {"generations": 3}}, flat["png"]),
                                  ("json", original, {"seed": 3, "params": {"generations": 3}}, flat["json"]),
                                  ("obj", box, {}, solid["obj"]), ("mtl", box, {}, solid["mtl"]), ("glb", box, {}, solid["glb"])]:
        status, got = request(port, "POST", "/api/export", {"text": text, "format": fmt, **args})
        if fmt == "json":   # parsed by request()
            check(status == 200 and got == json.loads(want), f"export json: {status}")
            continue
        got = got if isinstance(got, bytes) else got.encode()
        check(status == 200 and got == want, f"export {fmt}: {status}, {len(got)} bytes against {len(want)}")
    status, nope = request(port, "POST", "/api/export", {"text": original, "format": "pdf"})
    check(status == 400 and "format" in nope["message"], f"an unknown export format: {status} {nope}")
    status, nope = request(port, "POST", "/api/export", {"text": BROKEN, "format": "svg"})
    check(status == 422 and nope["status"] == "invalid", f"exporting a broken grammar: {status}")

    # The trace for the player: what `g2d run --trace-json` writes.
    traced = cli_outputs(original, ["--seed", "2", "--trace-json", "t.json", "--no-svg"], {"trace": "t.json"})
    status, with_trace = request(port, "POST", "/api/run", {"text": original, "seed": 2, "trace": True})
    check(status == 200 and with_trace.get("trace") == json.loads(traced["trace"]), f"the run's trace: {status}")
    check("trace" not in run, "a run without \"trace\": true has none")

    # The seeds sheet: one small PNG per seed, in order.
    status, sheet = request(port, "POST", "/api/seeds", {"text": original, "first": 5, "count": 4, "width": 64})
    cells = sheet.get("sheet", []) if isinstance(sheet, dict) else []
    check(status == 200 and [c["seed"] for c in cells] == [5, 6, 7, 8]
          and all(c["png"].startswith("data:image/png;base64,iVBORw0KGgo") and c["steps"] == 5 for c in cells),
          f"seeds sheet: {status} {str(sheet)[:200]}")
    for bad_sheet in [{"first": 1, "count": 0, "width": 64}, {"first": 1, "count": 65, "width": 64},
                      {"first": -1, "count": 2, "width": 64}, {"first": 1, "count": 2, "width": 5000}]:
        status, _ = request(port, "POST", "/api/seeds", {"text": original, **bad_sheet})
        check(status == 400, f"a bad seeds request {bad_sheet}: {status}")
    status, nope = request(port, "POST", "/api/seeds", {"text": BROKEN, "first": 1, "count": 2, "width": 64})
    check(status == 422 and nope["status"] == "invalid", f"the seeds of a broken grammar: {status}")

    # A broken grammar and a run error answer in JSON; the server keeps running.
    status, invalid = request(port, "POST", "/api/run", {"text": BROKEN})
    check(status == 422 and invalid["status"] == "invalid" and invalid["diagnostics"] == expected, f"broken run: {status} {invalid}")
    status, failed = request(port, "POST", "/api/run", {"text": RUN_ERROR})
    check(status == 422 and failed["status"] == "error" and "division by zero" in failed["message"]
          and failed["location"]["line"] == 5 and failed["location"]["column"] == 48, f"run error: {status} {failed}")
    status, budget = request(port, "POST", "/api/run", {"text": SPIN, "steps": 10 ** 12, "timeout": 0.3})
    check(status == 422 and budget.get("stopped") == "time_limit", f"time budget: {status} {budget}")
    status, _ = request(port, "POST", "/api/run", {"text": original, "steps": 2 ** 64 - 1})
    check(status == 400, f"a step limit past a long long: {status}")
    status, bad = request(port, "POST", "/api/run", "{not json", headers={"Content-Type": "application/json"})
    check(status == 400, f"a body that is not JSON: {status}")

    # A newer run cancels the one in flight.
    slow, status, seconds = superseded(port, SPIN)
    check(slow[0] == 409 and slow[1]["status"] == "cancelled", f"the long run: {slow}")
    check(status == 200 and seconds < 5, f"the newer run: {status} {seconds:.1f} s")

    # ... even inside a step that never finishes (the run's deadline flag, raised early).
    slow, status, seconds = superseded(port, EXPO)
    check(slow[0] == 409 and status == 200 and seconds < 5, f"a step cancelled inside: {slow} {status} {seconds:.1f} s")

    # Imports: only the files the grammar imports (by name, never a path asked for).
    status, imports = request(port, "GET", "/api/imports")
    check(status == 200 and imports["files"] == [], f"imports of a grammar without: {imports}")

    # Images the drawing links: each image file gets an address the page can load, and only those
    # are served; a file that is not an image, or a URL, keeps its href.
    os.makedirs(os.path.join(work, "pics"))
    shutil.copy(os.path.join(SRC, "examples", "assets", "brush.png"), os.path.join(work, "pics", "dot.png"))
    status, pictured = request(port, "POST", "/api/run", {"text": IMAGES})
    hrefs = re.findall(r'href="([^"]*)"', pictured.get("svg", ""))
    check(status == 200 and hrefs == ["/api/image/0", "secret.txt", "/api/image/0", "data:image/png;base64,AAAA"],
          f"the images' hrefs: {status} {hrefs}")
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    conn.request("GET", "/api/image/0")
    res = conn.getresponse()
    check(res.status == 200 and res.getheader("Content-Type") == "image/png"
          and res.read() == open(os.path.join(work, "pics", "dot.png"), "rb").read(), f"GET /api/image/0: {res.status}")
    conn.close()
    for path in ["/api/image/1", "/api/image/-1", "/api/image/99999999999", "/api/image/0/../../secret.txt", "/api/image/x"]:
        line = raw(port, f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n".encode()).split("\r\n")[0]
        check(" 404 " in line, f"GET {path}: {line}")

    # Security: the Host (DNS rebinding).
    for host in ["evil.example", f"evil.example:{port}", f"127.0.0.1:{port + 1}", "127.0.0.1", f"localhost.evil:{port}"]:
        status, _ = request(port, "GET", "/api/file", host=host)
        check(status == 403, f"Host {host}: {status}")
        status, _ = request(port, "GET", "/", host=host)
        check(status == 403, f"Host {host} for the page: {status}")
    status, _ = request(port, "GET", "/api/file", host=f"localhost:{port}")
    check(status == 200, f"Host localhost:{port}: {status}")
    check(" 403 " in raw(port, b"GET /api/file HTTP/1.0\r\n\r\n").split("\r\n")[0], "no Host at all")

    # Origin: API calls from another page are refused; the studio's own pass.
    for origin in ["http://evil.example", f"http://127.0.0.1:{port + 1}", "null", f"https://127.0.0.1:{port}"]:
        status, _ = request(port, "POST", "/api/check", {"text": original}, headers={"Origin": origin})
        check(status == 403, f"Origin {origin} on a write: {status}")
        status, _ = request(port, "GET", "/api/file", headers={"Origin": origin})
        check(status == 403, f"Origin {origin} on a read: {status}")
    for origin in [own, f"http://localhost:{port}"]:
        status, _ = request(port, "POST", "/api/check", {"text": original}, headers={"Origin": origin})
        check(status == 200, f"own Origin {origin}: {status}")

    # Writes need a JSON content type (a form or a simple request cannot send it).
    for ctype in [None, "text/plain", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x"]:
        for method, path in [("POST", "/api/check"), ("POST", "/api/run"), ("PUT", "/api/file")]:
            status, _ = request(port, method, path, json.dumps({"text": "x", "version": version}), headers={"Content-Type": ctype})
            check(status == 403, f"{method} {path} with Content-Type {ctype}: {status}")
    status, _ = request(port, "POST", "/api/check", {"text": original}, headers={"Content-Type": "application/json; charset=utf-8"})
    check(status == 200, f"JSON with a charset: {status}")

    # An oversized body: 413, and the server keeps answering.
    big = json.dumps({"text": "x" * (17 << 20)})
    head = raw(port, (f"POST /api/check HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Type: application/json\r\n"
                      f"Content-Length: {len(big)}\r\n\r\n").encode() + big.encode())
    check(head.startswith("HTTP/1.1 413"), f"oversized body: {head[:80]!r}")
    status, _ = request(port, "GET", "/api/file")
    check(status == 200, "the server answers after an oversized body")

    # Path traversal: requests name no path on disk, so none reads one.
    for path in ["/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/%2E%2E%2F%2E%2E%2Fetc%2Fpasswd", "/..%2f..%2fetc%2fpasswd",
                 "/api/file/../../etc/passwd", "/api/file?path=/etc/passwd", "/studio.js/../../secret.txt", "/secret.txt",
                 f"/{NAME}", "/api/imports/../../../etc/passwd", "/%2e%2e/secret.txt", "//etc/passwd", "/api/../secret.txt"]:
        reply = raw(port, f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n".encode())
        line = reply.split("\r\n")[0]
        leaked = "root:" in reply or "not for the browser" in reply or "Sierpinski" in reply and path != "/api/file?path=/etc/passwd"
        check(not leaked, f"GET {path} leaked a file: {line}")
        check(" 404 " in line or " 400 " in line or path == "/api/file?path=/etc/passwd", f"GET {path}: {line}")
    status, ignored = request(port, "GET", "/api/file?path=/etc/passwd")
    check(status == 200 and ignored["text"] == original, "a path in the query is ignored")

    # Saving: only the edited file, atomically, and only at the version the client has.
    before = snapshot(work)
    status, saved = request(port, "PUT", "/api/file", {"text": original + "// edited\n", "version": version})
    check(status == 200 and saved["status"] == "saved", f"save: {status} {saved}")
    after = snapshot(work)
    check(after[NAME] == (original + "// edited\n").encode(), "the save wrote the text")
    check({k: v for k, v in after.items() if k != NAME} == {k: v for k, v in before.items() if k != NAME},
          f"the save touched other files: {sorted(after)}")
    status, stale = request(port, "PUT", "/api/file", {"text": "lost", "version": version})
    check(status == 409 and "changed on disk" in stale["message"] and stale["version"] == saved["version"], f"stale save: {status} {stale}")
    check(open(os.path.join(work, NAME)).read() == original + "// edited\n", "a stale save writes nothing")
    status, _ = request(port, "PUT", "/api/file", {"text": "saved again\n", "version": saved["version"], "path": "secret.txt"})
    check(status == 200 and open(os.path.join(work, "secret.txt")).read() == "not for the browser\n"
          and open(os.path.join(work, NAME)).read() == "saved again\n", "a path in the body is ignored")
    version = request(port, "GET", "/api/file")[1]["version"]

    # Events: a change on disk (another editor) is pushed to the page.
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    conn.request("GET", "/api/events")
    events = conn.getresponse()
    check(events.status == 200 and events.getheader("Content-Type", "").startswith("text/event-stream"), "events: the stream")
    hello = events.readline().decode() + events.readline().decode()
    check(hello.startswith("event: hello") and version in hello, f"events: hello {hello!r}")
    events.readline()
    time.sleep(0.05)
    with open(os.path.join(work, NAME), "w") as f:
        f.write(original + "// changed on disk\n")
    now = request(port, "GET", "/api/file")[1]["version"]
    changed = ""
    for _ in range(3):   # the watch may first report the save above, if it had not seen it yet
        changed = events.readline().decode() + events.readline().decode()
        events.readline()
        if now in changed:
            break
    check(changed.startswith("event: file") and now in changed and now != version, f"events: the change {changed!r}")
    conn.close()
    status, stale = request(port, "PUT", "/api/file", {"text": "lost", "version": version})
    check(status == 409 and "changed on disk" in stale["message"], f"save after a change on disk: {status} {stale}")
    leftovers = [n for n in os.listdir(work) if n not in (NAME, "secret.txt", "pics")]
    check(not leftovers, f"files left beside the grammar: {leftovers}")

    # A clean exit on SIGINT, even with a run in flight.
    t = threading.Thread(target=lambda: request(port, "POST", "/api/run", {"text": SPIN, "steps": 10 ** 12, "timeout": 30}))
    t.daemon = True
    t.start()
    time.sleep(0.3)
    code = stopped_by(proc, signal.SIGINT)
    check(code == 0, f"exit code after SIGINT: {code}")
finally:
    if proc.poll() is None:
        proc.kill()

# No file: nothing to save; SIGTERM ends it cleanly too.
proc, port = start(["--port", "0"], work)
try:
    status, file = request(port, "GET", "/api/file")
    check(status == 200 and not file["exists"] and file["version"] == "none", f"no file: {file}")
    status, refused = request(port, "PUT", "/api/file", {"text": "x", "version": "none"})
    check(status == 403 and "without a file" in refused["message"], f"no file, save: {status} {refused}")
    code = stopped_by(proc, signal.SIGTERM)
    check(code == 0, f"exit code after SIGTERM: {code}")
finally:
    if proc.poll() is None:
        proc.kill()

# A signal as soon as the URL is out (before the server has begun listening) still ends it.
for _ in range(5):
    proc, port = start([NAME], work)
    code = stopped_by(proc, signal.SIGINT)
    check(code == 0, f"exit code after an early SIGINT: {code}")
    if code is None:
        proc.kill()
        break

# A port in use: an error, exit 1.
busy = socket.socket()
busy.bind(("127.0.0.1", 0))
busy.listen()
out = subprocess.run([G2D, "studio", NAME, "--port", str(busy.getsockname()[1])], cwd=work, capture_output=True, text=True, timeout=10)
check(out.returncode == 1 and "cannot listen" in out.stderr and out.stdout == "", f"port in use: {out.returncode} {out.stderr}")
busy.close()

# A folder is not a file to edit.
out = subprocess.run([G2D, "studio", ".", "--port", "0"], cwd=work, capture_output=True, text=True, timeout=10)
check(out.returncode == 1 and "is not a file" in out.stderr and out.stdout == "", f"a folder: {out.returncode} {out.stderr}")

shutil.rmtree(work)
finish()
