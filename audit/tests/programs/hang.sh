#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Fake mesher: never ends, with a child that keeps stderr open and ignores SIGTERM. usage: hang.sh IN OUT
trap '' TERM
(trap '' TERM; while :; do sleep 1; done) &
while :; do sleep 1; done
