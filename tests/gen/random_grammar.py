#!/usr/bin/env python3
"""Writes random, valid .g2d grammars for differential testing (interpreter vs
compiled). Each uses a broad mix of the language: node and edge kinds with
int/float/bool/string/enum attributes, directed and undirected edges, params,
random constants, functions, conditions, negative conditions, wildcards,
lets, weighted daughters, kept/deleted/new/rewired elements, explicit and
automatic placement, `placed`, styles, priorities, limits (global, a
priority's, a rule's), oldest/random and parallel rules.

usage: random_grammar.py SEED > grammar.g2d
"""
import random
import sys


def grammar(seed: int) -> str:
    r = random.Random(seed)
    # Near conditions (a node near a point: the spatial index) come from a
    # generator of their own, so the rest of each grammar stays as it was.
    near = random.Random(seed * 7919 + 1)
    out = []
    w = out.append
    w(f"// random grammar {seed} (tests/gen/random_grammar.py)")
    w("enum Color { Red, Green, Blue }")
    w(f"param p: int = {r.randint(1, 4)};")
    w(f"param q: float = {r.uniform(0.5, 2):.3f};")
    w("const wobble = uniform(-0.5, 0.5);")
    w("fn twice(x: float) -> float = 2 * x + wobble;")
    w("fn near(a: vec2, b: vec2) -> bool = distance(a, b) < 50;")

    node_kinds = []
    for k in range(r.randint(1, 3)):
        name = f"N{k}"
        attrs = [("i", "int", "0"), ("f", "float", "1.5")]
        if r.random() < 0.5:
            attrs.append(("c", "Color", "Red"))
        if r.random() < 0.5:
            attrs.append(("s", "string", '"x"'))
        if r.random() < 0.5:
            attrs.append(("b", "bool", "false"))
        node_kinds.append((name, attrs))
        body = " ".join(f"{a}: {t} = {d};" for a, t, d in attrs)
        style = r.choice(['style { r = 0.05 + f / 20; fill = "none"; }',
                          'style { tag = "rect"; width = 0.2; height = 0.1; }',
                          'style { tag = "none"; }', ''])
        w(f"node {name} {{ {body} {style} }}")
    edge_kinds = []
    for k in range(r.randint(1, 3)):
        name = f"E{k}"
        directed = r.random() < 0.6
        edge_kinds.append((name, directed))
        w(f"edge {name} {'directed' if directed else 'undirected'} {{ n: int = 0; style {{ stroke_width = 0.02 + n / 100; }} }}")

    def arrow(kind):
        return f"-[{kind[0]}]->" if kind[1] else f"-[{kind[0]}]-"

    # Axiom
    w("axiom {")
    names = []
    for i in range(r.randint(3, 6)):
        kind = r.choice(node_kinds)
        names.append((f"v{i}", kind))
        w(f"    v{i}: {kind[0]} at ({r.uniform(-5, 5):.3f}, {r.uniform(-5, 5):.3f}) {{ i = {r.randint(0, 5)} }};")
    for i in range(r.randint(3, 8)):
        a, b = r.choice(names), r.choice(names)
        w(f"    v_{i}: {a[0]} {arrow(r.choice(edge_kinds))} {b[0]};".replace("v_", "x_"))
    w("}")
    w(f"limit {r.randint(20, 60)};")
    if r.random() < 0.5:
        w(f"priority 1 limit {r.randint(3, 10)};")
    # Parallel rules rewrite every match at once: a few such steps only, or
    # the graph doubles each step and the run ends at the element bound.
    w("priority 3 limit 4;")

    for ri in range(r.randint(2, 5)):
        opts = [f"priority {r.randint(0, 2)}"]
        if r.random() < 0.3:
            opts.append("pick oldest")
        parallel = r.random() < 0.2
        if parallel:
            opts[0] = "priority 3"
            opts.append("parallel")
        sketched = r.random() < 0.5
        ordered = sketched and r.random() < 0.3
        if ordered:
            opts.append("ordered")
        # A rule's own limit, drawn apart so that the rest of the grammar is
        # what it was before rule limits existed.
        if random.Random(seed * 7919 + ri).random() < 0.25:
            opts.append(f"limit {random.Random(seed * 104729 + ri).randint(1, 4)}")
        size = r.randint(1, 3)
        mnodes = []
        for i in range(size):
            kind = r.choice(node_kinds)
            mnodes.append((f"m{i}", kind))
        lines = []
        for i, (n, kind) in enumerate(mnodes):
            sk = f" @ ({i * 2}, {r.choice([0, 1])})" if sketched else ""
            cond = f" where {n}.i < {r.randint(3, 9)}" if r.random() < 0.6 else ""
            lines.append(f"{n}: {kind[0]}{sk}{cond};")
        medges = []
        for i in range(size - 1):
            kind = r.choice(edge_kinds)
            en = f"e{i}"
            medges.append((en, kind, mnodes[i][0], mnodes[i + 1][0]))
            lines.append(f"{en}: {mnodes[i][0]} {arrow(kind)} {mnodes[i + 1][0]};")
        wildcard = size >= 1 and r.random() < 0.3
        if wildcard:
            lines.append("w: *" + (" @ (9, 9)" if sketched else "") + ";")
            kind = r.choice(edge_kinds)
            lines.append(f"ew: {mnodes[0][0]} {arrow(kind)} w;")
        if size >= 2 and r.random() < 0.5:
            lines.append(f"where {mnodes[0][0]}.f <= {mnodes[1][0]}.f + q;")
        if r.random() < 0.3:
            kind = r.choice(edge_kinds)
            lines.append(f"not {{ z: {r.choice(node_kinds)[0]}; {mnodes[0][0]} {arrow(kind)} z; }}")
        if near.random() < 0.3:
            o_kind = near.choice(node_kinds)[0]
            attr = near.choice(["", f" where o.i > {near.randint(1, 8)}"])
            centre = f"{mnodes[-1][0]}.pos + ({near.choice([0, 0.5, -1])}, {near.choice([0, 1])})"
            test = near.choice([f"distance(o.pos, {centre}) < {near.choice(['0.8', '2', 'q + 1'])}",
                                f"{near.choice(['1.5', '3'])} >= distance({centre}, o.pos)"])
            lines.append(f"not {{ o: {o_kind}{attr}; where {test}; }}")
        w(f"rule R{ri} {' '.join(opts)} {{")
        w("    match { " + " ".join(lines) + " }")
        w(f"    let v = {mnodes[-1][0]}.pos - {mnodes[0][0]}.pos;")
        w(f"    let jitter = (uniform(-1, 1), normal(0, 0.2));")
        w(f"    let tag = choice(\"a\", \"b\", \"c\");")
        ndaughters = r.randint(1, 2)
        for d in range(ndaughters):
            weight = f" weight {r.choice(['1', '2.5', 'p', '3'])}" if ndaughters > 1 else ""
            body = []
            kept = [n for n in mnodes if r.random() < 0.7] or [mnodes[0]]
            for n, kind in kept:
                assign = r.choice([
                    f" {{ i = ({n}.i + randint(0, 3)) % 11 }}",
                    f" {{ f = twice({n}.f) / 3 }}",
                    f" at {n}.pos + jitter * 0.1",
                    "",
                ])
                body.append(f"{n}{assign};")
            kept_edges = set()
            for en, kind, a, b in medges:
                if any(a == k[0] for k in kept) and any(b == k[0] for k in kept) and r.random() < 0.6:
                    body.append(f"{en} {{ n = {en}.n + 1 }};")
                    kept_edges.add(en)
            for j in range(r.randint(0, 2)):
                kind = r.choice(node_kinds)
                if sketched and r.random() < 0.5:
                    pos = f" @ ({r.randint(-2, 4)}, {r.randint(-2, 2)})"
                    if r.random() < 0.3:
                        pos += " at placed + (0.1, 0)"
                else:
                    pos = f" at {kept[0][0]}.pos + v * {r.uniform(0.1, 0.9):.2f} + jitter"
                attrs = [f"i = {r.randint(0, 4)}", "f = uniform(0, q)"]
                if any(a[0] == "s" for a in kind[1]):
                    attrs.append('s = format("{} {:.2} {}", tag, random(), p)')
                if any(a[0] == "c" for a in kind[1]):
                    attrs.append("c = choice(Red, Green, Blue)")
                body.append(f"n{j}: {kind[0]}{pos} {{ {', '.join(attrs)}, style.opacity = random() }};")
                ek = r.choice(edge_kinds)
                body.append(f"{kept[0][0]} {arrow(ek)} n{j};")
            if len(medges) > 0 and medges[0][0] not in kept_edges and r.random() < 0.3:
                en, kind, a, b = medges[0]
                body.append(f"{en}: {kept[0][0]} {arrow(kind)} {kept[-1][0]};")   # rewire
            w(f"    produce{weight} {{ " + " ".join(body) + " }")
        w("}")
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    sys.stdout.write(grammar(int(sys.argv[1])))
