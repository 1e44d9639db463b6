#!/usr/bin/env python3
"""`g2d studio`'s infer mode: POST /api/infer over HTTP.

An example of the reference set (the author's JSON) and a drawn SVG each
give the labels, primitives and rules `g2d infer` reports, the grammar
`g2d infer -o` writes (byte for byte), which `g2d check` accepts, the
example and each primitive and rule side drawn, and one generated output:
the SVG `g2d run --svg-compact` writes for that grammar and seed (as
/api/run sends it). Broken examples answer 422 with the reader's message
and its line; malformed requests 400; the server keeps running. A long inference is cancelled by a newer run and by a
newer inference.
Usage: studio_infer_test.py G2D SOURCE_DIR
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from checks import check, finish  # noqa: E402
from studio_client import post, start, stop  # noqa: E402

G2D, SRC = (os.path.abspath(p) for p in sys.argv[1:3])


def cli(*args, cwd):
    return subprocess.run([G2D, *args], cwd=cwd, capture_output=True, text=True)


def is_svg(text):
    return isinstance(text, str) and text.startswith("<svg xmlns=\"http://www.w3.org/2000/svg\"") and text.endswith("</svg>")


work = tempfile.mkdtemp(prefix="g2d-studio-infer-")
EXAMPLES = {   # file in the work folder: its source and format
    "T.json": (os.path.join(SRC, "examples/infer/merrell/2D Branches/T.json"), "json"),
    "house.svg": (os.path.join(SRC, "examples/infer/house.svg"), "svg"),
}
for name, (source, _) in EXAMPLES.items():
    shutil.copy(source, os.path.join(work, name))
# The studio's file: /api/run and /api/infer compile their text as this file.
GRAMMAR = "inferred.g2d"

proc, port = start(G2D, [GRAMMAR, "--port", "0"], work)
try:
    for name, (_, fmt) in EXAMPLES.items():
        text = open(os.path.join(work, name)).read()
        status, got = post(port, "/api/infer", {"example": text, "format": fmt, "name": name, "seed": 4})
        check(status == 200 and got.get("status") == "ok", f"{name}: {status} {str(got)[:300]}")
        if status != 200:
            continue
        stats = json.loads(cli("infer", "--stats", name, cwd=work).stdout)
        for key in ("vertices", "edges", "labels", "primitives", "graphs", "pruned", "left_over", "rules", "starters"):
            check(got["counts"][key] == stats[key], f"{name}: counts.{key} {got['counts'][key]} vs g2d infer's {stats[key]}")
        report = cli("infer", name, cwd=work).stdout
        check(got["report"] == report, f"{name}: the report is g2d infer's")

        # The primitives: as the report lists them, each with its star drawn.
        check(len(got["primitives"]) == stats["primitives"] and len(got["labels"]) == stats["labels"], f"{name}: primitives, labels")
        for k, p in enumerate(got["primitives"]):
            check(p["id"] == f"P{k}" and f"  P{k}: {p['boundary']} ({p['count']} in the example)" in report,
                  f"{name}: primitive {k} as the report has it: {p['id']} {p['boundary']}")
            check(is_svg(p["svg"]) and len(re.findall("<line ", p["svg"])) == len(p["halves"]) and p["halves"],
                  f"{name}: primitive {k} drawn with a ray per half-edge")
            check(re.fullmatch("#[0-9a-f]{6}", p["color"]) and f'fill="{p["color"]}"' in got["example_svg"],
                  f"{name}: primitive {k}'s colour marks its vertices in the example")
        check(sum(p["count"] for p in got["primitives"]) == stats["vertices"], f"{name}: every vertex has a primitive")

        # The rules: the report's lines, both sides drawn (a starter's right side is nothing).
        check(len(got["rules"]) == stats["rules"] + stats["starters"], f"{name}: {len(got['rules'])} rules")
        for r in got["rules"]:
            right = " nothing" if r["starter"] else "".join((" | " if k else " ") + s for k, s in enumerate(r["right"]))
            line = f"  {r['index']}: {r['left']} <->{right}" + ("  (restructures, §5.4)" if r["restructures"] else "")
            check(line + "\n" in report, f"{name}: rule {r['index']} as the report has it: {line!r}")
            check(is_svg(r["left_svg"]) and (r["right_svg"] == "" if r["starter"] else is_svg(r["right_svg"])),
                  f"{name}: rule {r['index']}'s sides drawn")

        # The example drawn: an edge per example edge, a dot per vertex.
        ex = got["example_svg"]
        check(is_svg(ex) and ex.count("<circle ") == stats["vertices"] and ex.count('stroke-width="2.5"') == stats["edges"],
              f"{name}: the example drawn: {ex[:200]}")

        # The grammar g2d infer writes, which g2d check accepts; its output as g2d run draws it.
        written = cli("infer", name, "-o", "cli.g2d", cwd=work)
        check(written.returncode == 0 and got["grammar"] == open(os.path.join(work, "cli.g2d")).read(),
              f"{name}: the grammar is g2d infer -o's")
        with open(os.path.join(work, GRAMMAR), "w") as f:
            f.write(got["grammar"])
        checked = cli("check", GRAMMAR, cwd=work)
        check(checked.returncode == 0, f"{name}: g2d check refuses the grammar: {checked.stderr}")
        ran = cli("run", GRAMMAR, "--seed", "4", "--svg-compact", "-o", "cli.svg", cwd=work)
        check(ran.returncode == 0 and got["generated_svg"] == open(os.path.join(work, "cli.svg")).read(),
              f"{name}: generated_svg is g2d run --svg-compact's for seed 4 ({ran.stderr})")
        check(got["generated"]["elements"]["nodes"] > stats["vertices"] and re.search("<(path|line|polygon) ", got["generated_svg"]),
              f"{name}: the output is drawn and larger than the example: {got['generated']}")
        check(got["seed"] == 4 and got["ms"] > 0, f"{name}: seed and time")
        # The page's Generate: another seed, another output; /api/run draws the same for the same seed.
        status, again = post(port, "/api/infer", {"example": text, "format": fmt, "name": name, "seed": 5})
        check(status == 200 and again["generated_svg"] != got["generated_svg"] and again["grammar"] == got["grammar"],
              f"{name}: another seed, another output")
        status, run = post(port, "/api/run", {"text": got["grammar"], "seed": 5})
        check(status == 200 and run["svg"] == again["generated_svg"], f"{name}: /api/run of the grammar draws the same")

    # --size and --connected, as g2d infer takes them.
    text = open(os.path.join(work, "T.json")).read()
    status, sized = post(port, "/api/infer", {"example": text, "format": "json", "name": "T.json", "size": 30, "connected": True})
    written = cli("infer", "T.json", "--size", "30", "--connected", "-o", "cli.g2d", cwd=work)
    check(status == 200 and sized.get("grammar") == open(os.path.join(work, "cli.g2d")).read(), "size and connected as --size, --connected")

    # Broken examples: the reader's message with its line; the server keeps running.
    broken = {
        "bad.svg": ("svg", '<svg xmlns="http://www.w3.org/2000/svg">\n<g stroke="black">\n<circle r="3"/>\n</g>\n</svg>\n',
                    "bad.svg:3: <circle> is not supported", {"line": 3}),
        "curve.svg": ("svg", '<svg xmlns="http://www.w3.org/2000/svg">\n<path d="M0 0 C 1 1 2 2 3 3" stroke="red"/>\n</svg>\n',
                      "curve.svg:2: <path>: d: the command 'C' draws a curve", {"line": 2}),
        "open.svg": ("svg", '<svg xmlns="http://www.w3.org/2000/svg">\n<g>\n</svg>\n', "open.svg:3: not well-formed XML", {"line": 3}),
        "empty.svg": ("svg", '<svg xmlns="http://www.w3.org/2000/svg"/>\n', "empty.svg:1: the drawing has no edges", {"line": 1}),
        "bad.json": ("json", '{"data": [1, 2\n', "bad.json:2:1: not valid JSON", {"line": 2, "column": 1}),
        "data.json": ("json", '[{"x": 1}]', "data.json: data[0]: expected the format version", None),
    }
    for name, (fmt, text, message, location) in broken.items():
        status, got = post(port, "/api/infer", {"example": text, "format": fmt, "name": name})
        check(status == 422 and got.get("status") == "error" and got["message"].startswith(message) and got.get("location") == location,
              f"{name}: {status} {got}")
        with open(os.path.join(work, name), "w") as f:
            f.write(text)
        refused = cli("infer", name, cwd=work)
        check(refused.returncode == 1 and refused.stderr == f"g2d infer: error: {got.get('message')}\n",
              f"{name}: the message is g2d infer's: {refused.stderr}")
    for body, what in (({"example": "<svg/>", "format": "png"}, "a format"), ({"format": "svg"}, "no example"),
                       ({"example": "x", "format": "svg", "seed": -1}, "a negative seed"),
                       ({"example": "x", "format": "svg", "size": 0}, "size 0"),
                       ({"example": "x", "format": "svg", "timeout": 100}, "a timeout past 60 s")):
        status, got = post(port, "/api/infer", body)
        check(status == 400 and got.get("status") == "error" and got["message"], f"{what}: {status} {got}")
    # A name is only a name: no path in it reaches a message.
    status, got = post(port, "/api/infer", {"example": broken["bad.svg"][1], "format": "svg", "name": "../../etc/x.svg"})
    check(status == 422 and got.get("message", "").startswith("x.svg:3: "), f"a name with a path: {got}")
    # Nor can a name add a line to the grammar: control characters become spaces.
    status, got = post(port, "/api/infer", {"example": open(os.path.join(work, "house.svg")).read(), "format": "svg",
                                            "name": "a\rrule X {}\n.svg"})
    check(status == 200 and got["grammar"].startswith("// Inferred by `g2d infer` from a rule X {} .svg (Merrell"),
          f"a name with line breaks: {status} {got.get('grammar', '')[:100]}")

    # Cancellation: a long inference (a million steps of generation) gives way to a newer run, and to a newer inference.
    t_json = open(os.path.join(work, "T.json")).read()
    slow_body = {"example": t_json, "format": "json", "name": "T.json", "size": 100000, "timeout": 30}
    for newer, body in (("/api/run", {"text": "node P;\naxiom { a: P at (0, 0); }\n"}),
                        ("/api/infer", {"example": t_json, "format": "json", "name": "T.json"})):
        slow = {}
        worker = threading.Thread(target=lambda: slow.update(r=post(port, "/api/infer", slow_body)))
        began = time.monotonic()
        worker.start()
        time.sleep(0.8)
        status, _ = post(port, newer, body)
        worker.join(40)
        took = time.monotonic() - began
        check(slow.get("r", (0, {}))[0] == 409 and slow["r"][1] == {"status": "cancelled"} and status == 200 and took < 10,
              f"a newer {newer} cancels an inference: {str(slow.get('r'))[:200]} {status} after {took:.1f} s")
    status, _ = post(port, "/api/infer", {"example": t_json, "format": "json"})
    check(status == 200, "the server still infers")
finally:
    code = stop(proc)
check(code == 0, f"the studio exits with 0 on SIGINT: {code}")

finish()
