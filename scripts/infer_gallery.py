#!/usr/bin/env python3
"""Gallery of `g2d infer`: every Merrell example beside three generated shapes.

For every example JSON under examples/infer/merrell/ (sorted by path) this

  1. infers a grammar:   g2d infer EXAMPLE -o TMP/NAME.g2d --iterations 1000
  2. generates shapes:   g2d run TMP/NAME.g2d --seed S --stats -o OUT/NAME/seedS.svg
                         for S = 1, 2, 3 (wall time and the --stats line are kept)
  3. draws the example itself as OUT/NAME/example.svg (from the JSON's
     "decoded" member: every instance's edges as lines, coloured by the
     edge label's brush colour, else #202020),

and writes OUT/README.md, a table "example -> three generated shapes" with
the nodes and edges of every output and the run statistics per seed.

NAME is the example's file name without .json, lowercase, spaces -> '-'
("2D Regions/framed box hollow.json" -> framed-box-hollow). The generated
SVGs are g2d's own, unchanged; a grammar and a seed give the same bytes on
every run.

Run from anywhere (needs only Python 3 and the release build of g2d):

    python3 scripts/infer_gallery.py                  # -> docs/gallery/infer
    python3 scripts/infer_gallery.py --out /tmp/gal   # another folder
    python3 scripts/infer_gallery.py --g2d PATH/TO/g2d --examples DIR

It takes about a minute (see the README it writes for the times per run).
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from urllib.parse import quote

ROOT = Path(__file__).resolve().parent.parent
SEEDS = (1, 2, 3)
ITERATIONS = 1000
DEFAULT_STROKE = "#202020"
COMMAND = "python3 scripts/infer_gallery.py"


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


# ---------------------------------------------------------------- gallery

def parse_stats(stdout):
    for line in reversed(stdout.splitlines()):
        line = line.strip()
        if line.startswith("{"):
            try:
                return json.loads(line)
            except ValueError:
                pass
    return None


def one_example(g2d, path, examples_dir, out, tmp, timeout):
    rel = path.relative_to(examples_dir)
    name = slug(path.stem)
    folder = out / name
    folder.mkdir(parents=True, exist_ok=True)
    example = json.loads(path.read_text(encoding="utf-8"))
    (folder / "example.svg").write_text(example_svg(example), encoding="utf-8")

    rec = {"rel": rel, "name": name, "title": example.get("name", path.stem),
           "infer_error": None, "infer_seconds": None, "seeds": {}}
    grammar = tmp / f"{name}.g2d"
    rc, so, se, secs = run(g2d, ["infer", str(path), "-o", str(grammar),
                                 "--iterations", str(ITERATIONS)], timeout)
    rec["infer_seconds"] = secs
    if rc != 0 or not grammar.is_file():
        rec["infer_error"] = (se.strip() or so.strip() or f"exit {rc}").splitlines()[-1]
        return rec
    for seed in SEEDS:
        svg = folder / f"seed{seed}.svg"
        rc, so, se, secs = run(g2d, ["run", str(grammar), "--seed", str(seed), "--stats",
                                     "-o", str(svg)], timeout)
        stats = parse_stats(so) or {}
        rec["seeds"][seed] = {
            "seconds": secs, "stats": stats, "svg": svg.is_file() and rc == 0,
            "error": None if rc == 0 else (se.strip() or f"exit {rc}").splitlines()[-1]}
    return rec


def cell_img(src, alt):
    return f'<img src="{src}" width="160" alt="{escape(alt)}">'


def ne(stats):
    if not stats:
        return "–"
    return f'{stats.get("nodes", "?")} nodes, {stats.get("edges", "?")} edges'


def per_seed(rec, key, form="{}"):
    vals = []
    for seed in SEEDS:
        s = rec["seeds"].get(seed)
        if not s or not s["stats"] or key not in s["stats"]:
            vals.append("–")
        else:
            vals.append(form.format(s["stats"][key]))
    return " / ".join(vals)


def write_readme(out, records, examples_dir, total_seconds):
    link_base = os.path.relpath(examples_dir, out).replace(os.sep, "/")
    seeds = ", ".join(str(s) for s in SEEDS)
    L = []
    L.append("# `g2d infer` gallery: each example beside three generated shapes")
    L.append("")
    L.append(f"Made by `{COMMAND}` (from the repository root, with the release build). "
             f"For each of Merrell's example shapes in `examples/infer/merrell/` it runs "
             f"`g2d infer EXAMPLE -o G.g2d --iterations {ITERATIONS}` and then "
             f"`g2d run G.g2d --seed S --stats -o seedS.svg` for S = {seeds}. "
             f"The first picture is the example itself (its edges, coloured by brush, "
             f"drawn by the script from the JSON's `decoded` member); the other three are "
             f"g2d's SVGs as written. Outputs are byte-reproducible: the same example and "
             f"seed give the same grammar and the same SVG, byte for byte, on every run.")
    L.append("")
    infer_md = os.path.relpath(ROOT / "docs" / "infer.md", out).replace(os.sep, "/")
    L.append(f"See [docs/infer.md]({infer_md}) for what is inferred and why a few "
             "examples give empty outputs (0 nodes: no drawing of the starter was found "
             f"within {ITERATIONS} steps).")
    L.append("")
    L.append("| example | example shape | seed 1 | seed 2 | seed 3 |")
    L.append("|---|---|---|---|---|")
    for rec in records:
        rel = rec["rel"].as_posix()
        title = rel[:-len(".json")] if rel.endswith(".json") else rel
        link = f'{link_base}/{quote(rel)}'
        first = f'[{title}]({link})'
        if rec["title"] and rec["title"].lower() != Path(rel).stem.lower():
            first += f'<br>“{rec["title"]}”'
        cells = [first, cell_img(f'{rec["name"]}/example.svg', f"{title}: example")]
        for seed in SEEDS:
            if rec["infer_error"]:
                cells.append("infer failed: " + escape(rec["infer_error"]))
                continue
            s = rec["seeds"].get(seed)
            if s and s["svg"]:
                cells.append(cell_img(f'{rec["name"]}/seed{seed}.svg', f"{title}: seed {seed}")
                             + "<br>" + ne(s["stats"]))
            else:
                cells.append("run failed: " + escape(s["error"] if s else "?"))
        L.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
    L.append("")
    L.append("## Run statistics")
    L.append("")
    L.append("Per example the values of seeds " + " / ".join(str(s) for s in SEEDS) +
             ", from `g2d run --stats` (steps done, nodes and edges of the output, rule "
             "applications, drawings rejected), and the wall time of each `g2d run` "
             "(including process start; times vary from run to run, everything else "
             f"does not). The whole gallery took {total_seconds:.0f} s to make.")
    L.append("")
    L.append("| example | steps | nodes | edges | applications | rejected drawings | time (s) |")
    L.append("|---|---|---|---|---|---|---|")
    for rec in records:
        rel = rec["rel"].as_posix()
        title = rel[:-len(".json")] if rel.endswith(".json") else rel
        if rec["infer_error"]:
            L.append(f"| {title} | infer failed | | | | | |")
            continue
        times = " / ".join(
            f'{rec["seeds"][s]["seconds"]:.2f}' if s in rec["seeds"] else "–" for s in SEEDS)
        L.append(f"| {title} | {per_seed(rec, 'steps')} | {per_seed(rec, 'nodes')} | "
                 f"{per_seed(rec, 'edges')} | {per_seed(rec, 'applications')} | "
                 f"{per_seed(rec, 'rejected_drawings')} | {times} |")
    L.append("")
    empty = [r for r in records if not r["infer_error"] and r["seeds"] and all(
        (r["seeds"][s]["stats"] or {}).get("nodes", 0) == 0 for s in SEEDS)]
    if empty:
        L.append("Empty for every seed (0 nodes): " +
                 ", ".join(r["rel"].as_posix()[:-5] for r in empty) + ".")
        L.append("")
    (out / "README.md").write_text("\n".join(L), encoding="utf-8")


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
                    f'seed {s}: {ne(v["stats"])}, {v["seconds"]:.2f} s'
                    + (f' (error: {v["error"]})' if v["error"] else "")
                    for s, v in rec["seeds"].items())
            print(f"[{i}/{len(paths)}] {rec['rel'].as_posix()}: {note}", file=sys.stderr)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    total = time.perf_counter() - start
    write_readme(out, records, examples_dir, total)
    size = sum(f.stat().st_size for f in out.rglob("*") if f.is_file())
    print(f"wrote {out}/README.md: {len(records)} examples, {size / 1e6:.2f} MB, "
          f"{total:.1f} s", file=sys.stderr)
    failed = [r for r in records if r["infer_error"] or any(v["error"] for v in r["seeds"].values())]
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
