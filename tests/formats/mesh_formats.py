#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""`lepp refine --format vtu|msh2|msh4` (and --binary) read back by meshio and
by Gmsh itself (its Python API, the library the gmsh program runs on).

For each input, lepp writes Triangle's files in the same run as the other
format; those are the truth. Each .msh and .vtu must give, read by meshio and
(for .msh) by Gmsh:
- the same vertices, bit for bit (ASCII coordinates are shortest round-trip
  decimals), and the same triangles, corner for corner, and the constrained
  edges as line elements;
- the physical groups of docs/FORMATS.md: triangles by region (found here
  independently, by flooding the .poly's region points across the edges that
  are not segments, tests/formats/region_areas.py), lines by the boundary
  marker of their input segment (read from the input .poly), with their names;
- in the .vtu, the per-triangle quality arrays as recomputed here with NumPy
  (relative 1e-9), the region array, and the input/Steiner flag per vertex;
- on the first input, the gmsh program opens each .msh and saves it again
  (`gmsh FILE -0 -o OUT.msh`) with the same vertices and groups.
Then broken copies (one coordinate moved by an ulp, one group tag changed, a
truncated file) must each be reported by the same checks, so they can fail.

usage: mesh_formats.py LEPP SOURCE_DIR SCRATCH_DIR
Exit 0 all pass, 1 a failure (each printed), 77 when meshio or gmsh is not
installed (scripts/install-deps.sh installs both).
"""
import math
import os
import shutil
import struct
import sys

try:
    import numpy as np
    import meshio
    import gmsh
except ImportError as e:
    print(f"skipped: {e} (scripts/install-deps.sh installs python3-meshio and python3-gmsh)")
    sys.exit(77)

from formats_check import fail, failures, run, tokens
from region_areas import read_mesh, read_regions, region_of_triangles

CASES = [
    ("tests/formats/data/labelled.poly", []),            # markers 1..6, two regions, a hole
    ("corpus/triangle-formats/regions.poly", []),        # regions, no markers
    ("corpus/triangle-formats/region-areas.poly", ["--region-areas"]),
    ("corpus/triangle-formats/zero-based.poly", []),     # 0-based, markers 3
    ("corpus/triangle-formats/crossing.poly", ["--split-crossings"]),
    ("corpus/paper/A.poly", []),
]
# (format, --binary): each written beside Triangle's files in its own run.
VARIANTS = [("vtu", False), ("msh2", False), ("msh4", False), ("msh2", True), ("msh4", True)]


def segment_markers(poly):
    """The boundary marker of each segment of an input .poly (0 when the file has none)."""
    r = tokens(poly)
    nv = int(r[0][0])
    head = r[1 + nv]
    ns, has = int(head[0]), len(head) > 1 and head[1] == "1"
    return [int(row[3]) if has and len(row) > 3 else 0 for row in r[2 + nv:2 + nv + ns]]


class Expected:
    """What every format must say, from Triangle's files of the same run and the input."""

    def __init__(self, prefix, poly):
        self.pts, self.tris, segs = read_mesh(prefix)
        node = tokens(prefix + ".node")
        self.input = [int(row[3]) for row in node[1:1 + len(self.pts)]]
        poly_rows = tokens(prefix + ".poly")
        ns = int(poly_rows[1][0])
        markers = segment_markers(poly)
        self.edges = []  # (a, b, boundary marker)
        for row in poly_rows[2:2 + ns]:
            seg = int(row[3])
            self.edges.append((int(row[1]) - 1, int(row[2]) - 1, markers[seg - 1] if seg >= 1 else 0))
        regions = read_regions(poly)
        self.region = region_of_triangles(self.pts, self.tris, segs, regions)
        nregions = len(regions)
        top = max([k for _, _, k in self.edges] + [0])
        # The groups of docs/FORMATS.md: {(dim, tag): (name, sorted elements)}.
        self.groups = {}
        for t, tri in enumerate(self.tris):
            tag = self.region[t] if self.region[t] > 0 else nregions + 1
            name = "domain" if tag == nregions + 1 else f"region_{tag}"
            self.groups.setdefault((2, tag), (name, []))[1].append(tuple(tri))
        for a, b, k in self.edges:
            tag = k if k >= 1 else top + 1
            name = f"marker_{k}" if k >= 1 else "unmarked"
            self.groups.setdefault((1, tag), (name, []))[1].append((a, b))
        for key in self.groups:
            self.groups[key][1].sort()


