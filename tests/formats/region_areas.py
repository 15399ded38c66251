#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Region area bounds through the CLI: `lepp refine --region-areas` against
Triangle's `-pq30a` (the -a switch with no number) on the .poly files with
regions in corpus/triangle-formats/.

Each mesh is checked here from its own files (.node, .ele, .poly) alone: the
region of every triangle is found by flooding from the region points, in file
order, across edges that are not segments (later regions overwrite earlier
ones, Triangle's order; a point on a segment, on a vertex or outside every
triangle sets nothing), and every triangle must have an area at most its
region's bound, exactly (rational arithmetic on the doubles). Triangle computes
areas in floating point, so its triangles get a relative slack of 1e-12.

Also: the fast and reference engines write the same mesh; lepp's mesh
certifies with `lepp certify --region-areas` (the certifier's own flood and
exact areas), as Triangle's does, and the mesh made without the bounds does not; --json counts the triangles refined for area; without
--region-areas, lepp warns naming the option and its mesh fails the check (so
the check can fail). Triangle's point counts differ (another algorithm): only
that both honour the bounds is compared.

usage: region_areas.py LEPP SOURCE_DIR SCRATCH_DIR [NODE]
Exit 0 all pass, 1 a failure (each printed). Without NODE, or without
triangle-wasm, the Triangle side is skipped (said on stdout).
"""
import json
import os
import sys
from fractions import Fraction

from formats_check import fail, failures, run, tokens

FILES = ["regions.poly", "region-areas.poly"]


def read_regions(poly):
    """The region lines of an input .poly: [(x, y, bound)] (four fields: the one value is the bound)."""
    r = tokens(poly)
    nv = int(r[0][0])
    at = 1 + nv
    ns = int(r[at][0])
    at += 1 + ns
    if at >= len(r):
        return []
    nh = int(r[at][0])
    at += 1 + nh
    if at >= len(r):
        return []
    regions = []
    for row in r[at + 1:at + 1 + int(r[at][0])]:
        regions.append((float(row[1]), float(row[2]), float(row[4] if len(row) > 4 else row[3])))
    return regions


def read_mesh(prefix):
    """Vertices (float pairs), triangles (index triples), segment edges (frozensets)."""
    node = tokens(prefix + ".node")
    n = int(node[0][0])
    first = int(node[1][0])
    pts = [(float(r[1]), float(r[2])) for r in node[1:1 + n]]
    ele = tokens(prefix + ".ele")
    tris = [tuple(int(r[k]) - first for k in (1, 2, 3)) for r in ele[1:1 + int(ele[0][0])]]
    poly = tokens(prefix + ".poly")
    skip = int(poly[0][0])
    ns = int(poly[1 + skip][0])
    segs = {frozenset((int(r[1]) - first, int(r[2]) - first)) for r in poly[2 + skip:2 + skip + ns]}
    return pts, tris, segs


def orient(a, b, c):
    d = (Fraction(b[0]) - Fraction(a[0])) * (Fraction(c[1]) - Fraction(a[1])) - \
        (Fraction(b[1]) - Fraction(a[1])) * (Fraction(c[0]) - Fraction(a[0]))
    return (d > 0) - (d < 0)


def twice_area(a, b, c):
    return abs((Fraction(b[0]) - Fraction(a[0])) * (Fraction(c[1]) - Fraction(a[1])) -
               (Fraction(b[1]) - Fraction(a[1])) * (Fraction(c[0]) - Fraction(a[0])))


def region_of_triangles(pts, tris, segs, regions):
    """0 for none, k + 1 for region k: flood from each region point in order."""
    by_edge = {}
    for t, tri in enumerate(tris):
        for i in range(3):
            by_edge.setdefault(frozenset((tri[i], tri[(i + 1) % 3])), []).append(t)
    region = [0] * len(tris)
    for k, (x, y, _) in enumerate(regions):
        p = (x, y)
        todo = []
        for t, tri in enumerate(tris):
            o = [orient(pts[tri[i]], pts[tri[(i + 1) % 3]], p) for i in range(3)]
            if min(o) < 0 or o.count(0) > 1:
                continue  # outside, or on a vertex
            if o.count(0) == 1:
                i = o.index(0)
                if frozenset((tri[i], tri[(i + 1) % 3])) in segs:
                    continue  # on a segment
            todo.append(t)
        seen = set(todo)
        while todo:
            t = todo.pop()
            region[t] = k + 1
            tri = tris[t]
            for i in range(3):
                e = frozenset((tri[i], tri[(i + 1) % 3]))
                if e in segs:
                    continue
                for u in by_edge[e]:
                    if u not in seen:
                        seen.add(u)
                        todo.append(u)
    return region


def violations(prefix, regions, slack=Fraction(0)):
    """(triangles above their region's bound, triangles per region)."""
    pts, tris, segs = read_mesh(prefix)
    region = region_of_triangles(pts, tris, segs, regions)
    bad = []
    for t, tri in enumerate(tris):
        if region[t] == 0 or regions[region[t] - 1][2] <= 0:
            continue
        bound = Fraction(regions[region[t] - 1][2])
        if twice_area(*(pts[v] for v in tri)) > 2 * bound * (1 + slack):
            bad.append(t)
    counts = [region.count(k + 1) for k in range(len(regions))]
    return bad, counts


def same_files(a, b):
    for ext in (".node", ".ele", ".poly"):
        with open(a + ext) as f, open(b + ext) as g:
            if f.read() != g.read():
                return False
    return True


def main():
    lepp, source, scratch = sys.argv[1:4]
    node = sys.argv[4] if len(sys.argv) > 4 else None
    runner = os.path.join(source, "tools", "triangle", "triangle.js")
    corpus = os.path.join(source, "corpus", "triangle-formats")
    os.makedirs(scratch, exist_ok=True)
    triangle = node is not None
    for name in FILES:
        path = os.path.join(corpus, name)
        stem = os.path.join(scratch, os.path.splitext(name)[0])
        regions = read_regions(path)
        # lepp with the bounds, both engines.
        r = run([lepp, "refine", path, "-o", stem, "--region-areas", "--json"])
        if r.returncode != 0:
            fail(f"{name}: lepp refine --region-areas exit {r.returncode}: {r.stderr.strip()}")
            continue
        report = json.loads(r.stdout)
        bad, counts = violations(stem, regions)
        print(f"{name}: lepp --region-areas: {report['steiner_points']} Steiner points, "
              f"{report['area_refined']} triangles refined for area, triangles per region {counts}, "
              f"{len(bad)} above their bound")
        if bad:
            fail(f"{name}: lepp --region-areas left {len(bad)} triangles above their region's bound")
        if report["area_refined"] <= 0:
            fail(f"{name}: --json says no triangle was refined for area")
        r = run([lepp, "refine", path, "-o", stem + "-reference", "--region-areas", "--engine", "reference", "-q"])
        if r.returncode != 0 or not same_files(stem, stem + "-reference"):
            fail(f"{name}: the reference engine's mesh differs (exit {r.returncode})")
        c = run([lepp, "certify", path, stem, "--min-angle", "30", "--region-areas"])
        if c.returncode != 0:
            fail(f"{name}: lepp certify --region-areas exit {c.returncode}: {c.stdout[-600:]}")
        # Without the option: a warning naming it, and a mesh the check rejects.
        r = run([lepp, "refine", path, "-o", stem + "-ignored", "-q"])
        if r.returncode != 0 or "--region-areas" not in r.stderr:
            fail(f"{name}: without --region-areas expected a warning naming it, got exit {r.returncode}: {r.stderr.strip()}")
        bad, _ = violations(stem + "-ignored", regions)
        print(f"  without --region-areas: {len(bad)} triangles above their region's bound")
        if not bad:
            fail(f"{name}: the check accepts the mesh made without the bounds (it cannot fail here)")
        c = run([lepp, "certify", path, stem + "-ignored", "--region-areas"])
        if c.returncode != 1 or "area-above-bound" not in c.stdout:
            fail(f"{name}: lepp certify --region-areas accepts the mesh made without the bounds (exit {c.returncode})")
        # Triangle -pq30a: the same bounds, honoured its own way.
        if not triangle:
            continue
        t = run([node, runner, path, "-pq30a", stem + "-triangle"])
        if t.returncode == 77:
            print("triangle-wasm missing: Triangle side skipped")
            triangle = False
            continue
        if t.returncode != 0:
            fail(f"{name}: Triangle -pq30a failed: {t.stderr.strip()}")
            continue
        bad, counts = violations(stem + "-triangle", regions, Fraction(1, 10**12))
        print(f"  Triangle -pq30a: {t.stdout.strip()}, triangles per region {counts}, {len(bad)} above their bound")
        if bad:
            fail(f"{name}: Triangle -pq30a left {len(bad)} triangles above their region's bound (the checker's reading differs?)")
        # The certifier decides every area exactly (no slack): Triangle's mesh passes it too.
        c = run([lepp, "certify", path, stem + "-triangle", "--min-angle", "30", "--region-areas"])
        if c.returncode != 0:
            fail(f"{name}: lepp certify --region-areas rejects Triangle's -pq30a mesh (exit {c.returncode}): {c.stdout[-600:]}")
    if not triangle:
        print("Triangle not compared (no node or no triangle-wasm)")
    print(f"{len(FILES)} files, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
