#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Fake mesher: debug noise on stderr, then its real error on the last line, exit 1
# with no mesh. usage: noisy_fail.sh IN OUT
echo "debug: reading $1" >&2
echo "debug: 3 vertices" >&2
echo "error: the triangulation failed (boom)" >&2
exit 1
