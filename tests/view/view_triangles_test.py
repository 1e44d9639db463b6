#!/usr/bin/env python3
"""The --view page draws each face with the triangles g2d found in its plane
(issue #47): for every face of examples/g3_sofa.g2d in the page's model, the
triangles' areas add up to the polygon's area, computed here independently
with Newell's formula from the face's 3D corners as --json gives them, and
every triangle runs the face's way round (its normal along the face's). A
fan from the first corner, as the page drew before, fails both on the
sofa's non-convex faces.

usage: view_triangles_test.py G2D SOURCE_DIR
"""
import json
import os
import re
import subprocess
import sys
import tempfile

g2d, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
work = tempfile.mkdtemp()
sys.path.insert(0, os.path.join(src, "tests", "pylib"))
from checks import check, finish  # noqa: E402


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def newell(ring):
    """Twice the polygon's vector area: its length is twice the area."""
    n = [0.0, 0.0, 0.0]
    for i, a in enumerate(ring):
        b = ring[(i + 1) % len(ring)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return n


r = subprocess.run([g2d, "run", os.path.join(src, "examples", "g3_sofa.g2d"), "--no-svg", "--json", "sofa.json",
                    "--view", "sofa.html"], cwd=work, capture_output=True, text=True)
check(r.returncode == 0, "g3_sofa --view: exit %d %s" % (r.returncode, r.stderr))
if r.returncode != 0:
    finish()
graph = json.load(open(os.path.join(work, "sofa.json")))
page = open(os.path.join(work, "sofa.html")).read()
model = json.loads(re.search(r'<script id="g2d-model" type="application/json">(.*?)</script>', page, re.S).group(1))
pos = {n["id"]: n["pos"] for n in graph["nodes"]}
corners = {f["id"]: f["corners"] for f in graph["faces"]}

check(len(model["faces"]) == len(corners) == 3776, "faces: %d in the page, %d in the graph" % (len(model["faces"]), len(corners)))
bad_area, bad_turn, non_convex, triangles = [], [], 0, 0
for face_id, _, points, tris in model["faces"]:
    ring = [pos[c] for c in corners[face_id]]
    normal = newell(ring)
    area = (dot(normal, normal) ** 0.5) / 2
    # Non-convex: some corner turns against the face's normal.
    non_convex += any(dot(cross(sub(ring[i], ring[i - 1]), sub(ring[(i + 1) % len(ring)], ring[i])), normal) < -1e-12
                      for i in range(len(ring)))
    p = [points[3 * i:3 * i + 3] for i in range(len(points) // 3)]
    covered = 0.0
    for k in range(0, len(tris), 3):
        n = cross(sub(p[tris[k + 1]], p[tris[k]]), sub(p[tris[k + 2]], p[tris[k]]))
        covered += (dot(n, n) ** 0.5) / 2
        if dot(n, normal) <= 0:
            bad_turn.append(face_id)
        triangles += 1
    if abs(covered - area) > 1e-9 * max(area, 1e-9) + 1e-12:
        bad_area.append((face_id, covered, area))
print("sofa: %d faces (%d non-convex), %d triangles" % (len(model["faces"]), non_convex, triangles))
check(non_convex > 1000, "the sofa should have many non-convex faces (%d)" % non_convex)
check(not bad_area, "%d faces whose triangles do not cover their area, e.g. %s" % (len(bad_area), bad_area[:3]))
check(not bad_turn, "%d faces with a triangle turned against the face, e.g. %s" % (len(set(bad_turn)), sorted(set(bad_turn))[:5]))
finish()
