#!/usr/bin/env python3
"""Time per derivation step as the graph grows: the Koch snowflake from level
5 to level 9 (≈ 3·10^3 to 1.6·10^6 elements), oldest and random selection,
sequential and parallel steps, compiled (and optionally interpreted). A
per-step cost that does not grow with the graph shows as a flat column.

usage: bench/koch_scaling.py [--g2d build/release/bin/g2d] [--levels 5 6 7 8 9] [--interpreted]
"""
import argparse
import json
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KOCH = os.path.join(ROOT, "examples/koch_snowflake.g2d")

VARIANTS = {
    "oldest": lambda s: s,
    "random": lambda s: s.replace("rule Split pick oldest", "rule Split"),
    "parallel": lambda s: s.replace("rule Split pick oldest", "rule Split parallel"),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--g2d", default=os.path.join(ROOT, "build/release/bin/g2d"))
    ap.add_argument("--levels", type=int, nargs="+", default=[5, 6, 7, 8, 9])
    ap.add_argument("--interpreted", action="store_true")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="g2d-koch-")
    source = open(KOCH).read()
    print("| variant | backend | level | steps | elements | seconds | µs per step |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for name, edit in VARIANTS.items():
        grammar = os.path.join(work, f"koch_{name}.g2d")
        open(grammar, "w").write(edit(source))
        exe = grammar + ".exe"
        subprocess.run([args.g2d, "build", grammar, "-o", exe], check=True)
        backends = [("compiled", [exe])] + ([("interpreted", [args.g2d, "run", grammar])] if args.interpreted else [])
        for backend, cmd in backends:
            for level in args.levels:
                out = subprocess.run(cmd + ["-D", f"max_lod={level}", "--no-svg", "--stats"],
                                     check=True, capture_output=True, text=True).stdout
                s = json.loads(out.strip().splitlines()[-1])
                per = s["seconds"] / max(s["steps"], 1) * 1e6
                print(f"| {name} | {backend} | {level} | {s['steps']} | {s['nodes'] + s['edges']} | "
                      f"{s['seconds']:.4f} | {per:.2f} |", flush=True)


if __name__ == "__main__":
    main()
