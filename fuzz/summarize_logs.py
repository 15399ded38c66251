#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Summarizes fuzz/run.sh logs into the rows of docs/FUZZING.md's findings table.

usage: fuzz/summarize_logs.py LOG...
For each log: executions, exec/s, final cov:, CPU seconds (user + sys), and the
LEPP-FINDING classes with their counts (under -fork, the parent's crash, timeout and
oom counts: the jobs' findings are in findings/, classified by replaying them)."""
import collections
import re
import sys

for path in sys.argv[1:]:
    text = open(path, errors="replace").read()
    # "#N  NEW  cov: C" (one process) or "#N: cov: C ... oom/timeout/crash: a/b/c" (-fork=N).
    runs = re.findall(r"^#(\d+):?\s+(?:\w+\s+)?cov: (\d+)", text, re.M)
    forked = re.findall(r"oom/timeout/crash: (\d+)/(\d+)/(\d+)", text)
    execs = max((int(r[0]) for r in runs), default=0)
    cov = runs[-1][1] if runs else "?"
    done = re.search(r"Done (\d+) runs in (\d+) second", text)
    if done:
        execs = int(done.group(1))
    cpu = re.search(r"cpu: real ([\d.]+) s, user ([\d.]+) s, sys ([\d.]+) s", text)
    cpu_s = float(cpu.group(2)) + float(cpu.group(3)) if cpu else None
    wall = float(cpu.group(1)) if cpu else (int(done.group(2)) if done else None)
    rate = re.findall(r"exec/s:? (\d+)", text)
    classes = collections.Counter(re.findall(r"LEPP-FINDING target=\S+ class=(\S+)", text))
    if forked:  # the jobs' own output is not in this log: the counts the parent keeps
        oom, timeout, crash = (int(x) for x in forked[-1])
        classes.update({k: v for k, v in (("oom", oom), ("timeout", timeout), ("crash", crash)) if v})
    crash = not forked and ("deadly signal" in text or "ERROR: AddressSanitizer" in text or "runtime error" in text)
    print(f"{path}: execs={execs} exec/s={rate[-1] if rate else '?'} cov={cov} "
          f"cpu_s={cpu_s if cpu_s is not None else '?'} wall_s={wall if wall is not None else '?'} "
          f"findings={dict(classes)} stopped_on_crash={crash}")
