#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The mutation harness (docs/MUTATION.md). Opt-in: not part of CI.

  tools/mutation/run.py [--scratch DIR] [--only ID,...] [--rerun] [--report-only] [--fuzz]

Copies the tree (tracked and new files, not the build trees) into a scratch
directory (default build-mutation/src: never the working tree's own files),
builds it once (Release, no benchmarks), checks the default ctest passes there,
then for each mutant of tools/mutation/mutants.txt: applies its one edit, builds
the executables it names and runs their tests matching its `quick` regex
(ctest --stop-on-failure); a mutant that survives that is built whole and runs
the whole default ctest. The edit is reverted before the next mutant. Results go
to DIR/../results.json (a rerun resumes: mutants with a result are skipped
unless --rerun) and docs/MUTATION.md is written from the catalogue and them.

--fuzz: a mutant that survived ctest is also tried against the fuzz corpora grown
by campaigns (out/fuzz/TARGET/corpus in the working tree, replayed by the g++
replay drivers): such kills are counted apart from ctest's.
"""
import argparse
import datetime
import json
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CATALOGUE = os.path.join(ROOT, "tools", "mutation", "mutants.txt")
REPORT = os.path.join(ROOT, "docs", "MUTATION.md")
FUZZ_TARGETS = ["fuzz_parse", "fuzz_refine", "fuzz_differential", "fuzz_cdt"]


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def parse_catalogue(path):
    mutants, cur = [], None
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        line = line.rstrip("\n")
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        m = re.match(r"^\[([A-Za-z0-9_.-]+)\]$", line)
        if m:
            cur = {"id": m.group(1), "line": n}
            mutants.append(cur)
            continue
        if cur is None or " = " not in line:
            sys.exit(f"{path}:{n}: expected [id] or 'key = value'")
        key, value = line.split(" = ", 1)
        cur[key.strip()] = value
    ids = set()
    for m in mutants:
        for key in ("file", "from", "to", "bug"):
            if key not in m:
                sys.exit(f"{path}:{m['line']}: mutant {m['id']} has no '{key}'")
        if m["id"] in ids:
            sys.exit(f"{path}:{m['line']}: duplicate mutant id {m['id']}")
        ids.add(m["id"])
        m["from_text"] = m["from"].replace("\\n", "\n")
        m["to_text"] = m["to"].replace("\\n", "\n")
    return mutants


def area_of(m):
    f = m["file"]
    for prefix, area in (("impl/", "impl"), ("reference/", "reference"), ("core/", "core"),
                         ("properties/certify/", "certifier"), ("properties/gen/", "generators"),
                         ("audit/", "audit")):
        if f.startswith(prefix):
            return area
    return "other"


def run(cmd, cwd=None, timeout=None, log_path=None):
    start = time.time()
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           timeout=timeout, errors="replace")
        out, code = p.stdout, p.returncode
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        code = "timeout"
    if log_path:
        with open(log_path, "a", encoding="utf-8") as f:
            f.write(f"$ {' '.join(cmd)}\n{out}\n[exit {code}, {time.time() - start:.0f} s]\n")
    return code, out, time.time() - start


def sync_scratch(scratch):
    files = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=ROOT, stdout=subprocess.PIPE,
                           check=True).stdout.split(b"\0")
    os.makedirs(scratch, exist_ok=True)
    copied = 0
    for raw in files:
        if not raw:
            continue
        rel = raw.decode()
        src, dst = os.path.join(ROOT, rel), os.path.join(scratch, rel)
        if not os.path.isfile(src):
            continue
        # Copy only what changed: unchanged files keep their mtime (an incremental build).
        if os.path.exists(dst) and open(src, "rb").read() == open(dst, "rb").read():
            continue
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        # A fresh mtime, not the source's: a file changed in the working tree (a rebase)
        # before the scratch was last built would otherwise look older than its
        # objects, and ninja would keep them (stale objects, crashes of the unmutated tree).
        shutil.copy(src, dst)
        os.utime(dst)
        copied += 1
    # Files the tree no longer has (removed, renamed) go from the scratch too: a
    # stale regression file would otherwise fail the unmutated ctest there.
    kept = set(raw.decode() for raw in files if raw)
    removed = 0
    for dirpath, dirnames, filenames in os.walk(scratch):
        if dirpath == scratch and "build" in dirnames:
            dirnames.remove("build")
        for name in filenames:
            rel = os.path.relpath(os.path.join(dirpath, name), scratch)
            if rel not in kept:
                os.remove(os.path.join(dirpath, name))
                removed += 1
    log(f"scratch {scratch}: {copied} files updated, {removed} removed")


NICE = 19  # --nice: how much to lower the harness's priority (19 leaves the machine to others)

# mutation.catalogue_applies fails for any edited catalogued line, whatever the
# behaviour: a kill it alone made would say nothing about the suite. It is left
# out of every mutant's run (never of the baseline).
NEVER_JUDGES = r"^mutation\.catalogue_applies$"


def exclude_regex(extra):
    """The ctest -E regex of a mutant's run: the never-judging tests and --exclude."""
    return NEVER_JUDGES + (f"|{extra}" if extra else "")


def nice(cmd):
    return ["nice", "-n", str(NICE)] + cmd


def failed_tests(out):
    # A parameterized test's name goes on with "  # GetParam() = ..." before the reason.
    names = re.findall(r"\d+ - (\S+)(?:  # GetParam\(\) = [^\n]*?)? \((Failed|Timeout|SEGFAULT|Subprocess aborted|Exception|Child aborted|[^)]*)\)", out)
    return [f"{n} ({why})" for n, why in names]


def test_map(build):
    """ctest name -> executable path, for every registered test."""
    code, out, _ = run(["ctest", "--test-dir", build, "--show-only=json-v1"])
    if code != 0:
        sys.exit("ctest --show-only failed:\n" + out[-2000:])
    data = json.loads(out)
    return {t["name"]: os.path.basename(t["command"][0]) if t.get("command") else "" for t in data.get("tests", [])}


def quick_regex(tests, targets, pattern):
    names = [n for n, exe in tests.items() if exe in targets and re.search(pattern, n)]
    return names, "^(" + "|".join(re.escape(n) for n in names) + ")$"


def ctest(build, args, timeout, log_path, jobs):
    return run(nice(["ctest", "--test-dir", build, "-j", str(jobs), "--stop-on-failure", "--timeout", "300"] + args),
               timeout=timeout, log_path=log_path)


def try_fuzz(build, log_path):
    for t in FUZZ_TARGETS:
        d = os.path.join(ROOT, "out", "fuzz", t, "corpus")
        exe = os.path.join(build, "fuzz", t + "_replay")
        if os.path.isdir(d) and os.path.exists(exe):
            code, out, _ = run(nice([exe, d]), timeout=1800, log_path=log_path)
            if code != 0:
                return f"{t}_replay on out/fuzz/{t}/corpus"
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scratch", default=os.path.join(ROOT, "build-mutation", "src"))
    ap.add_argument("--only", default="", help="comma-separated mutant ids")
    ap.add_argument("--rerun", action="store_true", help="run mutants that already have a result")
    ap.add_argument("--report-only", action="store_true")
    ap.add_argument("--check", action="store_true",
                    help="only check that every edit applies to the tree as it is (each 'from' exactly once in its "
                         "file) and that every entry not argued equivalent has quick tests and targets; exit 1 "
                         "naming those that fail (a ctest runs this)")
    ap.add_argument("--catalogue", default=CATALOGUE, help="the catalogue to read (default tools/mutation/mutants.txt)")
    ap.add_argument("--no-sync", action="store_true", help="keep the scratch tree as it is")
    ap.add_argument("--fuzz", action="store_true")
    ap.add_argument("--exclude", default="", help="ctest -E regex: tests failing on the unmutated tree too, left out (named in the report)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--nice", type=int, default=19, help="niceness of builds and tests (0: compete evenly with other work)")
    ap.add_argument("--pass", dest="pass_", choices=["both", "quick", "full"], default="both",
                    help="quick: only each mutant's quick tests (survivors wait as survived-quick); "
                         "full: the whole ctest for those waiting; both (default): one after the other per mutant")
    a = ap.parse_args()
    global NICE
    NICE = a.nice

    mutants = parse_catalogue(a.catalogue)
    if a.check:
        stale = [m for m in mutants if open(os.path.join(ROOT, m["file"]), encoding="utf-8").read().count(m["from_text"]) != 1]
        for m in stale:
            count = open(os.path.join(ROOT, m["file"]), encoding="utf-8").read().count(m["from_text"])
            print(f"{a.catalogue}:{m['line']}: mutant {m['id']}: 'from' occurs {count} times in {m['file']} (must be exactly once)")
        # A mutant not argued equivalent needs its quick tests and their targets: without
        # them the quick pass runs nothing and calls it survived-quick.
        untested = [m for m in mutants if "equivalent" not in m and not ("quick" in m and "targets" in m)]
        for m in untested:
            print(f"{a.catalogue}:{m['line']}: mutant {m['id']}: no 'quick' or no 'targets' (the quick pass would run no test)")
        print(f"{len(mutants)} mutants, {len(stale)} that do not apply, {len(untested)} without quick tests")
        sys.exit(1 if stale or untested else 0)
    scratch = os.path.abspath(a.scratch)
    build = os.path.join(scratch, "build")
    results_path = os.path.join(os.path.dirname(scratch), "results.json")
    log_path = os.path.join(os.path.dirname(scratch), "mutation.log")
    results = json.load(open(results_path)) if os.path.exists(results_path) else results_from_report(REPORT)

    def save():
        with open(results_path, "w") as f:
            json.dump(results, f, indent=1, sort_keys=True)

    if not a.report_only:
        # Every edit must apply to the tree as it is now.
        for m in mutants:
            text = open(os.path.join(ROOT, m["file"]), encoding="utf-8").read()
            count = text.count(m["from_text"])
            if count != 1:
                sys.exit(f"mutant {m['id']}: 'from' occurs {count} times in {m['file']} (must be exactly once)")
        if not a.no_sync:
            sync_scratch(scratch)
        if not os.path.exists(os.path.join(build, "build.ninja")):
            code, out, _ = run(nice(["cmake", "-S", scratch, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                                     "-DLEPP_BUILD_BENCH=OFF"]), log_path=log_path)
            if code != 0:
                sys.exit("configure failed; see " + log_path)
        log("building the unmutated scratch tree")
        code, out, _ = run(nice(["cmake", "--build", build, "-j", str(a.jobs)]), log_path=log_path)
        if code != 0:
            sys.exit("the unmutated tree does not build; see " + log_path)
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, stdout=subprocess.PIPE, text=True).stdout.strip()
        results["excluded"] = a.exclude
        if results.get("baseline_head") != head or a.rerun:
            log("baseline: the whole default ctest on the unmutated tree")
            code, out, secs = run(nice(["ctest", "--test-dir", build, "-j", str(a.jobs), "--timeout", "600"]), log_path=log_path)
            results["baseline"] = {"exit": code, "seconds": round(secs), "failed": failed_tests(out),
                                   "summary": "".join(re.findall(r"\d+% tests passed.*", out))}
            results["baseline_head"] = head
            results["excluded"] = a.exclude
            save()
            real = [f for f in results["baseline"]["failed"] if "(Skipped)" not in f and not (a.exclude and re.search(a.exclude, f))]
            if code != 0 and real:
                sys.exit("the default ctest fails on the unmutated tree (%s); fix that first" % results["baseline"]["failed"])
        tests = test_map(build)
        only = set(x for x in a.only.split(",") if x)
        # Round-robin over the areas: a run cut short still samples every area.
        by_area = {}
        for m in mutants:
            by_area.setdefault(area_of(m), []).append(m)
        order = [v[k] for k in range(max(len(v) for v in by_area.values())) for v in by_area.values() if k < len(v)]
        for m in order:
            if only and m["id"] not in only:
                continue
            prev = results["mutants"].get(m["id"], {}).get("status")
            if a.pass_ == "full":
                if prev not in ("survived-quick", "survived") or (prev == "survived" and not a.rerun):
                    continue
            elif prev is not None and not a.rerun and not only:
                continue
            path = os.path.join(scratch, m["file"])
            original = open(path, encoding="utf-8").read()
            if original.count(m["from_text"]) != 1:
                sys.exit(f"mutant {m['id']}: the scratch copy of {m['file']} differs from the tree; resync")
            r = {"status": "survived", "killed_by": [], "stage": "", "seconds": 0}
            start = time.time()
            log(f"[{m['id']}] {m['bug']}")
            try:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(original.replace(m["from_text"], m["to_text"]))
                targets = m.get("targets", "").split()
                stages = []
                if targets and m.get("quick") and a.pass_ != "full":
                    stages.append("quick")
                if a.pass_ != "quick":
                    stages.append("full")
                for stage in stages:
                    build_cmd = ["cmake", "--build", build, "-j", str(a.jobs)] + (["--target"] + targets if stage == "quick" else [])
                    code, out, _ = run(nice(build_cmd), log_path=log_path)
                    if code != 0:
                        r = {"status": "stillborn", "killed_by": ["does not compile"], "stage": stage}
                        break
                    if stage == "quick":
                        names, regex = quick_regex(test_map(build), set(targets), m["quick"])
                        names = [n for n in names if not re.search(exclude_regex(a.exclude), n)]
                        regex = "^(" + "|".join(re.escape(n) for n in names) + ")$"
                        if not names:
                            continue
                        code, out, _ = ctest(build, ["-R", regex], 3600, log_path, a.jobs)
                    else:
                        code, out, _ = ctest(build, ["-E", exclude_regex(a.exclude)], 7200, log_path, a.jobs)
                    if code != 0:
                        # ctest lists the tests that skipped beside those that failed: never a kill.
                        by = [f for f in failed_tests(out) if not f.endswith("(Skipped)")] or [f"ctest exit {code}"]
                        if all(re.match(NEVER_JUDGES.rstrip("$"), f) for f in by):
                            continue  # cannot happen (it is left out), but never a kill
                        r = {"status": "killed", "killed_by": by, "stage": stage}
                        break
                if r["status"] == "survived" and a.pass_ == "quick":
                    r["status"] = "survived-quick"
                if r["status"] == "survived" and a.fuzz:
                    who = try_fuzz(build, log_path)
                    if who:
                        r = {"status": "killed-by-fuzz", "killed_by": [who], "stage": "fuzz"}
            finally:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(original)
                os.utime(path)
            r["seconds"] = round(time.time() - start)
            r["when"] = datetime.datetime.now().isoformat(timespec="seconds")
            results["mutants"][m["id"]] = r
            save()
            log(f"[{m['id']}] {r['status']} ({r['stage']}, {r['seconds']} s) {', '.join(r['killed_by'][:3])}")
        # Leave the scratch build unmutated.
        run(nice(["cmake", "--build", build, "-j", str(a.jobs)]), log_path=log_path)

    write_report(mutants, results, REPORT)


