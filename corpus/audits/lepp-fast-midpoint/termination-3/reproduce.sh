#!/bin/sh
lepp audit --engine fast --method midpoint --theta 33 --timeout 5 --inputs corpus/audits/lepp-fast-midpoint/termination-3/input.poly
