#!/bin/sh
lepp audit --engine reference --method centroid --theta 33 --timeout 5 --inputs corpus/audits/lepp-reference-centroid/certificate-1/input.poly
