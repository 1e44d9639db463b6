#!/usr/bin/env python3
"""`g2d infer` at the paper's scale (issue #44): how large, how connected and
how locally similar the written grammars' outputs are, and how fast they run.

For every example of examples/infer/merrell (and any more folders given with
--examples), it writes the grammar with the defaults and with --connected,
runs each for seeds 1..3 (interpreted, the grammar's own iterations) and
reads the JSON: vertices (÷ the example's), pieces (connected components),
the largest piece, and whether every vertex's star is one of the example's
primitives (the kinds name them; `g2d infer` lists their half-edges).
--speed also builds each default grammar and times 20,000 iterations
compiled, and the time per iteration at about 50 and 5,000 vertices on one
example.

usage: bench/infer_scale.py [--g2d build/release/bin/g2d] [--examples DIR ...] [--seeds 3] [--speed]
                            [--only SUBSTRING] [--json OUT.json]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MERRELL = os.path.join(ROOT, "examples", "infer", "merrell")


def examples(folders):
    for top in folders:
        for dirpath, _, files in sorted(os.walk(top)):
            for name in sorted(files):
                if name.endswith(".json") or name.endswith(".svg"):
                    yield os.path.join(dirpath, name)


def primitives(g2d, example):
    """The example's vertex count and its primitives' half-edge labels as sorted tuples, by index."""
    text = subprocess.run([g2d, "infer", example], check=True, capture_output=True, text=True).stdout
    vertices = int(re.search(r"\((\d+) vertices", text).group(1))
    prims = {}
    for m in re.finditer(r"^  P(\d+): (.*?) \^", text, re.M):
        prims[int(m.group(1))] = tuple(sorted(m.group(2).split()))
    return vertices, prims


def measure(output, prims):
    """Vertices, pieces, the largest piece, and whether every star is a primitive's."""
    d = json.load(open(output))
    ids = [n["id"] for n in d["nodes"]]
    kind = {n["id"]: int(n["kind"][1:]) for n in d["nodes"]}
    halves = {i: [] for i in ids}
    parent = {i: i for i in ids}

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for link in d["links"]:
        halves[link["source"]].append(str(link["label"]))
        halves[link["target"]].append(str(link["label"]) + "'")
        parent[find(link["source"])] = find(link["target"])
    sizes = {}
    for i in ids:
        sizes[find(i)] = sizes.get(find(i), 0) + 1
    similar = all(tuple(sorted(halves[i])) == prims.get(kind[i]) for i in ids)
    return len(ids), len(sizes), max(sizes.values(), default=0), similar


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(" ".join(cmd) + ": " + p.stderr[:400])
    return json.loads(p.stdout.splitlines()[-1])


def scale_table(g2d, folders, seeds, only):
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for example in examples(folders):
            if only and only not in example:
                continue
            vertices, prims = primitives(g2d, example)
            row = {"example": os.path.relpath(example, ROOT), "vertices": vertices}
            for mode, flags in (("default", []), ("connected", ["--connected"])):
                grammar = os.path.join(tmp, mode + ".g2d")
                subprocess.run([g2d, "infer", example, "-o", grammar] + flags, check=True, stdout=subprocess.DEVNULL)
                outs = []
                for seed in range(1, seeds + 1):
                    out = os.path.join(tmp, f"{mode}{seed}.json")
                    stats = run([g2d, "run", grammar, "--no-svg", "--json", out, "--stats", "--seed", str(seed)])
                    n, pieces, largest, similar = measure(out, prims)
                    outs.append({"vertices": n, "pieces": pieces, "largest": largest, "similar": similar,
                                 "seconds": stats["seconds"], "steps": stats["steps"]})
                row[mode] = outs
            rows.append(row)
            d, c = row["default"], row["connected"]
            print(f"| {row['example'][len('examples/infer/merrell/'):] if row['example'].startswith('examples/infer/merrell/') else row['example']} "
                  f"| {vertices} | {statistics.median(o['vertices'] for o in d) / vertices:.1f} "
                  f"| {statistics.median(o['pieces'] for o in d):.0f} | {statistics.median(o['largest'] for o in d) / vertices:.1f} "
                  f"| {statistics.median(o['largest'] for o in c) / vertices:.1f} | {max(o['pieces'] for o in c)} "
                  f"| {'yes' if all(o['similar'] for o in d + c) else 'NO'} "
                  f"| {max(o['seconds'] for o in d) * 1000:.0f} |", flush=True)
    return rows


