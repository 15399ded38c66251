#!/bin/sh
lepp audit --engine fast --method centroid --theta 20 --timeout 5 --inputs corpus/audits/lepp-fast-centroid/termination-2/input.poly
