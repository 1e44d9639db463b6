#!/usr/bin/env python3
"""Writes brush.png: one soft, grey-scale brush stroke on a transparent
background, for examples/tree_painting.g2d (thesis §7.3, Fig. 7.17).

The stroke runs along the image's x axis (the grammar stretches the image
along a branch and rotates it), thick and dense where the brush lands on the
left and thinning into dry, broken bristle streaks towards the right. Only the
alpha channel matters once the grammar's feColorMatrix filters recolour it.

Standard library only (zlib + struct); deterministic (fixed seed).
Usage: python3 make_brush.py [OUTPUT]   (default: brush.png next to this file)
"""
import math
import os
import random
import struct
import sys
import zlib

W, H = 192, 48
rng = random.Random(2019)


def smooth_noise(n, scale, rng):
    """1-D value noise of length n: random knots every `scale` samples,
    cosine-interpolated."""
    knots = [rng.random() for _ in range(n // scale + 3)]
    out = []
    for i in range(n):
        k, f = divmod(i / scale, 1.0)
        k = int(k)
        t = (1 - math.cos(math.pi * f)) / 2
        out.append(knots[k] * (1 - t) + knots[k + 1] * t)
    return out


# Per-row bristle properties: density (how much paint the bristle carries)
# and where along the stroke it runs dry.
density = [0.6 + 0.4 * v for v in smooth_noise(H, 3, rng)]
fine = [rng.random() for _ in range(H)]
dry_at = [0.8 + 0.19 * v for v in smooth_noise(H, 2, rng)]
# Slight wobble of the stroke's centre line and of its edges along x.
wobble = smooth_noise(W, 40, rng)
edge_noise = smooth_noise(W, 9, rng)


def half_thickness(t):
    """Half the stroke's thickness (in rows) at t in [0, 1] along it: a
    rounded landing on the left, a body that narrows a little towards the
    right, where the bristles run dry."""
    head = min(1.0, t / 0.06) ** 0.5
    body = 1 - 0.3 * t
    return (H / 2 - 1.5) * head * body * (0.93 + 0.07 * edge_noise[int(t * (W - 1))])


def pixel(x, y):
    t = (x + 0.5) / W
    centre = H / 2 + (wobble[x] - 0.5) * 2
    ht = half_thickness(t)
    if ht <= 0:
        return 0, 0
    d = abs(y + 0.5 - centre) / ht          # 0 on the centre line, 1 at the edge
    if d >= 1:
        return 0, 0
    edge = 1 - d ** 6                       # soft, slightly rounded edge
    row = density[y] * (0.8 + 0.2 * fine[y])
    # Dry brush: each bristle runs out of paint somewhere in the last fifth.
    dry = 1.0
    if t > dry_at[y]:
        dry = max(0.0, 1 - (t - dry_at[y]) / 0.08)
    alpha = 1.2 * edge * row ** 1.5 * dry
    grey = 0.25 + 0.5 * (1 - row) + 0.1 * fine[y]   # darker where more paint
    return int(255 * min(1.0, grey)), int(255 * max(0.0, min(1.0, alpha)))


def png(width, height, rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + bytes(r) for r in rows)    # filter type 0 per row
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 4, 0, 0, 0)   # 8-bit grey + alpha
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


rows = []
for y in range(H):
    r = []
    for x in range(W):
        g, a = pixel(x, y)
        r += [g, a]
    rows.append(r)

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "brush.png")
with open(out, "wb") as f:
    f.write(png(W, H, rows))
print(out, os.path.getsize(out), "bytes")
