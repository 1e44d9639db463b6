#!/usr/bin/env python3
"""Two g2d builds side by side on one grammar: is a change faster?

Builds GRAMMAR with each `g2d` (`g2d build`), checks that both programs
write the same SVG and JSON for the arguments given (a change meant for
speed must not change output), then runs them in alternating rounds (A
then B, then B then A, and so on) and prints, for each, the fastest and
median derivation time (`--stats` "seconds") and peak memory, and the
median of the per-round ratios B / A with its quartiles.

On a shared machine the speed of memory drifts over minutes by tens of
per cent; two runs in the same round see nearly the same machine, so
their ratio is steadier than either time. Example:

    python3 bench/compare.py --a /tmp/old/build/release/bin/g2d \\
        --b build/release/bin/g2d --rounds 25 examples/koch_snowflake.g2d -D max_lod=9
"""
import argparse
import filecmp
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import run_measured  # noqa: E402  (the suite's fork/exec/wait4 runner)


def build(g2d, grammar, exe):
    try:
        done = subprocess.run([g2d, "build", grammar, "-o", exe], capture_output=True, text=True)
    except OSError as e:
        sys.exit(f"compare.py: cannot run {g2d}: {e.strerror}")
    if done.returncode != 0:
        sys.exit(f"compare.py: {g2d} build {grammar} failed:\n{done.stderr}")


def same_output(exes, args, work):
    """Whether both programs write byte-identical SVG and JSON."""
    outputs = []
    for k, exe in enumerate(exes):
        svg, graph = os.path.join(work, f"out{k}.svg"), os.path.join(work, f"out{k}.json")
        done = subprocess.run([exe] + args + ["-o", svg, "--json", graph], capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"compare.py: {exe} {' '.join(args)} failed:\n{done.stderr}")
        outputs.append((svg, graph))
    return all(filecmp.cmp(a, b, shallow=False) for a, b in zip(*outputs))


def quartiles(values):
    v = sorted(values)
    return v[len(v) // 4], statistics.median(v), v[(3 * len(v)) // 4]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--a", required=True, help="the g2d to compare against (the baseline)")
    ap.add_argument("--b", required=True, help="the g2d with the change")
    ap.add_argument("--rounds", type=int, default=15, help="rounds of one run each (default 15)")
    ap.add_argument("--skip-output-check", action="store_true",
                    help="do not compare outputs (for a change meant to alter them)")
    ap.add_argument("grammar")
    ap.add_argument("args", nargs=argparse.REMAINDER, help="arguments for the program (-D, --seed, --steps...)")
    opts = ap.parse_args()
    if opts.rounds < 1:
        ap.error("--rounds must be at least 1")
    work = tempfile.mkdtemp(prefix="g2d-compare-")
    exes = [os.path.join(work, "a"), os.path.join(work, "b")]
    for g2d, exe in zip([opts.a, opts.b], exes):
        build(g2d, opts.grammar, exe)
    if not opts.skip_output_check and not same_output(exes, opts.args, work):
        sys.exit("compare.py: A and B write different output for these arguments "
                 "(--skip-output-check to time them anyway)")

    seconds, rss = [[], []], [0, 0]
    steps = None
    for r in range(opts.rounds):
        for k in ((0, 1) if r % 2 == 0 else (1, 0)):
            stats, peak = run_measured([exes[k]] + opts.args + ["--no-svg", "--stats"])
            seconds[k].append(stats["seconds"])
            rss[k] = max(rss[k], peak)
            steps = stats["steps"]
    ratios = [b / a for a, b in zip(*seconds)]
    print(f"{opts.grammar} {' '.join(opts.args)}: {steps} steps, {opts.rounds} rounds, outputs "
          f"{'not compared' if opts.skip_output_check else 'identical'}")
    print()
    print("| build | fastest s | median s | peak memory MB |")
    print("|---|---:|---:|---:|")
    for name, times, peak in zip(["A", "B"], seconds, rss):
        print(f"| {name} | {min(times):.4g} | {statistics.median(times):.4g} | {peak / 2**20:.1f} |")
    low, mid, high = quartiles(ratios)
    print()
    print(f"B / A per round: median {mid:.3f} (quartiles {low:.3f} to {high:.3f})")


if __name__ == "__main__":
    main()
