#!/usr/bin/env python3
"""Gallery of `g2d infer`: every Merrell example beside a large, a connected and a detailed output.

For every example JSON under examples/infer/merrell/ (sorted by path), as
Merrell's Fig. 9 shows an example beside its outputs, this

  1. draws the example itself as OUT/NAME/example.svg (from the JSON's
     "decoded" member: every instance's edges as lines, coloured by the edge
     label's brush colour, else #202020);
  2. infers three grammars: g2d infer EXAMPLE -o TMP/G.g2d             (defaults)
                            g2d infer EXAMPLE --connected -o TMP/C.g2d
                            g2d infer EXAMPLE --bend -o TMP/B.g2d  (bent edges: Appendix B)
  3. runs three outputs, each with --seed 1 --stats --json:
       large      g2d run G.g2d                        (target_vertices: 20 x the example's)
       connected  g2d run C.g2d                        (one piece: Appendix A)
       detailed   g2d run B.g2d -D target_vertices=5N  (N: the example's vertices; the
                                                        canvas, sized from the target, follows;
                                                        edges bent, as Merrell's Fig. 9a, d-g)
     each written as OUT/NAME/KIND.svg, or, when that SVG is over 150 KB, as
     OUT/NAME/KIND.png (g2d run -o KIND.png --width 480, rendered by librsvg);
  4. counts each output's vertices, edges and pieces (connected components of
     the --json graph), the largest piece's vertices, and the pairs of pieces
     that touch (closer than 1% of the median edge length: joined in the
     picture, apart in the graph),

and writes OUT/README.md (the table, with a paragraph on what the pictures
show, worked out from the counts) and OUT/gallery.json (every number).

NAME is the example's file name without .json, lowercase, spaces -> '-'
("2D Regions/framed box hollow.json" -> framed-box-hollow). The pictures are
g2d's own, unchanged; a grammar and a seed give the same bytes on every run.

Times (g2d's own --stats "seconds": the derivation, without process start
and writing) vary from run to run; so that remaking the gallery changes no
file unless something did change, a time measured within 3x (or 0.1 s) of
the one already in OUT/gallery.json keeps the old value (--fresh-times: take
every new one). Files of an example folder that the run did not write (e.g. a
large.svg that is now large.png) are removed.

Run from anywhere (needs only Python 3 and the release build of g2d):

    python3 scripts/infer_gallery.py                  # -> docs/gallery/infer
    python3 scripts/infer_gallery.py --out /tmp/gal   # another folder
    python3 scripts/infer_gallery.py --g2d PATH/TO/g2d --examples DIR

It takes a few minutes (the README it writes says how long).
"""

import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from urllib.parse import quote

ROOT = Path(__file__).resolve().parent.parent
SEED = 1
DETAIL_FACTOR = 5          # the detailed output's target: 5 x the example's vertices
SVG_LIMIT = 150_000        # bytes; a larger SVG is written as a PNG instead
PNG_WIDTH = 480
DEFAULT_STROKE = "#202020"
COMMAND = "python3 scripts/infer_gallery.py"
KINDS = ("large", "connected", "detailed")
WIDTHS = {"example": 150, "large": 300, "connected": 200, "detailed": 200}  # px in the README
TIME_FACTOR = 3.0          # a new time within this factor of the stored one keeps it
TIME_SLACK = 0.1           # ... or within this many seconds


def slug(stem):
    """A file-system-safe folder name: lowercase, spaces -> '-'."""
    s = stem.strip().lower().replace(" ", "-")
    s = re.sub(r"[^a-z0-9._+-]", "-", s)
    s = s.replace("+", "plus")
    return s or "example"


def wait_for(binary, seconds=300):
    """The binary may be missing for a moment while someone rebuilds it."""
    deadline = time.monotonic() + seconds
    while not (binary.is_file() and os.access(binary, os.X_OK)):
        if time.monotonic() > deadline:
            sys.exit(f"infer_gallery: {binary} not found (build it with scripts/build.sh)")
        time.sleep(2)


