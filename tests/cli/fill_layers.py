#!/usr/bin/env python3
"""Checks the layering of filled rectangles in a g2d SVG, as the thesis tool
drew them (each part over the parts made before it): every <rect> comes after
the <line>s along its border (its outline) and before the <line>s inside it
(e.g. a blind's outline drawn over the window's glass).

Usage: fill_layers.py SVG MIN_OUTLINED MIN_COVERED
MIN_OUTLINED: how many rects must have an outline; MIN_COVERED: how many must
have lines inside them (so that the check cannot pass on an empty picture).
Prints the first misplaced element and exits 1 when the order is wrong."""
import sys
import xml.etree.ElementTree as ET

EPS = 1e-6


def on_side(p, lo, hi, axis, at):
    """p lies on the rect's side at coordinate `at` of `axis`, within [lo, hi]."""
    other = 1 - axis
    return abs(p[axis] - at) < EPS and lo[other] - EPS <= p[other] <= hi[other] + EPS


def main():
    svg, min_outlined, min_covered = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    items = []   # ("rect", lo, hi, fill) or ("line", p, q)
    for el in ET.parse(svg).getroot().iter():
        tag = el.tag.rsplit('}', 1)[-1]
        if tag == 'rect':
            x, y = float(el.get('x')), float(el.get('y'))
            w, h = float(el.get('width')), float(el.get('height'))
            items.append(('rect', (x, y), (x + w, y + h), el.get('fill')))
        elif tag == 'line':
            items.append(('line', (float(el.get('x1')), float(el.get('y1'))),
                          (float(el.get('x2')), float(el.get('y2')))))
    outlined = covered = 0
    for i, item in enumerate(items):
        if item[0] != 'rect':
            continue
        _, lo, hi, fill = item
        border = inside = False
        for j, other in enumerate(items):
            if other[0] != 'line':
                continue
            p, q = other[1], other[2]
            sides = [(a, at) for a in (0, 1) for at in (lo[a], hi[a])]
            if any(on_side(p, lo, hi, a, at) and on_side(q, lo, hi, a, at) for a, at in sides):
                border = True
                if j > i:
                    sys.exit(f'{svg}: rect {fill} at {lo} is drawn before its outline line {p}-{q}')
            elif all(lo[a] - EPS <= r[a] <= hi[a] + EPS for r in (p, q) for a in (0, 1)):
                inside = True
                if j < i:
                    sys.exit(f'{svg}: line {p}-{q} inside rect {fill} at {lo} is drawn under it')
        outlined += border
        covered += inside
    if outlined < min_outlined or covered < min_covered:
        sys.exit(f'{svg}: {outlined} outlined rects (wanted {min_outlined}), '
                 f'{covered} with lines inside (wanted {min_covered})')


if __name__ == '__main__':
    main()
