#!/usr/bin/env python3
"""What a screenshot shows, for view_page_test.sh: how many pixels of a PNG
are near each of the given CSS colours. A lit face keeps its hue but not its
brightness, so a pixel counts for a colour when it is that colour scaled by
some shade k in [0.55, 1.25], within `tolerance` per channel. Reads the PNG
with zlib alone (PIL is not a dependency).

usage: png_colors.py FILE.png COLOR...   (COLOR: #rrggbb or hsl(h, s%, l%))
prints JSON: {"width", "height", "counts": {COLOR: pixels}, "matched": pixels near
any COLOR, "background": white pixels}
"""
import collections
import colorsys
import json
import re
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and ctype in (2, 6) and interlace == 0, "only 8-bit RGB(A), not interlaced"
            channels = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride = zlib.decompress(idat), width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    pixels = [tuple(r[x * channels:x * channels + 3]) for r in rows for x in range(width)]
    return width, height, pixels


def parse_color(css):
    m = re.fullmatch(r"#([0-9a-fA-F]{6})", css)
    if m:
        return tuple(int(m.group(1)[i:i + 2], 16) for i in (0, 2, 4))
    m = re.fullmatch(r"hsl\(\s*([\d.]+)\s*,\s*([\d.]+)%\s*,\s*([\d.]+)%\s*\)", css)
    if m:
        h, s, l = (float(v) for v in m.groups())
        r, g, b = colorsys.hls_to_rgb(h / 360 % 1, l / 100, s / 100)
        return tuple(round(v * 255) for v in (r, g, b))
    raise ValueError("colour not understood: " + css)


def near(pixel, color, tolerance=14):
    # The least-squares shade, then the worst channel's distance.
    k = sum(p * c for p, c in zip(pixel, color)) / max(1, sum(c * c for c in color))
    return 0.55 <= k <= 1.25 and max(abs(p - k * c) for p, c in zip(pixel, color)) <= tolerance


def main():
    width, height, pixels = read_png(sys.argv[1])
    colors = {css: parse_color(css) for css in sys.argv[2:]}
    counts, matched = {css: 0 for css in colors}, 0
    for p, n in collections.Counter(pixels).items():
        hits = [css for css, c in colors.items() if near(p, c)]
        for css in hits:
            counts[css] += n
        matched += n if hits else 0
    background = sum(n for p, n in collections.Counter(pixels).items() if p == (255, 255, 255))
    print(json.dumps({"width": width, "height": height, "counts": counts, "matched": matched, "background": background}))


main()
