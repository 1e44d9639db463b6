#!/usr/bin/env python3
"""Every pure built-in, on edge cases (huge ints, overflow, infinity, NaN, zero
vectors, bad text), three ways: folded by the compiler (`const c = f(...)` of
literals), interpreted, and compiled (the same call on parameters set with
-D, which nothing folds). The three must give the same value, or fail with
the same words.

usage: builtins_test.py G2D SOURCE_DIR
"""
import json
import os
import re
import subprocess
import sys
import tempfile

g2d, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
sys.path.insert(0, os.path.join(src, "tests", "pylib"))
from checks import check, finish  # noqa: E402

work = tempfile.mkdtemp()

# (call with arguments a, b, c; result type; the arguments as (type, g2d literal, -D text)).
# A literal that cannot be written as one token (the least int) is an expression.
I, F, V, S = "int", "float", "vec2", "string"
INT_MIN = (I, "(-9223372036854775807 - 1)", "-9223372036854775808")


def i(n):
    return (I, str(n) if n >= 0 else "(%d)" % n, str(n))


def f(x):
    return (F, x if not x.startswith("-") else "(%s)" % x, x)


def v(x, y):
    return (V, "(%s, %s)" % (x, y), "%s,%s" % (x, y))


def s(t):
    return (S, json.dumps(t), t)


CASES = [
    ("sin(a)", F, [f("1e300")]),
    ("cos(a)", F, [f("-0.5")]),
    ("tan(a)", F, [f("1.5707963267948966")]),
    ("asin(a)", F, [f("2.0")]),
    ("acos(a)", F, [f("1.0")]),
    ("atan(a)", F, [f("1e308")]),
    ("atan2(a, b)", F, [f("0.0"), f("-1.0")]),
    ("sqrt(a)", F, [f("-1.0")]),
    ("sqrt(a)", F, [f("2.0")]),
    ("exp(a)", F, [f("710.0")]),
    ("exp(a)", F, [f("-1000.0")]),
    ("log(a)", F, [f("0.0")]),
    ("pow(a, b)", F, [f("10.0"), f("400.0")]),
    ("pow(a, b)", F, [f("-8.0"), f("0.5")]),
    ("hypot(a, b)", F, [f("1e308"), f("1e308")]),
    ("floor(a)", I, [f("1e19")]),
    ("floor(a)", I, [f("-2.5")]),
    ("ceil(a)", I, [f("-9.3e18")]),
    ("round(a)", I, [f("2.5")]),
    ("round(a)", I, [f("-2.5")]),
    ("radians(a)", F, [f("1e308")]),
    ("degrees(a)", F, [f("1e307")]),
    ("abs(a)", I, [INT_MIN]),
    ("abs(a)", I, [i(-7)]),
    ("abs(a)", F, [f("-2.5")]),
    ("sign(a)", I, [i(-3)]),
    ("sign(a)", F, [f("-0.0")]),
    ("clamp(a, b, c)", I, [i(5), i(10), i(1)]),
    ("clamp(a, b, c)", F, [f("0.5"), f("-1e308"), f("1e308")]),
    ("smoothstep(a, b, c)", F, [f("0.0"), f("2.0"), f("0.5")]),
    ("smoothstep(a, b, c)", F, [f("2.0"), f("0.0"), f("0.5")]),
    ("smoothstep(a, b, c)", F, [f("1.0"), f("1.0"), f("0.5")]),
    ("smoothstep(a, b, c)", F, [f("-1e308"), f("1e308"), f("0.0")]),
    ("min(a, b)", I, [i(9007199254740993), i(9007199254740992)]),
    ("max(a, b)", I, [i(9007199254740992), i(9007199254740993)]),
    ("min(a, b, c)", I, [INT_MIN, i(9223372036854775807), i(0)]),
    ("max(a, b)", F, [f("1e308"), f("-1e308")]),
    ("vec2(a, b)", V, [f("1e308"), f("-1e308")]),
    ("dot(a, b)", F, [v("1e200", "1e200"), v("1e200", "1e200")]),
    ("cross(a, b)", F, [v("1e200", "1e200"), v("1e200", "1e200")]),
    ("length(a)", F, [v("1e308", "1e308")]),
    ("length(a)", F, [v("3.0", "4.0")]),
    ("distance(a, b)", F, [v("-1e308", "0.0"), v("1e308", "0.0")]),
    ("normalize(a)", V, [v("0.0", "0.0")]),
    ("normalize(a)", V, [v("1e308", "1e308")]),
    ("perp_left(a)", V, [v("1.5", "-2.0")]),
    ("perp_right(a)", V, [v("1.5", "-2.0")]),
    ("rotate(a, b)", V, [v("1e308", "1e308"), f("0.7853981633974483")]),
    ("rotate(a, b, c)", V, [v("1.0", "0.0"), f("3.141592653589793"), v("-1e308", "0.0")]),
    ("angle(a)", F, [v("0.0", "0.0")]),
    ("angle(a, b)", F, [v("1e200", "1e200"), v("1e200", "-1e200")]),
    ("angle(a, b)", F, [v("1.0", "0.0"), v("0.0", "1.0")]),
    ("lerp(a, b, c)", F, [f("1e308"), f("-1e308"), f("0.5")]),
    ("lerp(a, b, c)", V, [v("0.0", "0.0"), v("2.0", "4.0"), f("0.25")]),
    ("int(a)", I, [f("1e19")]),
    ("int(a)", I, [f("-2.9")]),
    ("int(a)", I, [s("12x")]),
    ("int(a)", I, [s("-9223372036854775808")]),
    ("float(a)", F, [s("abc")]),
    ("float(a)", F, [s("1e400")]),
    ("float(a)", F, [s("0.1")]),
]
ATTR = {I: "ri", F: "rf", V: "rv"}
NODE = "node P { ri: int = 0; rf: float = 0; rv: vec2 = (0, 0); done: bool = false; }\n"


