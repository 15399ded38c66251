# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs a command and writes its CPU time, "USER SYS" in seconds to the microsecond.

usage: python3 bench/lib/cpu_time.py OUT COMMAND...   (exits with the command's status)
GNU time's %U %S print hundredths: a fuzz row that replays its corpus in 0.12 s read
to 8 % either way (bench/fuzz_throughput.sh). The times are the child's own rusage,
from wait4, its children included once they were waited for, as GNU time's are.
"""
import os
import subprocess
import sys

if len(sys.argv) < 3:
    sys.exit("usage: cpu_time.py OUT COMMAND...")
child = subprocess.Popen(sys.argv[2:])
_, status, usage = os.wait4(child.pid, 0)
with open(sys.argv[1], "w") as out:
    out.write(f"{usage.ru_utime:.6f} {usage.ru_stime:.6f}\n")
sys.exit(os.waitstatus_to_exitcode(status) if os.WIFEXITED(status) else 128 + os.WTERMSIG(status))
