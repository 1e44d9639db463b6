#!/usr/bin/env python3
"""`g2d run --trace-json` checked step by step on small grammars: the Koch
snowflake's first steps (a split: one edge deleted, three nodes and four
edges added), a production that moves a node and rewires an edge, one that
deletes a node with its edges, and a parallel step; compiled programs write
the same bytes; replaying the deltas gives the final graph of --json.

usage: trace_json_test.py G2D SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

g2d, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
work = tempfile.mkdtemp()
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from checks import check, finish  # noqa: E402


def run(args, cwd=work):
    r = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    check(r.returncode == 0, "%s: exit %d %s" % (" ".join(args), r.returncode, r.stderr))
    return r


def trace_of(grammar_text, name, *extra):
    path = os.path.join(work, name + ".g2d")
    with open(path, "w") as f:
        f.write(grammar_text)
    run([g2d, "run", path, "-o", name + ".svg", "--json", name + ".graph.json", "--trace-json", name + ".trace.json"] + list(extra))
    return json.load(open(os.path.join(work, name + ".trace.json"))), json.load(open(os.path.join(work, name + ".graph.json")))


def replay(t):
    nodes = {n[0]: n for n in t["axiom"]["nodes"]}
    edges = {e[0]: e for e in t["axiom"]["edges"]}
    for s in t["steps"]:
        for i in s["deleted"]["edges"]:
            del edges[i]
        for i in s["deleted"]["nodes"]:
            del nodes[i]
        for n in s["added"]["nodes"] + s["moved"]:
            nodes[n[0]] = n
        for e in s["added"]["edges"] + s["rewired"]:
            edges[e[0]] = e
    return nodes, edges


# 1. Koch snowflake, level 1: three splits.
koch_path = os.path.join(src, "examples", "koch_snowflake.g2d")
run([g2d, "run", koch_path, "-D", "max_lod=1", "--no-svg", "--json", "koch.graph.json", "--trace-json", "koch.trace.json"])
t = json.load(open(os.path.join(work, "koch.trace.json")))
check(t["format"] == "g2d-trace-1" and t["grammar"] == "koch_snowflake.g2d" and t["seed"] == 1 and t["stopped"] == "terminal",
      "header: %s" % {k: t[k] for k in ("format", "grammar", "seed", "stopped")})
check([k["name"] for k in t["kinds"]] == ["Point", "Seg"] and t["kinds"][1]["edge"] and t["kinds"][1]["directed"], "kinds: %s" % t["kinds"])
check(t["kinds"][0]["style"]["tag"] == "none" and t["kinds"][1]["style"]["stroke_width"] == 0.1, "kind styles: %s" % t["kinds"])
check(t["axiom"] == {"nodes": [[0, 0, -4, 0], [1, 0, 0, 6.93], [2, 0, 4, 0]], "edges": [[0, 1, 0, 1], [1, 1, 1, 2], [2, 1, 2, 0]]},
      "axiom: %s" % t["axiom"])
check(len(t["steps"]) == 3 and [s["step"] for s in t["steps"]] == [1, 2, 3], "three steps")
s1 = t["steps"][0]
# Oldest first, seed 1: the edge c -> a (id 2) splits first: P = (4, 0), Q = (-4, 0).
check(s1["rule"] == "Split" and s1["daughters"] == [0], "step 1 rule: %s" % s1)
check(s1["matched"] == {"nodes": [0, 2], "edges": [2]}, "step 1 matched: %s" % s1["matched"])
check(s1["deleted"] == {"nodes": [], "edges": [2]}, "step 1 deleted: %s" % s1["deleted"])
added = s1["added"]
check([n[0] for n in added["nodes"]] == [3, 4, 5] and all(n[1] == 0 for n in added["nodes"]), "step 1 added nodes: %s" % added)
check(abs(added["nodes"][0][2] - 4 / 3) < 1e-12 and added["nodes"][0][3] == 0, "p = c + v/3: %s" % added["nodes"][0])
check(added["edges"] == [[3, 1, 2, 3], [4, 1, 3, 4], [5, 1, 4, 5], [6, 1, 5, 0]], "step 1 added edges: %s" % added["edges"])
check(s1["moved"] == [] and s1["rewired"] == [], "step 1 moves nothing")
nodes, edges = replay(t)
g = json.load(open(os.path.join(work, "koch.graph.json")))
check(sorted(nodes) == sorted(n["id"] for n in g["nodes"]) and len(edges) == len(g["links"]) == 12,
      "replaying the trace gives the final graph (%d nodes, %d edges)" % (len(nodes), len(edges)))

# 2. Moving a node and rewiring an edge.
t, g = trace_of("""node P;
edge E directed;
axiom { a: P at (0, 0); b: P at (1, 0); a -[E]-> b; }
limit 2;
rule Flip { match { a: P; b: P; e: a -[E]-> b; } produce { a at a.pos + (0, 1); b; e: b -[E]-> a; } }
""", "flip")
s1, s2 = t["steps"]
check(s1["moved"] == [[0, 0, 0, 1]] and s1["rewired"] == [[0, 1, 1, 0]] and s1["deleted"] == {"nodes": [], "edges": []}
      and s1["added"] == {"nodes": [], "edges": []}, "step 1 of Flip: %s" % s1)
check(s2["matched"] == {"nodes": [0, 1], "edges": [0]} and s2["moved"] == [[1, 0, 1, 1]] and s2["rewired"] == [[0, 1, 0, 1]],
      "step 2 of Flip: %s" % s2)

# 3. Deleting a node with its edges.
t, g = trace_of("""node P;
node Q;
edge E;
axiom { a: P at (0, 0); b: Q at (1, 0); c: Q at (2, 0); a -[E]- b; a -[E]- c; b -[E]- c; }
rule Remove { match { a: P; } produce { } }
""", "remove")
check(len(t["steps"]) == 1 and t["steps"][0]["deleted"] == {"nodes": [0], "edges": [0, 1]} and t["steps"][0]["matched"] == {"nodes": [0], "edges": []},
      "deleting a node deletes its edges: %s" % t["steps"])
nodes, edges = replay(t)
check(sorted(nodes) == [1, 2] and sorted(edges) == [2], "after Remove: %s %s" % (nodes, edges))

# 4. A parallel step: every match at once, one daughter per rewrite.
t, g = trace_of("""node P;
node Q;
axiom { a: P at (0, 0); b: P at (1, 0); c: P at (2, 0); }
rule Grow parallel { match { p: P; } produce { q: Q at p.pos + (0, 1); } }
""", "parallel")
check(len(t["steps"]) == 1 and t["steps"][0]["daughters"] == [0, 0, 0] and t["steps"][0]["deleted"]["nodes"] == [0, 1, 2]
      and len(t["steps"][0]["added"]["nodes"]) == 3, "parallel step: %s" % t["steps"])

# 4b. Each step names the rule applied, not the one whose code ran last: after
# First's step, match repair runs Second's search before the step is recorded.
priorities = """node A; node B; node C;
axiom { a: A; }
rule First priority 0 { match { x: A; } produce { y: B at (1, 0); } }
rule Second priority 1 { match { x: B; } produce { z: C at (2, 0); } }
"""
t, g = trace_of(priorities, "priorities")
check([s["rule"] for s in t["steps"]] == ["First", "Second"], "rules named in the trace: %s" % [s["rule"] for s in t["steps"]])
run([g2d, "build", os.path.join(work, "priorities.g2d"), "-o", "priorities_program"])
run([os.path.join(work, "priorities_program"), "--no-svg", "--trace-json", "priorities.compiled.json"])
check(open(os.path.join(work, "priorities.compiled.json")).read() == open(os.path.join(work, "priorities.trace.json")).read(),
      "compiled and interpreted traces of priorities.g2d differ")

# 4c. A 3D grammar keeps z (#47): nodes [id, kind, x, y, z]; a move in z
# alone is a move; faces carry their triangles as node ids; replaying gives
# the final positions of --json; compiled programs write the same.
lift = """space 3d;
node P;
edge E;
face F;
axiom { a: P at (0, 0, 0); b: P at (1, 0, 0); c: P at (1, 1, 0); d: P at (0, 1, 0);
        a -[E]- b; b -[E]- c; c -[E]- d; d -[E]- a; F(a, b, c, d); }
