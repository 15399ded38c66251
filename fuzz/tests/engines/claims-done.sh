#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A mesher that hides its stop: runs the command it is given (lepp refine, which
# exits 3 when it stops at its budget) and always exits 0, so a mesh with angles
# below theta is claimed as converged (fuzz_engine must report it even on an input
# below double resolution, where a run that says it stopped short is a known class).
"$@"
exit 0