def compare_points(where, points, exp):
    if points.shape[0] != len(exp.pts):
        return [f"{where}: {points.shape[0]} vertices, expected {len(exp.pts)}"]
    want = np.array(exp.pts, dtype=np.float64)
    bad = np.nonzero((points[:, 0] != want[:, 0]) | (points[:, 1] != want[:, 1]))[0]
    if len(bad):
        v = bad[0]
        return [f"{where}: {len(bad)} vertices differ, first {v + 1}: {tuple(points[v, :2])} instead of {exp.pts[v]}"]
    if points.shape[1] > 2 and np.any(points[:, 2] != 0):
        return [f"{where}: a vertex has z != 0"]
    return []


def compare_groups(where, got, exp):
    """got: {(dim, tag): (name, sorted elements)}."""
    problems = []
    for key in sorted(set(got) | set(exp.groups)):
        if key not in got:
            problems.append(f"{where}: physical group {key} ({exp.groups[key][0]}) missing")
        elif key not in exp.groups:
            problems.append(f"{where}: unexpected physical group {key} ({got[key][0]}, {len(got[key][1])} elements)")
        elif got[key][0] != exp.groups[key][0]:
            problems.append(f"{where}: group {key} is named {got[key][0]!r}, expected {exp.groups[key][0]!r}")
        elif got[key][1] != exp.groups[key][1]:
            problems.append(f"{where}: group {key} ({got[key][0]}) has {len(got[key][1])} elements, "
                            f"expected {len(exp.groups[key][1])}, or other ones")
    return problems


def check_msh_meshio(path, exp):
    where = f"meshio {os.path.basename(path)}"
    try:
        m = meshio.read(path, file_format="gmsh")
    except Exception as e:  # a reader error is what a broken file should give
        return [f"{where}: {type(e).__name__}: {e}"]
    problems = compare_points(where, m.points, exp)
    names = {(int(v[1]), int(v[0])): k for k, v in m.field_data.items()}  # (dim, tag) -> name
    got = {}
    tris, lines = [], []
    physical = m.cell_data.get("gmsh:physical")
    if physical is None:
        return problems + [f"{where}: no physical tags"]
    for block, tags in zip(m.cells, physical):
        dim = {"triangle": 2, "line": 1}.get(block.type)
        if dim is None:
            problems.append(f"{where}: unexpected cells {block.type}")
            continue
        for cell, tag in zip(block.data.tolist(), tags.tolist()):
            key = (dim, int(tag))
            got.setdefault(key, (names.get(key, "?"), []))[1].append(tuple(cell))
            (tris if dim == 2 else lines).append(tuple(cell))
    for key in got:
        got[key][1].sort()
    if sorted(tris) != sorted(tuple(t) for t in exp.tris):
        problems.append(f"{where}: {len(tris)} triangles, not those of the .ele ({len(exp.tris)})")
    if sorted(lines) != sorted((a, b) for a, b, _ in exp.edges):
        problems.append(f"{where}: {len(lines)} lines, not the constrained edges of the .poly ({len(exp.edges)})")
    return problems + compare_groups(where, got, exp)


