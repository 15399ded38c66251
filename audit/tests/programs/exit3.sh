#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Fake mesher: complains and exits 3. usage: exit3.sh IN OUT
echo "exit3.sh: cannot mesh $1" >&2
exit 3