def results_from_report(path):
    """The results the report holds (its "Every mutant" table), for a tree without
    build-mutation/results.json (a clean clone): a run of a few mutants then adds to
    the report instead of dropping every earlier result from it. The baseline is not
    kept with its commit, so a run on a later commit runs it again."""
    results = {"mutants": {}}
    if not os.path.exists(path):
        return results
    text = open(path, encoding="utf-8").read()
    if b := re.search(r"^Baseline \(unmutated tree, commit (\w+)\): default ctest (.*), (\d+) s wall", text, re.M):
        results["baseline_head"] = b.group(1)
        results["baseline"] = {"exit": 0, "seconds": int(b.group(3)), "failed": [], "summary": b.group(2)}
    rows = text.split("\n## Every mutant\n", 1)
    for line in (rows[1].splitlines() if len(rows) == 2 else []):
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if len(cells) != 5 or not cells[0].startswith("`"):
            continue
        status, by = cells[3], cells[4]
        stage = ""
        if m := re.fullmatch(r"(\w[\w-]*) \((.*)\)", status):
            status, stage = m.group(1), m.group(2)
        if status == "not run":
            continue
        results["mutants"][cells[0].strip("`")] = {"status": status, "stage": stage, "seconds": 0,
                                                   "killed_by": [b for b in by.split(", ") if b], "from_report": True}
    return results


