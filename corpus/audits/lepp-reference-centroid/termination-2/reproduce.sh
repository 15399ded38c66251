#!/bin/sh
lepp audit --engine reference --method centroid --theta 20 --timeout 5 --inputs corpus/audits/lepp-reference-centroid/termination-2/input.poly
