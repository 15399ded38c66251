#!/bin/sh
lepp audit --engine reference --method midpoint --theta 33 --timeout 5 --inputs corpus/audits/lepp-reference-midpoint/termination-1/input.poly
