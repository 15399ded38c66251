#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A fake mesher that exits 0 with garbage in place of its mesh (fuzz_engine must report unreadable output).
echo "this is not a node file" > "$2.node"
printf '1 3 0\n0 0 1 7\n' > "$2.ele"
