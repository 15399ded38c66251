#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A fake mesher that gives up with a non-zero exit status (fuzz_engine must report it).
echo "fail.sh: cannot mesh $1" >&2
exit 3
