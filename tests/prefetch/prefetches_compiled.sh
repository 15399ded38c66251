#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The software prefetches of the mesher's queue and the certifier's Lepp passes are
# in the linked binary. GCC deletes calls to a function it finds pure, and a
# prefetch is no effect to it: an out-of-line prefetch helper then compiles to
# nothing, silently (issue 40: the queue's prefetches were missing for three steps
# of measurements). The helpers are always inlined; this says they still arrive.
# usage: tests/prefetch/prefetches_compiled.sh OBJDUMP BINARY
set -euo pipefail
objdump=$1 binary=$2
"$objdump" -d -C --no-show-raw-insn "$binary" | awk '
  /^[0-9a-f]+ </ { fn = $0; next }
  /prefetch/ {
    if (fn ~ /Refiner::run(_queue)?\(/) queue++  # run_queue, or run where it is inlined
    if (fn ~ /BadQueue::pop/) pop++
    if (fn ~ /check_terminal_edges/) theorem2++
    if (fn ~ /average_lepp|lepp_size_sum/) lepp_size++
    if (fn ~ /Inserter::insert/) insert++
  }
  END {
    printf "prefetch instructions: run_queue %d, BadQueue::pop %d, Theorem 2 pass %d, mean Lepp size pass %d, Inserter::insert %d\n",
           queue, pop, theorem2, lepp_size, insert
    # run_queue holds prefetch_around (8 today); prefetch_ahead (6) is in BadQueue::pop,
    # or in run_queue where pop is inlined into it.
    ahead = pop > 0 || queue > 8
    exit (queue > 0 && ahead && theorem2 > 0 && lepp_size > 0 && insert > 0) ? 0 : 1
  }'
