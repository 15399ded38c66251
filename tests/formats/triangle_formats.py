#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every file of corpus/triangle-formats/ read by lepp the way Triangle reads it.

For each file: lepp's constrained Delaunay triangulation (refine --min-angle 0)
and Triangle's (tools/triangle/triangle.js, the matching switches) have the
same vertex, segment and triangle counts, and the same triangles (by
coordinates) when the file says it has no cocircular ties; lepp's quality mesh
certifies; Triangle's quality mesh, as Triangle writes it (.node with
attributes and markers, .ele with attributes, .poly with no vertices), is read
and certified by lepp; and lepp's mesh is read by Triangle (no point added).

usage: triangle_formats.py LEPP NODE SOURCE_DIR SCRATCH_DIR
Exit 0 all pass, 1 a failure (each printed), 77 triangle-wasm missing.
"""
import os
import sys

from formats_check import fail, failures, run, tokens

# file, lepp domain options, Triangle switches for the same domain, same mesh expected
CASES = [
    ("marker-column.poly", [], "-p", True),
    ("points.node", [], "-c", True),
    ("no-segments.poly", [], "-pc", True),
    ("open-boundary.poly", ["--convex-hull"], "-pc", True),
    ("crossing.poly", ["--split-crossings"], "-p", True),
    ("regions.poly", [], "-pA", True),
    ("region-areas.poly", [], "-pA", True),
    ("zero-based.poly", [], "-p", True),
    ("attributes.poly", [], "-p", True),
    ("coincident.poly", [], "-p", True),
]
# lepp's warnings for these files must contain each fragment (file and line named).
WARNS = {
    "coincident.poly": ["coincident.poly:21: segment 7 has zero length (both endpoints are vertex 3); dropped",
                        "coincident.poly:22: segment 8 has zero length (vertices 2 and 6 are the same point); dropped",
                        "vertex 6 duplicates vertex 2", "segment 6"],
}
# Without its option, each of these is rejected (exit 2) with this in the message.
REJECTED_WITHOUT = {
    "open-boundary.poly": "--convex-hull",
    "crossing.poly": "--split-crossings",
}


def read_mesh(prefix):
    """(vertices, triangles as frozensets of coordinate pairs, segment count)."""
    node = tokens(prefix + ".node")
    n = int(node[0][0])
    first = int(node[1][0]) if n else 1
    pts = [(float(r[1]), float(r[2])) for r in node[1:1 + n]]
    ele = tokens(prefix + ".ele")
    tris = set()
    for r in ele[1:1 + int(ele[0][0])]:
        tris.add(frozenset(pts[int(r[k]) - first] for k in (1, 2, 3)))
    segments = 0
    if os.path.exists(prefix + ".poly"):
        poly = tokens(prefix + ".poly")
        skip = int(poly[0][0])
        segments = int(poly[1 + skip][0])
    return pts, tris, segments


def snapped(tris, to_points):
    """Triangles with each corner replaced by the point of to_points within
    1e-12 (relative) of it: Triangle rounds crossing points its own way."""
    def snap(p):
        for q in to_points:
            if abs(p[0] - q[0]) <= 1e-12 * max(1, abs(q[0])) and abs(p[1] - q[1]) <= 1e-12 * max(1, abs(q[1])):
                return q
        return p
    return {frozenset(snap(p) for p in t) for t in tris}


def main():
    lepp, node, source, scratch = sys.argv[1:5]
    runner = os.path.join(source, "tools", "triangle", "triangle.js")
    corpus = os.path.join(source, "corpus", "triangle-formats")
    os.makedirs(scratch, exist_ok=True)
    for name, options, switches, same_mesh in CASES:
        path = os.path.join(corpus, name)
        stem = os.path.join(scratch, os.path.splitext(name)[0])
        # Triangle's reading of the file: its CDT.
        t = run([node, runner, path, switches, stem + "-triangle"])
        if t.returncode == 77:
            print(t.stderr, end="")
            return 77
        if t.returncode != 0:
            fail(f"{name}: Triangle failed: {t.stderr.strip()}")
            continue
        # lepp's reading: the CDT of the same domain.
        r = run([lepp, "refine", path, "-o", stem + "-cdt", "--min-angle", "0", "-q"] + options)
        if r.returncode != 0:
            fail(f"{name}: lepp refine --min-angle 0 {' '.join(options)} exit {r.returncode}: {r.stderr.strip()}")
            continue
        for fragment in WARNS.get(name, []):
            if fragment not in r.stderr:
                fail(f"{name}: lepp's warnings lack '{fragment}': {r.stderr.strip()}")
        tv, tt, ts = read_mesh(stem + "-triangle")
        lv, lt, ls = read_mesh(stem + "-cdt")
        # Distinct points: Triangle keeps an exact duplicate in its .node (unused), lepp merges it.
        tv, lv = sorted(set(tv)), sorted(set(lv))
        print(f"{name}: Triangle {switches}: {len(tv)} vertices {ts} segments {len(tt)} triangles; "
              f"lepp {' '.join(options) or '(no option)'}: {len(lv)} vertices {ls} segments {len(lt)} triangles")
        if (len(tv), ts, len(tt)) != (len(lv), ls, len(lt)):
            fail(f"{name}: counts differ")
        elif same_mesh and snapped(tt, lv) != lt:
            fail(f"{name}: same counts, different triangles ({len(tt - lt)} of Triangle's not in lepp's)")
        # Without its option the file is rejected, naming the way out.
        if name in REJECTED_WITHOUT:
            r = run([lepp, "refine", path, "-o", stem + "-rejected", "-q"])
            if r.returncode != 2 or REJECTED_WITHOUT[name] not in r.stderr:
                fail(f"{name}: without {options} expected exit 2 and '{REJECTED_WITHOUT[name]}', got {r.returncode}: {r.stderr.strip()}")
        # lepp's quality mesh certifies.
        r = run([lepp, "refine", path, "-o", stem, "-q"] + options)
        if r.returncode != 0:
            fail(f"{name}: lepp refine exit {r.returncode}: {r.stderr.strip()}")
            continue
        c = run([lepp, "certify", path, stem, "--min-angle", "30"] + options)
        if c.returncode != 0:
            fail(f"{name}: lepp certify of lepp's mesh exit {c.returncode}: {c.stdout[-600:]} {c.stderr.strip()}")
        # Triangle's quality mesh, as Triangle writes it, read and certified by lepp.
        # coincident.poly: Triangle keeps the exact duplicate vertex in its .node, unused;
        # lepp certify merges it into the copy the triangles use, with a warning.
        q = stem + ".1"
        t = run([node, runner, path, switches + "q30", q])
        if t.returncode != 0:
            fail(f"{name}: Triangle -q30 failed: {t.stderr.strip()}")
        else:
            c = run([lepp, "certify", path, q, "--min-angle", "30", "--no-theorem2"] + options)
            if c.returncode != 0:
                fail(f"{name}: lepp certify of Triangle's {switches}q30 mesh exit {c.returncode}: {c.stdout[-600:]} {c.stderr.strip()}")
            elif name == "coincident.poly" and "an input vertex, and is in no triangle; merged" not in c.stdout:
                fail(f"{name}: lepp certify of Triangle's mesh does not say it merged the unused duplicate: {c.stdout[-600:]}")
        # Round trip: Triangle reads lepp's mesh (its .poly points at its .node) and adds nothing.
        t = run([node, runner, stem + ".poly", "-p", stem + "-back"])
        lv, lt, _ = read_mesh(stem)
        if t.returncode != 0 or "points added 0" not in t.stdout:
            fail(f"{name}: Triangle -p on lepp's mesh: exit {t.returncode} {t.stdout.strip()} {t.stderr.strip()}")
        else:
            # lepp writes no hole points (docs/FORMATS.md), so Triangle also fills the holes.
            bv, bt, _ = read_mesh(stem + "-back")
            missing = len(lt - bt)
            print(f"  round trip: lepp's mesh {len(lv)} vertices {len(lt)} triangles; Triangle -p on it: "
                  f"{len(bv)} vertices {len(bt)} triangles, {missing} of lepp's triangles not among them (cocircular ties)")
            if len(bv) != len(lv) or len(bt) < len(lt):
                fail(f"{name}: Triangle read lepp's mesh as {len(bv)} vertices {len(bt)} triangles")
    print(f"{len(CASES)} files, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
