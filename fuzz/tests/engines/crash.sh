#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A fake mesher that dies of a signal (fuzz_engine must report a crash).
kill -SEGV $$