def run(g2d, args, timeout):
    """Run g2d (retrying while the binary is being replaced); return (rc, stdout, stderr, seconds)."""
    for attempt in range(30):
        wait_for(g2d)
        start = time.perf_counter()
        try:
            p = subprocess.run([str(g2d)] + args, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return 124, "", f"timed out after {timeout} s", time.perf_counter() - start
        except OSError:  # e.g. "text file busy" during a rebuild
            time.sleep(2)
            continue
        return p.returncode, p.stdout, p.stderr, time.perf_counter() - start
    return 127, "", f"could not execute {g2d}", 0.0


def last_line(so, se, rc):
    text = (se.strip() or so.strip() or f"exit {rc}")
    return text.splitlines()[-1]


# ---------------------------------------------------------------- example SVG

def fmt(x):
    s = f"{x:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def example_svg(example):
    """The example as SVG: its edges as lines, in the app's orientation.

    The app's coordinates are screen pixels, y down; `g2d infer` reads them as
    y up (y' = -y) and g2d's SVGs flip y' back, so drawing the pixels as they
    are (y down, SVG's own direction) shows the example the way the generated
    shapes are shown.
    """
    dec = example["decoded"]
    shapes = dec.get("shapes", [])
    instances = dec.get("instances") or [
        {"shape": i, "offsetX": 0, "offsetY": 0} for i in range(len(shapes))]
    labels = dec.get("edgeLabels", [])

    lines = []  # (x1, y1, x2, y2, colour)
    points = []
    for inst in instances:
        shape = shapes[inst.get("shape", 0)]
        ox, oy = inst.get("offsetX", 0) or 0, inst.get("offsetY", 0) or 0
        verts = [(x + ox, y + oy) for x, y in shape["vertices"]]
        for e in shape["edges"]:
            a, b = e["v"]
            colour = DEFAULT_STROKE
            lab = e.get("edgeLabel")
            if isinstance(lab, int) and 0 <= lab < len(labels) and labels[lab].get("color"):
                colour = labels[lab]["color"]
            (x1, y1), (x2, y2) = verts[a], verts[b]
            lines.append((x1, y1, x2, y2, colour))
            points += [(x1, y1), (x2, y2)]
        if not shape["edges"]:
            points += verts
    if not points:
        points = [(0, 0), (40, 40)]

    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    extent = max(max(xs) - min(xs), max(ys) - min(ys), 40)
    stroke = 0.11 * 40  # g2d's inferred grammars draw edges 0.11 cells wide (40 px a cell)
    margin = 0.06 * extent + stroke
    x0, y0 = min(xs) - margin, min(ys) - margin
    w, h = max(xs) - min(xs) + 2 * margin, max(ys) - min(ys) + 2 * margin

    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           f'<svg xmlns="http://www.w3.org/2000/svg" width="{fmt(w)}" height="{fmt(h)}" '
           f'viewBox="{fmt(x0)} {fmt(y0)} {fmt(w)} {fmt(h)}">',
           f'<title>{escape(example.get("category", ""))}/{escape(example.get("name", ""))}</title>',
           f'<g stroke-width="{fmt(stroke)}" stroke-linecap="round" fill="none">']
    for x1, y1, x2, y2, colour in lines:
        out.append(f'<line x1="{fmt(x1)}" y1="{fmt(y1)}" x2="{fmt(x2)}" y2="{fmt(y2)}" '
                   f'stroke="{escape(colour)}"/>')
    out += ["</g>", "</svg>", ""]
    return "\n".join(out)


def escape(s):
    return (str(s).replace("&", "&amp;").replace("<", "&lt;")
            .replace(">", "&gt;").replace('"', "&quot;"))


# ---------------------------------------------------------------- outputs

def parse_stats(stdout):
    for line in reversed(stdout.splitlines()):
        line = line.strip()
        if line.startswith("{"):
            try:
                return json.loads(line)
            except ValueError:
                pass
    return None


def pieces(graph):
    """(pieces, vertices of the largest, pairs of pieces that touch) of a node-link JSON graph.

    A piece is a connected component. Two pieces touch when an edge of one
    comes within TOUCH x the median edge length of an edge of the other: far
    less than a stroke's width, so the picture shows them joined although
    the graph keeps them apart.
    """
    pos = {n["id"]: n.get("pos") for n in graph.get("nodes", [])}
    parent = {i: i for i in pos}

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    edges = []
    for link in graph.get("links", []):
        a, b = link["source"], link["target"]
        if a in parent and b in parent:
            ra, rb = find(a), find(b)
            if ra != rb:
                parent[ra] = rb
            if pos[a] and pos[b] and a != b:
                edges.append((a, b))
    sizes = {}
    for n in parent:
        r = find(n)
        sizes[r] = sizes.get(r, 0) + 1
    return len(sizes), max(sizes.values(), default=0), touching(pos, edges, find)


