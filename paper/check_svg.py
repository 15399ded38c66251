#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks an SVG written by `lepp render`: well-formed XML, an <svg> root, and,
with --ele, one closed triangle per line of the mesh's .ele file.

    /usr/bin/python3 paper/check_svg.py out.svg [--ele MESH.ele]

Exit status 0 when it holds, 1 (with the reason) when not.
"""
import argparse
import re
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("svg")
    ap.add_argument("--ele", help="the mesh's .ele file: the SVG must draw each of its triangles once")
    args = ap.parse_args()
    try:
        root = ET.parse(args.svg).getroot()
    except (ET.ParseError, OSError) as e:
        sys.exit(f"check_svg: {args.svg}: not well-formed: {e}")
    if root.tag != SVG + "svg":
        sys.exit(f"check_svg: {args.svg}: root is {root.tag}, not svg")
    # Triangles are the closed subpaths of the filled paths inside the first <g>.
    group = root.find(SVG + "g")
    if group is None:
        sys.exit(f"check_svg: {args.svg}: no group of triangle paths")
    triangles = sum(len(re.findall("z", p.get("d", ""))) for p in group.iter(SVG + "path"))
    if triangles == 0:
        sys.exit(f"check_svg: {args.svg}: no triangles drawn")
    if args.ele:
        with open(args.ele) as f:
            header = next(line for line in f if line.strip() and not line.lstrip().startswith("#"))
        expected = int(header.split()[0])
        if triangles != expected:
            sys.exit(f"check_svg: {args.svg}: {triangles} triangles drawn, {args.ele} has {expected}")
    print(f"check_svg: {args.svg}: ok, {triangles} triangles")


if __name__ == "__main__":
    main()
