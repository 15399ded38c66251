#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Fake mesher: dies of SIGSEGV after writing half a mesh. usage: crash.sh IN OUT
printf '3 2 0 0\n' > "$2.node"
kill -SEGV $$