TOUCH = 0.01


def seg_distance(p, q, r, s):
    def to_segment(x, a, b):
        ax, ay = b[0] - a[0], b[1] - a[1]
        ll = ax * ax + ay * ay
        t = 0.0 if ll == 0 else max(0.0, min(1.0, ((x[0] - a[0]) * ax + (x[1] - a[1]) * ay) / ll))
        return math.hypot(x[0] - a[0] - t * ax, x[1] - a[1] - t * ay)
    return min(to_segment(p, r, s), to_segment(q, r, s), to_segment(r, p, q), to_segment(s, p, q))


def touching(pos, edges, find):
    """Pairs of different pieces with edges closer than TOUCH x the median edge length."""
    if len(edges) < 2:
        return 0
    lengths = sorted(math.dist(pos[a][:2], pos[b][:2]) for a, b in edges)
    gap = TOUCH * lengths[len(lengths) // 2]
    cell = max(lengths[len(lengths) // 2], 1e-9)
    grid = {}
    for i, (a, b) in enumerate(edges):
        (x1, y1), (x2, y2) = pos[a][:2], pos[b][:2]
        for gx in range(int(math.floor((min(x1, x2) - gap) / cell)),
                        int(math.floor((max(x1, x2) + gap) / cell)) + 1):
            for gy in range(int(math.floor((min(y1, y2) - gap) / cell)),
                            int(math.floor((max(y1, y2) + gap) / cell)) + 1):
                grid.setdefault((gx, gy), []).append(i)
    pairs = set()
    seen = set()
    for members in grid.values():
        for k, i in enumerate(members):
            for j in members[k + 1:]:
                if (i, j) in seen:
                    continue
                seen.add((i, j))
                (a, b), (c, d) = edges[i], edges[j]
                pa, pc = find(a), find(c)
                if pa == pc:
                    continue
                key = (min(pa, pc), max(pa, pc))
                if key in pairs:
                    continue
                if seg_distance(pos[a][:2], pos[b][:2], pos[c][:2], pos[d][:2]) <= gap:
                    pairs.add(key)
    return len(pairs)


def one_output(g2d, grammar, extra, folder, kind, tmp, timeout):
    """Run one output; write folder/kind.svg (or .png); return its record."""
    svg_tmp = tmp / f"{kind}.svg"
    json_tmp = tmp / f"{kind}.json"
    for f in (svg_tmp, json_tmp):
        if f.exists():
            f.unlink()
    args = ["run", str(grammar), "--seed", str(SEED)] + extra
    rc, so, se, wall = run(g2d, args + ["--stats", "-o", str(svg_tmp), "--json", str(json_tmp)],
                           timeout)
    rec = {"args": extra, "file": None, "error": None, "stats": parse_stats(so) or {},
           "wall": wall}
    if rc != 0 or not svg_tmp.is_file() or not json_tmp.is_file():
        rec["error"] = last_line(so, se, rc)
        return rec
    graph = json.loads(json_tmp.read_text(encoding="utf-8"))
    rec["vertices"] = len(graph.get("nodes", []))
    rec["edges"] = len(graph.get("links", []))
    rec["pieces"], rec["largest"], rec["touching"] = pieces(graph)
    rec["svg_bytes"] = svg_tmp.stat().st_size
    if rec["svg_bytes"] <= SVG_LIMIT:
        rec["file"] = f"{kind}.svg"
        shutil.copyfile(svg_tmp, folder / rec["file"])
    else:
        rec["file"] = f"{kind}.png"
        rc, so, se, _ = run(g2d, args + ["-o", str(folder / rec["file"]),
                                         "--width", str(PNG_WIDTH)], timeout)
        if rc != 0:
            rec["error"] = "PNG: " + last_line(so, se, rc)
            rec["file"] = None
    return rec


def one_example(g2d, path, examples_dir, out, tmp, timeout):
    rel = path.relative_to(examples_dir)
    name = slug(path.stem)
    folder = out / name
    folder.mkdir(parents=True, exist_ok=True)
    example = json.loads(path.read_text(encoding="utf-8"))
    (folder / "example.svg").write_text(example_svg(example), encoding="utf-8")

    rec = {"rel": rel.as_posix(), "name": name, "title": example.get("name", path.stem),
           "written": ["example.svg"], "example_vertices": None, "infer_error": None,
           "infer_seconds": {}, "outputs": {}}
    grammars = {}
    for which, flags in (("default", []), ("connected", ["--connected"]), ("bent", ["--bend"])):
        g = tmp / f"{name}.{which}.g2d"
        rc, so, se, secs = run(g2d, ["infer", str(path), "-o", str(g)] + flags, timeout)
        rec["infer_seconds"][which] = secs
        if rc != 0 or not g.is_file():
            rec["infer_error"] = f"g2d infer {' '.join(flags)}: " + last_line(so, se, rc)
            return rec
        grammars[which] = g
    text = grammars["default"].read_text(encoding="utf-8")
    m = re.search(r"the example has (\d+)", text)
    if m:
        n = int(m.group(1))
    else:  # the target is 20 x the example's vertices
        m = re.search(r"param target_vertices: int = (\d+)", text)
        n = max(1, int(m.group(1)) // 20) if m else 1
    rec["example_vertices"] = n
    plan = {"large": (grammars["default"], []),
            "connected": (grammars["connected"], []),
            "detailed": (grammars["bent"], ["-D", f"target_vertices={DETAIL_FACTOR * n}"])}
    for kind in KINDS:
        grammar, extra = plan[kind]
        o = one_output(g2d, grammar, extra, folder, kind, tmp, timeout)
        rec["outputs"][kind] = o
        if o["file"]:
            rec["written"].append(o["file"])
    return rec


# ---------------------------------------------------------------- stable times

def keep_close(new, old, fresh):
    """The stored time when the new one is within measuring noise of it."""
    if fresh or not isinstance(old, (int, float)) or new is None:
        return new
    if abs(new - old) <= TIME_SLACK or (old > 0 and 1 / TIME_FACTOR <= new / old <= TIME_FACTOR):
        return old
    return new


def previous_times(out):
    try:
        data = json.loads((out / "gallery.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}, None
    times = {}
    for ex in data.get("examples", []):
        for kind, o in (ex.get("outputs") or {}).items():
            times[(ex.get("example"), kind)] = o.get("seconds")
        times[(ex.get("example"), "infer")] = ex.get("infer_seconds")
    return times, data.get("total_seconds")


def settle_times(records, out, fresh):
    old, _ = previous_times(out)
    for rec in records:
        for kind, o in rec["outputs"].items():
            o["seconds"] = keep_close(o["stats"].get("seconds"), old.get((rec["rel"], kind)), fresh)
        inf = sum(rec["infer_seconds"].values()) / max(1, len(rec["infer_seconds"]))
        rec["infer_time"] = keep_close(inf, old.get((rec["rel"], "infer")), fresh)


# ---------------------------------------------------------------- README

def fmt_time(t):
    if t is None:
        return "–"
    if t < 1:
        return f"{t * 1000:.0f} ms" if t >= 0.0095 else f"{t * 1000:.1f} ms"
    return f"{t:.1f} s"


def ratio(a, b):
    return a / b if b else 0.0


def fmt_ratio(x):
    return f"{x:.1f}×"


def title_of(rec):
    rel = rec["rel"]
    return rel[:-len(".json")] if rel.endswith(".json") else rel


def plural(n, one, many):
    return f"{n} {one if n == 1 else many}"


def cell_img(src, alt, width):
    return f'<img src="{src}" width="{width}" alt="{escape(alt)}">'


def output_cell(rec, kind, width):
    title = title_of(rec)
    if rec["infer_error"]:
        return "infer failed: " + escape(rec["infer_error"])
    o = rec["outputs"].get(kind)
    if not o:
        return "–"
    if o["error"]:
        return f"run failed: {escape(o['error'])}"
    pieces_text = plural(o["pieces"], "piece", "pieces")
    if o["pieces"] > 1:
        pieces_text += f' (largest {o["largest"]} vertices)'
    return (cell_img(f'{rec["name"]}/{o["file"]}', f"{title}: {kind} output", width) +
            f'<br>{plural(o["vertices"], "vertex", "vertices")}, '
            f'{plural(o["edges"], "edge", "edges")}<br>{pieces_text}'
            f'<br>{fmt_time(o["seconds"])}')


def summary(records):
    """The paragraph on what the pictures show, from the counts."""
    ok = [r for r in records if not r["infer_error"]]

    def outs(kind):
        return [(r, r["outputs"][kind]) for r in ok
                if kind in r["outputs"] and not r["outputs"][kind]["error"]]

    large, conn, det = outs("large"), outs("connected"), outs("detailed")
    n = len(large)
    if not n:
        return "No output was made."
    one = sum(1 for _, o in large if o["pieces"] == 1)
    many = [(r, o) for r, o in large if o["pieces"] > 1]
    med_pieces = statistics.median(o["pieces"] for _, o in large)
    med_ratio = statistics.median(ratio(o["vertices"], r["example_vertices"]) for r, o in large)
    small_largest = sum(1 for r, o in large if o["largest"] <= 2 * r["example_vertices"])
    empty = sum(1 for _, o in large + conn + det if o["vertices"] == 0)
    c_one = sum(1 for _, o in conn if o["pieces"] == 1)
    c_big = sum(1 for r, o in conn if o["pieces"] == 1
                and o["vertices"] >= 5 * r["example_vertices"])
    c_med = statistics.median(ratio(o["vertices"], r["example_vertices"]) for r, o in conn) \
        if conn else 0
    d_one = sum(1 for _, o in det if o["pieces"] == 1)
    s = []
    s.append("**What the pictures show today.** ")
    if len(many) * 3 >= n:
        s.append("Many outputs are many small pieces rather than one structure: ")
    else:
        s.append("Most outputs are one structure: ")
    s.append(f"{one} of the {n} large outputs are one connected piece and {len(many)} fall into "
             f"several (median {med_pieces:g} pieces); in {small_largest} of {n} the largest piece "
             f"has at most twice the example's vertices, so the picture is a scatter of "
             f"example-sized (or smaller) bits spread over the canvas, not a large shape like the "
             f"paper's Fig. 9. The large outputs do reach the size asked for "
             f"(median {fmt_ratio(med_ratio)} the example's vertices, the target being 20×), "
             f"as the sum of their pieces. ")
    touch = sum(1 for _, o in many if o["touching"])
    if many:
        s.append(("Pieces often touch" if touch * 3 >= len(many) else "Some pieces touch") +
                 f": in {touch} of the {len(many)} large outputs of several "
                 f"pieces, some come within {TOUCH:.0%} of an edge's length of another, less "
                 f"than a stroke's width, so the picture shows them joined where the graph "
                 f"has two pieces (the counts under each picture are the graph's). ")
    s.append(f"With `--connected` {c_one} of {len(conn)} outputs are one piece, but they stay "
             f"small (median {fmt_ratio(c_med)} the example's vertices; {c_big} of {len(conn)} "
             f"reach 5×) and sit small in a canvas sized for the large output. ")
    s.append(f"The detailed outputs (target 5×) are one piece in {d_one} of {len(det)}. ")
    if empty:
        s.append(f"{empty} of the {len(large) + len(conn) + len(det)} outputs are empty. ")
    else:
        s.append("No output is empty. ")
    s.append("Issue 44 tracks the work toward single large structures.")
    return "".join(s)


def write_readme(out, records, examples_dir, total_seconds):
    link_base = os.path.relpath(examples_dir, out).replace(os.sep, "/")
    L = []
    L.append("# `g2d infer` gallery: each example beside a large, a connected and a detailed output")
    L.append("")
    L.append(summary(records))
    L.append("")
    L.append(
        f"Made by `{COMMAND}` (from the repository root, with the release build). For each of "
        f"Merrell's example shapes in `examples/infer/merrell/`, as the paper's Fig. 9 shows "
        f"an example beside its outputs: the **example** itself (its edges, coloured by brush, "
        f"drawn by the script from the JSON's `decoded` member; its areas are not filled, "
        f"the outputs' faces are); a **large** output "
        f"(`g2d infer EXAMPLE -o G.g2d` with the defaults, then `g2d run G.g2d --seed {SEED}`: "
        f"the target is 20× the example's vertices); a **connected** one "
        f"(`g2d infer EXAMPLE --connected -o C.g2d`, `g2d run C.g2d --seed {SEED}`); and a "
        f"**detailed** one, its edges bent as in the paper's Fig. 9a, d–g (Appendix B: "
        f"`g2d infer EXAMPLE --bend -o B.g2d`, then `g2d run B.g2d --seed {SEED} -D target_vertices=` "
        f"{DETAIL_FACTOR}× the example's vertices; the canvas, sized from the target, "
        f"follows, and the iterations stay the large output's). Every picture is g2d's own "
        f"output as written, its frame the grammar's canvas; an SVG over "
        f"{SVG_LIMIT // 1000} KB is shown as the PNG g2d writes of it "
        f"(`-o KIND.png --width {PNG_WIDTH}`). Under each: the output's vertices and edges, "
        f"its pieces (connected components of the `--json` graph, and the largest piece's "
        f"vertices), and the derivation's time (`--stats` seconds, without process start and "
        f"writing). The same example and seed give the same pictures, byte for byte, on "
        f"every run; a time is kept from the previous run when the new one is within "
        f"{TIME_FACTOR:g}× (or {TIME_SLACK:g} s) of it, so remaking "
        f"the gallery changes no file unless something changed. All numbers are also in "
        f"[gallery.json](gallery.json).")
    L.append("")
    infer_md = os.path.relpath(ROOT / "docs" / "infer.md", out).replace(os.sep, "/")
    L.append(f"See [docs/infer.md]({infer_md}) (\"Generation\") for what the written grammar "
             f"holds and how its size, canvas and `--connected` work.")
    L.append("")
    L.append("| example | large | connected | detailed |")
    L.append("|---|---|---|---|")
    for rec in records:
        rel = rec["rel"]
        title = title_of(rec)
        first = f'[{title}]({link_base}/{quote(rel)})'
        if rec["title"] and rec["title"].lower() != Path(rel).stem.lower():
            first += f'<br>“{escape(rec["title"])}”'
        first += "<br>" + cell_img(f'{rec["name"]}/example.svg', f"{title}: example",
                                   WIDTHS["example"])
        if rec["example_vertices"]:
            first += (f'<br>{plural(rec["example_vertices"], "vertex", "vertices")}'
                      f'<br>inferred in {fmt_time(rec["infer_time"])}')
        cells = [first] + [output_cell(rec, kind, WIDTHS[kind]) for kind in KINDS]
        L.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
    L.append("")
    L.append("## Sizes")
    L.append("")
    L.append("Each output's vertices and its largest piece's, as multiples of the example's "
             "vertices; its pieces, and in brackets the pairs of pieces that touch (an edge "
             f"of one within {TOUCH:.0%} of the median edge length of an edge of the other: "
             "in the picture they look joined, in the graph they are not); and the steps "
             "whose drawing was rejected (`--stats` `rejected_drawings`) of all steps done.")
    L.append("")
    L.append("| example | vertices | large: × / largest × / pieces | connected: × / pieces "
             "| detailed: × / largest × / pieces | rejected drawings (large, connected, detailed) |")
    L.append("|---|---|---|---|---|---|")
    for rec in records:
        if rec["infer_error"]:
            L.append(f"| {title_of(rec)} | infer failed | | | | |")
            continue
        n = rec["example_vertices"]
        cols = []
        rej = []
        for kind in KINDS:
            o = rec["outputs"][kind]
            if o["error"]:
                cols.append("run failed")
                rej.append("–")
                continue
            part = f'{fmt_ratio(ratio(o["vertices"], n))}'
            if kind != "connected":
                part += f' / {fmt_ratio(ratio(o["largest"], n))}'
            part += f' / {o["pieces"]}'
            if o["pieces"] > 1:
                part += f' ({o["touching"]})'
            cols.append(part)
            st = o["stats"]
            rej.append(f'{st.get("rejected_drawings", "?")}/{st.get("steps", "?")}')
        L.append(f"| {title_of(rec)} | {n} | " + " | ".join(cols) + " | " + ", ".join(rej) + " |")
    L.append("")
    L.append(f"The whole gallery took {total_seconds:.0f} s to make.")
    L.append("")
    (out / "README.md").write_text("\n".join(L), encoding="utf-8")


def write_data(out, records, total_seconds):
    data = {"seed": SEED, "detail_factor": DETAIL_FACTOR, "svg_limit": SVG_LIMIT,
            "png_width": PNG_WIDTH, "total_seconds": total_seconds, "examples": []}
    for rec in records:
        ex = {"example": rec["rel"], "folder": rec["name"],
              "example_vertices": rec["example_vertices"], "infer_error": rec["infer_error"],
              "infer_seconds": rec.get("infer_time"), "outputs": {}}
        for kind, o in rec["outputs"].items():
            st = o["stats"]
            ex["outputs"][kind] = {
                "file": o["file"], "error": o["error"], "args": o["args"],
                "vertices": o.get("vertices"), "edges": o.get("edges"),
                "pieces": o.get("pieces"), "largest_piece": o.get("largest"),
                "touching_pairs": o.get("touching"),
                "steps": st.get("steps"), "applications": st.get("applications"),
                "rejected_drawings": st.get("rejected_drawings"),
                "rejected_by_cost": st.get("rejected_by_cost"),
                "seconds": o.get("seconds")}
        data["examples"].append(ex)
    (out / "gallery.json").write_text(json.dumps(data, indent=1, sort_keys=True) + "\n",
                                      encoding="utf-8")


def prune(out, records):
    """Remove pictures of the example folders that this run did not write."""
    for rec in records:
        folder = out / rec["name"]
        keep = set(rec["written"])
        for f in sorted(folder.iterdir()):
            if f.is_file() and f.suffix in (".svg", ".png") and f.name not in keep:
                f.unlink()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "docs" / "gallery" / "infer"),
                    help="output folder (default docs/gallery/infer)")
    ap.add_argument("--g2d", default=str(ROOT / "build" / "release" / "bin" / "g2d"),
                    help="the g2d binary (default build/release/bin/g2d)")
    ap.add_argument("--examples", default=str(ROOT / "examples" / "infer" / "merrell"),
                    help="folder of example JSONs (searched recursively)")
    ap.add_argument("--timeout", type=float, default=600,
                    help="seconds allowed for one g2d call (default 600)")
    ap.add_argument("--fresh-times", action="store_true",
                    help="write every time as measured (default: keep a stored time "
                         "the new one is within 3x or 0.1 s of)")
    args = ap.parse_args()

    g2d = Path(args.g2d).resolve()
    examples_dir = Path(args.examples).resolve()
    out = Path(args.out).resolve()
    paths = sorted(examples_dir.rglob("*.json"), key=lambda p: p.as_posix())
    if not paths:
        sys.exit(f"infer_gallery: no example JSON under {examples_dir}")
    names = [slug(p.stem) for p in paths]
    if len(set(names)) != len(names):
        sys.exit("infer_gallery: two examples have the same folder name")

    out.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix="infer_gallery."))
    start = time.perf_counter()
    records = []
    try:
        for i, path in enumerate(paths, 1):
            rec = one_example(g2d, path, examples_dir, out, tmp, args.timeout)
            records.append(rec)
            if rec["infer_error"]:
                note = "infer failed: " + rec["infer_error"]
            else:
                note = "; ".join(
                    f'{k}: ' + (f'error: {o["error"]}' if o["error"] else
                                f'{o["vertices"]} v, {o["pieces"]} pieces, {o["file"]}, '
                                f'{o["wall"]:.2f} s')
                    for k, o in rec["outputs"].items())
            print(f"[{i}/{len(paths)}] {rec['rel']} ({rec['example_vertices']} v): {note}",
                  file=sys.stderr)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    total = time.perf_counter() - start
    _, old_total = previous_times(out)
    total = keep_close(total, old_total, args.fresh_times)
    settle_times(records, out, args.fresh_times)
    prune(out, records)
    write_readme(out, records, examples_dir, total)
    write_data(out, records, total)
    size = sum(f.stat().st_size for f in out.rglob("*") if f.is_file())
    print(f"wrote {out}/README.md: {len(records)} examples, {size / 1e6:.2f} MB, "
          f"{time.perf_counter() - start:.1f} s", file=sys.stderr)
    failed = [r for r in records if r["infer_error"] or any(o["error"] for o in r["outputs"].values())]
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
