"""Shared by the Python checks of 3D meshes in the CLI tests (node-link JSON
with "faces"): a closed, consistently oriented surface."""
from collections import Counter


def oriented_sides(faces):
    """Counts each face side (a, b); asserts every face has 3 or more
    distinct corners and every side is run once each way (closed, and
    consistently oriented). Returns the counts."""
    sides = Counter()
    for f in faces:
        c = f["corners"]
        assert len(set(c)) == len(c) >= 3, c
        for i in range(len(c)):
            sides[(c[i], c[(i + 1) % len(c)])] += 1
    assert max(sides.values()) == 1, "a side run twice the same way"
    assert all((b, a) in sides for (a, b) in sides), "a side with a face on one side only"
    return sides
