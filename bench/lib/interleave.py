# SPDX-License-Identifier: GPL-3.0-or-later
"""Interleaved whole-process timing for bench/'s side-by-side scripts.

Each round runs every step once, in order, so that the programs compared share
the machine's load; a step's wall time, CPU time (user + system, the child's own
rusage from wait4, as GNU time reports it) and peak resident memory are kept, and
the medians over the rounds are what the scripts print. Used by
bench/beside_triangle.sh and bench/certify_beside_refine.sh (issue 40).
"""
import os
import statistics
import subprocess
import sys
import time


class Step:
    """One program run per round: `name` keys the results, `label` is its table row.

    ok: exit statuses that count as success (lepp refine's 3 is a guard's stop);
    then: called after each successful run (e.g. to read and remove its output);
    first: called before each run, untimed (e.g. to remove the files it writes, so
    that no program is charged for truncating the previous round's).
    """

    def __init__(self, name, label, argv, ok=(0,), then=None, first=None):
        self.name, self.label, self.argv, self.ok, self.then = name, label, [str(a) for a in argv], tuple(ok), then
        self.first = first


def remove_outputs(prefix, extensions=("node", "ele", "poly", "unimprovable")):
    """A function removing PREFIX.EXT for each extension that exists (a Step's first)."""
    def remove():
        for ext in extensions:
            try:
                os.remove(f"{prefix}.{ext}")
            except FileNotFoundError:
                pass
    return remove


def timed(argv):
    """Runs argv with stdout discarded; returns (status, wall s, cpu s, peak bytes, stderr)."""
    start = time.monotonic()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    # ru_maxrss is in KiB on Linux.
    return proc.returncode, wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss * 1024, err


def idle_share(seconds=0.5):
    """The machine's idle share of CPU time over the next `seconds` (/proc/stat)."""
    def snapshot():
        with open("/proc/stat") as f:
            ticks = [int(x) for x in f.readline().split()[1:]]
        return ticks[3] + ticks[4], sum(ticks)  # idle + iowait, all
    idle0, all0 = snapshot()
    time.sleep(seconds)
    idle1, all1 = snapshot()
    return (idle1 - idle0) / max(1, all1 - all0)


def wait_until_idle(share=0.9, limit=120.0):
    """With LEPP_BENCH_QUIET set: waits (at most `limit` seconds) until the machine is
    idle (`share` of its CPU time over half a second), so that a round on a machine
    shared with other work starts when no other program runs. Returns the seconds waited."""
    if not os.environ.get("LEPP_BENCH_QUIET"):
        return 0.0
    start = time.monotonic()
    while time.monotonic() - start < limit and idle_share() < share:
        pass
    return time.monotonic() - start


def run_rounds(steps, rounds, progress=""):
    """Every step once per round, `rounds` times; {name: [(wall, cpu, peak), ...]}.
    With LEPP_BENCH_QUIET set, each round first waits for an idle machine (wait_until_idle).

    Exits 1 with the program's stderr when a step fails."""
    samples = {s.name: [] for s in steps}
    tty = sys.stderr.isatty()
    for r in range(rounds):
        wait_until_idle()
        if tty and progress:
            sys.stderr.write(f"\r{progress}: round {r + 1} of {rounds}")
            sys.stderr.flush()
        for s in steps:
            if s.first:
                s.first()
            status, wall, cpu, peak, err = timed(s.argv)
            if status not in s.ok:
                if tty and progress:
                    sys.stderr.write("\r\033[K")
                sys.stderr.write(f"{s.name} failed ({status}): {' '.join(s.argv)}\n")
                sys.stderr.buffer.write(err)
                sys.exit(1)
            samples[s.name].append((wall, cpu, peak))
            if s.then:
                s.then()
    if tty and progress:
        sys.stderr.write("\r\033[K")
    return samples


def medians(samples):
    """{name: {"wall": s, "cpu": s, "peak": bytes}}: each the median over the rounds."""
    return {
        name: {
            "wall": statistics.median(x[0] for x in rows),
            "cpu": statistics.median(x[1] for x in rows),
            "peak": statistics.median(x[2] for x in rows),
        }
        for name, rows in samples.items()
    }


def minima(samples):
    """{name: {"wall": s, "cpu": s}}: each the smallest over the rounds (on a shared
    machine, the round least disturbed by the others' work)."""
    return {
        name: {"wall": min(x[0] for x in rows), "cpu": min(x[1] for x in rows)}
        for name, rows in samples.items()
    }


def markdown_table(steps, med, columns):
    """A markdown table, a row per step: columns is a list of (header, function(step, medians) -> str)."""
    lines = ["| program | " + " | ".join(h for h, _ in columns) + " |",
             "|---|" + "|".join("---:" for _ in columns) + "|"]
    for s in steps:
        lines.append(f"| {s.label} | " + " | ".join(f(s, med[s.name]) for _, f in columns) + " |")
    return "\n".join(lines)


def first_count(path):
    """The first number of a file's first line (a Triangle header's count)."""
    with open(path) as f:
        return int(f.readline().split()[0])
