#!/usr/bin/env python3
"""Interpreted (`g2d run`) against compiled (`g2d build`) on the same grammars,
measured side by side in one run: each case alternates the two back ends,
several rounds, and reports the fastest derivation time of each (`--stats`
seconds: the derivation alone) and their ratio. The machines are shared and
noisy; alternating and taking minima keeps the ratio fair.

usage: bench/compare_backends.py [--g2d build/release/bin/g2d] [--rounds 5]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CASES = [
    # name, grammar, arguments
    ("koch level 5", "examples/koch_snowflake.g2d", ["-D", "max_lod=5"]),
    ("koch level 6", "examples/koch_snowflake.g2d", ["-D", "max_lod=6"]),
    ("koch 192 steps (thesis)", "examples/koch_snowflake.g2d", ["--steps", "192"]),
    ("tree 200 steps", "examples/tree.g2d", []),
    ("varied façade", "examples/facade_varied.g2d", []),
    ("square pattern", "examples/pattern_square.g2d", []),
    ("sierpinski g=7", "examples/sierpinski.g2d", ["-D", "generations=7"]),
    ("maze 14×14", "examples/maze.g2d", []),
]


def stats(cmd, cwd):
    out = subprocess.run(cmd, cwd=cwd, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--g2d", default=os.path.join(ROOT, "build/release/bin/g2d"))
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="g2d-bench-")
    programs = {}
    print("| case | steps | elements | interpreted s | compiled s | speed-up |")
    print("|---|---:|---:|---:|---:|---:|")
    for name, grammar, extra in CASES:
        path = os.path.join(ROOT, grammar)
        if grammar not in programs:
            exe = os.path.join(work, os.path.basename(grammar) + ".exe")
            subprocess.run([args.g2d, "build", path, "-o", exe], check=True)
            programs[grammar] = exe
        common = ["--no-svg", "--stats"] + extra
        best = {"interpreted": None, "compiled": None}
        info = None
        for _ in range(args.rounds):
            for backend, cmd in (("interpreted", [args.g2d, "run", path] + common),
                                 ("compiled", [programs[grammar]] + common)):
                s = stats(cmd, os.path.dirname(path))
                info = s
                if best[backend] is None or s["seconds"] < best[backend]:
                    best[backend] = s["seconds"]
        ratio = best["interpreted"] / best["compiled"] if best["compiled"] > 0 else float("inf")
        print(f"| {name} | {info['steps']} | {info['nodes'] + info['edges']} | {best['interpreted']:.5f} | "
              f"{best['compiled']:.5f} | {ratio:.1f}× |", flush=True)


if __name__ == "__main__":
    sys.exit(main())
