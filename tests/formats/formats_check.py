# SPDX-License-Identifier: GPL-3.0-or-later
"""What the format tests of tests/formats/ share: failures collected and printed,
a command run with its output captured, and Triangle's files read as rows of
tokens (comments after '#' and blank lines dropped)."""
import subprocess

failures = []


def fail(what):
    failures.append(what)
    print("FAIL:", what)


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True)


def tokens(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                rows.append(line)
    return rows