def write_report(mutants, results, path):
    # A mutant that survived its quick tests and waits for the whole ctest is not run yet.
    res = {k: v for k, v in results.get("mutants", {}).items() if v["status"] != "survived-quick"}
    run_ = [m for m in mutants if m["id"] in res and res[m["id"]]["status"] != "stillborn"]
    killed = [m for m in run_ if res[m["id"]]["status"] == "killed"]
    fuzz = [m for m in run_ if res[m["id"]]["status"] == "killed-by-fuzz"]
    survived = [m for m in run_ if res[m["id"]]["status"] == "survived"]
    equivalent = [m for m in survived if m.get("equivalent")]
    stillborn = [m for m in mutants if m["id"] in res and res[m["id"]]["status"] == "stillborn"]
    pending = [m for m in mutants if m["id"] not in res]
    scored = len(run_) - len(equivalent)

    def pct(k, n):
        return f"{100.0 * k / n:.1f} %" if n else "n/a"

    L = []
    L.append("# Mutation score")
    L.append("")
    L.append("Generated by `tools/mutation/run.py` from `tools/mutation/mutants.txt`; do not edit by hand.")
    L.append("")
    L.append("Each mutant is one exact edit of one line (or two) of the sources, modelling a bug")
    L.append("someone could plausibly write: a tie broken the wrong way, a strict comparison made")
    L.append("non-strict, a rule applied to the wrong triangle, a sign flipped on the exact path.")
    L.append("The harness applies it in a scratch copy of the tree (never the working tree), builds,")
    L.append("runs the tests (first the mutant's own executables' tests matching its `quick` regex,")
    L.append("then, if it survived those, the whole default `ctest`), and reverts it. A mutant is")
    L.append("*killed* when a test fails or times out (`mutation.catalogue_applies`, which fails for any")
    L.append("edited catalogued line, is never run on a mutant). Opt-in, not in CI: `tools/mutation/run.py`")
    L.append("(about 1 to 3 CPU-minutes a mutant on this machine; results resume from")
    L.append("`build-mutation/results.json`).")
    L.append("")
    base = results.get("baseline", {})
    if base:
        L.append(f"Baseline (unmutated tree, commit {results.get('baseline_head', '?')}): default ctest "
                 f"{base.get('summary', '').strip() or 'passed'}, {base.get('seconds', '?')} s wall with `-j2`.")
        if results.get("excluded"):
            L.append("")
            L.append(f"Left out of every run (they fail on the unmutated tree too, not this harness's business): "
                     f"tests matching `{results['excluded']}`.")
        L.append("")
    waiting = [m for m in mutants if results.get("mutants", {}).get(m["id"], {}).get("status") == "survived-quick"]
    notes = os.path.join(ROOT, "tools", "mutation", "notes.md")
    if os.path.exists(notes):
        L.append(open(notes, encoding="utf-8").read().rstrip())
        L.append("")
    L.append("## Score")
    L.append("")
    L.append("| | count |")
    L.append("| --- | ---: |")
    L.append(f"| mutants in the catalogue | {len(mutants)} |")
    L.append(f"| run | {len(run_)} |")
    L.append(f"| killed by the default ctest | {len(killed)} |")
    L.append(f"| killed only by the fuzz corpora (counted apart) | {len(fuzz)} |")
    L.append(f"| survived, argued equivalent | {len(equivalent)} |")
    L.append(f"| survived, not equivalent (a test is owed) | {len(survived) - len(equivalent)} |")
    if stillborn:
        L.append(f"| stillborn (did not compile; not counted) | {len(stillborn)} |")
    if waiting:
        L.append(f"| survived their quick tests, waiting for the whole ctest (not counted yet) | {len(waiting)} |")
    if pending:
        L.append(f"| not decided yet (incl. those waiting) | {len(pending)} |")
    L.append("")
    L.append(f"**Mutation score (default ctest alone): {len(killed)} / {scored} = {pct(len(killed), scored)}** "
             f"of the non-equivalent mutants run; with the fuzz corpora: {pct(len(killed) + len(fuzz), scored)}.")
    L.append("")
    areas = ["impl", "reference", "core", "certifier", "generators", "audit"]
    L.append("| area | mutants | killed | survived (equivalent) |")
    L.append("| --- | ---: | ---: | ---: |")
    for area in areas:
        ms = [m for m in run_ if area_of(m) == area]
        k = sum(1 for m in ms if res[m["id"]]["status"] == "killed")
        s = [m for m in ms if res[m["id"]]["status"] == "survived"]
        e = sum(1 for m in s if m.get("equivalent"))
        L.append(f"| {area} | {len(ms)} | {k} | {len(s)} ({e}) |")
    L.append("")
    if waiting:
        L.append("## Waiting for the whole ctest")
        L.append("")
        L.append("These survived the tests of their own executables; the whole default ctest has not been run on them yet:")
        L.append("")
        for m in waiting:
            L.append(f"- `{m['id']}` ({m['file']}): {m['bug']}.")
        L.append("")
    if survived:
        L.append("## Survivors")
        L.append("")
        for m in survived:
            L.append(f"- `{m['id']}` ({m['file']}): {m['bug']}.")
            if m.get("equivalent"):
                L.append(f"  Equivalent: {m['equivalent']}.")
            else:
                L.append("  **Not equivalent: a test is owed.**")
        L.append("")
    L.append("## Every mutant")
    L.append("")
    L.append("| mutant | file | bug it models | result | killed by |")
    L.append("| --- | --- | --- | --- | --- |")
    for m in mutants:
        r = res.get(m["id"])
        status = r["status"] if r else "not run"
        if r and r.get("stage") and status == "killed":
            status += f" ({r['stage']})"
        by = ", ".join(r["killed_by"][:2]) if r else ""
        if r and len(r["killed_by"]) > 2:
            by += f" and {len(r['killed_by']) - 2} more"
        L.append(f"| `{m['id']}` | {m['file']} | {m['bug']} | {status} | {by.replace('|', '/')} |")
    L.append("")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(L))
    log(f"wrote {os.path.relpath(path, ROOT)}: {len(killed)}/{scored} killed by ctest")


if __name__ == "__main__":
    main()
