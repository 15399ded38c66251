#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The browser check of lepp's HTML reports (issue 41): a page is opened in Debian's
headless Chromium, as a reader would open it, and must show what its JSON report says.

  check_page.py PAGE.html --json REPORT.json --kind certify|audit --shots DIR [--max-load-ms MS]
  check_page.py PAGE.html --kind paper --shots DIR    (docs/paper/index.html: the page's own checks only)

1. The DOM as the browser built it (--dump-dom, the page opened with #check: every
   <details> open, each picture's place and size written on it by the page's script):
   the page's script ran; #page-errors (the page's error hook: script errors, failed
   loads, console.error) is empty; the verdict, the rows and the counts equal the JSON
   report's (certify: a row per kind with its count, a section per kind with its listed
   violations; audit: a row per statement with runs/held/failed/findings, a row per
   named deviation with its runs, a section per saved finding; paper: Table 1 with a
   row per angle and a table per problem); every picture has a nonzero width and height.
2. The console: Chromium's log (--enable-logging=stderr) has no console message at all.
3. A screenshot of the whole page (kept in DIR): no picture is blank (one colour) in it.
4. With --max-load-ms: the page's load event came within that many milliseconds.

Exit 0 when the page passes, 1 with one line per problem when it does not, 2 for bad
usage, 77 when Chromium or Python's PIL is missing (ctest's skip code).
"""
import argparse
import html.parser
import json
import os
import shutil
import subprocess
import sys
import tempfile

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--hide-scrollbars", "--force-device-scale-factor=1", "--enable-logging=stderr", "--v=0"]
WIDTH = 1280
MAX_HEIGHT = 30000  # a screenshot taller than this is not taken: the check fails instead


class Element:
    def __init__(self, tag, attrs, parent):
        self.tag, self.attrs, self.parent, self.children, self.text = tag, dict(attrs), parent, [], ""

    def classes(self):
        return (self.attrs.get("class") or "").split()

    def walk(self):
        yield self
        for c in self.children:
            yield from c.walk()

    def find_all(self, pred):
        return [e for e in self.walk() if pred(e)]

    def all_text(self):
        return self.text + "".join(c.all_text() for c in self.children)


class Tree(html.parser.HTMLParser):
    VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track", "wbr"}

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.root = Element("#root", {}, None)
        self.at = self.root

    def handle_starttag(self, tag, attrs):
        e = Element(tag, attrs, self.at)
        self.at.children.append(e)
        if tag not in self.VOID:
            self.at = e

    def handle_startendtag(self, tag, attrs):
        self.at.children.append(Element(tag, attrs, self.at))

    def handle_endtag(self, tag):
        e = self.at
        while e is not None and e.tag != tag:
            e = e.parent
        if e is not None and e.parent is not None:
            self.at = e.parent

    def handle_data(self, data):
        self.at.text += data


def chromium(args, timeout=120):
    exe = os.environ.get("CHROMIUM", "chromium")
    with tempfile.TemporaryDirectory() as profile:
        p = subprocess.run([exe] + CHROMIUM_FLAGS + [f"--user-data-dir={profile}"] + args, capture_output=True, text=True,
                           timeout=timeout)
    return p


def by_id(root, ident):
    found = root.find_all(lambda e: e.attrs.get("id") == ident)
    return found[0] if found else None


def check_certify(root, report, problems):
    verdict = by_id(root, "verdict")
    if verdict is None:
        problems.append("no #verdict")
    elif verdict.attrs.get("data-certified") != ("true" if report["certified"] else "false"):
        problems.append(f"verdict says certified={verdict.attrs.get('data-certified')}, the report {report['certified']}")
    counts = {k: v for k, v in report["violation_counts"].items() if v}
    listed = {}
    for v in report["violations"]:
        listed[v["reason"]] = listed.get(v["reason"], 0) + 1
    table = by_id(root, "counts")
    rows = {} if table is None else {e.attrs["data-reason"]: e for e in table.find_all(lambda e: e.tag == "tr" and "data-reason" in e.attrs)}
    if counts and table is None:
        problems.append("no #counts table, the report has violations")
    for reason, n in counts.items():
        row = rows.get(reason)
        if row is None:
            problems.append(f"missing row: #counts has no row for {reason} ({n} violations)")
        elif row.attrs.get("data-count") != str(n) or str(n) not in row.all_text():
            problems.append(f"row {reason}: count {row.attrs.get('data-count')}, the report {n}")
    for reason in rows:
        if reason not in counts:
            problems.append(f"row {reason} in #counts, not in the report")
    sections = {e.attrs["data-reason"]: e for e in root.find_all(lambda e: e.tag == "section" and "kind" in e.classes())}
    for reason, n in counts.items():
        s = sections.get(reason)
        if s is None:
            problems.append(f"missing section: no section for {reason}")
            continue
        shown = len(s.find_all(lambda e: "violation" in e.classes()))
        if shown != listed.get(reason, 0):
            problems.append(f"section {reason}: {shown} violations on the page, the report lists {listed.get(reason, 0)}")
    for reason in sections:
        if reason not in counts:
            problems.append(f"section {reason} on the page, not in the report")
    stats = by_id(root, "statistics")
    if stats is None or str(report["statistics"]["triangles"]) not in stats.all_text():
        problems.append("#statistics missing or without the triangle count")


def check_audit(root, report, problems):
    verdict = by_id(root, "verdict")
    if verdict is None:
        problems.append("no #verdict")
    elif verdict.attrs.get("data-holds") != ("true" if report["holds"] else "false"):
        problems.append(f"verdict says holds={verdict.attrs.get('data-holds')}, the report {report['holds']}")
    table = by_id(root, "rows")
    rows = {} if table is None else {e.attrs["data-row"]: e for e in table.find_all(lambda e: e.tag == "tr" and "data-row" in e.attrs)}
    for r in report["rows"]:
        row = rows.get(r["check"])
        if row is None:
            problems.append(f"missing row: #rows has no row for {r['check']}")
            continue
        for key, field in (("data-runs", "runs"), ("data-held", "held"), ("data-failed", "failed"), ("data-findings", "findings")):
            if row.attrs.get(key) != str(r[field]):
                problems.append(f"row {r['check']}: {field} {row.attrs.get(key)}, the report {r[field]}")
    if len(rows) != len(report["rows"]):
        problems.append(f"#rows has {len(rows)} rows, the report {len(report['rows'])}")
    deviations = {}
    table = by_id(root, "deviations")
    if table is not None:
        for e in table.find_all(lambda e: e.tag == "tr" and "data-deviation" in e.attrs):
            deviations[(e.attrs["data-row"], e.attrs["data-deviation"])] = e
    expected = {(r["check"], name): n for r in report["rows"] for name, n in r["deviations"].items()}
    for key, n in expected.items():
        row = deviations.get(key)
        if row is None:
            problems.append(f"missing row: #deviations has no row for {key[1]} ({key[0]})")
        elif row.attrs.get("data-count") != str(n):
            problems.append(f"deviation {key[1]}: {row.attrs.get('data-count')} runs, the report {n}")
    for key in deviations:
        if key not in expected:
            problems.append(f"deviation {key[1]} on the page, not in the report")
    findings = root.find_all(lambda e: e.tag == "section" and "finding" in e.classes())
    saved = sum(len(r["counterexamples"]) for r in report["rows"]) + len(report["internal_errors"])
    if len(findings) != saved:
        problems.append(f"{len(findings)} finding sections, the report saved {saved}")
    for f in findings:
        if not f.find_all(lambda e: "picture" in e.classes()):
            problems.append(f"{f.attrs.get('id')}: a finding without a picture")
        # A conformance finding with a named deviation shows its step, and the link to it resolves.
        for link in f.find_all(lambda e: e.tag == "a" and e.attrs.get("href", "").startswith("#")):
            if by_id(root, link.attrs["href"][1:]) is None:
                problems.append(f"{f.attrs.get('id')}: link {link.attrs['href']} leads nowhere")


def check_paper(root, report, problems):
    table = by_id(root, "table1")
    rows = [] if table is None else table.find_all(lambda e: e.tag == "tr" and "data-theta" in e.attrs)
    if len(rows) < 5:
        problems.append(f"missing row: Table 1 has {len(rows)} rows")
    if not root.find_all(lambda e: e.tag == "table" and "problem" in e.classes()):
        problems.append("no table per problem")


def blank(image, box):
    """Whether the screenshot is one colour in `box` (left, top, right, bottom)."""
    crop = image.crop(box).convert("RGB")
    colours = crop.getcolors(maxcolors=1 << 16)
    if colours is None:  # more than 65536 colours: certainly not blank
        return False
    common = max(colours)[0]
    return crop.width * crop.height - common < 4  # at most a stray pixel or three differ


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("page")
    ap.add_argument("--json", help="the report's JSON (lepp certify --json, lepp audit --json; not for paper)")
    ap.add_argument("--kind", required=True, choices=["certify", "audit", "paper"])
    ap.add_argument("--shots", required=True, help="directory the screenshot is kept in")
    ap.add_argument("--max-load-ms", type=float, default=0)
    a = ap.parse_args()
    exe = shutil.which(os.environ.get("CHROMIUM", "chromium"))
    try:
        from PIL import Image
    except ImportError:
        Image = None
    if exe is None or Image is None:
        print("check_page: skipped: needs chromium and python3-pil (scripts/install-deps.sh)")
        return 77
    try:
        report = json.load(open(a.json)) if a.kind != "paper" else None
    except (OSError, ValueError, TypeError) as e:
        print(f"check_page: {a.json}: {e}", file=sys.stderr)
        return 2
    if not os.path.isfile(a.page):
        print(f"check_page: {a.page}: no such file", file=sys.stderr)
        return 2
    url = "file://" + os.path.abspath(a.page) + "#check"
    name = os.path.splitext(os.path.basename(a.page))[0]
    os.makedirs(a.shots, exist_ok=True)
    problems = []

    dump = chromium([f"--window-size={WIDTH},900", "--dump-dom", url])
    tree = Tree()
    tree.feed(dump.stdout)
    root = tree.root
    console = [l for l in dump.stderr.splitlines() if ":CONSOLE" in l]
    problems += [f"console: {l.split('] ', 1)[-1]}" for l in console]
    body = root.find_all(lambda e: e.tag == "body")
    body = body[0] if body else None
    if body is None or body.attrs.get("data-ready") != "1":
        problems.append("the page's script did not run to its end (no data-ready on <body>)")
    errors = by_id(root, "page-errors")
    if errors is None:
        problems.append("no #page-errors (the page's error hook)")
    else:
        problems += [f"page error: {li.all_text().strip()}" for li in errors.find_all(lambda e: e.tag == "li")]
    {"certify": check_certify, "audit": check_audit, "paper": check_paper}[a.kind](root, report, problems)

    pictures = root.find_all(lambda e: "picture" in e.classes())
    if not pictures and a.kind == "certify":  # the histogram and the mesh at least (an audit's are its findings')
        problems.append("no picture on the page")
    boxes = []
    for i, p in enumerate(pictures):
        try:
            x, y, w, h = (int(float(p.attrs[k])) for k in ("data-x", "data-y", "data-w", "data-h"))
        except (KeyError, ValueError):
            problems.append(f"picture {i + 1}: no size written (the page's #check script)")
            continue
        if w <= 0 or h <= 0:
            problems.append(f"picture {i + 1}: size {w} x {h}")
            continue
        boxes.append((i, x, y, w, h))

    if a.max_load_ms > 0 and body is not None:
        load = float(body.attrs.get("data-load-ms", "inf"))
        if load > a.max_load_ms:
            problems.append(f"loaded in {load:.0f} ms, more than {a.max_load_ms:.0f} ms")
        print(f"check_page: {a.page}: load event after {load:.0f} ms")

    height = int(body.attrs.get("data-height", "0")) if body is not None else 0
    if boxes and height > MAX_HEIGHT:
        problems.append(f"page {height} px tall: no screenshot above {MAX_HEIGHT} px")
    elif boxes or a.kind == "audit":
        shot = os.path.join(a.shots, name + ".png")
        if os.path.exists(shot):
            os.remove(shot)
        chromium([f"--window-size={WIDTH},{max(height, 100)}", f"--screenshot={os.path.abspath(shot)}", url])
        if not os.path.isfile(shot):
            problems.append("no screenshot written")
        else:
            image = Image.open(shot)
            for i, x, y, w, h in boxes:
                box = (max(x, 0), max(y, 0), min(x + w, image.width), min(y + h, image.height))
                if box[2] <= box[0] or box[3] <= box[1]:
                    problems.append(f"picture {i + 1} at ({x}, {y}) is outside the screenshot ({image.width} x {image.height})")
                elif blank(image, box):
                    problems.append(f"picture {i + 1} at ({x}, {y}), {w} x {h}: blank in the screenshot")
            print(f"check_page: screenshot {shot} ({image.width} x {image.height}), {len(boxes)} pictures")

    for p in problems:
        print(f"FAIL: {a.page}: {p}")
    if problems:
        return 1
    print(f"ok: {a.page}: {len(pictures)} pictures" + (f", DOM agrees with {a.json}" if a.json else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
