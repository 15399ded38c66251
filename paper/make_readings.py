#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes paper/readings/*.poly: other plausible readings of Circles240 and
Rectangle162, whose exact geometry the paper does not give (Fig. 9 only shows
them). `lepp paper` runs Triangle and Lepp-centroid on each and reports which
reading comes closest to the paper's Table 1. corpus/paper/ holds the reading
chosen first (see corpus/paper/README.md); these are the alternatives.

    /usr/bin/python3 paper/make_readings.py      # rewrites paper/readings/

File names are PROBLEM-WHAT.poly; the first line says what the reading is.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "readings")


def write_poly(name, comment, loops, holes):
    """loops: closed polygons (lists of (x, y)); each becomes a cycle of segments."""
    points, segments = [], []
    for loop in loops:
        first = len(points)
        for i, p in enumerate(loop):
            points.append(p)
            segments.append((first + i, first + (i + 1) % len(loop)))
    lines = [f"# {comment}", f"{len(points)} 2 0 1"]
    lines += [f"{i + 1} {x!r} {y!r} 1" for i, (x, y) in enumerate(points)]
    lines.append(f"{len(segments)} 1")
    lines += [f"{i + 1} {a + 1} {b + 1} 1" for i, (a, b) in enumerate(segments)]
    lines.append(f"{len(holes)}")
    lines += [f"{i + 1} {x!r} {y!r}" for i, (x, y) in enumerate(holes)]
    with open(os.path.join(OUT, name + ".poly"), "w") as f:
        f.write("\n".join(lines) + "\n")


def circle(cx, cy, r, n, clockwise=False, phase=0.0):
    s = -1 if clockwise else 1
    return [(cx + r * math.cos(s * (2 * math.pi * i / n + phase)), cy + r * math.sin(s * (2 * math.pi * i / n + phase)))
            for i in range(n)]


def circles(name, comment, outer_n=120, inner_n=120, r=0.2, gap=0.15, scale=1.0, phase=0.0):
    cx = 1.0 - gap - r
    outer = [(scale * x, scale * y) for x, y in circle(0, 0, 1.0, outer_n)]
    inner = [(scale * x, scale * y) for x, y in circle(cx, 0, r, inner_n, clockwise=True, phase=phase)]
    write_poly(name, comment, [outer, inner], [(scale * cx, 0.0)])


def rectangle(name, comment, bottom, top, width=2.0, height=1.0):
    """bottom, top: functions of t in [0, 1] giving x / width, increasing; 81 points per long side."""
    n = 80
    lower = [(width * bottom(i / n), 0.0) for i in range(n + 1)]
    upper = [(width * top(i / n), height) for i in range(n + 1)]
    upper.reverse()  # counter-clockwise: along the top from right to left
    write_poly(name, comment, [lower + upper], [])


def main():
    os.makedirs(OUT, exist_ok=True)
    circles("circles240-gap005", "Circles240: hole r=0.2 at gap 0.05 from the outer circle, 120 + 120 points", gap=0.05)
    circles("circles240-gap010", "Circles240: hole r=0.2 at gap 0.10, 120 + 120 points", gap=0.10)
    circles("circles240-gap020", "Circles240: hole r=0.2 at gap 0.20, 120 + 120 points", gap=0.20)
    circles("circles240-r030", "Circles240: hole r=0.3 at gap 0.15, 120 + 120 points", r=0.3)
    circles("circles240-160-80", "Circles240: 160 outer + 80 hole points (equal counts per length closer), r=0.2, gap 0.15",
            outer_n=160, inner_n=80)
    circles("circles240-scale100", "Circles240: the corpus reading scaled by 100", scale=100.0)
    rectangle("rect162-uniform", "Rectangle162: [0,2]x[0,1], 81 evenly spaced points on each long side",
              lambda t: t, lambda t: t)
    rectangle("rect162-same", "Rectangle162: both long sides clustered the same way, x = 2(1-(1-t)^3)",
              lambda t: 1 - (1 - t) ** 3, lambda t: 1 - (1 - t) ** 3)
    rectangle("rect162-opposite", "Rectangle162: bottom clustered right x = 2(1-(1-t)^3), top clustered left x = 2t^3",
              lambda t: 1 - (1 - t) ** 3, lambda t: t ** 3)
    rectangle("rect162-quadratic", "Rectangle162: bottom x = 2(1-(1-t)^2), top x = 2t^2 (mismatched, milder)",
              lambda t: 1 - (1 - t) ** 2, lambda t: t ** 2)
    rectangle("rect162-scale100", "Rectangle162: the corpus reading scaled by 100, [0,200]x[0,100]",
              lambda t: 1 - (1 - t) ** 3, lambda t: 1 - (1 - t) ** 2, width=200.0, height=100.0)


if __name__ == "__main__":
    main()
