#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A fake mesher that never ends (fuzz_engine must report a timeout).
while :; do sleep 1; done
