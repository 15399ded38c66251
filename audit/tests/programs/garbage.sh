#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Fake mesher: writes garbage where the mesh should be. usage: garbage.sh IN OUT
printf '3 2 0 0\n1 0 0\n2 x y\n' > "$2.node"
head -c 300 /dev/urandom > "$2.ele"
exit 0
