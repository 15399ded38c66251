#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Turns `llvm-cov export -format=text` (clang's source-based coverage) into the
per-line shape of gcovr's JSON that tools/coverage/report.py reads:

  {"files": [{"file": REL, "lines": [{"line_number": N, "count": C, "strict_count": S,
                                      "branches": [{"count": T}, {"count": F}, ...]}]}]}

A line's count follows llvm-cov's own rule (LineCoverageStats): the largest count
of the regions starting on it and of the region it continues. Its branches are the
conditions that start on it, each as two outcomes (true, false): the conditions
written in the source, not the branches of the code a compiler inlines there.

  llvm_json.py EXPORT.json --root DIR > OUT.json
"""
import argparse
import json
import os


def line_counts(segments):
    """{line: count} for mapped lines, from segments [line, col, count, has_count, entry, gap]."""
    by_line = {}
    for seg in segments:
        by_line.setdefault(seg[0], []).append(seg)
    if not by_line:
        return {}
    out = {}
    wrapped = None  # the segment in effect at the start of the line
    last = max(by_line)
    for line in range(min(by_line), last + 1):
        segs = by_line.get(line, [])
        starts = [s for s in segs if s[3] and s[4] and not s[5]]
        skipped = bool(segs) and not segs[0][3] and segs[0][4]
        mapped = not skipped and ((wrapped is not None and wrapped[3]) or starts)
        if mapped:
            count = wrapped[2] if wrapped is not None else 0
            for s in starts:
                count = max(count, s[2])
            # strict: the regions that start on the line when there are some (the count
            # of `} catch (...) {` is the catch's, not the try block's it closes).
            strict = max(s[2] for s in starts) if starts else count
            out[line] = (count, strict)
        if segs:
            wrapped = segs[-1]
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("export")
    ap.add_argument("--root", required=True)
    a = ap.parse_args()
    root = os.path.realpath(a.root) + os.sep
    data = json.load(open(a.export))
    files = []
    for unit in data.get("data", []):
        for f in unit.get("files", []):
            name = os.path.realpath(f["filename"])
            if not name.startswith(root):
                continue
            counts = line_counts(f.get("segments", []))
            branches = {}
            for b in f.get("branches", []):
                branches.setdefault(b[0], []).extend([{"count": b[4]}, {"count": b[5]}])
            lines = []
            for n in sorted(set(counts) | set(branches)):
                count, strict = counts.get(n, (0, 0))
                lines.append({"line_number": n, "count": count, "strict_count": strict, "branches": branches.get(n, [])})
            files.append({"file": name[len(root):], "lines": lines})
    json.dump({"files": files}, __import__("sys").stdout)


if __name__ == "__main__":
    main()