limit 1;
rule Lift { match { p: P where p.pos.x == 1 and p.pos.y == 1; } produce { p at p.pos + (0, 0, 2); } }
"""
t, g = trace_of(lift, "lift")
check(t.get("space") == "3d", "3D trace header: %s" % {k: v for k, v in t.items() if k not in ("axiom", "steps", "kinds")})
check(t["axiom"]["nodes"] == [[0, 0, 0, 0, 0], [1, 0, 1, 0, 0], [2, 0, 1, 1, 0], [3, 0, 0, 1, 0]], "3D axiom nodes: %s" % t["axiom"]["nodes"])
face = t["axiom"]["faces"][0]
check(face[:3] == [0, 2, [0, 1, 2, 3]] and len(face[3]) == 6 and sorted(set(face[3])) == [0, 1, 2, 3],
      "a 3D face with its two triangles: %s" % face)
check(len(t["steps"]) == 1 and t["steps"][0]["moved"] == [[2, 0, 1, 1, 2]], "a move in z: %s" % t["steps"])
nodes, edges = replay(t)
check({i: n[2:] for i, n in nodes.items()} == {n["id"]: n["pos"] for n in g["nodes"]}, "replayed 3D positions: %s" % nodes)
run([g2d, "build", os.path.join(work, "lift.g2d"), "-o", "lift_program"])
run([os.path.join(work, "lift_program"), "--no-svg", "--trace-json", "lift.compiled.json"])
check(open(os.path.join(work, "lift.compiled.json")).read() == open(os.path.join(work, "lift.trace.json")).read(),
      "compiled and interpreted 3D traces differ")

# 4d. Faces that keep their id but gain corners (the house's walls, as
# `insert … between` puts nodes on their sides) are deleted and added again:
# replaying the faces gives those of --json.
run([g2d, "run", os.path.join(src, "examples", "g3_house.g2d"), "--no-svg", "--quiet", "--json", "house.json", "--trace-json", "house.trace.json"])
t, g = json.load(open(os.path.join(work, "house.trace.json"))), json.load(open(os.path.join(work, "house.json")))
faces = {f[0]: f[2] for f in t["axiom"]["faces"]}
for s in t["steps"]:
    for i in s["deleted"]["faces"]:
        del faces[i]
    for f in s["added"]["faces"]:
        faces[f[0]] = f[2]
check(faces == {f["id"]: f["corners"] for f in g["faces"]}, "replaying the house's faces gives its final faces")

# 5. Compiled programs write the same trace, and --trace writes a page holding it.
run([g2d, "build", koch_path, "-o", "koch_program"])
run([os.path.join(work, "koch_program"), "-D", "max_lod=1", "--no-svg", "--trace-json", "koch.compiled.json", "--trace", "koch.html"])
check(open(os.path.join(work, "koch.compiled.json")).read() == open(os.path.join(work, "koch.trace.json")).read(),
      "compiled and interpreted traces differ")
page = open(os.path.join(work, "koch.html")).read()
check(page.startswith("<!DOCTYPE html>") and '<script id="trace" type="application/json">{"format":"g2d-trace-1"' in page
      and "<svg" in page and "http" not in page.replace("http://www.w3.org/", ""), "the page is self-contained and holds the trace")

finish()
