#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes docs/COVERAGE.md (on stdout) from gcovr's JSON reports (scripts/coverage.sh).

  report.py --ctest CTEST.json --fuzz FUZZ.json --all ALL.json --reasons reasons.txt
            [--ctest-seconds N] [--ctest-log LOG]

reasons.txt says why a line or branch stays uncovered, one per line:
  FILE | TEXT | KIND | WHY
where TEXT is a piece of the source line (matched as a substring, so the entry
survives edits that move the line), KIND one of unreachable, defensive, owed.
Every uncovered branch without an entry is listed as "owed" (a test is owed).
"""
import argparse
import json
import os
import re
import sys

AREAS = [  # (name, path prefixes, goal applies)
    ("impl/src", ("impl/src/", "impl/include/"), True),
    ("reference/src", ("reference/src/", "reference/include/"), True),
    ("certifier", ("properties/certify/",), True),
    ("core", ("core/",), False),
    ("audit", ("audit/src/", "audit/include/"), False),
    ("engines", ("engines/src/", "engines/include/"), False),
]
GOAL_LINES, GOAL_BRANCHES = 95.0, 90.0


def load(path):
    data = json.load(open(path))
    files = {}
    for f in data.get("files", []):
        name = f["file"]
        lines = {}
        for ln in f.get("lines", []):
            if ln.get("gcovr/noncode"):
                continue
            n = ln["line_number"]
            prev = lines.get(n)
            branches = [b["count"] for b in ln.get("branches", []) if not b.get("throw")]
            if prev:  # the same line listed twice (template instances): merge
                prev["count"] += ln["count"]
                if len(prev["branches"]) == len(branches):
                    prev["branches"] = [x + y for x, y in zip(prev["branches"], branches)]
                else:
                    prev["branches"] += branches
            else:
                lines[n] = {"count": ln["count"], "branches": branches, "strict": ln.get("strict_count", ln["count"])}
        files[name] = lines
    return files


def totals(lines):
    lt = len(lines)
    lc = sum(1 for v in lines.values() if v["count"] > 0)
    bt = sum(len(v["branches"]) for v in lines.values())
    bc = sum(sum(1 for c in v["branches"] if c > 0) for v in lines.values())
    return lt, lc, bt, bc


def summed(files, keep):
    """totals() summed over the files (name -> lines) whose name keep() accepts."""
    t = [0, 0, 0, 0]
    for n, lines in files.items():
        if keep(n):
            t = [x + y for x, y in zip(t, totals(lines))]
    return t


def pct(k, n):
    return 100.0 * k / n if n else 100.0


def fmt_pct(k, n):
    return f"{pct(k, n):.1f} %" if n else "-"


def area_of(name):
    for area, prefixes, _ in AREAS:
        if name.startswith(prefixes):
            return area
    return None


def ranges(nums):
    nums = sorted(nums)
    out, start, prev = [], None, None
    for n in nums:
        if start is None:
            start = prev = n
        elif n == prev + 1:
            prev = n
        else:
            out.append((start, prev))
            start = prev = n
    if start is not None:
        out.append((start, prev))
    return ", ".join(str(a) if a == b else f"{a}-{b}" for a, b in out)


def load_reasons(path):
    reasons = []
    if not os.path.exists(path):
        return reasons
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        parts = [p.strip() for p in line.rstrip("\n").split(" | ")]
        if len(parts) != 4 or parts[2] not in ("unreachable", "defensive", "owed"):
            sys.exit(f"{path}:{n}: expected 'FILE | TEXT | unreachable|defensive|owed | WHY'")
        reasons.append({"file": parts[0], "text": parts[1], "kind": parts[2], "why": parts[3], "used": False})
    return reasons


def source_line(root, name, n, cache={}):
    if name not in cache:
        try:
            cache[name] = open(os.path.join(root, name), encoding="utf-8").read().split("\n")
        except OSError:
            cache[name] = []
    lines = cache[name]
    return lines[n - 1].strip() if 0 < n <= len(lines) else ""


def reason_for(reasons, name, text):
    for r in reasons:
        if r["file"] == name and r["text"] in text:
            r["used"] = True
            return r
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ctest", required=True)
    ap.add_argument("--fuzz", required=True)
    ap.add_argument("--all", required=True)
    ap.add_argument("--reasons", required=True)
    ap.add_argument("--ctest-seconds", default="?")
    ap.add_argument("--ctest-log", default="")
    ap.add_argument("--ctest-args", default="", help="the ctest selection, when not the whole default ctest")
    ap.add_argument("--root", default=os.getcwd())
    ap.add_argument("--without", default="", help="gcovr JSON of ctest without the --split tests")
    ap.add_argument("--split", default="", help="the ctest -R regex of the tests left out of --without")
    ap.add_argument("--flags", default="-O1", help="the instrumented build's optimisation flags")
    ap.add_argument("--build", default="build-cov", help="the instrumented build's directory")
    ap.add_argument("--source-branches", default="", help="tools/coverage/llvm_json.py's output: the default ctest's "
                    "source-level branches (clang), which then decide the branch goal and the list of uncovered branches")
    a = ap.parse_args()

    runs = {"ctest": load(a.ctest), "fuzz": load(a.fuzz)}
    # "all": ctest and fuzz merged line by line (gcovr's merged file lists some lines twice).
    merged = {}
    for name in set(runs["ctest"]) | set(runs["fuzz"]):
        x, y = runs["ctest"].get(name, {}), runs["fuzz"].get(name, {})
        out_lines = {}
        for ln in set(x) | set(y):
            p, q = x.get(ln), y.get(ln)
            if p and q:
                br = [u + v for u, v in zip(p["branches"], q["branches"])] if len(p["branches"]) == len(q["branches"]) else p["branches"]
                out_lines[ln] = {"count": p["count"] + q["count"], "branches": br}
            else:
                out_lines[ln] = dict(p or q)
        merged[name] = out_lines
    runs["all"] = merged
    if a.without and os.path.exists(a.without):
        runs["without"] = load(a.without)
    srcb = load(a.source_branches) if a.source_branches and os.path.exists(a.source_branches) else None
    reasons = load_reasons(a.reasons)
    names = sorted(n for n in runs["ctest"] if area_of(n))
    failed = ""
    if a.ctest_log and os.path.exists(a.ctest_log):
        m = re.findall(r"(\d+)% tests passed, (\d+) tests failed out of (\d+)", open(a.ctest_log, errors="replace").read())
        if m:
            failed = f"{sum(int(x[2]) for x in m)} tests, {sum(int(x[1]) for x in m)} failed"

    out = []
    w = out.append
    w("# Coverage")
    w("")
    w(f"Generated by `scripts/coverage.sh` (gcovr on a g++ `--coverage {a.flags}` build in `{a.build}/`"
      + (", and clang's source-based coverage for the branches as written" if srcb is not None else "") + ");")
    w("do not edit by hand. Opt-in, not in CI: instrumented rebuilds (about 20 CPU-minutes each)")
    w("and their test runs. Measured: the libraries in core/, impl/, reference/,")
    w("properties/certify/, audit/ and engines/ (not their tests, benchmarks or the CLI).")
    w("")
    which = f"`ctest {a.ctest_args}` (the default ctest restricted so)" if a.ctest_args.strip() else "the default `ctest` (no LEPP_LONG_TESTS)"
    w(f"- **ctest**: {which}" + (f": {failed}" if failed else "") + f", {a.ctest_seconds} s wall at `-j2` in the instrumented build.")
    w("- **fuzz**: the replay of every fuzz corpus by the g++ replay drivers (`corpus/fuzz/TARGET`,")
    w("  `corpus/regressions/TARGET` with `open/`, and `out/fuzz/TARGET/corpus` where a campaign grew one).")
    w("- **all**: both.")
    w("")
    w("Branches are counted with gcovr's `--exclude-throw-branches` (the exception edges g++ adds")
    w("to every call that may throw) and `--exclude-unreachable-branches` (branches on lines with no")
    w("code of their own); `throw` statements themselves stay counted as lines. Goal (issue 13):")
    w(f">= {GOAL_LINES:.0f} % of lines and >= {GOAL_BRANCHES:.0f} % of branches in impl/src, reference/src and the")
    w("certifier under ctest alone.")
    w("")
    w("## Per area")
    w("")
    cols = ["ctest", "fuzz", "all"]
    head = "| area | lines ctest | branches ctest | lines fuzz | branches fuzz | lines all | branches all |"
    if "without" in runs:
        cols = ["without"] + cols
        head = "| area | lines ctest without | branches ctest without " + head[len("| area "):]
    if srcb is not None:
        head += " branches ctest, source-level (clang) |"
    w(head + " goal met (ctest) |")
    w("|" + " --- |" + " ---: |" * (2 * len(cols) + (srcb is not None)) + " --- |")
    for area, _, goal in AREAS:
        row = [area]
        met = None
        for run in cols:
            t = summed(runs[run], lambda n: area_of(n) == area)
            row += [fmt_pct(t[1], t[0]), fmt_pct(t[3], t[2])]
            if run == "ctest" and goal and t[0]:
                met = pct(t[1], t[0]) >= GOAL_LINES and pct(t[3], t[2]) >= GOAL_BRANCHES
                lines_met = pct(t[1], t[0]) >= GOAL_LINES
        if srcb is not None:
            t = summed(srcb, lambda n: area_of(n) == area)
            row.append(fmt_pct(t[3], t[2]))
            if met is not None:  # lines as g++ counts them, branches as written in the source
                met = lines_met and pct(t[3], t[2]) >= GOAL_BRANCHES
        row.append("-" if met is None else ("yes" if met else "**no**"))
        w("| " + " | ".join(row) + " |")
        # The same area over the files the measured tests enter at all (see the notes).
        entered = {n for n, lines in runs["ctest"].items() if area_of(n) == area and totals(lines)[1] > 0}
        if goal and len(entered) < sum(1 for n in runs["ctest"] if area_of(n) == area):
            row = [f"{area}, files entered"]
            for run in cols:
                t = summed(runs[run], lambda n: n in entered)
                row += [fmt_pct(t[1], t[0]), fmt_pct(t[3], t[2])]
            if srcb is not None:
                t = summed(srcb, lambda n: n in entered)
                row.append(fmt_pct(t[3], t[2]))
            row.append("")
            w("| " + " | ".join(row) + " |")
    w("")
    if "without" in runs:
        w(f"\"ctest without\": the default ctest less the tests matching `{a.split}` (the degenerate-case")
        w("tests of issue 13), run first: what the suite covered before them.")
        w("")
    notes = os.path.join(os.path.dirname(os.path.abspath(__file__)), "notes.md")
    if os.path.exists(notes):
        w(open(notes, encoding="utf-8").read().rstrip())
        w("")
    w("## Per file")
    w("")
    extra = " source branches | source branches ctest |" if srcb is not None else ""
    w("| file | lines | lines ctest | branches | branches ctest | lines all | branches all |" + extra)
    w("| --- | ---: | ---: | ---: | ---: | ---: | ---: |" + (" ---: | ---: |" if srcb is not None else ""))
    for n in names:
        lt, lc, bt, bc = totals(runs["ctest"][n])
        al = runs["all"].get(n, runs["ctest"][n])
        alt, alc, abt, abc = totals(al)
        cells = ""
        if srcb is not None:
            _, _, sbt, sbc = totals(srcb.get(n, {}))
            cells = f" {sbt} | {fmt_pct(sbc, sbt)} |"
        w(f"| {n} | {lt} | {fmt_pct(lc, lt)} | {bt} | {fmt_pct(bc, bt)} | {fmt_pct(alc, alt)} | {fmt_pct(abc, abt)} |" + cells)
    w("")
    w("## What ctest leaves uncovered, and why")
    w("")
    w("Every line and branch the default ctest never reaches, per file, with its reason from")
    w("`tools/coverage/reasons.txt`: **unreachable** (no input can get there: an invariant")
    w("another part guarantees), **defensive** (a check of an invariant that fails only if")
    w("there is a bug: a `logic_error` or a guard), **owed** (a test is owed), or **artefact** (a line")
    w("g++ -O1 reports unrun whose code ran: clang's source-based count says how often). A branch")
    w("`k/n` is a line whose n branch outcomes were taken k times in all; `(fuzz)` marks")
    w("those the fuzz corpora do reach.")
    w("")
    kinds = {"unreachable": 0, "defensive": 0, "owed": 0, "artefact": 0}
    unreached = []
    for n in names:
        lines = runs["ctest"][n]
        every = runs["all"].get(n, lines)
        items = []
        # With source-level branches, a line's branches are those written on it (clang);
        # its count stays g++'s.
        sl = srcb.get(n, {}) if srcb is not None else None
        for ln in sorted(set(lines) | (set(k for k, v in sl.items() if v["branches"]) if sl else set())):
            v = lines.get(ln, {"count": 1, "branches": []})
            br = (sl.get(ln, {"branches": []})["branches"]) if sl is not None else v["branches"]
            missed_line = v["count"] == 0
            nb = len(br)
            taken = sum(1 for c in br if c > 0)
            if not missed_line and taken == nb:
                continue
            text = source_line(a.root, n, ln)
            r = reason_for(reasons, n, text)
            kind = r["kind"] if r else "owed"
            why = r["why"] if r else "no reason recorded"
            if missed_line and taken == nb and sl is not None and sl.get(ln, {"strict": 0})["strict"] > 0:
                # g++ -O1 gives this line's code to its neighbours; clang counts the line itself.
                kind, why = "artefact", f"the line runs ({sl[ln]['strict']} times, clang); g++ -O1 counts its code on other lines"
            ev = every.get(ln, v)
            fuzz = (missed_line and ev["count"] > 0) or (sl is None and sum(1 for c in ev["branches"] if c > 0) > taken)
            what = "line" if missed_line else f"branch {taken}/{nb}"
            items.append((ln, what, text, kind, why, fuzz))
        if not items:
            continue
        lt, lc, _, _ = totals(lines)
        if lc == 0:
            # A whole file no measured test reaches: one row, not one per line.
            kinds["owed"] += 1
            where = "the fuzz corpora do" if totals(every)[1] else "neither do the fuzz corpora"
            unreached.append(f"- `{n}` ({lt} lines): not reached by the measured tests ({where}).")
            continue
        w(f"### {n}")
        w("")
        w("| line | what | source | kind | why |")
        w("| ---: | --- | --- | --- | --- |")
        for ln, what, text, kind, why, fuzz in items:
            kinds[kind] += 1
            src = text if len(text) <= 90 else text[:87] + "..."
            w(f"| {ln} | {what}{' (fuzz)' if fuzz else ''} | `{src.replace('|', '/').replace('`', '')}` | {kind} | {why.replace('|', '/')} |")
        w("")
    if unreached:
        w("### Files the measured tests never enter")
        w("")
        w("Counted as one owed item each: their tests are outside the measured selection, or there are none.")
        w("")
        for u in unreached:
            w(u)
        w("")
    w(f"In all: {kinds['unreachable']} unreachable, {kinds['defensive']} defensive, {kinds['owed']} owed, "
      f"{kinds['artefact']} measurement artefacts (lines g++ misses that clang counts as run).")
    unused = [r for r in reasons if not r["used"]]
    if unused:
        w("")
        w(f"({len(unused)} entries of reasons.txt matched nothing uncovered: lines now covered.)")
    w("")
    print("\n".join(out))


if __name__ == "__main__":
    main()