def summary(rows):
    ratios = [statistics.median(o["vertices"] for o in r["default"]) / r["vertices"] for r in rows]
    connected_ok = sum(1 for r in rows if all(o["pieces"] == 1 and o["vertices"] >= 5 * r["vertices"] for o in r["connected"]))
    print(f"\nmedian output vertices / example vertices (defaults): {statistics.median(ratios):.1f} "
          f"(lowest {min(ratios):.1f}); --connected: one piece of at least 5x the example in {connected_ok} of {len(rows)} examples; "
          f"locally similar: {sum(1 for r in rows if all(o['similar'] for o in r['default'] + r['connected']))} of {len(rows)}")


def speed_table(g2d, folders, only):
    """20,000 iterations of each default grammar, compiled."""
    print("\n| example | compiled seconds for 20,000 iterations | output vertices |")
    print("|---|---|---|")
    worst = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for example in examples(folders):
            if only and only not in example:
                continue
            grammar, exe = os.path.join(tmp, "g.g2d"), os.path.join(tmp, "g")
            subprocess.run([g2d, "infer", example, "-o", grammar, "--iterations", "20000"], check=True, stdout=subprocess.DEVNULL)
            subprocess.run([g2d, "build", grammar, "-o", exe], check=True, stdout=subprocess.DEVNULL)
            best = min((run([exe, "--no-svg", "--stats", "--seed", "1"]) for _ in range(3)), key=lambda s: s["seconds"])
            worst = max(worst, best["seconds"])
            print(f"| {os.path.relpath(example, MERRELL)} | {best['seconds']:.2f} | {best['nodes']} |", flush=True)
    print(f"\nslowest: {worst:.2f} s (target: 2 s; the paper: 44 s for Factory's 20k)")


def per_iteration(g2d, example, sizes=(50, 5000)):
    """The compiled grammar's time per iteration once the output has about T vertices: the
    time of iterations 10T..10T + W, W = max(2T, 4000) (best of 5 of each run), for each T."""
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        grammar, exe = os.path.join(tmp, "g.g2d"), os.path.join(tmp, "g")
        subprocess.run([g2d, "infer", example, "-o", grammar], check=True, stdout=subprocess.DEVNULL)
        subprocess.run([g2d, "build", grammar, "-o", exe], check=True, stdout=subprocess.DEVNULL)
        for t in sizes:
            def best(steps):
                return min((run([exe, "--no-svg", "--stats", "--seed", "1", "-D", f"target_vertices={t}",
                                 "--steps", str(steps), "-D", f"iterations={steps}"]) for _ in range(5)), key=lambda s: s["seconds"])
            window = max(2 * t, 4000)
            a, b = best(10 * t), best(10 * t + window)
            out[t] = ((b["seconds"] - a["seconds"]) / window, b["nodes"])
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--g2d", default=os.path.join(ROOT, "build", "release", "bin", "g2d"))
    ap.add_argument("--examples", nargs="*", default=[MERRELL])
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--only", default="")
    ap.add_argument("--speed", action="store_true")
    ap.add_argument("--json")
    a = ap.parse_args()
    print("| example | vertices | output ÷ example (median) | pieces | largest piece ÷ example | --connected: largest ÷ example "
          "| --connected: most pieces | locally similar | ms (slowest seed) |")
    print("|---|---|---|---|---|---|---|---|---|")
    rows = scale_table(a.g2d, a.examples, a.seeds, a.only)
    summary(rows)
    if a.json:
        json.dump(rows, open(a.json, "w"), indent=1)
    if a.speed:
        speed_table(a.g2d, a.examples, a.only)
        print("\n| example | µs per iteration at about 50 vertices | at about 5,000 | ratio |")
        print("|---|---|---|---|")
        for name in ("2D Branches/branches.json", "2D Basic Shapes/star hollow.json", "2D Networks/4-way hollow.json",
                     "2D Basic Shapes/square hollow.json", "2D Networks/4-way filled.json"):
            r = per_iteration(a.g2d, os.path.join(MERRELL, name))
            (small, n1), (large, n2) = r[50], r[5000]
            print(f"| {name} | {small * 1e6:.1f} ({n1} vertices) | {large * 1e6:.1f} ({n2} vertices) | {large / small:.2f} |", flush=True)


if __name__ == "__main__":
    sys.exit(main())
