#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Prints each of its arguments in brackets, one a line, on stderr, and the name of
# its parent process (sh when a shell started it). usage: args.sh ARG...
for a in "$@"; do printf '[%s]\n' "$a" >&2; done
printf 'parent: %s\n' "$(cat /proc/$PPID/comm)" >&2