def substitute(call, values):
    return re.sub(r"\b([abc])\b", lambda m: values["abc".index(m.group(1))], call)


def run(args, cwd=work):
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True)


def outcome(result, json_path, attr):
    """('value', text) from the JSON, or ('error', the message without its place)."""
    if result.returncode == 0:
        node = json.load(open(json_path))["nodes"][0]
        return ("value", json.dumps(node[attr]))
    first = result.stderr.splitlines()[0] if result.stderr else ""
    m = re.match(r"^\S+:\d+:\d+: error: (.*?)(?: in constant `c`| \(in rule `\w+`, step \d+\)| \(before the first step\))?$", first)
    return ("error", m.group(1) if m else "unrecognised: " + first)


# One grammar with every case as a rule on parameters; -D which=K runs case K.
params, rules, defines = ["param which: int = -1;"], [], []
for k, (call, result, args) in enumerate(CASES):
    names = []
    for j, (t, _, text) in enumerate(args):
        names.append("p%d_%d" % (k, j))
        default = {I: "0", F: "0.0", V: "(0, 0)", S: '""'}[t]
        params.append("param %s: %s = %s;" % (names[-1], t, default))
    defines.append(["-D", "which=%d" % k] + sum([["-D", "%s=%s" % (n, a[2])] for n, a in zip(names, args)], []))
    rules.append("rule Case%d { match { n: P where which == %d and not n.done; } produce { n { %s = %s, done = true }; } }"
                 % (k, k, ATTR[result], substitute(call, names)))
runtime = os.path.join(work, "runtime.g2d")
with open(runtime, "w") as out:
    out.write("\n".join(params) + "\n" + NODE + "axiom { n: P at (0, 0); }\n" + "\n".join(rules) + "\n")
r = run([g2d, "check", runtime])
check(r.returncode == 0, "the runtime grammar: %s" % r.stderr)
r = run([g2d, "build", runtime, "-o", "runtime_program"])
check(r.returncode == 0, "g2d build: %s" % r.stderr)
if r.returncode != 0:
    finish()

errors = values = 0
for k, (call, result, args) in enumerate(CASES):
    attr = ATTR[result]
    shown = substitute(call, [a[1] for a in args])
    folded_src = os.path.join(work, "folded%d.g2d" % k)
    with open(folded_src, "w") as out:
        out.write(NODE + "const c = %s;\naxiom { n: P at (0, 0) { %s = c }; }\n" % (shown, attr))
    folded = outcome(run([g2d, "run", folded_src, "--no-svg", "--json", "f%d.json" % k]), os.path.join(work, "f%d.json" % k), attr)
    interp = outcome(run([g2d, "run", runtime, "--no-svg", "--json", "i%d.json" % k] + defines[k]), os.path.join(work, "i%d.json" % k), attr)
    comp = outcome(run([os.path.join(work, "runtime_program"), "--no-svg", "--json", "c%d.json" % k] + defines[k]),
                   os.path.join(work, "c%d.json" % k), attr)
    same = folded == interp == comp and not folded[1].startswith("unrecognised")
    check(same, "%s: folded %s, interpreted %s, compiled %s" % (shown, folded, interp, comp))
    if same:
        errors += folded[0] == "error"
        values += folded[0] == "value"
    print("%-60s %s %s" % (shown, folded[0], folded[1]))

# The cases must exercise both outcomes, or the table has drifted.
check(errors >= 20 and values >= 20, "%d errors and %d values agreed" % (errors, values))
finish()
