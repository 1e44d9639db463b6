#!/usr/bin/env python3
"""Writes random, valid .g2d grammars with faces for differential testing
(interpreter vs compiled): a grid of quads and triangles of two face kinds,
and rules drawn from face templates: faces with corners (any kind, wildcards)
or of any corner count, two faces sharing a side, faces in negative
conditions, conditions on face facts and attributes, kept, changed, deleted
and new faces, `for` loops over sides (with `prev`, `next`, and a face over
all turns: `all m`, `all m reversed`), moved corners, and random, oldest
and parallel picks.

usage: random_face_grammar.py SEED > grammar.g2d
"""
import random
import sys


def grammar(seed: int) -> str:
    r = random.Random(seed)
    out = []
    w = out.append
    w(f"// random face grammar {seed} (tests/gen/random_face_grammar.py)")
    w("node A { v: int = 0; }")
    w("node B { v: int = 0; }")
    w("edge E;")
    w('face F { v: int = 0; style { fill = v > 2 ? "#cc3333" : "#33cc33"; } }')
    w("face G { w: float = 1; }")
    cols, rows = r.randint(2, 4), r.randint(2, 3)
    kind = {}
    w("axiom {")
    for y in range(rows + 1):
        for x in range(cols + 1):
            kind[(x, y)] = r.choice("AB")
            w(f"    n{x}_{y}: {kind[(x, y)]} at ({x}, {y}) {{ v = {r.randint(0, 3)} }};")
    for y in range(rows):
        for x in range(cols):
            a, b, c, d = f"n{x}_{y}", f"n{x + 1}_{y}", f"n{x + 1}_{y + 1}", f"n{x}_{y + 1}"
            if r.random() < 0.3:   # two triangles
                w(f"    F({a}, {b}, {c}) {{ v = {r.randint(0, 3)} }};")
                w(f"    G({a}, {c}, {d});")
            elif r.random() < 0.5:
                w(f"    F({a}, {b}, {c}, {d}) {{ v = {r.randint(0, 3)} }};")
            else:
                w(f"    G({a}, {b}, {c}, {d}) {{ w = {r.uniform(0.5, 2):.2f} }};")
            if r.random() < 0.5:
                w(f"    {a} -[E]- {b};")
    w("}")
    w(f"limit {r.randint(20, 60)};")

    def corner():
        return r.choice(["A", "B", "*", "*"])

    def opts():
        o = []
        if r.random() < 0.4:
            o.append(f"priority {r.randint(0, 2)}")
        p = r.random()
        if p < 0.25:
            o.append("pick oldest")
        elif p < 0.45:
            o.append("parallel")
        return (" " + " ".join(o)) if o else ""

    templates = ["split", "fan", "neighbours", "drop", "nac", "move", "quads", "inset"]
    for i, t in enumerate(r.sample(templates, r.randint(3, 5))):
        if t == "split":
            k = r.choice("FG")
            cond = "f.v < 3" if k == "F" else "f.w < 3"
            attr = "v = f.v + 1" if k == "F" else "w = f.w + 1"
            w(f"rule R{i}{opts()} {{")
            w(f"    match {{ f: {k}(a, b, c, d) where {cond}; a: {corner()}; b: {corner()}; c: {corner()}; d: {corner()}; }}")
            w("    produce { m: A at f.centroid;"
              f" {k}(a, b, m) {{ {attr} }}; {k}(b, c, m) {{ {attr} }}; {k}(c, d, m) {{ {attr} }}; {k}(d, a, m) {{ {attr} }}; }}")
            w("}")
        elif t == "fan":
            w(f"rule R{i}{opts()} {{")
            w(f"    match {{ f: G where f.corners > 3 and f.area > {r.uniform(0.2, 0.8):.2f}; }}")
            w("    produce { c: B at f.centroid + (0.01, 0); for (u, v) in f.sides { F(u, v, c) { v = u.degree }; u -[E]- c; } }")
            w("}")
        elif t == "neighbours":
            w(f"rule R{i}{opts()} {{")
            w(f"    match {{ f: F(a, b, c) where f.v < 4; g: {r.choice('FG')}(b, a, d); a: *; b: *; c: {corner()}; d: *; }}")
            w("    produce { a; b; c; d; g; f { v = f.v + 1 }; }")
            w("}")
        elif t == "drop":
            w(f"rule R{i}{opts()} {{")
            w(f"    match {{ f: {r.choice('FG')} where f.area < {r.uniform(0.2, 0.6):.2f} and f.neighbours < {r.randint(1, 3)}; }}")
            w("    produce { }")
            w("}")
        elif t == "nac":
            w(f"rule R{i}{opts()} {{")
            w(f"    match {{ x: A where x.v < 3; not {{ g: F(x, y, z) where g.v > {r.randint(0, 2)}; y: *; z: *; }} }}")
            w("    produce { x { v = x.v + 1 }; }")
            w("}")
        elif t == "move":
            w(f"rule R{i}{opts()} {{")
            w("    match { x: B where x.v < 2 and x.faces > 0; }")
            w(f"    produce {{ x at x.pos + ({r.uniform(-0.2, 0.2):.2f}, {r.uniform(-0.2, 0.2):.2f}) {{ v = x.v + 1 }}; }}")
            w("}")
        elif t == "inset":   # a quad per side, and one face over all turns' inset corners
            ring = r.choice(["all m", "all m reversed", "all u reversed"])
            w(f"rule R{i}{opts()} {{")
            w(f"    match {{ f: G where f.w < 2 and f.area > {r.uniform(0.1, 0.5):.2f}; }}")
            w("    produce { for (u, v) in f.sides { m: B at lerp(u.pos, f.centroid, 0.3); F(u, v, next.m, m) { v = u.degree }; }"
              f" G({ring}) {{ w = f.w + 1 }}; }}")
            w("}")
        else:   # quads around the centroid, midpoints shared between neighbouring turns
            w(f"rule R{i}{opts()} {{")
            w("    match { f: G where f.corners == 3 and f.w < 2; }")
            w("    produce { c: A at f.centroid; for (u, v) in f.sides { m: B at (u.pos + v.pos) / 2; G(u, m, c, prev.m) { w = f.w + 1 }; } }")
            w("}")
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    sys.stdout.write(grammar(int(sys.argv[1])))