def check_msh_gmsh(path, exp):
    where = f"gmsh {os.path.basename(path)}"
    gmsh.initialize(["gmsh"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.logger.start()
        try:
            gmsh.open(path)
        except Exception as e:
            return [f"{where}: {e}"]
        errors = [line for line in gmsh.logger.get() if line.startswith("Error")]
        if errors:
            return [f"{where}: {errors[0]}"]
        tags, coords, _ = gmsh.model.mesh.getNodes()
        if len(tags) != len(exp.pts):
            return [f"{where}: {len(tags)} nodes, expected {len(exp.pts)}"]
        points = np.zeros((len(exp.pts), 3))
        points[np.asarray(tags, dtype=np.int64) - 1] = np.asarray(coords).reshape(-1, 3)
        problems = compare_points(where, points, exp)
        got = {}
        for dim, tag in gmsh.model.getPhysicalGroups():
            name = gmsh.model.getPhysicalName(dim, tag)
            elements = []
            for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
                types, _, nodes = gmsh.model.mesh.getElements(dim, entity)
                for t, n in zip(types, nodes):
                    k = 3 if t == 2 else 2
                    elements += [tuple(int(v) - 1 for v in n[i:i + k]) for i in range(0, len(n), k)]
            got[(dim, tag)] = (name, sorted(elements))
        for dim, want in ((2, sorted(tuple(t) for t in exp.tris)), (1, sorted((a, b) for a, b, _ in exp.edges))):
            types, _, nodes = gmsh.model.mesh.getElements(dim)
            k = dim + 1
            have = sorted(tuple(int(v) - 1 for v in n[i:i + k]) for n in nodes for i in range(0, len(n), k))
            if have != want:
                problems.append(f"{where}: {len(have)} elements of dimension {dim}, expected {len(want)} (or other ones)")
        return problems + compare_groups(where, got, exp)
    finally:
        gmsh.logger.stop()
        gmsh.finalize()


def check_msh_gmsh_program(path, exp):
    """The gmsh program opens the file and saves it again (`gmsh FILE -0 -o OUT.msh`, format 4.1):
    the saved mesh, read by meshio, has the same vertices to Gmsh's 16 printed digits and the
    same groups (Gmsh keeps the elements of physical groups). Gmsh may save the nodes in
    another order: each saved vertex is matched to the nearest expected one."""
    where = f"gmsh program {os.path.basename(path)}"
    out = path + ".resaved.msh"
    r = run([GMSH, path, "-0", "-o", out, "-format", "msh41"])
    errors = [line for line in (r.stdout + r.stderr).splitlines() if "Error" in line]
    if r.returncode != 0 or errors or not os.path.exists(out):
        return [f"{where}: exit {r.returncode}: {errors[0] if errors else r.stderr.strip()}"]
    try:
        m = meshio.read(out, file_format="gmsh")
    except Exception as e:
        return [f"{where}: its output does not read: {type(e).__name__}: {e}"]
    finally:
        os.remove(out)
    want = np.array(exp.pts)
    if m.points.shape[0] != len(want):
        return [f"{where}: {m.points.shape[0]} vertices saved, expected {len(want)}"]
    nearest = np.array([int(np.argmin(np.abs(want - p[:2]).sum(axis=1))) for p in m.points])
    if len(set(nearest.tolist())) != len(want) or not np.allclose(m.points[:, :2], want[nearest], rtol=1e-15, atol=0):
        return [f"{where}: the saved vertices differ"]
    names = {(int(v[1]), int(v[0])): k for k, v in m.field_data.items()}
    got = {}
    for block, tags in zip(m.cells, m.cell_data.get("gmsh:physical", [])):
        dim = {"triangle": 2, "line": 1}.get(block.type, 0)
        for cell, tag in zip(block.data.tolist(), tags.tolist()):
            cell = tuple(int(nearest[v]) for v in cell)
            got.setdefault((dim, int(tag)), (names.get((dim, int(tag)), "?"), []))[1].append(cell)
    for key in got:
        got[key][1].sort()
    return compare_groups(where, got, exp)


GMSH = shutil.which("gmsh")


def quality(pts, tris):
    """min angle, max angle (degrees), q, radius ratio, edge ratio per triangle (NumPy)."""
    p = np.array(pts)[np.array(tris)]
    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    la, lb, lc = (np.linalg.norm(b - c, axis=1), np.linalg.norm(c - a, axis=1), np.linalg.norm(a - b, axis=1))
    area = 0.5 * np.abs((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])
    # Angles from the law of cosines, opposite each side.
    angles = np.degrees(np.stack([np.arccos(np.clip((lb**2 + lc**2 - la**2) / (2 * lb * lc), -1, 1)),
                                  np.arccos(np.clip((lc**2 + la**2 - lb**2) / (2 * lc * la), -1, 1)),
                                  np.arccos(np.clip((la**2 + lb**2 - lc**2) / (2 * la * lb), -1, 1))]))
    longest, shortest = np.maximum(np.maximum(la, lb), lc), np.minimum(np.minimum(la, lb), lc)
    r_in = area / (0.5 * (la + lb + lc))
    r_circ = la * lb * lc / (4 * area)
    return {"min_angle": angles.min(axis=0), "max_angle": angles.max(axis=0),
            "area_quality": 4 / math.sqrt(3) * area / longest**2,
            "radius_ratio": 2 * r_in / r_circ, "edge_ratio": longest / shortest}


def check_vtu_meshio(path, exp):
    where = f"meshio {os.path.basename(path)}"
    try:
        m = meshio.read(path, file_format="vtu")
    except Exception as e:
        return [f"{where}: {type(e).__name__}: {e}"]
    problems = compare_points(where, m.points, exp)
    if len(m.cells) != 1 or m.cells[0].type != "triangle":
        return problems + [f"{where}: cells {[c.type for c in m.cells]}, expected one block of triangles"]
    if m.cells[0].data.tolist() != [list(t) for t in exp.tris]:
        problems.append(f"{where}: triangles differ from the .ele")
    want = quality(exp.pts, exp.tris)
    want["region"] = np.array(exp.region)
    for name, values in want.items():
        got = m.cell_data.get(name)
        if got is None:
            problems.append(f"{where}: no cell data {name}")
        elif not np.allclose(got[0], values, rtol=1e-9, atol=1e-9 if name.endswith("angle") else 0):
            i = int(np.argmax(np.abs(got[0] - values)))
            problems.append(f"{where}: {name} of triangle {i + 1} is {got[0][i]}, expected {values[i]}")
    if m.point_data.get("input") is None or m.point_data["input"].tolist() != exp.input:
        problems.append(f"{where}: point data 'input' differs from the .node's markers")
    return problems


def check(path, fmt, exp, program=False):
    if fmt == "vtu":
        return check_vtu_meshio(path, exp)
    problems = check_msh_meshio(path, exp) + check_msh_gmsh(path, exp)
    if program and GMSH:
        problems += check_msh_gmsh_program(path, exp)
    return problems


# --- broken copies -----------------------------------------------------------

def next_up(b, at):
    """The double at byte `at` of bytes b, moved up by one ulp."""
    (x,) = struct.unpack_from("<d", b, at)
    return b[:at] + struct.pack("<d", math.nextafter(x, math.inf)) + b[at + 8:]


def first_x_offset(data, fmt, binary):
    """Where vertex 1's x is, in bytes, in a file lepp wrote."""
    if fmt == "vtu":
        head = data[:data.index(b"<AppendedData")]
        at = head.index(b'Name="Points"')
        offset = int(head[head.index(b'offset="', at) + 8:].split(b'"')[0])
        return data.index(b"_", len(head)) + 1 + offset + 8
    start = data.index(b"$Nodes\n") + len(b"$Nodes\n")
    if fmt == "msh2":
        return data.index(b"\n", start) + 1 + 4  # past the count line and the int id
    return start + 4 * 8 + 3 * 4 + 8 + 8 * len_nodes(data, start)  # header, block header, tags


def len_nodes(data, start):
    return struct.unpack_from("<Q", data, start + 8)[0]


def moved_vertex(data, fmt, binary):
    if fmt == "vtu" or binary:
        return next_up(data, first_x_offset(data, fmt, binary))
    lines = data.decode().split("\n")
    i = lines.index("$Nodes")
    row = i + 2 if fmt == "msh2" else i + 3 + int(lines[i + 1].split()[1])
    fields = lines[row].split()
    k = 1 if fmt == "msh2" else 0
    fields[k] = repr(math.nextafter(float(fields[k]), math.inf))
    lines[row] = " ".join(fields)
    return "\n".join(lines).encode()


def changed_group(data, fmt, binary):
    """Triangle 1 put in another physical group (the .vtu: another region)."""
    if fmt == "vtu":
        head = data[:data.index(b"<AppendedData")]
        at = head.index(b'Name="region"')
        offset = int(head[head.index(b'offset="', at) + 8:].split(b'"')[0])
        pos = data.index(b"_", len(head)) + 1 + offset + 8
        (r,) = struct.unpack_from("<i", data, pos)
        return data[:pos] + struct.pack("<i", r + 1) + data[pos + 4:]
    if fmt == "msh2" and not binary:
        lines = data.decode().split("\n")
        i = lines.index("$Elements")
        for row in range(i + 2, len(lines)):
            f = lines[row].split()
            if f[0] == "1":
                f[3] = str(int(f[3]) + 100)
                lines[row] = " ".join(f)
                break
        return "\n".join(lines).encode()
    return None


def check_broken(path, fmt, binary, exp, scratch):
    variants = [("moved-vertex", moved_vertex(open(path, "rb").read(), fmt, binary)),
                ("changed-group", changed_group(open(path, "rb").read(), fmt, binary)),
                ("truncated", open(path, "rb").read()[:os.path.getsize(path) * 2 // 3])]
    for what, data in variants:
        if data is None:
            continue
        broken = os.path.join(scratch, f"broken-{what}-{os.path.basename(path)}")
        with open(broken, "wb") as f:
            f.write(data)
        readers = [check_vtu_meshio] if fmt == "vtu" else [check_msh_meshio, check_msh_gmsh]
        # The save-again check sees a truncated file; not an ulp (Gmsh prints 16 digits) nor one
        # element's 2.2 physical tag (Gmsh files groups by entity, and saves the entity's).
        if fmt != "vtu" and GMSH and what == "truncated":
            readers.append(check_msh_gmsh_program)
        for reader in readers:
            problems = reader(broken, exp)
            if problems:
                print(f"  {what} {os.path.basename(path)} ({reader.__name__}): rejected: {problems[0]}")
            else:
                fail(f"{what} copy of {path} passed {reader.__name__}: the check cannot fail")


def main():
    lepp, source, scratch = sys.argv[1:4]
    os.makedirs(scratch, exist_ok=True)
    if not GMSH:
        print("note: no gmsh program on PATH: the save-again check is skipped (Gmsh's library still reads every file)")
    for rel, options in CASES:
        poly = os.path.join(source, rel)
        name = os.path.splitext(os.path.basename(rel))[0]
        for fmt, binary in VARIANTS:
            prefix = os.path.join(scratch, f"{name}-{fmt}{'-binary' if binary else ''}")
            cmd = [lepp, "refine", poly, "-o", prefix, "-q", "--format", "triangle", "--format", fmt] + options
            if binary:
                cmd.append("--binary")
            r = run(cmd)
            if r.returncode != 0:
                fail(f"{' '.join(cmd)}: exit {r.returncode}: {r.stderr.strip()}")
                continue
            exp = Expected(prefix, poly)
            path = prefix + (".vtu" if fmt == "vtu" else ".msh")
            # The gmsh program (a process per file) on the first input only: its library reads them all.
            problems = check(path, fmt, exp, program=rel == CASES[0][0])
            for p in problems:
                fail(p)
            groups = sorted(f"{d}:{t}:{n}" for (d, t), (n, _) in exp.groups.items())
            print(f"{'ok' if not problems else 'FAILED'}: {rel} {fmt}{' binary' if binary else ''}: "
                  f"{len(exp.pts)} vertices, {len(exp.tris)} triangles, {len(exp.edges)} lines; groups {' '.join(groups)}")
            if rel == CASES[0][0]:
                check_broken(path, fmt, binary, exp, scratch)
    # Two .msh versions in one run would write the same file: a command-line error.
    r = run([lepp, "refine", os.path.join(source, CASES[0][0]), "-o", os.path.join(scratch, "both"),
             "--format", "msh2,msh4"])
    if r.returncode != 2 or "both.msh" not in r.stderr:
        fail(f"--format msh2,msh4: exit {r.returncode} ({r.stderr.strip()}), expected 2 naming both.msh")
    print(f"{len(failures)} failed" if failures else "all passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
